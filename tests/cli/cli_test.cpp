// The ffcompat command line as a script sees it: --json output and exit codes.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "image/image.h"

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

fs::path tmp(const std::string& name) {
  const fs::path d = fs::temp_directory_path() / "ffcompat_cli_test";
  fs::create_directories(d);
  return d / name;
}

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

TEST(Cli, BadInputIsAnErrorNotACrash) {
  EXPECT_EQ(ffcompat("render --scene teapot --out /tmp/x.png").status, 1);
  EXPECT_EQ(ffcompat("render --scene cube --shade phong --out /tmp/x.png").status, 1);
  EXPECT_EQ(ffcompat("render --scene cube --size 10by10 --out /tmp/x.png").status, 1);
  EXPECT_NE(ffcompat("render --scene icosphere --depth 40 --out /tmp/x.png").status, 0);
  EXPECT_EQ(ffcompat("compare /nonexistent/a.png /nonexistent/b.png").status, 1);
  EXPECT_NE(ffcompat("frobnicate").status, 0);
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
  // Which rasterizer ran: the AVX-512 kernels where the CPU has them, the scalar loops on request.
  const bool avx512 = __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512vl") && __builtin_cpu_supports("avx512dq");
  EXPECT_EQ(j["soft_kernels"], avx512 ? "avx512" : "scalar");
  const Result scalar = ffcompat("bench --scene cube --frames 2 --block 1 --backends soft --threads 1 --json", "FFCOMPAT_SCALAR=1");
  ASSERT_EQ(scalar.status, 0);
  const auto js = nlohmann::json::parse(scalar.out);
  EXPECT_EQ(js["soft_kernels"], "scalar");
  EXPECT_EQ(js["threads"], 1);
  EXPECT_NE(ffcompat("bench --scene cube --frames 2 --threads -1").status, 0);
}

}  // namespace
