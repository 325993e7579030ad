// Triangle setup shared by every path: the edges (area, order, ownership, pixel box) from the
// snapped positions, and the planes of depth, 1/w and colour / w, as llvmpipe's setup builds them.
// The triangle lists' faster setups (smooth_planes, wide/setup_group-inl.h) are held to these bit for bit.
#pragma once
#include <algorithm>
#include <cmath>

#include "raster/pixel_rules.h"
#include "raster/raster.h"

namespace ffc::raster::detail {

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
    const int j = (i + 1) % 3, k = (i + 2) % 3;
    t.inclusive[i] = owns_centres_on_edge(t.x[k] - t.x[j], t.y[k] - t.y[j]);
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

}  // namespace ffc::raster::detail
