#include "raster/raster.h"
#include "raster/fragment.h"
#include "raster/reference.h"
#include "raster/row_loop.h"
#include "pool/workers.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <stdexcept>
#include <string>

#include "raster/isa.h"
#if FFCOMPAT_X86
#include <xmmintrin.h>
#endif

namespace ffc::raster {

namespace detail {
bool g_llvmpipe_fma = true;
}

bool configure_llvmpipe_fma_from_environment() {
  // Read once: a process's llvmpipe does not change its mind.
  static const bool set = [] {
    const char* e = std::getenv("FFCOMPAT_LLVMPIPE_FMA");
    if (!e || !*e) return false;
    if (std::strcmp(e, "0") != 0 && std::strcmp(e, "1") != 0)
      throw std::invalid_argument(std::string("FFCOMPAT_LLVMPIPE_FMA=") + e + ": 1 (llvmpipe's multiply-adds fused, the default) or 0");
    set_llvmpipe_fma(*e == '1');
    return true;
  }();
  return set;
}

uint8_t to_unorm8(double c) {
  if (!(c > 0)) return 0;  // also NaN
  if (c >= 1) return 255;
  // In float, as llvmpipe: 0.3f * 255 is exactly 76.5 in float and goes to even, 76. Adding and
  // taking away 1.5 * 2^23 rounds to an integer, half to even, without a library call.
  const float v = float(c) * 255.0f + 12582912.0f;  // not folded: FP addition is not associative
  return uint8_t(v - 12582912.0f);
}

namespace {

// The clipper of Mesa's draw module (draw_pipe_clip.c), which both llvmpipe's drawing and
// feedback run, step for step and in the same arithmetic: float where the window is llvmpipe's
// (State::float_window), double otherwise.
template <typename T>
using V4 = glm::vec<4, T>;

template <typename T>
struct ClipVertex {
  V4<T> clip;
  V4<T> c[4];  // front, back, front_sec, back_sec
  T fog;       // the fog coordinate (Context::vertex), interpolated as the colours
  int source;  // the primitive's vertex this is, or -1: made by the clipper
};

// Mesa's interp(): dst = out + t (in - out), for the clip position and every colour.
template <typename T>
ClipVertex<T> interp(T t, const ClipVertex<T>& out, const ClipVertex<T>& in) {
  ClipVertex<T> r;
  r.clip = out.clip + t * (in.clip - out.clip);
  // Equal ends give that value: the same bits as the formula, but a -0 (a NaN colour clamped,
  // vertex_stage.cpp clamp_unlit, which Mesa interpolates as NaN and feeds back as 1) stays -0.
  for (int k = 0; k < 4; ++k)
    r.c[k] = glm::mix(out.c[k] + t * (in.c[k] - out.c[k]), out.c[k], glm::equal(out.c[k], in.c[k]));
  r.fog = out.fog + t * (in.fog - out.fog);
  r.source = -1;
  return r;
}

// Signed distance to view-volume plane i in draw's order (draw_context.c): x <= w, x >= -w,
// y <= w, y >= -w, z >= -w, z <= w. Mesa takes dot4(clip, plane) left to right; the terms with a
// zero coefficient add only a signed zero, so it is w - x or x + w exactly.
template <typename T>
T plane_dist(const V4<T>& c, int plane) {
  switch (plane) {
    case 0: return -c.x + c.w;
    case 1: return c.x + c.w;
    case 2: return -c.y + c.w;
    case 3: return c.y + c.w;
    case 4: return c.z + c.w;
    default: return -c.z + c.w;
  }
}

// A vertex's clipmask: bit i set when it lies outside plane i (draw_cliptest_tmp.h's tests).
template <typename T>
unsigned clipmask(const V4<T>& c) {
  unsigned m = 0;
  for (int i = 0; i < 6; ++i) m |= unsigned(plane_dist(c, i) < 0) << i;
  return m;
}

constexpr size_t kClipRoom = 10;  // a triangle clipped by six planes has at most nine vertices
template <typename T>
using ClipPolygon = Fixed<ClipVertex<T>, kClipRoom>;

// do_clip_tri: Sutherland-Hodgman over the planes that some vertex is outside of (a plane the
// clipmasks do not name is skipped even where a clip-made vertex falls an ulp outside it). A new
// vertex is interpolated from whichever end of the edge is nearer the plane, with t from the two
// distances, as Mesa does to keep shared edges watertight.
template <typename T, typename Made>
ClipPolygon<T> clip_polygon(ClipPolygon<T> in, unsigned mask, Made&& made) {
  while (mask && in.size() >= 3) {
    const int plane = __builtin_ctz(mask);
    mask &= mask - 1;
    ClipPolygon<T> out;
    const size_t n = in.size();
    size_t prev = 0;
    T dp_prev = plane_dist(in[0].clip, plane);
    if (!std::isfinite(dp_prev)) return {};  // a distance that overflows: Mesa discards the primitive
    for (size_t i = 1; i <= n; ++i) {
      const size_t cur = i % n;  // the first vertex again closes the polygon
      const T dp = plane_dist(in[cur].clip, plane);
      if (!std::isfinite(dp)) return {};
      // Rounding can make a polygon a hair concave and cross a plane more than twice: past the
      // room for one (which an exact triangle never needs), the primitive is dropped, as Mesa
      // drops one past MAX_CLIPPED_VERTICES.
      const bool keep = dp_prev >= 0, different_sign = keep ? dp < 0 : !(dp < 0);
      if (out.size() + keep + different_sign > kClipRoom) return {};
      if (keep) out.push_back(in[prev]);
      if (different_sign) {
        const T denom = dp - dp_prev;
        const ClipVertex<T>&v = in[cur], &p = in[prev];
        if (dp < 0)  // going out
          out.push_back(-dp < dp_prev ? interp(dp / denom, v, p) : interp(-dp_prev / denom, p, v));
        else  // coming back in
          out.push_back(-dp_prev < dp ? interp(-dp_prev / denom, p, v) : interp(dp / denom, v, p));
        made(out[out.size() - 1]);
      }
      prev = cur;
      dp_prev = dp;
    }
    in = out;
  }
  return in;
}

// do_clip_line: the line's two ends move in by the largest t of any plane, from each end; a line
// whose two t add up to 1 or more is dropped (a zero-length remainder included).
template <typename T, typename Made>
ClipPolygon<T> clip_line(const ClipVertex<T>& a, const ClipVertex<T>& b, Made&& made) {
  const unsigned ma = clipmask(a.clip), mb = clipmask(b.clip);
  T t0 = 0, t1 = 0;
  for (unsigned mask = ma | mb; mask; mask &= mask - 1) {
    const int plane = __builtin_ctz(mask);
    const T dp0 = plane_dist(a.clip, plane), dp1 = plane_dist(b.clip, plane);
    if (!std::isfinite(dp0) || !std::isfinite(dp1)) return {};  // as Mesa, discarded
    if (dp1 < 0) {
      const T t = dp1 / (dp1 - dp0);
      t1 = t1 > t ? t1 : t;
    }
    if (dp0 < 0) {
      const T t = dp0 / (dp0 - dp1);
      t0 = t0 > t ? t0 : t;
    }
    if (t0 + t1 >= 1) return {};
  }
  ClipPolygon<T> out{ma ? interp(t0, a, b) : a, mb ? interp(t1, b, a) : b};
  if (ma) made(out[0]);
  if (mb) made(out[1]);
  return out;
}

}  // namespace

namespace {
// nearbyint(v) for a float in the current (round-to-even) mode: on x86 one cvtss2si when in range.
int64_t round_even(float v) {
#if FFCOMPAT_X86
  if (std::fabs(v) < 0x1p30f) return _mm_cvtss_si32(_mm_set_ss(v));
#endif
  return int64_t(std::nearbyint(v));
}
}  // namespace

// The multiply-adds of llvmpipe's viewport transform (draw_llvm.c, llvm.fmuladd: llvmpipe_fma()).
// On x86 built twice, with and without FMA instructions (chosen at load time): std::fma is one
// instruction where the CPU has it, a library call otherwise; the same bits either way. (AArch64
// always has it.) Not under ThreadSanitizer: the chooser runs as the program loads, before the
// sanitizer's runtime, and its instrumented code crashes there.
#if FFCOMPAT_X86 && !defined(__SANITIZE_THREAD__)
__attribute__((target_clones("fma", "default")))
#endif
FloatWindow map_float(const glm::vec4& clip, const State& s) {
  const glm::ivec4 vp = s.viewport;
  const float fiw = 1.0f / clip.w;
  const float nx = clip.x * fiw, ny = clip.y * fiw, nz = clip.z * fiw;
  const float hw = float(vp[2]) * 0.5f, hh = float(vp[3]) * 0.5f;
  const float x = llvmpipe_mul_add(nx, hw, float(vp[0]) + hw);
  const float y_down = llvmpipe_mul_add(ny, -hh, float(s.fb_height) - (float(vp[1]) + hh));
  const float dn = float(s.depth_range.x), df = float(s.depth_range.y);
  FloatWindow w;
  w.x = x, w.y = float(s.fb_height) - y_down, w.y_down = y_down, w.z = llvmpipe_mul_add(nz, (df - dn) * 0.5f, (df + dn) * 0.5f);
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
    w.fx = float(w.pos.x);
    return w;
  }
  const FloatWindow f = map_float(glm::vec4(clip), s);
  w.pos = {f.x, f.y, f.z};
  w.snapped = true;
  w.sx = f.sx, w.sy = f.sy, w.y_down = f.y_down;
  w.fx = f.x;
  return w;
}

bool sliver(const WindowVertex& a, const WindowVertex& b, const WindowVertex& c) {
  const float x0 = float(a.pos.x), y0 = float(a.pos.y);
  const float dx01 = x0 - float(b.pos.x), dy01 = y0 - float(b.pos.y);
  const float dx20 = float(c.pos.x) - x0, dy20 = float(c.pos.y) - y0;
  const float dx12 = float(c.pos.x) - float(b.pos.x), dy12 = float(c.pos.y) - float(b.pos.y);
  const float det = dx01 * dy20 - dy01 * dx20;
  const float longest = std::max({dx01 * dx01 + dy01 * dy01, dx20 * dx20 + dy20 * dy20, dx12 * dx12 + dy12 * dy12});
  return std::fabs(det) < 1e-4f * longest;
}

void count_if_sliver(const WindowVertex& a, const WindowVertex& b, const WindowVertex& c, const State& s) {
  if (s.counters && !s.flat && sliver(a, b, c)) s.counters->clipped_slivers.fetch_add(1, std::memory_order_relaxed);
}

bool back_facing_triangle(const glm::dvec4& a, const glm::dvec4& b, const glm::dvec4& c, const State& s) {
  // The sign of the homogeneous determinant is the window orientation whatever the w's signs.
  const double area = a.x * (b.y * c.w - c.y * b.w) - b.x * (a.y * c.w - c.y * a.w) + c.x * (a.y * b.w - b.y * a.w);
  return (s.front_face == GL_CCW) != (area > 0);
}

bool culled(bool back, const State& s) {
  return s.cull && (s.cull_mode == GL_FRONT_AND_BACK || (s.cull_mode == GL_BACK) == back);
}

namespace {

// The window position of a clip-made vertex as draw_pipe_clip.c's interp() computes it: 1/w, then
// x / w scaled and translated in plain float multiplies and adds (no fused multiply-add, unlike
// the vertex path's viewport transform in map_float), then snapped as map_float snaps.
WindowVertex map_clip_made(const glm::vec4& c, const State& s) {
  const glm::ivec4 vp = s.viewport;
  const float oow = 1.0f / c.w;
  const float hw = float(vp[2]) * 0.5f, hh = float(vp[3]) * 0.5f;
  const float dn = float(s.depth_range.x), df = float(s.depth_range.y);
  const float x = c.x * oow * hw + (float(vp[0]) + hw);
  const float y_down = c.y * oow * -hh + (float(s.fb_height) - (float(vp[1]) + hh));
  const float z = c.z * oow * ((df - dn) * 0.5f) + (df + dn) * 0.5f;
  WindowVertex w;
  w.inv_w = oow;
  w.pos = {x, float(s.fb_height) - y_down, z};
  w.y_down = y_down, w.fx = x;
  w.snapped = true;
  w.sx = round_even((x - 0.5f) * 256.0f) + 128;
  w.sy = int64_t(s.fb_height - 1) * 256 - round_even((y_down - 0.5f) * 256.0f) + 128;
  return w;
}

template <typename T>
WindowPolygon clip_and_map_in(const Vertex* prim, size_t count, const State& s, const Vertex* provoking,
                              bool is_line, bool back, ClipTemps* feedback) {
  ClipPolygon<T> cv;
  auto colours = [](const Vertex& v, glm::vec<4, T>* c) {
    c[0] = glm::vec<4, T>(v.front), c[1] = glm::vec<4, T>(v.back);
    c[2] = glm::vec<4, T>(v.front_sec), c[3] = glm::vec<4, T>(v.back_sec);
  };
  for (size_t i = 0; i < count; ++i) {
    ClipVertex<T> v;
    v.clip = glm::vec<4, T>(prim[i].clip);
    // Drawing flat: every vertex carries the provoking one's colours (the rasterizer reads them
    // from one vertex; which, the fan below decides). Feedback reports vertices, see below.
    colours(s.flat && provoking && !feedback ? *provoking : prim[i], v.c);
    v.fog = T(prim[i].fog);
    v.source = int(i);
    cv.push_back(v);
  }
  // Feedback: Mesa's clipper writes each vertex it makes into its next temporary vertex
  // (draw_pipe_clip.c, stage tmp[], from 0 for each primitive). Smooth, the colours are
  // interpolated there; flat, they are constant attributes that interp() leaves alone, so a
  // clip-made vertex reports whatever colours its temporary last held, from an earlier primitive.
  unsigned tmpnr = 0;
  auto slot = [&](glm::vec<4, T>* c, bool load) {
    const unsigned i = std::min<unsigned>(tmpnr++, ClipTemps::kSlots - 1);
    glm::vec4* t = feedback->c[i];
    if (load && !feedback->written[i]) feedback->read_unwritten = true;
    if (!load) feedback->written[i] = true;
    for (int k = 0; k < 4; ++k)
      if (load) c[k] = glm::vec<4, T>(t[k]);
      else t[k] = glm::vec4(c[k]);
  };
  auto made = [&](ClipVertex<T>& v) {
    if (feedback) slot(v.c, s.flat);
  };
  ClipPolygon<T> clipped;
  if (is_line) {
    if (clipmask(cv[0].clip) & clipmask(cv[1].clip)) return {};  // both ends outside one plane
    clipped = clip_line(cv[0], cv[1], [](ClipVertex<T>&) {});
    // A clip-made end is temporary 0 or 1, after the end it replaces. Flat, it takes the
    // provoking (second) vertex's colours (do_clip_line's copy_flat); an end that was not
    // clipped keeps its own.
    for (unsigned end = 0; end < clipped.size(); ++end) {
      ClipVertex<T>& v = clipped[end];
      if (v.source >= 0) continue;
      if (s.flat && provoking && feedback) colours(*provoking, v.c);
      if (feedback) tmpnr = end, slot(v.c, false);
    }
  } else {
    unsigned all = ~0u, any = 0;
    for (const ClipVertex<T>& v : cv) {
      const unsigned m = clipmask(v.clip);
      all &= m, any |= m;
    }
    if (all) return {};  // every vertex outside one plane
    clipped = clip_polygon(cv, any, made);
    if (clipped.size() < 3) return {};
    // Feedback, flat: do_clip_tri copies the polygon's first vertex, which ends every triangle of
    // its fan, into the next temporary with the provoking vertex's colours, unless it is the
    // provoking vertex itself; the others keep theirs (own, or their temporary's).
    if (feedback && s.flat && provoking && clipped[0].source != int(count) - 1)
      colours(*provoking, clipped[0].c), slot(clipped[0].c, false);
  }
  for (const ClipVertex<T>& v : clipped)  // e.g. w ~ 1e-40: 1/w is no float, nor are the positions
    if (!w_mappable(double(v.clip.w))) return {};
  WindowPolygon out;
  const bool use_back = back && s.two_side;
  for (const ClipVertex<T>& v : clipped) {
    WindowVertex w = v.source >= 0 || !s.float_window ? map_to_window(v.source >= 0 ? prim[v.source].clip : glm::dvec4(v.clip), s)
                                                      : map_clip_made(glm::vec4(v.clip), s);
    w.color = glm::dvec4(use_back ? v.c[1] : v.c[0]);
    w.sec = glm::dvec4(use_back ? v.c[3] : v.c[2]);
    w.fog = v.source >= 0 ? prim[v.source].fog : double(v.fog);
    out.push_back(w);
  }
  return out;
}

}  // namespace

WindowPolygon clip_and_map(const Vertex* prim, size_t count, const State& s, const Vertex* provoking, bool is_line,
                           bool* back_facing, ClipTemps* feedback) {
  // A NaN or infinite clip coordinate (unspecified input, GL 2.1 section 2.1.1) has no place in the
  // window: the primitive is dropped, so nothing non-finite reaches setup or feedback.
  for (size_t i = 0; i < count; ++i) {
    const glm::dvec4& c = prim[i].clip;
    if (!(std::isfinite(c.x) && std::isfinite(c.y) && std::isfinite(c.z) && std::isfinite(c.w))) return {};
  }
  // Facing is decided before clipping, from the whole primitive, in window orientation.
  bool back = false, back_colours = false;
  if (!is_line && count >= 3) {
    back = back_facing_triangle(prim[0].clip, prim[1].clip, prim[2].clip, s);
    if (culled(back, s)) return {};
    // Mesa's two-side stage takes a triangle of zero area as front-facing (gl_rules.h), clipped or
    // not (measured, seed 271828 stream 2682: a degenerate quad from elements with a vertex outside
    // the view volume fed back with the front colours; repro zero_area_two_side_clipped.txt).
    const glm::dvec4 &a = prim[0].clip, &b = prim[1].clip, &c = prim[2].clip;
    const double area = a.x * (b.y * c.w - c.y * b.w) - b.x * (a.y * c.w - c.y * a.w) + c.x * (a.y * b.w - b.y * a.w);
    back_colours = back && area != 0;
  }
  if (back_facing) *back_facing = back;
  return s.float_window ? clip_and_map_in<float>(prim, count, s, provoking, is_line, back_colours, feedback)
                        : clip_and_map_in<double>(prim, count, s, provoking, is_line, back_colours, feedback);
}

namespace {

void write_fragment(Framebuffer& fb, int x, int y, double z, const glm::dvec4& c, const State& s) {
  if (x < 0 || y < 0 || x >= fb.width || y >= fb.height) return;
  if (!detail::scissor_pass(s.ops, x, y) || !detail::alpha_pass(s.ops, c.a)) return;
  const size_t i = size_t(y) * fb.width + x;
  const uint32_t zi = detail::depth24(float(z));  // converted as a triangle's
  if (s.depth_test) {
    if (!detail::depth_pass(s.depth_func, zi, fb.depth[i])) return;
    if (s.ops.depth_write) fb.depth[i] = zi;
  }
  if (!std::isfinite(c.r + c.g + c.b + c.a)) count_nonfinite(s, 1);
  detail::write_color(s.ops, &fb.color[i * 4], c);
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
  if (s.fragment_ops()) {
    t.offset = s.offset_fill ? detail::polygon_offset(x, yd, z, swapped, s) : 0.0f;
    if (s.fog) {
      // The fog coordinate is a perspective-correct varying like the colours, whatever the shade
      // model (flat shading applies to colours only, GL 2.1 section 2.14.7).
      double p[3];
      const detail::PlaneSolver make(pos);
      make(v[0]->w->fog * inv_w[0], v[1]->w->fog * inv_w[1], v[2]->w->fog * inv_w[2], p);
      for (int i = 0; i < 3; ++i) t.fog[i] = float(p[i]);
      make(inv_w[0], inv_w[1], inv_w[2], p);
      for (int i = 0; i < 3; ++i) t.fog_w[i] = float(p[i]);
    }
  }
  return detail::setup_planes(t, pos, inv_w, color, sec, s.flat, s.add_secondary);
}

void draw_triangles(Framebuffer& fb, const std::vector<Triangle>* const* lists, size_t count, const State& s,
                    pool::Workers& workers) {
  ++fb.writes;
  if (reference_rasterizer() && !s.fragment_ops()) {
    for (size_t i = 0; i < count; ++i)
      for (const Triangle& t : *lists[i]) draw_reference(fb, t, s);
    return;
  }
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
        if (s.ops.scissor) {  // and to the scissor box
          c.xmin = std::max(c.xmin, s.ops.scissor_x0), c.ymin = std::max(c.ymin, s.ops.scissor_y0);
          c.xmax = std::min(c.xmax, s.ops.scissor_x1 - 1), c.ymax = std::min(c.ymax, s.ops.scissor_y1 - 1);
        }
        if (c.xmin > c.xmax || c.ymin > c.ymax) continue;
        // Fog and polygon offset are per-fragment operations only the scalar loop has.
        if (s.fragment_ops()) detail::rasterize_fragment_ops(fb, c, s, mine);
        else detail::rasterize(fb, c, s, mine, [] { return true; });
      }
  };
  if (bands == 1) return work(0);
  workers.run(work);
}

// Fog as Mesa 22.3's fixed-function fragment program applies it, with the parameters of
// prog_statevars.c STATE_FOG_PARAMS_OPTIMIZED: factor f from the fragment's fog coordinate c,
// linear c * (-1 / (end - start)) + end / (end - start), exp 2^-(c * density / ln 2), exp2
// 2^-((c * density / sqrt(ln 2))^2), clamped to [0, 1]; then rgb = fog colour * (1 - f) + rgb * f,
// alpha untouched (GL 2.1 section 3.10).
glm::dvec4 apply_fog(const glm::dvec4& c, float fog_coord, const State& s) {
  const float* p = s.fog_params;
  float f;
  if (s.fog_mode == GL_LINEAR) f = fog_coord * p[0] + p[1];
  else if (s.fog_mode == GL_EXP) f = std::exp2(-(fog_coord * p[2]));
  else {
    const float t = fog_coord * p[3];
    f = std::exp2(-(t * t));
  }
  f = f > 0 ? (f < 1 ? f : 1.0f) : 0.0f;  // saturate; a NaN to 0
  glm::dvec4 out = c;
  for (int k = 0; k < 3; ++k) out[k] = s.fog_color[k] * (1.0f - f) + float(c[k]) * f;
  return out;
}

namespace {

// llvmpipe's subpixel_snap: util_iround(256 * v), which on x86-64 rounds half away from zero by
// adding 0.5 in float (u_math.h), unlike the triangle path's round-to-even (see map_float).
int64_t snap_away(float v) {
  const float f = v * 256.0f;
  if (!(std::fabs(f) < 0x1p60f)) return 0;  // far outside; the callers clip first
  return f >= 0 ? int64_t(f + 0.5f) : int64_t(f - 0.5f);
}

glm::dvec4 summed(const glm::dvec4& c, const glm::dvec4& sec, const State& s) {
  return s.add_secondary ? c + glm::dvec4(glm::dvec3(sec), 0) : c;
}

}  // namespace

void draw_fragment(Framebuffer& fb, int x, int y, double z, const glm::dvec4& color, const State& s) {
  write_fragment(fb, x, y, z, color, s);
}

void draw_point(Framebuffer& fb, const WindowVertex& v, const State& s) {
  ++fb.writes;
  // GL 2.1 section 3.3.1 (non-antialiased points), as llvmpipe's legacy-point path computes it in
  // 1/256 pixel, rows counted down: size rounded to a whole number of pixels, at least 1 (half
  // rounds down: (256 size + 127) truncated); the square's first column and row from the snapped
  // centre (an odd size around the pixel holding it, an even one around the nearest pixel corner).
  // Rows come one step lower in 1/256 pixel (llvmpipe's bottom-edge `adj`), so a centre exactly
  // on a row boundary falls in the row above it in GL terms.
  const float size = std::min(s.point_size, 255.0f);  // LP_MAX_POINT_WIDTH; NaN: 1 below
  const int64_t width = std::max<int64_t>(1, ((snap_away(size > 0 ? size : 1) + 127) & ~int64_t(255)) >> 8);
  const int64_t sx = snap_away(v.fx), sy = snap_away(v.y_down) - 1;
  int64_t x0, y0;
  if (width & 1) {
    x0 = (sx >> 8) - (width - 1) / 2, y0 = (sy >> 8) - (width - 1) / 2;
  } else {
    x0 = ((sx + 128) >> 8) - width / 2, y0 = ((sy + 128) >> 8) - width / 2;
  }
  const glm::dvec4 col = s.fog ? apply_fog(summed(v.color, v.sec, s), float(v.fog), s) : summed(v.color, v.sec, s);
  for (int64_t yd = std::max<int64_t>(y0, 0); yd < std::min<int64_t>(y0 + width, fb.height); ++yd)
    for (int64_t x = std::max<int64_t>(x0, 0); x < std::min<int64_t>(x0 + width, fb.width); ++x)
      write_fragment(fb, int(x), fb.height - 1 - int(yd), v.pos.z, col, s);
}

namespace {
void draw_solid_line(Framebuffer& fb, const WindowVertex& a, const WindowVertex& b, const State& s);

// A point of the line a-b at t, as the draw module's stipple stage makes one (draw_pipe_stipple.c
// screen_interp): every attribute, window position included, linear in t, in float.
WindowVertex along(const WindowVertex& a, const WindowVertex& b, float t) {
  auto lerp = [t](double u, double v) { return double(float(u) + t * (float(v) - float(u))); };
  WindowVertex w = a;
  w.fx = float(lerp(a.fx, b.fx)), w.y_down = float(lerp(a.y_down, b.y_down));
  w.pos = {w.fx, lerp(a.pos.y, b.pos.y), lerp(a.pos.z, b.pos.z)};
  w.inv_w = lerp(a.inv_w, b.inv_w);
  for (int k = 0; k < 4; ++k) w.color[k] = lerp(a.color[k], b.color[k]), w.sec[k] = lerp(a.sec[k], b.sec[k]);
  w.fog = lerp(a.fog, b.fog);
  return w;
}
}  // namespace

// The stipple as Mesa's draw module applies it before llvmpipe's line rasterizer: one pattern bit
// per pixel of the line's length along its major axis (ceil of the larger of |dx|, |dy|), the
// counter running on from the previous segment of a strip; each run of set bits drawn as a line
// of its own between the points at start / length and end / length.
void draw_line(Framebuffer& fb, const WindowVertex& a, const WindowVertex& b, const State& s) {
  if (!s.line_stipple || !s.stipple_counter) return draw_solid_line(fb, a, b, s);
  ++fb.writes;
  const float length = std::max(std::fabs(a.fx - b.fx), std::fabs(a.y_down - b.y_down));
  const int n = std::isfinite(length) ? int(std::ceil(length)) : 0;
  int& counter = *s.stipple_counter;
  bool on = false;
  float start = 0;
  for (int i = 0; i < n; ++i, ++counter) {
    const bool bit = (s.stipple_pattern >> ((counter / s.stipple_factor) & 15)) & 1;
    if (bit == on) continue;
    if (on && start != float(i)) draw_solid_line(fb, start > 0 ? along(a, b, start / length) : a, along(a, b, float(i) / length), s);
    if (!on) start = float(i);
    on = bit;
  }
  if (on && start < length) draw_solid_line(fb, start > 0 ? along(a, b, start / length) : a, b, s);
}

namespace {
void draw_solid_line(Framebuffer& fb, const WindowVertex& a, const WindowVertex& b, const State& s) {
  ++fb.writes;
  // llvmpipe's lp_setup_line.c, non-rectangular (GL legacy) lines: a parallelogram `width` pixels
  // across the major axis whose two ends are moved by half a pixel along it where the
  // diamond-exit rule (GL 2.1 section 3.4.1) wants the end pixel and plain coverage would not
  // give it (or the reverse), rasterized with four edge functions in 1/256 pixel and the
  // triangles' ownership (left and bottom edges inclusive). Coordinates here are llvmpipe's: x,
  // rows counted down (y_down), pixel centres at whole numbers once 0.5 is taken away.
  const float ax = a.fx, ay = a.y_down, bx = b.fx, by = b.y_down;
  const float dx = ax - bx, dy = ay - by;
  const float area = dx * dx + dy * dy;
  if (area == 0 || !std::isfinite(area)) return;
  // Mesa's state tracker clamps the width to llvmpipe's aliased range [1, 255]; a NaN passes its
  // clamp, and llvmpipe draws it 1 wide as std::max(1, NaN) gives here.
  const float fwidth = std::min(std::max(1.0f, s.line_width), 255.0f);
  const int64_t half = (fwidth >= 0 ? int64_t(fwidth + 0.5f) : 1) * 256 / 2;  // util_iround(width) * 256 / 2
  const float x1diff = ax - std::floor(ax) - 0.5f, y1diff = ay - std::floor(ay) - 0.5f;
  float x2diff = bx - std::floor(bx) - 0.5f, y2diff = by - std::floor(by) - 0.5f;
  auto nonneg = [](float v) { return v >= 0; };
  auto frac = [](float v) { return v - std::floor(v); };
  float xo = 0, yo = 0, xoe = 0, yoe = 0;  // the moves of the first and the second end
  float p1x = ax, p1y = ay, p2x = bx, p2y = by;  // after the swap: first end right (x-major) or up
  int64_t x[4], y[4];
  const bool x_major = std::fabs(dx) >= std::fabs(dy);
  if (x_major) {
    const float dydx = dy / dx;
    if (y2diff == -0.5f && dy < 0) y2diff = 0.5f;
    bool draw_start, draw_end;  // whether the diamond-exit rule wants the end pixels
    if (std::fabs(x1diff) + std::fabs(y1diff) < 0.5f) draw_start = true;
    else if (nonneg(x1diff) == nonneg(-dx)) draw_start = false;
    else if (nonneg(-y1diff) != nonneg(dy)) draw_start = true;
    else {
      const float yi = frac(ay) + x1diff * dydx;
      draw_start = yi < 1 && yi > 0;
    }
    if (std::fabs(x2diff) + std::fabs(y2diff) < 0.5f) draw_end = false;
    else if (nonneg(x2diff) != nonneg(-dx)) draw_end = false;
    else if (nonneg(-y2diff) == nonneg(dy)) draw_end = true;
    else {
      const float yi = frac(by) + x2diff * dydx;
      draw_end = yi < 1 && yi > 0;
    }
    if (dx < 0) {  // the first end on the left: the ends exchanged, each end's move kept with it
      std::swap(p1x, p2x), std::swap(p1y, p2y);
      if ((x1diff <= 0) != draw_start) xoe = -x1diff - 0.5f, yoe = xoe * dydx;
      if ((x2diff > 0) != draw_end) xo = -x2diff - 0.5f, yo = xo * dydx;
    } else {
      if ((x1diff > 0) != draw_start) xo = -x1diff + 0.5f, yo = xo * dydx;
      if ((x2diff <= 0) != draw_end) xoe = -x2diff + 0.5f, yoe = xoe * dydx;
    }
    x[0] = x[3] = snap_away(p1x + xo - 0.5f), x[1] = x[2] = snap_away(p2x + xoe - 0.5f);
    const int64_t y1 = snap_away(p1y + yo - 0.5f), y2 = snap_away(p2y + yoe - 0.5f);
    y[0] = y1 - half, y[1] = y2 - half, y[2] = y2 + half, y[3] = y1 + half;
  } else {
    const float dxdy = dx / dy;
    if (x2diff == -0.5f && dx < 0) x2diff = 0.5f;
    bool draw_start, draw_end;
    if (std::fabs(x1diff) + std::fabs(y1diff) < 0.5f) draw_start = true;
    else if (nonneg(-y1diff) == nonneg(dy)) draw_start = false;
    else if (nonneg(x1diff) != nonneg(-dx)) draw_start = true;
    else {
      const float xi = frac(ax) + y1diff * dxdy;
      draw_start = xi < 1 && xi > 0;
    }
    if (std::fabs(x2diff) + std::fabs(y2diff) < 0.5f) draw_end = false;
    else if (nonneg(-y2diff) != nonneg(dy)) draw_end = false;
    else if (nonneg(x2diff) == nonneg(-dx)) draw_end = true;
    else {
      const float xi = frac(bx) + y2diff * dxdy;
      draw_end = xi < 1 && xi >= 0;  // >= here, > above: as llvmpipe
    }
    // Bottom-edge rule (GL's bottom is llvmpipe's bottom too, rows counted down).
    if (dy > 0) {
      std::swap(p1x, p2x), std::swap(p1y, p2y);
      if ((y1diff >= 0) != draw_start) yoe = -y1diff + 0.5f, xoe = yoe * dxdy;
      if ((y2diff < 0) != draw_end) yo = -y2diff + 0.5f, xo = yo * dxdy;
    } else {
      if ((y1diff < 0) != draw_start) yo = -y1diff - 0.5f, xo = yo * dxdy;
      if ((y2diff >= 0) != draw_end) yoe = -y2diff - 0.5f, xoe = yoe * dxdy;
    }
    y[0] = y[3] = snap_away(p1y + yo - 0.5f), y[1] = y[2] = snap_away(p2y + yoe - 0.5f);
    const int64_t x1 = snap_away(p1x + xo - 0.5f), x2 = snap_away(p2x + xoe - 0.5f);
    x[0] = x1 - half, x[1] = x2 - half, x[2] = x2 + half, x[3] = x1 + half;
  }
  // Edge i from corner i to i+1; a pixel centre P is inside when every edge function is positive,
  // or zero on an edge that owns its pixels (left edges; bottom edges, llvmpipe's bottom_edge_rule).
  int64_t dcdx[4], dcdy[4], own[4];
  for (int i = 0; i < 4; ++i) {
    const int j = (i + 1) & 3;
    dcdx[i] = y[i] - y[j], dcdy[i] = x[i] - x[j];
    own[i] = dcdx[i] < 0 || (dcdx[i] == 0 && dcdy[i] < 0);
  }
  const int64_t xmin = std::max<int64_t>(0, (std::min({x[0], x[1], x[2], x[3]}) >> 8) - 1);
  const int64_t xmax = std::min<int64_t>(fb.width - 1, (std::max({x[0], x[1], x[2], x[3]}) >> 8) + 1);
  const int64_t ymin = std::max<int64_t>(0, (std::min({y[0], y[1], y[2], y[3]}) >> 8) - 1);
  const int64_t ymax = std::min<int64_t>(fb.height - 1, (std::max({y[0], y[1], y[2], y[3]}) >> 8) + 1);
  // Attributes as llvmpipe's line setup: along the major axis only (the "wide-lines formula"),
  // from the ends in their given order, in float; colours perspective-correct through 1/w, depth
  // linear.
  const float inv_area = 1.0f / area;
  const float idx = x_major ? dx * (1.0f + (dy / dx) * (dy / dx)) : 0.0f;
  const float idy = x_major ? 0.0f : dy * (1.0f + (dx / dy) * (dx / dy));
  struct Plane {
    float a0, ax, ay;
    float at(float X, float Y) const { return a0 + ax * X + ay * Y; }
  };
  auto plane = [&](float a1, float a2) {
    const float d = a1 - a2;
    Plane p;
    p.ax = d * idx * inv_area, p.ay = d * idy * inv_area;
    p.a0 = a1 - (p.ax * (ax - 0.5f) + p.ay * (ay - 0.5f));
    return p;
  };
  const float w1 = float(a.inv_w), w2 = float(b.inv_w);
  const Plane zp = plane(float(a.pos.z), float(b.pos.z)), wp = plane(w1, w2);
  const Plane fp = plane(float(a.fog) * w1, float(b.fog) * w2);  // fog coordinate / w
  Plane cp[8];
  for (int k = 0; k < 4; ++k) {
    cp[k] = plane(float(a.color[k]) * w1, float(b.color[k]) * w2);
    cp[4 + k] = plane(float(a.sec[k]) * w1, float(b.sec[k]) * w2);
  }
  for (int64_t yd = ymin; yd <= ymax; ++yd)
    for (int64_t xp = xmin; xp <= xmax; ++xp) {
      const int64_t px = xp * 256, py = yd * 256;
      bool in = true;
      for (int i = 0; i < 4 && in; ++i) in = dcdx[i] * (x[i] - px) - dcdy[i] * (y[i] - py) + own[i] > 0;
      if (!in) continue;
      const float X = float(xp), Y = float(yd);
      glm::dvec4 col;
      if (s.flat) {
        col = summed(b.color, b.sec, s);  // clip_and_map gave both ends the provoking colours
      } else {
        const float w = 1.0f / wp.at(X, Y);
        glm::dvec4 c, sc;
        for (int k = 0; k < 4; ++k) c[k] = cp[k].at(X, Y) * w, sc[k] = cp[4 + k].at(X, Y) * w;
        col = summed(c, sc, s);
      }
      if (s.fog) col = apply_fog(col, fp.at(X, Y) / wp.at(X, Y), s);
      // Depth as the fragment shader interpolates it, two fused multiply-adds (detail::depth_at):
      // a line's end on a triangle is a tie decided by these bits (seed 000's axes on the cube).
      const float zplane[3] = {zp.a0, zp.ax, zp.ay};
      write_fragment(fb, int(xp), fb.height - 1 - int(yd), detail::depth_at(zplane, 1, X, Y), col, s);
    }
}

}  // namespace

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
  if (c.depth) std::fill_n(&fb.depth[first], n, c.depth24());
}

void clear_masked(Framebuffer& fb, const ClearRequest& c, const State::Ops& ops) {
  ++fb.writes;
  const int x0 = ops.scissor ? std::max(ops.scissor_x0, 0) : 0, y0 = ops.scissor ? std::max(ops.scissor_y0, 0) : 0;
  const int x1 = ops.scissor ? std::min(ops.scissor_x1, fb.width) : fb.width;
  const int y1 = ops.scissor ? std::min(ops.scissor_y1, fb.height) : fb.height;
  const glm::vec4& cc = c.clear_color;
  const uint8_t v[4] = {to_unorm8(cc.r), to_unorm8(cc.g), to_unorm8(cc.b), to_unorm8(cc.a)};
  const uint32_t z = c.depth24();
  for (int y = y0; y < y1; ++y)
    for (int x = x0; x < x1; ++x) {
      const size_t i = size_t(y) * fb.width + x;
      if (c.color)
        for (int k = 0; k < 4; ++k)
          if (ops.color_mask >> k & 1) fb.color[i * 4 + k] = v[k];
      if (c.depth && ops.depth_write) fb.depth[i] = z;
    }
}

void clear(Framebuffer& fb, const ClearRequest& c, pool::Workers& workers) {
  ++fb.writes;
  workers.run([&](int b) { clear_band(fb, c, b); }, (fb.height + kBandRows - 1) / kBandRows);  // a band a share
}

}  // namespace ffc::raster
