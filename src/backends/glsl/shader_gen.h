// GLSL 330 core programs for the fixed-function state: one program per ProgramKey (the lighting
// key and what else changes the code: lighting on or off, flat shading, colour material's face
// and mode), holding only the terms the key enables. Lighting is the equation of GL 2.1 section
// 2.14.1 as src/lighting evaluates it, per vertex, in eye space.
#pragma once
#include <GL/gl.h>

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "lighting/key.h"
#include "state/draw_sink.h"

namespace ffc::glsl {

struct ProgramKey {
  lighting::Key key;       // Key{} when lighting is off
  bool lit = false;        // GL_LIGHTING
  bool flat = false;       // GL_FLAT: the colours are `flat` varyings (the last vertex provokes)
  unsigned cm_faces = 0;   // colour material per vertex (the key's bit): bit 0 front, bit 1 back
  unsigned cm_mode = 0;    // and the material parameter it tracks (GL_AMBIENT ... GL_AMBIENT_AND_DIFFUSE)
  bool phong = false;      // the equation per fragment (--shading phong), lit and smooth only
  // The fragment stage's fixed functions (shader_features.cpp): fog's mode (0: off, else
  // GL_LINEAR, GL_EXP, GL_EXP2) and whether its coordinate is the eye-space depth (else the
  // current fog coordinate, 0); the alpha test's function (GL_ALWAYS when the test is off).
  GLenum fog = 0;
  bool fog_depth = false;
  GLenum alpha_func = GL_ALWAYS;
  // glMaterial changed inside glBegin/glEnd: the material comes per vertex, as attributes
  // (SinkMaterial's layout, from kMaterial on), not uniforms. Lit only; never per fragment.
  bool vertex_material = false;
  // One glPolygonMode pass drawing polygons as GL_LINE or GL_POINT (unfilled.h): the faces it
  // draws (bit 0 front, bit 1 back) and the front face's winding; a geometry shader draws the
  // boundary. 0: none (GL_FILL draws triangles as they are).
  GLenum unfilled = 0;
  unsigned unfilled_faces = 0;
  bool front_cw = false;
  // GL_POINTS drawn as llvmpipe's squares of whole pixels by a geometry shader (points.h).
  bool points = false;

  static ProgramKey of(const state::SinkState& s, bool phong = false);
  uint64_t packed() const;  // equal keys, equal numbers: the program cache's key
  bool two_side() const { return lit && key.two_side(); }
  bool secondary() const { return lit && key.separate_specular() && key.any_light() && key.specular(); }
  bool needs_eye_position() const;
  bool alpha_test() const { return alpha_func != GL_ALWAYS; }
};

// A uniform of a program: its name, GLSL type and value (column-major for matrices).
struct Uniform {
  std::string name;
  const char* type;  // "float", "vec3", "vec4", "mat3", "mat4"
  int size;          // floats: 1, 3, 4, 9 or 16
  std::array<float, 16> value{};
};

// The uniforms the program of `k` declares, with their values for the state `s` (zeros when s is
// null: the declarations only).
std::vector<Uniform> uniforms(const ProgramKey& k, const state::SinkState* s);

struct Sources {
  std::string vertex, fragment;
  std::string geometry;  // empty: none
  // What transform feedback records per vertex, in this order: gl_Position, then each varying.
  std::vector<std::string> feedback;
};
Sources generate(const ProgramKey& k);

// The vertex attributes' locations (SinkVertex's fields; then SinkMaterial's: the front face's
// ambient (shininess in its alpha), diffuse, specular, emission, then the back face's).
enum Attribute : unsigned { kPosition = 0, kNormal = 1, kColor = 2, kMaterial = 3, kMaterialCount = 8 };

}  // namespace ffc::glsl
