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

// A triangle's orientation as Mesa's draw module computes it for its cull, two-side and unfilled
// stages (draw_pipe_cull.c): the float determinant of its window-space edges from the third
// vertex, taken with rows counted down as the module holds them (llvmpipe's y_down, also in
// feedback, which turns them up only when it reports them), here signed positive for
// counter-clockwise. Triangles near zero area can get the other sign than their exact
// (homogeneous) area has, and then the other face's polygon mode (measured).
inline float window_det(const raster::WindowVertex* const* v) {
  const float ex = v[0]->fx - v[2]->fx, ey = v[0]->y_down - v[2]->y_down;
  const float fx = v[1]->fx - v[2]->fx, fy = v[1]->y_down - v[2]->y_down;
  return -(ex * fy - ey * fx);
}

// Facing by that determinant. One of zero area is clockwise to the unfilled stage (the back face
// under glFrontFace(GL_CCW), the front under GL_CW: measured), front-facing to the two-side stage
// (its colours), and a back face to the cull stage whatever glFrontFace says (culled when
// glCullFace names GL_BACK, passed with GL_FRONT: measured in feedback).
inline bool window_back_facing(float det, const raster::State& rs) { return (rs.front_face == GL_CCW) != (det > 0); }
inline bool window_culled(float det, const raster::State& rs) {
  if (det != 0) return raster::culled(window_back_facing(det, rs), rs);
  return rs.cull && (rs.cull_mode == GL_BACK || rs.cull_mode == GL_FRONT_AND_BACK);
}

}  // namespace ffc::state
