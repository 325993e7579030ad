// Client vertex arrays (GL 2.1 section 2.8): the pointers, glArrayElement, and the checks every
// draw from arrays makes (readable arrays, memory, the vertex array's stand-in).
#include <unistd.h>

#include "state/client_arrays.h"
#include "state/context.h"

namespace ffc::state {


// The array pointers check as Mesa's varray.c does: the stride first, then the type, then the size.
// A negative stride alone is recorded by Mesa and then the pointer is set all the same (stride -1
// read back); ours ignores the call, as GL 2.1 section 2.5 says.
void Context::VertexPointer(GLint size, GLenum type, GLsizei stride, const void* p) {
  if (!outside_begin_end_keeping_vertices()) return;
  if (stride < 0) return error(GL_INVALID_VALUE);
  if (type != GL_SHORT && type != GL_INT && type != GL_FLOAT && type != GL_DOUBLE) return error(GL_INVALID_ENUM);
  if (size < 2 || size > 4) return error(GL_INVALID_VALUE);
  vertex_array_ = {vertex_array_.enabled, size, type, stride, p};
}

void Context::NormalPointer(GLenum type, GLsizei stride, const void* p) {
  if (!outside_begin_end_keeping_vertices()) return;
  if (stride < 0) return error(GL_INVALID_VALUE);
  if (type != GL_BYTE && type != GL_SHORT && type != GL_INT && type != GL_FLOAT && type != GL_DOUBLE)
    return error(GL_INVALID_ENUM);
  normal_array_ = {normal_array_.enabled, 3, type, stride, p};
}

void Context::ColorPointer(GLint size, GLenum type, GLsizei stride, const void* p) {
  if (!outside_begin_end_keeping_vertices()) return;
  if (stride < 0) return error(GL_INVALID_VALUE);
  if (type_size(type) == 0) return error(GL_INVALID_ENUM);
  if (size != 3 && size != 4) return error(GL_INVALID_VALUE);
  color_array_ = {color_array_.enabled, size, type, stride, p};
}

void Context::fetch_vertex(GLint i, Fixed f) {
  // Through the current values, as glNormal, glColor and glVertex would be called.
  if (normal_array_.enabled) {
    const glm::dvec4 n = attribute(normal_array_, i, 3, f, glm::dvec4(0));
    Normal(n.x, n.y, n.z);
  }
  if (color_array_.enabled) {
    const glm::dvec4 c = attribute(color_array_, i, color_array_.size, f, glm::dvec4(1));
    Color(c.r, c.g, c.b, c.a, color_array_.size);
  }
  fetch_texcoord(i);
  if (!vertex_array_.enabled) return;
  const glm::dvec4 obj = attribute(vertex_array_, i, vertex_array_.size, Fixed::Raw, glm::dvec4(0, 0, 0, 1));
  sink_draws() ? sink_vertex(obj) : process_vertex(obj);  // a sink draws at glEnd (draw_sink.cpp)
}

// An enabled array that was never given a pointer: GL 2.1 leaves reading it undefined and Mesa
// reads address 0 (a crash); ours reads nothing: GL_INVALID_OPERATION, as core profiles say of a
// draw from no buffer.
bool Context::arrays_readable() {
  for (const ClientArray* a : {&vertex_array_, &normal_array_, &color_array_, &texcoord_array_})
    if (a->enabled && !a->pointer) return error(GL_INVALID_OPERATION), false;
  return true;
}

void Context::ArrayElement(GLint i) {
  // GL 2.1 defines no error for a negative index, and Mesa raises none (it reads before the
  // arrays); ours ignores the call.
  if (i < 0 || !arrays_readable()) return;
  if (!in_begin_) {
    // Outside glBegin/glEnd the element still sets the current normal and colour (its vertex has
    // no effect), as in Mesa.
    const bool vertex = vertex_array_.enabled;
    vertex_array_.enabled = false;
    fetch_vertex(i, element_fixed());
    vertex_array_.enabled = vertex;
    if (vertex) position_size(vertex_array_.size), stray_vertex();
    return;
  }
  if (vertex_array_.enabled) position_size(vertex_array_.size), format_has_position_ = !spec_;
  fetch_vertex(i, element_fixed());
}

// A draw from arrays: pending values copied first (Mesa's FLUSH_FOR_DRAW); the colour varies
// per vertex when it comes from an array.
void Context::begin_draw() {
  flush_stored();
  color_in_begin_format_ = false;
  texcoord_varies_ = false;
  set_color_varies(color_array_.enabled);
}

void Context::set_color_varies(bool v) {
  if (color_varies_ != v) color_varies_ = v, constants_dirty_ = true;
}

// Whether a draw of n vertices (and as many indices) fits in memory: each costs at most this many
// bytes on any path. Over half of the machine's memory is GL_OUT_OF_MEMORY, before anything is
// allocated: a vector of billions of vertices would fail, or worse, be granted and then touched
// page by page until the kernel kills the process.
bool Context::fits_in_memory(uint64_t n) {
  constexpr uint64_t kBytesPerVertex = sizeof(raster::Vertex) + sizeof(raster::WindowVertex) + 64;
  static const uint64_t budget = [] {
    const long pages = sysconf(_SC_PHYS_PAGES), page = sysconf(_SC_PAGESIZE);
    return pages > 0 && page > 0 ? uint64_t(pages) * uint64_t(page) / 2 : uint64_t(1) << 32;
  }();
  if (n <= budget / kBytesPerVertex) return true;
  error(GL_OUT_OF_MEMORY);
  return false;
}
}  // namespace ffc::state
