// ffcompat seeds: seed 000's fixed-function cube (the "mesa" backend) against seed 001's GLSL
// cubes (an EGL core-profile context), as a script reads it: the figures its --json gives must
// say what the handouts' equations say.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "../temp_dir.h"
#ifdef FFCOMPAT_WITH_EGL
#include "platform/egl_context.h"
#endif

namespace {

namespace fs = std::filesystem;

// Runs ffcompat with `args`; its exit status, and its standard output in `out`.
int run_seeds(const std::string& args, std::string& out) {
  const fs::path captured = ffc::test::temp_path("seeds-stdout.txt");
  const int st = std::system((std::string(FFCOMPAT_EXE) + " " + args + " >" + captured.string() + " 2>/dev/null").c_str());
  std::ifstream in(captured);
  std::stringstream text;
  text << in.rdbuf();
  out = text.str();
  return WIFEXITED(st) ? WEXITSTATUS(st) : -1;
}

// The difference row "from -> to" of a camera.
nlohmann::json row(const nlohmann::json& camera, const std::string& from, const std::string& to) {
  for (const auto& r : camera["differences"])
    if (r["from"] == from && r["to"] == to) return r;
  ADD_FAILURE() << "no row " << from << " -> " << to;
  return nlohmann::json::object();
}

class Seeds : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
#ifndef FFCOMPAT_WITH_EGL
    why_ = "built without EGL";
    return;
#else
    if (!ffc::platform::EglContext::available(&why_)) return;
    dir_ = ffc::test::temp_path("seeds");
    std::string out;
    status_ = run_seeds("seeds --size 96 --json --out " + dir_.string(), out);
    if (status_ == 0) j_ = nlohmann::json::parse(out);
#endif
  }
  void SetUp() override {
    if (!why_.empty()) GTEST_SKIP() << why_;
    ASSERT_EQ(status_, 0);
  }
  static inline std::string why_;
  static inline int status_ = -1;
  static inline fs::path dir_;
  static inline nlohmann::json j_;
};

TEST_F(Seeds, WritesThePicturesAndSheets) {
  ASSERT_EQ(j_["cameras"].size(), 3u);  // the seeds' camera, three faces, the highlight inside
  for (const char* f : {"sheet.png", "chain.png", "guard.png", "ff.png", "gouraud.png", "phong.png",
                        "highlight_diff_gouraud_vs_phong.png", "guard_step6_nl_test.png"})
    EXPECT_TRUE(fs::exists(dir_ / f)) << f;
  EXPECT_EQ(j_["cameras"][0]["pictures"].size(), 9u);
}

TEST_F(Seeds, GlslDoingGlsEquationIsMesasFixedFunction) {
  // The same equation (eye space, half vector, N.L test, clamped vertex colours) in a generated
  // shader and in Mesa's fixed function: within a step, on a few edge pixels at most.
  for (const auto& camera : j_["cameras"]) {
    const auto r = row(camera, "ff_local", "glsl_ff");
    EXPECT_LE(r["max_diff"].get<int>(), 1) << camera["label"];
    EXPECT_LT(r["differing_share"].get<double>(), 0.01) << camera["label"];
    // World space and eye space light alike under a rigid view.
    EXPECT_LE(row(camera, "glsl_ff", "glsl_world")["max_diff"].get<int>(), 1) << camera["label"];
  }
}

TEST_F(Seeds, TheReflectionVectorShrinksTheHighlight) {
  // Seen head-on, GL's half vector gives the front face a wide highlight (peak near 116 steps);
  // the handout's V.R, its peak outside the face, only the 11 steps at the corner v1:
  // pow(14/sqrt(238), 32) = 0.045.
  const auto r = row(j_["cameras"][0], "glsl_unclamped", "glsl_reflect");
  EXPECT_GT(r["specular_peak"][0].get<int>(), 100);
  EXPECT_NEAR(r["specular_peak"][1].get<int>(), 11, 1);
}

TEST_F(Seeds, PhongFindsTheHighlightGouraudMisses) {
  const auto r = row(j_["cameras"][2], "gouraud", "phong");  // the light's mirror image inside the face
  EXPECT_LT(r["specular_peak"][0].get<int>(), 128);
  EXPECT_GE(r["specular_peak"][1].get<int>(), 250);
}

TEST_F(Seeds, TheMissingNlTestShowsOnlyWithAveragedNormals) {
  const auto& g = j_["nl_guard_sweep"];
  EXPECT_EQ(g["face_normals"]["cameras"], 468);
  // Face normals: a face the light does not reach is seen only at angles where V.R stays small.
  EXPECT_LT(g["face_normals"]["max_steps"].get<double>(), 1);
  // Averaged normals lean past the silhouette: full highlights where N.L < 0.
  EXPECT_GT(g["averaged_normals"]["max_steps"].get<double>(), 200);
  EXPECT_GT(g["averaged_normals"]["cameras_affected"].get<int>(), 100);
  const auto& step6 = g["averaged_normals"]["pictures"][1];
  EXPECT_EQ(step6["step"], 6);
  EXPECT_GT(step6["max_diff"].get<int>(), 200);
  EXPECT_LT(step6["highlight_pixels"][1].get<int>(), step6["highlight_pixels"][0].get<int>() / 4);
}

TEST(SeedsUsage, BadInputIsAnError) {
  std::string out;
  EXPECT_EQ(run_seeds("seeds --json", out), 1);  // --out is required
  EXPECT_EQ(run_seeds("seeds --size 5 --out " + ffc::test::temp_path("small").string(), out), 1);
}

}  // namespace
