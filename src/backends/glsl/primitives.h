// GL's primitives as the lists a core profile draws (points, lines, triangles), each with its
// provoking vertex last, so that `flat` varyings under GL_LAST_VERTEX_CONVENTION take the colour
// GL 2.1 table 2.6 names: a quad's 4th vertex, a polygon's 1st (a triangle's corners rotated
// cyclically, which keeps its winding). Quads and quad strips split along the diagonal
// llvmpipe's fixed-function path takes (the rule soft's primitive.cpp measured).
#pragma once
#include <GL/gl.h>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace ffc::glsl {

struct SplitRule {
  bool flat = false;         // GL_FLAT
  bool from_elements = false;  // glDrawElements
  bool any_outside = false;  // a vertex outside the view volume: Mesa's draw pipeline splits the quads
  bool pipeline = false;     // as Mesa's draw pipeline assembles: feedback (the vertex check), glPolygonMode
};

// The list for `count` vertices of `mode` (elements[k] names vertex k when elements is not null):
// GL_POINTS, GL_LINES or GL_TRIANGLES, with the vertex numbers in `out`.
// With `edges`: per triangle, which of its edges (bit 0: first to second vertex, bit 1: second to
// third, bit 2: third to first) lie on the boundary of the GL polygon it came from: a quad's or a
// polygon's inner diagonals do not (glPolygonMode GL_LINE and GL_POINT draw only the boundary, as
// GL's edge flags say); every edge of a triangle, strip or fan does.
GLenum decompose(GLenum mode, const uint32_t* elements, size_t count, const SplitRule& rule, std::vector<uint32_t>& out,
                 std::vector<uint8_t>* edges = nullptr);

}  // namespace ffc::glsl
