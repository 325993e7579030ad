// The kernels of kernels.h for one Highway target: included once per target by the files that
// include hwy/foreach_target.h (kernels.cpp, triangle_list_wide.cpp), hence the toggled guard
// instead of #pragma once. Each function is the vector form of a scalar rule it cites; lanes are
// pixels of one row, x + k for lane k.
#if defined(FFCOMPAT_RASTER_WIDE_KERNELS_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef FFCOMPAT_RASTER_WIDE_KERNELS_INL_H_
#undef FFCOMPAT_RASTER_WIDE_KERNELS_INL_H_
#else
#define FFCOMPAT_RASTER_WIDE_KERNELS_INL_H_
#endif

#include <hwy/highway.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <new>

#include "raster/row_loop.h"
#include "raster/wide/kernels.h"

HWY_BEFORE_NAMESPACE();
namespace ffc::raster::detail::HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// Lanes 0, 1, 2, ... plus `first`. Highway 1.0.3 builds Iota(d, first) through memory, which
// stalls on store forwarding when first is not a constant; Iota(d, 0) is a constant.
template <class DI>
HWY_INLINE hn::Vec<DI> LanesFrom(DI di, int32_t first) {
  return hn::Add(hn::Iota(di, 0), hn::Set(di, first));
}

// Room for one vector of 32-bit lanes on any target.
constexpr size_t kMaxLanes32 = HWY_MAX_BYTES / 4;

// a * b + c as llvmpipe_mul_add (raster.h): where fused (llvmpipe_fma(), the default), rounded
// once, as std::fma: one instruction where the target has it (AVX2 and AVX-512, where Highway's
// MulAdd is fused; NEON and SVE on AArch64), in double on SSE4 and SSSE3 (MulAdd there is a
// product and a sum, two roundings), lane by lane elsewhere; else a product and a sum.
template <class DF, class V>
HWY_INLINE V FusedMulAddLanes(DF df, V a, V b, V c) {
  alignas(64) float x[kMaxLanes32], y[kMaxLanes32], z[kMaxLanes32];
  hn::Store(a, df, x), hn::Store(b, df, y), hn::Store(c, df, z);
  for (size_t k = 0; k < hn::Lanes(df); ++k) x[k] = std::fma(x[k], y[k], z[k]);
  return hn::Load(df, x);
}
#undef FFCOMPAT_FMA_IN_DOUBLE
#if (HWY_ARCH_X86 && HWY_TARGET <= HWY_AVX2) || (HWY_ARCH_ARM_A64 && HWY_TARGET != HWY_EMU128 && HWY_TARGET != HWY_SCALAR)
template <class DF, class V>
HWY_INLINE V FusedMulAdd(DF, V a, V b, V c) {
  if (HWY_UNLIKELY(!llvmpipe_fma())) return hn::Add(hn::Mul(a, b), c);
  return hn::MulAdd(a, b, c);
}
#define FFCOMPAT_FMA_IN_DOUBLE 0
#elif HWY_TARGET != HWY_SCALAR && HWY_TARGET != HWY_EMU128 && HWY_HAVE_FLOAT64
// Without a fused instruction (SSE4, SSSE3): in double. a * b is exact there (24 + 24 bits of
// significand fit in 53), so a * b + c in double is rounded once, and rounding that to float gives
// the fused result unless the double landed exactly halfway between two floats (then the first
// rounding may have decided the tie: those vectors, rare, go lane by lane through std::fma), or in
// float's subnormal range (its halfway points lie elsewhere: the same). A call to fmaf per lane
// made the cube four times slower than on AVX2.
#define FFCOMPAT_FMA_IN_DOUBLE 1
// The float sums of lo and hi (the lower and upper halves' exact products plus c, in double), or
// `lanes()` where a lane's double is one whose rounding to float could differ from the fused result.
template <class DF, class VD, class Lanes>
HWY_INLINE hn::Vec<DF> FusedFromDouble(DF df, VD lo, VD hi, Lanes&& lanes) {
  const hn::Half<DF> dh;
  const hn::Rebind<double, decltype(dh)> dd;
  const hn::RebindToUnsigned<decltype(dd)> du64;
  // Halfway (the 29 bits below float's last significand bit are 1000...0), or in float's
  // subnormal range.
  auto odd = [&](VD s) {
    const auto tail = hn::And(hn::BitCast(du64, s), hn::Set(du64, (uint64_t(1) << 29) - 1));
    const auto small = hn::And(hn::Lt(hn::Abs(s), hn::Set(dd, 0x1p-125)), hn::Ne(s, hn::Zero(dd)));
    return hn::Or(hn::RebindMask(dd, hn::Eq(tail, hn::Set(du64, uint64_t(1) << 28))), small);
  };
  // One test for both halves: nearly always none is odd.
  if (HWY_LIKELY(hn::AllFalse(dd, hn::Or(odd(lo), odd(hi))))) return hn::Combine(df, hn::DemoteTo(dh, hi), hn::DemoteTo(dh, lo));
  return lanes();
}
template <class DF, class V>
HWY_INLINE V FusedMulAdd(DF df, V a, V b, V c) {
  if (HWY_UNLIKELY(!llvmpipe_fma())) return hn::Add(hn::Mul(a, b), c);
  const hn::Half<DF> dh;
  const hn::Rebind<double, decltype(dh)> dd;
  auto exact = [&](auto x, auto y, auto z) {
    return hn::Add(hn::Mul(hn::PromoteTo(dd, x), hn::PromoteTo(dd, y)), hn::PromoteTo(dd, z));
  };
  return FusedFromDouble(df, exact(hn::LowerHalf(dh, a), hn::LowerHalf(dh, b), hn::LowerHalf(dh, c)),
                         exact(hn::UpperHalf(dh, a), hn::UpperHalf(dh, b), hn::UpperHalf(dh, c)),
                         [&] { return FusedMulAddLanes(df, a, b, c); });
}
#else
#define FFCOMPAT_FMA_IN_DOUBLE 0
template <class DF, class V>
HWY_INLINE V FusedMulAdd(DF df, V a, V b, V c) {
  if (HWY_UNLIKELY(!llvmpipe_fma())) return hn::Add(hn::Mul(a, b), c);
  return FusedMulAddLanes(df, a, b, c);
}
#endif

// FusedMulAdd(a, b, c) for a and b fixed while c varies (depth's second step, z2 Y_down + (...),
// along a row): where the fused step is done in double, a * b is made once, exactly.
template <class DF>
struct FusedRow {
  using V = hn::Vec<DF>;
  V a, b;
#if FFCOMPAT_FMA_IN_DOUBLE
  using DD = hn::Rebind<double, hn::Half<DF>>;
  hn::Vec<DD> ab_lo, ab_hi;
  bool fused;
  HWY_INLINE FusedRow(DF, V a_, V b_) : a(a_), b(b_), fused(llvmpipe_fma()) {
    const hn::Half<DF> dh;
    const DD dd;
    ab_lo = hn::Mul(hn::PromoteTo(dd, hn::LowerHalf(dh, a)), hn::PromoteTo(dd, hn::LowerHalf(dh, b)));
    ab_hi = hn::Mul(hn::PromoteTo(dd, hn::UpperHalf(dh, a)), hn::PromoteTo(dd, hn::UpperHalf(dh, b)));
  }
  HWY_INLINE V operator()(DF df, V c) const {
    if (HWY_UNLIKELY(!fused)) return hn::Add(hn::Mul(a, b), c);
    const hn::Half<DF> dh;
    const DD dd;
    return FusedFromDouble(df, hn::Add(ab_lo, hn::PromoteTo(dd, hn::LowerHalf(dh, c))), hn::Add(ab_hi, hn::PromoteTo(dd, hn::UpperHalf(dh, c))),
                           [&] { return FusedMulAddLanes(df, a, b, c); });
  }
#else
  HWY_INLINE FusedRow(DF, V a_, V b_) : a(a_), b(b_) {}
  HWY_INLINE V operator()(DF df, V c) const { return FusedMulAdd(df, a, b, c); }
#endif
};

#undef FFCOMPAT_X86_VECTORS
#if HWY_ARCH_X86 && HWY_TARGET != HWY_SCALAR && HWY_TARGET != HWY_EMU128
#define FFCOMPAT_X86_VECTORS 1
#else
#define FFCOMPAT_X86_VECTORS 0
#endif

// [0, 1] with a NaN as 0 (maxss's order in pixel_rules.h). x86's max returns its second operand
// when either is a NaN, and Highway's Max(v, 0) is that instruction there; NEON's max would keep
// the NaN, so elsewhere the NaN lanes are zeroed first.
template <class DF, class V>
HWY_INLINE V Clamp01(DF df, V v) {
#if FFCOMPAT_X86_VECTORS
  return hn::Min(hn::Max(v, hn::Zero(df)), hn::Set(df, 1.0f));
#else
  return hn::Min(hn::Max(hn::IfThenZeroElse(hn::IsNaN(v), v), hn::Zero(df)), hn::Set(df, 1.0f));
#endif
}

// Rounded half to even to int32, for values already within [0, 2^24] (clamped and scaled): on x86
// the conversion instruction alone (Highway's NearestInt adds a fix for values beyond int32, three
// more instructions a vector that these values never need), NearestInt elsewhere.
template <class DF, class V>
HWY_INLINE auto RoundInRange(DF, V v) {
  const hn::RebindToSigned<DF> di;
#if FFCOMPAT_X86_VECTORS
  if constexpr (sizeof(v.raw) == 64) {
    return hn::Vec<decltype(di)>{_mm512_cvtps_epi32(v.raw)};
  } else if constexpr (sizeof(v.raw) == 32) {
    return hn::Vec<decltype(di)>{_mm256_cvtps_epi32(v.raw)};
  } else {
    return hn::Vec<decltype(di)>{_mm_cvtps_epi32(v.raw)};
  }
#else
  (void)di;
  return hn::NearestInt(v);
#endif
}

// pixel_rules.h's depth24, a lane a pixel: clamped, times 2^24 - 1, rounded half to even.
template <class DF, class V>
HWY_INLINE auto Depth24(DF df, V z) {
  return RoundInRange(df, hn::Mul(Clamp01(df, z), hn::Set(df, 16777215.0f)));
}

// The lanes of `lanes` whose depth z passes against the stored one (24-bit values: the signed
// comparisons are the unsigned ones). pixel_rules.h's depth_pass.
template <DepthMode Mode, class DI, class VI, class M>
HWY_INLINE M DepthTest(DI di, M lanes, VI z, VI stored, GLenum func) {
  if constexpr (Mode == kNoDepth) return lanes;
  if constexpr (Mode == kLess) return hn::And(lanes, hn::Lt(z, stored));
  if constexpr (Mode == kLequal) return hn::AndNot(hn::Gt(z, stored), lanes);
  switch (func) {
    case GL_NEVER: return hn::FirstN(di, 0);
    case GL_LESS: return hn::And(lanes, hn::Lt(z, stored));
    case GL_EQUAL: return hn::And(lanes, hn::Eq(z, stored));
    case GL_LEQUAL: return hn::AndNot(hn::Gt(z, stored), lanes);
    case GL_GREATER: return hn::And(lanes, hn::Gt(z, stored));
    case GL_NOTEQUAL: return hn::AndNot(hn::Eq(z, stored), lanes);
    case GL_GEQUAL: return hn::AndNot(hn::Lt(z, stored), lanes);
    default: return lanes;
  }
}

// A triangle's planes, broadcast once.
template <class DF>
struct Planes {
  using V = hn::Vec<DF>;
  V z0, z1, z2, iw0, iw1, iw2, c0[4], cx[4], cy[4];
  HWY_INLINE Planes(DF df, const KernelPlanes& p) {
    const int n = p.stride;
    z0 = hn::Set(df, p.z[0]), z1 = hn::Set(df, p.z[n]), z2 = hn::Set(df, p.z[2 * n]);
    iw0 = hn::Set(df, p.f[0]), iw1 = hn::Set(df, p.f[n]), iw2 = hn::Set(df, p.f[2 * n]);
    for (int k = 0; k < 4; ++k)
      c0[k] = hn::Set(df, p.f[(3 + k) * n]), cx[k] = hn::Set(df, p.f[(7 + k) * n]), cy[k] = hn::Set(df, p.f[(11 + k) * n]);
  }
};

// A triangle's planes at columns col (X = col + 0.5), the terms that depend on X only added:
// depth's first fused step and (p0 + px X) of 1/w and of each colour / w. Shading then adds py Y
// in the planes' order, so the same bits; a box's blocks share their columns and compute these
// once.
template <class DF>
struct AtColumns {
  using V = hn::Vec<DF>;
  V z, iw, c[4];
  const Planes<DF>& p;
  HWY_INLINE AtColumns(DF df, const Planes<DF>& planes, V col) : p(planes) {
    const V fx = hn::Add(col, hn::Set(df, 0.5f));
    z = FusedMulAdd(df, p.z1, col, p.z0), iw = hn::Add(p.iw0, hn::Mul(p.iw1, fx));
    for (int k = 0; k < 4; ++k) c[k] = hn::Add(p.c0[k], hn::Mul(p.cx[k], fx));
  }
  // Read back from a ColumnCache's six arrays (pitch floats apart) at `at`.
  HWY_INLINE AtColumns(DF df, const Planes<DF>& planes, const float* at, size_t pitch) : p(planes) {
    z = hn::LoadU(df, at), iw = hn::LoadU(df, at + pitch);
    for (int k = 0; k < 4; ++k) c[k] = hn::LoadU(df, at + (2 + k) * pitch);
  }
};

// A large triangle's AtColumns for the columns this thread has drawn so far, each column's made
// once rather than once per row: the same values (they depend on the column alone), so the same
// bits. Six arrays of kCachedColumns (+ padding) floats on the caller's stack (a heap buffer
// would be allocated during some frame), for the triangle's columns xmin... up to kCachedColumns
// of them (row_loop.h); a span reaching further makes its own (Covers).
template <class DF>
struct ColumnCache {
  // Two vectors' padding: the last vector of a row reads up to a vector past its span, and the
  // last vector made for it writes up to a vector past that.
  static constexpr size_t kPitch = kCachedColumns + 2 * kMaxLanes32;
  float* store;  // 6 * kPitch floats
  int xmin;
  MadeColumns made;
  HWY_INLINE ColumnCache(float* storage, int xmin_) : store(storage), xmin(xmin_) {}
  HWY_INLINE bool Covers(int to) const { return to - xmin < kCachedColumns; }
  // Makes the columns from..to (within the triangle's, Covers(to)) that are not made yet, a vector
  // at a time; returns where column `from`'s values lie.
  HWY_INLINE const float* At(DF df, const Planes<DF>& p, int from, int to) {
    made.cover(from, to, [&](int a, int b) { Make(df, p, a, b); });
    return store + (from - xmin);
  }
  HWY_INLINE void Make(DF df, const Planes<DF>& p, int from, int to) {
    const hn::RebindToSigned<DF> di;
    const int n = int(hn::Lanes(df));
    for (int x = from; x <= to; x += n) {
      const AtColumns<DF> a(df, p, hn::ConvertTo(df, LanesFrom(di, x)));
      float* at = store + (x - xmin);
      hn::StoreU(a.z, df, at), hn::StoreU(a.iw, df, at + kPitch);
      for (int k = 0; k < 4; ++k) hn::StoreU(a.c[k], df, at + (2 + k) * kPitch);
    }
  }
};

// The pixels x + k of a row: read whole where the vector lies within the row (the row is this
// thread's, so lanes outside the mask are written back unchanged), else lane by lane (the last
// pixels of a row: the next row may be another thread's, or past the buffer). No masked loads
// and stores: AVX2's were slow on the AMD CPU this was measured on (docs/performance.md).
template <class DU>
HWY_INLINE hn::Vec<DU> LoadPixels(DU du, const uint32_t* at, bool whole, size_t lanes_in_row) {
  if (whole) return hn::LoadU(du, at);
  alignas(64) uint32_t buf[kMaxLanes32] = {};
  std::memcpy(buf, at, lanes_in_row * 4);
  return hn::Load(du, buf);
}
template <class DU>
HWY_INLINE void StorePixels(DU du, hn::Vec<DU> v, uint32_t* at, bool whole, size_t lanes_in_row) {
  if (whole) return hn::StoreU(v, du, at);
  alignas(64) uint32_t buf[kMaxLanes32];
  hn::Store(v, du, buf);
  std::memcpy(at, buf, lanes_in_row * 4);
}

// A triangle's planes at rows y, the terms that depend on Y only: py Y of 1/w and of each
// colour / w (Y = fy, the centre y + 0.5), and depth's second fused step, z2 Y_down + (...) with
// Y_down = height - 1 - y. Made once a row where lanes share their row.
template <class DF>
struct AtRows {
  using V = hn::Vec<DF>;
  V iw, c[4];
  FusedRow<DF> z;
  HWY_INLINE AtRows(DF df, const Planes<DF>& p, V fy, V y_down) : z(df, p.z2, y_down) {
    iw = hn::Mul(p.iw2, fy);
    for (int k = 0; k < 4; ++k) c[k] = hn::Mul(p.cy[k], fy);
  }
};

// Depth test and colour for the lanes of `lanes` at pixel columns col (a) and rows y (r), the row
// loop's span_scalar lane by lane; the stored depth and colour read by load(buffer) and written
// by store(buffer, v) (buffer 0: depth, 1: colour). Returns the drawn pixels whose colour was not
// finite.
template <DepthMode Mode, class DF, class Load, class Store>
HWY_INLINE uint64_t ShadeLanes(DF df, const AtColumns<DF>& a, const AtRows<DF>& r, hn::Mask<DF> lanes_f, GLenum func, Load&& load,
                               Store&& store) {
  const hn::RebindToSigned<DF> di;
  const hn::RebindToUnsigned<DF> du;
  auto pass = hn::RebindMask(di, lanes_f);
  if constexpr (Mode != kNoDepth) {
    const auto z = Depth24(df, r.z(df, a.z));  // FusedMulAdd(z2, Y_down, a.z)
    const auto old_z = load(0);
    pass = DepthTest<Mode>(di, pass, z, hn::BitCast(di, old_z), func);
    if (hn::AllFalse(di, pass)) return 0;
    store(0, hn::IfThenElse(hn::RebindMask(du, pass), hn::BitCast(du, z), old_z));
  }
  // Colour: ((c0 + cx X) + cy Y) * (1 / ((iw0 + iw1 X) + iw2 Y)), clamped, times 255, rounded
  // half to even, a byte a channel (pixel_rules.h unorm8).
  const auto inv = hn::Div(hn::Set(df, 1.0f), hn::Add(a.iw, r.iw));
  auto rgba = hn::Zero(du);
  auto finite = hn::RebindMask(df, pass);
#pragma GCC unroll 4
  for (int k = 0; k < 4; ++k) {
    const auto v = hn::Mul(hn::Add(a.c[k], r.c[k]), inv);
    finite = hn::And(finite, hn::IsFinite(v));
    const auto q = hn::BitCast(du, RoundInRange(df, hn::Mul(Clamp01(df, v), hn::Set(df, 255.0f))));
    rgba = hn::Or(rgba, hn::ShiftLeftSame(q, 8 * k));
  }
  store(1, hn::IfThenElse(hn::RebindMask(du, pass), rgba, load(1)));
  // The drawn lanes whose colour was not finite: nearly always none, so counted only when there
  // are some (SSSE3 has no popcount instruction: a library call per vector otherwise).
  const auto nonfinite = hn::AndNot(hn::RebindMask(di, finite), pass);
  return hn::AllFalse(di, nonfinite) ? 0 : hn::CountTrue(di, nonfinite);
}

// The row terms of row y.
template <class DF>
HWY_INLINE AtRows<DF> RowOf(DF df, const Planes<DF>& p, const Framebuffer& fb, int y) {
  return AtRows<DF>(df, p, hn::Set(df, float(double(y) + 0.5)), hn::Set(df, float(fb.height - 1 - y)));
}

// Pixels x + k of row y (its terms r) for the lanes k set in `lanes` (all within the
// framebuffer), at columns a.
template <DepthMode Mode, class DF>
HWY_INLINE uint64_t Segment(DF df, const AtColumns<DF>& a, const AtRows<DF>& r, Framebuffer& fb, int y, int x, hn::Mask<DF> lanes,
                            GLenum func) {
  const hn::RebindToUnsigned<DF> du;
  const size_t n = hn::Lanes(df), in_row = std::min(n, size_t(fb.width - x));
  const bool whole = in_row == n;
  uint32_t* const at[2] = {fb.depth.data() + size_t(y) * size_t(fb.width) + size_t(x),
                           reinterpret_cast<uint32_t*>(fb.color.data()) + size_t(y) * size_t(fb.width) + size_t(x)};
  return ShadeLanes<Mode>(df, a, r, lanes, func, [&](int b) { return LoadPixels(du, at[b], whole, in_row); },
                          [&](int b, hn::Vec<decltype(du)> v) { StorePixels(du, v, at[b], whole, in_row); });
}
// The same with the columns' terms made here.
template <DepthMode Mode, class DF>
HWY_INLINE uint64_t Segment(DF df, const Planes<DF>& p, const AtRows<DF>& r, Framebuffer& fb, int y, int x, hn::Mask<DF> lanes,
                            GLenum func) {
  const hn::RebindToSigned<DF> di;
  return Segment<Mode>(df, AtColumns<DF>(df, p, hn::ConvertTo(df, LanesFrom(di, x))), r, fb, y, x, lanes, func);
}

#if HWY_TARGET != HWY_SCALAR  // one lane: no halves to combine
// A box's rows `live` (bit r: row r has covered lanes), W pixels each, as one vector of
// MaxLanes / W rows: the rows without covered lanes are neither read (they may be another
// thread's, or past the buffer) nor written.
template <size_t W, class D>
HWY_INLINE hn::Vec<D> LoadRows(D d, const uint32_t* at, size_t pitch, unsigned live) {
  if constexpr (hn::MaxLanes(D()) <= W) {
    return (live & 1) ? hn::LoadU(d, at) : hn::Zero(d);
  } else {
    const hn::Half<D> dh;
    constexpr unsigned kHalf = unsigned(hn::MaxLanes(hn::Half<D>()) / W);
    return hn::Combine(d, LoadRows<W>(dh, at + kHalf * pitch, pitch, live >> kHalf), LoadRows<W>(dh, at, pitch, live));
  }
}
template <size_t W, class D>
HWY_INLINE void StoreRows(D d, hn::Vec<D> v, uint32_t* at, size_t pitch, unsigned live) {
  if constexpr (hn::MaxLanes(D()) <= W) {
    if (live & 1) hn::StoreU(v, d, at);
  } else {
    const hn::Half<D> dh;
    constexpr unsigned kHalf = unsigned(hn::MaxLanes(hn::Half<D>()) / W);
    StoreRows<W>(dh, hn::LowerHalf(dh, v), at, pitch, live);
    StoreRows<W>(dh, hn::UpperHalf(dh, v), at + kHalf * pitch, pitch, live >> kHalf);
  }
}
#endif

// The edge fields of a set-up triangle (counter-clockwise, box within the framebuffer, vertex
// extents below 31 pixels so that the edge functions fit in 32 bits): pixel_rules.h's edge_function.
HWY_INLINE void KernelEdgesOf(const Triangle& t, int32_t (&out)[kEdgeFields]) {
  out[kXmin] = t.xmin, out[kYmin] = t.ymin, out[kXmax] = t.xmax, out[kYmax] = t.ymax;
  for (int i = 0; i < 3; ++i) {
    const EdgeFunction e = edge_function(t, i, t.xmin, t.ymin);
    out[kE0 + i] = int32_t(e.at), out[kPerX + i] = int32_t(e.per_x), out[kPerY + i] = int32_t(e.per_y);
    out[kLimit + i] = int32_t(e.limit) - 1;  // e >= limit  as  e > limit - 1
  }
}

// Edge i's function at lanes x = x0 + k of row y0 + dy: e0 + per_x k + per_y dy, and whether
// every edge covers the lane (e > limit).
template <class DI>
HWY_INLINE hn::Mask<DI> Covered(DI di, const KernelEdges& e, int dx, int dy) {
  const auto lane = LanesFrom(di, dx);
  auto edge = [&](int i) {
    const auto v = hn::Add(hn::Set(di, e(kE0 + i) + e(kPerY + i) * dy), hn::Mul(hn::Set(di, e(kPerX + i)), lane));
    return hn::Gt(v, hn::Set(di, e(kLimit + i)));
  };
  return hn::And(hn::And(edge(0), edge(1)), edge(2));
}

// The covered pixel centres of a box of at most 8x8 in this thread's rows, bit 8 r + c for box
// row r, column c.
HWY_INLINE uint64_t BoxCover(const KernelEdges& e, const Bands& bands) {
  const hn::CappedTag<int32_t, 8> di;
  const int n = int(hn::Lanes(di));
  const int xmin = e(kXmin), ymin = e(kYmin), w = e(kXmax) - xmin + 1, h = e(kYmax) - ymin + 1;
  unsigned rows = 0;  // this thread's
  for (int r = 0; r < h; ++r) rows |= unsigned(bands.owns((ymin + r) / kBandRows)) << r;
  uint64_t cover = 0;
  for (int c = 0; c < w; c += n) {
    // The edges at the chunk's lanes of the first row, then a row's step added per row.
    hn::Vec<decltype(di)> at[3], per_y[3], limit[3];
    for (int i = 0; i < 3; ++i) {
      at[i] = hn::Add(hn::Set(di, e(kE0 + i)), hn::Mul(hn::Set(di, e(kPerX + i)), LanesFrom(di, c)));
      per_y[i] = hn::Set(di, e(kPerY + i)), limit[i] = hn::Set(di, e(kLimit + i));
    }
    const auto cols = hn::FirstN(di, size_t(w - c));
    for (int r = 0; r < h; ++r) {
      if (rows >> r & 1) {
        const auto in = hn::And(hn::And(hn::Gt(at[0], limit[0]), hn::Gt(at[1], limit[1])), hn::And(hn::Gt(at[2], limit[2]), cols));
        uint8_t bits[8] = {};
        hn::StoreMaskBits(di, in, bits);
        cover |= uint64_t(bits[0]) << (8 * r + c);
      }
      for (int i = 0; i < 3; ++i) at[i] = hn::Add(at[i], per_y[i]);
    }
  }
  return cover;
}

// Depth and colour for the covered centres of a box (BoxCover's bits).
template <DepthMode Mode>
HWY_INLINE uint64_t BoxShade(Framebuffer& fb, const KernelPlanes& kp, int xmin, int ymin, uint64_t cover, GLenum func) {
  using DF = hn::CappedTag<float, 8>;
  const DF df;
  const int n = int(hn::Lanes(df));
  const Planes<DF> p(df, kp);
  uint64_t nonfinite = 0;
  for (; cover; cover &= ~(uint64_t(0xFF) << (__builtin_ctzll(cover) & ~7))) {
    const int r = __builtin_ctzll(cover) >> 3;
    const unsigned row_bits = unsigned(cover >> (8 * r)) & 0xFF;
    const AtRows<DF> row = RowOf(df, p, fb, ymin + r);
    for (int c = 0; c < 8; c += n) {
      const uint8_t bits = uint8_t(row_bits >> c);
      if (!bits) continue;
      nonfinite += Segment<Mode>(df, p, row, fb, ymin + r, xmin + c, hn::LoadMaskBits(df, &bits), func);
    }
  }
  return nonfinite;
}

#if HWY_TARGET != HWY_SCALAR
// Depth and colour of the lanes `lanes` of a block whose first row is y0 (lane k: column
// xmin + k % W, row y0 + dy[k]), its rows `live` read and written whole.
template <size_t W, DepthMode Mode, class DF>
HWY_INLINE uint64_t ShadeBlock(DF df, const AtColumns<DF>& at_col, Framebuffer& fb, hn::Vec<hn::RebindToSigned<DF>> dy, int xmin, int y0,
                               hn::Mask<DF> lanes, unsigned live, GLenum func) {
  const hn::RebindToSigned<DF> di;
  const hn::RebindToUnsigned<DF> du;
  const size_t pitch = size_t(fb.width), off = size_t(y0) * pitch + size_t(xmin);
  uint32_t* const at[2] = {fb.depth.data() + off, reinterpret_cast<uint32_t*>(fb.color.data()) + off};
  const auto y = hn::Add(hn::Set(di, y0), dy);
  const AtRows<DF> rows(df, at_col.p, hn::Add(hn::ConvertTo(df, y), hn::Set(df, 0.5f)), hn::ConvertTo(df, hn::Sub(hn::Set(di, fb.height - 1), y)));
  return ShadeLanes<Mode, DF>(df, at_col, rows, lanes, func, [&](int b) { return LoadRows<W>(du, at[b], pitch, live); },
                              [&](int b, hn::Vec<decltype(du)> v) { StoreRows<W>(du, v, at[b], pitch, live); });
}
#endif

// The same, MaxLanes / W rows of the box a vector (W = 4 or 8, at least two rows a vector), for a
// box whose first W columns lie within the framebuffer: lane k is pixel (k % W, k / W) from the
// box's corner, its rows read and written whole.
#if HWY_TARGET != HWY_SCALAR
template <size_t W, DepthMode Mode>
HWY_INLINE uint64_t BoxShadeRows(Framebuffer& fb, const KernelPlanes& kp, int xmin, int ymin, uint64_t cover, GLenum func) {
  using DF = hn::CappedTag<float, 16>;
  const DF df;
  const hn::RebindToSigned<DF> di;
  const hn::RebindToUnsigned<DF> du;
  constexpr int kRows = int(hn::MaxLanes(DF()) / W);
  static_assert(kRows >= 2, "rows a vector");
  const Planes<DF> p(df, kp);
  const auto k = hn::Iota(di, 0);
  const auto dy = hn::ShiftRight<W == 4 ? 2 : 3>(k);
  const auto col = hn::ConvertTo(df, hn::Add(hn::Set(di, xmin), hn::And(k, hn::Set(di, int32_t(W - 1)))));
  const AtColumns<DF> at_col(df, p, col);
  uint64_t nonfinite = 0;
  for (int r0 = 0; r0 < 8 && (cover >> (8 * r0)); r0 += kRows) {
    uint32_t bits = 0;
    unsigned live = 0;
    for (int r = 0; r < kRows; ++r) {
      const uint32_t row = uint32_t(cover >> (8 * (r0 + r))) & ((1u << W) - 1);
      bits |= row << (r * int(W)), live |= unsigned(row != 0) << r;
    }
    if (!bits) continue;
    const uint8_t mask_bits[8] = {uint8_t(bits), uint8_t(bits >> 8)};
    nonfinite += ShadeBlock<W, Mode>(df, at_col, fb, dy, xmin, ymin + r0, hn::LoadMaskBits(df, mask_bits), live, func);
  }
  return nonfinite;
}
#endif

// The box kernel's shading, as many rows a vector as the target's vectors hold.
template <DepthMode Mode>
HWY_INLINE uint64_t BoxShadeAny(Framebuffer& fb, const KernelPlanes& kp, int xmin, int ymin, int w, uint64_t cover, GLenum func) {
#if HWY_TARGET != HWY_SCALAR
  constexpr size_t kN = hn::MaxLanes(hn::CappedTag<float, 16>());
  if constexpr (kN >= 8) {
    if (w <= 4 && xmin + 4 <= fb.width) return BoxShadeRows<4, Mode>(fb, kp, xmin, ymin, cover, func);
  }
  if constexpr (kN >= 16) {
    if (xmin + 8 <= fb.width) return BoxShadeRows<8, Mode>(fb, kp, xmin, ymin, cover, func);
  }
#else
  (void)w;
#endif
  return BoxShade<Mode>(fb, kp, xmin, ymin, cover, func);
}

#if HWY_TARGET != HWY_SCALAR
// The box kernel with coverage and shading together, a block of MaxLanes / W rows of W pixels a
// vector (lane k: pixel (k % W, k / W) from the block's corner; W = 4 or 8, at least two rows a
// block): each block's lanes tested against the edges, then its covered pixels shaded, with no
// coverage bits in between. For a box at most W wide whose first W columns lie within the
// framebuffer, planes ready (the grouped setup of setup_group-inl.h made them).
template <size_t W, DepthMode Mode>
HWY_INLINE uint64_t BoxBlocks(Framebuffer& fb, const KernelEdges& e, const KernelPlanes& kp, const Bands& bands, GLenum func) {
  using DF = hn::CappedTag<float, 16>;
  const DF df;
  const hn::RebindToSigned<DF> di;
  const hn::RebindToUnsigned<DF> du;
  using VI = hn::Vec<decltype(di)>;
  constexpr int kRows = int(hn::MaxLanes(DF()) / W);
  static_assert(kRows >= 2, "rows a block");
  const int xmin = e(kXmin), ymin = e(kYmin), ymax = e(kYmax), h = ymax - ymin + 1;
  // The box's rows in this thread's bands, a bit each (a box of at most 8 rows meets at most two bands).
  const int b0 = ymin / kBandRows, b1 = ymax / kBandRows;
  const unsigned all = (1u << h) - 1, first = b0 == b1 ? all : (1u << ((b0 + 1) * kBandRows - ymin)) - 1;
  const unsigned rows = (bands.owns(b0) ? first : 0) | (bands.owns(b1) ? all & ~first : 0);
  if (!rows) return 0;
  const VI k = hn::Iota(di, 0);
  const VI dx = hn::And(k, hn::Set(di, int32_t(W - 1))), dy = hn::ShiftRight<W == 4 ? 2 : 3>(k);
  const VI row_bit = hn::Set(di, 1) << dy;
  const auto cols = hn::Lt(dx, hn::Set(di, e(kXmax) - xmin + 1));
  VI at[3], step[3], limit[3];  // edge i at the block's lanes, its step a block, its limit
  for (int i = 0; i < 3; ++i) {
    at[i] = hn::Add(hn::Set(di, e(kE0 + i)), hn::Add(hn::Mul(hn::Set(di, e(kPerX + i)), dx), hn::Mul(hn::Set(di, e(kPerY + i)), dy)));
    step[i] = hn::Set(di, e(kPerY + i) * kRows), limit[i] = hn::Set(di, e(kLimit + i));
  }
  const Planes<DF> p(df, kp);
  const auto col = hn::ConvertTo(df, hn::Add(hn::Set(di, xmin), dx));
  const AtColumns<DF> at_col(df, p, col);
  uint64_t nonfinite = 0;
  for (int r0 = 0; r0 < h; r0 += kRows) {
    const unsigned live = rows >> r0 & ((1u << kRows) - 1);  // the block's rows read and written
    const auto in = hn::And(hn::And(hn::And(hn::Gt(at[0], limit[0]), hn::Gt(at[1], limit[1])), hn::Gt(at[2], limit[2])),
                            hn::And(cols, hn::TestBit(hn::Set(di, int32_t(live)), row_bit)));
    for (int i = 0; i < 3; ++i) at[i] = hn::Add(at[i], step[i]);
    if (hn::AllFalse(di, in)) continue;
    nonfinite += ShadeBlock<W, Mode>(df, at_col, fb, dy, xmin, ymin + r0, hn::RebindMask(df, in), live, func);
  }
  return nonfinite;
}
#endif

// A box of at most 2x2 pixel centres, planes ready, whose coverage the setup found (bits for
// (0,0) (1,0) (0,1) (1,1) from its corner, this thread's rows only): one block of two rows of four
// where a vector holds eight lanes and the four columns lie within the framebuffer, else through
// the coverage bits.
template <DepthMode Mode>
HWY_INLINE uint64_t TinyShade(Framebuffer& fb, const KernelPlanes& kp, int xmin, int ymin, int w, unsigned bits, GLenum func) {
#if HWY_TARGET != HWY_SCALAR
  using DF = hn::CappedTag<float, 8>;
  if constexpr (hn::MaxLanes(DF()) == 8) {
    if (xmin + 4 <= fb.width) {
      const DF df;
      const hn::RebindToSigned<DF> di;
      const Planes<DF> p(df, kp);
      const auto k = hn::Iota(di, 0);
      const auto col = hn::ConvertTo(df, hn::Add(hn::Set(di, xmin), hn::And(k, hn::Set(di, 3))));
      const uint8_t lanes = uint8_t((bits & 3) | (bits & 0xC) << 2);
      const unsigned live = unsigned((bits & 3) != 0) | unsigned((bits & 0xC) != 0) << 1;
      return ShadeBlock<4, Mode>(df, AtColumns<DF>(df, p, col), fb, hn::ShiftRight<2>(k), xmin, ymin, hn::LoadMaskBits(df, &lanes), live,
                                 func);
    }
  }
#endif
  return BoxShadeAny<Mode>(fb, kp, xmin, ymin, w, (bits & 3) | uint64_t(bits >> 2) << 8, func);
}

// A box of at most 8x8 pixel centres with planes ready: by blocks where the target's vectors hold
// two rows of the box or more and its first columns lie within the framebuffer, else coverage
// bits first and then rows.
template <DepthMode Mode>
HWY_INLINE uint64_t BoxDraw(Framebuffer& fb, const KernelEdges& e, const KernelPlanes& kp, const Bands& bands, GLenum func) {
  const int xmin = e(kXmin), w = e(kXmax) - xmin + 1;
#if HWY_TARGET != HWY_SCALAR
  constexpr size_t kN = hn::MaxLanes(hn::CappedTag<float, 16>());
  if constexpr (kN >= 8) {
    if (w <= 4 && xmin + 4 <= fb.width) return BoxBlocks<4, Mode>(fb, e, kp, bands, func);
  }
  if constexpr (kN >= 16) {
    if (xmin + 8 <= fb.width) return BoxBlocks<8, Mode>(fb, e, kp, bands, func);
  }
#endif
  const uint64_t cover = BoxCover(e, bands);
  return cover ? BoxShadeAny<Mode>(fb, kp, xmin, e(kYmin), w, cover, func) : 0;
}

// Pixels lo..hi of row y, a vector at a time, the columns' terms from the cache.
template <DepthMode Mode>
HWY_INLINE uint64_t SpanShade(Framebuffer& fb, const Planes<hn::ScalableTag<float>>& p, ColumnCache<hn::ScalableTag<float>>& cols, int y,
                              int lo, int hi, GLenum func) {
  using DF = hn::ScalableTag<float>;
  const DF df;
  const int n = int(hn::Lanes(df));
  const AtRows<DF> row = RowOf(df, p, fb, y);
  const int to = lo + (hi - lo) / n * n + n - 1;  // the last vector's last column
  uint64_t nonfinite = 0;
  if (!cols.Covers(to)) {
    for (int x = lo; x <= hi; x += n) nonfinite += Segment<Mode>(df, p, row, fb, y, x, hn::FirstN(df, size_t(hi - x + 1)), func);
    return nonfinite;
  }
  const float* at = cols.At(df, p, lo, to);
  for (int x = lo; x <= hi; x += n, at += n)
    nonfinite += Segment<Mode>(df, AtColumns<DF>(df, p, at, cols.kPitch), row, fb, y, x, hn::FirstN(df, size_t(hi - x + 1)), func);
  return nonfinite;
}

// A triangle with edge functions in 32 bits and a box larger than 8x8, in rows of a vector.
template <DepthMode Mode>
HWY_INLINE uint64_t RowsShade(Framebuffer& fb, const KernelEdges& e, const KernelPlanes& kp, const Bands& bands, GLenum func) {
  const hn::ScalableTag<float> df;
  const hn::RebindToSigned<decltype(df)> di;
  const int n = int(hn::Lanes(df));
  const Planes<hn::ScalableTag<float>> p(df, kp);
  const int xmin = e(kXmin), ymin = e(kYmin), xmax = e(kXmax), ymax = e(kYmax);
  uint64_t nonfinite = 0;
  for (int by = bands.next[size_t(ymin / kBandRows)]; by * kBandRows <= ymax; by += bands.count) {
    const int row_end = std::min(by * kBandRows + kBandRows - 1, ymax);
    for (int y = std::max(by * kBandRows, ymin); y <= row_end; ++y) {
      const AtRows<hn::ScalableTag<float>> row = RowOf(df, p, fb, y);
      for (int x = xmin; x <= xmax; x += n) {
        const auto in = hn::And(Covered(di, e, x - xmin, y - ymin), hn::FirstN(di, size_t(xmax - x + 1)));
        if (hn::AllFalse(di, in)) continue;
        nonfinite += Segment<Mode>(df, p, row, fb, y, x, hn::RebindMask(df, in), func);
      }
    }
  }
  return nonfinite;
}

// A triangle too large for 32-bit edge functions: each row's span solved for (row_loop.h), spans
// of a vector or more a vector at a time with the columns' terms from a ColumnCache, shorter ones
// by the scalar span. Not inlined: the cache lives on this function's stack.
template <DepthMode Mode, typename PlanesFn>
HWY_NOINLINE uint64_t RasterizeLarge(Framebuffer& fb, Triangle& t, GLenum func, const Bands& bands, PlanesFn&& planes) {
  using DF = hn::ScalableTag<float>;
  const DF df;
  const int n = int(hn::Lanes(df));
  uint64_t nonfinite = 0;
  bool ready = false;
  // Broadcast at the first span a vector long (placement new: std::optional's construction is
  // not compiled for the target, and Planes's constructor must inline into code that is).
  alignas(Planes<DF>) unsigned char planes_room[sizeof(Planes<DF>)];
  const Planes<DF>* p = nullptr;
  alignas(64) float column_store[6 * ColumnCache<DF>::kPitch];
  ColumnCache<DF> cols(column_store, t.xmin);
  for_each_row_span(t, bands, [&](int py, int lo, int hi) {
    if (!ready && !(ready = planes())) return false;
    if (hi - lo + 1 < n) {
      nonfinite += span_scalar<Mode>(fb, t, py, lo, hi, func);
      return true;
    }
    if (!p) p = new (planes_room) Planes<DF>(df, KernelPlanes{t.z, t.inv_w, 1});
    nonfinite += SpanShade<Mode>(fb, *p, cols, py, lo, hi, func);
    return true;
  });
  return nonfinite;
}

// The row loop's rasterize() (row_loop.h) with these kernels: tiny triangles by the scalar span,
// boxes of at most 8x8 by the box kernel, larger ones with 32-bit edge functions in rows, the
// largest by solved spans (long ones a vector at a time).
template <DepthMode Mode, typename PlanesFn>
HWY_INLINE uint64_t Rasterize(Framebuffer& fb, Triangle& t, GLenum func, const Bands& bands, PlanesFn&& planes) {
  uint64_t nonfinite = 0;
  const int64_t ext_x = std::max({t.x[0], t.x[1], t.x[2]}) - std::min({t.x[0], t.x[1], t.x[2]});
  const int64_t ext_y = std::max({t.y[0], t.y[1], t.y[2]}) - std::min({t.y[0], t.y[1], t.y[2]});
  if (is_tiny(t, ext_x, ext_y)) {
    bool ready = false;
    for_each_tiny_span(t, bands, [&](int py, int lo, int hi) {
      if (!ready && !(ready = planes())) return false;
      nonfinite += span_scalar<Mode>(fb, t, py, lo, hi, func);
      return true;
    });
  } else if (ext_x < 31 * 256 && ext_y < 31 * 256) {
    int32_t edges[kEdgeFields];
    KernelEdgesOf(t, edges);
    const KernelPlanes kp{t.z, t.inv_w, 1};
    if (t.xmax - t.xmin < 8 && t.ymax - t.ymin < 8) {
      const uint64_t cover = BoxCover({edges, 1}, bands);
      if (cover && planes()) nonfinite = BoxShadeAny<Mode>(fb, kp, t.xmin, t.ymin, t.xmax - t.xmin + 1, cover, func);
    } else if (planes()) {
      nonfinite = RowsShade<Mode>(fb, {edges, 1}, kp, bands, func);
    }
  } else {
    nonfinite = RasterizeLarge<Mode>(fb, t, func, bands, planes);
  }
  return nonfinite;
}

}  // namespace ffc::raster::detail::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#endif  // the toggled guard
