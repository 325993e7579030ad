// The Highway lighting kernel (lighting_simd.h) on every SIMD target this machine runs gives the
// scalar float kernel's bits, over generated states and vertices: every light kind, spot cones,
// attenuation, colour material in each mode and face, two sides, a local viewer, separate
// specular, shininess 0, w other than 1, normals long enough to overflow the specular power, zero
// and non-finite inputs.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "lighting/lighting.h"
#include "lighting/lighting_simd.h"
#include "simd/target.h"

namespace ffc::lighting {
namespace {

struct Case {
  LightParams l[8];
  MaterialParams m[2];
  ModelParams model;
  std::vector<glm::vec4> p, c;
  std::vector<glm::vec3> n;
};

Case make_case(std::mt19937& rng, int trial) {
  std::uniform_real_distribution<double> u(-1, 1), pos(0, 1);
  Case s;
  const int lights = trial % 9;  // 0 to 8 lights
  for (int i = 0; i < lights; ++i) {
    LightParams& l = s.l[(i * 5 + trial) % 8];
    l.enabled = true;
    l.diffuse = {pos(rng), pos(rng), pos(rng), 1};
    l.specular = trial % 7 == 0 ? glm::dvec4(0, 0, 0, 1) : glm::dvec4(pos(rng), pos(rng), pos(rng), 1);
    l.ambient = {pos(rng), pos(rng), pos(rng), 1};
    const int kind = (trial / 9) % 4;  // directional, point, mixed, mixed with spots
    const bool point = kind == 1 || (kind >= 2 && i % 2 == 0);
    l.position = {u(rng) * 5, u(rng) * 5, u(rng) * 5, point ? (trial % 5 == 0 ? 2.0 : 1.0) : 0.0};
    if (kind == 3 && i % 3 != 2) {
      l.spot_cutoff = i % 4 == 1 ? 90.0 : 5 + 85 * pos(rng);
      l.spot_exponent = i % 5 == 0 ? 0.0 : 128 * pos(rng);
      l.spot_direction = {u(rng), u(rng), u(rng)};
    }
    if ((trial / 36) % 2) {
      l.constant_attenuation = 0.5 + pos(rng), l.linear_attenuation = pos(rng), l.quadratic_attenuation = pos(rng);
    }
  }
  for (auto& m : s.m) {
    m.ambient = {pos(rng), pos(rng), pos(rng), pos(rng)};
    m.diffuse = {pos(rng), pos(rng), pos(rng), pos(rng)};
    m.specular = (trial / 3) % 2 ? glm::dvec4(pos(rng), pos(rng), pos(rng), 1) : glm::dvec4(0, 0, 0, 1);
    m.shininess = trial % 11 == 0 ? 0.0 : 128 * pos(rng);
    m.emission = {0.3 * pos(rng), 0.2 * pos(rng), 0, 1};
  }
  s.model.ambient = {0.3 * pos(rng), 0.2, 0.1, 1};
  s.model.two_side = (trial / 2) % 2;
  s.model.local_viewer = (trial / 4) % 2;
  s.model.separate_specular = (trial / 8) % 2;
  s.model.color_material = (trial / 16) % 2;
  static constexpr unsigned kModes[] = {0x1200, 0x1201, 0x1202, 0x1600, 0x1602};
  s.model.cm_mode = kModes[(trial / 32) % 5];
  s.model.cm_faces = 1 + (trial / 5) % 3;
  // Vertices: in front of the eye, some at w != 1, a few at the origin, on a light or not finite.
  const int count = 1 + trial % 83;
  const float inf = std::numeric_limits<float>::infinity(), nan = std::numeric_limits<float>::quiet_NaN();
  for (int v = 0; v < count; ++v) {
    glm::vec4 p(u(rng), u(rng), u(rng) - 3, 1);
    if (v % 7 == 3) p.w = float(u(rng) * 2);
    if (v % 13 == 5) p = glm::vec4(0, 0, 0, v % 2);
    if (v % 17 == 6) p = glm::vec4(glm::vec3(s.l[0].position), 1);
    glm::vec3 n(u(rng), u(rng), u(rng));
    if (v % 3 != 0) n = glm::normalize(n);
    if (v % 19 == 7) n = glm::vec3(0);
    if (v % 23 == 9) n *= float(2 + 3 * pos(rng));  // long enough for n.h^shininess to overflow
    glm::vec4 c(pos(rng), pos(rng), pos(rng), pos(rng));
    if (trial % 29 == 1 && v % 11 == 2) p.x = v % 2 ? nan : inf, n.y = nan, c.g = inf;
    s.p.push_back(p), s.n.push_back(n), s.c.push_back(c);
  }
  return s;
}

bool same_bits(float a, float b) { return std::memcmp(&a, &b, sizeof a) == 0; }

TEST(SimdKernel, EveryTargetGivesTheScalarKernelsBits) {
  const std::vector<std::string> targets = simd::available();
  ASSERT_FALSE(targets.empty());
  std::mt19937 rng(2026);
  unsigned long long shapes = 0;
  size_t compared = 0;
  for (int trial = 0; trial < 720; ++trial) {
    Case s = make_case(rng, trial);
    const Key key = make_key(s.l, s.m, s.model, false, false);
    shapes |= 1ull << (shape_index(key) & 63);
    const Prepared<float> prepared = prepare<float>(s.l, s.m, s.model, key);
    const size_t count = s.p.size();
    std::vector<Lit<float>> want(count);
    specialised<float>(key)(prepared, s.p.data(), s.n.data(), s.c.data(), count, want.data());
    for (const std::string& t : targets) {
      ASSERT_TRUE(simd::restrict(t)) << t;
      ASSERT_EQ(simd::current(), t);
      std::vector<Lit<float>> got(count);
      vectorised(key)(prepared, s.p.data(), s.n.data(), s.c.data(), count, got.data());
      for (size_t v = 0; v < count; ++v)
        for (int f = 0; f < 2; ++f)
          for (int k = 0; k < 4; ++k) {
            ASSERT_TRUE(same_bits(want[v].primary[f][k], got[v].primary[f][k]))
                << t << " trial " << trial << " vertex " << v << " face " << f << " component " << k << ": "
                << want[v].primary[f][k] << " vs " << got[v].primary[f][k];
            ASSERT_TRUE(same_bits(want[v].secondary[f][k], got[v].secondary[f][k]))
                << t << " trial " << trial << " vertex " << v << " secondary face " << f << " component " << k << ": " << want[v].secondary[f][k] << " vs " << got[v].secondary[f][k];
          }
      compared += count;
    }
  }
  simd::restrict("");
  EXPECT_GT(compared, 720u * targets.size() * 30);
  EXPECT_GE(__builtin_popcountll(shapes), 40);  // most of the 128 shapes' low bits met
}

// The columns entry point lights the padding lanes without touching what lies past them, and a
// vertex's colours do not depend on its neighbours (a lane is a vertex).
TEST(SimdKernel, AVertexsColoursDoNotDependOnItsLane) {
  std::mt19937 rng(5);
  Case s = make_case(rng, 2 * 9 + 3 * 4 + 1);  // point lights, two-sided, specular
  const Key key = make_key(s.l, s.m, s.model, false, false);
  const Prepared<float> prepared = prepare<float>(s.l, s.m, s.model, key);
  std::vector<Lit<float>> all(s.p.size());
  vectorised(key)(prepared, s.p.data(), s.n.data(), s.c.data(), s.p.size(), all.data());
  for (size_t v = 0; v < s.p.size(); ++v) {
    Lit<float> one;
    vectorised(key)(prepared, &s.p[v], &s.n[v], &s.c[v], 1, &one);
    for (int k = 0; k < 4; ++k) ASSERT_TRUE(same_bits(one.primary[1][k], all[v].primary[1][k])) << v;
  }
}

}  // namespace
}  // namespace ffc::lighting
