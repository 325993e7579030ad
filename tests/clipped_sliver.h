// tests/difftest/repros/clipped_sliver_triangle.txt's triangle in a 32x32 context, `copies` times
// in one glDrawElements: every copy is clipped, and the first triangle of its clipper's fan is a
// smooth sliver that covers pixels (docs/deviations.md row 63, clipped-sliver-planes).
#pragma once
#include <vector>

#include "state/context.h"

namespace ffc::test {

inline void draw_clipped_slivers(state::Context& ctx, size_t copies = 1) {
  static const GLint pos[] = {0, 0, 0, 1, 0, 0, 0, 0, -1, 1, 0, 2, 0, 0, 0, 0, 0, 0, 0, 0, -2, 0, 0, 1,
                              2, 2, 1, 2, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0, 0, 0, 1, 0, 1, 0, 0, 0};
  static const GLshort col[] = {0, 0, 0, 0, 0, 0, 1, 0, 0, 1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
                                0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 1, 0};
  std::vector<GLuint> elements;
  for (size_t i = 0; i < copies; ++i) elements.insert(elements.end(), {5, 2, 6});
  ctx.VertexPointer(4, GL_INT, 0, pos);
  ctx.ColorPointer(4, GL_SHORT, 1, col);  // the repro's stride of one byte, as the fuzzer wrote it
  ctx.EnableClientState(GL_VERTEX_ARRAY);
  ctx.EnableClientState(GL_COLOR_ARRAY);
  ctx.DrawElements(GL_TRIANGLES, GLsizei(elements.size()), GL_UNSIGNED_INT, elements.data());
}

}  // namespace ffc::test
