#include "raster/triangle_list.h"

#include "raster/span.h"

namespace ffc::raster {

void map_shaded(ShadedVertex& v, const State& s) {
  const glm::dvec4 clip(v.clip);
  v.inv_w = 1 / clip.w;
  v.outside = outside_planes(clip);
  if (v.outside) return;
  const WindowVertex w = map_to_window(clip, s);  // one definition of the mapping
  constexpr int64_t kLimit = int64_t(1) << 30;
  if (w.sx < -kLimit || w.sx > kLimit || w.sy < -kLimit || w.sy > kLimit) {
    v.outside = kUnsnappable;
    return;
  }
  v.x = float(w.pos.x), v.y = float(w.pos.y), v.z = float(w.pos.z);
  v.sx = int32_t(w.sx), v.sy = int32_t(w.sy);
}

namespace {

constexpr int kBandRows = 16;

struct List {
  Framebuffer& fb;
  const State& s;
  const ShadedVertex* v;
  const ShadedColors& colors;
  const uint32_t* idx;
  size_t count;
};

// A triangle with a vertex outside the view volume: clipped, fanned and set up as the general
// path does, then drawn in this thread's bands.
void draw_clipped(const List& l, const size_t (&vi)[3], int band, int bands) {
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
      detail::rasterize(l.fb, t, l.s, kBandRows, band, bands, [] { return true; });
  }
}

template <detail::DepthMode D>
void draw_share(const List& l, int band, int bands) {
  const State& s = l.s;
  const bool facing = s.cull || s.two_side;
  const int fb_w = l.fb.width, fb_h = l.fb.height;
  for (size_t tri = 0; tri < l.count; ++tri) {
    const size_t vi[3] = {l.idx ? l.idx[3 * tri] : 3 * tri, l.idx ? l.idx[3 * tri + 1] : 3 * tri + 1,
                          l.idx ? l.idx[3 * tri + 2] : 3 * tri + 2};
    const ShadedVertex* p[3] = {&l.v[vi[0]], &l.v[vi[1]], &l.v[vi[2]]};
    if (p[0]->outside | p[1]->outside | p[2]->outside) {
      draw_clipped(l, vi, band, bands);
      continue;
    }
    // Rows first: most triangles at high subdivision lie in one band, and most bands are another
    // thread's.
    const int32_t ylo = std::min({p[0]->sy, p[1]->sy, p[2]->sy}), yhi = std::max({p[0]->sy, p[1]->sy, p[2]->sy});
    const int row_lo = std::max(0, (ylo - 128 + 255) >> 8), row_hi = std::min(fb_h - 1, (yhi - 128) >> 8);
    if (row_lo > row_hi) continue;
    if (row_lo / kBandRows == row_hi / kBandRows && (row_lo / kBandRows) % bands != band) continue;
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
    detail::rasterize<D>(l.fb, t, s.depth_func, kBandRows, band, bands, planes);
  }
}

}  // namespace

void draw_triangle_list(Framebuffer& fb, const State& s, const ShadedVertex* v, const ShadedColors& colors,
                        const uint32_t* idx, size_t triangles, Workers& workers) {
  const List l{fb, s, v, colors, idx, triangles};
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
