#include "raster/raster.h"

#include <algorithm>
#include <cmath>

namespace ffc::raster {

uint8_t to_unorm8(double c) {
  if (!(c > 0)) return 0;  // also NaN
  if (c >= 1) return 255;
  return uint8_t(std::nearbyint(c * 255.0));  // default rounding mode: half to even
}

namespace {

struct ClipVertex {
  glm::dvec4 clip;
  glm::dvec4 c[4];  // front, back, front_sec, back_sec
};

ClipVertex lerp(const ClipVertex& a, const ClipVertex& b, double t) {
  ClipVertex r;
  r.clip = a.clip + (b.clip - a.clip) * t;
  for (int k = 0; k < 4; ++k) r.c[k] = a.c[k] + (b.c[k] - a.c[k]) * t;
  return r;
}

// Sutherland-Hodgman against -w <= x,y,z <= w, in homogeneous coordinates.
std::vector<ClipVertex> clip(std::vector<ClipVertex> poly, bool is_line) {
  for (int plane = 0; plane < 6 && !poly.empty(); ++plane) {
    const int axis = plane / 2;
    const double sign = plane % 2 ? -1 : 1;
    auto dist = [&](const ClipVertex& v) { return v.clip.w + sign * v.clip[axis]; };
    std::vector<ClipVertex> out;
    const size_t n = poly.size();
    const size_t edges = is_line ? 1 : n;
    if (is_line) {
      const double da = dist(poly[0]), db = dist(poly[1]);
      if (da < 0 && db < 0) return {};
      ClipVertex a = poly[0], b = poly[1];
      if (da < 0) a = lerp(poly[0], poly[1], da / (da - db));
      if (db < 0) b = lerp(poly[0], poly[1], da / (da - db));
      poly = {a, b};
      continue;
    }
    for (size_t i = 0; i < edges; ++i) {
      const ClipVertex &a = poly[i], &b = poly[(i + 1) % n];
      const double da = dist(a), db = dist(b);
      if (da >= 0) out.push_back(a);
      if ((da >= 0) != (db >= 0)) out.push_back(lerp(a, b, da / (da - db)));
    }
    poly = std::move(out);
  }
  return poly;
}

}  // namespace

std::vector<WindowVertex> clip_and_map(const std::vector<Vertex>& prim, const State& s, const Vertex* provoking,
                                      bool is_line, bool* back_facing) {
  std::vector<ClipVertex> cv;
  cv.reserve(prim.size());
  for (const Vertex& v : prim) cv.push_back({v.clip, {v.front, v.back, v.front_sec, v.back_sec}});
  if (s.flat && provoking)  // flat shading: every vertex carries the provoking vertex's colours
    for (ClipVertex& v : cv)
      v.c[0] = provoking->front, v.c[1] = provoking->back, v.c[2] = provoking->front_sec, v.c[3] = provoking->back_sec;
  // Facing is decided before clipping, from the whole primitive, in window orientation.
  bool back = false;
  if (!is_line && prim.size() >= 3) {
    // The sign of the homogeneous determinant is the window orientation whatever the w's signs.
    const glm::dmat3 m(glm::dvec3(prim[0].clip.x, prim[0].clip.y, prim[0].clip.w),
                       glm::dvec3(prim[1].clip.x, prim[1].clip.y, prim[1].clip.w),
                       glm::dvec3(prim[2].clip.x, prim[2].clip.y, prim[2].clip.w));
    const double area = glm::determinant(m);
    const bool ccw = area > 0;
    back = (s.front_face == GL_CCW) != ccw;
    if (s.cull && (s.cull_mode == GL_FRONT_AND_BACK || (s.cull_mode == GL_BACK) == back)) return {};
  }
  if (back_facing) *back_facing = back;
  const std::vector<ClipVertex> clipped = clip(std::move(cv), is_line);
  std::vector<WindowVertex> out;
  out.reserve(clipped.size());
  const glm::ivec4 vp = s.viewport;
  for (const ClipVertex& v : clipped) {
    const double iw = 1 / v.clip.w;
    const glm::dvec3 ndc = glm::dvec3(v.clip) * iw;
    WindowVertex w;
    w.pos = {(ndc.x + 1) * 0.5 * vp[2] + vp[0], (ndc.y + 1) * 0.5 * vp[3] + vp[1],
             (ndc.z * (s.depth_range.y - s.depth_range.x) + (s.depth_range.y + s.depth_range.x)) * 0.5};
    const bool use_back = back && s.two_side;
    w.color = use_back ? v.c[1] : v.c[0];
    w.sec = use_back ? v.c[3] : v.c[2];
    w.inv_w = iw;
    out.push_back(w);
  }
  return out;
}

namespace {

bool depth_pass(GLenum func, uint32_t z, uint32_t stored) {
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

void write_fragment(Framebuffer& fb, int x, int y, double z, const glm::dvec4& c, const State& s) {
  if (x < 0 || y < 0 || x >= fb.width || y >= fb.height) return;
  const size_t i = size_t(y) * fb.width + x;
  const uint32_t zi = uint32_t(std::clamp(z, 0.0, 1.0) * double(0xFFFFFF) + 0.5);
  if (s.depth_test) {
    if (!depth_pass(s.depth_func, zi, fb.depth[i])) return;
    fb.depth[i] = zi;
  }
  uint8_t* p = &fb.color[i * 4];
  for (int k = 0; k < 4; ++k) p[k] = to_unorm8(c[k]);
}

// Snapped to 1/256 pixel, as llvmpipe's 8 subpixel bits.
int64_t snap(double v) { return int64_t(std::nearbyint(v * 256.0)); }

void draw_triangle(Framebuffer& fb, const WindowVertex& a, const WindowVertex& b, const WindowVertex& c,
                   const State& s) {
  int64_t x[3] = {snap(a.pos.x), snap(b.pos.x), snap(c.pos.x)};
  int64_t y[3] = {snap(a.pos.y), snap(b.pos.y), snap(c.pos.y)};
  const WindowVertex* v[3] = {&a, &b, &c};
  int64_t area = (x[1] - x[0]) * (y[2] - y[0]) - (x[2] - x[0]) * (y[1] - y[0]);
  if (area == 0) return;
  if (area < 0) {  // make it counter-clockwise
    std::swap(x[1], x[2]), std::swap(y[1], y[2]), std::swap(v[1], v[2]);
    area = -area;
  }
  const int x0 = std::max(0, int(std::min({x[0], x[1], x[2]}) >> 8) - 1);
  const int x1 = std::min(fb.width - 1, int(std::max({x[0], x[1], x[2]}) >> 8) + 1);
  const int y0 = std::max(0, int(std::min({y[0], y[1], y[2]}) >> 8) - 1);
  const int y1 = std::min(fb.height - 1, int(std::max({y[0], y[1], y[2]}) >> 8) + 1);
  // Edge i runs from vertex i+1 to i+2; a pixel on an edge is inside only for left and bottom
  // edges (GL window coordinates), so shared edges are drawn once.
  auto edge = [&](int i, int64_t px, int64_t py) {
    const int j = (i + 1) % 3, k = (i + 2) % 3;
    return (x[k] - x[j]) * (py - y[j]) - (y[k] - y[j]) * (px - x[j]);
  };
  bool inclusive[3];
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3, k = (i + 2) % 3;
    const int64_t dx = x[k] - x[j], dy = y[k] - y[j];
    inclusive[i] = dy < 0 || (dy == 0 && dx > 0);  // left edge (going down) or bottom edge
  }
  for (int py = y0; py <= y1; ++py)
    for (int px = x0; px <= x1; ++px) {
      const int64_t cx = int64_t(px) * 256 + 128, cy = int64_t(py) * 256 + 128;
      int64_t e[3];
      bool in = true;
      for (int i = 0; i < 3 && in; ++i) {
        e[i] = edge(i, cx, cy);
        in = e[i] > 0 || (e[i] == 0 && inclusive[i]);
      }
      if (!in) continue;
      const double l0 = double(e[0]) / area, l1 = double(e[1]) / area, l2 = double(e[2]) / area;
      const double z = l0 * v[0]->pos.z + l1 * v[1]->pos.z + l2 * v[2]->pos.z;
      // Perspective-correct colour: interpolate c/w and 1/w.
      const double w0 = l0 * v[0]->inv_w, w1 = l1 * v[1]->inv_w, w2 = l2 * v[2]->inv_w;
      const double ws = w0 + w1 + w2;
      glm::dvec4 col = (w0 * v[0]->color + w1 * v[1]->color + w2 * v[2]->color) / ws;
      if (s.add_secondary)
        col += glm::dvec4(glm::dvec3((w0 * v[0]->sec + w1 * v[1]->sec + w2 * v[2]->sec) / ws), 0);
      write_fragment(fb, px, py, z, col, s);
    }
}

}  // namespace

void draw_polygon(Framebuffer& fb, const std::vector<WindowVertex>& poly, const State& s) {
  for (size_t i = 1; i + 1 < poly.size(); ++i) draw_triangle(fb, poly[0], poly[i], poly[i + 1], s);
}

void draw_line(Framebuffer& fb, const std::vector<WindowVertex>& line, const State& s) {
  if (line.size() != 2) return;
  const WindowVertex &a = line[0], &b = line[1];
  const double dx = b.pos.x - a.pos.x, dy = b.pos.y - a.pos.y;
  const int steps = int(std::ceil(std::max(std::abs(dx), std::abs(dy))));
  for (int i = 0; i < steps; ++i) {
    const double t = (i + 0.5) / steps;
    const glm::dvec3 p = a.pos + (b.pos - a.pos) * t;
    write_fragment(fb, int(std::floor(p.x)), int(std::floor(p.y)), p.z, a.color + (b.color - a.color) * t, s);
  }
}

void clear(Framebuffer& fb, bool color, bool depth, const glm::vec4& cc, double cd) {
  if (color) {
    const uint8_t c[4] = {to_unorm8(cc.r), to_unorm8(cc.g), to_unorm8(cc.b), to_unorm8(cc.a)};
    for (size_t i = 0; i < fb.color.size(); i += 4) std::copy(c, c + 4, &fb.color[i]);
  }
  if (depth) std::fill(fb.depth.begin(), fb.depth.end(), uint32_t(std::clamp(cd, 0.0, 1.0) * 0xFFFFFF + 0.5));
}

}  // namespace ffc::raster
