// Runs the legacy examples the way a user would (headless, with --keys) and checks the pictures:
// what must be equal is compared pixel for pixel, what must change is required to change, and a
// few pixels are checked against the lighting equation worked out by hand.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "image/image.h"

namespace fs = std::filesystem;
using ffc::image::Image;

namespace {

struct Result {
  int exit_code = -1;
  std::string out, err;
};

std::string slurp(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// Runs an example with `args` (shell syntax); stdout and stderr captured.
Result run(const std::string& example, const std::string& args, const std::string& env = "") {
  fs::create_directories(EXAMPLES_OUT_DIR);
  // CTest runs the tests in parallel, one process each: the pid keeps their files apart.
  const std::string tag = std::to_string(getpid());
  const fs::path out = fs::path(EXAMPLES_OUT_DIR) / ("stdout-" + tag + ".txt"),
                 err = fs::path(EXAMPLES_OUT_DIR) / ("stderr-" + tag + ".txt");
  const std::string cmd = env + " '" EXAMPLES_BIN_DIR "/" + example + "' " + args + " >'" + out.string() + "' 2>'" +
                          err.string() + "'";
  const int status = std::system(cmd.c_str());
  Result r;
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  r.out = slurp(out);
  r.err = slurp(err);
  fs::remove(out);
  fs::remove(err);
  return r;
}

int png_counter = 0;

// One headless frame of `example` with `args`; fails the test if the example does.
Image render(const std::string& example, const std::string& args = "") {
  const std::string test = ::testing::UnitTest::GetInstance()->current_test_info()->name();
  const fs::path png = fs::path(EXAMPLES_OUT_DIR) / (test + "-" + example + "-" + std::to_string(png_counter++) + ".png");
  const Result r = run(example, "--headless --out '" + png.string() + "' " + args);
  EXPECT_EQ(r.exit_code, 0) << example << " " << args << ": " << r.err;
  if (r.exit_code != 0) return Image();
  return ffc::image::read_png(png.string());
}

struct Diff {
  int max_channel = 0;   // largest |a-b| over all pixels and RGB channels
  long pixels = 0;       // pixels differing in any channel
  bool same_size = true;
};

Diff diff(const Image& a, const Image& b) {
  Diff d;
  if (a.width != b.width || a.height != b.height || a.width == 0) {
    d.same_size = false;
    return d;
  }
  for (int y = 0; y < a.height; ++y)
    for (int x = 0; x < a.width; ++x) {
      int m = 0;
      for (int c = 0; c < 3; ++c) m = std::max(m, std::abs(int(a.at(x, y)[c]) - int(b.at(x, y)[c])));
      d.max_channel = std::max(d.max_channel, m);
      d.pixels += m > 0;
    }
  return d;
}

long coverage(const Image& img) {  // pixels that are not background black
  long n = 0;
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x) n += img.at(x, y)[0] || img.at(x, y)[1] || img.at(x, y)[2];
  return n;
}

double brightness(const Image& img) {
  double sum = 0;
  for (size_t i = 0; i < img.rgba.size(); i += 4) sum += img.rgba[i] + img.rgba[i + 1] + img.rgba[i + 2];
  return sum;
}

#define EXPECT_IDENTICAL(a, b)         \
  do {                                 \
    const Diff d_ = diff(a, b);        \
    EXPECT_TRUE(d_.same_size);         \
    EXPECT_EQ(d_.max_channel, 0);      \
  } while (0)

}  // namespace

// ---- cube_lab --------------------------------------------------------------------------------

TEST(CubeLab, GlVertexAndGlDrawArraysPathsGiveTheSamePicture) {
  const Image arrays = render("cube_lab", "--path arrays"), vertex = render("cube_lab", "--path vertex");
  ASSERT_EQ(arrays.width, 640);
  ASSERT_EQ(arrays.height, 640);
  EXPECT_GT(coverage(arrays), 640 * 640 / 20);  // there is a cube to compare
  EXPECT_IDENTICAL(arrays, vertex);
  EXPECT_IDENTICAL(render("cube_lab", "--keys V"), vertex);           // V switches to glVertex
  EXPECT_IDENTICAL(render("cube_lab", "--keys 'V V'"), arrays);       // and back
  EXPECT_IDENTICAL(render("cube_lab", "--keys '3 V' --path vertex"),  // also from another side
                   render("cube_lab", "--keys 3"));
}

TEST(CubeLab, FrontFaceAtTheCentreIsLitRedAndTheBackgroundBlack) {
  const Image img = render("cube_lab");
  ASSERT_EQ(img.width, 640);
  // Eye (0,1,5), light (3,4,5): at the centre pixel the front face gets ambient .1, diffuse ~.63
  // and a white highlight of ~.24, so red saturates while green and blue only get the highlight.
  // The glColor3ub(0,0,255) must not show: lighting ignores it.
  const uint8_t* c = img.at(320, 320);
  EXPECT_GE(c[0], 250);
  EXPECT_NEAR(c[1], 62, 8);
  EXPECT_EQ(c[1], c[2]);
  const uint8_t* corner = img.at(5, 5);
  EXPECT_EQ(corner[0] + corner[1] + corner[2], 0);
}

TEST(CubeLab, TurningTheCameraChangesThePictureAndTurningBackRestoresIt) {
  const Image start = render("cube_lab");
  const Image turned = render("cube_lab", "--keys 3");
  EXPECT_GT(diff(start, turned).pixels, 1000);
  EXPECT_IDENTICAL(render("cube_lab", "--keys '3 1'"), start);
  EXPECT_IDENTICAL(render("cube_lab", "--keys '3 3 3 1 1 1'"), start);
  EXPECT_GT(diff(start, render("cube_lab", "--keys 2")).pixels, 1000);  // raised
  EXPECT_IDENTICAL(render("cube_lab", "--keys '2 w'"), start);           // key names ignore case
}

// ---- cube_shading ----------------------------------------------------------------------------

TEST(CubeShading, FlatCubeIsTheCubeLabsCube) {
  // Same triangles and normals in the same order; only the array layout differs.
  EXPECT_IDENTICAL(render("cube_shading", "--mode flat"), render("cube_lab"));
  EXPECT_IDENTICAL(render("cube_shading", "--mode flat --keys '1 1 2'"), render("cube_lab", "--keys '1 1 2'"));
}

TEST(CubeShading, AveragedNormalsChangeTheShadingButNotTheSilhouette) {
  const Image flat = render("cube_shading", "--mode flat"), smooth = render("cube_shading", "--mode smooth");
  EXPECT_GT(diff(flat, smooth).pixels, 10000);
  EXPECT_EQ(coverage(flat), coverage(smooth));
  EXPECT_IDENTICAL(render("cube_shading", "--keys S"), smooth);
}

TEST(CubeShading, GSwitchesTheShadeModel) {
  const Image smooth = render("cube_shading", "--mode smooth");
  const Image smooth_flat = render("cube_shading", "--mode smooth --keys G");
  EXPECT_GT(diff(smooth, smooth_flat).pixels, 10000);  // one colour per triangle instead of a blend
  EXPECT_IDENTICAL(render("cube_shading", "--mode smooth --keys 'G G'"), smooth);
}

// ---- icosphere -------------------------------------------------------------------------------

TEST(Icosphere, SubdivisionFillsOutTheSpheresDisc) {
  // The unit sphere seen from 4 units away with a 45 degree field of view: a disc of radius
  // tan(asin(1/4)) / tan(22.5 deg) * 256 = 159.6 pixels. Every vertex lies on the sphere, so each
  // subdivision covers more of that disc and never more.
  const double r = std::tan(std::asin(0.25)) / std::tan(M_PI / 8) * 256, disc = M_PI * r * r;
  long previous = 0;
  for (int depth : {0, 1, 2, 5}) {
    const long c = coverage(render("icosphere", "--shade flat --depth " + std::to_string(depth)));
    EXPECT_GT(c, previous) << "depth " << depth;
    EXPECT_LT(c, disc * 1.01) << "depth " << depth;
    previous = c;
  }
  EXPECT_GT(previous, disc * 0.99);  // depth 5: the disc, give or take the edge pixels
}

TEST(Icosphere, CentreIsLitByTheSeedsLightFromTheViewer) {
  // Sphere normals put a vertex at (0,0,1), facing the default light (0,0,1,0) head on:
  // (global ambient .2 + light ambient .2 + diffuse 1) * (.8,.6,.4) = (1.12 -> 1, .84, .56).
  const Image img = render("icosphere", "--normals sphere");
  const uint8_t* c = img.at(256, 256);
  EXPECT_EQ(c[0], 255);
  EXPECT_NEAR(c[1], 214, 3);
  EXPECT_NEAR(c[2], 143, 3);
}

TEST(Icosphere, ShadeModelMattersUnderSphereNormalsOnly) {
  // Sphere normals give each corner its own colour: GL_FLAT paints one, GL_SMOOTH blends three.
  EXPECT_GT(diff(render("icosphere", "--keys 'N F'"), render("icosphere", "--keys 'N S'")).pixels, 10000);
  // Face normals and a directional light give the three corners one colour already.
  EXPECT_LE(diff(render("icosphere", "--keys F"), render("icosphere", "--keys S")).max_channel, 1);
}

TEST(Icosphere, PlusAndMinusChangeTheDepthWithinZeroToEight) {
  EXPECT_IDENTICAL(render("icosphere", "--keys +"), render("icosphere", "--depth 4"));
  EXPECT_IDENTICAL(render("icosphere", "--keys ="), render("icosphere", "--depth 4"));
  const Image zero = render("icosphere", "--depth 0");
  EXPECT_IDENTICAL(render("icosphere", "--keys '- - - - -'"), zero);  // stops at 0
  EXPECT_IDENTICAL(render("icosphere", "--keys=-  --depth 1"), zero);
  EXPECT_NE(run("icosphere", "--headless --out /dev/null --depth 9").exit_code, 0);
}

// ---- normalize_rescale -----------------------------------------------------------------------

TEST(NormalizeRescale, NonUniformScaleNeedsGlNormalize) {
  const Image none = render("normalize_rescale", "--scale nonuniform --mode none");
  const Image normalize = render("normalize_rescale", "--scale nonuniform --mode normalize");
  const Image rescale = render("normalize_rescale", "--scale nonuniform --mode rescale");
  // The top face's normal comes out 5 times too long: brighter, not just different.
  EXPECT_GT(diff(none, normalize).pixels, 1000);
  EXPECT_GT(brightness(none), brightness(normalize));
  // Rescaling uses the length of the inverse modelview's third row, 1/sz = 1 here: no change.
  EXPECT_LE(diff(rescale, none).max_channel, 1);
}

TEST(NormalizeRescale, UniformScaleRescaleEqualsNormalize) {
  const Image none = render("normalize_rescale", "--scale uniform --mode none");
  const Image normalize = render("normalize_rescale", "--scale uniform --mode normalize");
  const Image rescale = render("normalize_rescale", "--scale uniform --mode rescale");
  EXPECT_GT(diff(none, normalize).pixels, 1000);  // normals twice as long without either
  EXPECT_GT(brightness(none), brightness(normalize));
  EXPECT_LE(diff(rescale, normalize).max_channel, 1);
}

TEST(NormalizeRescale, KCyclesThroughTheSixCombinations) {
  // Starting from none/nonuniform: normalize, rescale, then uniform none, normalize, rescale.
  EXPECT_IDENTICAL(render("normalize_rescale", "--keys K"),
                   render("normalize_rescale", "--scale nonuniform --mode normalize"));
  EXPECT_IDENTICAL(render("normalize_rescale", "--keys 'K K K'"),
                   render("normalize_rescale", "--scale uniform --mode none"));
  EXPECT_IDENTICAL(render("normalize_rescale", "--keys 'K K K K K K'"), render("normalize_rescale"));
}

// ---- the harness's command line ---------------------------------------------------------------

TEST(Harness, JsonDescribesTheHeadlessRender) {
  const std::string png = std::string(EXAMPLES_OUT_DIR) + "/Json-icosphere.png";
  const Result r = run("icosphere", "--headless --out '" + png + "' --json --keys '- N'");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j.at("example"), "icosphere");
  EXPECT_EQ(j.at("out"), png);
  EXPECT_EQ(j.at("width"), 512);
  EXPECT_EQ(j.at("height"), 512);
  EXPECT_EQ(j.at("backend"), "mesa");
  EXPECT_TRUE(fs::exists(png));
}

TEST(Harness, ErrorsExitWithOneAndSayWhy) {
  const std::string png = std::string(EXAMPLES_OUT_DIR) + "/never.png";
  fs::remove(png);
  Result r = run("cube_lab", "--headless --out '" + png + "' --keys '3 banana'");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("banana"), std::string::npos) << r.err;
  r = run("cube_lab", "--headless");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("--out"), std::string::npos) << r.err;
  r = run("cube_lab", "--headless --out '" + png + "' --backend nosuch");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("nosuch"), std::string::npos) << r.err;
  EXPECT_EQ(run("cube_lab", "--headless --out '" + png + "' --path diagonal").exit_code, 1);
  EXPECT_EQ(run("normalize_rescale", "--headless --out '" + png + "' --mode sometimes").exit_code, 1);
  EXPECT_EQ(run("cube_lab", "--headless --out /nonexistent-dir/x.png").exit_code, 1);
  EXPECT_FALSE(fs::exists(png));
  // Without a display the window cannot open (or GLFW is off): an error, not a crash.
  r = run("cube_shading", "--frames 1", "env -u DISPLAY -u WAYLAND_DISPLAY");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_FALSE(r.err.empty());
}
