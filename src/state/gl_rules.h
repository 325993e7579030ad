// Small rules of GL 2.1 and Mesa 22.3 that several of the context's files apply (not an
// interface: included by src/state's .cpp files only).
#pragma once
#include <GL/gl.h>

#include "raster/raster.h"

namespace ffc::state {

inline int light_index(GLenum light) { return light >= GL_LIGHT0 && light < GL_LIGHT0 + 8 ? int(light - GL_LIGHT0) : -1; }

// How many values a glLight / glMaterial / glLightModel parameter takes; 0 for an unknown name.
inline int light_param_count(GLenum p) {
  switch (p) {
    case GL_AMBIENT: case GL_DIFFUSE: case GL_SPECULAR: case GL_POSITION: return 4;
    case GL_SPOT_DIRECTION: return 3;
    case GL_SPOT_EXPONENT: case GL_SPOT_CUTOFF: case GL_CONSTANT_ATTENUATION: case GL_LINEAR_ATTENUATION:
    case GL_QUADRATIC_ATTENUATION: return 1;
    default: return 0;
  }
}

// Primitive modes: GL_POINTS (0) .. GL_POLYGON (9), and GL 3.2's adjacency modes (0xA..0xD:
// GL_LINES_ADJACENCY .. GL_TRIANGLE_STRIP_ADJACENCY), which Mesa 22.3's compatibility context
// accepts without error (GL 2.1 would say GL_INVALID_ENUM). GL_PATCHES (0xE) without a
// tessellation shader is GL_INVALID_OPERATION in Mesa; anything above, GL_INVALID_ENUM.
inline constexpr GLenum kPatches = 0xE;
inline bool valid_primitive(GLenum m) { return m < kPatches; }
inline GLenum primitive_error(GLenum m) { return m == kPatches ? GL_INVALID_OPERATION : GL_INVALID_ENUM; }

// Mesa's INT_TO_FLOAT (main/macros.h): GLint [-2^31, 2^31-1] onto [-1, 1] as (2i + 1) / (2^32 - 2).
inline GLfloat int_to_float(GLint i) { return GLfloat((2.0f * GLfloat(i) + 1.0f) * (1.0f / 4294967294.0)); }
inline bool valid_face(GLenum f) { return f == GL_FRONT || f == GL_BACK || f == GL_FRONT_AND_BACK; }
// Clamped to [0, 1], a NaN to 0 as Mesa stores it (GL 2.1 leaves a NaN's clamp undefined).
inline double clamp01(double x) { return x > 0 ? (x < 1 ? x : 1) : 0; }

// Whether a triangle's window-space area is 0 as Mesa's draw module computes it (float, edges
// from the third vertex): its cull and two-side stages both ask.
inline bool zero_area(const raster::WindowVertex* const* v) {
  const float ex = float(v[0]->pos.x) - float(v[2]->pos.x), ey = float(v[0]->pos.y) - float(v[2]->pos.y);
  const float fx = float(v[1]->pos.x) - float(v[2]->pos.x), fy = float(v[1]->pos.y) - float(v[2]->pos.y);
  return ex * fy - ey * fx == 0;
}

}  // namespace ffc::state
