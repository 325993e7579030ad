// The triangle lists' parts shared by the portable draw loop (triangle_list.cpp) and the Highway
// one (wide/triangle_list_wide.cpp): a draw's list of triangles, the marks of its binned entries,
// and the setup and drawing of one triangle. Not an interface.
#pragma once
#include <array>
#include <cstddef>
#include <cstdint>

#include "raster/row_loop.h"
#include "raster/setup.h"
#include "raster/triangle_list.h"

namespace ffc::raster::detail {

struct List {
  Framebuffer& fb;
  const State& s;
  const ListVertices& vs;
  const uint32_t* idx;
  size_t count;
  size_t base;  // unindexed: triangle t is vertices 3 (base + t) ..
  std::array<size_t, 3> corners(size_t tri) const {
    if (!idx) return {3 * (base + tri), 3 * (base + tri) + 1, 3 * (base + tri) + 2};
    return {idx[3 * tri], idx[3 * tri + 1], idx[3 * tri + 2]};
  }
};

constexpr uint32_t kClipped = 1u << 31;  // a binned triangle that needs clipping
constexpr int kMaxThreads = pool::Workers::kMax;
constexpr size_t kAhead = 12;  // triangles between a prefetch and the use
constexpr size_t kBinSlack = 16;  // entries past a bin list's end: room for a vector's store or load

// A triangle with a vertex outside the view volume: clipped, fanned and set up as the general
// path does, then drawn in this thread's bands.
void draw_clipped(const List& l, const std::array<size_t, 3>& vi, const Bands& bands);

#if FFCOMPAT_X86
// setup_planes for a smooth triangle without secondary colour, two values per SSE2 register: the
// same operations in the same order as detail::PlaneSolver, so the same bits, in fewer steps.
bool smooth_planes(Triangle& t, const ShadedVertex* const (&v)[3], float fbh, bool swapped);
#endif

// A triangle of the list, its vertices all mapped, set up for drawing: edges (t), culling and
// facing; false when it is culled or covers no pixel centre. `order` is its vertices in the
// set-up order.
inline bool setup_one(const List& l, const std::array<size_t, 3>& vi, const Snapped (&p)[3], Triangle& t, bool& back,
                      bool& swapped, std::array<size_t, 3>& order) {
  const State& s = l.s;
  for (int i = 0; i < 3; ++i) t.x[i] = p[i].x, t.y[i] = p[i].y;
  back = false;
  if (s.cull || s.two_side) {
    back = back_facing_triangle(glm::dvec4(l.vs.clip[vi[0]]), glm::dvec4(l.vs.clip[vi[1]]), glm::dvec4(l.vs.clip[vi[2]]), s);
    if (culled(back, s)) return false;
  }
  swapped = false;
  if (!detail::setup_edges(t, l.fb.width, l.fb.height, &swapped)) return false;
  order = vi;
  if (swapped) std::swap(order[1], order[2]);
  return true;
}

// The planes of a triangle setup_one prepared; false when they leave float (not drawn).
inline bool list_planes(const List& l, const std::array<size_t, 3>& vi, Triangle& t, bool back, bool swapped,
                        const std::array<size_t, 3>& order) {
  const State& s = l.s;
  const bool use_back = back && s.two_side;
  const ShadedVertex* const v[3] = {&l.vs.hot[order[0]], &l.vs.hot[order[1]], &l.vs.hot[order[2]]};
#if FFCOMPAT_X86
  if (!s.flat && !s.add_secondary && !use_back) return smooth_planes(t, v, float(s.fb_height), swapped);
#endif
  const float x[3] = {v[0]->x, v[1]->x, v[2]->x}, yd[3] = {v[0]->y, v[1]->y, v[2]->y}, z[3] = {v[0]->z, v[1]->z, v[2]->z};
  detail::depth_plane(x, yd, z, swapped, t.z);
  glm::dvec3 pos[3];
  double inv_w[3];
  const glm::vec4* c[3];
  const glm::vec4* sc[3];
  for (int i = 0; i < 3; ++i) {
    pos[i] = {v[i]->x, float(s.fb_height) - v[i]->y, v[i]->z};
    inv_w[i] = 1 / double(v[i]->w);
    const size_t from = s.flat ? vi[2] : order[i];  // flat: the provoking vertex's colours
    c[i] = use_back ? &l.vs.back[from] : &l.vs.hot[from].color;
    sc[i] = !s.add_secondary ? c[i] : use_back ? &l.vs.back_sec[from] : &l.vs.front_sec[from];
  }
  return detail::setup_planes(t, pos, inv_w, c, sc, s.flat, s.add_secondary);
}

// Sets up and draws, in this thread's bands, a triangle whose vertices are all mapped.
template <detail::DepthMode D>
void draw_one(const List& l, const std::array<size_t, 3>& vi, const Snapped (&p)[3], const detail::Bands& mine) {
  Triangle t;
  bool back, swapped;
  std::array<size_t, 3> order;
  if (!setup_one(l, vi, p, t, back, swapped, order)) return;
  count_nonfinite(l.s, detail::rasterize<D>(l.fb, t, l.s.depth_func, mine, [&] { return list_planes(l, vi, t, back, swapped, order); }));
}

// What every binning share kept for this thread, in primitive order: clipped triangles drawn
// here, the others given to one(vi, snapped corners).
template <typename One>
inline void for_each_binned(const List& l, const Bands& mine, const uint32_t* const* in, const size_t* counts, int shares, One&& one) {
  for (int share = 0; share < shares; ++share) {
    const uint32_t* list = in[share];
    const size_t n = counts[share];
    for (size_t e = 0; e < n; ++e) {
      if (e + kAhead < n) {
        const std::array<size_t, 3> ahead = l.corners(list[e + kAhead] & ~kClipped);
        for (size_t a : ahead) __builtin_prefetch(&l.vs.snapped[a]), __builtin_prefetch(&l.vs.hot[a]);
      }
      const std::array<size_t, 3> vi = l.corners(list[e] & ~kClipped);
      if (list[e] & kClipped) {
        draw_clipped(l, vi, mine);
        continue;
      }
      const Snapped p[3] = {l.vs.snapped[vi[0]], l.vs.snapped[vi[1]], l.vs.snapped[vi[2]]};
      one(vi, p);
    }
  }
}

// Vertex i of the list to the window: its snapped position, or kNotMapped when it needs clipping
// (outside_planes, or too far out for 32-bit coordinates), and x, y, z and w for setup.
void map_one(ListVertices& vs, size_t i, const State& s);
// map_one for vertices [first, end) a vector at a time on the dispatched target, with the same
// bits (the fused multiply-adds fused on every target), and the front colours from their columns
// where `front` is given (map_list_vertices); returns the first vertex it left (fewer than a
// vector, or all where the target has no vectors). Where wide_kernels().
size_t map_list_wide(ListVertices& vs, size_t first, size_t end, const State& s, const float* const* front);

// The list's draw loop (triangle_list.cpp's draw_bins) on the dispatched Highway target, its
// kernels inline (wide/triangle_list_wide.cpp); where wide_kernels().
void draw_bins_wide(DepthMode mode, const List& l, const Bands& mine, const uint32_t* const* in, const size_t* counts, int shares);

// bin_range's binning of triangles [first, last) a vector at a time on the dispatched target;
// returns the first triangle it left (fewer than a vector, or all where the target has no vectors
// or the numbers leave 32-bit lanes), for bin_range to finish. Where wide_kernels().
size_t bin_wide(const List& l, size_t first, size_t last, int units, uint32_t** out);

}  // namespace ffc::raster::detail
