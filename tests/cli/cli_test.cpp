// The ffcompat command line as a script sees it: --json output and exit codes.
#include <algorithm>
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <sys/wait.h>

#include <array>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "../temp_dir.h"
#include "image/image.h"
#include "simd/target.h"
#include "raster/isa.h"

namespace {

namespace fs = std::filesystem;

struct Result {
  int status;
  std::string out;
};

// env: assignments put before the command ("NAME=value").
Result ffcompat(const std::string& args, const std::string& env = "") {
  const std::string cmd = env + (env.empty() ? "" : " ") + std::string(FFCOMPAT_EXE) + " " + args + " 2>/dev/null";
  FILE* p = popen(cmd.c_str(), "r");
  std::string out;
  std::array<char, 4096> buf;
  while (size_t n = fread(buf.data(), 1, buf.size(), p)) out.append(buf.data(), n);
  const int st = pclose(p);
  return {WIFEXITED(st) ? WEXITSTATUS(st) : -1, out};
}

fs::path tmp(const std::string& name) { return ffc::test::temp_path(name); }

TEST(Cli, NormalsJsonIsTheSeedsSmoothTable) {
  const Result r = ffcompat("normals --scene cube --normals average --json");
  ASSERT_EQ(r.status, 0);
  const auto j = nlohmann::json::parse(r.out);
  ASSERT_EQ(j.size(), 8u);
  EXPECT_EQ(j[1]["vertex"], 1);
  EXPECT_EQ(j[1]["position"], nlohmann::json({1.0, 1.0, 1.0}));
  EXPECT_NEAR(j[1]["normal"][0].get<double>(), 0.8164965809277261, 1e-15);
  EXPECT_NEAR(j[1]["normal"][1].get<double>(), 0.4082482904638631, 1e-15);
}

TEST(Cli, NormalsFaceGivesOneRowPerCorner) {
  const Result r = ffcompat("normals --scene icosphere --depth 1 --normals face --json");
  ASSERT_EQ(r.status, 0);
  EXPECT_EQ(nlohmann::json::parse(r.out).size(), 80u * 3);
}

TEST(Cli, RenderWritesThePictureItReports) {
  const fs::path out = tmp("render.png");
  const Result r = ffcompat("render --scene icosphere --depth 2 --shade flat --size 64x48 --json --out " + out.string());
  ASSERT_EQ(r.status, 0);
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["width"], 64);
  EXPECT_EQ(j["height"], 48);
  EXPECT_EQ(j["shade"], "flat");
  EXPECT_EQ(j["normals"], "sphere");
  EXPECT_EQ(j["depth"], 2);
  EXPECT_EQ(j["backend"], "mesa");
  const auto img = ffc::image::read_png(out.string());
  EXPECT_EQ(img.width, 64);
  EXPECT_EQ(img.height, 48);
}

TEST(Cli, CompareAPictureWithItselfAndWithAnother) {
  const fs::path a = tmp("a.png"), b = tmp("b.png"), d = tmp("d.png");
  ASSERT_EQ(ffcompat("render --scene cube --size 80x80 --out " + a.string()).status, 0);
  ASSERT_EQ(ffcompat("render --scene cube --size 80x80 --cam-angle 30 --out " + b.string()).status, 0);
  auto same = nlohmann::json::parse(ffcompat("compare --json " + a.string() + " " + a.string()).out);
  EXPECT_EQ(same["max_diff"], 0);
  EXPECT_TRUE(same["psnr"].is_null());  // infinite
  const Result r = ffcompat("compare --json " + a.string() + " " + b.string() + " --diff " + d.string());
  ASSERT_EQ(r.status, 0);
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_GT(j["max_diff"].get<int>(), 0);
  EXPECT_GT(j["differing_share"].get<double>(), 0.0);
  EXPECT_LT(j["differing_share"].get<double>(), 1.0);
  EXPECT_TRUE(fs::exists(d));
}

TEST(Cli, ShadingWritesFourPicturesASheetAndThreeComparisons) {
  const fs::path dir = tmp("shading");
  const Result r = ffcompat("shading --scene icosphere --depth 1 --size 96x96 --json --out " + dir.string());
  ASSERT_EQ(r.status, 0);
  const auto j = nlohmann::json::parse(r.out);
  for (const char* k : {"flat_face", "smooth_face", "flat_average", "smooth_average"})
    EXPECT_TRUE(fs::exists(j["images"][k].get<std::string>())) << k;
  EXPECT_TRUE(fs::exists(j["sheet"].get<std::string>()));
  ASSERT_EQ(j["comparisons"].size(), 3u);
  // With face normals, a directional light and no specular, every vertex of a triangle has the
  // same colour: GL_FLAT and GL_SMOOTH agree exactly. With averaged normals they do not.
  EXPECT_EQ(j["comparisons"][0]["max_diff"], 0);
  EXPECT_GT(j["comparisons"][1]["max_diff"].get<int>(), 0);
}

TEST(Cli, ShadingTheCubeAddsAThreeFacesViewToTheSeedsOwn) {
  const fs::path dir = tmp("shading_cube");
  const Result r = ffcompat("shading --scene cube --size 96x96 --json --out " + dir.string());
  ASSERT_EQ(r.status, 0);
  const auto j = nlohmann::json::parse(r.out);
  ASSERT_EQ(j["comparisons"].size(), 3u);  // the seed's camera, as before
  ASSERT_TRUE(j.contains("three_faces"));
  const auto& t = j["three_faces"];
  EXPECT_EQ(t["cam_angle"], 35.0);
  EXPECT_EQ(t["cam_height"], 2.5);
  for (const char* k : {"flat_face", "smooth_face", "flat_average", "smooth_average"})
    EXPECT_TRUE(fs::exists(t["images"][k].get<std::string>())) << k;
  ASSERT_EQ(t["comparisons"].size(), 3u);
  // From there GL_FLAT paints each face's two triangles apart (the point light's direction
  // differs per vertex), and averaged normals change the picture.
  EXPECT_GT(t["comparisons"][0]["max_diff"].get<int>(), 0);
  EXPECT_GT(t["comparisons"][2]["max_diff"].get<int>(), 0);
  // The sheet: four rows of three 96-pixel cells, with labels and the legend around them.
  const ffc::image::Image sheet = ffc::image::read_png(j["sheet"].get<std::string>());
  EXPECT_GT(sheet.width, 3 * 96);
  EXPECT_GT(sheet.height, 4 * 96);
  // A camera of the user's own: one view only.
  const Result moved = ffcompat("shading --scene cube --size 64x64 --cam-angle 20 --json --out " + tmp("moved").string());
  ASSERT_EQ(moved.status, 0);
  EXPECT_FALSE(nlohmann::json::parse(moved.out).contains("three_faces"));
}

TEST(Cli, StressEndsWithASummaryLine) {
  const Result r = ffcompat("stress --case shininess_0 --no-mesa");
  ASSERT_EQ(r.status, 0) << r.out;
  EXPECT_NE(r.out.find("\nstress: 1 cases in "), std::string::npos) << r.out;
  EXPECT_NE(r.out.find(": 1 ok, 0 mesa-deviation, 0 FAIL; 0 crashed, 0 NaN pixels, 0 NaN vertices;"), std::string::npos)
      << r.out;
}

TEST(Cli, BadInputIsAnErrorNotACrash) {
  EXPECT_EQ(ffcompat("render --scene teapot --out " + tmp("x.png").string()).status, 1);
  EXPECT_EQ(ffcompat("render --scene cube --shade phong --out " + tmp("x.png").string()).status, 1);
  EXPECT_EQ(ffcompat("render --scene cube --size 10by10 --out " + tmp("x.png").string()).status, 1);
  EXPECT_EQ(ffcompat("render --scene icosphere --depth 40 --out " + tmp("x.png").string()).status, 1);
  EXPECT_EQ(ffcompat("compare /nonexistent/a.png /nonexistent/b.png").status, 1);
  EXPECT_EQ(ffcompat("frobnicate").status, 1);
}

// stderr too: the messages are part of the contract.
Result ffcompat_err(const std::string& args) {
  const std::string cmd = "timeout 60 " + std::string(FFCOMPAT_EXE) + " " + args + " 2>&1 >/dev/null";
  FILE* p = popen(cmd.c_str(), "r");
  std::string out;
  std::array<char, 4096> buf;
  while (size_t n = fread(buf.data(), 1, buf.size(), p)) out.append(buf.data(), n);
  const int st = pclose(p);
  return {WIFEXITED(st) ? WEXITSTATUS(st) : -1, out};
}

void expect_refused(const std::string& args, const std::string& message) {
  SCOPED_TRACE(args);
  const Result r = ffcompat_err(args);
  EXPECT_EQ(r.status, 1);  // the one code for usage and input errors, whichever layer finds them
  EXPECT_NE(r.out.find(message), std::string::npos) << r.out;
}

TEST(Cli, OptionsACommandDoesNotUseAreRefusedNamingWhatApplies) {
  expect_refused("check --scene cube --backend soft-double", "--backend: soft-double not in {soft,glsl}");
  expect_refused("bench --scene cube --frames 1 --backend soft", "bench takes --backends");
  // An unknown name is refused with the real choices (every backend this program has, glsl too).
  expect_refused("bench --scene cube --frames 1 --backends mesa,vulkan", "unknown backend 'vulkan' (");
  expect_refused("bench --scene cube --frames 1 --backends mesa,vulkan", "glsl");
  expect_refused("render --scene icosphere --cam-angle 30 --out " + tmp("x.png").string(), "the built-in icosphere's camera is fixed");
  expect_refused("render --scene cube --backend vulkan --out " + tmp("x.png").string(), "vulkan");
  expect_refused("check --level vertex --scene cube --max-diff 3", "--max-diff and --out apply to --level pixel");
  expect_refused("check --level pixel --scene cube --tolerance 1", "--tolerance applies to --level vertex");
}

TEST(Cli, HelpListsEveryBackend) {
  const Result r = ffcompat("render --help");
  EXPECT_EQ(r.status, 0);
  for (const char* b : {"mesa", "soft", "soft-double", "glsl", "glsl-phong"}) EXPECT_NE(r.out.find(b), std::string::npos) << b;
  // check names ours to set against Mesa: soft or glsl.
  EXPECT_NE(ffcompat("check --help").out.find("glsl (the generated shaders"), std::string::npos);
}

TEST(Cli, AMistypedCommandNamesTheKnownOnes) {
  const Result r = ffcompat_err("rendr --scene cube");
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.out.find("unknown command 'rendr'"), std::string::npos) << r.out;
  for (const char* c : {"render", "normals", "compare", "shading", "check", "bench", "report", "stress"})
    EXPECT_NE(r.out.find(c), std::string::npos) << c;
  EXPECT_EQ(ffcompat_err("").status, 1);
}

TEST(Cli, ParseErrorsExitWithOneNotCli11sCodes) {
  // CLI11 gave 105 to 109 for these; every usage error is 1 now.
  EXPECT_EQ(ffcompat("render --scene cube").status, 1);                          // --out missing
  EXPECT_EQ(ffcompat("render --scene cube --out " + tmp("x.png").string() + " --frobnicate").status, 1);  // unknown option
  EXPECT_EQ(ffcompat("render --scene cube --depth three --out " + tmp("x.png").string()).status, 1);  // not a number
  EXPECT_EQ(ffcompat("render --scene cube --out " + tmp("x.png").string() + " extra").status, 1);   // extra argument
  EXPECT_EQ(ffcompat("--help").status, 0);
}

TEST(Cli, IcosphereDepthBeyondTheMemoryLimitIsRefusedAtOnceSayingWhy) {
  // Depths 11 and 12 passed validation and died of bad_alloc after half a minute.
  for (const std::string& cmd : {"render --scene icosphere --depth 11 --out " + tmp("x.png").string(),
                                 std::string("normals --scene icosphere --depth 12"),
                                 std::string("check --scene icosphere --depth 11")}) {
    SCOPED_TRACE(cmd);
    const auto t0 = std::chrono::steady_clock::now();
    const Result r = ffcompat_err(cmd);
    EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(), 5.0);
    EXPECT_EQ(r.status, 1);
    EXPECT_NE(r.out.find("beyond the limit of 10"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("quadruples the triangles and the memory"), std::string::npos) << r.out;
  }
}

TEST(Cli, ASceneFileThatIsAFifoOrADeviceIsRefusedNamingIt) {
  const fs::path fifo = tmp("fifo.toml"), zero = tmp("zero.toml");
  fs::remove(fifo), fs::remove(zero);
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  fs::create_symlink("/dev/zero", zero);
  for (const fs::path& p : {fifo, zero}) {
    // (ffcompat_err runs under `timeout`): before the fix the FIFO blocked forever and /dev/zero read until memory ran out.
    const Result r = ffcompat_err("render --scene " + p.string() + " --out " + tmp("x.png").string());
    EXPECT_EQ(r.status, 1) << p;
    EXPECT_NE(r.out.find(p.string() + ": is not a regular file"), std::string::npos) << r.out;
  }
  fs::remove(fifo), fs::remove(zero);
}


// Every draw pattern, the glDrawArrays soup's repeat finding on both threads included (depth 4:
// 15,360 corners, above kSoupParallel): nothing allocated per frame (the soup once made a vector
// a draw).
TEST(Cli, BenchAllocatesNothingPerFrameForEveryDrawPattern) {
  for (const char* draw : {"elements", "arrays", "immediate"}) {
    const Result r = ffcompat(std::string("bench --scene icosphere --depth 4 --frames 4 --block 2 --backends soft --json --draw ") + draw);
    ASSERT_EQ(r.status, 0) << draw;
    const auto j = nlohmann::json::parse(r.out);
    EXPECT_EQ(j["allocations_per_frame"]["soft"], 0.0) << draw;
  }
}

TEST(Cli, BenchReportsMediansTheRatioAndNoAllocationPerFrame) {
  const Result r = ffcompat("bench --scene icosphere --depth 3 --frames 6 --block 3 --backends mesa,soft,soft-double --json");
  ASSERT_EQ(r.status, 0);
  const auto j = nlohmann::json::parse(r.out);
  const double mesa = j["median_ms"]["mesa"], soft = j["median_ms"]["soft"];
  EXPECT_GT(mesa, 0);
  EXPECT_GT(soft, 0);
  EXPECT_DOUBLE_EQ(j["speedup"].get<double>(), mesa / soft);
  EXPECT_EQ(j["frames"], 6);
  EXPECT_GE(j["spread"]["soft"]["max_ms"].get<double>(), soft);
  // The memory goal: in steady state our pipeline allocates nothing, on either path.
  EXPECT_EQ(j["allocations_per_frame"]["soft"], 0.0);
  EXPECT_EQ(j["allocations_per_frame"]["soft-double"], 0.0);
  // Which rasterizer ran: the kernels on the best Highway target the CPU has (src/simd/target.h),
  // the scalar loops on request.
  EXPECT_EQ(j["soft_kernels"], ffc::simd::available().front());
  const Result scalar = ffcompat("bench --scene cube --frames 2 --block 1 --backends soft --threads 1 --json", "FFCOMPAT_SCALAR=1");
  ASSERT_EQ(scalar.status, 0);
  const auto js = nlohmann::json::parse(scalar.out);
  EXPECT_EQ(js["soft_kernels"], "scalar");
  EXPECT_EQ(js["threads"], 1);
  EXPECT_NE(ffcompat("bench --scene cube --frames 2 --threads -1").status, 0);
}

// --runs repeats the measurement: each run's medians and speed-up, the median speed-up of the runs
// and its spread, the medians the median of the runs' medians.
TEST(Cli, BenchRunsReportEachRunAndTheSpread) {
  const Result r = ffcompat("bench --scene cube --frames 3 --block 3 --runs 3 --backends mesa,soft --json");
  ASSERT_EQ(r.status, 0);
  const auto j = nlohmann::json::parse(r.out);
  ASSERT_EQ(j["runs"].size(), 3u);
  std::vector<double> ratios, soft;
  for (const auto& run : j["runs"]) {
    ratios.push_back(run["speedup"].get<double>());
    soft.push_back(run["median_ms"]["soft"].get<double>());
    EXPECT_DOUBLE_EQ(run["speedup"].get<double>(), run["median_ms"]["mesa"].get<double>() / run["median_ms"]["soft"].get<double>());
  }
  std::sort(ratios.begin(), ratios.end()), std::sort(soft.begin(), soft.end());
  EXPECT_DOUBLE_EQ(j["speedup_spread"]["min"].get<double>(), ratios[0]);
  EXPECT_DOUBLE_EQ(j["speedup_spread"]["median"].get<double>(), ratios[1]);
  EXPECT_DOUBLE_EQ(j["speedup_spread"]["max"].get<double>(), ratios[2]);
  EXPECT_DOUBLE_EQ(j["speedup"].get<double>(), ratios[1]);
  EXPECT_DOUBLE_EQ(j["median_ms"]["soft"].get<double>(), soft[1]);
  EXPECT_NE(ffcompat("bench --scene cube --frames 2 --runs 0").status, 0);
}

// --mesa-isa same gives llvmpipe only the instructions of soft's target (Mesa's
// GALLIUM_OVERRIDE_CPU_CAPS), and llvmpipe's renderer string shows the vector width it then uses:
// 128 bits for SSE4. Native is the default; a value that names nothing, or same without Mesa, is
// refused.
TEST(Cli, BenchMesaIsaSameRestrictsLlvmpipeToSoftsTarget) {
#if defined(__x86_64__)
  const std::vector<std::string> targets = ffc::simd::available();
  if (std::find(targets.begin(), targets.end(), "sse4") == targets.end()) GTEST_SKIP() << "no SSE4 here";
  const Result same = ffcompat("bench --scene cube --frames 1 --backends mesa,soft --mesa-isa same --json", "FFCOMPAT_SIMD=sse4");
  ASSERT_EQ(same.status, 0);
  const auto j = nlohmann::json::parse(same.out);
  EXPECT_EQ(j["soft_kernels"], "sse4");
  EXPECT_EQ(j["mesa_cpu_caps"], "sse4.1");
  EXPECT_NE(j["mesa_renderer"].get<std::string>().find("128 bits"), std::string::npos) << j["mesa_renderer"];
  const Result native = ffcompat("bench --scene cube --frames 1 --backends mesa,soft --json", "FFCOMPAT_SIMD=sse4");
  ASSERT_EQ(native.status, 0);
  EXPECT_EQ(nlohmann::json::parse(native.out)["mesa_cpu_caps"], "native");
#endif
  expect_refused("bench --scene cube --frames 1 --backends soft --mesa-isa same", "no mesa in --backends");
  EXPECT_NE(ffcompat("bench --scene cube --frames 1 --mesa-isa sse9").status, 0);
}

// Deviation 74 (docs/deviations.md): llvmpipe without FMA (GALLIUM_OVERRIDE_CPU_CAPS=sse4.1) rounds
// its multiply-adds twice, and a depth tie on the seed cube's silhouette from this camera goes the
// other way. Soft follows the llvmpipe beside it: the check passes on both. Where the two are
// chosen apart (FFCOMPAT_LLVMPIPE_FMA), the check fails and names the cause.
TEST(Cli, PixelCheckFollowsLlvmpipeWithOrWithoutFma) {
#if defined(__x86_64__)
  if (!__builtin_cpu_supports("fma")) GTEST_SKIP() << "llvmpipe has no FMA here: the fused side cannot be run";
  const std::string args = "check --level pixel --scene cube --shade flat --normals face --cam-angle 279 --cam-height -0.5 --json --out " +
                           tmp("fma_rounding").string();
  for (const char* caps : {"", "GALLIUM_OVERRIDE_CPU_CAPS=sse4.1"}) {
    const Result same = ffcompat(args, caps);
    EXPECT_EQ(same.status, 0) << caps;
    const auto j = nlohmann::json::parse(same.out);
    EXPECT_EQ(j["max_diff"], 0) << caps;
    EXPECT_EQ(j["known_mesa_deviations"], nlohmann::json::array()) << caps;
  }
  for (const char* apart : {"FFCOMPAT_LLVMPIPE_FMA=0", "GALLIUM_OVERRIDE_CPU_CAPS=sse4.1 FFCOMPAT_LLVMPIPE_FMA=1"}) {
    const Result r = ffcompat(args, apart);
    EXPECT_EQ(r.status, 2) << apart;
    const auto j = nlohmann::json::parse(r.out);
    EXPECT_GT(j["max_diff"].get<int>(), 1) << apart;
    EXPECT_EQ(j["known_mesa_deviations"], nlohmann::json::array({"llvmpipe-fma-rounding"})) << apart;
  }
  EXPECT_NE(ffcompat(args, "FFCOMPAT_LLVMPIPE_FMA=yes").status, 0);
#else
  GTEST_SKIP() << "GALLIUM_OVERRIDE_CPU_CAPS is x86's";
#endif
}

#ifdef FFCOMPAT_WITH_GLSL
// The GLSL backend keeps its buffers, lists and uniform values: after the warm-up frame (programs
// compiled, states seen) a frame allocates nothing, on each draw path, with two programs a frame
// (the cube: unlit and lit) and with twelve materials on one program (material_grid).
TEST(Cli, GlslBenchAllocatesNothingPerFrame) {
  const fs::path grid = fs::path(__FILE__).parent_path().parent_path().parent_path() / "scenes" / "material_grid.toml";
  for (const std::string& scene : {std::string("--scene icosphere --depth 3"), std::string("--scene cube"), "--scene '" + grid.string() + "'"})
    for (const char* draw : {"elements", "arrays", "immediate"}) {
      const std::string args = "bench " + scene + " --draw " + draw + " --frames 4 --block 2 --backends glsl --json";
      const Result r = ffcompat(args);
      ASSERT_EQ(r.status, 0) << args;
      const auto j = nlohmann::json::parse(r.out);
      EXPECT_GT(j["median_ms"]["glsl"].get<double>(), 0) << args;
      EXPECT_EQ(j["allocations_per_frame"]["glsl"], 0.0) << args;
    }
}
#endif

}  // namespace
