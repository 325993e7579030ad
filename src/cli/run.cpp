// ffcompat run: an unmodified classic GL program on ffcompat's libGL.so.1, libGLU.so.1 and
// libglut.so.3 (build/classic), headless with scripted input, its frames written as PNGs; with
// --compare, on Mesa and on --backend (soft, glsl, ...) with the same input, frame by frame (docs/run.md).
#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <memory>
#include <regex>
#include <sstream>
#include <thread>

#include "classic/glut/glut_script.h"
#include "cli/common.h"

namespace fs = std::filesystem;

namespace ffc::cli {

namespace {

struct RunOptions {
  std::string backend = "soft", size, keys, clicks, out;
  int frames = 0;  // 0: one more than the longest input script
  bool compare = false, json = false, window = false;
  double timeout = 60;
  std::vector<std::string> program;
};

// Where our libGL.so.1 & co. are: $FFCOMPAT_CLASSIC_DIR, else beside this executable (the build
// tree's build/classic), else an installed prefix's lib/ffcompat or lib/<multiarch>/ffcompat
// (where `cmake --install` puts them), else the build folder this binary was configured with.
std::string classic_dir() {
  auto has_libs = [](const fs::path& d) { return fs::exists(d / "libGL.so.1") && fs::exists(d / "libglut.so.3"); };
  if (const char* env = std::getenv("FFCOMPAT_CLASSIC_DIR")) return env;
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  std::vector<fs::path> candidates;
  if (!ec) {
    candidates.push_back(exe.parent_path() / "classic");
    const fs::path lib = exe.parent_path().parent_path() / "lib";
    candidates.push_back(lib / "ffcompat");
    if (fs::is_directory(lib, ec))
      for (const auto& entry : fs::directory_iterator(lib, ec))
        if (entry.is_directory()) candidates.push_back(entry.path() / "ffcompat");
  }
#ifdef FFCOMPAT_CLASSIC_BUILD_DIR
  candidates.push_back(FFCOMPAT_CLASSIC_BUILD_DIR);
#endif
  for (const fs::path& d : candidates)
    if (has_libs(d)) return d.string();
  throw std::runtime_error("cannot find ffcompat's libGL.so.1 and libglut.so.3 (looked beside the ffcompat binary, in "
                           "../lib/ffcompat, ../lib/*/ffcompat and in the build's classic/ folder); set FFCOMPAT_CLASSIC_DIR");
}

struct Outcome {
  int status = -1;        // exit status, when it exited
  int signal = 0;         // the signal that ended it, when one did
  bool timed_out = false;
  int frames = 0;         // frame-NNN.png files written
  double seconds = 0;
};

// Frames and diffs of an earlier run in the same folder would be taken for this run's.
void clear_frames(const fs::path& dir) {
  static const std::regex ours(R"((frame|window-\d+-frame|diff)-\d+\.png|stdout\.txt)");
  if (!fs::exists(dir)) return;
  for (const auto& entry : fs::directory_iterator(dir))
    if (entry.is_regular_file() && std::regex_match(entry.path().filename().string(), ours)) fs::remove(entry.path());
}

int count_frames(const fs::path& dir) {
  int n = 0;
  while (fs::exists(dir / ("frame-" + std::string(n < 10 ? "00" : n < 100 ? "0" : "") + std::to_string(n) + ".png"))) ++n;
  return n;
}

std::string frame_name(const char* prefix, int i) {
  char name[64];
  std::snprintf(name, sizeof name, "%s-%03d.png", prefix, i);
  return name;
}

// Runs the program once on `backend`, writing into `dir`; stdout goes to `stdout_file` when set.
Outcome run_once(const RunOptions& o, const std::string& backend, const fs::path& dir, const std::string& classic,
                 const std::string& stdout_file) {
  fs::create_directories(dir);
  clear_frames(dir);
  const auto start = std::chrono::steady_clock::now();
  const pid_t pid = fork();
  if (pid < 0) throw std::runtime_error(std::string("fork failed: ") + std::strerror(errno));
  if (pid == 0) {
    setpgid(0, 0);  // its own process group, so that a timeout ends its children too
    const char* old = std::getenv("LD_LIBRARY_PATH");
    const std::string path = classic + (old && *old ? ":" + std::string(old) : "");
    setenv("LD_LIBRARY_PATH", path.c_str(), 1);
    setenv("FFCOMPAT_BACKEND", backend.c_str(), 1);
    setenv("FFCOMPAT_RUN_OUT", dir.c_str(), 1);
    if (o.frames > 0) setenv("FFCOMPAT_RUN_FRAMES", std::to_string(o.frames).c_str(), 1);
    else unsetenv("FFCOMPAT_RUN_FRAMES");
    auto set_or_clear = [](const char* name, const std::string& v) {
      if (v.empty()) unsetenv(name);
      else setenv(name, v.c_str(), 1);
    };
    set_or_clear("FFCOMPAT_RUN_KEYS", o.keys);
    set_or_clear("FFCOMPAT_RUN_CLICKS", o.clicks);
    set_or_clear("FFCOMPAT_RUN_SIZE", o.size);
    set_or_clear("FFCOMPAT_RUN_WINDOW", o.window ? "1" : "");
    if (!stdout_file.empty()) {
      const int fd = open(stdout_file.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
      if (fd >= 0) dup2(fd, 1), close(fd);
    }
    std::vector<char*> argv;
    for (const std::string& a : o.program) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    execvp(argv[0], argv.data());
    std::fprintf(stderr, "ffcompat run: cannot start %s: %s\n", argv[0], std::strerror(errno));
    _exit(127);
  }
  Outcome r;
  int status = 0;
  for (;;) {
    const pid_t done = waitpid(pid, &status, WNOHANG);
    if (done == pid) break;
    if (std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() > o.timeout) {
      kill(-pid, SIGKILL);
      kill(pid, SIGKILL);
      waitpid(pid, &status, 0);
      r.timed_out = true;
      break;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  kill(-pid, SIGKILL);  // what it left running in its group
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (!r.timed_out) {
    if (WIFEXITED(status)) r.status = WEXITSTATUS(status);
    if (WIFSIGNALED(status)) r.signal = WTERMSIG(status);
  }
  r.frames = count_frames(dir);
  return r;
}

// A run that did not end well, in words; empty when it did.
std::string failure(const RunOptions& o, const std::string& backend, const Outcome& r) {
  std::ostringstream why;
  const std::string who = o.program[0] + " on " + backend;
  if (r.timed_out) why << who << " did not finish within " << o.timeout << " s (--timeout)";
  else if (r.signal) why << who << " was killed by signal " << r.signal << " (" << strsignal(r.signal) << ")";
  else if (r.status == 127) why << who << " could not be started";
  else if (r.status != 0) why << who << " exited with status " << r.status;
  else if (r.frames == 0) why << who << " showed no frame";
  return why.str();
}

int expected_frames(const RunOptions& o) {
  if (o.frames > 0) return o.frames;
  return int(1 + std::max(glut::parse_keys(o.keys).size(), glut::parse_clicks(o.clicks).size()));
}

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

void check_options(const RunOptions& o) {
  if (o.program.empty()) throw CLI::ValidationError("run", "no program given: ffcompat run [options] -- PROG [ARGS...]");
  glut::parse_keys(o.keys);  // throws std::invalid_argument with what is wrong
  glut::parse_clicks(o.clicks);
  if (!o.size.empty()) {
    int w = 0, h = 0;
    char tail = 0;
    if (std::sscanf(o.size.c_str(), "%dx%d%c", &w, &h, &tail) != 2 || w <= 0 || h <= 0 || w > 16384 || h > 16384)
      throw std::invalid_argument("--size '" + o.size + "' is not WxH (e.g. 200x200)");
  }
  if (o.timeout <= 0) throw std::invalid_argument("--timeout must be more than 0 seconds");
  if (o.compare && o.window) throw std::invalid_argument("--compare runs headless; leave out --window");
  if (o.compare && o.backend == "mesa") throw std::invalid_argument("--compare runs mesa against --backend: name one of ours");
}

// The names FFCOMPAT_BACKEND takes in libGL.so.1: glsl and glsl-phong beside soft's and mesa where
// the GLSL backend is built (libGL.so.1 says which when it is not).
std::vector<std::string> run_backend_names() {
  std::vector<std::string> names = kBackendNames;
#ifdef FFCOMPAT_WITH_GLSL
  names.push_back("glsl"), names.push_back("glsl-phong");
#endif
  return names;
}

int run_single(const RunOptions& o, const std::string& classic) {
  const fs::path dir = o.out;
  const Outcome r = run_once(o, o.backend, dir, classic, o.json ? (dir / "stdout.txt").string() : "");
  const std::string why = failure(o, o.backend, r);
  const int expected = expected_frames(o);
  if (o.json) {
    nlohmann::json j = {{"backend", o.backend}, {"frames", r.frames},          {"expected_frames", expected},
                        {"out", dir.string()}, {"seconds", r.seconds},       {"ok", why.empty()}};
    if (!why.empty()) j["error"] = why;
    print_json(j);
  } else if (why.empty()) {
    std::printf("%d frame%s in %s (%s, %.2f s)\n", r.frames, r.frames == 1 ? "" : "s", dir.c_str(), o.backend.c_str(), r.seconds);
  }
  if (!why.empty()) {
    std::fprintf(stderr, "ffcompat run: %s\n", why.c_str());
    return 1;
  }
  if (r.frames < expected && !o.window)
    std::fprintf(stderr, "ffcompat run: note: %d of the %d frames asked for (the program ended the run itself)\n",
                 r.frames, expected);
  return 0;
}

// Mesa against ours: `ours` is --backend (soft unless named), its frames in OUT/<ours>/.
int run_compare(const RunOptions& o, const std::string& classic) {
  const fs::path dir = o.out;
  fs::create_directories(dir);
  clear_frames(dir);
  const std::string& ours = o.backend;
  const Outcome mesa = run_once(o, "mesa", dir / "mesa", classic, (dir / "mesa" / "stdout.txt").string());
  const Outcome soft = run_once(o, ours, dir / ours, classic, (dir / ours / "stdout.txt").string());
  std::vector<std::string> errors;
  for (const auto& [name, r] : {std::pair{std::string("mesa"), mesa}, std::pair{ours, soft}})
    if (std::string why = failure(o, name, r); !why.empty()) errors.push_back(why);
  if (mesa.frames != soft.frames)
    errors.push_back("frame counts differ: mesa " + std::to_string(mesa.frames) + ", " + ours + " " + std::to_string(soft.frames));
  const bool stdout_same = slurp(dir / "mesa" / "stdout.txt") == slurp(dir / ours / "stdout.txt");
  if (!stdout_same) errors.push_back("the program printed differently on mesa and on " + ours + " (" + (dir / "mesa" / "stdout.txt").string() +
                                     ", " + (dir / ours / "stdout.txt").string() + ")");
  nlohmann::json frames = nlohmann::json::array();
  int max_diff = 0;
  bool frames_ok = true;
  for (int i = 0; i < std::min(mesa.frames, soft.frames); ++i) {
    const image::Image a = image::read_png((dir / "mesa" / frame_name("frame", i)).string());
    const image::Image b = image::read_png((dir / ours / frame_name("frame", i)).string());
    if (a.width != b.width || a.height != b.height) {
      errors.push_back("frame " + std::to_string(i) + " sizes differ");
      frames_ok = false;
      continue;
    }
    const image::Diff d = image::compare(a, b);
    if (d.max_diff > 0) image::write_png((dir / frame_name("diff", i)).string(), image::heat_map(a, b));
    max_diff = std::max(max_diff, d.max_diff);
    frames_ok &= d.max_diff <= 1;
    frames.push_back({{"index", i}, {"max_diff", d.max_diff}, {"differing_share", d.differing_share}});
    if (!o.json)
      std::printf("frame %03d  max_diff %3d steps  differing %8.4f%%%s\n", i, d.max_diff, 100 * d.differing_share,
                  d.max_diff > 1 ? "  FAIL" : "");
  }
  const bool pass = errors.empty() && frames_ok && mesa.frames > 0;
  if (o.json) {
    nlohmann::json j = {{"frames", frames},           {"max_diff", max_diff},          {"pass", pass},
                        {"backend", ours},
                        {"frames_mesa", mesa.frames}, {"frames_" + ours, soft.frames},   {"stdout_same", stdout_same},
                        {"seconds_mesa", mesa.seconds}, {"seconds_" + ours, soft.seconds}};
    if (!errors.empty()) j["errors"] = errors;
    print_json(j);
  } else {
    std::printf("%s: %d frame%s, largest difference %d step%s (mesa %.2f s, %s %.2f s)\n", pass ? "pass" : "FAIL",
                int(frames.size()), frames.size() == 1 ? "" : "s", max_diff, max_diff == 1 ? "" : "s", mesa.seconds,
                ours.c_str(), soft.seconds);
  }
  for (const std::string& e : errors) std::fprintf(stderr, "ffcompat run: %s\n", e.c_str());
  // A program that could not run is an error (1); pictures that differ are a failed check (2).
  for (const auto& [name, r] : {std::pair{std::string("mesa"), mesa}, std::pair{ours, soft}})
    if (!failure(o, name, r).empty()) return 1;
  return pass ? 0 : 2;
}

}  // namespace

void add_run(CLI::App& app) {
  auto o = std::make_shared<RunOptions>();
  auto* cmd = app.add_subcommand("run", "Run a classic GLUT program on ffcompat's libGL/GLU/GLUT, headless, frames as PNGs");
  cmd->add_option("--backend", o->backend, "Renderer: soft (ours), glsl (our state, GLSL shaders) or mesa, or another of `ffcompat --version`; with --compare, the one compared with mesa")
      ->check(CLI::IsMember(run_backend_names()))
      ->capture_default_str();
  cmd->add_option("--size", o->size, "Force every window to WxH (FFCOMPAT_RUN_SIZE)");
  cmd->add_option("--frames", o->frames, "Stop after N frames (default: one more than the longest input script)")
      ->check(CLI::Range(1, 100000));
  cmd->add_option("--keys", o->keys, "Keys, one per frame after the first: characters, <up>, <f1>, <esc>, <ctrl+a>, <wait>");
  cmd->add_option("--clicks", o->clicks, "Mouse, one per frame after the first: 'X,Y[,left|middle|right]', 'X,Y>X2,Y2' (drag), 'X,Y,move', wait");
  cmd->add_option("--out", o->out, "Folder for frame-NNN.png (with --compare: mesa/, <backend>/ and diff-NNN.png)")->required();
  cmd->add_flag("--compare", o->compare, "Run on mesa and on --backend (soft) with the same input; compare frame by frame (exit 2 past 1 step)");
  cmd->add_flag("--json", o->json, "Print the result as JSON (the program's stdout goes to OUT/stdout.txt)");
  cmd->add_option("--timeout", o->timeout, "Seconds a run may take before it is stopped and counted as a failure")->capture_default_str();
  cmd->add_flag("--window", o->window, "Show the frames in a window (GLFW) and take real input");
  cmd->add_option("program", o->program, "The program and its arguments, after --")->expected(-1);
  cmd->callback([o] {
    try {
      check_options(*o);
    } catch (const std::invalid_argument& e) {
      throw CLI::ValidationError("run", e.what());
    }
    const std::string classic = classic_dir();
    const int code = o->compare ? run_compare(*o, classic) : run_single(*o, classic);
    if (code != 0) throw CLI::RuntimeError(code);
  });
}

}  // namespace ffc::cli
