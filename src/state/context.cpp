// The context itself: construction, the current context, errors, and what belongs to no GL area.
// The entry points are defined in files named for the GL area they implement, as Mesa's
// src/mesa/main does: enable.cpp, light.cpp, matrix.cpp, clear.cpp, raster_state.cpp, fog.cpp,
// get.cpp (and get_table.cpp), array.cpp, immediate.cpp, draw.cpp, raster_pos.cpp, feedback.cpp
// and read_pixels.cpp; the vertex stage is vertex_stage.cpp and the general path's primitive
// assembly primitive.cpp.
#include "state/context.h"

#include <cstdlib>

#include "simd/target.h"

namespace ffc::state {

void Context::make_current(Context* c) { current_ = c; }

Context::Context(int width, int height, Precision precision)
    : fb_(width, height), precision_(precision), viewport_(0, 0, width, height) {
  lights_[0].diffuse = lights_[0].specular = glm::dvec4(1);
  simd::configure_from_environment();  // FFCOMPAT_SIMD / FFCOMPAT_SCALAR, before the first kernel
  raster::configure_llvmpipe_fma_from_environment();  // FFCOMPAT_LLVMPIPE_FMA
  if (const char* e = std::getenv("FFCOMPAT_EARLY_CORNERS"); e && *e) early_corners_ = std::strtoull(e, nullptr, 10);
}

Context::~Context() { early_join(); }

GLenum Context::GetError() {
  if (in_begin_ || exec_inside_) {  // Mesa: returns 0 and records INVALID_OPERATION
    error(GL_INVALID_OPERATION);
    return GL_NO_ERROR;
  }
  const GLenum e = error_;
  error_ = GL_NO_ERROR;
  return e;
}

bool Context::outside_begin_end() {
  if (in_begin_) error(GL_INVALID_OPERATION);
  // Nearly every call that checks this is one where Mesa flushes the vertices it keeps after
  // glEnd (FLUSH_VERTICES), emptying the pending current values (see update_color_material).
  else flush_vertices();
  return !in_begin_;
}

void Context::flush_vertices() {
  flush_pending(false);
  if (vertices_kept_) vertices_kept_ = false, flush_stored();
}

// Queries (glGet*, glIsEnabled, glGetLight, glGetPointerv, glGetString) and client state (the array
// pointers, glEnable/DisableClientState, glPixelStore), glMatrixMode, glPushMatrix and the clear
// values raise the same error inside glBegin/glEnd but flush nothing: Mesa keeps its stored
// vertices and vertex format through them (measured one call at a time: only glGetMaterial among
// the queries flushes). The current colour and normal are copied out first (FLUSH_CURRENT), see
// get_values.
//
// While a list compiles Mesa runs the calls that are not compiled through its compiling dispatch,
// which has no such check, so a GL_COMPILE_AND_EXECUTE list's wrapped primitive (display_list.cpp)
// leaves them taken (measured: glGet*, glGetLight, glGetMaterial, client state, glPixelStore,
// glFeedbackBuffer, glSelectBuffer, glReadPixels); glIsEnabled, glRenderMode, glGetError and
// glGetString check for themselves (getstring.c's ASSERT_OUTSIDE_BEGIN_END_WITH_RETVAL reads the
// executing side, CurrentExecPrimitive: repro list_get_string_executing_inside.txt).
bool Context::outside_begin_end_keeping_vertices() {
  if (in_begin_ && lists_.mode == 0) error(GL_INVALID_OPERATION);
  return !in_begin_ || lists_.mode != 0;
}
bool Context::query_allowed() { return outside_begin_end_keeping_vertices(); }
bool Context::outside_begin_end_or_compiling() { return (in_begin_ && lists_.mode != 0) || outside_begin_end(); }

// The calls whose Mesa entry point tests CurrentExecPrimitive itself (ASSERT_OUTSIDE_BEGIN_END), so
// that they are refused where a list's vertex list left it set without Mesa's glBegin/glEnd dispatch
// (exec_inside_, Context::node_ends), where every other call is taken. Measured after such a list:
// glNewList (GL_LIST_INDEX stays 0), glGenLists (returns 0), glIsList (returns GL_FALSE) refused;
// glPushMatrix, glPushAttrib, glMatrixMode, glEnable, glLineWidth and glGet* taken (repro
// list_draw_last_leaves_exec_inside.txt). glGetError, glIsEnabled, glGetString and glBegin test it too.
bool Context::outside_exec_primitive() {
  if (exec_inside_) return error(GL_INVALID_OPERATION), false;
  return outside_begin_end();
}

pool::Workers& Context::workers() {
  if (!workers_) workers_ = std::make_unique<pool::Workers>(threads_);
  return *workers_;
}

// Nothing is left to do: every draw is finished when its call returns. Inside glBegin/glEnd both
// are errors (GL 2.1 section 2.6.3).
void Context::Finish() { outside_begin_end(); }
void Context::Flush() { outside_begin_end(); }

const GLubyte* Context::GetString(GLenum name) {
  if (in_begin_ || exec_inside_) return error(GL_INVALID_OPERATION), nullptr;  // while a list compiles too, as glIsEnabled
  switch (name) {
    case GL_VENDOR: return reinterpret_cast<const GLubyte*>("ffcompat");
    case GL_RENDERER: return reinterpret_cast<const GLubyte*>("ffcompat soft (fixed-function)");
    case GL_VERSION: return reinterpret_cast<const GLubyte*>("2.1 ffcompat");
    case GL_EXTENSIONS: return reinterpret_cast<const GLubyte*>("");
    case GL_SHADING_LANGUAGE_VERSION: return reinterpret_cast<const GLubyte*>("1.20");  // GL 2.1's
  }
  error(GL_INVALID_ENUM);
  return nullptr;
}

}  // namespace ffc::state
