// glDrawArrays and glDrawElements (GL 2.1 section 2.8): validation, then the choice of path: the
// triangle-list path for GL_TRIANGLES while rendering in float, the general path (vertex by
// vertex, then primitive assembly) for everything else.
#include <algorithm>

#include "state/client_arrays.h"
#include "state/context.h"
#include "state/gl_rules.h"
#include "simd/index_range.h"

namespace ffc::state {

namespace {
constexpr GLint kParallelVertices = 8192;  // below this, starting a thread costs more than it saves
}  // namespace


// With the vertex array disabled GL draws nothing. Mesa draws all the same, each vertex at the
// current position, which its vbo module never updates from glVertex: the object-space origin
// (0, 0, 0, 1) every time, the other attributes from their arrays or current values. The default
// mode does so too (a constant array of the origin stands in for the positions); spec mode draws
// nothing.
template <class Draw>
void Context::with_positions(Draw draw) {
  if (vertex_array_.enabled) return draw();
  if (spec_) return;
  static const float kOrigin[4] = {0, 0, 0, 1};
  const ClientArray kept = vertex_array_;
  vertex_array_ = {true, 4, GL_FLOAT, 0, kOrigin, true};
  draw();
  vertex_array_ = kept;
}

// glDrawArrays and glDrawElements check as Mesa's draw_validate.c does: the count, then the mode,
// then the index type.
void Context::DrawArrays(GLenum mode, GLint first, GLsizei count) {
  if (!outside_begin_end()) return;
  validate_matrices();  // before any argument is checked, as Mesa's draws
  if (count < 0) return error(GL_INVALID_VALUE);
  if (!valid_primitive(mode)) return error(primitive_error(mode));
  with_positions([&] { draw_arrays(mode, first, count); });
}

void Context::draw_arrays(GLenum mode, GLint first, GLsizei count) {
  // A negative first is no error in GL 2.1 nor in Mesa (which then reads before the arrays); ours
  // draws nothing.
  if (first < 0 || !arrays_readable() || !fits_in_memory(uint64_t(count))) return;
  begin_draw();
  if (sink_draws()) return sink_arrays(mode, first, count);  // draw_sink.cpp
  prim_mode_ = mode;
  verts_.clear();
  if (triangle_list_path(mode)) {
    if (draw_soup(first, count)) return;  // soup.cpp
    arrays_to_list(first, count);
    return draw_triangle_list(nullptr, size_t(count) / 3);
  }
  const CurrentValues kept = current_values();
  if (count >= kParallelVertices && threads_ > 1)
    arrays_to_vertices(first, count);
  else
    for (GLint i = first; i < first + count; ++i) fetch_vertex(i, draw_fixed());
  restore(kept);
  light_pending();
  flush_primitive();
}

void Context::DrawElements(GLenum mode, GLsizei count, GLenum type, const void* indices) {
  if (!outside_begin_end()) return;
  validate_matrices();  // before any argument is checked, as Mesa's draws
  if (count < 0) return error(GL_INVALID_VALUE);
  if (!valid_primitive(mode)) return error(primitive_error(mode));
  if (type != GL_UNSIGNED_BYTE && type != GL_UNSIGNED_SHORT && type != GL_UNSIGNED_INT) return error(GL_INVALID_ENUM);
  with_positions([&] { draw_elements(mode, count, type, indices); });
}

void Context::draw_elements(GLenum mode, GLsizei count, GLenum type, const void* indices) {
  if (!indices || !arrays_readable() || !fits_in_memory(uint64_t(count))) return;
  begin_draw();
  if (sink_draws()) return sink_elements(mode, count, type, indices);  // draw_sink.cpp
  prim_mode_ = mode;
  verts_.clear();
  // Each array element in the indices' range is transformed and lit once, however often the
  // indices name it (a post-transform cache covering the whole draw).
  const uint8_t* p = static_cast<const uint8_t*>(indices);
  uint32_t lo = UINT32_MAX, hi = 0;
  if (type == GL_UNSIGNED_INT && count > 0 && triangle_list_path(mode)) {
    // The triangle-list path reads 32-bit indices in place when they start at 0.
    const auto* u = static_cast<const uint32_t*>(indices);
    index_range(u, size_t(count), lo, hi);
    if (lo == 0 && !fits_in_memory(uint64_t(hi) + 1)) return;
    if (lo == 0) {
      arrays_to_list(0, GLint(hi) + 1);
      return draw_triangle_list(u, size_t(count) / 3);
    }
  }
  elements_.resize(size_t(count));
  for (GLsizei i = 0; i < count; ++i) elements_[i] = uint32_t(read_component(p, type, i, Fixed::Raw));
  if (count > 0) index_range(elements_.data(), elements_.size(), lo, hi);
  if (count > 0 && !fits_in_memory(uint64_t(hi - lo) + 1)) return elements_.clear();
  if (count > 0 && triangle_list_path(mode)) {
    arrays_to_list(GLint(lo), GLint(hi - lo + 1));
    for (uint32_t& e : elements_) e -= lo;
    draw_triangle_list(elements_.data(), size_t(count) / 3);
    elements_.clear();
    return;
  }
  if (count > 0) {
    const CurrentValues kept = current_values();
    if (hi - lo + 1 >= kParallelVertices && threads_ > 1)
      arrays_to_vertices(GLint(lo), GLint(hi - lo + 1));
    else
      for (uint32_t i = lo; i <= hi; ++i) fetch_vertex(GLint(i), draw_fixed());
    restore(kept);
    light_pending();
    for (uint32_t& e : elements_) e -= lo;
  }
  flush_primitive();
  elements_.clear();
}
// A vector at a time on the dispatched Highway target (src/simd/index_range.cpp).
void index_range(const uint32_t* u, size_t n, uint32_t& lo, uint32_t& hi) { simd::index_range(u, n, lo, hi); }

bool Context::triangle_list_path(GLenum mode) const {
  // Fog, polygon offset, the per-fragment operations and glPolygonMode are applied by the general path only
  // (raster/fragment_ops.cpp): the triangle list's kernels have none of them.
  return triangle_lists_ && mode == GL_TRIANGLES && render_mode_ == GL_RENDER && precision_ == Precision::Float &&
         !fog_ && !offset_fill_ && fragment_ops_default() && !unfilled();
}

void Context::draw_triangle_list(const uint32_t* indices, size_t triangles) {
  // This context's count: another context drawing on another thread meanwhile names nothing here.
  const uint64_t slivers = counters_.clipped_slivers.load(std::memory_order_relaxed);
  raster::draw_triangle_list(fb_, raster_state(), list_vertices_, indices, triangles, workers(), bins_, pending_clear_);
  if (counters_.clipped_slivers.load(std::memory_order_relaxed) != slivers) deviations_.insert(kClippedSliver);  // docs/deviations.md row 63
  pending_clear_ = {};
}

}  // namespace ffc::state
