// The two drawing paths of the GLUT shapes: client arrays of positions and normals (and texture
// coordinates for the teapot family), enabled for the draw and disabled after, in freeglut's order
// of calls, so that display lists and feedback see the same stream.
#include "shapes.h"

namespace ffc::glut {

namespace {

void bind_arrays(const GLfloat *vertices, const GLfloat *normals) {
  glEnableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_NORMAL_ARRAY);
  glVertexPointer(3, GL_FLOAT, 0, vertices);
  glNormalPointer(GL_FLOAT, 0, normals);
}

void unbind_arrays() {
  glDisableClientState(GL_VERTEX_ARRAY);
  glDisableClientState(GL_NORMAL_ARRAY);
}

}  // namespace

void draw_wire(const GLfloat *vertices, const GLfloat *normals, const GLushort *indices, GLsizei parts,
               GLsizei per_part, GLenum mode, const GLushort *indices2, GLsizei parts2, GLsizei per_part2) {
  bind_arrays(vertices, normals);
  for (GLsizei i = 0; i < parts; ++i) {
    if (indices == nullptr)
      glDrawArrays(mode, i * per_part, per_part);
    else
      glDrawElements(mode, per_part, GL_UNSIGNED_SHORT, indices + i * per_part);
  }
  if (indices2 != nullptr)
    for (GLsizei i = 0; i < parts2; ++i)
      glDrawElements(GL_LINE_LOOP, per_part2, GL_UNSIGNED_SHORT, indices2 + i * per_part2);
  unbind_arrays();
}

void draw_solid(const GLfloat *vertices, const GLfloat *normals, const GLfloat *texcoords, GLsizei vertex_count,
                const GLushort *indices, GLsizei parts, GLsizei per_part) {
  bind_arrays(vertices, normals);
  if (texcoords != nullptr) {
    glEnableClientState(GL_TEXTURE_COORD_ARRAY);
    glTexCoordPointer(2, GL_FLOAT, 0, texcoords);
  }
  if (indices == nullptr)
    glDrawArrays(GL_TRIANGLES, 0, vertex_count);
  else if (parts > 1)
    for (GLsizei i = 0; i < parts; ++i)
      glDrawElements(GL_TRIANGLE_STRIP, per_part, GL_UNSIGNED_SHORT, indices + i * per_part);
  else
    glDrawElements(GL_TRIANGLES, per_part, GL_UNSIGNED_SHORT, indices);
  unbind_arrays();
  if (texcoords != nullptr) glDisableClientState(GL_TEXTURE_COORD_ARRAY);
}

}  // namespace ffc::glut
