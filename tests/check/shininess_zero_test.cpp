// Shininess 0 (GL's default) with a specular material, against Mesa 22.3, case by case. The
// vertex check flags a known Mesa deviation exactly where Mesa leaves the spec, and nowhere else.
#include <gtest/gtest.h>

#include <cmath>

#include "check/vertex_check.h"
#include "gl/dispatch.h"

namespace ffc {
namespace {

struct Light {
  bool point = false, attenuated = false, spot = false, two_side = false, color_material = false, local_viewer = false;
  float back_shininess = 0;
};

// One lit point per normal direction, at the origin, the light along +z (or at (0, 0, 3)); only the
// specular term is non-zero, so the fed-back red is att * (specular factor).
void draw(const Light& s) {
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(-2, 2, -2, 2, -5, 5);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  const float zero[] = {0, 0, 0, 1}, one[] = {1, 1, 1, 1};
  glLightModelfv(GL_LIGHT_MODEL_AMBIENT, zero);
  glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT, zero);
  glMaterialfv(GL_FRONT_AND_BACK, GL_DIFFUSE, zero);
  glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, one);
  glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 0);
  glMaterialf(GL_BACK, GL_SHININESS, s.back_shininess);
  const float dir[] = {0.70710678f, 0, 0.70710678f, 0}, pt[] = {2, 0, 2, 1};
  glLightfv(GL_LIGHT0, GL_POSITION, s.point ? pt : dir);
  if (s.attenuated) glLightf(GL_LIGHT0, GL_CONSTANT_ATTENUATION, 2);
  if (s.spot) glLightf(GL_LIGHT0, GL_SPOT_CUTOFF, 90);
  if (s.two_side) glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, 1);
  if (s.local_viewer) glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, 1);
  if (s.color_material) {
    glColorMaterial(GL_FRONT_AND_BACK, GL_DIFFUSE);
    glEnable(GL_COLOR_MATERIAL);
    glColor4f(0, 0, 0, 1);
  }
  glBegin(GL_POINTS);
  for (double deg = 0; deg < 150; deg += 7.5) {  // n.L from 1 down through 0; n.h <= 0 from 112.5
    const double a = deg * M_PI / 180;
    glNormal3f(float(std::sin(a)), 0, float(std::cos(a)));
    glVertex3f(float(deg / 100 - 0.75), 0, 0);  // apart in the window, so that none is dropped
  }
  glEnd();
}

check::VertexReport run(const Light& s) { return check::compare_vertices(32, 32, [&] { draw(s); }); }

TEST(ShininessZero, MesaFollowsTheSpecForLightsWithoutAttenuationOrSpot) {
  // Every face at shininess 0: Mesa's shininess-0 program gives (n.L > 0 ? 1 : 0), the spec's
  // pow(n.h, 0) = 1 with 0^0 = 1, also where n.h <= 0 < n.L.
  for (const Light& s : {Light{}, Light{true}, Light{false, false, false, true}, Light{false, false, false, false, true},
                         Light{false, false, false, false, false, true},
                         Light{true, false, false, false, false, true}}) {
    const check::VertexReport r = run(s);
    EXPECT_GT(r.vertices, 10u);
    EXPECT_LE(r.max_abs, 1e-6);
    EXPECT_TRUE(r.known_mesa_deviations.empty()) << r.known_mesa_deviations.front();
  }
}

TEST(ShininessZero, AnAttenuatedOrSpotLightGivesPowNLNLInMesaAndIsFlagged) {
  // The plain scene: a point light with attenuation, a specular material, shininess 0.
  for (const Light& s : {Light{true, true}, Light{true, false, true}, Light{false, false, true},
                         Light{true, true, false, true}, Light{true, true, false, false, false, true}}) {
    const check::VertexReport r = run(s);
    EXPECT_GT(r.max_abs, 0.05);  // a real difference: pow(n.L, n.L) is 0.69 at its smallest
    ASSERT_EQ(r.known_mesa_deviations.size(), 1u);
    EXPECT_NE(r.known_mesa_deviations[0].find("raises n.L to the power n.L"), std::string::npos);
  }
  // Mesa's value, worked out for the first point: at (-0.75, 0, 0), the normal along z, the light
  // at (2, 0, 2): n.L = 2 / |(2.75, 0, 2)|, attenuation 1/2.
  const Light s{true, true};
  auto mesa = backends::make("mesa");
  const auto prims = check::capture(*mesa, 32, 32, [&] { draw(s); });
  ASSERT_FALSE(prims.empty());
  const double nl = 2 / std::hypot(2.75, 2.0);
  EXPECT_NEAR(prims[0].vertices[0].color.r, 0.5 * std::pow(nl, nl), 1e-6);
}

TEST(ShininessZero, OneFaceShinyUnderTwoSidedLightingTakesPow00AsZeroAndIsFlagged) {
  const Light s{false, false, false, true, false, false, 10};
  const check::VertexReport r = run(s);
  EXPECT_NEAR(r.max_abs, 1.0, 1e-6);  // full specular (spec) against none (Mesa) where n.h <= 0 < n.L
  ASSERT_EQ(r.known_mesa_deviations.size(), 1u);
  EXPECT_NE(r.known_mesa_deviations[0].find("pow(0, 0) as 0"), std::string::npos);
}

}  // namespace
}  // namespace ffc
