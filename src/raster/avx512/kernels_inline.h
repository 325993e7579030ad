// The kernels' parts, inline: coverage of a box of at most 8x8 pixel centres and its blocks'
// depth and colour, the vector forms of pixel_rules.h (depth24x16, pack_rgba). Included only where
// AVX-512 code is compiled (after #pragma GCC target "avx2,avx512f,avx512vl,avx512dq"): by
// kernels.cpp, and by triangle_list_avx512.cpp so that its draw loop draws a triangle without a call.
#pragma once
#include <immintrin.h>

#include <array>
#include <cstddef>

#include "raster/avx512/kernels.h"
#include "raster/row_loop.h"

namespace ffc::raster::detail {

namespace {

// Lane k of a block: pixel (x + dx[k], y + dy[k]); 8x2 blocks for a box wider than 4, else 4x4.
__m512i lane_dx(bool wide) { return _mm512_and_si512(_mm512_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15), _mm512_set1_epi32(wide ? 7 : 3)); }
__m512i lane_dy(bool wide) { return _mm512_srli_epi32(_mm512_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15), wide ? 3 : 2); }

// depth24 of sixteen floats (the same instructions: max, min, multiply, round half to even).
__m512i depth24x16(__m512 z) {
  const __m512 c = _mm512_min_ps(_mm512_max_ps(z, _mm512_setzero_ps()), _mm512_set1_ps(1.0f));  // NaN: 0
  return _mm512_cvtps_epi32(_mm512_mul_ps(c, _mm512_set1_ps(16777215.0f)));
}

// depth_at of sixteen pixels: columns x, rows counted from the top y_down.
__m512 depth_at16(__m512 z0, __m512 z1, __m512 z2, __m512 x, __m512 y_down) {
  return _mm512_fmadd_ps(z2, y_down, _mm512_fmadd_ps(z1, x, z0));
}

// A block's rows in a buffer of 32-bit pixels: two of eight lanes (8x2) or four of four (4x4).
// Lanes outside the mask are neither read (they may be another thread's rows, or past the
// buffer) nor written.
template <bool Wide>
__m512i load_rows(const int* at, size_t pitch, __mmask16 m) {
  if constexpr (Wide)
    return _mm512_inserti64x4(_mm512_castsi256_si512(_mm256_maskz_loadu_epi32(__mmask8(m), at)),
                              _mm256_maskz_loadu_epi32(__mmask8(m >> 8), at + pitch), 1);
  // A four-lane operation reads the low four bits of its mask.
  __m512i v = _mm512_castsi128_si512(_mm_maskz_loadu_epi32(__mmask8(m), at));
  v = _mm512_inserti32x4(v, _mm_maskz_loadu_epi32(__mmask8(m >> 4), at + pitch), 1);
  v = _mm512_inserti32x4(v, _mm_maskz_loadu_epi32(__mmask8(m >> 8), at + 2 * pitch), 2);
  return _mm512_inserti32x4(v, _mm_maskz_loadu_epi32(__mmask8(m >> 12), at + 3 * pitch), 3);
}
template <bool Wide>
void store_rows(int* at, size_t pitch, __mmask16 m, __m512i v) {
  if constexpr (Wide) {
    _mm256_mask_storeu_epi32(at, __mmask8(m), _mm512_castsi512_si256(v));
    _mm256_mask_storeu_epi32(at + pitch, __mmask8(m >> 8), _mm512_extracti64x4_epi64(v, 1));
  } else {
    _mm_mask_storeu_epi32(at, __mmask8(m), _mm512_castsi512_si128(v));
    _mm_mask_storeu_epi32(at + pitch, __mmask8(m >> 4), _mm512_extracti32x4_epi32(v, 1));
    _mm_mask_storeu_epi32(at + 2 * pitch, __mmask8(m >> 8), _mm512_extracti32x4_epi32(v, 2));
    _mm_mask_storeu_epi32(at + 3 * pitch, __mmask8(m >> 12), _mm512_extracti32x4_epi32(v, 3));
  }
}

// The lanes of `lanes` whose depth z passes against the stored one (24-bit values: the signed
// comparisons are the unsigned ones).
template <DepthMode D>
__mmask16 depth_test(__mmask16 lanes, __m512i z, __m512i stored, GLenum depth_func) {
  if constexpr (D == kNoDepth) return lanes;
  if constexpr (D == kLess) return _mm512_mask_cmplt_epi32_mask(lanes, z, stored);
  if constexpr (D == kLequal) return _mm512_mask_cmple_epi32_mask(lanes, z, stored);
  switch (depth_func) {
    case GL_NEVER: return 0;
    case GL_LESS: return _mm512_mask_cmplt_epi32_mask(lanes, z, stored);
    case GL_EQUAL: return _mm512_mask_cmpeq_epi32_mask(lanes, z, stored);
    case GL_LEQUAL: return _mm512_mask_cmple_epi32_mask(lanes, z, stored);
    case GL_GREATER: return _mm512_mask_cmpgt_epi32_mask(lanes, z, stored);
    case GL_NOTEQUAL: return _mm512_mask_cmpneq_epi32_mask(lanes, z, stored);
    case GL_GEQUAL: return _mm512_mask_cmpge_epi32_mask(lanes, z, stored);
    default: return lanes;
  }
}

// Sixteen pixels' RGBA8 from colour / w and 1 / (1/w): multiplied, clamped (a NaN becomes 0),
// scaled, rounded half to even (the default), a byte a channel. `bad`: lanes with a channel not
// finite before the clamp.
__m512i pack_rgba(const __m512 (&over_w)[4], __m512 inv, __mmask16& bad) {
  const __m512 zero = _mm512_setzero_ps(), one = _mm512_set1_ps(1), k255 = _mm512_set1_ps(255);
  __m512i rgba = _mm512_setzero_si512();
  bad = 0;
  for (int k = 0; k < 4; ++k) {
    const __m512 v = _mm512_mul_ps(over_w[k], inv);
    bad |= _mm512_fpclass_ps_mask(v, 0x99);  // NaN or infinity
    const __m512i q = _mm512_cvtps_epi32(_mm512_mul_ps(_mm512_min_ps(_mm512_max_ps(v, zero), one), k255));
    rgba = _mm512_or_si512(rgba, _mm512_slli_epi32(q, unsigned(8 * k)));
  }
  return rgba;
}

template <DepthMode D, bool Wide>
__attribute__((always_inline)) inline uint64_t shade(Framebuffer& fb, const KernelPlanes& p, int xmin, int ymin, GLenum depth_func, const BoxCoverage& c) {
  constexpr int kRows = Wide ? 2 : 4;  // per block
  // Centres: X = x + 0.5 and Y = y + 0.5 exactly, as lane offsets added to the block's corner.
  const __m512i dy = lane_dy(Wide);
  const __m512 fy_off = _mm512_add_ps(_mm512_cvtepi32_ps(dy), _mm512_set1_ps(0.5f));
  // The parts of (p0 + px X) + py Y that depend on X only, once for the box.
  const int n = p.stride;
  const __m512i px = _mm512_add_epi32(_mm512_set1_epi32(xmin), lane_dx(Wide));
  const __m512 fx = _mm512_add_ps(_mm512_cvtepi32_ps(px), _mm512_set1_ps(0.5f));
  const __m512 z0 = _mm512_set1_ps(p.z[0]), z1 = _mm512_set1_ps(p.z[n]), z2 = _mm512_set1_ps(p.z[2 * n]);
  const __m512 zcol = _mm512_cvtepi32_ps(px);  // depth: pixel columns, rows from the top
  const __m512 zrow_off = _mm512_cvtepi32_ps(_mm512_sub_epi32(_mm512_set1_epi32(fb.height - 1 - ymin), dy));
  const __m512 iwx = _mm512_add_ps(_mm512_set1_ps(p.f[0]), _mm512_mul_ps(_mm512_set1_ps(p.f[n]), fx));
  const __m512 iw2 = _mm512_set1_ps(p.f[2 * n]);
  __m512 cx[4], cy[4];
  for (int k = 0; k < 4; ++k) {
    cx[k] = _mm512_add_ps(_mm512_set1_ps(p.f[(3 + k) * n]), _mm512_mul_ps(_mm512_set1_ps(p.f[(7 + k) * n]), fx));
    cy[k] = _mm512_set1_ps(p.f[(11 + k) * n]);
  }
  const size_t pitch = size_t(fb.width);
  uint64_t nonfinite = 0;
  for (unsigned blocks = c.blocks; blocks; blocks &= blocks - 1) {
    const int b = __builtin_ctz(blocks);
    const int y = ymin + b * kRows;
    const size_t at = size_t(y) * pitch + size_t(xmin);
    const __mmask16 lanes = c.lanes[b];
    __mmask16 pass = lanes;
    if constexpr (D != kNoDepth) {
      const __m512 y_down = _mm512_sub_ps(zrow_off, _mm512_set1_ps(float(y - ymin)));  // exact: small integers
      const __m512i z = depth24x16(depth_at16(z0, z1, z2, zcol, y_down));
      int* const zp = reinterpret_cast<int*>(fb.depth.data() + at);
      const __m512i stored = load_rows<Wide>(zp, pitch, lanes);
      pass = depth_test<D>(lanes, z, stored, depth_func);
      store_rows<Wide>(zp, pitch, pass, z);
      if (!pass) continue;  // hidden: no colour to compute (about a third of a sphere's blocks)
    }
    const __m512 fy = _mm512_add_ps(_mm512_set1_ps(float(y)), fy_off);
    const __m512 inv = _mm512_div_ps(_mm512_set1_ps(1), _mm512_add_ps(iwx, _mm512_mul_ps(iw2, fy)));
    __m512 over_w[4];
    for (int k = 0; k < 4; ++k) over_w[k] = _mm512_add_ps(cx[k], _mm512_mul_ps(cy[k], fy));
    __mmask16 bad;
    const __m512i rgba = pack_rgba(over_w, inv, bad);
    nonfinite += unsigned(__builtin_popcount(unsigned(bad & pass)));
    store_rows<Wide>(reinterpret_cast<int*>(fb.color.data()) + at, pitch, pass, rgba);
  }
  return nonfinite;
}

// Box row r's lanes in a block, from a bit per row: 16-bit masks for 4 rows of 4 (index: 4 row
// bits) or 2 rows of 8 (index: 2 row bits).
constexpr std::array<uint16_t, 16> kRowLanes4 = [] {
  std::array<uint16_t, 16> t{};
  for (unsigned r = 0; r < 16; ++r)
    for (unsigned k = 0; k < 4; ++k) t[r] |= uint16_t((r >> k & 1) * (0xFu << (4 * k)));
  return t;
}();
constexpr uint16_t kRowLanes8[4] = {0x0000, 0x00FF, 0xFF00, 0xFFFF};

__attribute__((always_inline)) inline BoxCoverage coverage(const KernelEdges& t, const Bands& bands) {
  BoxCoverage c;
  const int xmin = t(kXmin), ymin = t(kYmin), ymax = t(kYmax), w = t(kXmax) - xmin + 1, h = ymax - ymin + 1;
  c.wide = w > 4;
  // Rows of the box in this thread's bands (a box of 8 rows meets at most two bands).
  const int b0 = ymin / kBandRows, b1 = ymax / kBandRows;
  const int split = b0 == b1 ? h : (b0 + 1) * kBandRows - ymin;  // rows in the first band
  const unsigned first = (1u << split) - 1, all = (1u << h) - 1;
  const unsigned rows = (bands.owns(b0) ? first : 0) | (bands.owns(b1) ? all & ~first : 0);
  const unsigned cols = c.wide ? ((1u << w) - 1) * 0x0101 : ((1u << w) - 1) * 0x1111;
  const __m512i dx = lane_dx(c.wide), dy = lane_dy(c.wide);
  auto at = [&](int i) {  // edge i's function at the lanes of the first block
    return _mm512_add_epi32(_mm512_set1_epi32(t(kE0 + i)), _mm512_add_epi32(_mm512_mullo_epi32(_mm512_set1_epi32(t(kPerX + i)), dx),
                                                                            _mm512_mullo_epi32(_mm512_set1_epi32(t(kPerY + i)), dy)));
  };
  const unsigned shift = c.wide ? 1 : 2;  // log2 of the rows per block
  auto step = [&](int i) { return _mm512_set1_epi32(t(kPerY + i) << shift); };
  __m512i e0 = at(0), e1 = at(1), e2 = at(2);
  const __m512i s0 = step(0), s1 = step(1), s2 = step(2);
  const __m512i l0 = _mm512_set1_epi32(t(kLimit)), l1 = _mm512_set1_epi32(t(kLimit + 1)), l2 = _mm512_set1_epi32(t(kLimit + 2));
  c.blocks = 0;
  const int blocks = (h + (1 << shift) - 1) >> shift;
  for (int b = 0; b < blocks; ++b) {
    const unsigned box = cols & (c.wide ? kRowLanes8[rows >> (2 * b) & 3] : kRowLanes4[rows >> (4 * b) & 15]);
    const unsigned lanes = _mm512_mask_cmpgt_epi32_mask(_mm512_mask_cmpgt_epi32_mask(_mm512_cmpgt_epi32_mask(e0, l0), e1, l1), e2, l2) & box;
    c.lanes[b] = uint16_t(lanes);
    c.blocks |= unsigned(lanes != 0) << b;
    e0 = _mm512_add_epi32(e0, s0), e1 = _mm512_add_epi32(e1, s1), e2 = _mm512_add_epi32(e2, s2);
  }
  return c;
}

}  // namespace

// Coverage, then depth and colour, for planes known to be within float.
template <DepthMode D>
__attribute__((always_inline)) inline uint64_t box_draw_inline(Framebuffer& fb, const KernelEdges& e, const KernelPlanes& p,
                                                                const Bands& bands, GLenum depth_func) {
  const BoxCoverage c = coverage(e, bands);
  if (!c.blocks) return 0;
  return c.wide ? shade<D, true>(fb, p, e(kXmin), e(kYmin), depth_func, c) : shade<D, false>(fb, p, e(kXmin), e(kYmin), depth_func, c);
}

}  // namespace ffc::raster::detail
