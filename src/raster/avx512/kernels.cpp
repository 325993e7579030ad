// The kernels of kernels.h, built for AVX-512 (the CPU is asked at run time), and the switch that
// turns them on.
#include "raster/avx512/kernels.h"

#if FFCOMPAT_X86  // the whole file

// GCC 12's AVX-512 headers start some results from _mm512_undefined_*, which -Wuninitialized
// reports wherever they are inlined.
#pragma GCC diagnostic ignored "-Wuninitialized"
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"

#include <immintrin.h>

#include "raster/row_loop.h"

#include <algorithm>
#include <array>
#include <cstdlib>
#include <optional>
#include <cstddef>

namespace ffc::raster::detail {

namespace {
bool cpu_has_kernel_isa() { return __builtin_cpu_supports("avx2") && __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512vl") &&
         __builtin_cpu_supports("avx512dq"); }
}  // namespace

// FFCOMPAT_SCALAR=1 in the environment keeps the portable loops (to compare pictures and speed).
bool g_wide_kernels = cpu_has_kernel_isa() && !std::getenv("FFCOMPAT_SCALAR");
void set_wide_kernels(bool on) { g_wide_kernels = on && cpu_has_kernel_isa(); }

static_assert(offsetof(Triangle, cy) + 4 * sizeof(float) == offsetof(Triangle, inv_w) + kPlaneFloats * sizeof(float),
              "Triangle's planes are read as one array of floats");

void kernel_edges(const Triangle& t, int32_t (&out)[kEdgeFields]) {
  out[kXmin] = t.xmin, out[kYmin] = t.ymin, out[kXmax] = t.xmax, out[kYmax] = t.ymax;
  for (int i = 0; i < 3; ++i) {
    const EdgeFunction e = edge_function(t, i, t.xmin, t.ymin);
    out[kE0 + i] = int32_t(e.at), out[kPerX + i] = int32_t(e.per_x), out[kPerY + i] = int32_t(e.per_y);
    out[kLimit + i] = int32_t(e.limit) - 1;  // e >= limit  as  e > limit - 1
  }
}

}  // namespace ffc::raster::detail

#pragma GCC push_options
#pragma GCC target("avx2,avx512f,avx512vl,avx512dq")
#include "raster/avx512/kernels_inline.h"

namespace ffc::raster::detail {

BoxCoverage box_coverage(const KernelEdges& t, const Bands& bands) { return coverage(t, bands); }

template <DepthMode D>
uint64_t box_shade(Framebuffer& fb, const KernelPlanes& p, int xmin, int ymin, GLenum depth_func, const BoxCoverage& c) {
  return c.wide ? shade<D, true>(fb, p, xmin, ymin, depth_func, c) : shade<D, false>(fb, p, xmin, ymin, depth_func, c);
}

namespace {

// A triangle's planes broadcast for rows of sixteen pixels; per row, py Y once.
struct RowPlanes {
  __m512 z0, z1, z2;
  __m512 iw0, iw1, c0[4], cx[4];
  float iw2, cy[4];
  explicit RowPlanes(const KernelPlanes& p) {
    const int n = p.stride;
    z0 = _mm512_set1_ps(p.z[0]), z1 = _mm512_set1_ps(p.z[n]), z2 = _mm512_set1_ps(p.z[2 * n]);
    iw0 = _mm512_set1_ps(p.f[0]), iw1 = _mm512_set1_ps(p.f[n]), iw2 = p.f[2 * n];
    for (int k = 0; k < 4; ++k)
      c0[k] = _mm512_set1_ps(p.f[(3 + k) * n]), cx[k] = _mm512_set1_ps(p.f[(7 + k) * n]), cy[k] = p.f[(11 + k) * n];
  }
};
struct Row {
  __m512 y_down;  // the row counted from the top, for depth
  __m512 iwy, cy[4];
  int* zrow;
  int* crow;
  Row(const RowPlanes& p, Framebuffer& fb, int y) {
    const double row = double(y) + 0.5;
    const float frow = float(row);
    y_down = _mm512_set1_ps(float(fb.height - 1 - y)), iwy = _mm512_set1_ps(p.iw2 * frow);
    for (int k = 0; k < 4; ++k) cy[k] = _mm512_set1_ps(p.cy[k] * frow);
    zrow = reinterpret_cast<int*>(fb.depth.data() + size_t(y) * size_t(fb.width));
    crow = reinterpret_cast<int*>(fb.color.data()) + size_t(y) * size_t(fb.width);
  }
};

// Pixels x + k of a row for the lanes k set in `lanes`: depth test, colour, written through the
// masks. Returns the drawn pixels whose colour was not finite.
template <DepthMode D>
uint64_t segment(const RowPlanes& p, const Row& r, int x, __mmask16 lanes, GLenum depth_func) {
  const __m512i px = _mm512_add_epi32(_mm512_set1_epi32(x), _mm512_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15));
  __mmask16 pass = lanes;
  if constexpr (D != kNoDepth) {
    const __m512i z = depth24x16(depth_at16(p.z0, p.z1, p.z2, _mm512_cvtepi32_ps(px), r.y_down));
    const __m512i stored = _mm512_maskz_loadu_epi32(lanes, r.zrow + x);
    pass = depth_test<D>(lanes, z, stored, depth_func);
    _mm512_mask_storeu_epi32(r.zrow + x, pass, z);
    if (!pass) return 0;
  }
  const __m512 fx = _mm512_add_ps(_mm512_cvtepi32_ps(px), _mm512_set1_ps(0.5f));
  const __m512 inv = _mm512_div_ps(_mm512_set1_ps(1), _mm512_add_ps(_mm512_add_ps(p.iw0, _mm512_mul_ps(p.iw1, fx)), r.iwy));
  __m512 over_w[4];
  for (int k = 0; k < 4; ++k) over_w[k] = _mm512_add_ps(_mm512_add_ps(p.c0[k], _mm512_mul_ps(p.cx[k], fx)), r.cy[k]);
  __mmask16 bad;
  const __m512i rgba = pack_rgba(over_w, inv, bad);
  _mm512_mask_storeu_epi32(r.crow + x, pass, rgba);
  return unsigned(__builtin_popcount(unsigned(bad & pass)));
}

}  // namespace

template <DepthMode D>
uint64_t span_shade(Framebuffer& fb, const KernelPlanes& p, int y, int lo, int hi, GLenum depth_func) {
  const RowPlanes planes(p);
  const Row row(planes, fb, y);
  uint64_t nonfinite = 0;
  for (int x = lo; x <= hi; x += 16)
    nonfinite += segment<D>(planes, row, x, hi - x >= 15 ? __mmask16(0xFFFF) : __mmask16((1u << (hi - x + 1)) - 1), depth_func);
  return nonfinite;
}

template <DepthMode D>
uint64_t rows_shade(Framebuffer& fb, const KernelEdges& e, const KernelPlanes& p, const Bands& bands, GLenum depth_func) {
  const RowPlanes planes(p);
  const int xmin = e(kXmin), ymin = e(kYmin), xmax = e(kXmax), ymax = e(kYmax);
  const __m512i lane = _mm512_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15);
  __m512i at_x[3], per_x16[3], limit[3];  // edge values at lanes x = xmin + k, row ymin
  for (int i = 0; i < 3; ++i) {
    at_x[i] = _mm512_add_epi32(_mm512_set1_epi32(e(kE0 + i)), _mm512_mullo_epi32(_mm512_set1_epi32(e(kPerX + i)), lane));
    per_x16[i] = _mm512_set1_epi32(e(kPerX + i) * 16);
    limit[i] = _mm512_set1_epi32(e(kLimit + i));
  }
  uint64_t nonfinite = 0;
  for (int by = bands.next[size_t(ymin / kBandRows)]; by * kBandRows <= ymax; by += bands.count) {
    const int row_end = std::min(by * kBandRows + kBandRows - 1, ymax);
    for (int y = std::max(by * kBandRows, ymin); y <= row_end; ++y) {
      std::optional<Row> row;
      __m512i v[3];
      for (int i = 0; i < 3; ++i) v[i] = _mm512_add_epi32(at_x[i], _mm512_set1_epi32(e(kPerY + i) * (y - ymin)));
      for (int x = xmin; x <= xmax; x += 16) {
        __mmask16 in = _mm512_mask_cmpgt_epi32_mask(_mm512_mask_cmpgt_epi32_mask(_mm512_cmpgt_epi32_mask(v[0], limit[0]), v[1], limit[1]),
                                                    v[2], limit[2]);
        if (xmax - x < 15) in &= __mmask16((1u << (xmax - x + 1)) - 1);
        for (int i = 0; i < 3; ++i) v[i] = _mm512_add_epi32(v[i], per_x16[i]);
        if (!in) continue;
        if (!row) row.emplace(planes, fb, y);
        nonfinite += segment<D>(planes, *row, x, in, depth_func);
      }
    }
  }
  return nonfinite;
}

template uint64_t rows_shade<kNoDepth>(Framebuffer&, const KernelEdges&, const KernelPlanes&, const Bands&, GLenum);
template uint64_t rows_shade<kLess>(Framebuffer&, const KernelEdges&, const KernelPlanes&, const Bands&, GLenum);
template uint64_t rows_shade<kLequal>(Framebuffer&, const KernelEdges&, const KernelPlanes&, const Bands&, GLenum);
template uint64_t rows_shade<kAnyDepth>(Framebuffer&, const KernelEdges&, const KernelPlanes&, const Bands&, GLenum);
template uint64_t span_shade<kNoDepth>(Framebuffer&, const KernelPlanes&, int, int, int, GLenum);
template uint64_t span_shade<kLess>(Framebuffer&, const KernelPlanes&, int, int, int, GLenum);
template uint64_t span_shade<kLequal>(Framebuffer&, const KernelPlanes&, int, int, int, GLenum);
template uint64_t span_shade<kAnyDepth>(Framebuffer&, const KernelPlanes&, int, int, int, GLenum);
template uint64_t box_shade<kNoDepth>(Framebuffer&, const KernelPlanes&, int, int, GLenum, const BoxCoverage&);
template uint64_t box_shade<kLess>(Framebuffer&, const KernelPlanes&, int, int, GLenum, const BoxCoverage&);
template uint64_t box_shade<kLequal>(Framebuffer&, const KernelPlanes&, int, int, GLenum, const BoxCoverage&);
template uint64_t box_shade<kAnyDepth>(Framebuffer&, const KernelPlanes&, int, int, GLenum, const BoxCoverage&);

}  // namespace ffc::raster::detail

#pragma GCC pop_options

#endif  // FFCOMPAT_X86
