// The rasterizer's shared inner parts (not an interface): edge setup, attribute planes and the row
// loop, used by draw_triangles (set-up triangles) and draw_triangle_list (shared vertices).
#pragma once
#include "raster/isa.h"
#if FFCOMPAT_X86
#include <emmintrin.h>
#endif

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstring>

#include "raster/box.h"
#include "raster/raster.h"

namespace ffc::raster::detail {

extern std::atomic<uint64_t> g_nonfinite_fragments;

// The rows one thread draws: bands of kBandRows rows, band b belonging to thread b % count.
struct Bands {
  static constexpr int kMax = 16384 / kBandRows + 1;
  int mine, count;
  std::array<uint16_t, kMax + 1> next;  // next[b]: this thread's first band at or after b
  Bands(int mine_, int count_) : mine(mine_), count(count_) {
    for (int b = 0; b <= kMax; ++b) next[size_t(b)] = uint16_t(b + (mine - b % count + count) % count);
  }
  bool owns(int b) const { return next[size_t(b)] == b; }
};

// The depth functions the row loop is compiled for; the others go through depth_pass.
enum DepthMode : int { kNoDepth, kLess, kLequal, kAnyDepth };
inline DepthMode depth_mode(const State& s) {
  if (!s.depth_test) return kNoDepth;
  return s.depth_func == GL_LESS ? kLess : s.depth_func == GL_LEQUAL ? kLequal : kAnyDepth;
}

inline bool depth_pass(GLenum func, uint32_t z, uint32_t stored) {
  switch (func) {
    case GL_NEVER: return false;
    case GL_LESS: return z < stored;
    case GL_EQUAL: return z == stored;
    case GL_LEQUAL: return z <= stored;
    case GL_GREATER: return z > stored;
    case GL_NOTEQUAL: return z != stored;
    case GL_GEQUAL: return z >= stored;
    default: return true;
  }
}

// Depth as llvmpipe computes it (Mesa 22.3, 24-bit unorm buffer): the fragment's z in float from
// a plane through the window positions (depth_plane), clamped to [0, 1] (lp_state_fs.c
// lp_build_depth_clamp; a NaN to 0: maxss gives its second operand), scaled by 2^24 - 1 in float
// and rounded half to even (lp_bld_conv.c lp_build_clamped_float_to_unsigned_norm, the branch for
// 24 bits = float's mantissa + 1). Ties between triangles are decided by these exact bits, so every
// copy (box_kernels.h depth24x16, setup8 in triangle_list.cpp) computes the same.
inline uint32_t depth24(float z) {
#if FFCOMPAT_X86
  const __m128 c = _mm_min_ss(_mm_max_ss(_mm_set_ss(z), _mm_setzero_ps()), _mm_set_ss(1.0f));
  return uint32_t(_mm_cvtss_si32(_mm_mul_ss(c, _mm_set_ss(16777215.0f))));
#else
  const float c = std::min(z > 0 ? z : 0.0f, 1.0f);  // maxss's order: a NaN (and -0) to +0
  return uint32_t(std::nearbyint(c * 16777215.0f));
#endif
}

// A colour channel to 8 bits as the SSE loops and the kernels do it: clamped to [0, 1] (a NaN to
// 0, as maxss), times 255, rounded half to even (the current rounding mode, as cvtps2dq).
inline uint8_t unorm8(float c) {
  const float clamped = std::min(c > 0 ? c : 0.0f, 1.0f);
  return uint8_t(std::nearbyint(clamped * 255.0f));
}

// The depth plane of a triangle as llvmpipe's setup builds it (lp_state_setup.c, init_args and
// calc_coef4), in float, operation by operation: positions with y counted down from the top row
// (the framebuffer's, as llvmpipe sees it), relative to the pixel centre (x0 - 0.5). Returns
// {a0, dz/dx, dz/dy}; the value at pixel (X, row-from-top Y) is depth_at. llvmpipe takes the
// vertices in its own order: (v0, v1, v2) when counter-clockwise on the screen (GL's window), (v1,
// v0, v2) otherwise (lp_setup_tri.c triangle_both, last vertex provoking). Given the vertices in
// our counter-clockwise order (vertices 1 and 2 exchanged when `swapped`), that is a rotation.
inline void depth_plane(const float (&x)[3], const float (&yd)[3], const float (&z)[3], bool swapped, float (&out)[3]) {
  const int i0 = swapped ? 2 : 0, i1 = swapped ? 0 : 1, i2 = swapped ? 1 : 2;
  const float x0 = x[i0], y0 = yd[i0], z0 = z[i0], x1 = x[i1], y1 = yd[i1], z1 = z[i1];
  const float x2 = x[i2], y2 = yd[i2], z2 = z[i2];
  const float x0c = x0 - 0.5f, y0c = y0 - 0.5f;
  const float dx01 = x0 - x1, dy01 = y0 - y1, dx20 = x2 - x0, dy20 = y2 - y0;
  const float ooa = 1.0f / (dx01 * dy20 - dy01 * dx20);
  const float dx20o = dx20 * ooa, dy20o = dy20 * ooa, dx01o = dx01 * ooa, dy01o = dy01 * ooa;
  const float da01 = z0 - z1, da20 = z2 - z0;
  const float dzdx = da01 * dy20o - da20 * dy01o;
  const float dzdy = da20 * dx01o - da01 * dx20o;
  out[0] = z0 - (dzdx * x0c + dzdy * y0c), out[1] = dzdx, out[2] = dzdy;
}

// Polygon offset as llvmpipe's setup computes it (lp_state_setup.c lp_do_offset_tri), in float
// from the same vertex order and differences as depth_plane: the depth slopes |dz/dx|, |dz/dy|
// from the cross product of two edges over the doubled area, their maximum times the factor,
// plus the units already scaled to the 24-bit buffer (State::offset_units). The fragment shader
// adds it to each fragment's interpolated z before the clamp to [0, 1].
inline float polygon_offset(const float (&x)[3], const float (&yd)[3], const float (&z)[3], bool swapped,
                            const State& s) {
  const int i0 = swapped ? 2 : 0, i1 = swapped ? 0 : 1, i2 = swapped ? 1 : 2;
  const float dx01 = x[i0] - x[i1], dy01 = yd[i0] - yd[i1], dz01 = z[i0] - z[i1];
  const float dx20 = x[i2] - x[i0], dy20 = yd[i2] - yd[i0], dz20 = z[i2] - z[i0];
  const float ooa = 1.0f / (dx01 * dy20 - dy01 * dx20);
  const float dzdx = std::fabs((dz20 * dy01 - dy20 * dz01) * ooa);
  const float dzdy = std::fabs((dx20 * dz01 - dz20 * dx01) * ooa);
  const float max = !(dzdx <= dzdy) ? dzdx : dzdy;  // an unordered compare: a NaN dz/dx is taken
  return s.offset_units + max * s.offset_factor;
}

// Triangles under fog or polygon offset (State::fragment_ops): the pixels rasterize() covers,
// one by one, each with its fog and depth offset (fragment_ops.cpp).
void rasterize_fragment_ops(Framebuffer& fb, const Triangle& t, const State& s, const Bands& bands);

// The fragment's depth at pixel column X, row Y counted from the top: two fused multiply-adds, as
// lp_bld_interp.c's interp_attrib_linear (llvm.fmuladd, fused on a CPU with FMA).
inline float depth_at(const float* z, int stride, float x, float y_down) {
  return std::fma(z[2 * stride], y_down, std::fma(z[stride], x, z[0]));
}

// Solves value = p0 + p1 x + p2 y through three points once per triangle; each attribute is then
// a few multiplications.
struct PlaneSolver {
  double x0, y0, x1, y1, x2, y2, inv_det;
  explicit PlaneSolver(const glm::dvec3 (&pos)[3])
      : x0(pos[0].x), y0(pos[0].y), x1(pos[1].x - pos[0].x), y1(pos[1].y - pos[0].y),
        x2(pos[2].x - pos[0].x), y2(pos[2].y - pos[0].y) {
    const double det = x1 * y2 - x2 * y1;
    inv_det = det != 0 ? 1 / det : 0;  // degenerate unsnapped: a constant through vertex 0
  }
  void operator()(double a, double b, double c, double* p) const {
    const double d1 = b - a, d2 = c - a;
    p[1] = (d1 * y2 - d2 * y1) * inv_det;
    p[2] = (x1 * d2 - x2 * d1) * inv_det;
    p[0] = a - p[1] * x0 - p[2] * y0;
  }
};

// From t.x, t.y (snapped): the area, counter-clockwise order (*swapped: vertices 1 and 2 were
// exchanged), the edges' ownership and the pixel box within the framebuffer. False when no pixel
// centre can be covered.
inline bool setup_edges(Triangle& t, int fb_width, int fb_height, bool* swapped) {
  // Pixel centres (X + 0.5) inside the snapped bounding box: at high subdivision most triangles
  // have none, so this comes first.
  auto lo = [](int64_t v) { return int(std::clamp<int64_t>((v - 128 + 255) >> 8, -1, 1 << 30)); };  // first centre >= v
  auto hi = [](int64_t v) { return int(std::clamp<int64_t>((v - 128) >> 8, -1, 1 << 30)); };        // last centre <= v
  t.ymin = std::max(0, lo(std::min({t.y[0], t.y[1], t.y[2]})));
  t.ymax = std::min(fb_height - 1, hi(std::max({t.y[0], t.y[1], t.y[2]})));
  if (t.ymin > t.ymax) return false;
  t.xmin = std::max(0, lo(std::min({t.x[0], t.x[1], t.x[2]})));
  t.xmax = std::min(fb_width - 1, hi(std::max({t.x[0], t.x[1], t.x[2]})));
  if (t.xmin > t.xmax) return false;
  t.area = (t.x[1] - t.x[0]) * (t.y[2] - t.y[0]) - (t.x[2] - t.x[0]) * (t.y[1] - t.y[0]);
  if (t.area == 0) return false;
  *swapped = t.area < 0;
  if (*swapped) {  // make it counter-clockwise
    std::swap(t.x[1], t.x[2]), std::swap(t.y[1], t.y[2]);
    t.area = -t.area;
  }
  for (int i = 0; i < 3; ++i) {
    // A pixel exactly on an edge belongs to the triangle for left and bottom edges (GL window
    // coordinates), so a pixel on an edge shared by two triangles is drawn once.
    const int j = (i + 1) % 3, k = (i + 2) % 3;
    const int64_t dx = t.x[k] - t.x[j], dy = t.y[k] - t.y[j];
    t.inclusive[i] = (dy < 0) | ((dy == 0) & (dx > 0));
  }
  return true;
}

// The planes of 1/w and colour / w (secondary summed in) from the unsnapped positions, as
// llvmpipe builds them; flat: the colour as a constant, no rounding through 1/w. False when a
// plane leaves float (1/w near float's limits over a tiny area): not drawn rather than drawn from
// infinities. `color` and `sec` are per vertex (sec unread without add_secondary).
template <typename C>
bool setup_planes(Triangle& t, const glm::dvec3 (&pos)[3], const double (&inv_w)[3], const C* const (&color)[3],
                  const C* const (&sec)[3], bool flat, bool add_secondary) {
  const PlaneSolver make(pos);  // depth apart: depth_plane
  auto channel = [&](int i, int k) {
    return double((*color[i])[k]) + (add_secondary && k < 3 ? double((*sec[i])[k]) : 0.0);
  };
  if (flat) {
    t.inv_w[0] = 1, t.inv_w[1] = t.inv_w[2] = 0;
    for (int k = 0; k < 4; ++k) t.c0[k] = float(channel(0, k)), t.cx[k] = t.cy[k] = 0;
    return true;
  }
  double p[3];
  make(inv_w[0], inv_w[1], inv_w[2], p);
  for (int i = 0; i < 3; ++i) t.inv_w[i] = float(p[i]);
  for (int k = 0; k < 4; ++k) {
    make(channel(0, k) * inv_w[0], channel(1, k) * inv_w[1], channel(2, k) * inv_w[2], p);
    t.c0[k] = float(p[0]), t.cx[k] = float(p[1]), t.cy[k] = float(p[2]);
  }
  for (int k = 0; k < 4; ++k)
    if (!(std::isfinite(t.c0[k]) && std::isfinite(t.cx[k]) && std::isfinite(t.cy[k]))) return false;
  return std::isfinite(t.inv_w[0]) && std::isfinite(t.inv_w[1]) && std::isfinite(t.inv_w[2]);
}

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

// Draws the rows of t (edges set up, box within the framebuffer) that lie in this thread's bands.
// `planes()` fills t's planes
// and is called once, before the first covered pixel (most tiny triangles cover none); false
// from it drops the triangle.
template <DepthMode D, typename Planes>
void rasterize(Framebuffer& fb, Triangle& t, GLenum depth_func, const Bands& bands, Planes&& planes) {
  // Edge functions at pixel centres in 1/256 units. A pixel is inside when every e_i >= thr_i
  // (0 for inclusive edges, 1 otherwise).
  int64_t thr[3];
  for (int i = 0; i < 3; ++i) thr[i] = t.inclusive[i] ? 0 : 1;
  bool ready = false;
  uint64_t nonfinite = 0;
#if FFCOMPAT_X86
  const __m128 zero = _mm_setzero_ps(), one = _mm_set1_ps(1), k255 = _mm_set1_ps(255);
#endif
  // Pixels lo..hi of row py are covered. Each pixel's values come from the planes at its own
  // centre, (p0 + px X) + py Y, never stepped from a neighbour: the kernels of raster/box.h
  // compute the same bits sixteen pixels at a time.
  auto draw_span = [&](int py, int lo, int hi) {
    if (!ready) {
      if (!planes()) return false;
      ready = true;
    }
#if FFCOMPAT_X86
    if (hi - lo >= 15 && wide_kernels()) {  // the long rows of large triangles
      nonfinite += span_shade<D>(fb, {t.z, t.inv_w, 1}, py, lo, hi, depth_func);
      return true;
    }
#endif
    // py Y once for the row: the same products, so the same bits.
    const double y = py + 0.5;
    const float fy = float(y), iwy = t.inv_w[2] * fy, y_down = float(fb.height - 1 - py);
#if FFCOMPAT_X86
    const __m128 c0 = _mm_loadu_ps(t.c0), cx = _mm_loadu_ps(t.cx), cy = _mm_mul_ps(_mm_loadu_ps(t.cy), _mm_set1_ps(fy));
#else
    float cy[4];
    for (int k = 0; k < 4; ++k) cy[k] = t.cy[k] * fy;
#endif
    uint8_t* o = &fb.color[(size_t(py) * fb.width + lo) * 4];
    uint32_t* zp = &fb.depth[size_t(py) * fb.width + lo];
    for (int px = lo; px <= hi; ++px, o += 4, ++zp) {
      const double x = px + 0.5;
      bool pass = true;
      if constexpr (D != kNoDepth) {
        const uint32_t zi = depth24(depth_at(t.z, 1, float(px), y_down));
        if constexpr (D == kLess) pass = zi < *zp;
        else if constexpr (D == kLequal) pass = zi <= *zp;
        else pass = depth_pass(depth_func, zi, *zp);
        if (pass) *zp = zi;
      }
      if (pass) {
        const float fx = float(x), iw = t.inv_w[0] + t.inv_w[1] * fx + iwy;
#if FFCOMPAT_X86
        const __m128 col = _mm_add_ps(_mm_add_ps(c0, _mm_mul_ps(cx, _mm_set1_ps(fx))), cy);
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
          const float c = ((t.c0[k] + t.cx[k] * fx) + cy[k]) * inv;
          finite &= std::isfinite(c);
          o[k] = unorm8(c);
        }
        nonfinite += !finite;
#endif
      }
    }
    return true;
  };
  const int first_band = bands.next[size_t(t.ymin / kBandRows)];
  const int64_t ext_x = std::max({t.x[0], t.x[1], t.x[2]}) - std::min({t.x[0], t.x[1], t.x[2]});
  const int64_t ext_y = std::max({t.y[0], t.y[1], t.y[2]}) - std::min({t.y[0], t.y[1], t.y[2]});
  if (t.xmax - t.xmin <= 1 && t.ymax - t.ymin <= 1 && ext_x < 4 * 256 && ext_y < 4 * 256) {
    // Tiny (most triangles at high subdivision): the at most 2x2 pixel centres of the box tested
    // at once, lanes (0,0) (1,0) (0,1) (1,1), edge functions relative to the first centre in 32
    // bits (the vertices lie within a few pixels of it).
    const int64_t ox = int64_t(t.xmin) * 256 + 128, oy = int64_t(t.ymin) * 256 + 128;
#if FFCOMPAT_X86
    __m128i in = _mm_set1_epi32(-1);
#else
    unsigned mask = 0xF;
#endif
    for (int i = 0; i < 3; ++i) {
      const int j = (i + 1) % 3, k = (i + 2) % 3;
      const int32_t dx = int32_t(t.x[k] - t.x[j]), dy = int32_t(t.y[k] - t.y[j]);
      const int32_t e = dx * int32_t(oy - t.y[j]) - dy * int32_t(ox - t.x[j]), ea = -dy * 256, eb = dx * 256;
#if FFCOMPAT_X86
      const __m128i lanes = _mm_set_epi32(e + ea + eb, e + eb, e + ea, e);
      in = _mm_and_si128(in, _mm_cmpgt_epi32(lanes, _mm_set1_epi32(int32_t(thr[i]) - 1)));
#else
      const int32_t lanes[4] = {e, e + ea, e + eb, e + ea + eb};
      for (unsigned lane = 0; lane < 4; ++lane)
        if (lanes[lane] < thr[i]) mask &= ~(1u << lane);
#endif
    }
#if FFCOMPAT_X86
    unsigned mask = unsigned(_mm_movemask_ps(_mm_castsi128_ps(in)));
#endif
    if (t.xmax == t.xmin) mask &= 0x5;
    if (t.ymax == t.ymin) mask &= 0x3;
    for (int row = 0; mask; ++row, mask >>= 2) {
      const int py = t.ymin + row;
      if (!(mask & 3) || !bands.owns(py / kBandRows)) continue;
      if (!draw_span(py, t.xmin + ((mask & 1) ? 0 : 1), t.xmin + ((mask & 2) ? 1 : 0))) return;
    }
#if FFCOMPAT_X86
  } else if (ext_x < 31 * 256 && ext_y < 31 * 256 && wide_kernels()) {
    // Edge functions in 32 bits: at most 8x8 pixel centres (most triangles of a subdivided
    // sphere) by the box kernel, larger boxes in rows of sixteen pixels.
    int32_t edges[kEdgeFields];
    box_edges(t, edges);
    if (t.xmax - t.xmin < 8 && t.ymax - t.ymin < 8) {
      const BoxCoverage c = box_coverage({edges, 1}, bands);
      if (c.blocks && planes()) nonfinite = box_shade<D>(fb, {t.z, t.inv_w, 1}, t.xmin, t.ymin, depth_func, c);
    } else if (planes()) {
      nonfinite = rows_shade<D>(fb, {edges, 1}, {t.z, t.inv_w, 1}, bands, depth_func);
    }
  } else if (ext_x < 31 * 256 && ext_y < 31 * 256) {
    // Small (without AVX-512): edge functions relative to the box's first pixel centre fit in 32
    // bits, and four pixels of a row are tested at once; a row's covered pixels are contiguous.
    const int64_t ox = int64_t(t.xmin) * 256 + 128, oy = int64_t(t.ymin) * 256 + 128;
    int32_t e0[3], eb[3];
    __m128i step[3], row_lanes[3], limit[3];
    for (int i = 0; i < 3; ++i) {
      const int j = (i + 1) % 3, k = (i + 2) % 3;
      const int32_t dx = int32_t(t.x[k] - t.x[j]), dy = int32_t(t.y[k] - t.y[j]);
      const int32_t ea = -dy * 256;
      eb[i] = dx * 256;
      e0[i] = dx * int32_t(oy - t.y[j]) - dy * int32_t(ox - t.x[j]);
      row_lanes[i] = _mm_set_epi32(3 * ea, 2 * ea, ea, 0);
      step[i] = _mm_set1_epi32(4 * ea);
      limit[i] = _mm_set1_epi32(int32_t(thr[i]) - 1);  // e >= thr  as  e > thr - 1
    }
    const int width = t.xmax - t.xmin + 1;
    const uint32_t keep = width >= 32 ? ~0u : (1u << width) - 1;
    for (int by = first_band; by * kBandRows <= t.ymax; by += bands.count) {
      const int row_end = std::min(by * kBandRows + kBandRows - 1, t.ymax);
      for (int py = std::max(by * kBandRows, t.ymin); py <= row_end; ++py) {
        const int32_t dy = py - t.ymin;
        __m128i v[3];
        for (int i = 0; i < 3; ++i) v[i] = _mm_add_epi32(_mm_set1_epi32(e0[i] + eb[i] * dy), row_lanes[i]);
        uint32_t mask = 0;
        for (int chunk = 0; chunk < width; chunk += 4) {
          const __m128i in = _mm_and_si128(_mm_and_si128(_mm_cmpgt_epi32(v[0], limit[0]), _mm_cmpgt_epi32(v[1], limit[1])),
                                           _mm_cmpgt_epi32(v[2], limit[2]));
          mask |= uint32_t(_mm_movemask_ps(_mm_castsi128_ps(in))) << chunk;
          for (int i = 0; i < 3; ++i) v[i] = _mm_add_epi32(v[i], step[i]);
        }
        mask &= keep;
        if (!mask) continue;
        if (!draw_span(py, t.xmin + __builtin_ctz(mask), t.xmin + 31 - __builtin_clz(mask))) return;
      }
    }
#endif
  } else {
    // Without SSE2 also the small ones: the same pixels, found by another exact computation.
    // Large: each row's span is solved for in 64 bits, not searched.
    int64_t a[3], b[3], c[3];
    for (int i = 0; i < 3; ++i) {
      const int j = (i + 1) % 3, k = (i + 2) % 3;
      a[i] = -(t.y[k] - t.y[j]) * 256;  // per pixel in x
      b[i] = (t.x[k] - t.x[j]) * 256;   // per pixel in y
      c[i] = (t.x[k] - t.x[j]) * (128 - t.y[j]) - (t.y[k] - t.y[j]) * (128 - t.x[j]);
    }
    for (int by = first_band; by * kBandRows <= t.ymax; by += bands.count) {
      const int row_end = std::min(by * kBandRows + kBandRows - 1, t.ymax);
      for (int py = std::max(by * kBandRows, t.ymin); py <= row_end; ++py) {
        int lo = t.xmin, hi = t.xmax;
        for (int i = 0; i < 3; ++i) span(c[i] + b[i] * py, a[i], thr[i], lo, hi);
        if (lo > hi) continue;
        if (!draw_span(py, lo, hi)) return;
      }
    }
  }
  if (nonfinite) g_nonfinite_fragments.fetch_add(nonfinite, std::memory_order_relaxed);
}

// The same for a run-time depth function.
template <typename Planes>
void rasterize(Framebuffer& fb, Triangle& t, const State& s, const Bands& bands, Planes&& planes) {
  switch (depth_mode(s)) {
    case kNoDepth: return rasterize<kNoDepth>(fb, t, s.depth_func, bands, planes);
    case kLess: return rasterize<kLess>(fb, t, s.depth_func, bands, planes);
    case kLequal: return rasterize<kLequal>(fb, t, s.depth_func, bands, planes);
    case kAnyDepth: return rasterize<kAnyDepth>(fb, t, s.depth_func, bands, planes);
  }
}

}  // namespace ffc::raster::detail
