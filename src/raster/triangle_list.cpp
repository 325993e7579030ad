#include "raster/triangle_list.h"

#include "raster/span.h"

#include <emmintrin.h>
#include <xmmintrin.h>

#include <array>

namespace ffc::raster {

uint16_t map_shaded(ShadedVertex& v, const State& s) {
  v.inv_w = 1 / double(v.clip.w);
  v.outside = outside_planes(v.clip);
  if (v.outside) return kNoBand;
  const FloatWindow w = map_float(v.clip, s);
  constexpr int64_t kLimit = int64_t(1) << 30;
  if (w.sx < -kLimit || w.sx > kLimit || w.sy < -kLimit || w.sy > kLimit) {
    v.outside = kUnsnappable;
    return kNoBand;
  }
  v.x = w.x, v.y = w.y, v.z = w.z;
  v.sx = int32_t(w.sx), v.sy = int32_t(w.sy);
  return uint16_t(std::clamp(int((w.sy - 128) >> 8), 0, s.fb_height - 1) / kBandRows);
}

namespace {

struct List {
  Framebuffer& fb;
  const State& s;
  const ShadedVertex* v;
  const uint16_t* bands;
  const ShadedColors& colors;
  const uint32_t* idx;
  size_t count;
};

// A triangle with a vertex outside the view volume: clipped, fanned and set up as the general
// path does, then drawn in this thread's bands.
void draw_clipped(const List& l, const size_t (&vi)[3], const detail::Bands& bands) {
  const bool two_side = l.s.two_side, sec = l.s.add_secondary;
  auto full = [&](size_t i) {
    Vertex r;
    r.clip = glm::dvec4(l.v[i].clip);
    r.front = glm::dvec4(l.colors.front[i]);
    r.back = two_side ? glm::dvec4(l.colors.back[i]) : r.front;
    r.front_sec = sec ? glm::dvec4(l.colors.front_sec[i]) : glm::dvec4(0);
    r.back_sec = sec && two_side ? glm::dvec4(l.colors.back_sec[i]) : r.front_sec;
    return r;
  };
  const std::vector<Vertex> prim = {full(vi[0]), full(vi[1]), full(vi[2])};
  const std::vector<WindowVertex> w = clip_and_map(prim, l.s, &prim[2], false);
  for (size_t k = 1; k + 1 < w.size(); ++k) {
    Triangle t;
    if (!setup(w[0], w[k], w[k + 1], l.s, t)) continue;
    t.xmin = std::max(t.xmin, 0), t.ymin = std::max(t.ymin, 0);
    t.xmax = std::min(t.xmax, l.fb.width - 1), t.ymax = std::min(t.ymax, l.fb.height - 1);
    if (t.xmin <= t.xmax && t.ymin <= t.ymax)
      detail::rasterize(l.fb, t, l.s, bands, [] { return true; });
  }
}

// setup_planes for a smooth triangle without secondary colour, two values per SSE2 register: the
// same operations in the same order as detail::PlaneSolver, so the same bits, in fewer steps.
bool smooth_planes(Triangle& t, const ShadedVertex* const (&v)[3], const glm::vec4* const (&c)[3]) {
  const double X0 = v[0]->x, Y0 = v[0]->y;
  const double x1 = double(v[1]->x) - X0, y1 = double(v[1]->y) - Y0;
  const double x2 = double(v[2]->x) - X0, y2 = double(v[2]->y) - Y0;
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
  solve(_mm_set_pd(v[0]->inv_w, v[0]->z), _mm_set_pd(v[1]->inv_w, v[1]->z), _mm_set_pd(v[2]->inv_w, v[2]->z), p);
  double zw[2];
  for (int i = 0; i < 3; ++i) {
    _mm_storeu_pd(zw, p[i]);
    t.z[i] = zw[0], t.inv_w[i] = float(zw[1]);
  }
  __m128d w[3];
  for (int i = 0; i < 3; ++i) w[i] = _mm_set1_pd(v[i]->inv_w);
  alignas(16) float out[3][4];
  for (int half = 0; half < 2; ++half) {  // (r, g), then (b, a)
    __m128d cw[3];
    for (int i = 0; i < 3; ++i) cw[i] = _mm_mul_pd(_mm_cvtps_pd(_mm_loadl_pi(_mm_setzero_ps(), reinterpret_cast<const __m64*>(&(*c[i])[2 * half]))), w[i]);
    solve(cw[0], cw[1], cw[2], p);
    for (int i = 0; i < 3; ++i) _mm_storel_pi(reinterpret_cast<__m64*>(&out[i][2 * half]), _mm_cvtpd_ps(p[i]));
  }
  std::memcpy(t.c0, out[0], 16), std::memcpy(t.cx, out[1], 16), std::memcpy(t.cy, out[2], 16);
  // Planes beyond float: not drawn rather than drawn from infinities (as setup_planes).
  const __m128 all = _mm_add_ps(_mm_add_ps(_mm_load_ps(out[0]), _mm_load_ps(out[1])), _mm_load_ps(out[2]));
  const __m128 iw = _mm_set_ps(0, t.inv_w[2], t.inv_w[1], t.inv_w[0]);
  const __m128 probe = _mm_mul_ps(_mm_add_ps(_mm_mul_ps(all, _mm_setzero_ps()), _mm_mul_ps(iw, _mm_setzero_ps())), _mm_setzero_ps());
  return _mm_movemask_ps(_mm_cmpunord_ps(probe, probe)) == 0;
}

constexpr size_t kAhead = 12;  // triangles between a prefetch and the use

template <detail::DepthMode D>
void draw_share(const List& l, int band, int bands) {
  const State& s = l.s;
  const bool facing = s.cull || s.two_side;
  const bool fast_planes = !s.flat && !s.add_secondary;
  const int fb_w = l.fb.width, fb_h = l.fb.height;
  const detail::Bands mine(band, bands);
  for (size_t tri = 0; tri < l.count; ++tri) {
    const size_t vi[3] = {l.idx ? l.idx[3 * tri] : 3 * tri, l.idx ? l.idx[3 * tri + 1] : 3 * tri + 1,
                          l.idx ? l.idx[3 * tri + 2] : 3 * tri + 2};
    if (l.idx && tri + kAhead < l.count) {
      // Indexed vertices are scattered in memory: ask for a later triangle's while this one is drawn.
      for (int k = 0; k < 3; ++k) {
        const uint32_t ahead = l.idx[3 * (tri + kAhead) + k];
        __builtin_prefetch(&l.v[ahead]);
        __builtin_prefetch(&l.colors.front[ahead]);
      }
    }
    // Most triangles at high subdivision lie in one band, and most bands are another thread's:
    // skipped from a table that stays in cache, without touching the vertices.
    const uint16_t b0 = l.bands[vi[0]];
    if (b0 == l.bands[vi[1]] && b0 == l.bands[vi[2]] && b0 != kNoBand && !mine.owns(b0)) continue;
    const ShadedVertex* p[3] = {&l.v[vi[0]], &l.v[vi[1]], &l.v[vi[2]]};
    if (p[0]->outside | p[1]->outside | p[2]->outside) {
      draw_clipped(l, vi, mine);
      continue;
    }
    // No pixel centre between the vertices' rows or columns: at high subdivision, many.
    const int32_t ylo = std::min({p[0]->sy, p[1]->sy, p[2]->sy}), yhi = std::max({p[0]->sy, p[1]->sy, p[2]->sy});
    if ((ylo - 128 + 255) >> 8 > (yhi - 128) >> 8) continue;
    const int32_t xlo = std::min({p[0]->sx, p[1]->sx, p[2]->sx}), xhi = std::max({p[0]->sx, p[1]->sx, p[2]->sx});
    if ((xlo - 128 + 255) >> 8 > (xhi - 128) >> 8) continue;
    Triangle t;
    for (int i = 0; i < 3; ++i) t.x[i] = p[i]->sx, t.y[i] = p[i]->sy;
    bool back = false;
    if (facing) {
      back = back_facing_triangle(glm::dvec4(p[0]->clip), glm::dvec4(p[1]->clip), glm::dvec4(p[2]->clip), s);
      if (culled(back, s)) continue;
    }
    bool swapped = false;
    if (!detail::setup_edges(t, fb_w, fb_h, &swapped)) continue;
    size_t order[3] = {vi[0], vi[1], vi[2]};
    if (swapped) std::swap(order[1], order[2]);
    auto planes = [&] {
      if (fast_planes && !(back && s.two_side)) {
        const ShadedVertex* const pv[3] = {&l.v[order[0]], &l.v[order[1]], &l.v[order[2]]};
        const glm::vec4* const pc[3] = {&l.colors.front[order[0]], &l.colors.front[order[1]], &l.colors.front[order[2]]};
        return smooth_planes(t, pv, pc);
      }
      const bool use_back = back && s.two_side;
      const std::vector<glm::vec4>& col = use_back ? l.colors.back : l.colors.front;
      const std::vector<glm::vec4>& sec = use_back ? l.colors.back_sec : l.colors.front_sec;
      glm::dvec3 pos[3];
      double inv_w[3];
      const glm::vec4* c[3];
      const glm::vec4* sc[3];
      for (int i = 0; i < 3; ++i) {
        const ShadedVertex& sv = l.v[order[i]];
        pos[i] = {sv.x, sv.y, sv.z};
        inv_w[i] = sv.inv_w;
        const size_t from = s.flat ? vi[2] : order[i];  // flat: the provoking vertex's colours
        c[i] = &col[from];
        sc[i] = s.add_secondary ? &sec[from] : c[i];
      }
      return detail::setup_planes(t, pos, inv_w, c, sc, s.flat, s.add_secondary);
    };
    detail::rasterize<D>(l.fb, t, s.depth_func, mine, planes);
  }
}

}  // namespace

void draw_triangle_list(Framebuffer& fb, const State& s, const ShadedVertex* v, const uint16_t* vertex_bands,
                        const ShadedColors& colors, const uint32_t* idx, size_t triangles, Workers& workers) {
  const List l{fb, s, v, vertex_bands, colors, idx, triangles};
  const int bands = std::max(1, std::min(workers.size(), (fb.height + kBandRows - 1) / kBandRows));
  auto share = [&](int band) {
    if (band >= bands) return;
    switch (detail::depth_mode(s)) {
      case detail::kNoDepth: return draw_share<detail::kNoDepth>(l, band, bands);
      case detail::kLess: return draw_share<detail::kLess>(l, band, bands);
      case detail::kLequal: return draw_share<detail::kLequal>(l, band, bands);
      case detail::kAnyDepth: return draw_share<detail::kAnyDepth>(l, band, bands);
    }
  };
  if (bands == 1) return share(0);
  workers.run(share);
}

}  // namespace ffc::raster
