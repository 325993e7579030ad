// The triangle lists' AVX-512 code (run where raster::detail::wide_kernels()): binning sixteen
// triangles at a time, and drawing eight at a time, set up together (setup8) for the box kernel.
// Each is held bit for bit to the portable code of triangle_list.cpp and to row_loop.h.
#include "raster/triangle_list_parts.h"

#if FFCOMPAT_X86  // the whole file

// GCC 12's AVX-512 headers start some results from _mm512_undefined_*, which -Wuninitialized
// reports wherever they are inlined.
#pragma GCC diagnostic ignored "-Wuninitialized"
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"

#include <immintrin.h>

#include <algorithm>

#pragma GCC push_options
#pragma GCC target("avx2,avx512f,avx512vl,avx512dq")
#include "raster/avx512/kernels_inline.h"

namespace ffc::raster::detail {

namespace {

// Eight triangles of a list set up at once, a triangle a lane, for the box kernel (raster/avx512/kernels.h):
// the state draws smooth colour without secondary colour, culling or two-sided lighting. Bit for
// bit what setup_edges, kernel_edges and smooth_planes give one triangle.
struct Setup8 {
  alignas(64) int32_t edges[detail::kEdgeFields][8];
  alignas(64) float z[3][8];  // depth_plane's
  alignas(64) float f[detail::kPlaneFloats][8];
  unsigned box;   // lanes for the box kernel: box at most 8x8, vertex extents below 31 pixels
  unsigned none;  // lanes that cover no pixel centre
  unsigned ok;    // lanes whose planes are within float (the others are not drawn)
  unsigned tiny;  // box lanes of at most 2x2 pixel centres, their coverage below
  alignas(32) int32_t cover[8];  // of a tiny lane: bits for (0,0) (1,0) (0,1) (1,1) from the box's corner
};


// Rows of eight floats made columns.
void transpose8(__m256 (&r)[8]) {
  __m256 t[8], u[8];
  for (int i = 0; i < 4; ++i) t[2 * i] = _mm256_unpacklo_ps(r[2 * i], r[2 * i + 1]), t[2 * i + 1] = _mm256_unpackhi_ps(r[2 * i], r[2 * i + 1]);
  for (int i = 0; i < 2; ++i) {
    u[4 * i + 0] = _mm256_shuffle_ps(t[4 * i], t[4 * i + 2], _MM_SHUFFLE(1, 0, 1, 0));
    u[4 * i + 1] = _mm256_shuffle_ps(t[4 * i], t[4 * i + 2], _MM_SHUFFLE(3, 2, 3, 2));
    u[4 * i + 2] = _mm256_shuffle_ps(t[4 * i + 1], t[4 * i + 3], _MM_SHUFFLE(1, 0, 1, 0));
    u[4 * i + 3] = _mm256_shuffle_ps(t[4 * i + 1], t[4 * i + 3], _MM_SHUFFLE(3, 2, 3, 2));
  }
  for (int i = 0; i < 4; ++i) r[i] = _mm256_permute2f128_ps(u[i], u[i + 4], 0x20), r[i + 4] = _mm256_permute2f128_ps(u[i], u[i + 4], 0x31);
}

// corner[c][lane]: the triangle's vertices, all mapped (lanes past the chunk repeat one).
void setup8(const ListVertices& vs, const uint32_t (&corner)[3][8], int fb_w, int fb_h, Setup8& out) {
  // Snapped positions: box, extents, area.
  __m256i sx[3], sy[3];
  for (int c = 0; c < 3; ++c) {
    const __m512i xy = _mm512_i32gather_epi64(_mm256_load_si256(reinterpret_cast<const __m256i*>(corner[c])), vs.snapped.data(), 8);
    sx[c] = _mm512_cvtepi64_epi32(xy), sy[c] = _mm512_cvtepi64_epi32(_mm512_srli_epi64(xy, 32));
  }
  const __m256i xlo = _mm256_min_epi32(sx[0], _mm256_min_epi32(sx[1], sx[2])), xhi = _mm256_max_epi32(sx[0], _mm256_max_epi32(sx[1], sx[2]));
  const __m256i ylo = _mm256_min_epi32(sy[0], _mm256_min_epi32(sy[1], sy[2])), yhi = _mm256_max_epi32(sy[0], _mm256_max_epi32(sy[1], sy[2]));
  const __m256i zero = _mm256_setzero_si256(), k127 = _mm256_set1_epi32(127), k128 = _mm256_set1_epi32(128);
  // First pixel centre at or after the low end, last at or before the high end, in the framebuffer.
  const __m256i xmin = _mm256_max_epi32(zero, _mm256_srai_epi32(_mm256_add_epi32(xlo, k127), 8));
  const __m256i ymin = _mm256_max_epi32(zero, _mm256_srai_epi32(_mm256_add_epi32(ylo, k127), 8));
  const __m256i xmax = _mm256_min_epi32(_mm256_set1_epi32(fb_w - 1), _mm256_srai_epi32(_mm256_sub_epi32(xhi, k128), 8));
  const __m256i ymax = _mm256_min_epi32(_mm256_set1_epi32(fb_h - 1), _mm256_srai_epi32(_mm256_sub_epi32(yhi, k128), 8));
  const __mmask8 empty = _mm256_cmpgt_epi32_mask(xmin, xmax) | _mm256_cmpgt_epi32_mask(ymin, ymax);
  const __m256i seven = _mm256_set1_epi32(7), limit = _mm256_set1_epi32(31 * 256);
  const __mmask8 small = _mm256_cmple_epi32_mask(_mm256_sub_epi32(xmax, xmin), seven) & _mm256_cmple_epi32_mask(_mm256_sub_epi32(ymax, ymin), seven) &
                         _mm256_cmplt_epu32_mask(_mm256_sub_epi32(xhi, xlo), limit) & _mm256_cmplt_epu32_mask(_mm256_sub_epi32(yhi, ylo), limit) & ~empty;
  // 32 bits hold the area of a small triangle.
  const __m256i area = _mm256_sub_epi32(_mm256_mullo_epi32(_mm256_sub_epi32(sx[1], sx[0]), _mm256_sub_epi32(sy[2], sy[0])),
                                        _mm256_mullo_epi32(_mm256_sub_epi32(sx[2], sx[0]), _mm256_sub_epi32(sy[1], sy[0])));
  const __mmask8 flat = _mm256_cmpeq_epi32_mask(area, zero);
  out.none = empty | (small & flat);
  out.box = small & ~flat;
  // Counter-clockwise: vertices 1 and 2 exchanged where the area is negative.
  const __mmask8 swap = _mm256_cmplt_epi32_mask(area, zero);
  auto exchange = [&](__m256i& a, __m256i& b) {
    const __m256i a2 = _mm256_mask_blend_epi32(swap, a, b);
    b = _mm256_mask_blend_epi32(swap, b, a), a = a2;
  };
  exchange(sx[1], sx[2]), exchange(sy[1], sy[2]);
  _mm256_store_si256(reinterpret_cast<__m256i*>(out.edges[detail::kXmin]), xmin);
  _mm256_store_si256(reinterpret_cast<__m256i*>(out.edges[detail::kYmin]), ymin);
  _mm256_store_si256(reinterpret_cast<__m256i*>(out.edges[detail::kXmax]), xmax);
  _mm256_store_si256(reinterpret_cast<__m256i*>(out.edges[detail::kYmax]), ymax);
  const __m256i ox = _mm256_add_epi32(_mm256_slli_epi32(xmin, 8), k128), oy = _mm256_add_epi32(_mm256_slli_epi32(ymin, 8), k128);
  __mmask8 corner_in[4] = {0xFF, 0xFF, 0xFF, 0xFF};
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3, k = (i + 2) % 3;
    const __m256i ex = _mm256_sub_epi32(sx[k], sx[j]), ey = _mm256_sub_epi32(sy[k], sy[j]);
    const __m256i e0 = _mm256_sub_epi32(_mm256_mullo_epi32(ex, _mm256_sub_epi32(oy, sy[j])), _mm256_mullo_epi32(ey, _mm256_sub_epi32(ox, sx[j])));
    // pixel_rules.h's owns_centres_on_edge, lane by lane.
    const __mmask8 owns = _mm256_cmplt_epi32_mask(ey, zero) | (_mm256_cmpeq_epi32_mask(ey, zero) & _mm256_cmpgt_epi32_mask(ex, zero));
    _mm256_store_si256(reinterpret_cast<__m256i*>(out.edges[detail::kE0 + i]), e0);
    _mm256_store_si256(reinterpret_cast<__m256i*>(out.edges[detail::kPerX + i]), _mm256_slli_epi32(_mm256_sub_epi32(zero, ey), 8));
    _mm256_store_si256(reinterpret_cast<__m256i*>(out.edges[detail::kPerY + i]), _mm256_slli_epi32(ex, 8));
    _mm256_store_si256(reinterpret_cast<__m256i*>(out.edges[detail::kLimit + i]), _mm256_mask_blend_epi32(owns, zero, _mm256_set1_epi32(-1)));
    // The box's four first centres, as box_coverage tests them (e > limit).
    const __m256i lim = _mm256_mask_blend_epi32(owns, zero, _mm256_set1_epi32(-1));
    const __m256i px = _mm256_slli_epi32(_mm256_sub_epi32(zero, ey), 8), py = _mm256_slli_epi32(ex, 8);
    corner_in[0] &= _mm256_cmpgt_epi32_mask(e0, lim);
    corner_in[1] &= _mm256_cmpgt_epi32_mask(_mm256_add_epi32(e0, px), lim);
    corner_in[2] &= _mm256_cmpgt_epi32_mask(_mm256_add_epi32(e0, py), lim);
    corner_in[3] &= _mm256_cmpgt_epi32_mask(_mm256_add_epi32(e0, _mm256_add_epi32(px, py)), lim);
  }
  const __mmask8 one_col = _mm256_cmpeq_epi32_mask(xmin, xmax), one_row = _mm256_cmpeq_epi32_mask(ymin, ymax);
  corner_in[1] &= ~one_col, corner_in[2] &= ~one_row, corner_in[3] &= ~(one_col | one_row);
  __m256i cover = zero;
  for (int k = 0; k < 4; ++k) cover = _mm256_mask_or_epi32(cover, corner_in[k], cover, _mm256_set1_epi32(1 << k));
  _mm256_store_si256(reinterpret_cast<__m256i*>(out.cover), cover);
  const __m256i k1 = _mm256_set1_epi32(1);
  out.tiny = out.box & _mm256_cmple_epi32_mask(_mm256_sub_epi32(xmax, xmin), k1) & _mm256_cmple_epi32_mask(_mm256_sub_epi32(ymax, ymin), k1);
  // Window positions and colours: a vertex a row, made a lane; then in double.
  __m512d v[3][8];  // x, y (GL's, up), z, w, r, g, b, a
  __m256 fx[3], fyd[3], fz[3];  // in float for depth, y counted down
  for (int c = 0; c < 3; ++c) {
    __m256 r[8];
    for (int lane = 0; lane < 8; ++lane) r[lane] = _mm256_load_ps(&vs.hot[corner[c][lane]].x);
    transpose8(r);
    fx[c] = r[0], fyd[c] = r[1], fz[c] = r[2];
    r[1] = _mm256_sub_ps(_mm256_set1_ps(float(fb_h)), r[1]);  // as map_float's GL y
    for (int a = 0; a < 8; ++a) v[c][a] = _mm512_cvtps_pd(r[a]);
  }
  {  // detail::depth_plane, lane by lane: llvmpipe's order is (0, 1, 2), or (1, 0, 2) where swapped
    const __m256 x0 = _mm256_mask_blend_ps(swap, fx[0], fx[1]), x1 = _mm256_mask_blend_ps(swap, fx[1], fx[0]), x2 = fx[2];
    const __m256 y0 = _mm256_mask_blend_ps(swap, fyd[0], fyd[1]), y1 = _mm256_mask_blend_ps(swap, fyd[1], fyd[0]), y2 = fyd[2];
    const __m256 z0 = _mm256_mask_blend_ps(swap, fz[0], fz[1]), z1 = _mm256_mask_blend_ps(swap, fz[1], fz[0]), z2 = fz[2];
    const __m256 half = _mm256_set1_ps(0.5f);
    const __m256 x0c = _mm256_sub_ps(x0, half), y0c = _mm256_sub_ps(y0, half);
    const __m256 dx01 = _mm256_sub_ps(x0, x1), dy01 = _mm256_sub_ps(y0, y1), dx20 = _mm256_sub_ps(x2, x0), dy20 = _mm256_sub_ps(y2, y0);
    const __m256 ooa = _mm256_div_ps(_mm256_set1_ps(1.0f), _mm256_sub_ps(_mm256_mul_ps(dx01, dy20), _mm256_mul_ps(dy01, dx20)));
    const __m256 dx20o = _mm256_mul_ps(dx20, ooa), dy20o = _mm256_mul_ps(dy20, ooa), dx01o = _mm256_mul_ps(dx01, ooa),
                 dy01o = _mm256_mul_ps(dy01, ooa);
    const __m256 da01 = _mm256_sub_ps(z0, z1), da20 = _mm256_sub_ps(z2, z0);
    const __m256 dzdx = _mm256_sub_ps(_mm256_mul_ps(da01, dy20o), _mm256_mul_ps(da20, dy01o));
    const __m256 dzdy = _mm256_sub_ps(_mm256_mul_ps(da20, dx01o), _mm256_mul_ps(da01, dx20o));
    _mm256_store_ps(out.z[0], _mm256_sub_ps(z0, _mm256_add_ps(_mm256_mul_ps(dzdx, x0c), _mm256_mul_ps(dzdy, y0c))));
    _mm256_store_ps(out.z[1], dzdx), _mm256_store_ps(out.z[2], dzdy);
  }
  for (int a = 0; a < 8; ++a) {
    const __m512d v1 = _mm512_mask_blend_pd(swap, v[1][a], v[2][a]);
    v[2][a] = _mm512_mask_blend_pd(swap, v[2][a], v[1][a]), v[1][a] = v1;
  }
  // PlaneSolver, lane by lane.
  const __m512d x0 = v[0][0], y0 = v[0][1];
  const __m512d x1 = _mm512_sub_pd(v[1][0], x0), y1 = _mm512_sub_pd(v[1][1], y0);
  const __m512d x2 = _mm512_sub_pd(v[2][0], x0), y2 = _mm512_sub_pd(v[2][1], y0);
  const __m512d det = _mm512_sub_pd(_mm512_mul_pd(x1, y2), _mm512_mul_pd(x2, y1));
  const __m512d one = _mm512_set1_pd(1);
  const __m512d inv = _mm512_maskz_div_pd(_mm512_cmp_pd_mask(det, _mm512_setzero_pd(), _CMP_NEQ_UQ), one, det);
  __m512d a[3][6];  // (depth apart), 1/w, r/w, g/w, b/w, a/w
  for (int c = 0; c < 3; ++c) {
    const __m512d iw = _mm512_div_pd(one, v[c][3]);
    a[c][1] = iw;
    for (int k = 0; k < 4; ++k) a[c][2 + k] = _mm512_mul_pd(v[c][4 + k], iw);
  }
  const __m256 fzero = _mm256_setzero_ps();
  __m256 probe = fzero;
  for (int q = 1; q < 6; ++q) {
    const __m512d d1 = _mm512_sub_pd(a[1][q], a[0][q]), d2 = _mm512_sub_pd(a[2][q], a[0][q]);
    const __m512d p1 = _mm512_mul_pd(_mm512_sub_pd(_mm512_mul_pd(d1, y2), _mm512_mul_pd(d2, y1)), inv);
    const __m512d p2 = _mm512_mul_pd(_mm512_sub_pd(_mm512_mul_pd(x1, d2), _mm512_mul_pd(x2, d1)), inv);
    const __m512d p0 = _mm512_sub_pd(_mm512_sub_pd(a[0][q], _mm512_mul_pd(p1, x0)), _mm512_mul_pd(p2, y0));
    const __m512d p[3] = {p0, p1, p2};
    for (int m = 0; m < 3; ++m) {
      const __m256 f = _mm512_cvtpd_ps(p[m]);
      probe = _mm256_add_ps(probe, _mm256_mul_ps(f, fzero));  // x * 0 is NaN unless x is finite
      _mm256_store_ps(out.f[q == 1 ? m : 3 + 4 * m + (q - 2)], f);
    }
  }
  out.ok = _mm256_cmp_ps_mask(probe, probe, _CMP_ORD_Q);
}

// The corners of the list entries [0, lanes) (lanes past them repeat the last), built and stored
// as whole vectors: setup8 loads them as vectors, which element-by-element stores would stall.
// Returns the lanes to clip. Indices in 31 bits (draw_bins_wide checks that they fit).
unsigned chunk_corners(const List& l, const uint32_t* entries, int lanes, uint32_t (&corner)[3][8]) {
  const __m256i lane = _mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7);
  const __m256i entry = _mm256_permutexvar_epi32(_mm256_min_epi32(lane, _mm256_set1_epi32(lanes - 1)),
                                                 _mm256_loadu_si256(reinterpret_cast<const __m256i*>(entries)));
  const __m256i tri = _mm256_and_si256(entry, _mm256_set1_epi32(int(~kClipped)));
  const __m256i first = _mm256_add_epi32(tri, _mm256_add_epi32(tri, tri));  // 3 tri
  for (int k = 0; k < 3; ++k) {
    const __m256i c = l.idx ? _mm256_i32gather_epi32(reinterpret_cast<const int*>(l.idx + k), first, 4)
                            : _mm256_add_epi32(first, _mm256_set1_epi32(int(3 * l.base) + k));
    _mm256_store_si256(reinterpret_cast<__m256i*>(corner[k]), c);
  }
  return _mm256_movepi32_mask(entry);
}

}  // namespace

// triangle_list_parts.h says what these two do.
size_t bin16(const List& l, size_t first, size_t last, int units, uint32_t** out) {
  static_assert((kBandRows & (kBandRows - 1)) == 0, "bands by a shift");
  constexpr int kShift = __builtin_ctz(kBandRows);
  const __m512i lane = _mm512_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15);
  const __m512i k127 = _mm512_set1_epi32(127), k128 = _mm512_set1_epi32(128), zero = _mm512_setzero_si512();
  const __m512i last_col = _mm512_set1_epi32(l.fb.width - 1), last_row = _mm512_set1_epi32(l.fb.height - 1);
  const __m512i not_mapped = _mm512_set1_epi32(kNotMapped), span = _mm512_set1_epi32(units - 1);
  const __m512 per_unit = _mm512_set1_ps(1.0f / float(units));
  // Corner k of lane i is index 3i + k of 48: from the first 32 by one permutation, the rest from
  // the last 16 by a second.
  __m512i from_ab[3], from_c[3];
  __mmask16 past_32[3];
  for (int k = 0; k < 3; ++k) {
    const __m512i at = _mm512_add_epi32(_mm512_mullo_epi32(lane, _mm512_set1_epi32(3)), _mm512_set1_epi32(k));
    from_ab[k] = at, from_c[k] = _mm512_sub_epi32(at, _mm512_set1_epi32(32));
    past_32[k] = _mm512_cmpge_epi32_mask(at, _mm512_set1_epi32(32));
  }
  const __m512i evens = _mm512_add_epi32(lane, lane), odds = _mm512_add_epi32(evens, _mm512_set1_epi32(1));
  const long long* snapped = reinterpret_cast<const long long*>(l.vs.snapped.data());
  size_t tri = first;
  for (; tri + 16 <= last; tri += 16) {
    __m512i x[3], y[3];
    for (int k = 0; k < 3; ++k) {
      __m512i c;
      if (l.idx) {
        const uint32_t* p = l.idx + 3 * tri;
        c = _mm512_permutex2var_epi32(_mm512_loadu_si512(p), from_ab[k], _mm512_loadu_si512(p + 16));
        c = _mm512_mask_permutexvar_epi32(c, past_32[k], from_c[k], _mm512_loadu_si512(p + 32));
      } else {
        c = _mm512_add_epi32(_mm512_set1_epi32(int(3 * (l.base + tri)) + k), _mm512_mullo_epi32(lane, _mm512_set1_epi32(3)));
      }
      const __m512i lo = _mm512_i32gather_epi64(_mm512_castsi512_si256(c), snapped, 8);
      const __m512i hi = _mm512_i32gather_epi64(_mm512_extracti64x4_epi64(c, 1), snapped, 8);
      x[k] = _mm512_permutex2var_epi32(lo, evens, hi), y[k] = _mm512_permutex2var_epi32(lo, odds, hi);
    }
    const __mmask16 clipped = _mm512_cmpeq_epi32_mask(x[0], not_mapped) | _mm512_cmpeq_epi32_mask(x[1], not_mapped) |
                              _mm512_cmpeq_epi32_mask(x[2], not_mapped);
    const __m512i ylo = _mm512_min_epi32(y[0], _mm512_min_epi32(y[1], y[2])), yhi = _mm512_max_epi32(y[0], _mm512_max_epi32(y[1], y[2]));
    const __m512i xlo = _mm512_min_epi32(x[0], _mm512_min_epi32(x[1], x[2])), xhi = _mm512_max_epi32(x[0], _mm512_max_epi32(x[1], x[2]));
    const __m512i row_lo = _mm512_max_epi32(zero, _mm512_srai_epi32(_mm512_add_epi32(ylo, k127), 8));
    const __m512i row_hi = _mm512_min_epi32(last_row, _mm512_srai_epi32(_mm512_sub_epi32(yhi, k128), 8));
    const __m512i col_lo = _mm512_max_epi32(zero, _mm512_srai_epi32(_mm512_add_epi32(xlo, k127), 8));
    const __m512i col_hi = _mm512_min_epi32(last_col, _mm512_srai_epi32(_mm512_sub_epi32(xhi, k128), 8));
    const __mmask16 keep = _mm512_cmple_epi32_mask(row_lo, row_hi) & _mm512_cmple_epi32_mask(col_lo, col_hi) & ~clipped;
    const __m512i band_lo = _mm512_srai_epi32(row_lo, kShift);
    const __m512i bands = _mm512_min_epi32(_mm512_sub_epi32(_mm512_srai_epi32(row_hi, kShift), band_lo), span);  // met, less one
    // band_lo % units: the quotient of (band_lo + 0.5) / units is never near a whole number.
    const __m512i q = _mm512_cvttps_epi32(_mm512_mul_ps(_mm512_add_ps(_mm512_cvtepi32_ps(band_lo), _mm512_set1_ps(0.5f)), per_unit));
    const __m512i first_owner = _mm512_sub_epi32(band_lo, _mm512_mullo_epi32(q, _mm512_set1_epi32(units)));
    const __m512i ids = _mm512_add_epi32(_mm512_set1_epi32(int(tri)), lane);
    const __m512i marked = _mm512_mask_or_epi32(ids, clipped, ids, _mm512_set1_epi32(int(kClipped)));
    for (int o = 0; o < units; ++o) {
      // Owner o's distance past the first owner, around the units.
      __m512i d = _mm512_sub_epi32(_mm512_set1_epi32(o), first_owner);
      d = _mm512_mask_add_epi32(d, _mm512_cmplt_epi32_mask(d, zero), d, _mm512_set1_epi32(units));
      const __mmask16 mine = clipped | (keep & _mm512_cmple_epi32_mask(d, bands));
      _mm512_storeu_si512(out[o], _mm512_maskz_compress_epi32(mine, marked));
      out[o] += __builtin_popcount(mine);
    }
  }
  return tri;
}

template <detail::DepthMode D>
void draw_bins_wide(const List& l, const detail::Bands& mine, const uint32_t* const* in, const size_t* counts, int shares) {
  uint64_t nonfinite = 0;
  // Corner numbers, and three times a triangle's, in 31 bits: vectors of them (the lists have room
  // for a vector's load past their end).
  const bool vector_corners = 3 * (l.base + l.count) < size_t(INT32_MAX) && l.vs.snapped.size() <= size_t(INT32_MAX);
  for (int share = 0; share < shares; ++share) {
    const uint32_t* list = in[share];
    const size_t n = counts[share];
    for (size_t e = 0; e < n; e += 8) {
      const int lanes = int(std::min<size_t>(8, n - e));
      for (size_t a = e + 8; a < std::min(e + 16, n); ++a)
        for (size_t v : l.corners(list[a] & ~kClipped)) __builtin_prefetch(&l.vs.snapped[v]), __builtin_prefetch(&l.vs.hot[v]);
      alignas(32) uint32_t corner[3][8];
      unsigned clipped = 0;
      if (vector_corners) {
        clipped = chunk_corners(l, list + e, lanes, corner);
      } else {
        for (int lane = 0; lane < 8; ++lane) {
          const uint32_t entry = list[e + size_t(std::min(lane, lanes - 1))];
          const std::array<size_t, 3> vi = l.corners(entry & ~kClipped);
          for (int c = 0; c < 3; ++c) corner[c][lane] = uint32_t(vi[size_t(c)]);
          clipped |= unsigned(entry >> 31) << lane;
        }
      }
      Setup8 st;
      setup8(l.vs, corner, l.fb.width, l.fb.height, st);
      for (int lane = 0; lane < lanes; ++lane) {
        const std::array<size_t, 3> vi = {corner[0][lane], corner[1][lane], corner[2][lane]};
        if (clipped >> lane & 1) {
          draw_clipped(l, vi, mine);
        } else if (st.tiny >> lane & 1) {
          // At most 2x2 centres, their coverage known: most such triangles at high subdivision
          // cover none, and the others need no more than one 4x4 block.
          const int ymin = st.edges[detail::kYmin][lane];
          unsigned bits = unsigned(st.cover[lane]);
          if (!mine.owns(ymin / kBandRows)) bits &= 0xC;
          if (!mine.owns((ymin + 1) / kBandRows)) bits &= 0x3;
          if (!bits || !(st.ok >> lane & 1)) continue;
          detail::BoxCoverage c{{uint16_t((bits & 3) | (bits & 0xC) << 2), 0, 0, 0}, 1, false};  // lanes 0, 1, 4, 5
          nonfinite += detail::shade<D, false>(l.fb, {&st.z[0][lane], &st.f[0][lane], 8}, st.edges[detail::kXmin][lane], ymin,
                                               l.s.depth_func, c);
        } else if (st.box >> lane & 1) {
          if (st.ok >> lane & 1)  // else not drawn, as smooth_planes decides
            nonfinite += detail::box_draw_inline<D>(l.fb, {&st.edges[0][lane], 8}, {&st.z[0][lane], &st.f[0][lane], 8}, mine, l.s.depth_func);
        } else if (!(st.none >> lane & 1)) {
          const Snapped p[3] = {l.vs.snapped[vi[0]], l.vs.snapped[vi[1]], l.vs.snapped[vi[2]]};
          draw_one<D>(l, vi, p, mine);
        }
      }
    }
  }
  if (nonfinite) detail::g_nonfinite_fragments.fetch_add(nonfinite, std::memory_order_relaxed);
}

template void draw_bins_wide<kNoDepth>(const List&, const Bands&, const uint32_t* const*, const size_t*, int);
template void draw_bins_wide<kLess>(const List&, const Bands&, const uint32_t* const*, const size_t*, int);
template void draw_bins_wide<kLequal>(const List&, const Bands&, const uint32_t* const*, const size_t*, int);
template void draw_bins_wide<kAnyDepth>(const List&, const Bands&, const uint32_t* const*, const size_t*, int);

}  // namespace ffc::raster::detail

#pragma GCC pop_options

#endif  // FFCOMPAT_X86
