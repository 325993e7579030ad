// The lighting's power (simd/pow.h, exp2(log2) in double): within 1 ulp and 1e-6 relative of
// double pow over the bases and exponents lighting meets (shininess and spot exponent in [0, 128]),
// exact where the power is exact, C's special values, and every SIMD target's kernel giving the
// scalar function's bits for the specular term (n.h)^s.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "lighting/lighting.h"
#include "lighting/lighting_simd.h"
#include "simd/pow.h"
#include "simd/target.h"

namespace ffc::lighting {
namespace {

using simd::pow_float;
constexpr float kInf = std::numeric_limits<float>::infinity();

// Distance in float steps between two finite floats of one sign.
int64_t ulps(float a, float b) {
  int32_t ia, ib;
  std::memcpy(&ia, &a, 4), std::memcpy(&ib, &b, 4);
  return std::llabs(int64_t(ia) - int64_t(ib));
}

TEST(Pow, WithinOneUlpOfDoublePowOverTheLightingsRange) {
  std::mt19937 rng(14);
  std::uniform_real_distribution<double> exponent(0, 128), log_base(std::log(1e-6), std::log(4.0)),
      log_result(std::log(1e-30), std::log(1e3));
  size_t checked = 0, exact = 0;
  double worst = 0;
  for (int i = 0; i < 400000; ++i) {
    // Every quarter from 0 to 128, then random exponents; bases log-uniform in [1e-6, 4], or
    // (odd i) chosen for a power log-uniform in [1e-30, 1e3].
    const float e = i < 513 * 200 ? float(i / 200) * 0.25f : float(exponent(rng));
    const float x = float(i % 2 && e > 0 ? std::exp(log_result(rng) / e) : std::exp(log_base(rng)));
    const double want = std::pow(double(x), double(e));
    const float got = pow_float(x, e);
    if (want > 1e30 || want < 1e-30) continue;  // past float's normal range: below
    const float rounded = float(want);
    ASSERT_LE(ulps(got, rounded), 1) << "pow(" << x << ", " << e << ") = " << got << ", double pow " << want;
    const double rel = std::abs(double(got) - want) / want;
    ASSERT_LE(rel, 1e-6) << "pow(" << x << ", " << e << ")";
    worst = std::max(worst, rel);
    exact += got == rounded;
    ++checked;
  }
  EXPECT_GT(checked, 200000u);
  RecordProperty("correctly_rounded", std::to_string(exact) + " of " + std::to_string(checked));
  // Correctly rounded but for rare halfway cases (the double result is good to about 1e-10).
  EXPECT_GT(double(exact), 0.999 * double(checked));
  EXPECT_LT(worst, 1.2e-7);  // 1 ulp relative is at most 2^-23
}

TEST(Pow, ExactWhereThePowerIs) {
  EXPECT_EQ(pow_float(0.5f, 3), 0.125f);
  EXPECT_EQ(pow_float(2, 10), 1024.0f);
  EXPECT_EQ(pow_float(4, 0.5f), 2.0f);
  EXPECT_EQ(pow_float(0.25f, 128), std::ldexp(1.0f, -256) /* underflows to 0 */);
  EXPECT_EQ(pow_float(0.5f, 126), std::ldexp(1.0f, -126));  // the least normal float
  EXPECT_EQ(pow_float(0.5f, 149), std::ldexp(1.0f, -149));  // the least subnormal
  for (float x : {1e-6f, 0.1f, 0.3f, 0.7071f, 0.9999f, 1.5f, 3.0f}) EXPECT_EQ(pow_float(x, 1), x) << x;
  for (float x : {0.1f, 0.3f, 0.9999f}) EXPECT_EQ(pow_float(x, 2), float(double(x) * double(x))) << x;
}

TEST(Pow, SpecialValuesAsCsPow) {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  EXPECT_EQ(pow_float(0, 0), 1.0f);  // GL's rule for shininess 0 (docs/deviations.md row 10)
  EXPECT_EQ(pow_float(nan, 0), 1.0f);
  EXPECT_EQ(pow_float(kInf, 0), 1.0f);
  EXPECT_EQ(pow_float(0, 5), 0.0f);
  EXPECT_EQ(pow_float(0, 0.001f), 0.0f);
  EXPECT_EQ(pow_float(0, -1), kInf);
  EXPECT_EQ(pow_float(kInf, 2), kInf);
  EXPECT_EQ(pow_float(kInf, -2), 0.0f);
  EXPECT_EQ(pow_float(1, 128), 1.0f);
  EXPECT_EQ(pow_float(1, nan), 1.0f);
  EXPECT_TRUE(std::isnan(pow_float(0.5f, nan)));
  EXPECT_TRUE(std::isnan(pow_float(nan, 2)));
  EXPECT_EQ(pow_float(2, 128), kInf);  // overflows to +inf, not FLT_MAX
  EXPECT_EQ(pow_float(3, 100), kInf);
  EXPECT_EQ(pow_float(2, 127.5f), float(std::pow(2.0, 127.5)));  // finite, below FLT_MAX
  EXPECT_EQ(pow_float(1e-20f, 10), 0.0f);  // 1e-200 underflows
}

// A light whose only term is the specular one (white, infinite viewer, directional): the kernel's
// colour is pow(max(0, n.h), s) itself, on every target the scalar function's bits.
TEST(Pow, EveryTargetsKernelGivesTheScalarPowsBits) {
  LightParams l[8];
  MaterialParams m[2];
  ModelParams model;
  model.ambient = {0, 0, 0, 1};
  l[0].enabled = true;
  l[0].ambient = l[0].diffuse = {0, 0, 0, 1};
  l[0].specular = {1, 1, 1, 1};
  l[0].position = {0.3, 0.5, 0.8, 0};
  for (auto& f : m) f.ambient = f.diffuse = {0, 0, 0, 1}, f.specular = {1, 1, 1, 1};
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> u(-1, 1);
  std::vector<glm::vec4> p, c;
  std::vector<glm::vec3> n;
  for (int v = 0; v < 999; ++v) {
    // Normals near h (the powers that are not 0) and anywhere.
    const glm::vec3 d(u(rng), u(rng), u(rng));
    n.push_back(glm::normalize(v % 2 ? d : glm::vec3(0.15f, 0.25f, 1.0f) + 0.2f * d));
    p.emplace_back(u(rng), u(rng), -3, 1), c.emplace_back(1);
  }
  size_t between = 0;
  for (double s : {0.0, 0.5, 1.0, 7.3, 10.0, 64.0, 100.5, 128.0}) {
    m[0].shininess = m[1].shininess = s;
    const Key key = make_key(l, m, model, false, false);
    const Prepared<float> prepared = prepare<float>(l, m, model, key);
    const glm::vec3 h = prepared.light[0].half;
    std::vector<Lit<float>> want(n.size());
    specialised<float>(key)(prepared, p.data(), n.data(), c.data(), n.size(), want.data());
    for (size_t v = 0; v < n.size(); ++v) {
      const float dot = (n[v].x * h.x + n[v].y * h.y) + n[v].z * h.z;
      const float nl = (n[v].x * prepared.light[0].pos.x + n[v].y * prepared.light[0].pos.y) + n[v].z * prepared.light[0].pos.z;
      const float expect = nl > 0 ? std::min(1.0f, pow_float(std::max(0.0f, dot), float(s))) : 0.0f;
      ASSERT_EQ(want[v].primary[0].r, expect) << v << " s " << s;
      between += expect > 0 && expect < 1;
    }
    for (const std::string& t : simd::available()) {
      ASSERT_TRUE(simd::restrict(t)) << t;
      std::vector<Lit<float>> got(n.size());
      vectorised(key)(prepared, p.data(), n.data(), c.data(), n.size(), got.data());
      for (size_t v = 0; v < n.size(); ++v)
        ASSERT_EQ(std::memcmp(&got[v].primary[0].r, &want[v].primary[0].r, 4), 0)
            << t << " vertex " << v << " s " << s << ": " << got[v].primary[0].r << " vs " << want[v].primary[0].r;
    }
  }
  simd::restrict("");
  EXPECT_GT(between, 2000u);
}

}  // namespace
}  // namespace ffc::lighting
