#include "raster/triangle_list.h"

#include "raster/triangle_list_parts.h"

#include <array>
#include <cmath>

#if FFCOMPAT_X86
#include <immintrin.h>
#endif

namespace ffc::raster {

namespace detail {  // declared in triangle_list_parts.h

// One vertex: outside_planes, then map_float.
void map_one(ListVertices& vs, size_t i, const State& s) {
  const glm::vec4& clip = vs.clip[i];
  ShadedVertex& v = vs.hot[i];
  v.w = clip.w;
  vs.snapped[i] = {kNotMapped, 0};
  if (outside_planes(clip)) return;
  const FloatWindow w = map_float(clip, s);
  constexpr int64_t kLimit = int64_t(1) << 30;  // inside, but too far out for 32-bit coordinates: clipped
  if (w.sx < -kLimit || w.sx > kLimit || w.sy < -kLimit || w.sy > kLimit) return;
  v.x = w.x, v.y = w.y_down, v.z = w.z;
  vs.snapped[i] = {int32_t(w.sx), int32_t(w.sy)};
}

}  // namespace detail

namespace {

using detail::map_one;

#if FFCOMPAT_X86
// Fused multiply-add of four floats: one instruction where the CPU has it, four library calls
// otherwise; the same bits.
struct FmaInstruction {
  __attribute__((target("fma"))) static __m128 fma(__m128 a, __m128 b, __m128 c) { return _mm_fmadd_ps(a, b, c); }
};
// llvmpipe without FMA (llvmpipe_fma() false): a product, then a sum.
struct MulThenAdd {
  static __m128 fma(__m128 a, __m128 b, __m128 c) { return _mm_add_ps(_mm_mul_ps(a, b), c); }
};
struct FmaCall {
  static __m128 fma(__m128 a, __m128 b, __m128 c) {
    alignas(16) float x[4], y[4], z[4];
    _mm_store_ps(x, a), _mm_store_ps(y, b), _mm_store_ps(z, c);
    for (int k = 0; k < 4; ++k) x[k] = std::fma(x[k], y[k], z[k]);
    return _mm_load_ps(x);
  }
};

// Four vertices at once: map_one's operations, in the same order, a vertex a lane. False (nothing
// written) when a snapped coordinate would leave the range cvtps2dq rounds in; map_one then.
template <typename F>
bool map_four(ListVertices& vs, size_t i, const State& s) {
  __m128 X = _mm_loadu_ps(&vs.clip[i].x), Y = _mm_loadu_ps(&vs.clip[i + 1].x), Z = _mm_loadu_ps(&vs.clip[i + 2].x),
         W = _mm_loadu_ps(&vs.clip[i + 3].x);
  _MM_TRANSPOSE4_PS(X, Y, Z, W);
  const __m128 zero = _mm_setzero_ps(), sign = _mm_set1_ps(-0.0f);
  __m128 out = _mm_or_ps(_mm_or_ps(_mm_cmpgt_ps(X, W), _mm_cmplt_ps(X, _mm_sub_ps(zero, W))),
                         _mm_or_ps(_mm_cmpgt_ps(Y, W), _mm_cmplt_ps(Y, _mm_sub_ps(zero, W))));
  out = _mm_or_ps(out, _mm_or_ps(_mm_cmpgt_ps(Z, W), _mm_cmplt_ps(Z, _mm_sub_ps(zero, W))));
  out = _mm_or_ps(out, _mm_cmpunord_ps(_mm_add_ps(_mm_add_ps(_mm_mul_ps(X, zero), _mm_mul_ps(Y, zero)),
                                                  _mm_add_ps(_mm_mul_ps(Z, zero), _mm_mul_ps(W, zero))), zero));
  const __m128 aw = _mm_andnot_ps(sign, W);  // |w|: positive, and 1/w a normal float
  out = _mm_or_ps(out, _mm_or_ps(_mm_cmple_ps(W, zero), _mm_or_ps(_mm_cmplt_ps(aw, _mm_set1_ps(0x1p-126f)),
                                                                _mm_cmpgt_ps(aw, _mm_set1_ps(0x1p126f)))));
  const glm::ivec4 vp = s.viewport;
  const __m128 fiw = _mm_div_ps(_mm_set1_ps(1.0f), W);
  const __m128 nx = _mm_mul_ps(X, fiw), ny = _mm_mul_ps(Y, fiw), nz = _mm_mul_ps(Z, fiw);
  const float hw = float(vp[2]) * 0.5f, hh = float(vp[3]) * 0.5f, fbh = float(s.fb_height);
  const float dn = float(s.depth_range.x), df = float(s.depth_range.y);
  const __m128 x = F::fma(nx, _mm_set1_ps(hw), _mm_set1_ps(float(vp[0]) + hw));
  const __m128 y_down = F::fma(ny, _mm_set1_ps(-hh), _mm_set1_ps(fbh - (float(vp[1]) + hh)));
  const __m128 z = F::fma(nz, _mm_set1_ps((df - dn) * 0.5f), _mm_set1_ps((df + dn) * 0.5f));
  const __m128 sxf = _mm_mul_ps(_mm_sub_ps(x, _mm_set1_ps(0.5f)), _mm_set1_ps(256.0f));
  const __m128 syf = _mm_mul_ps(_mm_sub_ps(y_down, _mm_set1_ps(0.5f)), _mm_set1_ps(256.0f));
  // Rounded half to even (the SSE default) as map_float's cvtss2si, where both stay well within
  // 32 bits (and within kLimit of map_one, 2^30 after the offsets); elsewhere lane by lane.
  const __m128 limit = _mm_set1_ps(0x1p29f);
  const __m128 far = _mm_or_ps(_mm_cmpnlt_ps(_mm_andnot_ps(sign, sxf), limit), _mm_cmpnlt_ps(_mm_andnot_ps(sign, syf), limit));
  if (_mm_movemask_ps(_mm_andnot_ps(out, far))) return false;
  const __m128i sx = _mm_add_epi32(_mm_cvtps_epi32(sxf), _mm_set1_epi32(128));
  const __m128i sy = _mm_sub_epi32(_mm_set1_epi32((s.fb_height - 1) * 256 + 128), _mm_cvtps_epi32(syf));
  __m128 px = x, py = y_down, pz = z, pw = W;
  _MM_TRANSPOSE4_PS(px, py, pz, pw);
  const __m128 rows[4] = {px, py, pz, pw};
  alignas(16) int32_t ax[4], ay[4];
  _mm_store_si128(reinterpret_cast<__m128i*>(ax), sx), _mm_store_si128(reinterpret_cast<__m128i*>(ay), sy);
  const int outside = _mm_movemask_ps(out);
  for (int k = 0; k < 4; ++k) {
    _mm_storeu_ps(&vs.hot[i + k].x, rows[k]);  // x, y, z, w
    vs.snapped[i + k] = outside >> k & 1 ? Snapped{kNotMapped, 0} : Snapped{ax[k], ay[k]};
  }
  return true;
}
#endif

}  // namespace

void map_list_vertices(ListVertices& vs, size_t first, size_t count, const State& s, const float* const* front) {
  size_t i = first;
  if (detail::wide_kernels()) i = detail::map_list_wide(vs, first, first + count, s, front);
  if (front)  // those the vectors left
    for (size_t k = i; k < first + count; ++k) {
      const size_t j = k - first;
      vs.hot[k].color = {front[0][j], front[1][j], front[2][j], front[3][j]};
    }
#if FFCOMPAT_X86
  static const bool fma = __builtin_cpu_supports("fma");
  for (; i + 4 <= first + count; i += 4)
    if (!(!llvmpipe_fma() ? map_four<MulThenAdd>(vs, i, s) : fma ? map_four<FmaInstruction>(vs, i, s) : map_four<FmaCall>(vs, i, s)))
      for (size_t k = i; k < i + 4; ++k) map_one(vs, k, s);
#endif
  for (; i < first + count; ++i) map_one(vs, i, s);
}

namespace detail {  // declared in triangle_list_parts.h

void draw_clipped(const List& l, const std::array<size_t, 3>& vi, const detail::Bands& bands) {
  const bool two_side = l.s.two_side, sec = l.s.add_secondary;
  auto full = [&](size_t i) {
    Vertex r;
    r.clip = glm::dvec4(l.vs.clip[i]);
    r.front = glm::dvec4(l.vs.hot[i].color);
    r.back = two_side ? glm::dvec4(l.vs.back[i]) : r.front;
    r.front_sec = sec ? glm::dvec4(l.vs.front_sec[i]) : glm::dvec4(0);
    r.back_sec = sec && two_side ? glm::dvec4(l.vs.back_sec[i]) : r.front_sec;
    return r;
  };
  const Vertex prim[3] = {full(vi[0]), full(vi[1]), full(vi[2])};
  const WindowPolygon w = clip_and_map(prim, 3, l.s, &prim[2], false);
  for (size_t k = 1; k + 1 < w.size(); ++k) {
    Triangle t;
    if (!setup(w[k], w[k + 1], w[0], l.s, t)) continue;  // Mesa's clipper's fan (context.cpp)
    count_if_sliver(w[k], w[k + 1], w[0], l.s);          // docs/deviations.md row 63
    t.xmin = std::max(t.xmin, 0), t.ymin = std::max(t.ymin, 0);
    t.xmax = std::min(t.xmax, l.fb.width - 1), t.ymax = std::min(t.ymax, l.fb.height - 1);
    if (t.xmin <= t.xmax && t.ymin <= t.ymax)
      detail::rasterize(l.fb, t, l.s, bands, [] { return true; });
  }
}

#if FFCOMPAT_X86
bool smooth_planes(Triangle& t, const ShadedVertex* const (&v)[3], float fbh, bool swapped) {
  const float up[3] = {fbh - v[0]->y, fbh - v[1]->y, fbh - v[2]->y};  // GL's y, as map_float's
  const double X0 = v[0]->x, Y0 = up[0];
  const double x1 = double(v[1]->x) - X0, y1 = double(up[1]) - Y0;
  const double x2 = double(v[2]->x) - X0, y2 = double(up[2]) - Y0;
  const double det = x1 * y2 - x2 * y1;
  const __m128d inv = _mm_set1_pd(det != 0 ? 1 / det : 0);
  const __m128d vx0 = _mm_set1_pd(X0), vy0 = _mm_set1_pd(Y0), vx1 = _mm_set1_pd(x1), vy1 = _mm_set1_pd(y1),
                vx2 = _mm_set1_pd(x2), vy2 = _mm_set1_pd(y2);
  auto solve = [&](__m128d a, __m128d b, __m128d cc, __m128d (&p)[3]) {
    const __m128d d1 = _mm_sub_pd(b, a), d2 = _mm_sub_pd(cc, a);
    p[1] = _mm_mul_pd(_mm_sub_pd(_mm_mul_pd(d1, vy2), _mm_mul_pd(d2, vy1)), inv);
    p[2] = _mm_mul_pd(_mm_sub_pd(_mm_mul_pd(vx1, d2), _mm_mul_pd(vx2, d1)), inv);
    p[0] = _mm_sub_pd(_mm_sub_pd(a, _mm_mul_pd(p[1], vx0)), _mm_mul_pd(p[2], vy0));
  };
  __m128d p[3];
  // 1/w in double, as map_to_window takes it.
  const __m128d w01 = _mm_div_pd(_mm_set1_pd(1), _mm_set_pd(v[1]->w, v[0]->w));
  const __m128d w2 = _mm_div_sd(_mm_set_sd(1), _mm_set_sd(v[2]->w));
  const __m128d w[3] = {_mm_unpacklo_pd(w01, w01), _mm_unpackhi_pd(w01, w01), _mm_unpacklo_pd(w2, w2)};
  solve(w[0], w[1], w[2], p);  // 1/w (twice)
  double pw[2];
  for (int i = 0; i < 3; ++i) {
    _mm_storeu_pd(pw, p[i]);
    t.inv_w[i] = float(pw[1]);
  }
  const float x[3] = {v[0]->x, v[1]->x, v[2]->x}, yd[3] = {v[0]->y, v[1]->y, v[2]->y}, z[3] = {v[0]->z, v[1]->z, v[2]->z};
  detail::depth_plane(x, yd, z, swapped, t.z);
  // Colour / w, (r, g) and (b, a) apart; the halves joined in registers (storing them to memory
  // and loading them as one stalls store forwarding).
  __m128d half[2][3];
  for (int h = 0; h < 2; ++h) {
    __m128d cw[3];
    for (int i = 0; i < 3; ++i)
      cw[i] = _mm_mul_pd(_mm_cvtps_pd(_mm_loadl_pi(_mm_setzero_ps(), reinterpret_cast<const __m64*>(&v[i]->color[2 * h]))), w[i]);
    solve(cw[0], cw[1], cw[2], half[h]);
  }
  __m128 out[3];
  for (int i = 0; i < 3; ++i) out[i] = _mm_movelh_ps(_mm_cvtpd_ps(half[0][i]), _mm_cvtpd_ps(half[1][i]));
  _mm_storeu_ps(t.c0, out[0]), _mm_storeu_ps(t.cx, out[1]), _mm_storeu_ps(t.cy, out[2]);
  // Planes beyond float: not drawn rather than drawn from infinities (as setup_planes).
  // x * 0 is 0 for a finite x and NaN otherwise; a sum of those is NaN when any is.
  const __m128 zero = _mm_setzero_ps(), iw = _mm_set_ps(0, t.inv_w[2], t.inv_w[1], t.inv_w[0]);
  const __m128 probe = _mm_add_ps(_mm_add_ps(_mm_mul_ps(out[0], zero), _mm_mul_ps(out[1], zero)),
                                  _mm_add_ps(_mm_mul_ps(out[2], zero), _mm_mul_ps(iw, zero)));
  return _mm_movemask_ps(_mm_cmpunord_ps(probe, probe)) == 0;
}
#endif

}  // namespace detail

namespace {

using namespace detail;

// Binning: triangles [first, last), in order, each kept for the owners whose bands its box of
// pixel centres meets (a clipped one for all), appended at out[owner]. At high subdivision most
// triangles enclose no pixel centre; they are dropped here, once, by whichever thread meets them.
void bin_range(const List& l, size_t first, size_t last, int units, uint32_t** out) {
  const int fb_w = l.fb.width, fb_h = l.fb.height;
  if (detail::wide_kernels()) first = bin_wide(l, first, last, units, out);
  for (size_t tri = first; tri < last; ++tri) {
    if (l.idx && tri + kAhead < last)  // indexed vertices are scattered: ask for them early
      for (int k = 0; k < 3; ++k) __builtin_prefetch(&l.vs.snapped[l.idx[3 * (tri + kAhead) + k]]);
    const std::array<size_t, 3> vi = l.corners(tri);
    const Snapped p[3] = {l.vs.snapped[vi[0]], l.vs.snapped[vi[1]], l.vs.snapped[vi[2]]};
    if (p[0].x == kNotMapped || p[1].x == kNotMapped || p[2].x == kNotMapped) {
      for (int o = 0; o < units; ++o) *out[o]++ = uint32_t(tri) | kClipped;
      continue;
    }
    const int32_t ylo = std::min({p[0].y, p[1].y, p[2].y}), yhi = std::max({p[0].y, p[1].y, p[2].y});
    const int row_lo = std::max(0, (ylo - 128 + 255) >> 8), row_hi = std::min(fb_h - 1, (yhi - 128) >> 8);
    if (row_lo > row_hi) continue;
    const int32_t xlo = std::min({p[0].x, p[1].x, p[2].x}), xhi = std::max({p[0].x, p[1].x, p[2].x});
    if (std::max(0, (xlo - 128 + 255) >> 8) > std::min(fb_w - 1, (xhi - 128) >> 8)) continue;
    const int band_lo = row_lo / kBandRows, band_hi = std::min(row_hi / kBandRows, band_lo + units - 1);
    for (int b = band_lo; b <= band_hi; ++b) *out[b % units]++ = uint32_t(tri);
  }
}

void bin_share(const List& l, size_t first, size_t last, int units, uint32_t* const* lists, size_t* counts) {
  uint32_t* out[kMaxThreads];  // write pointers, kept in registers rather than counts in memory
  for (int o = 0; o < units; ++o) out[o] = lists[o];
  bin_range(l, first, last, units, out);
  for (int o = 0; o < units; ++o) counts[o] = size_t(out[o] - lists[o]);
}

// Rasterization: what every binning share kept for this thread, in primitive order.
template <detail::DepthMode D>
void draw_bins(const List& l, const detail::Bands& mine, const uint32_t* const* in, const size_t* counts, int shares) {
  for_each_binned(l, mine, in, counts, shares, [&](const std::array<size_t, 3>& vi, const Snapped (&p)[3]) { draw_one<D>(l, vi, p, mine); });
}

}  // namespace

void TriangleBins::reserve(size_t triangles, int threads) {
  const size_t units = size_t(std::max(1, std::min(threads, kMaxThreads)));
  if (lists.size() < units * units) lists.resize(units * units);
  for (std::vector<uint32_t>& l : lists) l.reserve(triangles / units + 1 + kBinSlack);
}

namespace {

void draw_part(const List& l, pool::Workers& workers, TriangleBins& bins, const ClearRequest& clear) {
  const State& s = l.s;
  const size_t triangles = l.count;
  // Units of work, one a thread, taken by the threads as they come: contiguous shares of the
  // triangles to bin, then owners of bands (band b is owner b % units's) to draw. More units than
  // threads measured no faster on the icosphere, and a triangle that needs clipping is clipped by
  // every unit.
  const int bands = (l.fb.height + kBandRows - 1) / kBandRows;
  const int units = std::max(1, std::min({workers.size(), kMaxThreads, bands}));
  // bins.lists[share * units + owner]: what binning share `share` kept for owner `owner`.
  bins.lists.resize(size_t(units * units));
  for (int share = 0; share < units; ++share) {
    const size_t n = triangles * size_t(share + 1) / size_t(units) - triangles * size_t(share) / size_t(units);
    for (int o = 0; o < units; ++o) bins.lists[size_t(share * units + o)].resize(n + kBinSlack);  // + the vector code's last store or load
  }
  size_t counts[kMaxThreads][kMaxThreads] = {};
  auto bin = [&](int share) {
    if (share >= units) return;
    uint32_t* out[kMaxThreads];
    for (int o = 0; o < units; ++o) out[o] = bins.lists[size_t(share * units + o)].data();
    bin_share(l, triangles * size_t(share) / size_t(units), triangles * size_t(share + 1) / size_t(units),
              units, out, counts[share]);
  };
  auto draw = [&](int owner) {
    if (owner >= units) return;
    const detail::Bands mine(owner, units);
    if (clear.pending())  // this thread's bands, into its cache just before it draws them
      for (int b = owner; b < bands; b += units) clear_band(l.fb, clear, b);
    const uint32_t* in[kMaxThreads];
    size_t n[kMaxThreads];
    for (int share = 0; share < units; ++share)
      in[share] = bins.lists[size_t(share * units + owner)].data(), n[share] = counts[share][owner];
    if (detail::wide_kernels()) return draw_bins_wide(depth_mode(s), l, mine, in, n, units);
    with_depth_mode(s, [&](auto mode) { draw_bins<decltype(mode)::value>(l, mine, in, n, units); });
  };
  if (units == 1) return bin(0), draw(0);
  workers.run(bin, units);
  workers.run(draw, units);
}

}  // namespace

void draw_triangle_list(Framebuffer& fb, const State& s, const ListVertices& vs, const uint32_t* idx,
                        size_t triangles, pool::Workers& workers, TriangleBins& bins, const ClearRequest& clear) {
  ++fb.writes;
  if (triangles == 0 && clear.pending()) raster::clear(fb, clear, workers);
  constexpr size_t kPart = size_t(1) << 30;  // binned triangle numbers have 31 bits
  for (size_t done = 0; done < triangles; done += kPart)
    draw_part({fb, s, vs, idx ? idx + 3 * done : nullptr, std::min(kPart, triangles - done), idx ? 0 : done}, workers, bins,
              done == 0 ? clear : ClearRequest{});
}

}  // namespace ffc::raster
