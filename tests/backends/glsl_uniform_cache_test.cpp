// The GLSL backend's uniform cache (uniform_cache.h) against uniforms() itself: every value it
// hands back equals the one uniforms() computes for the same state, whether it was rebuilt or
// reused, and it rebuilds only when what uniforms() reads besides the matrices changed.
#include <gtest/gtest.h>

#ifdef FFCOMPAT_WITH_GLSL  // a build with EGL
#include <cstring>

#include "backends/glsl/uniform_cache.h"

namespace ffc::glsl {
namespace {

struct World {
  lighting::LightParams lights[8];
  lighting::MaterialParams materials[2];
  state::FragmentState fragment;
  state::SinkState state() {
    state::SinkState s;
    std::memset(static_cast<void*>(static_cast<state::SinkValues*>(&s)), 0, sizeof(state::SinkValues));
    s.lighting = true;
    s.key.set_light(0, false, false, false);
    s.key.set(lighting::Key::kSpecular);
    s.lights = lights, s.materials = materials, s.fragment = &fragment;
    s.mvp = glm::mat4(1), s.modelview = glm::mat4(1), s.normal_inverse = glm::dmat3(1);
    s.model.ambient = glm::dvec4(0.2, 0.2, 0.2, 1);
    return s;
  }
};

void expect_as_uniforms(UniformCache& cache, const ProgramKey& k, const state::SinkState& s) {
  const std::vector<Uniform> want = uniforms(k, &s);
  const std::vector<Uniform>& got = cache.values(s);
  ASSERT_EQ(got.size(), want.size());
  for (size_t i = 0; i < want.size(); ++i) {
    EXPECT_EQ(got[i].name, want[i].name);
    for (int c = 0; c < want[i].size; ++c) EXPECT_EQ(got[i].value[size_t(c)], want[i].value[size_t(c)]) << want[i].name << c;
  }
}

TEST(GlslUniformCache, ValuesEqualUniformsAndRebuildOnlyWhenMoreThanTheMatricesChange) {
  World w;
  w.lights[0].enabled = true;
  w.lights[0].diffuse = glm::dvec4(1, 0.5, 0.25, 1);
  w.materials[0].shininess = 10;
  state::SinkState s = w.state();
  const ProgramKey k = ProgramKey::of(s);
  UniformCache cache(k);
  expect_as_uniforms(cache, k, s);
  EXPECT_EQ(cache.rebuilds(), 1u);
  expect_as_uniforms(cache, k, s);  // the same state: reused
  EXPECT_EQ(cache.rebuilds(), 1u);
  // Another object: only the matrices change; copied, not rebuilt.
  s.mvp = glm::mat4(2), s.modelview[3] = glm::vec4(1, 2, 3, 1), s.normal_inverse = glm::dmat3(0.5);
  expect_as_uniforms(cache, k, s);
  EXPECT_EQ(cache.rebuilds(), 1u);
  // A material and a light change: rebuilt, then the first state again: reused.
  w.materials[0].diffuse = glm::dvec4(0.1, 0.2, 0.3, 0.4);
  expect_as_uniforms(cache, k, s);
  EXPECT_EQ(cache.rebuilds(), 2u);
  w.lights[0].position = glm::dvec4(0, 1, 0, 0);
  expect_as_uniforms(cache, k, s);
  EXPECT_EQ(cache.rebuilds(), 3u);
  w.materials[0].diffuse = glm::dvec4(0.8, 0.8, 0.8, 1), w.lights[0].position = glm::dvec4(0, 0, 1, 0);
  expect_as_uniforms(cache, k, s);
  EXPECT_EQ(cache.rebuilds(), 3u);
}

TEST(GlslUniformCache, MoreStatesThanItKeepsAreRebuiltAndStillRight) {
  World w;
  w.lights[0].enabled = true;
  state::SinkState s = w.state();
  const ProgramKey k = ProgramKey::of(s);
  UniformCache cache(k);
  const size_t n = UniformCache::kStates + 1;  // one more than it keeps: each visit evicts the next
  for (int round = 0; round < 2; ++round)
    for (size_t m = 0; m < n; ++m) {
      w.materials[0].shininess = double(m);
      expect_as_uniforms(cache, k, s);
    }
  EXPECT_EQ(cache.rebuilds(), 2 * n);  // least recently used replaced: a cycle one too long misses every time
  for (size_t m = n - UniformCache::kStates; m < n; ++m) {  // the last kStates are kept
    w.materials[0].shininess = double(m);
    expect_as_uniforms(cache, k, s);
  }
  EXPECT_EQ(cache.rebuilds(), 2 * n);
}

}  // namespace
}  // namespace ffc::glsl
#endif
