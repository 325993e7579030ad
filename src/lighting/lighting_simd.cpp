// The float lighting kernel in Highway, one vertex a lane (lighting_simd.h). This file is compiled
// once per SIMD target (hwy/foreach_target.h includes it again for each); HWY_ONCE marks the part
// compiled once. Each lane repeats light_impl's scalar operations in the same order: dot products
// as (x*x' + y*y') + z*z', divisions and square roots (exact in IEEE on every target), comparisons
// as C++'s (no Ne: Highway's is ordered on AVX-512, where != is true for a NaN), max(0, x) as the
// select (0 < x ? x : 0), and no MulAdd (it fuses). The project compiles with -ffp-contract=off, so
// the compiler does not fuse the separate multiplies and adds either.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "lighting/lighting_simd.cpp"
#include "simd/targets.h"  // before Highway: the targets we compile
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <exception>
#include <limits>

#include "lighting/lighting_simd.h"
#include "simd/target.h"

HWY_BEFORE_NAMESPACE();
namespace ffc::lighting {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

using D = hn::ScalableTag<float>;
using V = hn::Vec<D>;
using M = hn::Mask<D>;

struct V3s {  // a vec3 per lane
  V x, y, z;
};

HWY_INLINE V3s Splat(D d, const V3<float>& v) { return {hn::Set(d, v.x), hn::Set(d, v.y), hn::Set(d, v.z)}; }
HWY_INLINE V Dot(const V3s& a, const V3s& b) {
  return hn::Add(hn::Add(hn::Mul(a.x, b.x), hn::Mul(a.y, b.y)), hn::Mul(a.z, b.z));
}
HWY_INLINE V3s Add3(const V3s& a, const V3s& b) { return {hn::Add(a.x, b.x), hn::Add(a.y, b.y), hn::Add(a.z, b.z)}; }
HWY_INLINE V3s Mul3(const V3s& a, const V3s& b) { return {hn::Mul(a.x, b.x), hn::Mul(a.y, b.y), hn::Mul(a.z, b.z)}; }
HWY_INLINE V3s Scale(V s, const V3s& a) { return {hn::Mul(s, a.x), hn::Mul(s, a.y), hn::Mul(s, a.z)}; }
HWY_INLINE V3s Select(M m, const V3s& a, const V3s& b) {
  return {hn::IfThenElse(m, a.x, b.x), hn::IfThenElse(m, a.y, b.y), hn::IfThenElse(m, a.z, b.z)};
}
// len > 0 ? v / len : 0, len the vector's length (glm::length: sqrt of the dot product).
HWY_INLINE V3s UnitOrZero(D d, const V3s& v, V* len_out = nullptr) {
  const V len = hn::Sqrt(Dot(v, v));
  if (len_out) *len_out = len;
  const M pos = hn::Gt(len, hn::Zero(d));
  return {hn::IfThenElseZero(pos, hn::Div(v.x, len)), hn::IfThenElseZero(pos, hn::Div(v.y, len)),
          hn::IfThenElseZero(pos, hn::Div(v.z, len))};
}
HWY_INLINE V Max0(D d, V x) { return hn::IfThenElseZero(hn::Gt(x, hn::Zero(d)), x); }  // std::max(0, x)
// !(x < 1) ? 1 : x > 0 ? x : 0: a NaN to 1, as light_impl's saturate.
HWY_INLINE V Saturate(D d, V x) { return hn::IfThenElse(hn::Lt(x, hn::Set(d, 1.0f)), Max0(d, x), hn::Set(d, 1.0f)); }

#include "simd/pow_core.h"  // pow_double for this target (simd/pow.h)

// The operations simd/pow.h's pow_double needs, on vectors of doubles.
struct PowOps {
  using DD = hn::ScalableTag<double>;
  using DU = hn::RebindToUnsigned<DD>;
  using V = hn::Vec<DD>;
  using M = hn::Mask<DD>;
  DD d;
  DU du;
  HWY_INLINE V set(double c) const { return hn::Set(d, c); }
  HWY_INLINE V add(V a, V b) const { return hn::Add(a, b); }
  HWY_INLINE V sub(V a, V b) const { return hn::Sub(a, b); }
  HWY_INLINE V mul(V a, V b) const { return hn::Mul(a, b); }
  HWY_INLINE V div(V a, V b) const { return hn::Div(a, b); }
  HWY_INLINE M lt(V a, V b) const { return hn::Lt(a, b); }
  HWY_INLINE M gt(V a, V b) const { return hn::Gt(a, b); }
  HWY_INLINE M eq(V a, V b) const { return hn::Eq(a, b); }
  HWY_INLINE V select(M m, V a, V b) const { return hn::IfThenElse(m, a, b); }
  HWY_INLINE V and_bits(V v, uint64_t k) const { return hn::BitCast(d, hn::And(hn::BitCast(du, v), hn::Set(du, k))); }
  HWY_INLINE V or_bits(V v, uint64_t k) const { return hn::BitCast(d, hn::Or(hn::BitCast(du, v), hn::Set(du, k))); }
  HWY_INLINE V shr52(V v) const { return hn::BitCast(d, hn::ShiftRight<52>(hn::BitCast(du, v))); }
  HWY_INLINE V shl52(V v) const { return hn::BitCast(d, hn::ShiftLeft<52>(hn::BitCast(du, v))); }
};

// pow(base, e) in every lane: simd/pow.h's exp2(log2) in double, half a vector of floats at a time
// (a vector of doubles holds half as many), the scalar kernel's bits (simd::pow_float).
HWY_INLINE V PowLanes(D d, V base, float e) {
  if (e == 0) return hn::Set(d, 1.0f);  // pow(x, 0) is 1 for every x, NaN included
  const PowOps o;
  const hn::Rebind<float, PowOps::DD> dh;
  HWY_ALIGN float b[HWY_MAX_BYTES / sizeof(float)];
  hn::Store(base, d, b);
  for (size_t i = 0; i < hn::Lanes(d); i += hn::Lanes(dh)) {
    PowOps::M over;
    const PowOps::V y = pow_double(o, hn::PromoteTo(o.d, hn::LoadU(dh, b + i)), double(e), &over);
    auto r = hn::DemoteTo(dh, y);
    if (!hn::AllFalse(o.d, over)) {  // +inf: the mask carried to the float lanes as 1.0
      const auto inf = hn::Eq(hn::DemoteTo(dh, hn::IfThenElseZero(over, hn::Set(o.d, 1.0))), hn::Set(dh, 1.0f));
      r = hn::IfThenElse(inf, hn::Set(dh, std::numeric_limits<float>::infinity()), r);
    }
    hn::StoreU(r, dh, b + i);
  }
  return hn::Load(d, b);
}

constexpr unsigned kAmbient = 0x1200, kDiffuse = 0x1201, kSpecular = 0x1202, kEmission = 0x1600;

// One vector of vertices at offset i. The shape's template arguments are the terms that change
// the code's structure (as lighting.cpp's StaticShape); the rest are uniform per call and read
// once per vector, a branch per light and vector rather than per vertex.
// LongOnly: a key without the specular term whose batch holds a long normal (LightColumns): the
// term is computed for the lanes whose normal is long alone, as light_impl decides per vertex.
template <bool TwoSide, bool Specular, unsigned Kind, bool LongOnly = false>
HWY_INLINE void LightVector(D d, const Prepared<float>& c, const SoaIn& in, size_t i, const SoaOut& out) {
  const Key& key = c.key;
  const bool local_viewer = key.local_viewer(), color_material = key.color_material(),
             separate = key.separate_specular();
  const V zero = hn::Zero(d), one = hn::Set(d, 1.0f);
  V3s p{hn::LoadU(d, in.p[0] + i), hn::LoadU(d, in.p[1] + i), hn::LoadU(d, in.p[2] + i)};
  {
    const V w = hn::LoadU(d, in.p[3] + i);
    const M divide = hn::Not(hn::Or(hn::Eq(w, zero), hn::Eq(w, one)));  // w != 0 && w != 1
    // Only where a lane divides: three vector divisions cost as much as the rest of a directional
    // light's vector, and outside spec mode the stage sets w to 1 before the lighting.
    if (!hn::AllFalse(d, divide)) p = Select(divide, V3s{hn::Div(p.x, w), hn::Div(p.y, w), hn::Div(p.z, w)}, p);
  }
  const V3s n{hn::LoadU(d, in.n[0] + i), hn::LoadU(d, in.n[1] + i), hn::LoadU(d, in.n[2] + i)};
  V3s cm{zero, zero, zero};
  V cm_a = zero;
  if (color_material) {
    cm = {hn::LoadU(d, in.c[0] + i), hn::LoadU(d, in.c[1] + i), hn::LoadU(d, in.c[2] + i)};
    cm_a = hn::LoadU(d, in.c[3] + i);
  }
  V3s to_eye{zero, zero, one};
  if (local_viewer) {
    const V3s neg{hn::Neg(p.x), hn::Neg(p.y), hn::Neg(p.z)};
    const V len = hn::Sqrt(Dot(p, p));
    const M pos = hn::Gt(len, zero);
    to_eye = {hn::IfThenElseZero(pos, hn::Div(neg.x, len)), hn::IfThenElseZero(pos, hn::Div(neg.y, len)),
              hn::IfThenElseZero(pos, hn::Div(neg.z, len))};
  }
  constexpr int kFaces = TwoSide ? 2 : 1;
  for (int f = 0; f < kFaces; ++f) {
    const V3s nf = f == 0 ? n : V3s{hn::Neg(n.x), hn::Neg(n.y), hn::Neg(n.z)};
    const bool cm_on = color_material && (c.model.cm_faces >> f & 1);
    V3s prim = Splat(d, c.scene[f]), sec{zero, zero, zero};
    V alpha = hn::Set(d, c.alpha[f]);
    bool track_amb = false, track_dif = false, track_spe = false;
    if (cm_on) {
      const ModelParams& m = c.model;
      track_amb = tracks(m, kAmbient), track_dif = tracks(m, kDiffuse), track_spe = tracks(m, kSpecular);
      const V3s ma = track_amb ? cm : Splat(d, V3<float>(glm::dvec3(c.mat[f].ambient)));
      const V3s me = tracks(m, kEmission) ? cm : Splat(d, V3<float>(glm::dvec3(c.mat[f].emission)));
      prim = Add3(me, Mul3(ma, Splat(d, c.global_ambient)));
      if (track_dif) alpha = cm_a;
    }
    for (int li = 0; li < c.count; ++li) {
      const PreparedLight<float>& L = c.light[li];
      const bool local = Kind == 0 ? L.local : Kind != 1;
      const bool attenuated = Kind == 0 ? L.attenuated : Kind == 3 && L.attenuated;
      const bool spot = Kind == 0 && L.spot;
      V3s vp = Splat(d, L.pos);
      V att = one;
      if (local) {
        V dist;
        vp = UnitOrZero(d, V3s{hn::Sub(vp.x, p.x), hn::Sub(vp.y, p.y), hn::Sub(vp.z, p.z)}, &dist);
        if (attenuated) {
          const V k2d = hn::Mul(hn::Set(d, L.k2), dist);
          att = hn::Div(one, hn::Add(hn::Add(hn::Set(d, L.k0), hn::Mul(hn::Set(d, L.k1), dist)), hn::Mul(k2d, dist)));
        }
      }
      if (spot) {
        const V3s neg{hn::Neg(vp.x), hn::Neg(vp.y), hn::Neg(vp.z)};
        const V cos_angle = Dot(neg, Splat(d, L.spot_dir));
        const M lit = hn::Not(hn::Lt(cos_angle, hn::Set(d, L.spot_cos)));
        // Outside the cone every term is multiplied by 0 (light_impl): nothing to add unless a
        // term is not finite, which only these can make.
        if (hn::AllFalse(d, lit) && L.finite && !color_material && hn::AllTrue(d, hn::IsFinite(att)) &&
            hn::AllFalse(d, hn::Ge(Dot(n, n), hn::Set(d, kLongNormal2<float>))))
          continue;
        att = hn::Mul(att, hn::IfThenElseZero(lit, PowLanes(d, Max0(d, cos_angle), L.spot_exp)));
      }
      const V3s amb = track_amb ? Mul3(Splat(d, L.la), cm) : Splat(d, L.amb[f]);
      const V3s dif = track_dif ? Mul3(Splat(d, L.ld), cm) : Splat(d, L.dif[f]);
      const V ndotl = Dot(nf, vp);
      V3s sum = Add3(amb, Scale(Max0(d, ndotl), dif));
      if (Specular) {
        // light_impl's factor: the power where n.L > 0, else 0, times the colour either way. Where
        // no lane faces the light the product is 0 unless the colour or the attenuation (a NaN
        // position) is not finite.
        const M want = LongOnly ? hn::Ge(Dot(n, n), hn::Set(d, kLongNormal2<float>)) : hn::Eq(zero, zero);
        const M facing = hn::And(want, hn::Gt(ndotl, zero));
        const bool any_facing = !hn::AllFalse(d, facing);
        if (any_facing || (!LongOnly && (track_spe || !L.finite || !hn::AllTrue(d, hn::IsFinite(att))))) {
          V factor = zero;
          if (any_facing) {
            V3s h = Splat(d, L.half);
            if (local_viewer || local) h = UnitOrZero(d, Add3(vp, to_eye));
            factor = hn::IfThenElseZero(facing, PowLanes(d, Max0(d, Dot(nf, h)), c.shininess[f]));
          }
          const V3s spe = track_spe ? Mul3(Splat(d, L.ls), cm) : Splat(d, L.spe[f]);
          const V3s s = Scale(factor, spe);
          if (separate) sec = Select(want, Add3(sec, Scale(att, s)), sec);
          else sum = Select(want, Add3(sum, s), sum);
        }
      }
      prim = Add3(prim, Scale(att, sum));
    }
    const V prgba[4] = {Saturate(d, prim.x), Saturate(d, prim.y), Saturate(d, prim.z), Saturate(d, alpha)};
    const V srgba[4] = {Saturate(d, sec.x), Saturate(d, sec.y), Saturate(d, sec.z), zero};
    const bool secondary = separate || !out.keyed, copy_back = !TwoSide && !out.keyed;
    for (int k = 0; k < 4; ++k) {
      hn::StoreU(prgba[k], d, out.col[0][f][k] + i);
      if (secondary) hn::StoreU(srgba[k], d, out.col[1][f][k] + i);
      if (copy_back) {
        hn::StoreU(prgba[k], d, out.col[0][1][k] + i);
        hn::StoreU(srgba[k], d, out.col[1][1][k] + i);
      }
    }
  }
}

// Whether a normal of the columns is long enough for n.h to the shininess to overflow a float
// (lighting.h's kLongNormal2).
HWY_INLINE bool AnyLongNormal(D d, const SoaIn& in, size_t count) {
  const V limit = hn::Set(d, kLongNormal2<float>);
  M any = hn::FirstN(d, 0);
  for (size_t i = 0; i < count; i += hn::Lanes(d)) {
    const V3s n{hn::LoadU(d, in.n[0] + i), hn::LoadU(d, in.n[1] + i), hn::LoadU(d, in.n[2] + i)};
    any = hn::Or(any, hn::And(hn::FirstN(d, count - i), hn::Ge(Dot(n, n), limit)));  // padding lanes not
  }
  return !hn::AllFalse(d, any);
}

template <bool TwoSide, bool Specular, unsigned Kind, bool LongOnly = false>
void LightColumns(const Prepared<float>& c, const SoaIn& in, size_t count, const SoaOut& out) {
  const D d;
  // light_impl's long_normal (lighting.cpp): a key without the specular term still computes it
  // where a normal may overflow its power. A batch holding such a normal takes a kernel with the
  // term for those lanes (LongOnly), so the kernels without the term keep no code for it.
  if constexpr (!Specular)
    if (AnyLongNormal(d, in, count)) return LightColumns<TwoSide, true, Kind, true>(c, in, count, out);
  // Copies: the stores to the columns could alias the caller's structs (the compiler would load
  // every column's pointer again for each store).
  const SoaIn columns_in = in;
  const SoaOut columns_out = out;
  for (size_t i = 0; i < count; i += hn::Lanes(d)) LightVector<TwoSide, Specular, Kind, LongOnly>(d, c, columns_in, i, columns_out);
}

using Columns = void (*)(const Prepared<float>&, const SoaIn&, size_t, const SoaOut&);
template <unsigned I>
constexpr Columns Instance() {
  return &LightColumns<(I & 1) != 0, (I & 2) != 0, (I >> 2)>;
}

// The shape as lighting.cpp's shape_index names it: bit 0 two-sided, bit 2 specular, bits 5-6
// the light kind (0 mixed or spot, 1 directional, 2 point, 3 attenuated point).
void LightSoa(const Prepared<float>& c, const SoaIn& in, size_t count, const SoaOut& out) {
  static constexpr Columns kTable[16] = {
      Instance<0>(),  Instance<1>(),  Instance<2>(),  Instance<3>(),  Instance<4>(),  Instance<5>(),
      Instance<6>(),  Instance<7>(),  Instance<8>(),  Instance<9>(),  Instance<10>(), Instance<11>(),
      Instance<12>(), Instance<13>(), Instance<14>(), Instance<15>()};
  const unsigned s = shape_index(c.key);
  kTable[(s & 1) | (s >> 1 & 2) | (s >> 5 & 3) << 2](c, in, count, out);
}

size_t Lanes() { return hn::Lanes(D()); }

}  // namespace HWY_NAMESPACE
}  // namespace ffc::lighting
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace ffc::lighting {

HWY_EXPORT(LightSoa);
HWY_EXPORT(Lanes);

namespace {
// FFCOMPAT_SIMD applies before the first dispatch (a function-local static: one load afterwards).
// A value naming no target is reported once and the best target runs: this is inside a GL call,
// where an exception would end the program (the command line reports it before drawing).
void configure_once() {
  static const bool configured = [] {
    try {
      simd::configure_from_environment();
    } catch (const std::exception& e) {
      std::fprintf(stderr, "ffcompat: %s\n", e.what());
    }
    return true;
  }();
  (void)configured;
}
}  // namespace

size_t soa_lanes() {
  configure_once();
  return HWY_DYNAMIC_DISPATCH(Lanes)();
}

void light_soa(const Prepared<float>& c, const SoaIn& in, size_t count, const SoaOut& out) {
  configure_once();
  HWY_DYNAMIC_DISPATCH(LightSoa)(c, in, count, out);
}

namespace {

// AoS to columns and back, kSoaPad vertices at a time (the padding lanes zero).
void columns_batch(const Prepared<float>& c, const V4<float>* p, const V3<float>* n, const V4<float>* color,
                   size_t count, Lit<float>* out) {
  alignas(64) float in_col[11][kSoaPad];
  alignas(64) float out_col[16][kSoaPad];
  const SoaIn in{{in_col[0], in_col[1], in_col[2], in_col[3]},
                 {in_col[4], in_col[5], in_col[6]},
                 {in_col[7], in_col[8], in_col[9], in_col[10]}};
  SoaOut o;
  for (int k = 0; k < 16; ++k) o.col[k >> 3][k >> 2 & 1][k & 3] = out_col[k];
  const bool cm = c.key.color_material();
  for (size_t base = 0; base < count; base += kSoaPad) {
    const size_t m = std::min(kSoaPad, count - base);
    if (m < kSoaPad) std::memset(in_col, 0, sizeof in_col);
    for (size_t j = 0; j < m; ++j) {
      for (int k = 0; k < 4; ++k) in_col[k][j] = p[base + j][k];
      for (int k = 0; k < 3; ++k) in_col[4 + k][j] = n[base + j][k];
      if (cm)
        for (int k = 0; k < 4; ++k) in_col[7 + k][j] = color[base + j][k];
    }
    light_soa(c, in, m, o);
    for (size_t j = 0; j < m; ++j) {
      Lit<float>& l = out[base + j];
      for (int k = 0; k < 4; ++k) {
        l.primary[0][k] = out_col[k][j], l.primary[1][k] = out_col[4 + k][j];
        l.secondary[0][k] = out_col[8 + k][j], l.secondary[1][k] = out_col[12 + k][j];
      }
    }
  }
}

}  // namespace

Kernel<float> vectorised(const Key&) { return &columns_batch; }

}  // namespace ffc::lighting
#endif  // HWY_ONCE
