// Display lists (GL 2.1 section 5.4): the name space (glGenLists, glDeleteLists, glIsList),
// compiling (glNewList/glEndList), executing (glCallList, glCallLists, glListBase), and the
// compile-time dereference of vertex arrays. How calls are recorded: display_list.h.
#include "state/display_list.h"

#include <algorithm>
#include <cmath>

#include "state/client_arrays.h"
#include "state/context.h"
#include "state/gl_rules.h"

namespace ffc::state {

// Row 71 (Context::note_node_primitive): whether a primitive of `count` vertices in `mode` after one of
// `last_count` in `last`, in one vertex list, makes Mesa 22.3 corrupt its heap.
static bool two_then_one_crashes(GLenum last, int last_count, GLenum mode, int count) {
  if (last_count != 2 || count != 1) return false;
  const bool two = last == GL_TRIANGLES || last == GL_TRIANGLE_STRIP || last == GL_TRIANGLE_FAN || last == GL_POLYGON;
  return (two && (mode == GL_QUADS || mode == GL_QUAD_STRIP)) || (last == GL_TRIANGLE_STRIP && mode == GL_TRIANGLE_STRIP);
}

void DisplayList::replay() const {
  const unsigned char* p = bytes_.data();
  const unsigned char* const end = p + bytes_.size();
  while (p < end) p = take<Replay>(p)(p);
}

namespace {
// What a dereferenced array element records: the values glArrayElement would send, by value.
void list_normal(double x, double y, double z) {
  if (Context* c = Context::current()) c->Normal(x, y, z);
}
void list_color(double r, double g, double b, double a, int components) {
  if (Context* c = Context::current()) c->Color(r, g, b, a, components);
}
void list_vertex(double x, double y, double z, double w) {
  if (Context* c = Context::current()) c->Vertex(x, y, z, w);
}
void list_begin(GLenum mode) {
  if (Context* c = Context::current()) c->Begin(mode);
}
void list_end() {
  if (Context* c = Context::current()) c->End();
}
void list_node_begins() {
  if (Context* c = Context::current()) c->node_begins();
}
void list_node_ends(bool draw, int loop, bool copy) {
  if (Context* c = Context::current()) c->node_ends(draw, loop, copy);
}
void list_stray_end() {
  if (Context* c = Context::current()) c->stray_end();
}
void list_node_split(bool draw, int copy, int joining) {
  if (Context* c = Context::current()) c->node_splits(draw, copy, joining);
}
void list_drop_open_primitive(bool keep_open, int drop) {
  if (Context* c = Context::current()) c->drop_open_primitive(keep_open, drop);
}
void list_error(GLenum e) {
  if (Context* c = Context::current()) c->record_error(e);
}
void list_pending_attribute(int kind) {
  if (Context* c = Context::current()) c->keep_pending(kind);
}
}  // namespace

// Measured against Mesa (repro list_normal_pending.txt): a list holding glNormal3f(.5, .5, .5), then
// glBegin, glNormal3f(0, 0, 1), a vertex, glEnd reads back (.5, .5, .5) after glCallList. The first
// glNormal runs through Mesa's immediate-mode vbo and waits there for a flush; the list's vertex
// list then writes its own last normal to the state, and the next flush (glGet, glBegin) copies the
// pending normal over it. glCallList flushes before it runs, so the pending normal lives from its
// glNormal to the end of the outermost glCallList or glCallLists; soft puts it back there. A glColor
// does the same (list_color_pending.txt).
void Context::mark_list_attribute(DisplayList& l, int kind) {
  l.record<list_pending_attribute>(kind);
  if (&l == &lists_.compiling) lists_.outside_attributes |= kind;
}

void Context::keep_pending(int kind) {
  if (!lists_.calling) return;  // GL_COMPILE_AND_EXECUTE's own calls: measured to agree already
  lists_.pending |= kind, lists_.need_update = true;
  if (kind == 1) lists_.pending_normal = normal_;
  if (kind == 2) lists_.pending_color = color_;  // its alpha as the vbo's colour size left it
}


namespace {
void list_snapshot_last_vertex() {
  if (Context* c = Context::current()) c->snapshot_last_vertex();
}
void list_drop_trailing(int kind) {
  if (Context* c = Context::current()) c->drop_trailing(kind);
}
void list_carry_trailing(int kind) {
  if (Context* c = Context::current()) c->carry_trailing(kind);
}
void list_loopback_attributes(int kinds, int kind, bool first_format) {
  if (Context* c = Context::current()) c->list_loopback(kinds, kind, first_format);
}
void list_loop_first_vertex() {
  if (Context* c = Context::current()) c->loop_first_vertex();
}
void list_value_before_joining() {
  if (Context* c = Context::current()) c->value_before_joining();
}
void list_copied_vertex_values(int kind, double x, double y, double z, double w) {
  if (Context* c = Context::current()) c->copied_vertex_values(kind, glm::dvec4(x, y, z, w));
}
}  // namespace

// Measured against Mesa (repro list_wrap_replaces_pending.txt): a list holding glColor4f(0, 0, 0,
// 0) outside its glBegin/glEnd, then glBegin, glVertex, glColor4f(0, 0, 0, 1), glVertex, glEnd
// reads back alpha 1 after glCallList, not the pending 0 (list_color_pending.txt's rule): the
// colour first appearing after a vertex wraps Mesa's list, and the rest of the primitive, which
// does not begin in its own vertex list, is replayed through immediate mode. That replay takes
// the pending values first and leaves the last vertex's values of the attributes it holds, those
// in the format at the wrap; an attribute outside it (a pending colour when a normal wrapped)
// stays pending. Measured too, and taken as found (the mechanism not traced): where the wrapping
// attribute is itself pending and the primitive's first vertex already had an attribute
// (glNormal, glVertex, then glColor), every pending value stays. An attribute that joins after the
// wrap but before the next vertex counts as wrapping again (Mesa's store holds the kept vertices).
void Context::list_loopback(int kinds, int kind, bool first_format) {
  if (!lists_.calling || ((lists_.pending & kind) && first_format)) return;
  lists_.pending &= ~kinds;
}

// Measured against Mesa, call by call (repro list_trailing_normal.txt): a glNormal or glColor
// after the last vertex of a list's own glBegin/glEnd does not become current when the list runs,
// in GL_COMPILE and in GL_COMPILE_AND_EXECUTE: glBegin, glVertex, glNormal3f(.5, .5, .5), glEnd
// leaves the normal from before the list; with glVertex, glNormal(.5), glVertex, glNormal(.7) it
// is .5, the last vertex's. Mesa's vertex list hands the state the values its last vertex stored.
// Soft keeps those values when the first such attribute runs and puts them back after glEnd.
void Context::list_trailing(DisplayList& l, int kind) {
  if (!lists_.had_vertex) return;
  if (lists_.trailing == 0) {
    l.record<list_snapshot_last_vertex>();
    if (list_executes()) lists_.held_back.record<list_snapshot_last_vertex>();
  }
  lists_.trailing |= kind;
}

// Measured (seed 299792 stream 14943971295263385005 shrunk, repro list_join_before_vertex_draw.txt): a
// compiled draw, then glBegin(GL_POLYGON) and a first glNormal before any vertex of it (a wrap of the
// draw's vertices), then a compiled draw inside that glBegin: after glCallList the normal is the one
// from before the list. The glNormal waits in the next vertex list's format, and that vertex list's
// last primitive is a draw, so it copies nothing; soft took the normal as current at the wrap
// (Context::node_splits, bit 64).
void Context::list_before_joining(DisplayList& l, int kind) {
  if (lists_.open && !lists_.had_vertex && !(lists_.attributes & kind) && lists_.stored > 0 && &l == &lists_.compiling)
    l.record<list_value_before_joining>();
}

void Context::value_before_joining() {
  lists_.before_join_normal = normal_, lists_.before_join_color = color_;
}

void Context::list_primitive_end(DisplayList& l, int trailing) {
  if (trailing) l.record<list_drop_trailing>(trailing);
}

void Context::snapshot_last_vertex() {
  lists_.last_vertex_normal = normal_, lists_.last_vertex_color = color_;
}

void Context::drop_trailing(int kind) {
  if (kind & 1) lists_.carried_normal = normal_, normal_ = lists_.last_vertex_normal;
  if (kind & 2) lists_.carried_color = color_, color_ = lists_.last_vertex_color;
}

// Measured by the seed-8086 helper (repro list_trailing_carried.txt, seed 8086 stream 212): the
// trailing values stay in Mesa's vertex template (vbo_save's attrptr) after the glEnd, so the next
// vertex the list stores before a flush carries them, in the next primitive, through a wrap, in
// either list mode, from glVertex or glArrayElement or a compiled draw, unless its primitive sent
// its own (glNormal before that vertex, a normal array); when the list runs, that vertex and so the
// current values after it take them. A flush (a state call) empties the format: no carry past it.
// `own`: the attributes the vertex brings itself; `last`: the last list the vertex is recorded into
// (the held-back calls after the list in GL_COMPILE_AND_EXECUTE).
void Context::list_vertex_compiled(DisplayList& l, int own, bool last) {
  if (const int carry = lists_.carry & ~own) l.record<list_carry_trailing>(carry);
  if (last) lists_.carry = 0;
}

// Measured (seed 299792 stream 5236854486341871494 shrunk, repro list_wrap_copies_take_list_current.txt):
// where an attribute first joins the format while the open primitive's last vertices are copied into
// the next vertex list (upgrade_vertex), and the list compiled that attribute outside its glBegin
// before (so the compiler knows a value: no loopback), the copies take the compiler's own current
// value (ListState.CurrentAttrib): the last value of that attribute the list sent, outside glBegin or
// in a format since flushed (a compiled draw's last element). A GL_QUAD_STRIP of one vertex after a
// draw with a normal array, glNormal after the vertex, glEnd: the current normal after glCallList is
// the draw's last element's. Soft takes that value for the last vertex's, which glEnd puts back.
void Context::copied_vertex_values(int kind, const glm::dvec4& v) {
  if (kind == 1) lists_.last_vertex_normal = glm::dvec3(v);
  if (kind == 2) lists_.last_vertex_color = v;
}

void Context::carry_trailing(int kind) {
  if (kind & 1) normal_ = lists_.carried_normal;
  if (kind & 2) color_ = lists_.carried_color;
}

// Mesa replays a list's vertex lists through immediate mode (UseLoopback) once its compiler met a
// vertex it cannot place at compile time: a glBegin still open at glEndList, a glCallList inside the
// list's glBegin, or a wrap that copies the open primitive's last vertices into the next vertex list
// while an attribute joins the format that the list never compiled outside its glBegin (the copies
// take a value the compiler does not know: vbo_save_api.c's dangling_attr_ref). Every vertex list of
// the list is then replayed so, compiled draws too, whose values therefore become current: measured,
// a compiled glDrawArrays with a colour array after such a wrap leaves its colour current and
// tracked by colour material after glCallList (repro list_loopback_draw_current.txt), where without
// the wrap the current colour stays as it was.
void Context::mark_loopback() { lists_.compiling.loopback = true; }

// The current values glGet reads while Mesa's executing side is inside the list's glBegin after a
// wrap or a fallback (ListState::shown), taken before the held-back calls run (Context::hold_back).
void Context::show_current() {
  const bool copied = !format_has_position_;
  lists_.shown_normal = copied ? normal_ : mesa_normal_;
  lists_.shown_color = copied ? color_ : mesa_color_;
}

// Measured (repro list_call_inside_begin_executing.txt, seed 8086 stream 58 shrunk): a glCallList
// compiled inside the list's own glBegin makes Mesa compile its store at once and mark the list for
// loopback (vbo_save_api.c, dlist_fallback), and the rest of the primitive, its glEnd included,
// compiles as calls that GL_COMPILE_AND_EXECUTE executes at once (dlist.c's save_Vertex, save_End).
// The loopback of that store runs the list's glBegin on the executing side without its glEnd, so
// Mesa is inside glBegin/glEnd from the glCallList to the list's glEnd: the glGetError after the
// called list's error (glCallList(0): GL_INVALID_VALUE) returns GL_NO_ERROR, glIsEnabled is refused,
// and glGet reads the current values as the last flush left them (show_current).
void Context::list_fallback() {
  mark_loopback();
  lists_.fallback = true;
  if (list_executes()) show_current();
}

void Context::fallen_back_run() {
  if (lists_.open && lists_.fallback) lists_.shown = true;
}

void Context::mark_called_loopback(const DisplayList& l) {
  for (GLuint name : l.calls) {
    const auto it = lists_.lists.find(name);
    if (it == lists_.lists.end() || it->second.loopback) continue;  // (Mesa crashes on a missing one: row 55)
    it->second.loopback = true;
    mark_called_loopback(it->second);
  }
}

// The vertices of the open primitive a wrap copies into the next vertex list (vbo_copy_vertices):
// what the mode has not drawn yet, and for the strips, fans, loops and polygons the vertices the
// rest is joined to.
static int wrap_copied_vertices(GLenum mode, int count) {
  switch (mode) {
    case GL_POINTS: return 0;
    case GL_LINES: return count % 2;
    case GL_TRIANGLES: return count % 3;
    case GL_QUADS: return count % 4;
    case GL_POLYGON:
    case GL_TRIANGLE_FAN: return std::min(count, 2);  // the first vertex and the last
    default: return count > 0 ? 1 : 0;  // at least one: how many does not matter here
  }
}

// Measured (repro list_line_loop_closing_vertex.txt): when Mesa compiles a vertex list whose last
// primitive is a GL_LINE_LOOP ended in it, it closes the loop by storing a copy of its first vertex
// after the last (convert_line_loop_to_strip); a GL_COMPILE_AND_EXECUTE list runs that vertex list
// through immediate mode at once, so the current values are the loop's first vertex's, not its last;
// so does glCallList of a list replayed through immediate mode (DisplayList::loopback; measured,
// repro list_loopback_line_loop_current.txt), where the others copy the last vertex's values. But
// a list replayed so reads its vertex lists from the buffer they were uploaded to, which ends with the
// loop's last vertex where the loop was restarted there by a wrap (the copy is not uploaded: Mesa
// reads the index data after it, the current colour then (0, 0, 0, 1) and the normal 0, measured),
// and an empty loop's copy is of a vertex never stored: both named (kListEmptyLoopCurrent, row 68).
void Context::loop_first_vertex() { lists_.loop_first_normal = normal_, lists_.loop_first_color = color_; }

// After a GL_LINE_LOOP's first vertex is compiled or held back: its values are kept when it runs
// (Context::loop_first_vertex).
void Context::note_loop_first_vertex(DisplayList& l) {
  if (lists_.open_mode == GL_LINE_LOOP && lists_.vertices == 1 && !lists_.wrapped) l.record<list_loop_first_vertex>();
}

// A primitive of `vertices` compiled into the list; in GL_COMPILE_AND_EXECUTE also among those the
// executing side runs at the next flush (ListState::held_incomplete, run_held_back).
void Context::note_list_primitive(GLenum mode, int vertices) {
  lists_.compiling.note_primitive(mode, vertices);
  if (list_executes() && vertices < fewest_vertices(mode)) lists_.held_incomplete = true;
}

void Context::run_held_back(bool new_format) {
  const bool closing_loop = lists_.closing_loop;
  const bool empty_loop = lists_.vertices == 0;  // its closing copy is of a vertex never stored (row 68)
  const int format = lists_.attributes;
  lists_.closing_loop = false;
  if (new_format) lists_.wrap_copies = 0;
  if (new_format) lists_.attributes = 0, lists_.color_size = lists_.position_size = 0, lists_.shown = false;
  // Measured (list_store_fills.txt): after a draw that filled the store and joined the primitive
  // restarted there (compile_elements), the next flush of a GL_COMPILE_AND_EXECUTE list (a state
  // call, glEndList) raises GL_INVALID_OPERATION on the executing side; glCallList raises it only
  // for a list replayed through immediate mode (list_stray_end), a GL_COMPILE list's glEndList never.
  if (new_format && lists_.refill_error) lists_.refill_error = false, error(GL_INVALID_OPERATION);
  lists_.vertices = lists_.stored = 0;
  lists_.prims = new_format ? 0 : 1;
  if (lists_.held_back.empty()) return;
  // Mesa's executing side plays the compiled vertex list back as glCallList does: a primitive too
  // short to draw is fed back padded (row 66; measured, seed 299792 stream 17539029581890894252: a
  // GL_LINE_LOOP of one vertex, then a glArrayElement outside glBegin flushing it, fed back as a line
  // from the vertex to itself; repro list_executing_incomplete_fed_back.txt).
  if (lists_.held_incomplete && render_mode_ != GL_RENDER) deviations_.insert(kListIncompleteFedBack);
  lists_.held_incomplete = false;
  ++lists_.depth;  // nothing recorded while they run
  lists_.held_back.replay();
  --lists_.depth;
  lists_.held_back.clear();
  // Their glEnd ended the wrapped primitive on the executing side, so glGet reads the current values
  // again (ListState::shown), a flush that keeps the format too: measured (seed 577215 stream
  // 15458122814594184789, repro list_store_fill_ends_shown.txt), a GL_POINTS wrapped by its first
  // glNormal, ended, then a glDrawArrays too large for the store reads back the normal sent.
  if (!in_begin_) lists_.shown = false;
  if (closing_loop && empty_loop) deviations_.insert(kListEmptyLoopCurrent);
  else if (closing_loop && (format & 1)) normal_ = lists_.loop_first_normal;
  if (closing_loop && !empty_loop && (format & 2)) color_ = lists_.loop_first_color;
}

// An attribute that first appears in the list's vertex format, or grows there (a glColor4 or
// glColor3ub after glColor3f, a glVertex3 after glVertex2), while the list's vertex store holds
// vertices wraps the list: in GL_COMPILE_AND_EXECUTE the vertices so far are drawn first and the
// open primitive stays open on the executing side. Measured (repros list_wrap_*.txt): the store's
// vertices may belong to an earlier primitive of the list (glBegin, glVertex, glEnd, glBegin,
// glNormal wraps with the second primitive open and empty), and the format is kept from one
// primitive to the next (glNormal, glVertex, glEnd, glBegin, glVertex, glNormal does not wrap).
// Every mode draws as sent but a triangle strip wrapped after an odd number of vertices
// (kListStripWrap) and a line loop (its closing segment lost, as in immediate mode: kLineLoopWrap).
// kind: a vertex (-1) or an attribute bit; size: a colour's or a position's components.
void Context::hold_back(int kind, int size) {
  if (kind == 0) return;
  const bool grows = kind < 0 ? size > lists_.position_size : kind == 2 ? size > lists_.color_size : !(lists_.attributes & kind);
  const bool known = kind < 0 ? lists_.position_size > 0 : (lists_.attributes & kind) != 0;
  // The first position of a format wraps nothing; a wider one does, as an attribute does.
  const bool joins = lists_.open && grows && (kind > 0 || known);
  // An attribute joining after the open primitive wrapped, before its next vertex, replays over
  // the pending values as the wrap itself does (list_loopback).
  if (joins && kind > 0 && lists_.vertices == 0 && lists_.wrapped)
    lists_.compiling.record<list_loopback_attributes>((lists_.attributes | kind) & 3, kind, lists_.first_format != 0);
  if (joins && lists_.stored > 0) {
    if (lists_.open_mode == GL_TRIANGLE_STRIP && lists_.vertices % 2) deviations_.insert(kListStripWrap);
    if (lists_.open_mode == GL_LINE_LOOP && lists_.vertices > 0)
      deviations_.insert(kLineLoopWrap), deviations_.insert(kListLineLoopCurrent);
    // A wrap at a line loop's first vertex (an attribute joining before it, the store holding an earlier
    // primitive): the loop begins in this vertex list and its vertices are all in the next, where
    // convert_line_loop_to_strip, seeing no glBegin there, skips the first: the segment from the first
    // vertex to the second is lost. Measured (seed 299792 stream 17539029581890894252, repro
    // list_loop_wrapped_at_first_vertex.txt): a GL_LINE_LOOP of two array elements whose first brings a
    // colour array new to the format is fed back as one line.
    if (lists_.open_mode == GL_LINE_LOOP && lists_.vertices == 0 && !lists_.wrapped) deviations_.insert(kLineLoopWrap);
    // The open primitive's rest begins in a vertex list of its own only if it had vertices before
    // the wrap (a wrap at its first vertex, of an earlier primitive's store, leaves it whole).
    if (lists_.vertices > 0) {
      lists_.wrapped = true;
      if (kind > 0)
        lists_.compiling.record<list_loopback_attributes>((lists_.attributes | kind) & 3, kind, lists_.first_format != 0);
    }
    // Measured: glBegin, glColor4f(0, 0, 0, 0), glVertex2f, then a first glNormal (the wrap) reads
    // GL_CURRENT_COLOR (1, 1, 1, 1) on Mesa, also after the list's glEnd, and 0 only once glEndList
    // flushed the rest: the wrapped vertices are drawn without touching the current values.
    // Mesa's executing side runs the held-back glBegin (its loopback), which copies what its vbo holds
    // to the current values first only where the vbo's format holds no position (vbo_exec_Begin):
    // after a glVertex outside glBegin (executed at once), or a primitive the last flush left in the
    // vbo (a glMatrixMode or glShadeModel in GL_COMPILE_AND_EXECUTE flushes nothing after it), the
    // current values are those the last flush copied (mesa_normal_), and stay so inside the glBegin:
    // measured, seed 2026 stream 594, seed 8086 stream 58, seed 777 stream 3 (repro
    // list_wrap_shows_last_flushed.txt).
    if (list_executes() && !lists_.shown) show_current(), lists_.shown = true;
    // The part of the primitive the wrap cut off is a primitive of its own in the list: too short to
    // draw, Mesa's playback in feedback pads it (measured: GL_TRIANGLES wrapped after one vertex is
    // fed back as that vertex three times before the rest; kListIncompleteFedBack).
    if (lists_.vertices > 0) note_list_primitive(lists_.open_mode, lists_.vertices);
    if (lists_.open) note_node_primitive(true);  // the wrap compiles the vertex list: row 71's pair too
    const int copies = lists_.open ? wrap_copied_vertices(lists_.open_mode, lists_.vertices + lists_.wrap_copies) : 0;
    if (lists_.open && lists_.open_mode == GL_LINE_LOOP) lists_.loop_restarted = true;
    split_list_node(kind > 0 ? kind & 3 : 0);  // the vertex list before the wrap is compiled first, then marked
    if (copies > 0 && kind > 0 && !(lists_.outside_attributes & kind)) mark_loopback();
    else if (copies > 0 && (kind == 1 || kind == 2) && !(lists_.attributes & kind) && lists_.had_vertex) {
      const glm::dvec4 v = kind == 1 ? glm::dvec4(lists_.store_normal, 0) : lists_.store_color;
      lists_.compiling.record<list_copied_vertex_values>(kind, v.x, v.y, v.z, v.w);
      if (list_executes()) lists_.held_back.record<list_copied_vertex_values>(kind, v.x, v.y, v.z, v.w);
    }
    if (list_executes()) run_held_back(false);
    // The copies are in the new store (upgrade_vertex replays them there), so an attribute joining
    // before the next vertex wraps again (measured, seed 223606 stream 6758869464152990923, repro
    // list_copies_wrap_again.txt: a GL_QUADS of one vertex wrapped by a colour, then a GL_LINE_LOOP
    // whose glColor4fv grows the colour before its first vertex restarts the loop: row 68).
    lists_.vertices = 0, lists_.stored = copies, lists_.prims = 1, lists_.wrap_copies = copies, lists_.node_vertices = copies;
  }
  if (kind < 0) {
    if (lists_.open && lists_.vertices == 0 && !lists_.wrapped) lists_.first_format = lists_.attributes;
    lists_.position_size = std::max(lists_.position_size, size);
    if (lists_.open) ++lists_.vertices, ++lists_.stored, ++lists_.primitive_vertices, ++lists_.node_vertices;
    return;
  }
  if (kind == 2) lists_.color_size = std::max(lists_.color_size, size);
  lists_.attributes |= kind;
}

// A compiled draw's error is a compile error: recorded in the list and raised at once in
// GL_COMPILE_AND_EXECUTE (measured: glDrawArrays(mode, 0, -1) while compiling), once, though the
// draw is also recorded into the held-back calls.
void Context::compile_error(DisplayList& l, GLenum e) {
  if (&l == &lists_.compiling) record_list_error(e);
  else if (&l != &lists_.held_back) l.record<list_error>(e);
}

void Context::record_list_error(GLenum e) {
  lists_.compiling.record<list_error>(e);
  if (lists_.mode == GL_COMPILE_AND_EXECUTE) error(e);
}

DisplayList* Context::list_recording() {
  return lists_.mode != 0 && lists_.depth == 0 ? &lists_.compiling : nullptr;
}

GLuint Context::GenLists(GLsizei range) {
  if (!outside_exec_primitive()) return 0;
  if (range < 0) return error(GL_INVALID_VALUE), 0;
  if (range == 0) return 0;
  // Mesa's hash table gives out the name after the largest it ever held (names deleted below it are
  // not reused while that leaves room), and holds the names given out, empty, until compiled. Where
  // that leaves no room (_mesa_HashFindFreeKeyBlock: the largest key is ~0 - 1), it searches from 1
  // for the first run of free names (measured, seed 173205 stream 7473006779468165034: glNewList(-1),
  // glEndList, glGenLists(3) returns 1; repro gen_lists_after_largest_name.txt).
  constexpr GLuint kMaxKey = ~GLuint(0) - 1;
  GLuint first = 0;
  if (kMaxKey - GLuint(range) > lists_.max_name) {
    first = lists_.max_name + 1;
  } else {
    GLuint free_start = 1;
    for (const auto& entry : lists_.lists) {
      if (entry.first >= kMaxKey) break;
      if (entry.first >= free_start && entry.first - free_start >= GLuint(range)) break;
      free_start = std::max(free_start, entry.first + 1);
    }
    if (free_start >= kMaxKey || kMaxKey - free_start < GLuint(range)) return 0;
    first = free_start;
  }
  for (GLsizei k = 0; k < range; ++k) lists_.lists[first + GLuint(k)];
  lists_.max_name = std::max(lists_.max_name, first + GLuint(range) - 1);
  return first;
}

void Context::DeleteLists(GLuint list, GLsizei range) {
  if (!outside_begin_end()) return;
  if (range < 0) return error(GL_INVALID_VALUE);
  for (GLsizei k = 0; k < range; ++k) lists_.lists.erase(list + GLuint(k));
}

GLboolean Context::IsList(GLuint list) {
  if (!outside_exec_primitive()) return GL_FALSE;
  return list != 0 && lists_.lists.count(list) ? GL_TRUE : GL_FALSE;
}

void Context::NewList(GLuint list, GLenum mode) {
  // While a list compiles, Mesa's compiling dispatch refuses glNewList before it looks at the
  // arguments (measured: glNewList(0, GL_CURRENT_NORMAL) then is GL_INVALID_OPERATION).
  if (lists_.mode != 0) return error(GL_INVALID_OPERATION);
  if (!outside_exec_primitive()) return;
  // Mesa's glNewList copies the pending current values (FLUSH_CURRENT), a glMaterial's and a colour
  // tracked by colour material included: measured, a GL_COMPILE_AND_EXECUTE list's wrap then shows
  // them (mesa_color_, mesa_materials_; repro list_new_list_copies_current.txt). Before the
  // arguments are checked here; not measured where they are refused.
  flush_current();
  if (list == 0) return error(GL_INVALID_VALUE);
  if (mode != GL_COMPILE && mode != GL_COMPILE_AND_EXECUTE) return error(GL_INVALID_ENUM);
  lists_.index = list;
  lists_.mode = mode;
  lists_.compiling.clear();
  lists_.held_back.clear();
  lists_.open = false, lists_.vertices = lists_.stored = 0, lists_.attributes = 0, lists_.had_vertex = false,
  lists_.trailing = lists_.carry = 0, lists_.color_size = lists_.position_size = 0;
  lists_.shown = lists_.fallback = false, lists_.refill_error = false;
  lists_.wrap_copies = lists_.outside_attributes = 0, lists_.closing_loop = false, lists_.node_open = false;
  lists_.shade_model = 0, lists_.node_modes.clear();
  lists_.store_vertices.clear(), lists_.store_repeats = lists_.deduplicated = false;
}

void Context::EndList() {
  // In GL_COMPILE_AND_EXECUTE the executing side can be inside glBegin/glEnd only because the list's
  // own primitive wrapped (hold_back): the vertices so far were drawn and the primitive left open.
  // glEndList flushes the rest and raises nothing, after the list's glEnd or inside its still open
  // glBegin (which the executing side then stays inside until the next glEnd). Measured against
  // Mesa (repro list_wrap_end_list.txt, State/DisplayLists.LitFanCompileAndExecute): the
  // GL_INVALID_OPERATION a stream finds at glEndList after the list's glEnd is the one the
  // glGetError before it recorded, inside the executing side's glBegin, as Mesa's does.
  const bool wrapped = in_begin_ && lists_.mode == GL_COMPILE_AND_EXECUTE;
  if (!wrapped && !outside_begin_end()) return;
  if (lists_.mode == 0) return error(GL_INVALID_OPERATION);
  if (lists_.open) mark_loopback();  // vbo_save_EndList inside the list's glBegin
  end_list_node();
  lists_.compiling.deduplicated = lists_.deduplicated;
  // Mesa marks the lists it calls, and theirs, too, for good (replace_op_vertex_list_recursively;
  // measured: a GL_COMPILE_AND_EXECUTE list calling a list whose glDrawElements repeats a vertex, then
  // wrapping so, reads that list's vertices shifted when it runs: repro list_loopback_marks_called.txt).
  if (lists_.compiling.loopback) mark_called_loopback(lists_.compiling);
  run_held_back();
  // The list replaces any list of that name only now: a glCallList of it while compiling ran the old one.
  lists_.lists[lists_.index] = std::move(lists_.compiling);
  lists_.max_name = std::max(lists_.max_name, lists_.index);
  lists_.compiling.clear();
  lists_.index = 0;
  lists_.mode = 0;
}

void Context::CallList(GLuint list) {
  if (lists_.calling) return call_one_list(list);
  begin_list_calls();
  call_one_list(list);
  end_list_calls();
}

void Context::end_list_calls() {
  // Mesa's vertex lists copied their values to the current ones (playback_copy_to_current); the
  // pending ones are in its vbo's format. The colour reaches the state (and a tracked material) at
  // soft's next flush, as Mesa's does.
  mesa_normal_ = normal_, mesa_color_ = color_;
  note_materials_flushed();
  if (lists_.pending & 1) normal_ = lists_.pending_normal;
  if (lists_.pending & 2) color_ = lists_.pending_color;
  lists_.calling = lists_.mesa_inside = false, lists_.pending = 0;
}

void Context::call_one_list(GLuint list) {
  // Mesa stops silently at its nesting limit, and a name without a list does nothing.
  if (lists_.depth >= ListState::kMaxNesting) return;
  const auto it = lists_.lists.find(list);
  if (it == lists_.lists.end()) return;
  // Measured: a list's GL_LINES of one vertex is fed back as a line from it to itself, GL_TRIANGLES
  // of two as a triangle with the second twice, an empty GL_LINE_LOOP alone as a line; GL_QUADS of
  // three, a strip of one and a polygon of two in one list crashed Mesa in glCallList.
  if (it->second.incomplete && render_mode_ != GL_RENDER) deviations_.insert(kListIncompleteFedBack);
  // In GL_RENDER under an unfilled polygon mode the padded triangle's edges are drawn (measured, seed
  // 161803 stream 1582: a strip of two, glPolygonMode(GL_LINE); repro list_incomplete_unfilled.txt).
  if (it->second.incomplete && render_mode_ == GL_RENDER && unfilled() && !it->second.loopback)
    deviations_.insert(kListIncompleteUnfilled);
  // Measured in GL_RENDER (repro list_quad_of_three_drawn.txt): a GL_QUADS or GL_QUAD_STRIP of
  // three, from glBegin/glEnd or a compiled glDrawArrays, draws the triangle of the three when the
  // list is called (not executing in GL_COMPILE_AND_EXECUTE, nor in immediate mode); GL_TRIANGLES of
  // two and a quad strip of five draw what GL says. Longer GL_QUADS were not measured apart from a
  // second finding: a self-intersecting quad in a list splits otherwise than drawn at once (open).
  if (it->second.padded_quad && render_mode_ == GL_RENDER) deviations_.insert(kListPaddedQuadDrawn);
  if (it->second.loopback && it->second.deduplicated) deviations_.insert(kListLoopbackDeduplicated);
  if (it->second.vertexless && !it->second.loopback) deviations_.insert(kListVertexlessNode);
  if (it->second.mixed_modes && !it->second.loopback && render_mode_ != GL_RENDER) deviations_.insert(kListModesFedBackFirst);
  if (it->second.modes_crash && !it->second.loopback && render_mode_ != GL_RENDER) deviations_.insert(kListModesCrash);
  const bool outer = lists_.replaying_loopback;
  ++lists_.depth, lists_.replaying_loopback = it->second.loopback;
  it->second.replay();
  --lists_.depth, lists_.replaying_loopback = outer;
  if (lists_.depth == 0) refused_node_ = false;
}

namespace {
// The i-th name of glCallLists' array, as an offset from the list base; false for an unknown type.
GLuint list_offset(GLenum type, const void* lists, GLsizei i) {
  const auto* b = static_cast<const GLubyte*>(lists);
  switch (type) {
    case GL_BYTE: return GLuint(GLint(static_cast<const GLbyte*>(lists)[i]));
    case GL_UNSIGNED_BYTE: return b[i];
    case GL_SHORT: return GLuint(GLint(static_cast<const GLshort*>(lists)[i]));
    case GL_UNSIGNED_SHORT: return static_cast<const GLushort*>(lists)[i];
    case GL_INT: return GLuint(static_cast<const GLint*>(lists)[i]);
    case GL_UNSIGNED_INT: return static_cast<const GLuint*>(lists)[i];
    case GL_FLOAT: {
      const float f = static_cast<const GLfloat*>(lists)[i];
      // (GLint) f as x86-64 converts it: out of range (or NaN) gives INT_MIN.
      return f > -2147483649.0f && f < 2147483648.0f ? GLuint(GLint(f)) : GLuint(0x80000000u);
    }
    case GL_2_BYTES: return GLuint(b[2 * i]) << 8 | b[2 * i + 1];
    case GL_3_BYTES: return GLuint(b[3 * i]) << 16 | GLuint(b[3 * i + 1]) << 8 | b[3 * i + 2];
    case GL_4_BYTES:
      return GLuint(b[4 * i]) << 24 | GLuint(b[4 * i + 1]) << 16 | GLuint(b[4 * i + 2]) << 8 | b[4 * i + 3];
  }
  return 0;
}

void replay_call_list_offset(GLuint offset);
}  // namespace

void Context::CallLists(GLsizei n, GLenum type, const void* lists) {
  const GLenum e = type < GL_BYTE || type > GL_4_BYTES ? GLenum(GL_INVALID_ENUM) : n < 0 ? GLenum(GL_INVALID_VALUE)
                                                                                          : GLenum(GL_NO_ERROR);
  // Compiled, the names are copied now and the list base read when the list runs. Mesa's save_CallLists
  // flushes and compiles the call whatever its arguments: a bad type or a negative count raises its error
  // when the list runs (and at once in GL_COMPILE_AND_EXECUTE, which executes it), not while compiling
  // (measured, seed 271828 stream 1365, seed 161803 streams 471 and 1775: repro list_call_lists_bad_compiled.txt).
  if (DisplayList* l = list_recording()) {
    if (lists_.open) list_fallback();  // as glCallList (soft_gl.cpp)
    end_list_node();
    if (e != GL_NO_ERROR) l->record<list_error>(e);
    for (GLsizei i = 0; e == GL_NO_ERROR && lists && i < n; ++i) l->record<replay_call_list_offset>(list_offset(type, lists, i));
    for (GLsizei i = 0; e == GL_NO_ERROR && lists && i < n && l == &lists_.compiling; ++i)
      l->calls.push_back(list_offset(type, lists, i));
    lists_.outside_attributes = 0, lists_.shade_model = 0;
    if (lists_.mode == GL_COMPILE) return;
    run_held_back();
    fallen_back_run();
  }
  if (e != GL_NO_ERROR) return error(e);
  if (n == 0 || !lists) return;
  const bool outermost = !lists_.calling;
  if (outermost) begin_list_calls();
  const GLuint base = lists_.base;
  for (GLsizei i = 0; i < n; ++i) CallList(base + list_offset(type, lists, i));
  if (outermost) end_list_calls();
}

namespace {
void replay_call_list_offset(GLuint offset) {
  if (Context* c = Context::current()) c->call_list_offset(offset);
}
}  // namespace

void Context::call_list_offset(GLuint offset) { CallList(lists_.base + offset); }

void Context::ListBase(GLuint base) {
  if (!outside_begin_end()) return;
  lists_.base = base;
}

int Context::list_values(GLenum pname, GLdouble* out) {
  switch (pname) {
    case GL_LIST_INDEX: out[0] = GLint(lists_.index); return 1;  // signed too (glNewList(-100, ...): -100)
    case GL_LIST_MODE: out[0] = lists_.mode; return 1;
    case GL_LIST_BASE: out[0] = GLint(lists_.base); return 1;  // Mesa reports it as a signed integer (glListBase(-100): -100)
    case GL_MAX_LIST_NESTING: out[0] = ListState::kMaxNesting; return 1;
  }
  return 0;
}

// A draw from vertex arrays while compiling: the elements are read now and recorded as the
// glBegin / glNormal / glColor / glVertex / glEnd calls that glArrayElement would make, so the
// list does not depend on the arrays later (section 5.4). The draw's own errors are recorded to be
// raised when the list runs, as Mesa's compiled errors are.
void Context::compile_elements(DisplayList& l, GLenum mode, GLsizei count, const GLuint* indices, GLint first) {
  GLenum e = GL_NO_ERROR;
  if (count < 0) e = GL_INVALID_VALUE;
  else if (!valid_primitive(mode)) e = primitive_error(mode);
  if (e != GL_NO_ERROR) return compile_error(l, e);
  // Inside the list's own open glBegin Mesa's save_DrawArrays begins the draw's primitive there and its
  // glEnd ends it: the list's primitive is left without an end and without its vertices (they precede
  // the draw's start), so nothing of it is drawn, and the list is outside glBegin after the draw, where
  // a glBegin is no error. Measured (seed 271828 stream 1376, repro list_draw_inside_begin.txt): GL_LINE_LOOP
  // of two vertices, glDrawArrays(GL_QUAD_STRIP, 0, 0), then a GL_TRIANGLES: no error, the triangle alone
  // fed back; with a draw of four the quad strip alone (row 72: two modes).
  // GL_COMPILE_AND_EXECUTE's executing side replays the vertex list through immediate mode
  // (vbo_loopback_vertex_list): the list's glBegin opens the primitive, empty; the draw's glBegin
  // raises GL_INVALID_OPERATION there (measured at the flush, glEndList), its vertices join the open
  // primitive and its glEnd ends it.
  // In GL_COMPILE_AND_EXECUTE the list's own pass of the draw comes first, before the held-back pass
  // that forms the store: a fill's split goes in before the draw's calls, so that the vertex list it
  // compiles is the one before the draw (measured, seed 173205 stream 5826937791591943647, repro
  // list_store_fill_vertexless.txt: a GL_POINTS wrapped by a colour with nothing to copy, then a draw
  // too large for the store, compiles a vertex list with attributes and no vertex, row 55's unwritten
  // values after glCallList, and leaves Mesa inside the points).
  if (count > 0 && &l == &lists_.compiling && list_executes() && store_fills(count)) split_list_node();
  const bool ends_open = lists_.open && !lists_.compiling_draw;
  const bool executing = &l == &lists_.held_back;
  // The vertices dropped: those sent since the primitive's glBegin or its last wrap (a wrap's first
  // vertex list drew those before it).
  if (ends_open) l.record<list_drop_open_primitive>(executing, lists_.vertices);
  if (ends_open && executing) l.record<list_error>(GL_INVALID_OPERATION);
  if (ends_open && count == 0 && executing) l.record<list_end>();
  if (ends_open && count == 0 && forms_format(l)) lists_.open = false, lists_.closing_loop = false;
  // A draw of no vertex is a primitive of Mesa's store too (save_DrawArrays begins it): its vertex
  // list's FLUSH_FOR_DRAW flushes the values pending when the list runs (Context::flush_pending).
  // Inside the list's glBegin in GL_COMPILE_AND_EXECUTE too, where the list's primitive is ended only
  // with the held-back calls, after this (seed 577215 stream 9400455120439465367: the vertex list
  // was taken for one that copies, so glCallList left soft outside; repro
  // list_draw_last_leaves_exec_inside.txt).
  if (count == 0 && &l == &lists_.compiling && (!lists_.open || ends_open)) start_list_node(true);
  if (count == 0) return;
  // Mesa compiles the draw as glBegin, glArrayElement for each element and glEnd into its vertex
  // store, so the elements grow the list's vertex format as calls do (hold_back).
  const bool format = forms_format(l);
  bool merged = false;
  if (format) {
    // Mesa makes room for the draw's vertices first: past its store's size (256 Ki bytes, counted
    // with the format as it is) and with a primitive already stored, it compiles what it holds
    // (drawn at once in GL_COMPILE_AND_EXECUTE, a wrapped primitive ended; measured: a
    // glDrawArrays of 2^20 vertices after a wrapped glBegin/glEnd finds the executing side outside
    // it). The draws of the generator's huge category are the ones this meets.
    // The next vertex list then begins with the store's last primitive restarted, empty and without
    // its glBegin (wrap_filled_vertex), and Mesa joins the draw to it where the modes are the same
    // and join (vbo_merge_draws): the draw is then a primitive without a glBegin, whose glEnd,
    // replayed through immediate mode, raises GL_INVALID_OPERATION on the executing side: at the
    // next flush of a GL_COMPILE_AND_EXECUTE list (measured: list_store_fills.txt) and when a list
    // replayed so (DisplayList::loopback) runs (measured: glCallList of such a list raises it, of
    // one without the wrap nothing; repro list_store_fills_loopback.txt).
    if (store_fills(count)) {
      merged = lists_.open_mode == mode &&
               (mode == GL_POINTS || mode == GL_LINES || mode == GL_TRIANGLES || mode == GL_QUADS);
      // A draw that stores no vertex (no vertex array) after such a fill: where Mesa's executing side
      // raises GL_INVALID_OPERATION then depends on more than soft models (measured in an OSMesa
      // program, a GL_TRIANGLES or GL_LINE_LOOP of one or three vertices, with a normal after the last
      // or not, then two such draws and a glMaterialfv: the error at the second draw, at the
      // glMaterialfv, at both, or nowhere; seed 223606 streams 6657219071999797025 and
      // 12307679055406691739, repros list_store_fills_without_vertices*.txt). Named (row 55).
      if (list_executes() && !(vertex_array_.enabled && vertex_array_.pointer)) deviations_.insert(kListFillEmptyDraw);
      if (list_executes()) run_held_back(false), lists_.refill_error = merged;
      lists_.stored = 0;
      if (!list_executes()) split_list_node();  // GL_COMPILE_AND_EXECUTE: split in the list's own pass
    }
    lists_.open = true, lists_.open_mode = mode, lists_.vertices = 0, lists_.wrapped = false, ++lists_.prims;
    lists_.wrap_copies = 0, lists_.closing_loop = lists_.loop_restarted = false;
  }
  if (&l == &lists_.compiling) {
    start_list_node(true);
    // A compiled draw is the second of row 71's pair after another draw (measured: a GL_TRIANGLES
    // draw of two, then a GL_QUADS draw of one), and the first before a glBegin.
    const int drawn = vertex_array_.enabled ? int(count) : 0;
    if (two_then_one_crashes(lists_.node_last_mode, lists_.node_last_count, mode, drawn))
      deviations_.insert(kListTwoThenQuadCrash);
    lists_.node_last_mode = mode, lists_.node_last_count = drawn;
  }
  if (!(ends_open && executing)) l.record<list_begin>(mode);
  lists_.compiling_draw = true;
  for (GLsizei k = 0; k < count; ++k) {
    compile_element(l, indices ? GLint(indices[k]) : first + k);
    // A line loop's first vertex (Context::loop_first_vertex): a wrap at it leaves the loop whole.
    if (k == 0 && mode == GL_LINE_LOOP && vertex_array_.enabled && vertex_array_.pointer)
      l.record<list_loop_first_vertex>();
  }
  lists_.compiling_draw = false;
  if (&l == &lists_.compiling) note_list_primitive(mode, vertex_array_.enabled ? int(count) : 0);
  if (format) note_node_mode(mode, lists_.vertices + lists_.wrap_copies);
  if (format) lists_.open = false, lists_.closing_loop = mode == GL_LINE_LOOP;
  l.record<list_end>();
  if (merged) lists_.compiling.record<list_stray_end>();  // after the draw, in either list mode
}

// Whether a compiled draw of `count` vertices overfills Mesa's vertex store (256 Ki bytes, counted
// with the format as it is) with a primitive already stored (compile_elements).
bool Context::store_fills(GLsizei count) const {
  const int format_floats = lists_.position_size + ((lists_.attributes & 1) ? 3 : 0) + lists_.color_size +
                            ((lists_.attributes & 4) ? 4 : 0) + ((lists_.attributes & 8) ? 1 : 0);
  return lists_.prims > 0 && (double(lists_.stored) + double(count)) * format_floats * 4 > ListState::kStoreBytes;
}

// The last `drop` vertices of the open primitive are forgotten; it is ended too unless keep_open
// (compile_elements).
void Context::drop_open_primitive(bool keep_open, int drop) {
  if (!in_begin_) return;
  const auto shorten = [drop](auto& v) { v.resize(v.size() - std::min(v.size(), size_t(std::max(drop, 0)))); };
  if (immediate_list_) {
    shorten(list_corner_);
    wrap_start_ = std::min(wrap_start_, list_corner_.size());
  } else {
    light_pending();  // the batch's slots index verts_
    const size_t n = verts_.size();
    shorten(verts_);
    wrap_start_ = std::min(wrap_start_, verts_.size());
    if (sink_materials_.size() == sink_verts_.size()) shorten(sink_materials_);
    if (n == 0) shorten(sink_verts_);  // feedback and selection keep their vertices there
  }
  if (!keep_open) End();
}

void Context::stray_end() {
  if (lists_.replaying_loopback && !in_begin_) error(GL_INVALID_OPERATION);
}

// The list whose recording stands for Mesa's vertex store: the held-back calls in
// GL_COMPILE_AND_EXECUTE (a wrap draws them), the list itself in GL_COMPILE.
bool Context::forms_format(const DisplayList& l) const {
  return &l == (list_executes() ? &lists_.held_back : &lists_.compiling);
}


// Mesa compiles the list's vertex store into a vertex list at each flush (a state call compiled, a
// glCallList, glEndList) and at each wrap, and plays each back from its buffer, copying the values
// its last vertex stored to the current ones (playback_copy_to_current), except where the last
// primitive begun in it is a compiled draw (no_current_update): then the vertex list leaves every
// current value as it was before it ran, the values of the glBegin/glEnd before the draw in it too.
// The values a draw's elements leave in the store's vertex format go on into the vertices that follow
// in the same vertex list (a glBegin after the draw takes its last colour). Measured (repro
// list_draw_values_carried.txt): a compiled glDrawArrays with a colour array, then glBegin, two
// vertices, glEnd draws the line in the array's colour and leaves it current; without the glBegin the
// colour stays as it was. Replayed through immediate mode (DisplayList::loopback) every vertex sets
// the current values. Soft records where each vertex list starts and ends and puts the values back.
void Context::start_list_node(bool draw) {
  if (!lists_.node_open) lists_.compiling.record<list_node_begins>(), lists_.node_open = true;
  lists_.node_draw = draw;
}

// Measured by the seed-8086 helper (repro list_two_then_quad_crash.txt, docs/fidelity.md): Mesa 22.3
// aborts on a corrupted heap (glibc's "free(): invalid next size") at the flush that compiles a
// vertex list holding a GL_TRIANGLES, GL_TRIANGLE_STRIP, GL_TRIANGLE_FAN or GL_POLYGON of two
// vertices (sent, or the two a wrapped polygon copies) followed by a GL_QUADS or GL_QUAD_STRIP of one
// (ended, or open at the flush), or a GL_TRIANGLE_STRIP of two followed by one of one, or at a later
// call; in both list modes; not with the quad first, a point between, a quad of two or three, nor
// other pairs of modes (measured over every pair of the six triangle and quad modes, one to three
// vertices each; seed 299792 stream 2831664394777852868 found the strip and the quad strip; repro
// list_strip_then_quad_crash.txt; two_then_one_crashes). A compiled draw counts as either
// primitive, after a glBegin/glEnd pair too: measured (seed 141421 stream 4449590931373811147, repro
// list_pair_then_quad_draw_crash.txt), GL_TRIANGLES, GL_TRIANGLE_FAN, GL_TRIANGLE_STRIP or GL_POLYGON
// of two vertices, then a glDrawArrays(GL_QUADS or GL_QUAD_STRIP) of one aborts at glCallList (the
// note of Stop 26 that it did not crash had compiled the list without calling it). The write that
// overflows was not found in the source. `open`: the primitive is still open.
void Context::note_node_primitive(bool open) {
  const int count = lists_.vertices + lists_.wrap_copies;  // its vertices in this vertex list
  if (two_then_one_crashes(lists_.node_last_mode, lists_.node_last_count, lists_.open_mode, count))
    deviations_.insert(kListTwoThenQuadCrash);
  if (!open) lists_.node_last_mode = lists_.open_mode, lists_.node_last_count = count;
  note_node_mode(lists_.open_mode, count);
}

// Measured (repro list_modes_fed_back_first.txt): a GL_COMPILE list holding GL_LINES of two vertices
// then GL_TRIANGLES of three, called in GL_FEEDBACK, feeds back the line alone (glRenderMode returns 5
// where GL says 13); two lines then two triangles, the lines; in GL_SELECT a triangle on screen after
// a line off it makes no hit. Mesa's compiler merges a vertex list's primitives of one mode into one
// draw (a GL_LINE_STRIP next to lines becomes lines, a primitive without a vertex is dropped) and,
// where the merged draws have more than one mode, its playback calls the driver's DrawGalliumMultiMode
// (vbo_save_draw.c), which in feedback and selection runs the draw module once per mode with one
// pipe_draw_info: only the first mode's draws are fed back, and with a second change of mode glCallList
// crashes (row 66). The playback saves and restores the info's index buffer (info->index.gl_bo) around
// that call, as the draws replace it; which line of 22.3 drops the later draws was not found. Not
// there: a state call between the modes (two vertex lists), a list replayed through immediate mode,
// GL_COMPILE_AND_EXECUTE's own drawing, GL_RENDER. Named (row 72, a bug no program relies on): soft
// feeds back every primitive.
void Context::note_node_mode(GLenum mode, int vertices) {
  if (vertices > 0) lists_.node_modes.push_back(mode);
}

// The draws of the vertex list being closed, as compile_vertex_list (vbo_save_api.c) merges its
// primitives: a GL_LINE_LOOP last in the vertex list becomes a GL_LINE_STRIP; a GL_LINE_STRIP becomes
// GL_LINES where the draw before is GL_LINES or the primitive after a strip or lines; a primitive
// joins the draw before where the modes are the same and not GL_LINE_LOOP, GL_TRIANGLE_FAN,
// GL_QUAD_STRIP or GL_POLYGON. More than one mode among the draws: row 72. Measured (seed 271828
// stream 817, repro list_modes_crash.txt): Mesa 22.3 segfaults in glCallList in feedback where a draw
// after the second has another mode than the one before it (GL_LINE_LOOP, GL_LINE_LOOP,
// GL_TRIANGLE_STRIP; three GL_LINE_LOOPs, the last a strip; GL_TRIANGLE_FAN, GL_TRIANGLE_FAN,
// GL_LINES; GL_POLYGON, GL_POLYGON, GL_POINTS), not where only the second does (GL_POINTS,
// GL_TRIANGLE_FAN, GL_TRIANGLE_FAN; two draws of two modes).
void Context::close_node_modes() {
  std::vector<GLenum>& m = lists_.node_modes;
  if (!m.empty() && m.back() == GL_LINE_LOOP) m.back() = GL_LINE_STRIP;
  std::vector<GLenum> draws;
  for (size_t i = 0; i < m.size(); ++i) {
    GLenum mode = m[i] == GL_LINE_STRIP ? GLenum(GL_LINES) : m[i];
    const bool merge = !draws.empty() && draws.back() == mode && mode != GL_LINE_LOOP && mode != GL_TRIANGLE_FAN &&
                       mode != GL_QUAD_STRIP && mode != GL_POLYGON;
    const bool next_lines = i + 1 < m.size() && (m[i + 1] == GL_LINE_STRIP || m[i + 1] == GL_LINES);
    if (m[i] == GL_LINE_STRIP && !merge && !next_lines) mode = GL_LINE_STRIP;
    if (!merge) draws.push_back(mode);
  }
  for (size_t k = 1; k < draws.size(); ++k) {
    if (draws[k] != draws[0]) lists_.compiling.mixed_modes = true;
    if (k >= 2 && draws[k] != draws[k - 1]) lists_.compiling.modes_crash = true;
  }
  m.clear();
}

// Measured by the seed-8086 helper (repro list_vertexless_wrap_current.txt, seed 2026 stream 972):
// a vertex list whose format holds an attribute besides the position and which has no vertex (a
// glNormal or glColor first sent after the last vertex of a GL_POINTS wraps the store with nothing
// to copy, and nothing follows before the flush; a primitive with attributes and no vertex) makes
// Mesa's compile_vertex_list take its current_data from the store's first slot (vertex_count - 1
// taken as 0), which that vertex list never wrote: glCallList then sets the current values from it
// (a stale vertex of an earlier list, zeros in fresh memory). Named (row 55); a compiled draw's
// vertex list copies nothing (no_current_update), and a list replayed through immediate mode replays
// no vertex.
void Context::note_vertexless_node() {
  if (lists_.node_open && !lists_.node_draw && lists_.node_vertices == 0 && (lists_.attributes & 7))
    lists_.compiling.vertexless = true;
  lists_.node_vertices = 0;
}

void Context::end_list_node() {
  lists_.carry = 0;  // the flush empties the store's format (list_vertex_compiled)
  if (lists_.open) note_node_primitive(true);
  close_node_modes();
  lists_.node_last_mode = 0;
  note_vertexless_node();
  if (lists_.node_open)
    lists_.compiling.record<list_node_ends>(lists_.node_draw, !lists_.closing_loop ? 0
                                                              : lists_.vertices == 0 || lists_.loop_restarted ? 8  // row 68
                                                                                     : lists_.attributes & 3,
                                            !lists_.node_draw && lists_.attributes != 0),
        lists_.node_open = false;
  // A line loop ended last in the vertex list is closed with a copy of its first vertex
  // (convert_line_loop_to_strip), a repeat the compiler then removes (kListLoopbackDeduplicated):
  // measured, seed 161803 stream 2075 (repro list_loop_copy_deduplicated.txt), a GL_COMPILE list's
  // glDrawArrays(GL_LINE_LOOP) of one vertex, a flush, then a wrap that marks the list for loopback
  // leaves another current colour than the loop's vertex after glCallList.
  if (lists_.closing_loop && lists_.vertices > 0) lists_.store_repeats = true;
  close_store();
  // The store and its format are emptied in GL_COMPILE too (GL_COMPILE_AND_EXECUTE's run_held_back
  // follows at the same call): a colour after the flush joins the format again.
  if (!list_executes()) run_held_back();
}

// Mesa's compiler keeps only the distinct vertices of a vertex list (one index each) unless the list
// is already marked for loopback, which replays the vertices by their first positions in that buffer.
// Measured (repro list_loopback_deduplicated.txt): a GL_COMPILE list's glDrawArrays(GL_LINES) of nine
// positions, then glBegin(GL_LINES) and a glVertex3 left open at glEndList, draws other lines than
// sent where a position repeats among the first eight (all nine distinct, or only the ninth, unused,
// repeating: as sent). Named, not modelled.
void Context::store_vertex(int kind, const glm::dvec4& v) {
  if (kind == 1) lists_.store_normal = glm::dvec3(v);
  if (kind == 2) lists_.store_color = v;
  if (kind >= 0 || lists_.store_repeats) return;
  if (lists_.store_vertices.size() >= 4096) return void(lists_.store_repeats = true);  // taken as repeating
  std::array<uint32_t, 11> key{};
  auto put = [&](int at, double x) {
    const float f = float(x);
    std::memcpy(&key[size_t(at)], &f, sizeof f);
  };
  for (int k = 0; k < 4; ++k) put(k, v[k]);
  for (int k = 0; k < 3 && (lists_.attributes & 1); ++k) put(4 + k, lists_.store_normal[k]);
  for (int k = 0; k < 4 && (lists_.attributes & 2); ++k) put(7 + k, lists_.store_color[k]);
  if (!lists_.store_vertices.insert(key).second) lists_.store_repeats = true;
}

void Context::close_store() {
  if (lists_.store_repeats && !lists_.compiling.loopback) lists_.deduplicated = true;
  lists_.store_vertices.clear(), lists_.store_repeats = false;
}

// A wrap ends a vertex list inside a primitive, which goes on in the next with the same
// no_current_update: one drawn from arrays leaves the values from before both (measured: a compiled
// glDrawArrays whose first element's position grows the format after another draw, lit: seed 4242
// stream 701 shrunk), so nothing is put back in the middle of the primitive; one from glBegin copies
// its values so far, the start of the next.
void Context::split_list_node(int joining) {
  close_node_modes();
  lists_.node_last_mode = 0;  // the open primitive's rest starts the next vertex list
  // Whether the vertex list before the wrap copies its last vertex to the current values (an attribute
  // besides the position in its format, its last primitive from glBegin), and so leaves Mesa inside
  // the open primitive (2) or outside (1) until the next vertex list copies (Context::flush_pending).
  const int copy = lists_.node_draw || lists_.attributes == 0 ? 0 : lists_.open ? 2 : 1;
  // Bits 16 (normal) and 32 (colour): attributes sent after the open primitive's last vertex, the
  // wrapping one or one already in the format. They wait in Mesa's vertex template, not in the vertex
  // list before the wrap, which hands the current values its last vertex's
  // (list_snapshot_last_vertex). Measured: the wrapping one, repro list_draw_inside_begin_wrapped.txt;
  // one in the format (seed 299792 stream 6292637399379987596: glBegin, glNormal, glVertex, glNormal,
  // then a first glColor wrapping and a compiled draw of none leave the first normal after
  // glCallList), repro list_trailing_before_wrap_draw.txt.
  const int last = lists_.had_vertex ? (lists_.trailing & (lists_.attributes | joining) & 3) << 4 : 0;
  // Bit 64: the wrapping attribute came before any vertex of the open primitive (list_before_joining).
  const int before = joining && lists_.open && !lists_.had_vertex ? 64 : 0;
  const int element = lists_.held_element ? 128 : 0;
  // Bit 8: the vertex list before the wrap holds an attribute besides the position, so it has current
  // values to copy, and its copy (playback_copy_to_current) sets Mesa's CurrentExecPrimitive; one of
  // positions alone returns before it (Context::node_ends).
  const int current = lists_.attributes != 0 ? 8 : 0;
  if (lists_.node_open) lists_.compiling.record<list_node_split>(lists_.node_draw, copy, joining | last | current | before | element);
  note_vertexless_node();
  close_store();
}

void Context::node_begins() {
  flush_pending(true);
  keep_node_values();
  lists_.node_inside = in_begin_ || exec_inside_;
}

// A vertex list whose last primitive begun is a compiled draw copies nothing to the current values
// (playback_copy_to_current is not called), so it leaves Mesa's CurrentExecPrimitive as the vertex
// lists before it left it: inside a primitive a wrap cut (its first vertex list ends it not) even
// where the list's glEnd ended it or a compiled draw inside it ended it, so that a glEnd the list
// compiled after the draw raises nothing. Measured (seed 271828 stream 1376, repro
// list_draw_inside_begin_wrapped.txt): glBegin(GL_POINTS), glColor3f, glVertex, glColor4f (the wrap),
// then glDrawArrays of none or four (or glEnd, then the draw), then glEnd: no error, the point drawn;
// without the wrap the last glEnd is GL_INVALID_OPERATION. Only CurrentExecPrimitive is set, not
// Mesa's glBegin/glEnd dispatch (playback_copy_to_current switches none), so soft stays outside and
// notes it (exec_inside_): the calls that test CurrentExecPrimitive themselves are refused, glEnd
// ends it, every other call is taken. Measured (seed 577215 stream 9400455120439465367, repro
// list_draw_last_leaves_exec_inside.txt): with a vertex after the wrap too (soft took that for
// outside, from a glGet answered), glPushMatrix is taken, glIsEnabled and glNewList refused, and a
// glEnd compiled after the draw raises nothing.
void Context::node_ends(bool draw, int loop, bool copy) {
  if (refused_node_) {  // skipped whole, its current values too (Context::Begin)
    refused_node_ = false;
    return restore(node_values_);
  }
  if (lists_.replaying_loopback) {
    if (loop & 8) deviations_.insert(kListEmptyLoopCurrent);
    if (loop & 1) normal_ = lists_.loop_first_normal;
    if (loop & 2) color_ = lists_.loop_first_color;
  } else if (draw) {
    // Measured (seed 173205 stream 10873261804190826188 shrunk, repro list_draw_node_keeps_materials.txt):
    // with colour material on, a compiled draw inside a glBegin whose vertex list copies nothing leaves
    // the material the vertex list before it tracked, not the draw's last colour.
    restore(node_values_);
    materials_[0] = node_materials_[0], materials_[1] = node_materials_[1], flushed_color_ = node_flushed_color_;
    constants_dirty_ = true;
    // Measured (seed 161803 stream 8254993617977854356 shrunk, repro list_exec_inside_holds_values.txt):
    // a list's glMaterialf after such a draw, or a glNormal after the list, reads back as before
    // until a glEnd ends the primitive.
    if (lists_.node_inside && !in_begin_ && !exec_inside_) {
      copy_pending();  // the vertex lists' copies track colour material at once
      inside_values_ = current_values(), inside_materials_[0] = materials_[0], inside_materials_[1] = materials_[1];
    }
    if (lists_.node_inside && !in_begin_) exec_inside_ = true;
  } else if (copy) {
    lists_.mesa_inside = exec_inside_ = false;  // its last primitive ended in it
  }
}

void Context::node_splits(bool draw, int copy, int joining) {
  const bool current = joining & 8, before = joining & 64, element = joining & 128;
  const int last = (joining >> 4) & 3;
  joining &= 3;
  if (copy && !lists_.replaying_loopback) lists_.mesa_inside = copy == 2;
  flush_pending(true, joining);  // the next vertex list's FLUSH_FOR_DRAW
  if (draw) return;
  // The values a later vertex list that copies nothing (its last primitive a compiled draw) leaves:
  // this vertex list's last vertex's, not the wrapping attribute's (measured: glColor3f, glVertex,
  // glColor4f(0, 0, 0, 0) (the wrap), a compiled draw: GL_CURRENT_COLOR alpha 1 after glCallList;
  // repro list_draw_inside_begin_wrapped.txt).
  keep_node_values(), lists_.node_inside = in_begin_ && current;
  if (element) node_values_.normal = lists_.before_join_normal, node_values_.color = lists_.before_join_color;
  if (last & 1) node_values_.normal = lists_.last_vertex_normal;
  if (last & 2) node_values_.color = lists_.last_vertex_color;
  if (before && (joining & 1)) node_values_.normal = lists_.before_join_normal;
  if (before && (joining & 2)) node_values_.color = lists_.before_join_color;
}

// Mesa's flushes of the values a list left pending (the rule of the unmerged reading of vbo_save,
// docs/fidelity.md; vbo_exec_api.c, vbo_exec_FlushVertices_internal): a glNormal or glColor the list
// runs outside its glBegin/glEnd goes to the immediate-mode vbo, whose NeedFlush then asks for
// FLUSH_UPDATE_CURRENT. The first flush (a vertex list's FLUSH_FOR_DRAW; glCallList's own
// FLUSH_CURRENT before the list) copies it to the current values and leaves NeedFlush =
// ~FLUSH_UPDATE_CURRENT, a flush of stored vertices; the next of those (a vertex list's
// FLUSH_FOR_DRAW, a state call's FLUSH_VERTICES) copies it again and forgets it (the vbo's format
// reset). So the pending value wins over the vertex lists run after the first flush and before the
// second, and loses to those after. Nothing flushes while a vertex list's copy left Mesa inside a
// wrapped primitive, nor in a list replayed through immediate mode (not modelled: list_loopback).
// Measured through seed 4242 streams 339 and 564 and seed 2026 stream 486's colour (repro
// list_pending_flushed_by_vertex_lists.txt); whatever is still pending at the end of the outermost
// glCallList reaches the state there (end_list_calls).
void Context::begin_list_calls() {
  lists_.calling = true, lists_.pending = 0, lists_.need_update = lists_.mesa_inside = false;
  lists_.stored_bit = vertices_kept_ || color_size_ > 0 || normal_in_format_;
}

void Context::apply_pending() {
  if (lists_.pending & 1) normal_ = node_values_.normal = lists_.pending_normal;
  if (lists_.pending & 2) color_ = node_values_.color = lists_.pending_color;
}

// joining: the attribute whose call wrapped the store, recorded before the wrap but in the next
// vertex list on Mesa, so its value stays.
void Context::flush_pending(bool draw, int joining) {
  // (soft is inside the list's primitive at a wrap, where Mesa is only after a copy: mesa_inside)
  if (!lists_.calling || lists_.replaying_loopback || lists_.mesa_inside || (!draw && in_begin_)) return;
  if (!lists_.stored_bit && !(draw && lists_.need_update)) return;
  const int pending = lists_.pending;
  lists_.pending &= ~joining;
  apply_pending();
  lists_.pending = pending;
  if (lists_.stored_bit) lists_.pending = 0, lists_.stored_bit = lists_.need_update = false;
  else lists_.need_update = false, lists_.stored_bit = true;
}

void Context::compile_draw_elements(DisplayList& l, GLenum mode, GLsizei count, GLenum type, const void* indices) {
  GLenum e = GL_NO_ERROR;
  if (count < 0) e = GL_INVALID_VALUE;
  else if (!valid_primitive(mode)) e = primitive_error(mode);
  // Mesa's compiled glDrawElements calls a bad index type GL_INVALID_VALUE (measured), where the
  // draw itself says GL_INVALID_ENUM.
  else if (type != GL_UNSIGNED_BYTE && type != GL_UNSIGNED_SHORT && type != GL_UNSIGNED_INT) e = GL_INVALID_VALUE;
  if (e != GL_NO_ERROR) return compile_error(l, e);
  if (!indices) return;
  std::vector<GLuint> names(static_cast<size_t>(count));
  for (GLsizei k = 0; k < count; ++k)
    names[k] = type == GL_UNSIGNED_BYTE    ? static_cast<const GLubyte*>(indices)[k]
               : type == GL_UNSIGNED_SHORT ? static_cast<const GLushort*>(indices)[k]
                                           : static_cast<const GLuint*>(indices)[k];
  compile_elements(l, mode, count, names.data(), 0);
}

void Context::compile_element(DisplayList& l, GLint i) {
  const Fixed f = element_fixed();
  // GL_COMPILE_AND_EXECUTE records the element into the list whole before it is held back, where a
  // wrap it causes records the split after it: the values the vertex list before the wrap leaves are
  // those from before the element (bit 128 of the split; measured, seed 161803 stream
  // 6598746491301999856, repro list_executing_element_wraps.txt: a normal trailing a GL_TRIANGLE_FAN's
  // vertex, glEnd, then glBegin and a glArrayElement whose colour array joins the format, and a
  // compiled draw: glCallList leaves the fan's vertex's normal, not the trailing one the element's
  // vertex carries).
  if (&l == &lists_.compiling && !lists_.compiling_draw && lists_.open && list_executes() && !lists_.fallback)
    l.record<list_value_before_joining>();
  lists_.held_element = &l == &lists_.held_back && !lists_.compiling_draw;
  // A glArrayElement outside the list's glBegin/glEnd sets the pending values too (end_list_calls).
  const bool compiled = &l == &lists_.compiling && !lists_.compiling_draw;
  const bool outside = compiled && !lists_.open;
  // Inside the list's own glBegin its values count as glNormal, glColor and glVertex do for the
  // trailing attributes (list_trailing).
  const bool inside = compiled && lists_.open;
  // Inside a primitive (the list's own or a compiled draw's) the element enters the vertex store.
  const bool format = lists_.open && forms_format(l);
  if (normal_array_.enabled && normal_array_.pointer) {
    const glm::dvec4 n = attribute(normal_array_, i, 3, f, glm::dvec4(0));
    if (inside) list_trailing(l, 1);
    if (format) hold_back(1), store_vertex(1, n);
    l.record<list_normal>(n.x, n.y, n.z);
    if (outside) mark_list_attribute(l, 1), store_vertex(1, n);
  }
  if (color_array_.enabled && color_array_.pointer) {
    const glm::dvec4 c = attribute(color_array_, i, color_array_.size, f, glm::dvec4(1));
    if (inside) list_trailing(l, 2);
    if (format) hold_back(2, int(color_array_.size)), store_vertex(2, c);
    l.record<list_color>(c.r, c.g, c.b, c.a, int(color_array_.size));
    if (outside) mark_list_attribute(l, 2), store_vertex(2, c);
  }
  if (vertex_array_.enabled && vertex_array_.pointer) {
    const glm::dvec4 v = attribute(vertex_array_, i, vertex_array_.size, Fixed::Raw, glm::dvec4(0, 0, 0, 1));
    if (format) hold_back(-1, int(vertex_array_.size)), store_vertex(-1, v);
    if (lists_.open || lists_.compiling_draw)
      list_vertex_compiled(l, (normal_array_.enabled && normal_array_.pointer ? 1 : 0) |
                                  (color_array_.enabled && color_array_.pointer ? 2 : 0),
                           forms_format(l));
    l.record<list_vertex>(v.x, v.y, v.z, v.w);
    if (inside) lists_.had_vertex = true, lists_.trailing = 0;
    // A glArrayElement in the list's glBegin: a line loop's first vertex keeps its values (counted in
    // the vertex store by the list that forms it, the held-back calls after the list in
    // GL_COMPILE_AND_EXECUTE).
    if (lists_.open && !lists_.compiling_draw) {
      if (format) note_loop_first_vertex(l);
      else if (lists_.open_mode == GL_LINE_LOOP && lists_.vertices == 0 && !lists_.wrapped)
        l.record<list_loop_first_vertex>();
    }
  }
  lists_.held_element = false;
}

}  // namespace ffc::state
