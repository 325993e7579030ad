// Shared by the GLUT shapes (shapes_*.cpp, teapot.cpp): how freeglut 3.4.0 hands its generated
// geometry to GL in the fixed-function path, so that ours makes the very same calls. Vertices and
// normals are tightly packed float triples; indices are GLushort (freeglut's choice, which makes
// indices wrap above 65535 vertices, as they do there).
#pragma once

#include <GL/freeglut.h>

#define FFC_GLUT_EXPORT extern "C" __attribute__((visibility("default")))

namespace ffc::glut {

// Edges: `parts` draws of `per_part` vertices in `mode` (glDrawArrays over consecutive vertices
// when `indices` is null, else glDrawElements), then `parts2` line loops from `indices2`.
void draw_wire(const GLfloat *vertices, const GLfloat *normals, const GLushort *indices, GLsizei parts,
               GLsizei per_part, GLenum mode, const GLushort *indices2 = nullptr, GLsizei parts2 = 0,
               GLsizei per_part2 = 0);

// Faces: without indices, all `vertex_count` vertices as triangles; with them, `parts` triangle
// strips of `per_part` indices each, or one triangle list when `parts` is 1. Texture coordinates
// (pairs) are optional.
void draw_solid(const GLfloat *vertices, const GLfloat *normals, const GLfloat *texcoords, GLsizei vertex_count,
                const GLushort *indices, GLsizei parts, GLsizei per_part);

}  // namespace ffc::glut
