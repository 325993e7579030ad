// ffcompat bench: frames of one scene on each backend in turn (blocks of frames, alternating), in
// one run; the median time per frame of each and their ratio. A benchmark, not a test: read the
// ratio, not a lone time.
#include <sys/resource.h>

#include <cstdlib>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <map>
#include <memory>
#include <sstream>

#include "cli/common.h"
#include "gl/dispatch.h"
#include "raster/wide/kernels.h"
#include "simd/target.h"
#include "state/context.h"

namespace ffc::cli {

// Mesa's GALLIUM_OVERRIDE_CPU_CAPS value (util/u_cpu_detect.c) that leaves llvmpipe the
// instructions of one of soft's targets: what llvmpipe has on a CPU whose best target that is.
// "" for the best x86 target (nothing to take away); throws where Mesa has no such override.
static std::string mesa_caps_for(const std::string& target) {
#if defined(__x86_64__) || defined(__i386__)
  if (target == "avx512") return "";
  if (target == "avx2") return "avx";  // clears AVX-512 only: AVX2 and FMA stay
  if (target == "sse4") return "sse4.1";  // clears AVX and with it AVX2 and FMA
  if (target == "ssse3") return "ssse3";  // clears SSE4.1
  if (target == "scalar") return "sse2";  // x86-64's baseline, which soft's scalar loops also use
#endif
  throw std::invalid_argument("--mesa-isa same: Mesa offers no CPU override matching soft's target '" + target + "' here");
}

void add_bench(CLI::App& app) {
  auto* cmd = app.add_subcommand("bench", "Median time per frame of a scene on each backend, and the speed-up");
  auto opts = std::make_shared<SceneOptions>();
  auto backends_list = std::make_shared<std::string>("mesa,soft");
  auto frames = std::make_shared<int>(20);
  auto block = std::make_shared<int>(5);
  auto json = std::make_shared<bool>(false);
  auto threads = std::make_shared<int>(0);
  auto runs = std::make_shared<int>(1);
  opts->add_to(cmd, true, false);
  refuse_option(cmd, "--backend", "bench takes --backends, a comma-separated list of backends (mesa, soft, glsl, ...)");
  cmd->add_option("--backends", *backends_list, "Comma-separated: mesa, soft, soft-double, glsl, ... (every registered backend)")
      ->capture_default_str();
  cmd->add_option("--frames", *frames, "Timed frames per backend (after one warm-up frame)")
      ->check(CLI::Range(1, 100000))
      ->capture_default_str();
  cmd->add_option("--block", *block, "Frames a backend draws before the next one takes its turn")
      ->check(CLI::Range(1, 100000))
      ->capture_default_str();
  cmd->add_option("--threads", *threads, "Threads for soft and soft-double (0: the default, both cores)")
      ->check(CLI::Range(0, 64))
      ->capture_default_str();
  cmd->add_option("--runs", *runs,
                  "Repeat the whole measurement this many times; report each run's medians and the spread of the "
                  "speed-up over the runs")
      ->check(CLI::Range(1, 100))
      ->capture_default_str();
  auto mesa_isa = std::make_shared<std::string>("native");
  cmd->add_option("--mesa-isa", *mesa_isa,
                  "native: llvmpipe uses every instruction the CPU has; same: only those of soft's SIMD target "
                  "(FFCOMPAT_SIMD), as on a CPU whose best target that is (sets GALLIUM_OVERRIDE_CPU_CAPS)")
      ->check(CLI::IsMember({"native", "same"}))
      ->capture_default_str();
  cmd->add_flag("--json", *json, "Print {median_ms: {backend: ms}, speedup, ...}");
  cmd->callback([=] {
    const scene::Description d = opts->description();
    const std::function<void()> issue = scene::frame(d);  // meshes built once, outside the timing
    std::vector<std::string> names;
    const std::vector<std::string> known = backends::names();
    std::string choices;
    for (const std::string& k : known) choices += (choices.empty() ? "" : ", ") + k;
    std::stringstream list(*backends_list);
    for (std::string n; std::getline(list, n, ',');) {
      if (std::find(known.begin(), known.end(), n) == known.end())
        throw std::invalid_argument("--backends: unknown backend '" + n + "' (" + choices + ")");
      names.push_back(n);
    }
    if (names.empty()) throw std::invalid_argument("--backends: no backend named (" + choices + ")");
    // Mesa reads its CPU caps once, when its first context is made: set before that.
    simd::configure_from_environment();
    const std::string soft_target = simd::vector_target() ? simd::current() : "scalar";
    if (*mesa_isa == "same") {
      if (std::find(names.begin(), names.end(), "mesa") == names.end())
        throw std::invalid_argument("--mesa-isa same: no mesa in --backends");
      const std::string caps = mesa_caps_for(soft_target);
      if (caps.empty()) unsetenv("GALLIUM_OVERRIDE_CPU_CAPS");
      else setenv("GALLIUM_OVERRIDE_CPU_CAPS", caps.c_str(), 1);
    }
    std::string mesa_renderer;
    nlohmann::json medians = nlohmann::json::object(), all = nlohmann::json::object(), alloc_json = nlohmann::json::object();
    std::vector<std::unique_ptr<backends::Backend>> backends;
    for (const std::string& name : names) {
      backends.push_back(backends::make(name));
      backends.back()->begin(d.width, d.height);
      if (*threads > 0 && name != "mesa") state::Context::current()->set_threads(*threads);
      if (name == "mesa" && ffc_glGetString) {
        const GLubyte* r = ffc_glGetString(GL_RENDERER);
        if (r) mesa_renderer = reinterpret_cast<const char*>(r);
      }
      issue();  // warm-up: Mesa compiles its fixed-function programs on the first frame
      (void)backends.back()->read();
    }
    // The backends take turns in blocks of frames, so that a machine that slows down for a while
    // (other load, clock changes) slows them alike and their ratio holds. The first frame of a
    // block is not timed: it brings the backend's data back into the caches the other one used.
    // With --runs, the whole measurement is repeated: the spread of the runs' ratios is what a
    // reader should quote, not one run's.
    image::Image picture;
    nlohmann::json run_list = nlohmann::json::array();
    std::vector<double> speedups;
    std::map<std::string, double> median;
    std::vector<uint64_t> allocs(names.size(), 0);
    for (int run = 0; run < *runs; ++run) {
      std::vector<std::vector<double>> ms(names.size());
      for (auto& m : ms) m.reserve(size_t(*frames));
      std::fill(allocs.begin(), allocs.end(), 0);
      for (int done = 0; done < *frames; done += *block)
        for (size_t b = 0; b < backends.size(); ++b) {
          backends[b]->resume();
          for (int f = -1; f < std::min(*block, *frames - done); ++f) {
            const uint64_t a0 = allocations();
            const auto t0 = std::chrono::steady_clock::now();
            issue();
            backends[b]->read_into(picture);  // finishes the frame (glFinish for Mesa)
            const auto t1 = std::chrono::steady_clock::now();
            const uint64_t a1 = allocations();
            if (f < 0) continue;
            ms[b].push_back(std::chrono::duration<double, std::milli>(t1 - t0).count());
            allocs[b] += a1 - a0;
          }
        }
      nlohmann::json run_medians = nlohmann::json::object();
      for (size_t b = 0; b < names.size(); ++b) {
        std::vector<double> sorted = ms[b];
        std::sort(sorted.begin(), sorted.end());
        median[names[b]] = sorted[sorted.size() / 2];
        run_medians[names[b]] = median[names[b]];
        // the fastest and slowest frame of all runs
        const double lo = run == 0 ? sorted.front() : std::min(sorted.front(), all[names[b]]["min_ms"].get<double>());
        const double hi = run == 0 ? sorted.back() : std::max(sorted.back(), all[names[b]]["max_ms"].get<double>());
        all[names[b]] = {{"min_ms", lo}, {"max_ms", hi}};
        alloc_json[names[b]] = double(allocs[b]) / double(*frames);
      }
      nlohmann::json r = {{"median_ms", run_medians}};
      if (median.count("mesa") && median.count("soft")) {
        speedups.push_back(median["mesa"] / median["soft"]);
        r["speedup"] = speedups.back();
      }
      run_list.push_back(r);
    }
    // With one run the medians are that run's; with several, each backend's median of the runs' medians.
    for (size_t b = 0; b < names.size(); ++b) {
      std::vector<double> per_run;
      for (const auto& r : run_list) per_run.push_back(r["median_ms"][names[b]].get<double>());
      std::sort(per_run.begin(), per_run.end());
      median[names[b]] = per_run[per_run.size() / 2];
      medians[names[b]] = median[names[b]];
    }
    rusage ru{};
    getrusage(RUSAGE_SELF, &ru);
    const std::string kernels = raster::detail::wide_kernels() ? simd::current() : "scalar";
    nlohmann::json j = {{"scene", opts->json(d)}, {"frames", *frames}, {"block", *block}, {"threads", *threads}, {"median_ms", medians},
                        {"spread", all}, {"peak_rss_mb", ru.ru_maxrss / 1024.0},
                        // C++ heap allocations per timed frame (Mesa's C code allocates with malloc: not seen)
                        {"allocations_per_frame", alloc_json},
                        // soft's rasterizer: the Highway target its kernels ran on (FFCOMPAT_SIMD), or the
                        // scalar loops (same pictures)
                        {"soft_kernels", kernels}};
    if (!speedups.empty()) {
      std::vector<double> sorted = speedups;
      std::sort(sorted.begin(), sorted.end());
      j["speedup"] = *runs == 1 ? speedups.front() : sorted[sorted.size() / 2];
      if (*runs > 1) {
        j["runs"] = run_list;
        j["speedup_spread"] = {{"median", sorted[sorted.size() / 2]}, {"min", sorted.front()}, {"max", sorted.back()}};
      }
    }
    if (median.count("mesa")) {
      add_platform(j, "mesa");
      // llvmpipe's renderer string names its vector width ("llvmpipe (LLVM 15.0.6, 512 bits)")
      j["mesa_renderer"] = mesa_renderer;
      const char* caps = std::getenv("GALLIUM_OVERRIDE_CPU_CAPS");
      j["mesa_cpu_caps"] = caps && *caps ? caps : "native";
    }
    if (*json) return print_json(j);
    std::printf("%-12s %12s %18s\n", "backend", "median ms", "allocations/frame");
    for (const auto& n : names) std::printf("%-12s %12.3f %18.1f\n", n.c_str(), median[n], alloc_json[n].get<double>());
    if (j.contains("speedup_spread"))
      std::printf("speedup (mesa / soft) over %d runs: median %.2fx, min %.2fx, max %.2fx\n", *runs,
                  j["speedup_spread"]["median"].get<double>(), j["speedup_spread"]["min"].get<double>(),
                  j["speedup_spread"]["max"].get<double>());
    else if (j.contains("speedup"))
      std::printf("speedup (mesa / soft): %.2fx\n", j["speedup"].get<double>());
    std::printf("%d frames each in blocks of %d, %dx%d; peak RSS %.0f MB; soft's kernels: %s\n", *frames, *block, d.width,
                d.height, ru.ru_maxrss / 1024.0, kernels.c_str());
    if (j.contains("mesa_renderer"))
      std::printf("mesa: %s, CPU caps %s\n", mesa_renderer.c_str(), j["mesa_cpu_caps"].get<std::string>().c_str());
  });
}

}  // namespace ffc::cli
