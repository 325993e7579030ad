// The quadric object shared by gluSphere, gluCylinder and gluPartialDisk, and the conventions
// they share with SGI's GLU (Mesa libGLU 9.0.2), whose output they reproduce vertex for vertex:
// angles and sine/cosine tables in single precision (the sines themselves taken in double), at
// most kMaxSlices slices, errors reported through the quadric's GLU_ERROR callback only.
#pragma once

#include "glu_export.h"

class GLUquadric {
 public:
  GLenum normals = GLU_SMOOTH;
  GLboolean texture = GL_FALSE;
  GLenum orientation = GLU_OUTSIDE;
  GLenum draw_style = GLU_FILL;
  void(GLAPIENTRY *error_callback)(GLenum) = nullptr;
};

namespace ffc::glu {

constexpr double kPi = 3.14159265358979323846;
// GLU's tables hold 240 entries (one more than the slices, to close the loop).
constexpr int kTableSize = 240;

void report_error(GLUquadric *quadric, GLenum error);

// Emits the normal only when the quadric asks for some (GLU_FLAT or GLU_SMOOTH).
inline void normal_if_any(const GLUquadric *quadric, GLfloat x, GLfloat y, GLfloat z) {
  if (quadric->normals != GLU_NONE) glNormal3f(x, y, z);
}

inline bool outside(const GLUquadric *quadric) { return quadric->orientation == GLU_OUTSIDE; }

}  // namespace ffc::glu
