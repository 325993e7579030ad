// Immediate mode (GL 2.1 section 2.6): glBegin / glVertex / glEnd and the current normal and
// colour. A glVertex is a store: GL_TRIANGLES while rendering in float keeps the vertices as sent
// (a repeated one shared) and lights them together at glEnd on the triangle-list path; every
// other primitive keeps them in a batch lit before anything reads them (light_pending).
#include <algorithm>
#include <cstring>

#include "state/context.h"
#include "state/gl_rules.h"

namespace ffc::state {

void Context::Normal(double x, double y, double z) {
  if (!spec_) {  // the normal joins Mesa's vbo format (vbo_wrap)
    if (in_begin_ && !normal_in_format_) vbo_wrap(false);
    normal_in_format_ = true;
  }
  normal_ = {x, y, z};
  // A list replayed through immediate mode writes its vertices' normals into the vbo slot a normal
  // the list left pending waits in (measured, seed 223606 stream 5306296736714326599, repro
  // list_loopback_replaces_pending.txt: a glNormal outside glBegin, then a vertex with a normal from
  // an array, in a list replayed so: the vertex's normal is current after glCallList).
  if (lists_.calling && lists_.replaying_loopback) lists_.pending &= ~1;
}

void Context::Color(double r, double g, double b, double a, int components) {
  // A colour that changes what the stage reads (the key's colour material below, spec mode's
  // tracked material) comes after the kept vertices are lit.
  if (spec_ || (in_begin_ && !color_varies_)) light_pending();
  // glColor3 sets alpha to 1 (GL 2.1 section 2.7). Mesa's vbo keeps the colour attribute's size and
  // active size between flushes: a glColor3 that shrinks the active size fills alpha with 1, but
  // one at active size 3 in an attribute of size 4 (glColor4, glColor3, glColor4 since the last
  // flush) leaves alpha as the last glColor4 set it. Measured call by call; tested on generated
  // streams (ColorMaterialStreams).
  if (!spec_) {
    if (in_begin_ && prim_mode_ == GL_LINE_LOOP && components > color_size_ && !verts_.empty())
      deviations_.insert(kLineLoopWrap);  // docs/deviations.md row 48
    // Joining the format, or growing from 3 to 4 components, wraps (vbo_exec_fixup_vertex); the
    // vertices kept by a growth had 3 components, alpha 1, as they have here already.
    if (in_begin_ && components > color_size_) vbo_wrap(color_size_ == 0 && components == 3 && flushed_color_.a != 1);
    if (components > color_size_) color_size_ = color_active_ = components;
    else if (components < color_active_) {
      color_active_ = components;
      if (in_begin_) deviations_.insert(kColorShrinkInPrimitive);  // docs/deviations.md row 44
    }
    // A display list's own glBegin/glEnd stores its colours through Mesa's save path, whose
    // fixup_vertex (vbo_save_api.c) sets the active size at every call: a glColor3 after a glColor4
    // there stores alpha 1 (measured, seed 271828 stream 156: glColor3fv, glColor4fv(0, 0, 0, 0),
    // glColor3f, glVertex in a list's GL_POINTS reads back alpha 1, in the current colour and the
    // material colour material tracks; repro list_color3_after_color4_alpha.txt). The list's
    // vertices replay here inside its glBegin.
    else if (components == 3 && !(lists_.depth > 0 && in_begin_)) a = color_.a;
  }
  color_ = {r, g, b, a};
  if (lists_.calling && lists_.replaying_loopback) lists_.pending &= ~2;  // as for the normal (Normal)
  if (in_begin_ && !color_varies_) color_varies_ = true, constants_dirty_ = true;
  if (!spec_) return;  // tracked at the next flush (see update_color_material)
  flushed_color_ = color_;  // GL 2.1: tracked at once
  update_color_material();
}
// An attribute joining Mesa's vbo vertex format inside glBegin/glEnd (the first glNormal or glColor
// since the format's reset), or a colour growing from 3 components to 4: the vbo draws the whole primitives it holds as a draw of their own
// (vbo_exec_wrap_upgrade_vertex), keeps the vertices the rest of the primitive needs and lays them
// out again with the attribute as the state holds it. A colour joining at three components so
// gives the kept vertices alpha 1 (`alpha_one`; the vertices drawn already keep the state's
// alpha); and the draws being two, each decides alone whether a vertex lies outside the view
// volume, which chooses how quads are split (Assembly::assemble). Measured per mode in feedback:
// lines, triangles and quads keep the unfinished primitive's vertices; a line strip its last; a
// fan and a polygon the first and the last; a triangle or quad strip its last 2, or 3 after an odd
// count (an even number of triangles drawn keeps the strip's winding), or every vertex before its
// first whole primitive. A line loop's wrap is named, not modelled (kLineLoopWrap).
void Context::vbo_wrap(bool alpha_one) {
  early_join();  // it may rewrite the unfinished triangle's corners and add entries
  light_pending();
  const size_t n = immediate_list_ ? list_corner_.size() : verts_.size();
  if (n == 0) return;
  early_after_wrap_ = false;
  size_t keep = 0;
  bool shared = false;  // the kept vertices belong to primitives already drawn too
  switch (prim_mode_) {
    case GL_LINES: keep = n % 2; break;
    case GL_TRIANGLES: keep = n % 3; break;
    case GL_QUADS: keep = n % 4; break;
    case GL_LINE_STRIP: keep = 1, shared = n >= 2; break;
    case GL_TRIANGLE_FAN: case GL_POLYGON: keep = n < 3 ? n : 2, shared = n >= 3; break;
    case GL_TRIANGLE_STRIP: case GL_QUAD_STRIP:
      keep = n < (prim_mode_ == GL_QUAD_STRIP ? 4u : 3u) ? n : 2 + n % 2;
      shared = keep < n;
      break;
    case GL_LINE_LOOP: deviations_.insert(kLineLoopWrap), wrap_start_ = n - 1; return;  // docs/deviations.md row 48
    default: wrap_start_ = n; return;  // points keep nothing
  }
  // What is left after the changes below, less the kept vertices (stored again after the wrap).
  const size_t left = immediate_list_ || !(shared || (prim_mode_ == GL_QUADS && n - keep >= 4)) ? n : keep;
  wrap_start_ = left - keep;
  if (immediate_list_) {  // GL_TRIANGLES: the unfinished triangle's colours, lit at glEnd
    if (alpha_one && !list_color_.empty())
      for (size_t i = n - keep; i < n; ++i) {
        // The corner's own entry, alpha 1: one it shared with an earlier corner keeps its alpha.
        const uint32_t e = list_corner_[i];
        list_pos_.push_back(list_pos_[e]);
        if (!list_normal_.empty()) list_normal_.push_back(list_normal_[e]);
        list_color_.push_back(glm::dvec4(glm::dvec3(list_color_[e]), 1));
        list_corner_[i] = uint32_t(list_pos_.size() - 1);
      }
    return;
  }
  std::vector<raster::Vertex> kept;
  if (prim_mode_ == GL_TRIANGLE_FAN || prim_mode_ == GL_POLYGON) {
    kept.push_back(verts_.front());
    if (keep == 2) kept.push_back(verts_.back());
  } else {
    kept.assign(verts_.end() - std::ptrdiff_t(keep), verts_.end());
  }
  // The whole quads drawn apart matter to their split; other modes draw the same primitives
  // either way, so only shared vertices need the draw now (their alpha changes after it).
  const bool quads_apart = prim_mode_ == GL_QUADS && n - keep >= 4;
  if (shared || quads_apart) {
    if (prim_mode_ == GL_TRIANGLE_STRIP || prim_mode_ == GL_QUAD_STRIP) verts_.resize(n - keep + 2);
    else if (quads_apart) verts_.resize(n - keep);
    flush_primitive();
  }
  if (alpha_one) {
    // The alpha the vertex stage took from the colour: unlit, or lit with colour material on the
    // diffuse colour of that face.
    const bool diffuse = color_material_ && (cm_mode_ == GL_DIFFUSE || cm_mode_ == GL_AMBIENT_AND_DIFFUSE);
    const bool front = !lighting_ || (diffuse && cm_face_ != GL_BACK);
    const bool back = !lighting_ || (diffuse && cm_face_ != GL_FRONT);
    for (raster::Vertex& v : kept) {
      if (front) v.front.a = 1;
      if (back) v.back.a = 1;
    }
  }
  if (shared || quads_apart) verts_ = std::move(kept);
  else std::copy(kept.begin(), kept.end(), verts_.end() - std::ptrdiff_t(keep));
}

// A position growing inside glBegin/glEnd (glVertex2 then glVertex3 or 4, 3 then 4, from calls or
// glArrayElement) wraps Mesa's vbo as a colour growing does (measured: an unfilled polygon fed back
// with a second reset token, repro position_grows_in_polygon.txt); the format keeps the size with
// the position until it is reset. Size 0: not known, nothing tracked.
void Context::position_size(int size) {
  if (spec_ || size == 0) return;
  const int had = format_has_position_ ? position_size_ : 0;
  if (size <= had) return;
  if (in_begin_ && had > 0) vbo_wrap(false);
  position_size_ = size;
}

void Context::Vertex(double x, double y, double z, double w, int size) {
  position_size(size);
  if (!in_begin_) return stray_vertex();  // outside glBegin/glEnd a vertex draws nothing (undefined in GL)
  format_has_position_ = !spec_;
  if (sink_draws()) return sink_vertex({x, y, z, w});  // drawn at glEnd (draw_sink.cpp)
  process_vertex({x, y, z, w});
}

// glBegin and glEnd: Mesa's vbo resets its vertex format at glBegin only while the format holds no
// position ("attributes occurring outside begin/end pairs", vbo_exec_Begin), and never at glEnd, so
// once a glVertex has been sent the colour's size and active size carry over to the next primitive
// until a call that flushes the stored vertices. Soft still takes the pending values here (it
// draws at glEnd; Mesa's draw reads them from the stored vertices).
void Context::flush_stored_keeping_format(bool begin) {
  // Mesa copies the current values (mesa_normal_) here only at a glBegin whose format holds
  // attributes and no position.
  const bool copies = begin && !format_has_position_ && (color_size_ > 0 || normal_in_format_);
  // (its materials too where the format holds a glMaterial's: mesa_materials_)
  const bool copies_materials = copies || (begin && !format_has_position_ && material_in_format_);
  const glm::dvec3 mesa_normal = mesa_normal_;
  const glm::dvec4 mesa_color = mesa_color_;
  const lighting::MaterialParams mesa_front = mesa_materials_[0], mesa_back = mesa_materials_[1];
  if (!format_has_position_) {
    flush_stored();
  } else {
    const int size = color_size_, active = color_active_;
    const bool normal = normal_in_format_;
    flush_stored();
    color_size_ = size, color_active_ = active, normal_in_format_ = normal, format_has_position_ = true;
  }
  if (!copies) mesa_normal_ = mesa_normal, mesa_color_ = mesa_color;
  if (!copies_materials) mesa_materials_[0] = mesa_front, mesa_materials_[1] = mesa_back;
}

// A glVertex outside glBegin/glEnd draws nothing, but the position joins Mesa's vbo vertex format
// (measured: glColor4f(a=0); glVertex; glColor3f; glColor4f(a=0); glBegin; glColor3f; glEnd leaves
// alpha 0 in Mesa, 1 without the glVertex). It asks for no flush of stored vertices: the format
// stays through glEnable, glGetMaterial and glFinish (measured) until a glBegin/glEnd's vertices
// are flushed.
void Context::stray_vertex() {
  if (!spec_) format_has_position_ = true;
}

void Context::Begin(GLenum mode) {
  if (in_begin_) return error(GL_INVALID_OPERATION);
  // Where a list left Mesa's CurrentExecPrimitive set, a list's vertex list that begins a primitive
  // is refused whole (vbo_save_playback_vertex_list: "draw operation inside glBegin/End"): its glEnd
  // with it, and it copies nothing to the current values, so Mesa stays inside (Context::node_ends).
  // One replayed through immediate mode meets vbo_exec_Begin's refusal and its glEnd ends the
  // primitive. Measured (seed 577215 stream 9400455120439465367, repro
  // list_draw_last_leaves_exec_inside.txt): glBegin(GL_POINTS), glColor3fv, glEnd after such a draw
  // and a state call in the same list leaves Mesa inside, its glCallList raising nothing to see.
  if (exec_inside_) {
    refused_node_ |= lists_.depth > 0 && !lists_.replaying_loopback;
    return error(GL_INVALID_OPERATION);
  }
  validate_matrices();  // Mesa validates its state before it checks the mode
  if (!valid_primitive(mode)) return error(primitive_error(mode));
  // Mesa's glBegin asks for no flush: its glEnd does when the primitive left vertices stored
  // (End), a list's primitive too (a glBegin a list runs counted as storing until seed 244949
  // stream 14039353168182627223: repro material_joins_format_in_begin.txt). Its own flush of a
  // format without a position answers the flush asked for so far.
  if (!format_has_position_ && (color_size_ > 0 || normal_in_format_ || !pending_materials_.empty()))
    vertices_kept_ = false;
  flush_stored_keeping_format(true);
  // A colour still in Mesa's vbo format (one whose format held a position, so this glBegin flushed
  // nothing) is stored with each vertex, as a glColor inside glBegin is; otherwise the vertices draw
  // the current colour, a constant (vertex_stage.cpp clamp_unlit: a NaN differs between the two).
  color_in_begin_format_ = !spec_ && color_size_ > 0;
  set_color_varies(false);
  wrap_start_ = 0;
  in_begin_ = true;
  prim_mode_ = mode;
  texcoord_varies_ = false;
  verts_.clear();
  sink_verts_.clear();
  // Triangles in immediate mode take the triangle-list path: the vertices are kept as sent and
  // lit together at glEnd, unless a glMaterial between them changes the lighting
  // (leave_triangle_list()).
  immediate_list_ = triangle_list_path(mode);
  store_corners_ = immediate_list_ && !spec_ && !sink_draws();
  list_pos_.clear(), list_normal_.clear(), list_color_.clear(), list_corner_.clear();
  early_.lit = early_.drawn = 0;
  early_after_wrap_ = false;
  // Not while a list compiles: in GL_COMPILE_AND_EXECUTE the calls inside glBegin/glEnd that are
  // errors elsewhere are taken (outside_begin_end_keeping_vertices), and could move what a job reads.
  early_.next = store_corners_ && early_corners_ > 0 && threads_ > 1 && lists_.depth == 0 && lists_.mode == 0
                    ? early_corners_ : SIZE_MAX;
  if (immediate_list_ && ++corner_generation_ == 0) {  // wrapped: no slot may look current
    std::fill(corner_slots_.begin(), corner_slots_.end(), CornerSlot{});
    corner_generation_ = 1;
  }
}

// Immediate mode's GL_TRIANGLES: the vertex kept for the list, only what the lighting reads (the
// position rounded to float, as the float path rounds it anyway). A vertex equal to one a slot
// holds (bit for bit, under the same state: nothing between glBegin and glEnd changes the
// lighting but glMaterial, which leaves the list) shares that entry's lit colours.
void Context::keep_list_vertex(float x, float y, float z, float w) {
  const bool normal = lighting_, color = !lighting_ || color_material_;
  const uint64_t p[2] = {float_bits(x, y), float_bits(z, w)};
  const uint64_t n[3] = {double_bits(normal_.x), double_bits(normal_.y), double_bits(normal_.z)};
  CornerSlot& s = corner_slots_[corner_hash(p, n) >> (64 - kCornerSlotBits)];
  // One branch: the comparisons are cheap next to a mispredicted one.
  bool same = (s.generation == corner_generation_) & (s.pos[0] == p[0]) & (s.pos[1] == p[1]);
  if (normal) same &= (s.normal[0] == n[0]) & (s.normal[1] == n[1]) & (s.normal[2] == n[2]);
  if (same && (!color || std::memcmp(&list_color_[s.entry], &color_, sizeof color_) == 0)) {
    if (early_.in_flight && list_corner_.size() == list_corner_.capacity()) early_join();  // it reads them
    list_corner_.push_back(s.entry);
    return;
  }
  if (early_.in_flight) {  // the job reads the lists: none may move while it runs
    const auto full = [](const auto& v) { return v.size() == v.capacity(); };
    if (full(list_pos_) || full(list_corner_) || (normal && full(list_normal_)) || (color && full(list_color_))) early_join();
  }
  const auto e = uint32_t(list_pos_.size());
  list_pos_.emplace_back(x, y, z, w);
  if (normal) list_normal_.push_back(normal_);
  if (color) list_color_.push_back(color_);
  list_corner_.push_back(e);
  s = {{p[0], p[1]}, {n[0], n[1], n[2]}, e, corner_generation_};
  if (list_corner_.size() >= early_.next) early_handoff();  // checked on new entries only: a hit stays short
}

// Hands the triangles complete so far (and the entries not yet lit) to a worker thread, when it
// is free; else tries again a little later.
void Context::early_handoff() {
  if (early_.in_flight) {
    if (!workers().posted_done()) {
      early_.next = list_corner_.size() + early_corners_ / 8;
      return;
    }
    early_join();
  }
  // Colour material with no glColor yet inside this glBegin: the constants would change at the
  // first one (cm_per_vertex()), and the triangles drawn early would have been lit without it.
  if (lighting_ && color_material_ && !color_varies_) {
    early_.next = SIZE_MAX;
    return;
  }
  // Every complete triangle: a join stops the job after its chunk (early_wait), so a long job
  // costs glEnd no longer wait than a short one.
  const size_t triangles = list_corner_.size() / 3;
  update_vertex_constants();  // the job's stage reads them; nothing runs now
  EarlyJob& j = early_job_;
  j.rs = raster_state();
  // Room for every entry so far: growing value-initialises the new records, work the application's
  // thread would do at every handoff, so it grows to the lists' capacity, and a frame that sends
  // what the last one did finds it sized already (glEnd trims it to the entries there are).
  list_vertices_.grow(list_pos_.size(), list_pos_.capacity(), j.rs.two_side, j.rs.add_secondary);
  // The job's draws and glEnd's (of what is left, up to the whole primitive) allocate nothing
  // once the lists have reached this glBegin's size.
  if (list_corner_.capacity() / 3 > bins_reserved_) {
    bins_reserved_ = list_corner_.capacity() / 3;
    bins_.reserve(bins_reserved_, workers().size());
    early_bins_.reserve(bins_reserved_, 1);
  }
  j.first = early_.lit, j.lit = early_.lit = list_pos_.size();
  j.tri_first = j.reached = early_.drawn, j.drawn = early_.drawn = triangles;
  j.chunk = early_chunk_;
  j.stop.store(false, std::memory_order_relaxed);  // published by the post
  j.pos = list_pos_.data();
  j.normal = list_normal_.empty() ? nullptr : list_normal_.data();
  j.color = list_color_.empty() ? nullptr : list_color_.data();
  j.corners = list_corner_.data();
  j.cur_normal = normal_, j.cur_color = color_;
  j.clear = pending_clear_;
  pending_clear_ = {};
  early_.in_flight = true;
  early_.next = triangles * 3 + early_corners_;
  workers().post([](void* c) { static_cast<Context*>(c)->early_job(); }, this);
}

void Context::early_wait() {
  early_job_.stop.store(true, std::memory_order_relaxed);  // the job stops after its chunk
  workers_->wait_posted();
  early_.in_flight = false;
  if (early_job_.reached < early_job_.drawn) ++early_.stops;
  early_.drawn = early_job_.reached;  // the rest is the caller's
  if (early_job_.zero_normal) deviations_.insert(kZeroNormal);
  if (early_job_.sliver) deviations_.insert(kClippedSliver);  // docs/deviations.md row 63
  early_job_.zero_normal = early_job_.sliver = false;
}

// Also lights the vertices kept for the batch: the caller is about to change what they read.
void Context::leave_triangle_list() {
  if (immediate_list_) {
    immediate_list_ = store_corners_ = false;
    early_join();
    // The triangles drawn early are done: the rest of the primitive goes on without them, and
    // whether corners came after the last wrap (End) counts them too.
    const size_t dropped = 3 * early_.drawn;
    if (dropped > wrap_start_) early_after_wrap_ = true;
    wrap_start_ = wrap_start_ > dropped ? wrap_start_ - dropped : 0;
    early_.next = SIZE_MAX;
    for (size_t i = dropped; i < list_corner_.size(); ++i) {
      const uint32_t e = list_corner_[i];
      const glm::dvec3 normal = normal_;
      const glm::dvec4 color = color_;
      // As they were at that glVertex (what was not kept is not read).
      if (!list_normal_.empty()) normal_ = list_normal_[e];
      if (!list_color_.empty()) color_ = list_color_[e];
      process_vertex(glm::dvec4(list_pos_[e]));
      normal_ = normal, color_ = color;
    }
  }
  light_pending();
}

// Mesa's glEnd asks for a flush of stored vertices only when its primitive still holds some: not
// after a wrap that drew them all and kept none (a glColor after the last vertex of GL_LINES,
// GL_TRIANGLES, GL_QUADS or GL_POINTS) nor for a primitive without a vertex. Then the values sent
// stay pending: the next state call flushes nothing, and a glColorMaterial that changes the mode
// tracks the colour with the new mode only (measured: glEnable(GL_COLOR_MATERIAL), glBegin(GL_LINES),
// two vertices, glColor3f(0, 0, 0), glEnd, glColorMaterial(GL_FRONT_AND_BACK, GL_EMISSION) leaves
// the ambient 1 on Mesa; soft read 0 before; repro trailing_color_after_wrap.txt).
void Context::End() {
  // Where a list left Mesa's CurrentExecPrimitive set (exec_inside_), its glEnd ends that primitive,
  // which holds no vertex: no error, nothing drawn.
  if (!in_begin_ && refused_node_) return;
  // Mesa is outside again, so a list's vertex list flushes what a list left pending again (measured,
  // seed 173205 stream 10873261804190826188 shrunk, repro list_calls_itself_pending_colour.txt).
  if (!in_begin_ && exec_inside_) return void(exec_inside_ = lists_.mesa_inside = false);
  if (!in_begin_) return error(GL_INVALID_OPERATION);
  in_begin_ = store_corners_ = false;
  if (!immediate_list_) early_join();  // (none in flight: leave_triangle_list joined it) else immediate_to_list
  early_.next = SIZE_MAX;
  const size_t sent = immediate_list_ ? list_corner_.size() : verts_.size();
  const bool stored = spec_ || sink_draws() || sent > wrap_start_ || early_after_wrap_;
  if (stored && !spec_) vertices_kept_ = true;
  const auto flush = [&] {
    if (stored) flush_stored_keeping_format();
  };
  if (sink_draws()) return sink_end(), flush();  // draw_sink.cpp
  if (!immediate_list_) {
    light_pending();
    flush_primitive();
    return flush();
  }
  immediate_list_ = false;
  immediate_to_list();  // the entries not lit early
  draw_triangle_list(list_corner_.data() + 3 * early_.drawn, list_corner_.size() / 3 - early_.drawn);
  flush();
}
}  // namespace ffc::state
