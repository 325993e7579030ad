// Seed 001's six programs held to the handout: its data and numbers by hand, then the pictures
// (EGL core profile, llvmpipe) against the equation evaluated in double on the CPU. The picture
// tests skip, saying why, where no headless EGL context exists.
#include <gtest/gtest.h>

#include <cmath>

#include "image/compare.h"
#include "platform/egl_context.h"
#include "seed001_reference.h"
#include "seed001_renderer.h"

namespace seed001 {
namespace {

glm::dvec3 n_of(const Vertex& v) { return {v.normal[0], v.normal[1], v.normal[2]}; }
glm::dvec3 p_of(const Vertex& v) { return {v.pos[0], v.pos[1], v.pos[2]}; }

TEST(Seed001Data, AveragedNormalsAreTheHandoutsTable) {
  const auto& v = averaged_normal_vertices();
  ASSERT_EQ(v.size(), 8u);
  const double a = 0.5773502691896258, b = 0.8164965809277261, c = 0.4082482904638631;  // the table's digits
  const glm::dvec3 table[8] = {{-a, a, a}, {b, c, c},   {c, -c, b},  {-c, -b, c},
                               {-c, c, -b}, {c, b, -c}, {a, -a, -a}, {-b, -c, -c}};
  for (int i = 0; i < 8; ++i)
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(n_of(v[i])[k], table[i][k], 1e-7) << "v" << i;
  EXPECT_EQ(p_of(v[6]), glm::dvec3(1, -1, -1));
}

TEST(Seed001Data, FaceNormalArrayIsTheHandoutsListing) {
  const auto& v = face_normal_vertices();
  ASSERT_EQ(v.size(), 36u);
  // The listing starts v0, v2, v1 on +z and ends v0, v4, v7 on -x.
  EXPECT_EQ(p_of(v[0]), glm::dvec3(-1, 1, 1));
  EXPECT_EQ(p_of(v[1]), glm::dvec3(1, -1, 1));
  EXPECT_EQ(p_of(v[2]), glm::dvec3(1, 1, 1));
  EXPECT_EQ(n_of(v[2]), glm::dvec3(0, 0, 1));
  EXPECT_EQ(p_of(v[34]), glm::dvec3(-1, 1, -1));
  EXPECT_EQ(n_of(v[35]), glm::dvec3(-1, 0, 0));
  // Every triangle is counterclockwise seen from outside: its winding agrees with its normal.
  for (int t = 0; t < 12; ++t) {
    const glm::dvec3 g = glm::cross(p_of(v[3 * t + 1]) - p_of(v[3 * t]), p_of(v[3 * t + 2]) - p_of(v[3 * t]));
    EXPECT_GT(glm::dot(g, n_of(v[3 * t])), 0) << "triangle " << t;
  }
}

TEST(Seed001Camera, FortyFiveIsRadians) {
  View v;
  // glm.perspective(45, ...) halves 45 rad: tan(22.5) = tan(22.5 - 7 pi), about 0.5089 rad.
  const double half = 22.5 - 7 * M_PI;
  EXPECT_NEAR(fovy_degrees(v), 2 * half * 180 / M_PI, 1e-9);
  EXPECT_NEAR(fovy_degrees(v), 58.3101, 1e-4);
  EXPECT_NEAR(projection(v)[1][1], 1 / std::tan(half), 1e-12);
  v.fovy_radians = false;  // gluPerspective's degrees
  EXPECT_NEAR(projection(v)[1][1], 1 / std::tan(22.5 * M_PI / 180), 1e-12);
  EXPECT_EQ(eye_position(v), glm::dvec3(0, 1, 5));
  EXPECT_TRUE(v.on_key('3'));
  EXPECT_NEAR(eye_position(v).x, 5 * std::sin(M_PI / 18), 1e-12);
  EXPECT_FALSE(v.on_key('Q'));
}

TEST(Seed001Equation, ClosedFormsAtVertexV1OfTheFrontFace) {
  const View v;  // the eye at (0,1,5)
  const glm::dvec3 p(1, 1, 1), n(0, 0, 1);
  EXPECT_NEAR(illuminate(step_lighting(1), v, n, p).r, 0.1, 1e-15);
  // L = (2,1,3)/sqrt(14): N.L = 3/sqrt(14).
  EXPECT_NEAR(illuminate(step_lighting(2), v, n, p).r, 0.1 + 3 / std::sqrt(14.0), 1e-15);
  // R = reflect(-L, N) = (-2,-1,3)/sqrt(14), V = (-1,0,4)/sqrt(17): V.R = 14/sqrt(238).
  const double spec = std::pow(14 / std::sqrt(238.0), 32);
  const glm::dvec3 c3 = illuminate(step_lighting(3), v, n, p);
  EXPECT_NEAR(c3.r, 0.1 + 3 / std::sqrt(14.0) + spec, 1e-14);
  EXPECT_NEAR(c3.g, spec, 1e-15);
  // Blinn instead: H = normalize(L + V).
  Lighting blinn = step_lighting(3);
  blinn.half_vector = true;
  const glm::dvec3 h = glm::normalize(glm::dvec3(2, 1, 3) / std::sqrt(14.0) + glm::dvec3(-1, 0, 4) / std::sqrt(17.0));
  EXPECT_NEAR(illuminate(blinn, v, n, p).g, std::pow(h.z, 32), 1e-15);
  EXPECT_THROW(step_lighting(0), std::invalid_argument);
  EXPECT_THROW(step_lighting(7), std::invalid_argument);
}

TEST(Seed001Equation, SpecularWithoutTheGuardOnAFaceTurnedAway) {
  // The bottom face (N = (0,-1,0)) at (0,-1,-1) has the light above it: N.L = -3/sqrt(43) < 0.
  // An eye just below the face's plane, on the far side from the light (205 degrees, height -1.1),
  // still sees it, and V.R > 0 there: the handout's shader adds specular, GL's fixed function none.
  View v;
  v.cam_ang = 205 * M_PI / 180, v.cam_height = -1.1;
  Lighting l = step_lighting(3);
  const glm::dvec3 p(0, -1, -1), n(0, -1, 0);
  ASSERT_GT(glm::dot(n, eye_position(v) - p), 0);  // the camera sees the face
  ASSERT_LT(glm::dot(n, l.light_pos - p), 0);       // the light does not
  const glm::dvec3 r = glm::dvec3(-3, 3, -5) / std::sqrt(43.0);  // reflect(-L, N), L = (3,3,5)/sqrt(43)
  const double expected = std::pow(glm::dot(glm::normalize(eye_position(v) - p), r), 32);
  const double unguarded = illuminate(l, v, n, p).g;
  EXPECT_NEAR(unguarded, expected, 1e-15);
  EXPECT_GT(unguarded, 0.01);  // 2.5 steps and more
  l.nl_guard = true;
  EXPECT_EQ(illuminate(l, v, n, p).g, 0);
}

// ------------------------------------------------------------------ pictures (EGL core 3.3)

// A view of the pictures' size (the reference casts its rays through kSize x kSize pixels).
constexpr int kSize = 256;
View view(double angle_deg = 0, double height = 1) {
  View v;
  v.cam_ang = angle_deg * M_PI / 180, v.cam_height = height;
  v.width = v.height = kSize;
  return v;
}

class Seed001Picture : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    std::string why;
    if (!ffc::platform::EglContext::available(&why)) {
      skip_ = why;
      return;
    }
    gl_ = new Headless(kSize, kSize);
  }
  static void TearDownTestSuite() {
    delete gl_;
    gl_ = nullptr;
  }
  void SetUp() override {
    if (!gl_) GTEST_SKIP() << "no EGL: " << skip_;
  }
  static inline Headless* gl_ = nullptr;
  static inline std::string skip_;
};

TEST_F(Seed001Picture, Step1IsTheAmbientColour) {
  const View v = view(35, 2.5);  // three faces show
  const Lighting l = step_lighting(1);
  const ffc::image::Image img = gl_->render(l, v);
  // 0.1 * 1 * 1 is 25.5 steps: on the rounding boundary. In float 0.1f is 0.100000001 (26), but
  // interpolating three equal colours with weights that sum to 1 within a float's rounding lands
  // some fragments at 0.0999999 (25). So every pixel of the cube is red 25 or 26, nothing else,
  // and every other pixel black.
  int r26 = 0, r25 = 0, black = 0, other = 0;
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      const uint8_t* p = img.at(x, y);
      const bool covered = reference_pixel(l, v, x, y).triangle >= 0;
      if (covered && p[0] == 26 && !p[1] && !p[2]) ++r26;
      else if (covered && p[0] == 25 && !p[1] && !p[2]) ++r25;
      else if (!covered && !p[0] && !p[1] && !p[2]) ++black;
      else ++other;
    }
  EXPECT_GT(r26, 5000);
  EXPECT_GT(r26, 4 * r25);  // most fragments keep 0.1f's excess
  // Pixel centres on the silhouette, where the ray cast and the rasterizer may disagree.
  EXPECT_LT(other, 4 * kSize);
  EXPECT_EQ(r26 + r25 + black + other, kSize * kSize);
  const ReferenceCheck r = check_against_reference(img, l, v);
  EXPECT_LE(r.max_diff, 1);
  EXPECT_EQ(r.background_wrong, 0);
}

TEST_F(Seed001Picture, EveryStepMatchesTheEquationInDouble) {
  for (const double height : {1.0, 2.5})
    for (int step = 2; step <= kSteps; ++step) {
      const View v = view(height > 1 ? 35 : 0, height);
      const ffc::image::Image img = gl_->render(step_lighting(step), v);
      const ReferenceCheck r = check_against_reference(img, step_lighting(step), v);
      EXPECT_GT(r.pixels, 5000) << "step " << step;
      // Float shaders against double: Gouraud within a step; Phong's pow(x, 32) per fragment two.
      EXPECT_LE(r.max_diff, step == 4 || step == 6 ? 2 : 1)
          << "step " << step << " height " << height << " worst at " << r.worst_x << "," << r.worst_y;
      EXPECT_EQ(r.background_wrong, 0);
    }
}

TEST_F(Seed001Picture, GouraudFaceCentreIsTheDiagonalsMidpointColour) {
  // The front face's centre (0,0,1) lies on the diagonal v0-v2 both triangles share: Gouraud gives
  // it the mean of v0's and v2's colours. Eye (0,1,5) sees it just below the picture's centre.
  const View v = view();
  const Lighting l = step_lighting(2);
  const glm::dvec3 n(0, 0, 1);
  const double expected = 255 * (illuminate(l, v, n, {-1, 1, 1}) + illuminate(l, v, n, {1, -1, 1})).r / 2;
  const ffc::image::Image img = gl_->render(l, v);
  // The pixel whose centre is nearest (0,0,1), found by the ray cast.
  int bx = -1, by = -1;
  double best = 1e9;
  for (int y = kSize / 2 - 20; y < kSize / 2 + 20; ++y)
    for (int x = kSize / 2 - 20; x < kSize / 2 + 20; ++x) {
      const PixelRef r = reference_pixel(l, v, x, y);
      if (r.face == 0 && glm::length(r.point - glm::dvec3(0, 0, 1)) < best) best = glm::length(r.point - glm::dvec3(0, 0, 1)), bx = x, by = y;
    }
  ASSERT_GE(bx, 0);
  EXPECT_LT(best, 0.02);  // under a pixel's width on the face
  EXPECT_NEAR(img.at(bx, by)[0], expected, 1.0);
}

TEST_F(Seed001Picture, GouraudNearAVertexIsThatVertexsColour) {
  // Step 3 at the front face's corner v1 = (1,1,1): 0.1 + 3/sqrt(14) + pow(14/sqrt(238), 32) red,
  // the specular alone in green and blue. The front-face pixel whose centre lies nearest v1 is
  // within a couple of pixels of it, where the interpolated colour has moved by under 2 steps.
  const View v = view();
  const Lighting l = step_lighting(3);
  const double spec = std::pow(14 / std::sqrt(238.0), 32), red = 0.1 + 3 / std::sqrt(14.0) + spec;
  const ffc::image::Image img = gl_->render(l, v);
  int bx = -1, by = -1;
  double best = 1e9;
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      const PixelRef r = reference_pixel(l, v, x, y);
      if (r.face == 0 && glm::length(r.point - glm::dvec3(1, 1, 1)) < best) best = glm::length(r.point - glm::dvec3(1, 1, 1)), bx = x, by = y;
    }
  ASSERT_GE(bx, 0);
  EXPECT_LT(best, 0.05);
  EXPECT_NEAR(img.at(bx, by)[0], 255 * red, 2.0);
  EXPECT_NEAR(img.at(bx, by)[1], 255 * spec, 2.0);
  // And the pixel is what the reference interpolates for its centre, to a step.
  EXPECT_NEAR(img.at(bx, by)[0], 255 * reference_pixel(l, v, bx, by).colour.r, 1.0);
}

TEST_F(Seed001Picture, PhongShowsTheHighlightGouraudLoses) {
  // From 30 degrees left and 0.5 down (keys 1 1 1, W x 15), the mirror image of the light in the
  // front face's plane is seen at (0.39, 0.81, 1), inside the face: there V = R and the specular is
  // 1. Phong lights that fragment and shows it; Gouraud only interpolates its four corners'.
  const View v = view(-30, -0.5);
  const glm::dvec3 light(3, 2, 4), eye = eye_position(v), mirrored(eye.x, eye.y, 2 - eye.z);
  const glm::dvec3 peak = light + (mirrored - light) * (3 / (3 + (eye.z - 1)));  // where the segment meets z = 1
  ASSERT_LT(std::abs(peak.x), 1);
  ASSERT_LT(std::abs(peak.y), 1);
  EXPECT_NEAR(illuminate(step_lighting(4), v, {0, 0, 1}, peak).g, 1, 1e-12);
  double corners = 0;
  for (const glm::dvec3 c : {glm::dvec3(-1, 1, 1), glm::dvec3(1, 1, 1), glm::dvec3(1, -1, 1), glm::dvec3(-1, -1, 1)})
    corners = std::max(corners, illuminate(step_lighting(3), v, {0, 0, 1}, c).g);
  const ffc::image::Image g = gl_->render(step_lighting(3), v), p = gl_->render(step_lighting(4), v);
  int gpeak = 0, ppeak = 0;
  for (size_t i = 1; i < g.rgba.size(); i += 4) gpeak = std::max<int>(gpeak, g.rgba[i]), ppeak = std::max<int>(ppeak, p.rgba[i]);
  EXPECT_LE(gpeak, std::lround(255 * corners) + 1);
  EXPECT_LT(gpeak, 128);
  EXPECT_GE(ppeak, 250);  // the nearest pixel centre to the peak, a fraction of a pixel away
}

TEST_F(Seed001Picture, EyeSpaceLightsAsWorldSpace) {
  const View v = view(35, 2.5);
  for (int step : {3, 4}) {
    Lighting world = step_lighting(step), eye = world;
    eye.eye_space = true;
    const ffc::image::Diff d = ffc::image::compare(gl_->render(world, v), gl_->render(eye, v));
    EXPECT_LE(d.max_diff, 1) << "step " << step;
  }
}

TEST(Seed001Headless, BadSizeIsAnError) {
  EXPECT_THROW(Headless(0, 10), std::invalid_argument);
  EXPECT_THROW(Headless(10, 9000), std::invalid_argument);
}

}  // namespace
}  // namespace seed001
