// glPolygonMode (GL 2.1 section 3.5.4): front- and back-facing polygons drawn filled, as their
// edges or as their vertices. The drawing is Assembly's (primitive.cpp, unfilled_triangle).
#include "state/context.h"

namespace ffc::state {

void Context::PolygonMode(GLenum face, GLenum mode) {
  if (!outside_begin_end_keeping_vertices()) return;
  if (face != GL_FRONT && face != GL_BACK && face != GL_FRONT_AND_BACK) return error(GL_INVALID_ENUM);
  if (mode != GL_POINT && mode != GL_LINE && mode != GL_FILL) return error(GL_INVALID_ENUM);
  // Mesa's polygon.c: FLUSH_VERTICES only when a mode the face names changes.
  if (!changes((face != GL_BACK && polygon_mode_[0] != mode) || (face != GL_FRONT && polygon_mode_[1] != mode))) return;
  if (face != GL_BACK) polygon_mode_[0] = mode;
  if (face != GL_FRONT) polygon_mode_[1] = mode;
}

}  // namespace ffc::state
