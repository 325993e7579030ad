// ffcompat with --scene naming a TOML scene file: run from the repository root as a user would,
// overrides from the command line, and a bad file reported on stderr as file:line:column.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "../temp_dir.h"
#include "image/image.h"

namespace {

namespace fs = std::filesystem;

const fs::path repo = fs::path(__FILE__).parent_path().parent_path().parent_path();

struct Outcome {
  int status;
  std::string out, err;
};

fs::path tmp(const std::string& name) { return ffc::test::temp_path(name); }

// Runs ffcompat in the repository root, so scene paths are the ones a user types.
Outcome run(const std::string& args) {
  const fs::path err = tmp("stderr.txt");
  const std::string cmd = "cd '" + repo.string() + "' && " + FFCOMPAT_EXE + " " + args + " 2>'" + err.string() + "'";
  FILE* p = popen(cmd.c_str(), "r");
  std::string out;
  std::array<char, 4096> buf;
  while (size_t n = fread(buf.data(), 1, buf.size(), p)) out.append(buf.data(), n);
  const int st = pclose(p);
  std::stringstream e;
  e << std::ifstream(err).rdbuf();
  return {WIFEXITED(st) ? WEXITSTATUS(st) : -1, out, e.str()};
}

TEST(CliSceneFile, RenderSpotlightWritesThePictureItReports) {
  const fs::path out = tmp("spotlight.png");
  const Outcome r = run("render --scene scenes/spotlight.toml --out " + out.string() + " --json");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.err, "");
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["scene"], "spotlight");
  EXPECT_EQ(j["file"], "scenes/spotlight.toml");
  EXPECT_EQ(j["width"], 512);
  EXPECT_EQ(j["height"], 512);
  EXPECT_EQ(j["shade"], "smooth");
  EXPECT_EQ(j["normals"], "mixed");  // the floor's averaged, the sphere's, the box's faces
  EXPECT_EQ(j["depth"], 3);          // its icosphere's
  EXPECT_EQ(j["backend"], "mesa");
  EXPECT_EQ(j["out"], out.string());
  const auto img = ffc::image::read_png(out.string());
  EXPECT_EQ(img.width, 512);
  EXPECT_EQ(img.height, 512);
}

TEST(CliSceneFile, CommandLineOptionsOverrideTheFile) {
  const fs::path out = tmp("small.png");
  const Outcome r = run("render --scene scenes/icosphere.toml --size 64x48 --shade flat --normals face --depth 1 --json --out " +
                    out.string());
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["width"], 64);
  EXPECT_EQ(j["height"], 48);
  EXPECT_EQ(j["shade"], "flat");
  EXPECT_EQ(j["normals"], "face");
  EXPECT_EQ(j["depth"], 1);
  EXPECT_EQ(ffc::image::read_png(out.string()).width, 64);
  // The file's picture and the built-in scene's are the same file with the same overrides.
  const fs::path builtin = tmp("small_builtin.png");
  ASSERT_EQ(run("render --scene icosphere --size 64x48 --shade flat --normals face --depth 1 --out " + builtin.string()).status, 0);
  const auto same = nlohmann::json::parse(run("compare --json " + out.string() + " " + builtin.string()).out);
  EXPECT_EQ(same["max_diff"], 0);
}

TEST(CliSceneFile, NormalsAndShadingTakeFiles) {
  const Outcome n = run("normals --scene scenes/two_sided.toml --json");
  ASSERT_EQ(n.status, 0) << n.err;
  const auto rows = nlohmann::json::parse(n.out);
  EXPECT_EQ(rows.size(), 385u);  // the bowl's vertices, with the file's normals
  EXPECT_NEAR(rows[0]["normal"][1].get<double>(), -1.0, 1e-6);
  const Outcome several = run("normals --scene scenes/spotlight.toml --json");
  ASSERT_EQ(several.status, 0) << several.err;
  const auto s = nlohmann::json::parse(several.out);
  EXPECT_EQ(s.front()["mesh"], 0);
  EXPECT_EQ(s.back()["mesh"], 2);
  const Outcome sh = run("shading --scene scenes/material_grid.toml --size 96x72 --json --out " + tmp("grid").string());
  ASSERT_EQ(sh.status, 0) << sh.err;
  const auto j = nlohmann::json::parse(sh.out);
  EXPECT_EQ(j["comparisons"].size(), 3u);
  EXPECT_EQ(j["scene"]["width"], 96);
}

TEST(CliSceneFile, ABadFileExitsOneWithFileLineColumnOnStderr) {
  const fs::path bad = tmp("bad.toml");
  std::ofstream(bad) << "size = [64, 64]\n\n[[light]]\nspot_cutoff = 95\n\n[[mesh]]\nsource = \"cube\"\n";
  const Outcome r = run("render --scene " + bad.string() + " --out " + tmp("never.png").string());
  EXPECT_EQ(r.status, 1);
  EXPECT_EQ(r.out, "");
  EXPECT_NE(r.err.find(bad.string() + ":4:15: light[0].spot_cutoff: 95 is outside GL's range"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(tmp("never.png")));

  const Outcome missing = run("normals --scene scenes/absent.toml --json");
  EXPECT_EQ(missing.status, 1);
  EXPECT_NE(missing.err.find("scenes/absent.toml: the scene file does not exist"), std::string::npos) << missing.err;

  std::ofstream(tmp("syntax.toml")) << "shade = \"flat\n";
  const Outcome s = run("render --scene " + tmp("syntax.toml").string() + " --out " + tmp("never.png").string());
  EXPECT_EQ(s.status, 1);
  EXPECT_NE(s.err.find(tmp("syntax.toml").string() + ":1:"), std::string::npos) << s.err;
}

TEST(CliSceneFile, OptionsThatDoNotFitAFileAreErrors) {
  EXPECT_EQ(run("render --scene scenes/cube.toml --cam-angle 30 --out " + tmp("x.png").string()).status, 1);
  EXPECT_EQ(run("render --scene scenes/cube.toml --normals file --out " + tmp("x.png").string()).status, 1);
  EXPECT_EQ(run("render --scene scenes/cube.toml --shade phong --out " + tmp("x.png").string()).status, 1);
  EXPECT_EQ(run("render --scene cube --normals file --out " + tmp("x.png").string()).status, 1);
  const Outcome r = run("render --scene teapot --out " + tmp("x.png").string());
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find("unknown scene 'teapot' (cube, icosphere, or a .toml scene file)"), std::string::npos) << r.err;
}

}  // namespace
