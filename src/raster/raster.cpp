#include "raster/raster.h"
#include "raster/span.h"
#include "raster/workers.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstring>
#include <emmintrin.h>
#include <xmmintrin.h>

namespace ffc::raster {

// Fragments written from a non-finite colour (NaN or an infinity before the clamp): what
// `ffcompat stress` reads to tell that no pixel was written from one (declared in
// raster.h). The check costs three SSE instructions per fragment, no branch.
namespace detail {
std::atomic<uint64_t> g_nonfinite_fragments{0};
}
using detail::g_nonfinite_fragments;
uint64_t nonfinite_fragments() { return g_nonfinite_fragments.load(std::memory_order_relaxed); }
void reset_nonfinite_fragments() { g_nonfinite_fragments.store(0, std::memory_order_relaxed); }

uint8_t to_unorm8(double c) {
  if (!(c > 0)) return 0;  // also NaN
  if (c >= 1) return 255;
  // In float, as llvmpipe: 0.3f * 255 is exactly 76.5 in float and goes to even, 76. Adding and
  // taking away 1.5 * 2^23 rounds to an integer, half to even, without a library call.
  const float v = float(c) * 255.0f + 12582912.0f;  // not folded: FP addition is not associative
  return uint8_t(v - 12582912.0f);
}

namespace {

const Vertex& flat_source(const Vertex& v, const State& s, const Vertex* provoking) {
  return s.flat && provoking ? *provoking : v;
}

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

using ClipPolygon = Fixed<ClipVertex, 10>;

// Sutherland-Hodgman against -w <= x,y,z <= w, in homogeneous coordinates: each plane adds at most
// one vertex, so a triangle stays within nine.
ClipPolygon clip(ClipPolygon poly, bool is_line) {
  for (int plane = 0; plane < 6 && !poly.empty(); ++plane) {
    const int axis = plane / 2;
    const double sign = plane % 2 ? -1 : 1;
    auto dist = [&](const ClipVertex& v) { return v.clip.w + sign * v.clip[axis]; };
    ClipPolygon out;
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
    poly = out;
  }
  return poly;
}

}  // namespace

namespace {
// nearbyint(v) for a float, as one cvtss2si in the current (round-to-even) mode when in range.
int64_t round_even(float v) {
  return std::fabs(v) < 0x1p30f ? _mm_cvtss_si32(_mm_set_ss(v)) : int64_t(std::nearbyint(v));
}
}  // namespace

// Built twice, with and without FMA instructions (chosen at load time): std::fma is one
// instruction where the CPU has it, a library call otherwise; the same bits either way.
__attribute__((target_clones("fma", "default"))) FloatWindow map_float(const glm::vec4& clip, const State& s) {
  const glm::ivec4 vp = s.viewport;
  const float fiw = 1.0f / clip.w;
  const float nx = clip.x * fiw, ny = clip.y * fiw, nz = clip.z * fiw;
  const float hw = float(vp[2]) * 0.5f, hh = float(vp[3]) * 0.5f;
  const float x = std::fma(nx, hw, float(vp[0]) + hw);
  const float y_down = std::fma(ny, -hh, float(s.fb_height) - (float(vp[1]) + hh));
  const float dn = float(s.depth_range.x), df = float(s.depth_range.y);
  FloatWindow w;
  w.x = x, w.y = float(s.fb_height) - y_down, w.y_down = y_down, w.z = std::fma(nz, (df - dn) * 0.5f, (df + dn) * 0.5f);
  // Snapped where llvmpipe snaps: (v - 0.5) in 1/256 pixel, half to even, rows counted down.
  w.sx = round_even((x - 0.5f) * 256.0f) + 128;
  w.sy = int64_t(s.fb_height - 1) * 256 - round_even((y_down - 0.5f) * 256.0f) + 128;
  return w;
}

WindowVertex map_to_window(const glm::dvec4& clip, const State& s) {
  const glm::ivec4 vp = s.viewport;
  WindowVertex w;
  w.inv_w = 1 / clip.w;
  if (!s.float_window) {
    const glm::dvec3 ndc = glm::dvec3(clip) * w.inv_w;
    w.pos = {(ndc.x + 1) * 0.5 * vp[2] + vp[0], (ndc.y + 1) * 0.5 * vp[3] + vp[1],
             (ndc.z * (s.depth_range.y - s.depth_range.x) + (s.depth_range.y + s.depth_range.x)) * 0.5};
    w.y_down = float(s.fb_height - w.pos.y);
    return w;
  }
  const FloatWindow f = map_float(glm::vec4(clip), s);
  w.pos = {f.x, f.y, f.z};
  w.snapped = true;
  w.sx = f.sx, w.sy = f.sy, w.y_down = f.y_down;
  return w;
}

bool back_facing_triangle(const glm::dvec4& a, const glm::dvec4& b, const glm::dvec4& c, const State& s) {
  // The sign of the homogeneous determinant is the window orientation whatever the w's signs.
  const double area = a.x * (b.y * c.w - c.y * b.w) - b.x * (a.y * c.w - c.y * a.w) + c.x * (a.y * b.w - b.y * a.w);
  return (s.front_face == GL_CCW) != (area > 0);
}

bool culled(bool back, const State& s) {
  return s.cull && (s.cull_mode == GL_FRONT_AND_BACK || (s.cull_mode == GL_BACK) == back);
}

WindowPolygon clip_and_map(const Vertex* prim, size_t count, const State& s, const Vertex* provoking, bool is_line,
                           bool* back_facing) {
  // A NaN or infinite clip coordinate (unspecified input, GL 2.1 section 2.1.1) has no place in the
  // window: the primitive is dropped, so nothing non-finite reaches setup or feedback.
  for (size_t i = 0; i < count; ++i) {
    const glm::dvec4& c = prim[i].clip;
    if (!(std::isfinite(c.x) && std::isfinite(c.y) && std::isfinite(c.z) && std::isfinite(c.w))) return {};
  }
  ClipPolygon cv;
  for (size_t i = 0; i < count; ++i) {
    const Vertex& v = flat_source(prim[i], s, provoking);  // flat: every vertex carries the provoking one's colours
    cv.push_back({prim[i].clip, {v.front, v.back, v.front_sec, v.back_sec}});
  }
  // Facing is decided before clipping, from the whole primitive, in window orientation.
  bool back = false;
  if (!is_line && count >= 3) {
    back = back_facing_triangle(prim[0].clip, prim[1].clip, prim[2].clip, s);
    if (culled(back, s)) return {};
  }
  if (back_facing) *back_facing = back;
  const ClipPolygon clipped = clip(cv, is_line);
  for (const ClipVertex& v : clipped)  // e.g. w ~ 1e-40: 1/w is no float, nor are the positions
    if (!w_mappable(v.clip.w)) return {};
  WindowPolygon out;
  for (const ClipVertex& v : clipped) {
    WindowVertex w = map_to_window(v.clip, s);
    const bool use_back = back && s.two_side;
    w.color = use_back ? v.c[1] : v.c[0];
    w.sec = use_back ? v.c[3] : v.c[2];
    out.push_back(w);
  }
  return out;
}

namespace {

void write_fragment(Framebuffer& fb, int x, int y, double z, const glm::dvec4& c, const State& s) {
  if (x < 0 || y < 0 || x >= fb.width || y >= fb.height) return;
  const size_t i = size_t(y) * fb.width + x;
  const uint32_t zi = detail::depth24(float(z));  // converted as a triangle's
  if (s.depth_test) {
    if (!detail::depth_pass(s.depth_func, zi, fb.depth[i])) return;
    fb.depth[i] = zi;
  }
  uint8_t* p = &fb.color[i * 4];
  if (!std::isfinite(c.r + c.g + c.b + c.a)) g_nonfinite_fragments.fetch_add(1, std::memory_order_relaxed);
  for (int k = 0; k < 4; ++k) p[k] = to_unorm8(c[k]);
}

// Snapped to 1/256 pixel, as llvmpipe's 8 subpixel bits; nearbyint rounds half to even.
int64_t snap(double v) { return int64_t(std::nearbyint(v * 256.0)); }

}  // namespace

bool setup(const WindowVertex& va, const WindowVertex& vb, const WindowVertex& vc, const State& s, Triangle& t) {
  return setup({{{&va, &va.color, &va.sec}, {&vb, &vb.color, &vb.sec}, {&vc, &vc.color, &vc.sec}}}, s, t);
}

bool setup(const std::array<SetupVertex, 3>& sv, const State& s, Triangle& t) {
  const SetupVertex* v[3] = {&sv[0], &sv[1], &sv[2]};
  for (int i = 0; i < 3; ++i) {
    const WindowVertex& w = *v[i]->w;
    t.x[i] = w.snapped ? w.sx : snap(w.pos.x);
    t.y[i] = w.snapped ? w.sy : snap(w.pos.y);
  }
  // The box is kept within 16384 pixels of the framebuffer; draw_triangles clips it.
  bool swapped = false;
  if (!detail::setup_edges(t, 1 << 30, 1 << 30, &swapped)) return false;
  if (swapped) std::swap(v[1], v[2]);
  const glm::dvec3 pos[3] = {v[0]->w->pos, v[1]->w->pos, v[2]->w->pos};
  const double inv_w[3] = {v[0]->w->inv_w, v[1]->w->inv_w, v[2]->w->inv_w};
  const glm::dvec4* const color[3] = {v[0]->color, v[1]->color, v[2]->color};
  const glm::dvec4* const sec[3] = {v[0]->sec, v[1]->sec, v[2]->sec};
  const float x[3] = {float(pos[0].x), float(pos[1].x), float(pos[2].x)};
  const float yd[3] = {v[0]->w->y_down, v[1]->w->y_down, v[2]->w->y_down};
  const float z[3] = {float(pos[0].z), float(pos[1].z), float(pos[2].z)};
  detail::depth_plane(x, yd, z, swapped, t.z);
  return detail::setup_planes(t, pos, inv_w, color, sec, s.flat, s.add_secondary);
}

void draw_triangles(Framebuffer& fb, const std::vector<Triangle>* const* lists, size_t count, const State& s,
                    Workers& workers) {
  size_t total = 0;
  for (size_t i = 0; i < count; ++i) total += lists[i]->size();
  const int bands = std::max(1, std::min(total < 64 ? 1 : workers.size(), (fb.height + kBandRows - 1) / kBandRows));
  auto work = [&](int band) {
    if (band >= bands) return;
    const detail::Bands mine(band, bands);
    for (size_t i = 0; i < count; ++i)
      for (const Triangle& t : *lists[i]) {
        // Most triangles fall in one band: skip the others' without touching more of them.
        if (t.ymin / kBandRows == t.ymax / kBandRows && !mine.owns(std::clamp(t.ymin / kBandRows, 0, detail::Bands::kMax))) continue;
        Triangle c = t;  // clip the box to the framebuffer
        c.xmin = std::max(c.xmin, 0), c.ymin = std::max(c.ymin, 0);
        c.xmax = std::min(c.xmax, fb.width - 1), c.ymax = std::min(c.ymax, fb.height - 1);
        if (c.xmin <= c.xmax && c.ymin <= c.ymax) detail::rasterize(fb, c, s, mine, [] { return true; });
      }
  };
  if (bands == 1) return work(0);
  workers.run(work);
}

void draw_line(Framebuffer& fb, const WindowVertex& a, const WindowVertex& b, const State& s) {
  // llvmpipe draws a line as a parallelogram one pixel wide across its major axis, rasterized with
  // the triangle rules (left and bottom edges inclusive). Along the major axis a pixel belongs to
  // the line when its centre lies in [start, end): the diamond-exit rule, for thin lines.
  // Across it, a centre c is inside when c is in [p - 0.5, p + 0.5), that is pixel ceil(p) - 1.
  const double dx = b.pos.x - a.pos.x, dy = b.pos.y - a.pos.y;
  const bool x_major = std::abs(dx) >= std::abs(dy);
  const double a_major = x_major ? a.pos.x : a.pos.y, b_major = x_major ? b.pos.x : b.pos.y;
  const double d_major = b_major - a_major;
  if (d_major == 0) return;
  const double lo = std::min(a_major, b_major), hi = std::max(a_major, b_major);
  for (int i = int(std::ceil(lo - 0.5)); i + 0.5 < hi; ++i) {
    const double c = i + 0.5;
    if (c < lo) continue;
    const double t = (c - a_major) / d_major;
    const double minor = x_major ? a.pos.y + dy * t : a.pos.x + dx * t;
    const int j = int(std::ceil(minor)) - 1;
    const int px = x_major ? i : j, py = x_major ? j : i;
    glm::dvec4 col = a.color + (b.color - a.color) * t;
    if (s.add_secondary) col += glm::dvec4(glm::dvec3(a.sec + (b.sec - a.sec) * t), 0);
    write_fragment(fb, px, py, a.pos.z + (b.pos.z - a.pos.z) * t, col, s);
  }
}

void clear_band(Framebuffer& fb, const ClearRequest& c, int b) {
  const size_t first = size_t(b) * kBandRows * fb.width;
  const size_t n = size_t(std::min(kBandRows, fb.height - b * kBandRows)) * fb.width;
  if (c.color) {  // one pixel, then the filled part copied onto what follows it, doubling
    const glm::vec4& cc = c.clear_color;
    const uint8_t v[4] = {to_unorm8(cc.r), to_unorm8(cc.g), to_unorm8(cc.b), to_unorm8(cc.a)};
    uint8_t* p = &fb.color[first * 4];
    std::memcpy(p, v, 4);
    for (size_t done = 4; done < n * 4; done *= 2) std::memcpy(p + done, p, std::min(done, n * 4 - done));
  }
  if (c.depth) std::fill_n(&fb.depth[first], n, uint32_t(std::clamp(c.clear_depth, 0.0, 1.0) * 0xFFFFFF + 0.5));
}

void clear(Framebuffer& fb, const ClearRequest& c, Workers& workers) {
  workers.run([&](int b) { clear_band(fb, c, b); }, (fb.height + kBandRows - 1) / kBandRows);  // a band a share
}

}  // namespace ffc::raster
