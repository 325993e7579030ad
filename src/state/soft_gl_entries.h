// The C entry points of our GL (src/state/soft_gl*.cpp), declared once from the dispatch's list
// (src/gl/gl_functions.inc) so that proc_address finds each in whichever file defines it; a name
// in the list that no file defines fails the link. LISTABLE makes an entry point compile into
// display lists (the rule: src/state/display_list.h).
#pragma once
#include <GL/gl.h>

#include "state/context.h"
#include "state/display_list.h"

namespace ffc::state::entry {

#define FFC_GL_FUNCTION(ret, fn, params) ret APIENTRY fn params;
#include "gl/gl_functions.inc"
#undef FFC_GL_FUNCTION

inline Context* C() { return Context::current(); }

// The by-value twins of glLoadMatrix and glMultMatrix that lists record (soft_gl.cpp).
void APIENTRY LoadMatrixValues(Floats<16, GLdouble> m);
void APIENTRY MultMatrixValues(Floats<16, GLdouble> m);

// Records the call `Fn(a...)` into the list being compiled, if any; true when it must not also
// execute now (GL_COMPILE).
template <auto Fn, typename... A>
bool compiled_only(const A&... a) {
  Context* c = C();
  DisplayList* l = c ? c->list_recording() : nullptr;
  if (!l) return false;
  l->record<Fn>(a...);
  return !c->list_executes();
}

}  // namespace ffc::state::entry

// The first statement of a listable entry point: LISTABLE(Name, its arguments by value...).
#define LISTABLE(fn, ...)                                                  \
  do {                                                                     \
    if (::ffc::state::entry::compiled_only<fn>(__VA_ARGS__)) return;       \
  } while (0)
