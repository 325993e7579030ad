// Primitive assembly on the general path (GL 2.1 sections 2.6.1 and 2.15 to 3.5): the vertices
// of a draw or a glBegin/glEnd assembled into points, lines and triangles, clipped, culled and
// set up for the rasterizer, or handed to feedback (feedback.cpp).
#include <array>
#include <atomic>
#include <initializer_list>
#include <vector>

#include "state/context.h"
#include "state/gl_rules.h"

namespace ffc::state {

// One flush of the general path: the settings fixed for its primitives and the steps that turn
// the vertices in Context::verts_ (named through Context::elements_ when drawn from elements)
// into triangles in Context::triangles_, lines and points drawn at once, or feedback.
class Assembly {
 public:
  explicit Assembly(Context& c) : c_(c), rs_(c.raster_state()), feedback_(c.render_mode_ != GL_RENDER) {}
  void run();

 private:
  void assemble_and_draw();
  // A triangle's temporaries: its vertices as fed back, or as handed to the clipper.
  struct Scratch {
    raster::WindowVertex inside[3];
    raster::Vertex prim[3];
  };
  size_t index(size_t i) const { return c_.elements_.empty() ? i : size_t(c_.elements_[i]); }
  const raster::Vertex& at(size_t i) const { return c_.verts_[index(i)]; }
  void note_smooth();
  void map_inside();
  void triangle(size_t i0, size_t i1, size_t i2, size_t provoking, std::vector<raster::Triangle>& out,
                Scratch& scratch);
  void line_or_point(std::initializer_list<size_t> idx, size_t provoking, GLenum kind);
  bool clip_and_draw(const raster::Vertex& a, const raster::Vertex& b, const raster::Vertex& provoking, GLenum kind);
  bool unfilled_triangle(const size_t v[3], size_t provoking);
  void emit(std::initializer_list<size_t> idx, size_t provoking, GLenum kind, unsigned edges = 7, bool reset = true);
  void assemble(size_t n);
  void triangles_on_threads(size_t n);
  void draw_held_triangles();

  Context& c_;
  const raster::State rs_;
  const bool feedback_;
  // Mesa's draw module runs its pipeline (feedback, glPolygonMode's unfilled stage, and llvmpipe's
  // polygon stipple stage, which GL_POLYGON_STIPPLE puts in it even with the all-ones pattern, the
  // only one soft offers): quads, quad strips and polygons take its decomposition. Measured (seed
  // 264575 stream 13881488703804146128, repro quad_strip_stipple_split.txt): a smooth quad strip
  // with GL_POLYGON_STIPPLE on is split as in feedback.
  const bool pipeline_ = feedback_ || c_.unfilled() || c_.enabled_state(GL_POLYGON_STIPPLE) == 1;
  // The triangle being emitted: which of its edges (bit k: vertex k to k + 1) are edges of the
  // polygon it comes from, and whether it starts a polygon (a new stipple pattern).
  unsigned edges_ = 7;
  bool reset_ = true;
  bool offset_stage_ = false;  // feedback through the offset stage of Mesa's draw module
  bool zero_depth_ = false;    // the points or lines of a zero-area triangle the offset stage made NaN (unfilled_triangle)
  bool any_outside_ = false;   // a vertex of a whole primitive lies outside the view volume
  // A smooth clipped sliver was set up (row 63). triangle() runs on the worker threads
  // (triangles_on_threads): it only sets this flag, and run() names the deviation on the calling
  // thread; two threads inserting into Context::deviations_ at once corrupted the set.
  std::atomic<bool> sliver_{false};
  Scratch scratch_;
  raster::Fixed<raster::Vertex, 2> prim_;
};

void Context::flush_primitive() {
  Assembly(*this).run();  // in selection mode, as feedback: hits instead of values
  verts_.clear();
}

void Assembly::run() {
  assemble_and_draw();
  if (sliver_.load(std::memory_order_relaxed)) c_.deviations_.insert(kClippedSliver);  // docs/deviations.md row 63
}

void Assembly::assemble_and_draw() {
  note_smooth();
  c_.triangles_.clear();
  if (feedback_) c_.note_texgen_in_feedback();
  // Any of the three polygon offset enables puts the offset stage of Mesa's draw module in the
  // feedback pipeline (Context::feedback_offset).
  offset_stage_ = feedback_ && (c_.offset_fill_ || c_.enabled_state(GL_POLYGON_OFFSET_LINE) == 1 ||
                                c_.enabled_state(GL_POLYGON_OFFSET_POINT) == 1);
  if (c_.prim_mode_ >= GL_TRIANGLES) map_inside();
  const size_t n = c_.elements_.empty() ? c_.verts_.size() : c_.elements_.size();
  if (c_.prim_mode_ == GL_TRIANGLES && !feedback_ && !c_.unfilled() && c_.threads_ > 1 && n >= 3 * 4096)
    return triangles_on_threads(n);
  assemble(n);
  draw_held_triangles();
}

// Filled triangles are held in Context::triangles_ and rasterized together; a line or point drawn
// in between (a face glPolygonMode draws unfilled) draws those held first, so that each primitive
// lands over the ones before it, in the order Mesa's pipeline hands them to its rasterizer
// (measured: a strip's front face outlined over the back face filled before it).
void Assembly::draw_held_triangles() {
  if (c_.triangles_.empty()) return;
  const std::vector<raster::Triangle>* list = &c_.triangles_;
  c_.flush_clear();
  raster::draw_triangles(c_.fb_, &list, 1, rs_, c_.workers());
  c_.triangles_.clear();
}

// Smooth lines and points are drawn aliased: named when a drawn primitive meets them.
void Assembly::note_smooth() {
  if (feedback_) return;
  const bool any = !(c_.elements_.empty() ? c_.verts_.empty() : c_.elements_.empty());
  const bool two = (c_.elements_.empty() ? c_.verts_.size() : c_.elements_.size()) >= 2;
  const GLenum m = c_.prim_mode_;
  if ((m == GL_LINES || m == GL_LINE_STRIP || m == GL_LINE_LOOP) && two && c_.enabled_state(GL_LINE_SMOOTH) == 1)
    c_.deviations_.insert(kLineSmooth);
  if (m == GL_POINTS && any && c_.enabled_state(GL_POINT_SMOOTH) == 1) c_.deviations_.insert(kPointSmooth);
  // Polygons drawn as lines or points (glPolygonMode) go through the same antialiasing stages: a
  // degenerate triangle's edges of length 0 as dots (measured, seed 161803 streams 980 and 2648:
  // glPolygonMode(GL_LINE) with GL_LINE_SMOOTH, a strip of one repeated index; repro
  // polygon_mode_line_smooth.txt).
  const bool polygon = m == GL_TRIANGLES || m == GL_TRIANGLE_STRIP || m == GL_TRIANGLE_FAN || m == GL_QUADS ||
                       m == GL_QUAD_STRIP || m == GL_POLYGON;
  if (polygon && any) {
    const GLenum* pm = c_.polygon_mode_;
    if ((pm[0] == GL_LINE || pm[1] == GL_LINE) && c_.enabled_state(GL_LINE_SMOOTH) == 1) c_.deviations_.insert(kLineSmooth);
    if ((pm[0] == GL_POINT || pm[1] == GL_POINT) && c_.enabled_state(GL_POINT_SMOOTH) == 1)
      c_.deviations_.insert(kPointSmooth);
  }
}

// Most triangles lie inside the view volume: their vertices map to the window once, however many
// triangles share them, and they skip clipping.
void Assembly::map_inside() {
  const std::vector<raster::Vertex>& verts = c_.verts_;
  c_.outside_.resize(verts.size());
  c_.window_.resize(verts.size());
  for (size_t i = 0; i < verts.size(); ++i)
    if ((c_.outside_[i] = raster::outside_planes(verts[i].clip)) == 0) {
      c_.window_[i] = raster::map_to_window(verts[i].clip, rs_);
      c_.window_[i].fog = verts[i].fog;
    }
  // Mesa's draw module looks for vertices outside the view volume among those its primitives use:
  // vertices (or elements) past the last whole primitive are dropped first (u_trim_pipe_prim), and
  // a vertex in the range of a glDrawElements that no element names is never looked at (measured:
  // a quad strip from elements takes the inside split beside an unused vertex with w = 0).
  size_t whole = c_.elements_.empty() ? verts.size() : c_.elements_.size();
  const GLenum m = c_.prim_mode_;
  if (m == GL_TRIANGLES) whole -= whole % 3;
  else if (m == GL_QUADS) whole -= whole % 4;
  else if (m == GL_QUAD_STRIP) whole = whole < 4 ? 0 : whole - whole % 2;
  else if (whole < 3) whole = 0;
  for (size_t k = 0; k < whole; ++k) {
    any_outside_ = any_outside_ || c_.outside_[index(k)] != 0;
    if (c_.verts_[index(k)].clip == glm::dvec4(0)) c_.deviations_.insert(kZeroClipVertex);
  }
}

// One triangle: inside the view volume from the per-vertex window positions, otherwise clipped.
// Safe to run on several threads at once when not in feedback mode (only `out` and `scratch`
// are written).
void Assembly::triangle(size_t i0, size_t i1, size_t i2, size_t provoking, std::vector<raster::Triangle>& out,
                        Scratch& scratch) {
  const std::vector<raster::Vertex>& verts = c_.verts_;
  const std::vector<raster::WindowVertex>& window = c_.window_;
  const size_t v[3] = {index(i0), index(i1), index(i2)};
  if (c_.unfilled() && unfilled_triangle(v, provoking)) return;
  if ((c_.outside_[v[0]] | c_.outside_[v[1]] | c_.outside_[v[2]]) == 0) {
    const bool back = raster::back_facing_triangle(verts[v[0]].clip, verts[v[1]].clip, verts[v[2]].clip, rs_);
    if (feedback_) {  // each vertex's own colour
      raster::WindowVertex* in = scratch.inside;
      // Mesa's pipeline: facing from the window-space determinant (gl_rules.h); its two-side stage
      // takes a triangle of zero area as front-facing.
      const raster::WindowVertex* wv[3] = {&window[v[0]], &window[v[1]], &window[v[2]]};
      const float det = window_det(wv);
      if (window_culled(det, rs_)) return;
      const bool reported_back = rs_.two_side && det != 0 && window_back_facing(det, rs_);
      for (int k = 0; k < 3; ++k) {
        in[k] = window[v[k]];
        in[k].color = reported_back ? verts[v[k]].back : verts[v[k]].front;
        in[k].sec = reported_back ? verts[v[k]].back_sec : verts[v[k]].front_sec;
      }
      return c_.feedback_primitive(GL_POLYGON_TOKEN, in, 3, false, rs_, offset_stage_);
    }
    if (raster::culled(back, rs_)) return;
    const bool use_back = back && rs_.two_side;
    std::array<raster::SetupVertex, 3> sv;
    for (int k = 0; k < 3; ++k) {
      const raster::Vertex& src = rs_.flat ? at(provoking) : verts[v[k]];  // flat: the provoking colour
      sv[k] = {&window[v[k]], use_back ? &src.back : &src.front, use_back ? &src.back_sec : &src.front_sec};
    }
    raster::Triangle t;
    if (raster::setup(sv, rs_, t)) out.push_back(t);
    return;
  }
  for (int k = 0; k < 3; ++k) scratch.prim[k] = verts[v[k]];
  raster::ClipTemps* temps = feedback_ ? &c_.clip_temps_ : nullptr;
  const raster::WindowPolygon w = raster::clip_and_map(scratch.prim, 3, rs_, &at(provoking), false, nullptr, temps);
  if (feedback_ && c_.render_mode_ == GL_FEEDBACK && c_.clip_temps_.read_unwritten) c_.deviations_.insert(kClipTempsUnwritten);
  if (w.empty()) return;
  if (feedback_) return c_.feedback_primitive(GL_POLYGON_TOKEN, w.begin(), w.size(), true, rs_, offset_stage_);
  raster::Triangle t;
  for (size_t k = 1; k + 1 < w.size(); ++k)
    if (raster::setup(w[k], w[k + 1], w[0], rs_, t)) {
      out.push_back(t);
      if (!rs_.flat && raster::sliver(w[k], w[k + 1], w[0])) sliver_.store(true, std::memory_order_relaxed);  // row 63
    }
}

// A line or a point, clipped (a point as a degenerate line) and drawn at once, or fed back.
void Assembly::line_or_point(std::initializer_list<size_t> idx, size_t provoking, GLenum kind) {
  const size_t* i = idx.begin();
  clip_and_draw(at(i[0]), at(kind == GL_POINT_TOKEN ? i[0] : i[1]), at(provoking), kind);
}

// False: nothing of it lies inside the view volume.
bool Assembly::clip_and_draw(const raster::Vertex& a, const raster::Vertex& b, const raster::Vertex& provoking,
                             GLenum kind) {
  prim_.clear();
  prim_.push_back(a);
  prim_.push_back(b);
  // Feedback reports each vertex's own colour (Mesa does not flatten there), but for the ends
  // that clipping makes (clip_and_map), and where the draw module's pipeline holds its flatshade
  // stage: with flat shading and a polygon mode other than GL_FILL on either face, whose unfilled
  // stage asks for it (draw_pipe_validate.c, precalc_flat), lines too are fed back with the
  // provoking vertex's colours. Measured (seed 161803 stream 1479, repro feedback_flat_line_unfilled.txt):
  // a flat line strip under glPolygonMode(GL_POINT) fed back with the first vertex's alpha 0 (the
  // provoking vertex's), 0.125 (its own) without the glPolygonMode.
  if (feedback_ && rs_.flat && kind != GL_POINT_TOKEN && c_.unfilled())
    for (raster::Vertex& v : prim_)
      v.front = provoking.front, v.back = provoking.back, v.front_sec = provoking.front_sec, v.back_sec = provoking.back_sec;
  raster::ClipTemps* temps = feedback_ ? &c_.clip_temps_ : nullptr;
  const raster::WindowPolygon w = raster::clip_and_map(prim_.begin(), 2, rs_, &provoking, true, nullptr, temps);
  if (feedback_ && c_.render_mode_ == GL_FEEDBACK && c_.clip_temps_.read_unwritten) c_.deviations_.insert(kClipTempsUnwritten);
  if (w.empty()) return false;
  if (feedback_) {
    raster::WindowVertex zeroed[2];  // a point or a line: two vertices at most
    const raster::WindowVertex* fed = w.begin();
    if (zero_depth_) {
      for (size_t k = 0; k < w.size(); ++k) zeroed[k] = w[k], zeroed[k].pos.z = 0;
      fed = zeroed;
    }
    c_.feedback_primitive(kind, fed, w.size(), true, rs_, offset_stage_);
    return true;
  }
  draw_held_triangles();
  c_.flush_clear();
  if (kind == GL_POINT_TOKEN) raster::draw_point(c_.fb_, w[0], rs_);
  else raster::draw_line(c_.fb_, w[0], w[1], rs_);
  return true;
}

// glPolygonMode GL_LINE or GL_POINT for the triangle's facing: its polygon's edges (edges_) as
// lines, or their first vertices as points, in the order of Mesa's unfilled stage (measured in
// feedback: the edge from vertex 2 to 0 first, then 0 to 1, 1 to 2; points 0, 1, 2), the first
// line of a polygon a GL_LINE_RESET_TOKEN. Culling, flat shading and the two-sided colours come
// first, as in Mesa's pipeline. False: the face is filled (the caller goes on). The lines are
// clipped one by one where Mesa clips the triangle first and draws the pieces of its edges that
// remain (zero-length ones too): named when a triangle is clipped (kUnfilledClipped).
bool Assembly::unfilled_triangle(const size_t v[3], size_t provoking) {
  const std::vector<raster::Vertex>& verts = c_.verts_;
  const bool clipped = c_.outside_[v[0]] | c_.outside_[v[1]] | c_.outside_[v[2]];
  bool back, front_colours;
  if (!clipped) {  // facing as Mesa's pipeline finds it (gl_rules.h), zero area included
    const raster::WindowVertex* wv[3] = {&c_.window_[v[0]], &c_.window_[v[1]], &c_.window_[v[2]]};
    const float det = window_det(wv);
    if (window_culled(det, rs_)) return true;
    back = window_back_facing(det, rs_), front_colours = det == 0;
  } else {
    back = raster::back_facing_triangle(verts[v[0]].clip, verts[v[1]].clip, verts[v[2]].clip, rs_);
    if (raster::culled(back, rs_)) return true;
    front_colours = false;
  }
  const GLenum mode = c_.polygon_mode_[back ? 1 : 0];
  if (mode == GL_FILL) return false;
  // Mesa's offset stage comes before the unfilled one: with any offset enable on, a triangle of zero
  // area gets depths of NaN there (0/0 slopes), clamped to 0 in feedback and selection, and its
  // points or lines keep them (measured in an OSMesa program: glPolygonMode(GL_BACK, GL_POINT), any of
  // the three enables, three points at depth 0; seed 1 stream 14737018816213568908, repro
  // zero_area_unfilled_offset_depth.txt). One with area keeps its depths (row 40).
  zero_depth_ = !clipped && front_colours && offset_stage_;
  struct Reset {
    bool& flag;
    ~Reset() { flag = false; }
  } reset_zero{zero_depth_};
  if (clipped) c_.deviations_.insert(kUnfilledClipped);
  const bool use_back = back && rs_.two_side && !front_colours;
  raster::Vertex corner[3];
  for (int k = 0; k < 3; ++k) {
    corner[k] = verts[v[k]];
    const raster::Vertex& src = rs_.flat ? at(provoking) : verts[v[k]];
    corner[k].front = use_back ? src.back : src.front;
    corner[k].front_sec = use_back ? src.back_sec : src.front_sec;
  }
  if (mode == GL_POINT) {
    for (int k = 0; k < 3; ++k)
      if (edges_ & (1u << k)) clip_and_draw(corner[k], corner[k], corner[k], GL_POINT_TOKEN);
    return true;
  }
  if (reset_) raster::reset_stipple(rs_);
  bool reset = reset_;  // the reset token goes with the first line that comes out
  for (int k : {2, 0, 1}) {
    if (!(edges_ & (1u << k))) continue;
    const raster::Vertex& b = corner[(k + 1) % 3];
    if (clip_and_draw(corner[k], b, b, reset ? GL_LINE_RESET_TOKEN : GL_LINE_TOKEN)) reset = false;
  }
  return true;
}

void Assembly::emit(std::initializer_list<size_t> idx, size_t provoking, GLenum kind, unsigned edges, bool reset) {
  const size_t* i = idx.begin();
  edges_ = edges, reset_ = reset;
  if (kind == GL_POLYGON_TOKEN) return triangle(i[0], i[1], i[2], provoking, c_.triangles_, scratch_);
  line_or_point(idx, provoking, kind);
}

// The mode's primitives from n vertices (or elements), each with its provoking vertex.
void Assembly::assemble(size_t n) {
  switch (c_.prim_mode_) {
    case GL_POINTS:
      for (size_t i = 0; i < n; ++i) emit({i}, i, GL_POINT_TOKEN);
      break;
    case GL_LINES:
      for (size_t i = 0; i + 1 < n; i += 2) raster::reset_stipple(rs_), emit({i, i + 1}, i + 1, GL_LINE_TOKEN);
      break;
    case GL_LINE_STRIP:
    case GL_LINE_LOOP:
      raster::reset_stipple(rs_);  // the stipple pattern runs on along a strip (GL 2.1 section 3.4.2)
      for (size_t i = 0; i + 1 < n; ++i) emit({i, i + 1}, i + 1, GL_LINE_TOKEN);
      if (c_.prim_mode_ == GL_LINE_LOOP && n >= 2) emit({n - 1, 0}, 0, GL_LINE_TOKEN);
      break;
    case GL_TRIANGLES:
      for (size_t i = 0; i + 2 < n; i += 3) emit({i, i + 1, i + 2}, i + 2, GL_POLYGON_TOKEN);
      break;
    case GL_TRIANGLE_STRIP:
      for (size_t i = 0; i + 2 < n; ++i)
        if (i % 2 == 0) emit({i, i + 1, i + 2}, i + 2, GL_POLYGON_TOKEN);
        else emit({i + 1, i, i + 2}, i + 2, GL_POLYGON_TOKEN);
      break;
    case GL_TRIANGLE_FAN:
      for (size_t i = 1; i + 1 < n; ++i) emit({0, i, i + 1}, i + 1, GL_POLYGON_TOKEN);
      break;
    // Mesa splits quads and polygons one way when drawing and another in feedback (measured with
    // Mesa 22.3 in tests/raster/prims_test.cpp). Drawing smooth, the quad (q0, q1, q2, q3) is the
    // fan (q0, q1, q2), (q0, q2, q3); feedback, and drawing flat quads, take the draw module's
    // decomposition for the last vertex provoking: (q0, q1, q3), (q1, q2, q3); feedback gives a
    // polygon's fan with its first vertex last. GL 2.1 leaves the split open (section 2.6.1).
    // A draw with any vertex outside the view volume runs the draw module's pipeline (its clipper)
    // for all of its primitives, and so takes that decomposition too, drawing smooth; so does
    // every glDrawElements of quads (measured: a smooth quad from elements 0,1,2,3 is split as
    // (q0, q1, q3), (q1, q2, q3), the same corners from glDrawArrays as the fan; quad strips and
    // polygons from elements split as from arrays). So does a display list's quad when glCallList
    // draws it from its vertex list, an indexed draw (measured: repro list_quad_split.txt, seed 2026
    // stream 486), not when Mesa replays the list through immediate mode (Context::list_indexed).
    case GL_QUADS:  // the 4th vertex provokes
      for (size_t i = 0; i + 3 < n; i += 4) {
        if (pipeline_ || rs_.flat || any_outside_ || !c_.elements_.empty() || c_.list_indexed()) {  // edges: the quad's
          emit({i, i + 1, i + 3}, i + 3, GL_POLYGON_TOKEN, 0b101, true);
          emit({i + 1, i + 2, i + 3}, i + 3, GL_POLYGON_TOKEN, 0b011, false);
        } else {
          emit({i, i + 1, i + 2}, i + 3, GL_POLYGON_TOKEN);
          emit({i, i + 2, i + 3}, i + 3, GL_POLYGON_TOKEN);
        }
      }
      break;
    case GL_QUAD_STRIP:  // quad (2i, 2i+1, 2i+3, 2i+2), as Mesa's feedback (2i+2, 2i, 2i+1, 2i+3); 2i+3 provokes
      for (size_t i = 0; i + 3 < n; i += 2) {
        if (pipeline_ || any_outside_) {
          emit({i + 2, i, i + 3}, i + 3, GL_POLYGON_TOKEN, 0b101, true);
          emit({i, i + 1, i + 3}, i + 3, GL_POLYGON_TOKEN, 0b011, false);
        } else {
          emit({i, i + 1, i + 3}, i + 3, GL_POLYGON_TOKEN);
          emit({i, i + 3, i + 2}, i + 3, GL_POLYGON_TOKEN);
        }
      }
      break;
    case GL_POLYGON:  // a fan from the first vertex, which provokes
      for (size_t i = 1; i + 1 < n; ++i)
        if (pipeline_)  // the polygon's edges: (i, i + 1), and its first and last to vertex 0
          emit({i, i + 1, 0}, 0, GL_POLYGON_TOKEN, 1u | (i + 2 == n ? 2u : 0u) | (i == 1 ? 4u : 0u), i == 1);
        else emit({0, i, i + 1}, 0, GL_POLYGON_TOKEN);
      break;
  }
}

// GL_TRIANGLES, many of them, while rendering: assembly and setup split in contiguous ranges, one
// per thread; the rasterizer takes the ranges in order, so the picture is the same as from one
// thread.
void Assembly::triangles_on_threads(size_t n) {
  pool::Workers& w = c_.workers();
  const size_t count = n / 3, parts = size_t(w.size());
  c_.tri_parts_.resize(parts - 1);
  w.run([&](int share) {
    const size_t p = size_t(share);
    Scratch local;
    std::vector<raster::Triangle>& out = p == 0 ? c_.triangles_ : c_.tri_parts_[p - 1];
    if (p > 0) out.clear();
    for (size_t t = count * p / parts; t < count * (p + 1) / parts; ++t)
      triangle(3 * t, 3 * t + 1, 3 * t + 2, 3 * t + 2, out, p == 0 ? scratch_ : local);
  });
  const std::vector<raster::Triangle>* lists[pool::Workers::kMax] = {&c_.triangles_};
  for (size_t p = 1; p < parts; ++p) lists[p] = &c_.tri_parts_[p - 1];
  c_.flush_clear();
  raster::draw_triangles(c_.fb_, lists, parts, rs_, w);
}

}  // namespace ffc::state
