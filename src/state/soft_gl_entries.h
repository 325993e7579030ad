// The C entry points of our GL (src/state/soft_gl*.cpp), declared once from the dispatch's list
// (src/gl/gl_functions.inc) so that proc_address finds each in whichever file defines it; a name
// in the list that no file defines fails the link. LISTABLE makes an entry point compile into
// display lists (the rule: src/state/display_list.h).
#pragma once
#include <GL/gl.h>

#include <tuple>
#include <type_traits>

#include "state/context.h"
#include "state/display_list.h"
#include "state/gl_rules.h"

namespace ffc::state::entry {

#define FFC_GL_FUNCTION(ret, fn, params) ret APIENTRY fn params;
#include "gl/gl_functions.inc"
#undef FFC_GL_FUNCTION
// The by-value calls the immediate-mode variants end in (soft_gl_immediate.cpp).
void APIENTRY VertexValues(GLdouble x, GLdouble y, GLdouble z, GLdouble w, GLint size);  // size: 2, 3 or 4 components
void APIENTRY NormalValues(GLdouble x, GLdouble y, GLdouble z);
void APIENTRY ColorValues(GLdouble r, GLdouble g, GLdouble b, GLdouble a, GLint components);
void APIENTRY TexCoordValues(GLfloat s, GLfloat t, GLfloat r, GLfloat q);

inline Context* C() { return Context::current(); }

// The by-value twins of glLoadMatrix and glMultMatrix that lists record (soft_gl.cpp).
void APIENTRY LoadMatrixValues(Floats<16, GLdouble> m);
void APIENTRY MultMatrixValues(Floats<16, GLdouble> m);

// How a listable call compiles, as Mesa's lists do. While the list's own glBegin is open (one
// compiled and its glEnd not yet), a state call is not recorded: an error is, raised when the list
// runs, and at once in GL_COMPILE_AND_EXECUTE (Mesa's compile errors). In GL_COMPILE_AND_EXECUTE a
// state call first executes the vertex-stream calls held back, then itself; a vertex-stream call
// (glBegin, glVertex, glColor ...) is held back: Mesa's list keeps those vertices in its vertex
// store and draws them at its next flush, which also comes when an attribute first appears after
// a vertex of an open primitive (its vertex format grows); glMaterialfv and glMaterialiv (and
// glMaterialf and glMateriali, which reach them: soft_gl.cpp) execute at once without that flush.
// Measured: docs/deviations.md row 50.
enum class ListKind { State, Vertex, Material };

// Whether two entry points are the same one (of any signatures).
template <auto F, auto G>
constexpr bool same_entry() {
  if constexpr (std::is_same_v<decltype(F), decltype(G)>) return F == G;
  else return false;
}

// The value a glNormal (kind 1), glColor (2) or glVertex (-1) enters the list's store with, as
// Context::store_vertex takes it: the normal, the colour or position with its fourth component.
template <auto Fn, typename... A>
void store_value(Context* c, int kind, const A&... a) {
  if constexpr (same_entry<Fn, &NormalValues>()) {
    c->store_vertex(kind, glm::dvec4(a..., 0.0));
  } else {
    const auto v = std::tie(a...);
    c->store_vertex(kind, glm::dvec4(std::get<0>(v), std::get<1>(v), std::get<2>(v), std::get<3>(v)));
  }
}

template <ListKind K, auto Fn, typename... A>
bool compiled_only(const A&... a) {
  Context* c = C();
  DisplayList* l = c ? c->list_recording() : nullptr;
  if (!l) return false;
  ListState& ls = c->list_state();
  if (K == ListKind::State && ls.open) {
    c->record_list_error(GL_INVALID_OPERATION);
    return true;
  }
  if constexpr (same_entry<Fn, &ShadeModel>()) {
    // Mesa's save_ShadeModel (dlist.c), unlike the other state calls, executes first in
    // GL_COMPILE_AND_EXECUTE, before the list's store is flushed (so a primitive held back is drawn
    // with the new model and its values stay pending on the executing side), and where the list's
    // last compiled shade model is the same it is neither compiled nor a flush. Measured: repro
    // list_shade_model_order.txt.
    // Executed inside the list's wrapped glBegin, the executing side refuses it (measured).
    if (c->list_executes() && c->inside_begin()) c->record_error(GL_INVALID_OPERATION);
    else if (c->list_executes()) {
      ++ls.depth;  // executes, recording nothing
      Fn(a...);
      --ls.depth;
    }
    const GLenum mode = GLenum(a...);
    if (ls.shade_model == mode) return true;
    ls.shade_model = mode;
    c->end_list_node();
    l->record<Fn>(a...);
    if (c->list_executes()) c->run_held_back();
    return true;
  }
  // Outside the list's own glBegin/glEnd a vertex-stream call other than glBegin and glEnd compiles
  // as a state call does (Mesa swaps its vertex format out there: "compiled as opcodes"), so in
  // GL_COMPILE_AND_EXECUTE it flushes what was held back and executes at once (measured: glNormal3d
  // then glGet of GL_CURRENT_NORMAL; repro list_attribute_outside_begin.txt).
  constexpr bool begin_or_end = same_entry<Fn, &Begin>() || same_entry<Fn, &End>();
  if (K == ListKind::Vertex && !begin_or_end && !ls.open) {
    c->end_list_node();  // Mesa's vertex lists: display_list.cpp, Context::start_list_node
    l->record<Fn>(a...);
    // The compiler's own current value too (ListState.CurrentAttrib: Context::copied_vertex_values).
    if constexpr (same_entry<Fn, &NormalValues>()) c->mark_list_attribute(*l, 1), store_value<Fn>(c, 1, a...);
    if constexpr (same_entry<Fn, &ColorValues>()) c->mark_list_attribute(*l, 2), store_value<Fn>(c, 2, a...);
    if (!c->list_executes()) return true;
    c->run_held_back();
    return false;
  }
  if constexpr (same_entry<Fn, &Begin>()) {
    // A bad mode is a compile error (raised at once in GL_COMPILE_AND_EXECUTE), nothing opened:
    // measured, glBegin(GL_CONSTANT_ATTENUATION) while compiling. So is a glBegin inside the
    // list's own open glBegin (measured: GL_INVALID_OPERATION at once in GL_COMPILE_AND_EXECUTE).
    if (ls.open) return c->record_list_error(GL_INVALID_OPERATION), true;
    if (!valid_primitive(GLenum(a...))) return c->record_list_error(primitive_error(GLenum(a...))), true;
  }
  if constexpr (K == ListKind::Vertex) {
    // After a glCallList inside the list's glBegin the rest of the primitive compiles as calls that
    // GL_COMPILE_AND_EXECUTE executes at once, outside the vertex store (Context::list_fallback).
    if (ls.open && ls.fallback) {
      if constexpr (same_entry<Fn, &End>()) ls.open = ls.fallback = ls.shown = false;
      l->record<Fn>(a...);
      return !c->list_executes();
    }
    if constexpr (same_entry<Fn, &Begin>())
      ls.fallback = false, ls.open = true, ls.vertices = ls.primitive_vertices = 0, ls.open_mode = GLenum(a...), ls.had_vertex = false,
      ls.trailing = 0, ls.wrapped = false, ++ls.prims, ls.wrap_copies = 0, ls.closing_loop = ls.loop_restarted = false;
    if constexpr (same_entry<Fn, &NormalValues>()) c->list_trailing(*l, 1), ls.carry &= ~1;
    if constexpr (same_entry<Fn, &ColorValues>()) c->list_trailing(*l, 2), ls.carry &= ~2;
    if constexpr (same_entry<Fn, &VertexValues>()) {
      // A vertex after an earlier primitive's trailing values carries them (Context::list_vertex_compiled).
      if (ls.open) c->list_vertex_compiled(*l, 0, !c->list_executes());
      ls.had_vertex = true, ls.trailing = 0;
    }
    if constexpr (same_entry<Fn, &End>()) {
      // A glEnd without its glBegin in the list: Mesa records it, and in GL_COMPILE_AND_EXECUTE
      // executes it now as a state call (measured: GL_INVALID_OPERATION after a refused glBegin).
      if (!ls.open) {
        c->end_list_node();
        l->record<Fn>(a...);
        if (!c->list_executes()) return true;
        c->run_held_back();
        return false;
      }
      c->note_node_primitive(false);
      if (ls.had_vertex) ls.carry |= ls.trailing;  // left in Mesa's vertex template (Context::list_vertex_compiled)
      ls.open = false, ls.closing_loop = ls.open_mode == GL_LINE_LOOP;
      c->note_list_primitive(ls.open_mode, ls.primitive_vertices);
    }
  }
  if constexpr (same_entry<Fn, &Begin>()) c->start_list_node(false);
  if constexpr (K != ListKind::Vertex) {
    if (!ls.open) c->end_list_node();
  }
  if constexpr (same_entry<Fn, &NormalValues>()) c->list_before_joining(*l, 1);
  if constexpr (same_entry<Fn, &ColorValues>()) c->list_before_joining(*l, 2);
  l->record<Fn>(a...);
  [[maybe_unused]] const int trailing = ls.had_vertex ? ls.trailing : 0;  // what glEnd drops (Context::list_trailing)
  if constexpr (same_entry<Fn, &End>()) c->list_primitive_end(*l, trailing);
  if constexpr (K == ListKind::Vertex) {
    int kind = 0;  // what enters Mesa's vertex format: a vertex (-1), an attribute (a bit), or neither
    int size = 0;  // a position's or colour's components (the last argument of both)
    if constexpr (same_entry<Fn, &VertexValues>()) kind = -1, size = int(std::get<4>(std::tie(a...)));
    if constexpr (same_entry<Fn, &NormalValues>()) kind = 1;
    if constexpr (same_entry<Fn, &ColorValues>()) kind = 2, size = int(std::get<4>(std::tie(a...)));
    if constexpr (same_entry<Fn, &TexCoordValues>()) kind = 4;
    if constexpr (same_entry<Fn, &EdgeFlag>()) kind = 8;
    c->hold_back(kind, size);  // in GL_COMPILE too: the list's own wraps are named there (display_list.cpp)
    // The values entering the store, for the repeats Mesa's compiler removes (display_list.cpp).
    if constexpr (same_entry<Fn, &NormalValues>() || same_entry<Fn, &VertexValues>() || same_entry<Fn, &ColorValues>())
      store_value<Fn>(c, kind, a...);
    if constexpr (same_entry<Fn, &VertexValues>())
      if (ls.open && c->list_executes()) c->list_vertex_compiled(c->list_held_back(), 0, true);
    if (c->list_executes()) c->list_held_back().record<Fn>(a...);
    if constexpr (same_entry<Fn, &VertexValues>()) {
      c->note_loop_first_vertex(*l);
      if (c->list_executes()) c->note_loop_first_vertex(c->list_held_back());
    }
    if constexpr (same_entry<Fn, &End>()) {
      if (c->list_executes()) c->list_primitive_end(c->list_held_back(), trailing);
      ls.had_vertex = false, ls.trailing = 0;
    }
    return true;
  }
  if (!c->list_executes()) return true;
  if constexpr (K == ListKind::State) c->run_held_back();
  if constexpr (K == ListKind::Material) {
    // Outside the list's own glBegin/glEnd Mesa's compiled glMaterial executes first and then
    // flushes what the list holds (so a held-back primitive is drawn with the new material: row
    // 50), measured: after a wrapped primitive's glEnd the executing side leaves its glBegin at
    // the glMaterialfv (repro list_material_flushes.txt).
    if (!ls.open) {
      ++ls.depth;  // executes, recording nothing
      Fn(a...);
      --ls.depth;
      c->run_held_back();
      return true;
    }
  }
  return false;
}

}  // namespace ffc::state::entry

// The first statement of a listable entry point: LISTABLE(Name, its arguments by value...);
// LISTABLE_VERTEX for the vertex stream, LISTABLE_MATERIAL for glMaterialfv (see ListKind).
#define FFC_LISTABLE(kind, fn, ...)                                                                  \
  do {                                                                                               \
    if (::ffc::state::entry::compiled_only<::ffc::state::entry::ListKind::kind, fn>(__VA_ARGS__)) return; \
  } while (0)
#define LISTABLE(fn, ...) FFC_LISTABLE(State, fn, __VA_ARGS__)
#define LISTABLE_VERTEX(fn, ...) FFC_LISTABLE(Vertex, fn, __VA_ARGS__)
#define LISTABLE_MATERIAL(fn, ...) FFC_LISTABLE(Material, fn, __VA_ARGS__)
