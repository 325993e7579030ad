// The GLSL backend's parts that need no GL: the primitives as core-profile lists with the
// provoking vertex last, and the programs generated from a lighting key (only its terms).
#include <gtest/gtest.h>

#ifdef FFCOMPAT_WITH_GLSL  // a build with EGL
#include <cmath>

#include "backends/glsl/primitives.h"
#include "backends/glsl/shader_gen.h"

namespace ffc::glsl {
namespace {

std::vector<uint32_t> list(GLenum mode, size_t n, SplitRule rule, GLenum want_mode) {
  std::vector<uint32_t> out;
  EXPECT_EQ(decompose(mode, nullptr, n, rule, out), want_mode);
  return out;
}

TEST(GlslPrimitives, FlatQuadsSplitWithTheFourthVertexLast) {
  SplitRule flat;
  flat.flat = true;
  EXPECT_EQ(list(GL_QUADS, 4, flat, GL_TRIANGLES), (std::vector<uint32_t>{0, 1, 3, 1, 2, 3}));
  // Smooth quads from arrays inside the view volume: llvmpipe's fan from the first vertex.
  EXPECT_EQ(list(GL_QUADS, 4, {}, GL_TRIANGLES), (std::vector<uint32_t>{0, 1, 2, 0, 2, 3}));
}

TEST(GlslPrimitives, FlatQuadStripsPutTheirFourthVertexLast) {
  SplitRule flat;
  flat.flat = true;
  EXPECT_EQ(list(GL_QUAD_STRIP, 4, flat, GL_TRIANGLES), (std::vector<uint32_t>{0, 1, 3, 2, 0, 3}));
}

TEST(GlslPrimitives, FlatPolygonsPutTheFirstVertexLastKeepingTheWinding) {
  SplitRule flat;
  flat.flat = true;
  EXPECT_EQ(list(GL_POLYGON, 5, flat, GL_TRIANGLES), (std::vector<uint32_t>{1, 2, 0, 2, 3, 0, 3, 4, 0}));
}

TEST(GlslPrimitives, StripsFansAndLoops) {
  EXPECT_EQ(list(GL_TRIANGLE_STRIP, 5, {}, GL_TRIANGLES), (std::vector<uint32_t>{0, 1, 2, 2, 1, 3, 2, 3, 4}));
  EXPECT_EQ(list(GL_TRIANGLE_FAN, 4, {}, GL_TRIANGLES), (std::vector<uint32_t>{0, 1, 2, 0, 2, 3}));
  EXPECT_EQ(list(GL_LINE_LOOP, 3, {}, GL_LINES), (std::vector<uint32_t>{0, 1, 1, 2, 2, 0}));
  EXPECT_EQ(list(GL_QUAD_STRIP, 4, {}, GL_TRIANGLES), (std::vector<uint32_t>{0, 1, 3, 0, 3, 2}));
  EXPECT_TRUE(list(GL_TRIANGLES, 2, {}, GL_TRIANGLES).empty());  // no whole triangle
}

TEST(GlslPrimitives, ElementsNameTheVertices) {
  const uint32_t e[4] = {7, 5, 9, 2};
  std::vector<uint32_t> out;
  EXPECT_EQ(decompose(GL_QUADS, e, 4, {false, true, false}, out), GLenum(GL_TRIANGLES));
  EXPECT_EQ(out, (std::vector<uint32_t>{7, 5, 2, 5, 9, 2}));  // from elements: the draw module's split
}

ProgramKey lit_key(bool local, bool attenuated, bool spot, bool specular) {
  ProgramKey k;
  k.lit = true;
  k.key.set_light(0, local, spot, attenuated);
  k.key.set(lighting::Key::kSpecular, specular);
  return k;
}

bool has(const std::string& s, const std::string& what) { return s.find(what) != std::string::npos; }

TEST(GlslShaders, OneDirectionalDiffuseLightHasOnlyItsTerms) {
  const Sources s = generate(lit_key(false, false, false, false));
  EXPECT_TRUE(has(s.vertex, "u_light0_diffuse"));
  EXPECT_FALSE(has(s.vertex, "u_light1_"));
  EXPECT_FALSE(has(s.vertex, "u_modelview"));  // no eye position needed
  EXPECT_FALSE(has(s.vertex, "power("));        // no specular, no spot
  EXPECT_FALSE(has(s.vertex, "v_back"));
  EXPECT_FALSE(has(s.vertex, "flat "));
  EXPECT_EQ(s.feedback, (std::vector<std::string>{"gl_Position", "v_front"}));
}

TEST(GlslShaders, LocalAttenuatedSpotLightWithSpecularReadsTheEyePosition) {
  const Sources s = generate(lit_key(true, true, true, true));
  for (const char* w : {"u_modelview", "u_light0_attenuation", "u_light0_spot_cos", "u_front_shininess", "power("})
    EXPECT_TRUE(has(s.vertex, w)) << w;
  EXPECT_FALSE(has(s.vertex, "u_light0_half"));  // a local light's half vector varies per vertex
}

TEST(GlslShaders, TwoSidedFlatLightingHasFlatFrontAndBackColours) {
  ProgramKey k = lit_key(false, false, false, true);
  k.key.set(lighting::Key::kTwoSide);
  k.flat = true;
  const Sources s = generate(k);
  EXPECT_TRUE(has(s.vertex, "flat out vec4 v_back;"));
  EXPECT_TRUE(has(s.fragment, "gl_FrontFacing ? v_front : v_back"));
  EXPECT_TRUE(has(s.vertex, "u_back_shininess"));
  EXPECT_EQ(s.feedback.size(), 3u);
}

TEST(GlslShaders, ColourMaterialTakesTheTrackedTermsFromTheVertexColour) {
  ProgramKey k = lit_key(false, false, false, false);
  k.key.set(lighting::Key::kColorMaterial);
  k.cm_faces = 1, k.cm_mode = GL_AMBIENT_AND_DIFFUSE;
  const Sources s = generate(k);
  EXPECT_TRUE(has(s.vertex, "vec3 ma = a_color.rgb, md = a_color.rgb;"));
  EXPECT_TRUE(has(s.vertex, "a_color.a));"));
  for (const Uniform& u : uniforms(k, nullptr)) EXPECT_NE(u.name, "u_front_ambient");
}

TEST(GlslShaders, UniformValuesFollowTheState) {
  lighting::LightParams lights[8];
  lighting::MaterialParams mats[2];
  lights[0].enabled = true;
  lights[0].position = {3, 0, 4, 0};  // directional: the unit direction (0.6, 0, 0.8)
  lights[0].specular = {1, 1, 1, 1};
  mats[0].specular = {0.5, 0.5, 0.5, 1};
  state::SinkState s;
  s.lighting = true;
  s.lights = lights, s.materials = mats;
  s.key = lighting::make_key(lights, mats, s.model, false, false);
  const ProgramKey k = ProgramKey::of(s);
  ASSERT_TRUE(k.key.specular());
  bool seen_position = false, seen_half = false;
  for (const Uniform& u : uniforms(k, &s)) {
    if (u.name == "u_light0_position") {
      seen_position = true;
      EXPECT_FLOAT_EQ(u.value[0], 0.6f);
      EXPECT_FLOAT_EQ(u.value[2], 0.8f);
    }
    if (u.name == "u_light0_half") {  // (0.6, 0, 1.8) / |(0.6, 0, 1.8)|
      seen_half = true;
      const double len = std::sqrt(0.36 + 3.24);
      EXPECT_NEAR(u.value[0], 0.6 / len, 1e-7);
      EXPECT_NEAR(u.value[2], 1.8 / len, 1e-7);
    }
  }
  EXPECT_TRUE(seen_position && seen_half);
}

TEST(GlslShaders, ProgramKeysPackOnlyWhatChangesTheCode) {
  ProgramKey a = lit_key(false, false, false, true), b = a;
  b.key.set(lighting::Key::kShininessZero);  // no code of ours depends on it
  EXPECT_EQ(a.packed(), b.packed());
  b.flat = true;
  EXPECT_NE(a.packed(), b.packed());
  ProgramKey c = a;
  c.key.set_light(3, false, false, false);
  EXPECT_NE(a.packed(), c.packed());
}

}  // namespace
}  // namespace ffc::glsl
#endif  // FFCOMPAT_WITH_GLSL
