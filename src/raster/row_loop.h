// The row loop: which pixels of a set-up triangle this thread draws, found by the cheapest exact
// strategy for the triangle's size (tiny: a 2x2 test; small: four centres at a time in SSE2;
// large: each row's span solved for), each pixel's depth and colour by the rules of
// pixel_rules.h. Where the dispatch picks a vector target (wide/kernels.h), its kernels draw
// instead; they draw the same bits. Used by draw_triangles (set-up triangles) and
// draw_triangle_list (shared vertices); not an interface.
#pragma once
#include "raster/isa.h"
#if FFCOMPAT_X86
#include <emmintrin.h>
#endif

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstring>
#include <type_traits>

#include "raster/wide/kernels.h"
#include "raster/pixel_rules.h"
#include "raster/raster.h"
#include "raster/setup.h"

namespace ffc::raster::detail {

// The rows one thread draws: bands of kBandRows rows, band b belonging to thread b % count.
struct Bands {
  static constexpr int kMax = 16384 / kBandRows + 1;
  int mine, count;
  std::array<uint16_t, kMax + 1> next;  // next[b]: this thread's first band at or after b
  // next[b] = b + (mine - b % count) mod count, with b % count stepped rather than divided: a
  // table is made per thread per draw, and 258 divisions cost the early draws' small ones 2 % of
  // a frame.
  Bands(int mine_, int count_) : mine(mine_), count(count_) {
    for (int b = 0, rem = 0; b <= kMax; ++b, rem = rem + 1 == count ? 0 : rem + 1) {
      const int ahead = mine - rem;  // in (-count, count): 0 <= mine, rem < count
      next[size_t(b)] = uint16_t(b + (ahead < 0 ? ahead + count : ahead));
    }
  }
  bool owns(int b) const { return next[size_t(b)] == b; }
};

// The depth functions the row loop is compiled for; the others go through depth_pass.
enum DepthMode : int { kNoDepth, kLess, kLequal, kAnyDepth };
inline DepthMode depth_mode(const State& s) {
  if (!s.depth_test) return kNoDepth;
  return s.depth_func == GL_LESS ? kLess : s.depth_func == GL_LEQUAL ? kLequal : kAnyDepth;
}
// Calls f(mode) with the state's depth mode as a compile-time constant (std::integral_constant):
// the one switch from the run-time depth function to the loops compiled for it.
template <typename F>
void with_depth_mode(const State& s, F&& f) {
  switch (depth_mode(s)) {
    case kNoDepth: return f(std::integral_constant<DepthMode, kNoDepth>{});
    case kLess: return f(std::integral_constant<DepthMode, kLess>{});
    case kLequal: return f(std::integral_constant<DepthMode, kLequal>{});
    case kAnyDepth: return f(std::integral_constant<DepthMode, kAnyDepth>{});
  }
}

// Triangles under fog, polygon offset or a per-fragment operation (State::fragment_ops): the
// pixels rasterize() covers, one by one, each through them (fragment_ops.cpp).
void rasterize_fragment_ops(Framebuffer& fb, const Triangle& t, const State& s, const Bands& bands);

// First and last k with e0 + a k >= thr, for k in [lo, hi]; empty when first > last.
inline void span(int64_t e0, int64_t a, int64_t thr, int& lo, int& hi) {
  const int64_t need = thr - e0;  // a k >= need
  if (a > 0) {
    const int64_t k = need >= 0 ? (need + a - 1) / a : -((-need) / a);
    lo = int(std::max<int64_t>(lo, k));
  } else if (a < 0) {
    const int64_t b = -a, m = -need;  // k <= m / b
    const int64_t k = m >= 0 ? m / b : -((-m + b - 1) / b);
    hi = int(std::min<int64_t>(hi, k));
  } else if (need > 0) {
    hi = lo - 1;
  }
}

// Calls row(py, lo, hi) for each row py of t in this thread's bands that has covered pixels,
// lo..hi, each row's span solved for in 64 bits rather than searched; stops at a row that
// returns false, and returns false then.
template <typename Row>
bool for_each_row_span(const Triangle& t, const Bands& bands, Row&& row) {
  EdgeFunction e[3];
  for (int i = 0; i < 3; ++i) e[i] = edge_function(t, i, 0, 0);
  for (int by = bands.next[size_t(t.ymin / kBandRows)]; by * kBandRows <= t.ymax; by += bands.count) {
    const int row_end = std::min(by * kBandRows + kBandRows - 1, t.ymax);
    for (int py = std::max(by * kBandRows, t.ymin); py <= row_end; ++py) {
      int lo = t.xmin, hi = t.xmax;
      for (int i = 0; i < 3; ++i) span(e[i].at + e[i].per_y * py, e[i].per_x, e[i].limit, lo, hi);
      if (lo <= hi && !row(py, lo, hi)) return false;
    }
  }
  return true;
}

// Which of the box's first 2x2 pixel centres t covers, a bit each: (0,0) (1,0) (0,1) (1,1). The
// edge functions relative to the first centre fit in 32 bits (the vertices lie within a few
// pixels of it).
inline unsigned cover_2x2(const Triangle& t) {
#if FFCOMPAT_X86
  __m128i in = _mm_set1_epi32(-1);
  for (int i = 0; i < 3; ++i) {
    const EdgeFunction e = edge_function(t, i, t.xmin, t.ymin);
    const int32_t at = int32_t(e.at), px = int32_t(e.per_x), py = int32_t(e.per_y);
    const __m128i lanes = _mm_set_epi32(at + px + py, at + py, at + px, at);
    in = _mm_and_si128(in, _mm_cmpgt_epi32(lanes, _mm_set1_epi32(int32_t(e.limit) - 1)));
  }
  return unsigned(_mm_movemask_ps(_mm_castsi128_ps(in)));
#else
  unsigned in = 0xF;
  for (int i = 0; i < 3; ++i) {
    const EdgeFunction e = edge_function(t, i, t.xmin, t.ymin);
    const int64_t lanes[4] = {e.at, e.at + e.per_x, e.at + e.per_y, e.at + e.per_x + e.per_y};
    for (unsigned lane = 0; lane < 4; ++lane)
      if (lanes[lane] < e.limit) in &= ~(1u << lane);
  }
  return in;
#endif
}

// llvmpipe_mul_add(a, b, c) for a and b fixed along a row (depth's second step,
// z2 Y_down + (...)). Fused without an FMA instruction (x86 before FMA3: std::fma is a library
// call there): in double, the product made once. It is exact (24 + 24 significand bits fit in
// 53), the sum is rounded once, and rounding that to float gives the fused result unless the
// double lies exactly halfway between two floats or in float's subnormal range (then std::fma
// decides), as wide/kernels-inl.h FusedMulAdd does a vector at a time. Unfused: the product
// rounded to float once, then the sum.
struct FusedRowScalar {
  float a, b, ab;  // ab: the unfused product
  bool fused;
#if FFCOMPAT_X86 && !defined(__FMA__)
  double ab_exact;
  FusedRowScalar(float a_, float b_)
      : a(a_), b(b_), ab(a_ * b_), fused(llvmpipe_fma()), ab_exact(double(a_) * double(b_)) {}
  float operator()(float c) const {
    if (!fused) return ab + c;
    const double s = ab_exact + double(c);
    uint64_t bits;
    std::memcpy(&bits, &s, 8);
    const bool halfway = (bits & ((uint64_t(1) << 29) - 1)) == uint64_t(1) << 28;
    if (__builtin_expect(halfway || (std::fabs(s) < 0x1p-125 && s != 0), 0)) return std::fma(a, b, c);
    return float(s);
  }
#else
  FusedRowScalar(float a_, float b_) : a(a_), b(b_), ab(a_ * b_), fused(llvmpipe_fma()) {}
  float operator()(float c) const { return fused ? std::fma(a, b, c) : ab + c; }
#endif
};

// The plane terms of a column that depend on X alone: depth's first step z1 X + z0,
// (iw0 + iw1 X) and each colour's (c0 + cx X) (X = px + 0.5; depth at the column px).
struct ColumnTerms {
  alignas(32) float z, iw, pad[2], c[4];
};
inline ColumnTerms column_terms(const Triangle& t, int px) {
  ColumnTerms k{};
  const float fx = float(px + 0.5);
  k.z = llvmpipe_mul_add(t.z[1], float(px), t.z[0]);
  k.iw = t.inv_w[0] + t.inv_w[1] * fx;
  for (int i = 0; i < 4; ++i) k.c[i] = t.c0[i] + t.cx[i] * fx;
  return k;
}

// A large triangle's column terms, each column's made once for the rows this thread draws (they
// depend on the column alone, so the same values), for its first kCachedColumns columns; rows
// reaching further make their own (covers). The storage is the caller's (its stack: a heap
// buffer would be allocated during some frame).
inline constexpr int kCachedColumns = 1024;

// The columns a cache has made, lo..hi (none at first), grown to cover from..to by making only the
// columns missing (make(a, b) makes a..b). Shared by the row loop's cache and the kernels'.
struct MadeColumns {
  int lo = 0, hi = -1;
  template <class Make>
  void cover(int from, int to, Make&& make) {
    if (lo > hi) {
      make(from, to), lo = from, hi = to;
      return;
    }
    if (from < lo) make(from, lo - 1), lo = from;
    if (to > hi) make(hi + 1, to), hi = to;
  }
};

class ColumnCache {
 public:
  ColumnCache(const Triangle& t, ColumnTerms* store) : t_(t), store_(store) {}
  bool covers(int to) const { return to - t_.xmin < kCachedColumns; }
  // Columns from..to (within the triangle's box, covers(to)), made where they are not yet.
  const ColumnTerms* at(int from, int to) {
    made_.cover(from, to, [&](int a, int b) {
      for (int px = a; px <= b; ++px) store_[px - t_.xmin] = column_terms(t_, px);
    });
    return store_ + (from - t_.xmin);
  }

 private:
  const Triangle& t_;
  ColumnTerms* store_;
  MadeColumns made_;
};

// Pixels lo..hi of row py, covered by t (planes filled), drawn one by one: depth test, colour.
// Each pixel's values come from the planes at its own centre, (p0 + px X) + py Y, never stepped
// from a neighbour, so that the vector kernels (wide/kernels.h) compute the same bits a vector of
// pixels at a time. The column terms come from `cols` (cols[k] for pixel lo + k) where given, else
// are made here. Returns the drawn pixels whose colour was not finite.
template <DepthMode D>
inline uint64_t span_scalar(Framebuffer& fb, const Triangle& t, int py, int lo, int hi, GLenum depth_func,
                            const ColumnTerms* cols = nullptr) {
  uint64_t nonfinite = 0;
#if FFCOMPAT_X86
  const __m128 zero = _mm_setzero_ps(), one = _mm_set1_ps(1), k255 = _mm_set1_ps(255);
#endif
  // py Y once for the row: the same products, so the same bits.
  const double y = py + 0.5;
  const float fy = float(y), iwy = t.inv_w[2] * fy, y_down = float(fb.height - 1 - py);
  const FusedRowScalar depth_row(t.z[2], y_down);
#if FFCOMPAT_X86
  const __m128 cy = _mm_mul_ps(_mm_loadu_ps(t.cy), _mm_set1_ps(fy));
#else
  float cy[4];
  for (int k = 0; k < 4; ++k) cy[k] = t.cy[k] * fy;
#endif
  uint8_t* o = &fb.color[(size_t(py) * fb.width + lo) * 4];
  uint32_t* zp = &fb.depth[size_t(py) * fb.width + lo];
  for (int px = lo; px <= hi; ++px, o += 4, ++zp) {
    const ColumnTerms here = cols ? cols[px - lo] : column_terms(t, px);
    bool pass = true;
    if constexpr (D != kNoDepth) {
      const uint32_t zi = depth24(depth_row(here.z));  // depth_at(t.z, 1, X, Y_down)
      if constexpr (D == kLess) pass = zi < *zp;
      else if constexpr (D == kLequal) pass = zi <= *zp;
      else pass = depth_pass(depth_func, zi, *zp);
      if (pass) *zp = zi;
    }
    if (pass) {
      const float iw = here.iw + iwy;
#if FFCOMPAT_X86
      const __m128 col = _mm_add_ps(_mm_load_ps(here.c), cy);
      // Clamp (a NaN becomes 0), scale, round half to even (the SSE default), pack to bytes.
      __m128 cl = _mm_mul_ps(col, _mm_set1_ps(1.0f / iw));
      nonfinite += _mm_movemask_ps(_mm_cmpunord_ps(_mm_mul_ps(cl, zero), zero)) != 0;  // c * 0: NaN unless finite
      cl = _mm_min_ps(_mm_max_ps(cl, zero), one);
      const __m128i i32 = _mm_cvtps_epi32(_mm_mul_ps(cl, k255));
      const __m128i i16 = _mm_packs_epi32(i32, i32);
      const uint32_t rgba = uint32_t(_mm_cvtsi128_si32(_mm_packus_epi16(i16, i16)));
      std::memcpy(o, &rgba, 4);
#else
      const float inv = 1.0f / iw;
      bool finite = true;
      for (int k = 0; k < 4; ++k) {
        const float c = (here.c[k] + cy[k]) * inv;
        finite &= std::isfinite(c);
        o[k] = unorm8(c);
      }
      nonfinite += !finite;
#endif
    }
  }
  return nonfinite;
}

// Calls draw(py, lo, hi) for the covered pixels of a triangle whose box is at most 2x2 pixel
// centres and whose vertices lie within 4 pixels of each other, in this thread's bands; stops at
// a call that returns false.
template <typename Draw>
inline void for_each_tiny_span(const Triangle& t, const Bands& bands, Draw&& draw) {
  unsigned mask = cover_2x2(t);
  if (t.xmax == t.xmin) mask &= 0x5;
  if (t.ymax == t.ymin) mask &= 0x3;
  for (int row = 0; mask; ++row, mask >>= 2) {
    const int py = t.ymin + row;
    if (!(mask & 3) || !bands.owns(py / kBandRows)) continue;
    if (!draw(py, t.xmin + ((mask & 1) ? 0 : 1), t.xmin + ((mask & 2) ? 1 : 0))) return;
  }
}

inline bool is_tiny(const Triangle& t, int64_t ext_x, int64_t ext_y) {
  return t.xmax - t.xmin <= 1 && t.ymax - t.ymin <= 1 && ext_x < 4 * 256 && ext_y < 4 * 256;
}

// rasterize()'s large triangles: each row's span solved for, the column terms made once a column
// (ColumnCache). Not inlined: the cache lives on this function's stack.
template <DepthMode D, typename Planes>
[[gnu::noinline]] uint64_t rasterize_large(Framebuffer& fb, const Triangle& t, GLenum depth_func, const Bands& bands, Planes&& planes) {
  uint64_t nonfinite = 0;
  bool ready = false;
  ColumnTerms store[kCachedColumns];
  ColumnCache cols(t, store);
  for_each_row_span(t, bands, [&](int py, int lo, int hi) {
    if (!ready) {
      if (!planes()) return false;
      ready = true;
    }
    nonfinite += span_scalar<D>(fb, t, py, lo, hi, depth_func, cols.covers(hi) ? cols.at(lo, hi) : nullptr);
    return true;
  });
  return nonfinite;
}

// Draws the rows of t (edges set up, box within the framebuffer) that lie in this thread's bands.
// `planes()` fills t's planes and is called once, before the first covered pixel (most tiny
// triangles cover none); false from it drops the triangle. Where wide_kernels(), the dispatched
// target's kernels draw it (wide/kernels.h), else the loops below. Returns the fragments it wrote
// from a non-finite colour (the caller counts them in its State's counters).
template <DepthMode D, typename Planes>
uint64_t rasterize(Framebuffer& fb, Triangle& t, GLenum depth_func, const Bands& bands, Planes&& planes) {
  uint64_t nonfinite = 0;
  if (wide_kernels()) {
    return rasterize_wide(D, fb, t, depth_func, bands, PlanesRef::of(planes));
  }
  bool ready = false;
  auto draw_span = [&](int py, int lo, int hi) {
    if (!ready) {
      if (!planes()) return false;
      ready = true;
    }
    nonfinite += span_scalar<D>(fb, t, py, lo, hi, depth_func);
    return true;
  };
  const int64_t ext_x = std::max({t.x[0], t.x[1], t.x[2]}) - std::min({t.x[0], t.x[1], t.x[2]});
  const int64_t ext_y = std::max({t.y[0], t.y[1], t.y[2]}) - std::min({t.y[0], t.y[1], t.y[2]});
  if (is_tiny(t, ext_x, ext_y)) {
    // Tiny (most triangles at high subdivision): the at most 2x2 pixel centres of the box tested
    // at once.
    for_each_tiny_span(t, bands, draw_span);
#if FFCOMPAT_X86
  } else if (ext_x < 31 * 256 && ext_y < 31 * 256) {
    // Small (SSE2): edge functions relative to the box's first pixel centre fit in
    // 32 bits, and four pixels of a row are tested at once; a row's covered pixels are contiguous.
    int32_t at[3], per_y[3];
    __m128i step[3], row_lanes[3], limit[3];
    for (int i = 0; i < 3; ++i) {
      const EdgeFunction e = edge_function(t, i, t.xmin, t.ymin);
      const int32_t per_x = int32_t(e.per_x);
      at[i] = int32_t(e.at), per_y[i] = int32_t(e.per_y);
      row_lanes[i] = _mm_set_epi32(3 * per_x, 2 * per_x, per_x, 0);
      step[i] = _mm_set1_epi32(4 * per_x);
      limit[i] = _mm_set1_epi32(int32_t(e.limit) - 1);  // e >= limit  as  e > limit - 1
    }
    const int width = t.xmax - t.xmin + 1;
    const uint32_t keep = width >= 32 ? ~0u : (1u << width) - 1;
    for (int by = bands.next[size_t(t.ymin / kBandRows)]; by * kBandRows <= t.ymax; by += bands.count) {
      const int row_end = std::min(by * kBandRows + kBandRows - 1, t.ymax);
      for (int py = std::max(by * kBandRows, t.ymin); py <= row_end; ++py) {
        const int32_t dy = py - t.ymin;
        __m128i v[3];
        for (int i = 0; i < 3; ++i) v[i] = _mm_add_epi32(_mm_set1_epi32(at[i] + per_y[i] * dy), row_lanes[i]);
        uint32_t mask = 0;
        for (int chunk = 0; chunk < width; chunk += 4) {
          const __m128i in = _mm_and_si128(_mm_and_si128(_mm_cmpgt_epi32(v[0], limit[0]), _mm_cmpgt_epi32(v[1], limit[1])),
                                           _mm_cmpgt_epi32(v[2], limit[2]));
          mask |= uint32_t(_mm_movemask_ps(_mm_castsi128_ps(in))) << chunk;
          for (int i = 0; i < 3; ++i) v[i] = _mm_add_epi32(v[i], step[i]);
        }
        mask &= keep;
        if (!mask) continue;
        if (!draw_span(py, t.xmin + __builtin_ctz(mask), t.xmin + 31 - __builtin_clz(mask))) return nonfinite;
      }
    }
#endif
  } else {
    nonfinite += rasterize_large<D>(fb, t, depth_func, bands, planes);  // large (and, without x86 intrinsics, small)
  }
  return nonfinite;
}

// The same for a run-time depth function.
template <typename Planes>
void rasterize(Framebuffer& fb, Triangle& t, const State& s, const Bands& bands, Planes&& planes) {
  with_depth_mode(s, [&](auto mode) { count_nonfinite(s, rasterize<decltype(mode)::value>(fb, t, s.depth_func, bands, planes)); });
}

}  // namespace ffc::raster::detail
