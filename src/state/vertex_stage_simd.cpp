// The float vertex stage's transforms many vertices at a time (Highway, compiled per target as
// lighting_simd.cpp is; declared in vertex_stage.h). Each lane repeats the scalar code's
// operations in its order: positions as fmat::transform's ((m0 x + m1 y) + m2 z) + m3 w in float,
// normals as glm's row vector times matrix and glm::length in double, no fused multiply-add.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "state/vertex_stage_simd.cpp"
#include "simd/targets.h"  // before Highway: the targets we compile
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include <algorithm>
#include <cstring>

#include "state/vertex_stage.h"

HWY_BEFORE_NAMESPACE();
namespace ffc::state {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// m x (x, y, z, w) for one row r of the column-major matrix.
template <class D, class V = hn::Vec<D>>
HWY_INLINE V Row(D d, const glm::mat4& m, int r, V x, V y, V z, V w) {
  return hn::Add(hn::Add(hn::Add(hn::Mul(hn::Set(d, m[0][r]), x), hn::Mul(hn::Set(d, m[1][r]), y)),
                         hn::Mul(hn::Set(d, m[2][r]), z)),
                 hn::Mul(hn::Set(d, m[3][r]), w));
}

void TransformColumns(const glm::mat4& to_clip, const glm::mat4* to_eye, const float* const obj[4], size_t count,
                      glm::vec4* clip, float* const eye[4], bool eye_w_one) {
  const hn::ScalableTag<float> d;
  const size_t n = hn::Lanes(d);
  HWY_ALIGN float tail[4 * HWY_MAX_BYTES / sizeof(float)];
  for (size_t i = 0; i < count; i += n) {
    const auto x = hn::LoadU(d, obj[0] + i), y = hn::LoadU(d, obj[1] + i), z = hn::LoadU(d, obj[2] + i),
               w = hn::LoadU(d, obj[3] + i);
    const auto c0 = Row(d, to_clip, 0, x, y, z, w), c1 = Row(d, to_clip, 1, x, y, z, w),
               c2 = Row(d, to_clip, 2, x, y, z, w), c3 = Row(d, to_clip, 3, x, y, z, w);
    // The clip positions are records (x, y, z, w): interleaved, the last partial vector through
    // a buffer so that nothing past `count` is written.
    if (i + n <= count) {
      hn::StoreInterleaved4(c0, c1, c2, c3, d, &clip[i].x);
    } else {
      hn::StoreInterleaved4(c0, c1, c2, c3, d, tail);
      std::copy(tail, tail + 4 * (count - i), &clip[i].x);
    }
    if (to_eye) {
      for (int r = 0; r < 3; ++r) hn::StoreU(Row(d, *to_eye, r, x, y, z, w), d, eye[r] + i);
      hn::StoreU(eye_w_one ? hn::Set(d, 1.0f) : Row(d, *to_eye, 3, x, y, z, w), d, eye[3] + i);
    }
  }
}

bool EyeNormalColumns(const glm::dmat3& inv, bool normalize, double rescale, const double* const raw[3],
                      size_t count, float* const out[3]) {
  const hn::ScalableTag<double> d;
  const hn::Rebind<float, decltype(d)> df;
  const size_t n = hn::Lanes(d);
  const auto zero = hn::Zero(d);
  auto zero_met = hn::Lt(zero, zero);  // none
  for (size_t i = 0; i < count; i += n) {
    const auto x = hn::LoadU(d, raw[0] + i), y = hn::LoadU(d, raw[1] + i), z = hn::LoadU(d, raw[2] + i);
    hn::Vec<decltype(d)> e[3];
    for (int c = 0; c < 3; ++c)
      e[c] = hn::Add(hn::Add(hn::Mul(hn::Set(d, inv[c][0]), x), hn::Mul(hn::Set(d, inv[c][1]), y)),
                     hn::Mul(hn::Set(d, inv[c][2]), z));
    if (normalize) {
      const auto len = hn::Sqrt(hn::Add(hn::Add(hn::Mul(e[0], e[0]), hn::Mul(e[1], e[1])), hn::Mul(e[2], e[2])));
      const auto pos = hn::Gt(len, zero);  // else the normal stays as it is (zero, or not finite)
      // Lanes past `count` are the caller's padding, not vertices.
      zero_met = hn::Or(zero_met, hn::And(hn::Not(pos), hn::FirstN(d, count - i)));
      for (auto& c : e) c = hn::IfThenElse(pos, hn::Div(c, len), c);
    } else if (rescale > 0) {
      for (auto& c : e) c = hn::Div(c, hn::Set(d, rescale));
    }
    for (int c = 0; c < 3; ++c) hn::StoreU(hn::DemoteTo(df, e[c]), df, out[c] + i);
  }
  return !hn::AllFalse(d, zero_met);
}

// The packed arrays' columns (vertex_stage.h): a vector of elements at a time through Highway's
// interleaved loads, the rest one by one (copies: the client's pointer may have any alignment).
void FloatColumns(const uint8_t* packed, int comps, size_t count, float* const out[4]) {
  const hn::ScalableTag<float> d;
  const size_t n = hn::Lanes(d);
  size_t i = 0;
  const float* src = reinterpret_cast<const float*>(packed);  // read through unaligned loads
  hn::Vec<decltype(d)> c0, c1, c2, c3;
  if (comps == 3) {
    for (; i + n <= count; i += n) {
      hn::LoadInterleaved3(d, src + 3 * i, c0, c1, c2);
      hn::StoreU(c0, d, out[0] + i), hn::StoreU(c1, d, out[1] + i), hn::StoreU(c2, d, out[2] + i);
    }
  } else {
    for (; i + n <= count; i += n) {
      hn::LoadInterleaved4(d, src + 4 * i, c0, c1, c2, c3);
      hn::StoreU(c0, d, out[0] + i), hn::StoreU(c1, d, out[1] + i), hn::StoreU(c2, d, out[2] + i);
      hn::StoreU(c3, d, out[3] + i);
    }
  }
  for (; i < count; ++i)
    for (int k = 0; k < comps; ++k) std::memcpy(out[k] + i, packed + 4 * (size_t(comps) * i + size_t(k)), 4);
}

void DoubleColumns(const uint8_t* packed, size_t count, double* const out[3]) {
  const hn::ScalableTag<double> d;
  const hn::Rebind<float, decltype(d)> df;
  const size_t n = hn::Lanes(d);
  size_t i = 0;
  const float* src = reinterpret_cast<const float*>(packed);
  hn::Vec<decltype(df)> c0, c1, c2;
  for (; i + n <= count; i += n) {
    hn::LoadInterleaved3(df, src + 3 * i, c0, c1, c2);
    hn::StoreU(hn::PromoteTo(d, c0), d, out[0] + i), hn::StoreU(hn::PromoteTo(d, c1), d, out[1] + i);
    hn::StoreU(hn::PromoteTo(d, c2), d, out[2] + i);
  }
  for (; i < count; ++i)
    for (int k = 0; k < 3; ++k) {
      float f;
      std::memcpy(&f, packed + 4 * (3 * i + size_t(k)), 4);
      out[k][i] = f;
    }
}

}  // namespace HWY_NAMESPACE
}  // namespace ffc::state
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace ffc::state {

HWY_EXPORT(TransformColumns);
HWY_EXPORT(EyeNormalColumns);
HWY_EXPORT(FloatColumns);
HWY_EXPORT(DoubleColumns);

void float_columns(const uint8_t* packed, int comps, size_t count, float* const out[4]) {
  HWY_DYNAMIC_DISPATCH(FloatColumns)(packed, comps, count, out);
}

void double_columns(const uint8_t* packed, size_t count, double* const out[3]) {
  HWY_DYNAMIC_DISPATCH(DoubleColumns)(packed, count, out);
}

void transform_columns(const glm::mat4& to_clip, const glm::mat4* to_eye, const float* const obj[4], size_t count,
                       glm::vec4* clip, float* const eye[4], bool eye_w_one) {
  HWY_DYNAMIC_DISPATCH(TransformColumns)(to_clip, to_eye, obj, count, clip, eye, eye_w_one);
}

bool eye_normal_columns(const glm::dmat3& inv, bool normalize, double rescale, const double* const raw[3],
                        size_t count, float* const out[3]) {
  return HWY_DYNAMIC_DISPATCH(EyeNormalColumns)(inv, normalize, rescale, raw, count, out);
}

}  // namespace ffc::state
#endif  // HWY_ONCE
