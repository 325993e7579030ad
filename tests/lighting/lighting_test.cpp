// The lighting stage against closed forms of the equation (OpenGL 2.1, 2.14.1), and the
// specialised kernels against the generic one.
#include "lighting/lighting.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace ffc::lighting {
namespace {

struct Rig {
  Rig() { l[0].diffuse = l[0].specular = glm::dvec4(1); }  // GL's defaults for GL_LIGHT0
  LightParams l[8];
  MaterialParams m[2];
  ModelParams model;
  Key key() const { return make_key(l, m, model, false, false); }  // the context's own writer
  Lit<double> at(glm::dvec4 p, glm::dvec3 n, glm::dvec4 color = glm::dvec4(1)) const {
    return light<double>(prepare<double>(l, m, model, key()), p, n, color);
  }
};

void expect_rgb(const glm::dvec4& got, glm::dvec3 want, double tol = 1e-12) {
  EXPECT_NEAR(got.r, want.r, tol);
  EXPECT_NEAR(got.g, want.g, tol);
  EXPECT_NEAR(got.b, want.b, tol);
}

TEST(Lighting, DefaultsLightZeroHeadOnGivesAmbientPlusDiffuse) {
  Rig s;
  s.l[0].enabled = true;  // white diffuse, directional (0,0,1); material diffuse .8, ambient .2
  const auto c = s.at({0, 0, -3, 1}, {0, 0, 1});
  expect_rgb(c.primary[0], glm::dvec3(0.2 * 0.2 + 0.8));  // global ambient .2 x .2, n.L = 1
  EXPECT_DOUBLE_EQ(c.primary[0].a, 1.0);                   // alpha: the diffuse material's, 1
}

TEST(Lighting, DiffuseFollowsLambertAndClampsBelowZero) {
  Rig s;
  s.l[0].enabled = true;
  s.model.ambient = glm::dvec4(0);
  const double a = 0.7;
  expect_rgb(s.at({0, 0, 0, 1}, {std::sin(a), 0, std::cos(a)}).primary[0], glm::dvec3(0.8 * std::cos(a)));
  expect_rgb(s.at({0, 0, 0, 1}, {0, 0, -1}).primary[0], glm::dvec3(0));
}

TEST(Lighting, SpecularUsesTheBlinnHalfVectorWithAnInfiniteViewer) {
  Rig s;
  s.l[0].enabled = true;
  s.l[0].diffuse = glm::dvec4(0, 0, 0, 1);
  s.l[0].position = {1, 0, 1, 0};  // L at 45 degrees
  s.m[0].specular = glm::dvec4(1);
  s.m[0].shininess = 16;
  s.model.ambient = glm::dvec4(0);
  // h = normalize(L + (0,0,1)) is at 22.5 degrees: n.h = cos(22.5°).
  const double want = std::pow(std::cos(M_PI / 8), 16);
  expect_rgb(s.at({5, 5, -5, 1}, {0, 0, 1}).primary[0], glm::dvec3(want));
}

TEST(Lighting, LocalViewerAimsHAtTheEye) {
  Rig s;
  s.l[0].enabled = true;
  s.l[0].diffuse = glm::dvec4(0, 0, 0, 1);
  s.l[0].position = {0, 0, 1, 0};
  s.m[0].specular = glm::dvec4(1);
  s.m[0].shininess = 1;
  s.model.ambient = glm::dvec4(0);
  s.model.local_viewer = true;
  // Vertex at (3,0,-3): the eye is at 45 degrees, so h is at 22.5 degrees from n = (0,0,1).
  expect_rgb(s.at({3, 0, -3, 1}, {0, 0, 1}).primary[0], glm::dvec3(std::cos(M_PI / 8)));
}

TEST(Lighting, AttenuationOfAPointLight) {
  Rig s;
  s.l[0].enabled = true;
  s.l[0].position = {0, 0, 4, 1};
  s.l[0].ambient = glm::dvec4(0.5, 0.5, 0.5, 1);
  s.l[0].constant_attenuation = 1, s.l[0].linear_attenuation = 0.5, s.l[0].quadratic_attenuation = 0.25;
  s.model.ambient = glm::dvec4(0);
  // Distance 4: att = 1 / (1 + 2 + 4); n.L = 1; ambient .5 x .2 and diffuse .8, both attenuated.
  expect_rgb(s.at({0, 0, 0, 1}, {0, 0, 1}).primary[0], glm::dvec3((0.1 + 0.8) / 7));
}

TEST(Lighting, SpotlightConeAndExponent) {
  Rig s;
  s.l[0].enabled = true;
  s.l[0].position = {0, 0, 1, 1};
  s.l[0].spot_direction = {0, 0, -1};
  s.l[0].spot_cutoff = 30;
  s.l[0].spot_exponent = 2;
  s.model.ambient = glm::dvec4(0);
  // A vertex 20 degrees off the axis is inside: spot = cos(20°)^2, n.L = cos(20°).
  const double t = 20 * M_PI / 180, d = 1 / std::cos(t);
  const glm::dvec4 p(d * std::sin(t), 0, 1 - d * std::cos(t), 1);
  expect_rgb(s.at(p, {0, 0, 1}).primary[0], glm::dvec3(0.8 * std::pow(std::cos(t), 3)));
  // 40 degrees off the axis is outside the cone: the light adds nothing, ambient included.
  s.l[0].ambient = glm::dvec4(1);
  const double u = 40 * M_PI / 180, e = 1 / std::cos(u);
  expect_rgb(s.at({e * std::sin(u), 0, 1 - e * std::cos(u), 1}, {0, 0, 1}).primary[0], glm::dvec3(0));
}

TEST(Lighting, TwoSidedLightingUsesTheBackMaterialAndTheNegatedNormal) {
  Rig s;
  s.l[0].enabled = true;
  s.model.two_side = true;
  s.model.ambient = glm::dvec4(0);
  s.m[1].diffuse = glm::dvec4(0, 0.5, 0, 1);
  const auto c = s.at({0, 0, -2, 1}, {0, 0, -1});  // facing away from the light
  expect_rgb(c.primary[0], glm::dvec3(0));
  expect_rgb(c.primary[1], glm::dvec3(0, 0.5, 0));
}

TEST(Lighting, SeparateSpecularGoesToTheSecondaryColour) {
  Rig s;
  s.l[0].enabled = true;
  s.m[0].specular = glm::dvec4(1);
  s.m[0].shininess = 0;  // (n.h)^0 = 1 wherever n.L > 0
  s.model.ambient = glm::dvec4(0);
  s.model.separate_specular = true;
  const auto c = s.at({0, 0, -2, 1}, {0, 0, 1});
  expect_rgb(c.primary[0], glm::dvec3(0.8));
  expect_rgb(c.secondary[0], glm::dvec3(1));
}

TEST(Lighting, ColourMaterialTracksTheCurrentColour) {
  Rig s;
  s.l[0].enabled = true;
  s.model.ambient = glm::dvec4(0);
  s.model.color_material = true;  // GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE
  expect_rgb(s.at({0, 0, -2, 1}, {0, 0, 1}, {0.25, 0.5, 1, 0.5}).primary[0], glm::dvec3(0.25, 0.5, 1));
  EXPECT_DOUBLE_EQ(s.at({0, 0, -2, 1}, {0, 0, 1}, {0.25, 0.5, 1, 0.5}).primary[0].a, 0.5);
}

TEST(Lighting, EmissionAndColoursAboveOneClamp) {
  Rig s;
  s.m[0].emission = glm::dvec4(2, -1, 0.5, 1);
  expect_rgb(s.at({0, 0, -2, 1}, {0, 0, 1}).primary[0], glm::dvec3(1, 0, 0.5 + 0.2 * 0.2));
}

// Mesa's program raises n.h to the shininess whatever the specular colour: with a normal 4.5 long
// (a glOrtho on the modelview scaled it, GL_NORMALIZE off) 4.5^59 overflows a float, and infinity
// times the default black specular is a NaN that clamps to 1 (fuzz seed 2026 stream 505). 4.5^58
// does not: the term adds 0, the colour is the ambient plus the diffuse with n.L = 4.5. A unit
// normal never overflows, and in double 4.5^128 is finite.
TEST(Lighting, AZeroSpecularColourStillOverflowsAsMesasProgram) {
  LightParams l[8];
  l[0].enabled = true;
  l[0].diffuse = {0.1, 0, 0, 1};
  l[0].specular = glm::dvec4(1);  // GL_LIGHT0's; the material's specular is GL's black
  MaterialParams m[2];
  const ModelParams model;
  const glm::vec4 p(0, 0, -1, 1), color(1);
  const double lit_red = 0.2 * 0.2 + 4.5 * 0.1 * 0.8, ambient = 0.2 * 0.2;
  for (const double shininess : {58.0, 59.0, 128.0}) {
    m[0].shininess = m[1].shininess = shininess;
    const Key key = make_key(l, m, model, false, false);
    ASSERT_FALSE(key.specular());
    const auto pf = prepare<float>(l, m, model, key);
    const glm::dvec4 got = light<float>(pf, p, {0, 0, 4.5f}, color).primary[0];
    if (shininess == 58) expect_rgb(got, {lit_red, ambient, ambient}, 1e-6);
    else expect_rgb(got, glm::dvec3(1), 0);
    expect_rgb(light<float>(pf, p, {0, 0, 1}, color).primary[0], {0.2 * 0.2 + 0.1 * 0.8, ambient, ambient}, 1e-6);
    const auto pd = prepare<double>(l, m, model, key);
    expect_rgb(light<double>(pd, glm::dvec4(p), {0, 0, 4.5}, glm::dvec4(1)).primary[0], {lit_red, ambient, ambient});
  }
}

// Outside a spot light's cone Mesa's program multiplies the light's terms by 0 rather than leaving
// them out: the same for finite terms, but 0 times an overflowing specular power is a NaN, white.
TEST(Lighting, OutsideTheConeAnOverflowingPowerStillShows) {
  LightParams l[8];
  l[0].enabled = true;
  l[0].diffuse = l[0].specular = glm::dvec4(1);
  l[0].position = {0, 0, 0, 1};
  l[0].spot_cutoff = 10;  // pointing down -z; the vertex below sits 90 degrees off the axis
  MaterialParams m[2];
  m[0].shininess = m[1].shininess = 60;
  const ModelParams model;
  const Key key = make_key(l, m, model, false, false);
  const auto pf = prepare<float>(l, m, model, key);
  const glm::vec4 p(0, -1, 0, 1), color(1);  // the light at (0, 1, 0) from the vertex: n.L > 0
  expect_rgb(light<float>(pf, p, {0, 1, 0}, color).primary[0], glm::dvec3(0.2 * 0.2), 1e-7);  // ambient only
  expect_rgb(light<float>(pf, p, {0, 9, 0}, color).primary[0], glm::dvec3(1), 0);  // n.h = 9/sqrt(2)
}

// Random states: every specialised kernel gives the generic kernel's colours.
TEST(Kernels, SpecialisedAgreeWithGenericOnRandomStates) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1, 1), pos(0, 1);
  unsigned long long shapes_seen = 0;
  for (int trial = 0; trial < 512; ++trial) {
    Rig s;
    const int lights = 1 + trial % 8;
    for (int i = 0; i < lights; ++i) {
      LightParams& l = s.l[(i * 3 + trial) % 8];
      l.enabled = true;
      l.diffuse = {pos(rng), pos(rng), pos(rng), 1};
      l.specular = {pos(rng), pos(rng), pos(rng), 1};
      l.ambient = {pos(rng), pos(rng), pos(rng), 1};
      // All directional, all points, or (every fourth trial) mixed.
      const bool point = trial % 4 == 3 ? i % 2 == 0 : (trial >> 1) % 2 == 1;
      l.position = {u(rng) * 5, u(rng) * 5, u(rng) * 5, point ? 1.0 : 0.0};
      if ((trial >> 2) % 2) l.spot_cutoff = 10 + 80 * pos(rng), l.spot_exponent = 128 * pos(rng);
      l.linear_attenuation = (trial >> 7) % 2 ? pos(rng) : 0.0;
    }
    for (auto& m : s.m) {
      m.specular = (trial >> 3) % 2 ? glm::dvec4(pos(rng), pos(rng), pos(rng), 1) : glm::dvec4(0, 0, 0, 1);
      m.shininess = 128 * pos(rng);
      m.emission = {0.1 * pos(rng), 0, 0, 1};
    }
    s.model.two_side = (trial >> 4) % 2;
    s.model.local_viewer = (trial >> 5) % 2;
    s.model.color_material = (trial >> 6) % 2;
    s.model.separate_specular = trial % 3 == 0;
    const Key key = s.key();
    shapes_seen |= 1ull << shape_index(key) % 64;
    const auto prepared = prepare<float>(s.l, s.m, s.model, key);
    std::vector<glm::vec4> p, c;
    std::vector<glm::vec3> n;
    for (int v = 0; v < 16; ++v) {
      p.emplace_back(u(rng), u(rng), u(rng) - 3, 1);
      n.push_back(glm::normalize(glm::vec3(u(rng), u(rng), u(rng))));
      c.emplace_back(pos(rng), pos(rng), pos(rng), 1);
    }
    std::vector<Lit<float>> a(16), b(16);
    generic<float>()(prepared, p.data(), n.data(), c.data(), 16, a.data());
    specialised<float>(key)(prepared, p.data(), n.data(), c.data(), 16, b.data());
    for (int v = 0; v < 16; ++v)
      for (int f = 0; f < 2; ++f)
        for (int k = 0; k < 4; ++k) {
          ASSERT_NEAR(a[v].primary[f][k], b[v].primary[f][k], 1e-6) << "trial " << trial;
          ASSERT_NEAR(a[v].secondary[f][k], b[v].secondary[f][k], 1e-6) << "trial " << trial;
        }
  }
  EXPECT_GT(__builtin_popcountll(shapes_seen), 24);
}

}  // namespace
}  // namespace ffc::lighting
