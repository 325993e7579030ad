// The vertex lighting stage: the fixed-function equation of OpenGL 2.1, section 2.14.1, in one
// templated source for double (the reference) and float (the fast path).
//
//   c = e + a_cm * a_cs + sum_i att_i spot_i [a_cm a_cl + (n.L) d_cm d_cl + f_i (n.h)^s s_cm s_cl]
//
// Constants (light x material products, directional half vectors, cos cutoff) are prepared once
// per state change by prepare(); light() evaluates one vertex in eye space.
#pragma once
#include <glm/glm.hpp>

#include "lighting/key.h"

namespace ffc::lighting {

template <typename T>
using V3 = glm::vec<3, T>;
template <typename T>
using V4 = glm::vec<4, T>;

struct MaterialParams {  // what glMaterial sets, per face
  glm::dvec4 ambient{0.2, 0.2, 0.2, 1}, diffuse{0.8, 0.8, 0.8, 1}, specular{0, 0, 0, 1}, emission{0, 0, 0, 1};
  double shininess = 0;
};

struct LightParams {  // what glLight sets; position and spot direction already in eye space
  glm::dvec4 ambient{0, 0, 0, 1}, diffuse{0, 0, 0, 1}, specular{0, 0, 0, 1};
  glm::dvec4 position{0, 0, 1, 0};
  glm::dvec3 spot_direction{0, 0, -1};
  double spot_exponent = 0, spot_cutoff = 180;
  double constant_attenuation = 1, linear_attenuation = 0, quadratic_attenuation = 0;
  bool enabled = false;
};

struct ModelParams {  // glLightModel and glColorMaterial
  glm::dvec4 ambient{0.2, 0.2, 0.2, 1};
  bool local_viewer = false, two_side = false, separate_specular = false;
  bool color_material = false;
  int cm_faces = 3;          // bit 0 front, bit 1 back
  unsigned cm_mode = 0x1602; // GL_AMBIENT_AND_DIFFUSE
};

// Whether colour material makes the per-vertex colour stand for the material's `what` (GL_AMBIENT,
// GL_DIFFUSE, GL_SPECULAR or GL_EMISSION).
inline bool tracks(const ModelParams& m, unsigned what) {
  constexpr unsigned kAmbient = 0x1200, kDiffuse = 0x1201, kAmbientAndDiffuse = 0x1602;
  return m.cm_mode == what || (m.cm_mode == kAmbientAndDiffuse && (what == kAmbient || what == kDiffuse));
}

// Per-light constants in T, for the lights that are on, packed.
template <typename T>
struct PreparedLight {
  V3<T> la, ld, ls;            // the light's colours (colour material needs them unmultiplied)
  V3<T> amb[2], dif[2], spe[2];  // products with the front and back material
  V3<T> pos;                   // local: eye-space position (w divided out); directional: unit L
  V3<T> half;                  // directional light with infinite viewer: the constant unit h
  V3<T> spot_dir;              // unit
  T spot_cos = -1, spot_exp = 0;
  T k0 = 1, k1 = 0, k2 = 0;
  bool local = false, spot = false, attenuated = false;
  bool finite = true;  // every colour above finite (a kernel may skip what it multiplies by 0)
};

template <typename T>
struct Prepared {
  Key key;
  int count = 0;
  PreparedLight<T> light[8];
  V3<T> scene[2];       // emission + global ambient x material ambient
  V3<T> global_ambient;
  MaterialParams mat[2];  // as set (colour material overrides a term per vertex)
  ModelParams model;
  T alpha[2] = {1, 1};  // the diffuse alpha
  T shininess[2] = {0, 0};
};

// The squared eye-normal length from which pow(n.h, shininess) may overflow a float (n.h <= |n|,
// shininess <= 128: from |n| = 2 on), a little below 4 so that a rounding of n.h cannot pass it:
// where the key has no specular term, the kernels compute it for such normals only (lighting.cpp).
template <typename T>
inline constexpr T kLongNormal2 = T(3.9);

// Output colours of one vertex, clamped to [0,1]: primary and secondary, front and back.
template <typename T>
struct Lit {
  V4<T> primary[2], secondary[2];
};

template <typename T>
Prepared<T> prepare(const LightParams (&lights)[8], const MaterialParams (&materials)[2], const ModelParams& model,
                    Key key);

// n: the eye-space normal, already normalized or rescaled as the state asks; p: eye-space
// position; color: the current colour, read when colour material is on.
template <typename T>
Lit<T> light(const Prepared<T>& c, const V4<T>& p, const V3<T>& n, const V4<T>& color);

// Lights `count` vertices. The generic kernel reads every choice from the key at run time; a
// specialised one is compiled for the key's shape (two-sided, local viewer, specular, colour
// material, separate specular, and whether the lights are all directional, all points, all
// points without attenuation, or mixed), so what the scene does not use is not in its code.
// Both give the same colours.
template <typename T>
using Kernel = void (*)(const Prepared<T>& c, const V4<T>* p, const V3<T>* n, const V4<T>* color, size_t count,
                        Lit<T>* out);
template <typename T>
Kernel<T> generic();
template <typename T>
Kernel<T> specialised(const Key& key);
unsigned shape_index(const Key& key);
// The key's one writer: the terms that exist for these parameters. `model.color_material` means
// the colour comes per vertex (and `model.cm_mode` what it tracks); normalize and rescale are the
// GL_NORMALIZE and GL_RESCALE_NORMAL enables. With lighting off the key is Key{}.
Key make_key(const LightParams (&lights)[8], const MaterialParams (&materials)[2], const ModelParams& model,
             bool normalize, bool rescale);  // which of the 128 compiled shapes a key selects

}  // namespace ffc::lighting
