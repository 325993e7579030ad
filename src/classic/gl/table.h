// The table behind libGL.so.1's exports: one slot per GLAPI function of <GL/gl.h>
// (gl_exports.inc), filled per surface from its backend, and the surface current on this thread.
#pragma once

namespace ffc::classic {

enum Entry : int {
#define FFC_CLASSIC_GL(R, N, P, A, G) k_##N,
#include "gl_exports.inc"
#undef FFC_CLASSIC_GL
  kEntryCount
};

// "glAccum", ... indexed by Entry.
extern const char* const kEntryNames[kEntryCount];

// A backend's entry points: null where the backend has none.
struct Table {
  void* fn[kEntryCount] = {};
  const char* backend = "";  // for the report of a missing entry point
  bool soft = false;         // a missing call records GL_INVALID_OPERATION on the soft context
};

// The table of the surface current on this thread (null: none), as the exports read it. Initial-
// exec: read straight off the thread pointer, where the default model for a shared library calls
// __tls_get_addr on every gl* call (measured, 20 million glNormal3f on soft: 16.6 ns a call with
// the default model, 11.8 with this; 5.3 for soft's entry point called from a static program,
// where Context::current() is thread-local too but not behind __tls_get_addr).
extern thread_local const Table* g_current __attribute__((tls_model("initial-exec")));

inline void* entry(Entry e) {
  const Table* t = g_current;
  return t ? t->fn[e] : nullptr;
}

// A call the current backend lacks, or made with no surface current: reported once per name on
// stderr (once in all for no surface); on soft it records GL_INVALID_OPERATION.
void unavailable(Entry e);

// Our export of a name of gl_exports.inc, or null (exports.cpp).
void* export_address(const char* name);

}  // namespace ffc::classic
