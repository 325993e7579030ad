// The float vertex stage on every SIMD target: its transforms on columns (vertex_stage_simd.cpp)
// give the scalar formulas' bits (fmat::transform; glm's row vector times matrix, length and
// division in double), and whole pictures and depth buffers drawn from elements, arrays and
// immediate mode are the same bytes on every target.
#include <gtest/gtest.h>

#include <cstring>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "backends/backend.h"
#include "lighting/lighting_simd.h"
#include "scene/scene.h"
#include "simd/target.h"
#include "state/context.h"
#include "state/float_matrix.h"
#include "state/vertex_stage.h"

namespace ffc {
namespace {

template <typename T>
bool same_bits(T a, T b) {
  return std::memcmp(&a, &b, sizeof a) == 0;
}

TEST(SimdStage, ColumnTransformsGiveTheScalarFormulasBits) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-3, 3);
  constexpr size_t kCount = 45;  // a partial last vector on every target
  const size_t padded = lighting::kSoaPad;
  for (int trial = 0; trial < 40; ++trial) {
    glm::mat4 clip_m, eye_m;
    glm::dmat3 inv;
    for (int c = 0; c < 4; ++c)
      for (int r = 0; r < 4; ++r) clip_m[c][r] = float(u(rng)), eye_m[c][r] = float(u(rng));
    for (int c = 0; c < 3; ++c)
      for (int r = 0; r < 3; ++r) inv[c][r] = u(rng);
    const bool normalize = trial % 3 != 2;
    const double rescale = trial % 3 == 2 ? 1.0 + std::abs(u(rng)) : 0.0;
    std::vector<float> obj[4];
    std::vector<double> raw[3];
    for (auto& v : obj) v.resize(padded);
    for (auto& v : raw) v.resize(padded);
    for (size_t i = 0; i < padded; ++i) {
      for (int k = 0; k < 4; ++k) obj[k][i] = float(u(rng));
      for (int k = 0; k < 3; ++k) raw[k][i] = u(rng);
      if (i % 9 == 4) raw[0][i] = raw[1][i] = raw[2][i] = 0;  // a zero normal
    }
    if (trial % 5 == 1) raw[1][7] = std::numeric_limits<double>::quiet_NaN();
    const float* const obj_cols[4] = {obj[0].data(), obj[1].data(), obj[2].data(), obj[3].data()};
    const double* const raw_cols[3] = {raw[0].data(), raw[1].data(), raw[2].data()};
    for (const std::string& t : simd::available()) {
      ASSERT_TRUE(simd::restrict(t));
      std::vector<glm::vec4> clip(kCount + 1, glm::vec4(-7));  // one past: never written
      std::vector<float> eye[4], normal[3];
      for (auto& v : eye) v.resize(padded);
      for (auto& v : normal) v.resize(padded);
      float* const eye_cols[4] = {eye[0].data(), eye[1].data(), eye[2].data(), eye[3].data()};
      float* const normal_cols[3] = {normal[0].data(), normal[1].data(), normal[2].data()};
      state::transform_columns(clip_m, &eye_m, obj_cols, kCount, clip.data(), eye_cols);
      const bool zero = state::eye_normal_columns(inv, normalize, rescale, raw_cols, kCount, normal_cols);
      EXPECT_EQ(zero, normalize) << t;  // vertex 4 has a zero normal
      EXPECT_EQ(clip[kCount], glm::vec4(-7)) << t;
      for (size_t i = 0; i < kCount; ++i) {
        const glm::vec4 o(obj[0][i], obj[1][i], obj[2][i], obj[3][i]);
        const glm::vec4 want_clip = state::fmat::transform(clip_m, o), want_eye = state::fmat::transform(eye_m, o);
        glm::dvec3 n = glm::dvec3(raw[0][i], raw[1][i], raw[2][i]) * inv;
        if (normalize) {
          const double len = glm::length(n);
          if (len > 0) n /= len;
        } else {
          n /= rescale;
        }
        for (int k = 0; k < 4; ++k) {
          ASSERT_TRUE(same_bits(clip[i][k], want_clip[k])) << t << " trial " << trial << " vertex " << i;
          ASSERT_TRUE(same_bits(eye[k][i], want_eye[k])) << t << " trial " << trial << " vertex " << i;
        }
        for (int k = 0; k < 3; ++k)
          ASSERT_TRUE(same_bits(normal[k][i], float(n[k]))) << t << " trial " << trial << " vertex " << i;
      }
    }
  }
  simd::restrict("");
}

// Normals whose quotient lies within a few double steps of a float's halfway point, where a
// shortcut for the division (a product with the reciprocal) would round to another float: x / 1.1
// for such x, found here by the scalar formulas; every target gives the quotient's float
// (GL_RESCALE_NORMAL with a scale of 1.1, an identity inverse).
TEST(SimdStage, NormalsNearAFloatsHalfwayPointRoundAsTheDivision) {
  const double scale = 1.1, inverse = 1 / scale;
  std::vector<double> x;
  for (float f = 0.1f; x.size() < 48 && f < 1; f = std::nextafter(f, 2.0f) + 1e-4f) {
    const double half_up = (double(f) + double(std::nextafter(f, 2.0f))) / 2;  // halfway, exact in double
    for (int k = -6; k <= 6; ++k) {
      const double q = half_up + k * std::ldexp(1.0, std::ilogb(half_up) - 52);
      const double v = q * scale;
      if (float(v * inverse) != float(v / scale)) x.push_back(v);
    }
  }
  ASSERT_GE(x.size(), 40u);  // the product would give other floats for these
  const size_t padded = lighting::kSoaPad;
  std::vector<double> raw[3];
  for (auto& v : raw) v.assign(padded, 0.0);
  std::copy(x.begin(), x.end(), raw[0].begin());
  const double* const raw_cols[3] = {raw[0].data(), raw[1].data(), raw[2].data()};
  for (const std::string& t : simd::available()) {
    ASSERT_TRUE(simd::restrict(t));
    std::vector<float> normal[3];
    for (auto& v : normal) v.assign(padded, 0.0f);
    float* const cols[3] = {normal[0].data(), normal[1].data(), normal[2].data()};
    state::eye_normal_columns(glm::dmat3(1), false, scale, raw_cols, x.size(), cols);
    for (size_t i = 0; i < x.size(); ++i) ASSERT_TRUE(same_bits(normal[0][i], float(x[i] / scale))) << t << " " << i;
  }
  simd::restrict("");
}

// The packed arrays' columns (float_columns, double_columns): every component of every element
// in its column, from a pointer of any alignment, a partial last vector on every target, nothing
// written past the last element.
TEST(SimdStage, PackedArraysGiveTheirColumns) {
  constexpr size_t kCount = 45, kPad = lighting::kSoaPad;
  for (const std::string& t : simd::available()) {
    ASSERT_TRUE(simd::restrict(t));
    for (int comps : {3, 4})
      for (size_t offset : {0, 1, 4}) {
        std::vector<uint8_t> bytes(offset + kCount * size_t(comps) * 4);
        for (size_t i = 0; i < kCount * size_t(comps); ++i) {
          const float v = float(i) * 0.37f - 5;
          std::memcpy(&bytes[offset + 4 * i], &v, 4);
        }
        std::vector<float> col[4];
        for (auto& c : col) c.assign(kPad, -99.0f);
        float* const cols[4] = {col[0].data(), col[1].data(), col[2].data(), col[3].data()};
        state::float_columns(bytes.data() + offset, comps, kCount, cols);
        std::vector<double> dcol[3];
        for (auto& c : dcol) c.assign(kPad, -99.0);
        double* const dcols[3] = {dcol[0].data(), dcol[1].data(), dcol[2].data()};
        if (comps == 3) state::double_columns(bytes.data() + offset, kCount, dcols);
        for (size_t j = 0; j < kPad; ++j)
          for (int k = 0; k < 4; ++k) {
            const float want = j < kCount && k < comps ? float(j * size_t(comps) + size_t(k)) * 0.37f - 5 : -99.0f;
            ASSERT_EQ(col[k][j], want) << t << " comps " << comps << " offset " << offset << " element " << j;
            if (comps == 3 && k < 3) {
              ASSERT_EQ(dcol[k][j], double(want)) << t << " element " << j;
            }
          }
      }
  }
  simd::restrict("");
}

struct Picture {
  std::vector<uint8_t> color;
  std::vector<uint32_t> depth;
};

Picture draw(scene::Description d, scene::DrawPath path) {
  for (scene::Object& o : d.objects) o.draw = path;
  auto soft = backends::make("soft");
  soft->begin(d.width, d.height);
  scene::draw(d);
  const raster::Framebuffer& fb = state::Context::current()->framebuffer();
  return {fb.color, fb.depth};
}

std::vector<scene::Description> scenes() {
  auto sphere = [](int depth) {
    scene::Spec s = scene::builtin("icosphere");
    s.depth = depth;
    s.normals = mesh::NormalSource::Average;
    return scene::describe(s);
  };
  std::vector<scene::Description> out{sphere(4)};
  scene::Description d = sphere(3);  // a spot light and an attenuated point light, specular
  d.lights[0].specular = {1, 1, 1, 1}, d.front.specular = {1, 1, 1, 1}, d.front.shininess = 20;
  d.lights[1] = d.lights[0];
  d.lights[1].position = {1, 2, 3, 1}, d.lights[1].spot_cutoff = 30, d.lights[1].spot_exponent = 5;
  d.lights[1].spot_direction = {-1, -2, -3};
  d.lights[2] = d.lights[0];
  d.lights[2].position = {-2, 1, 2, 1}, d.lights[2].linear_attenuation = 0.3f;
  d.light_model.local_viewer = true;
  out.push_back(d);
  d = sphere(3);  // two sides, separate specular, colour material from the positions
  d.cull_face = true, d.cull_mode = scene::Face::Front, d.light_model.two_sided = true;
  d.light_model.separate_specular = true, d.lights[0].specular = {1, 1, 1, 1}, d.back.specular = {1, 1, 1, 1};
  d.color_material.enabled = true;
  d.objects[0].color.kind = scene::ColorSource::Kind::Position;
  out.push_back(d);
  return out;
}

TEST(SimdStage, EveryTargetDrawsTheSameBytes) {
  const std::vector<std::string> targets = simd::available();
  for (const scene::Description& d : scenes())
    for (auto path : {scene::DrawPath::Elements, scene::DrawPath::Arrays, scene::DrawPath::Immediate}) {
      ASSERT_TRUE(simd::restrict("scalar"));
      const Picture want = draw(d, path);
      size_t drawn = 0;
      for (size_t i = 0; i < want.color.size(); i += 4) drawn += want.color[i] != 0;
      EXPECT_GT(drawn, want.color.size() / 4 / 50) << "a picture with something in it";
      for (const std::string& t : targets) {
        ASSERT_TRUE(simd::restrict(t));
        const Picture got = draw(d, path);
        EXPECT_TRUE(got.color == want.color) << t << " " << scene::to_string(path);
        EXPECT_TRUE(got.depth == want.depth) << t << " " << scene::to_string(path);
      }
    }
  simd::restrict("");
}

}  // namespace
}  // namespace ffc
