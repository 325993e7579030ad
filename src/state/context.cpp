#include "state/context.h"

#include "state/float_matrix.h"
#include "state/client_arrays.h"
#include "state/read_pixels.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <unistd.h>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

namespace ffc::state {

namespace {
thread_local Context* g_current = nullptr;
constexpr GLint kParallelVertices = 8192;  // below this, starting a thread costs more than it saves

int light_index(GLenum light) { return light >= GL_LIGHT0 && light < GL_LIGHT0 + 8 ? int(light - GL_LIGHT0) : -1; }

// How many values a glLight / glMaterial / glLightModel parameter takes; 0 for an unknown name.
int light_param_count(GLenum p) {
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
constexpr GLenum kPatches = 0xE;
bool valid_primitive(GLenum m) { return m < kPatches; }
GLenum primitive_error(GLenum m) { return m == kPatches ? GL_INVALID_OPERATION : GL_INVALID_ENUM; }

// Mesa's INT_TO_FLOAT (main/macros.h): GLint [-2^31, 2^31-1] onto [-1, 1] as (2i + 1) / (2^32 - 2).
GLfloat int_to_float(GLint i) { return GLfloat((2.0f * GLfloat(i) + 1.0f) * (1.0f / 4294967294.0)); }
bool valid_face(GLenum f) { return f == GL_FRONT || f == GL_BACK || f == GL_FRONT_AND_BACK; }
// Clamped to [0, 1], a NaN to 0 as Mesa stores it (GL 2.1 leaves a NaN's clamp undefined).
double clamp01(double x) { return x > 0 ? (x < 1 ? x : 1) : 0; }
}  // namespace

Context* Context::current() { return g_current; }
void Context::make_current(Context* c) { g_current = c; }

Context::Context(int width, int height, Precision precision)
    : fb_(width, height), precision_(precision), viewport_(0, 0, width, height) {
  lights_[0].diffuse = lights_[0].specular = glm::dvec4(1);
}

GLenum Context::GetError() {
  if (in_begin_) {  // Mesa: returns 0 and records INVALID_OPERATION
    error(GL_INVALID_OPERATION);
    return GL_NO_ERROR;
  }
  const GLenum e = error_;
  error_ = GL_NO_ERROR;
  return e;
}

bool Context::outside_begin_end() {
  if (in_begin_) error(GL_INVALID_OPERATION);
  // Nearly every call that checks this is one where Mesa flushes the vertices it keeps after
  // glEnd (FLUSH_VERTICES), emptying the pending current values (see update_color_material).
  else if (vertices_kept_) vertices_kept_ = false, flush_stored();
  return !in_begin_;
}

bool* Context::capability(GLenum cap) {
  switch (cap) {
    case GL_LIGHTING: return &lighting_;
    case GL_NORMALIZE: return &normalize_;
    case GL_RESCALE_NORMAL: return &rescale_normal_;
    case GL_COLOR_MATERIAL: return &color_material_;
    case GL_DEPTH_TEST: return &depth_test_;
    case GL_CULL_FACE: return &cull_face_;
    case GL_FOG: return &fog_;
    case GL_POLYGON_OFFSET_FILL: return &offset_fill_;
    default: {
      const int i = light_index(cap);
      return i >= 0 ? &lights_[i].enabled : nullptr;
    }
  }
}

namespace {
// Capabilities and client arrays GL 2.1 knows that this pipeline does not model, with their
// defaults (GL 2.1 tables 6.x; GL_DITHER and GL_MULTISAMPLE start enabled): glEnable / glDisable /
// glEnableClientState / glDisableClientState record them and glIsEnabled / glGet report them, as
// Mesa 22.3's compatibility context does. Imaging-subset capabilities (GL_COLOR_TABLE,
// GL_CONVOLUTION_1D, GL_HISTOGRAM, ...) are not here: Mesa has no ARB_imaging and rejects them.
struct OtherEnable {
  GLenum name;
  bool initial;
};
constexpr OtherEnable kOtherCaps[] = {
    {GL_ALPHA_TEST, false}, {GL_AUTO_NORMAL, false}, {GL_BLEND, false}, {GL_CLIP_PLANE0, false},
    {GL_CLIP_PLANE1, false}, {GL_CLIP_PLANE2, false}, {GL_CLIP_PLANE3, false}, {GL_CLIP_PLANE4, false},
    {GL_CLIP_PLANE5, false}, {GL_CLIP_PLANE0 + 6, false}, {GL_CLIP_PLANE0 + 7, false}, {GL_COLOR_LOGIC_OP, false},
    {GL_COLOR_SUM, false}, {GL_DITHER, true}, {GL_INDEX_LOGIC_OP, false}, {GL_LINE_SMOOTH, false},
    {GL_LINE_STIPPLE, false}, {GL_MAP1_COLOR_4, false}, {GL_MAP1_INDEX, false}, {GL_MAP1_NORMAL, false},
    {GL_MAP1_TEXTURE_COORD_1, false}, {GL_MAP1_TEXTURE_COORD_2, false}, {GL_MAP1_TEXTURE_COORD_3, false},
    {GL_MAP1_TEXTURE_COORD_4, false}, {GL_MAP1_VERTEX_3, false}, {GL_MAP1_VERTEX_4, false},
    {GL_MAP2_COLOR_4, false}, {GL_MAP2_INDEX, false}, {GL_MAP2_NORMAL, false}, {GL_MAP2_TEXTURE_COORD_1, false},
    {GL_MAP2_TEXTURE_COORD_2, false}, {GL_MAP2_TEXTURE_COORD_3, false}, {GL_MAP2_TEXTURE_COORD_4, false},
    {GL_MAP2_VERTEX_3, false}, {GL_MAP2_VERTEX_4, false}, {GL_MULTISAMPLE, true}, {GL_POINT_SMOOTH, false},
    {GL_POINT_SPRITE, false}, {GL_POLYGON_OFFSET_LINE, false},
    {GL_POLYGON_OFFSET_POINT, false}, {GL_POLYGON_SMOOTH, false}, {GL_POLYGON_STIPPLE, false},
    {GL_SAMPLE_ALPHA_TO_COVERAGE, false}, {GL_SAMPLE_ALPHA_TO_ONE, false}, {GL_SAMPLE_COVERAGE, false},
    {GL_SCISSOR_TEST, false}, {GL_STENCIL_TEST, false}, {GL_TEXTURE_1D, false}, {GL_TEXTURE_2D, false},
    {GL_TEXTURE_3D, false}, {GL_TEXTURE_CUBE_MAP, false}, {GL_TEXTURE_GEN_S, false}, {GL_TEXTURE_GEN_T, false},
    {GL_TEXTURE_GEN_R, false}, {GL_TEXTURE_GEN_Q, false}, {GL_VERTEX_PROGRAM_POINT_SIZE, false},
    {GL_VERTEX_PROGRAM_TWO_SIDE, false}};
constexpr OtherEnable kOtherArrays[] = {{GL_TEXTURE_COORD_ARRAY, false}, {GL_INDEX_ARRAY, false},
                                        {GL_EDGE_FLAG_ARRAY, false}, {GL_FOG_COORD_ARRAY, false},
                                        {GL_SECONDARY_COLOR_ARRAY, false}};

template <size_t N>
const OtherEnable* find_enable(const OtherEnable (&table)[N], GLenum name) {
  for (const OtherEnable& e : table)
    if (e.name == name) return &e;
  return nullptr;
}
}  // namespace

void Context::set_enabled(GLenum cap, bool on) {
  if (!outside_begin_end()) return;
  // Mesa's glEnable / glDisable also take the client arrays, as glEnableClientState does (GL 2.1:
  // GL_INVALID_ENUM).
  if (cap == GL_VERTEX_ARRAY || cap == GL_NORMAL_ARRAY || cap == GL_COLOR_ARRAY || find_enable(kOtherArrays, cap))
    return set_client_state(cap, on);
  bool* c = capability(cap);
  if (!c) {
    if (find_enable(kOtherCaps, cap)) other_enables_[cap] = on;  // accepted, recorded, not modelled
    else error(GL_INVALID_ENUM);
    return;
  }
  if (cap == GL_COLOR_MATERIAL) {
    if (*c == on) return;
    flush_current();  // Mesa's enable.c: pending values first, then the tracking
    *c = on;
    constants_dirty_ = true;
    if (on) update_color_material();
    return;
  }
  *c = on;
  constants_dirty_ = true;
}

int Context::enabled_state(GLenum cap) {
  switch (cap) {
    case GL_VERTEX_ARRAY: return vertex_array_.enabled;
    case GL_NORMAL_ARRAY: return normal_array_.enabled;
    case GL_COLOR_ARRAY: return color_array_.enabled;
  }
  if (bool* c = capability(cap)) return *c;
  const OtherEnable* o = find_enable(kOtherCaps, cap);
  if (!o) o = find_enable(kOtherArrays, cap);
  if (!o) return -1;
  const auto it = other_enables_.find(cap);
  return it != other_enables_.end() ? it->second : o->initial;
}

GLboolean Context::IsEnabled(GLenum cap) {
  if (!outside_begin_end()) return GL_FALSE;
  const int on = enabled_state(cap);
  if (on < 0) return error(GL_INVALID_ENUM), GL_FALSE;
  return GLboolean(on);
}

void Context::set_client_state(GLenum array, bool on) {
  if (!outside_begin_end()) return;
  ClientArray* a = array == GL_VERTEX_ARRAY   ? &vertex_array_
                   : array == GL_NORMAL_ARRAY ? &normal_array_
                   : array == GL_COLOR_ARRAY  ? &color_array_
                                              : nullptr;
  if (!a) {
    if (find_enable(kOtherArrays, array)) other_enables_[array] = on;
    else error(GL_INVALID_ENUM);
    return;
  }
  a->enabled = on;
}

// ---------------------------------------------------------------- lights and materials

glm::dmat4 Context::projection() const {
  return precision_ == Precision::Float ? glm::dmat4(projection_f_.back().values()) : projection_.back();
}
glm::dmat4 Context::texture() const {
  return precision_ == Precision::Float ? glm::dmat4(texture_f_.back().values()) : texture_.back();
}

glm::dmat4 Context::modelview() const {
  return precision_ == Precision::Float ? glm::dmat4(modelview_f_.back().values()) : modelview_.back();
}

// The position and the spot direction are transformed by the modelview as it is when they are
// set; in float, as Mesa's light.c does (TRANSFORM_POINT / TRANSFORM_DIRECTION with the float
// matrix), so that a light moves exactly as the geometry drawn under the same matrix.
glm::dvec4 Context::to_eye(const double* v, double w) const {
  if (precision_ == Precision::Double) return modelview_.back() * glm::dvec4(v[0], v[1], v[2], w);
  return glm::dvec4(fmat::transform(modelview_f_.back().values(), glm::vec4(float(v[0]), float(v[1]), float(v[2]), float(w))));
}

// A spot direction is transformed by the modelview's upper 3x3 only (Mesa's TRANSFORM_DIRECTION,
// each sum left to right), so an infinite translation does not make it NaN; Mesa analyses the
// modelview first, as glPushMatrix does.
glm::dvec3 Context::direction_to_eye(const double* v) {
  if (precision_ == Precision::Double) return glm::dmat3(modelview_.back()) * glm::dvec3(v[0], v[1], v[2]);
  fmat::Matrix& mv = modelview_f_.back();
  if (mv.dirty()) mv.analyse();
  const glm::mat4& m = mv.values();
  const float x = float(v[0]), y = float(v[1]), z = float(v[2]);
  glm::dvec3 out;
  for (int i = 0; i < 3; ++i) out[i] = x * m[0][i] + y * m[1][i] + z * m[2][i];
  return out;
}

void Context::set_light(int i, GLenum pname, const double* v) {
  lighting::LightParams& l = lights_[i];
  switch (pname) {
    case GL_AMBIENT: l.ambient = glm::make_vec4(v); break;
    case GL_DIFFUSE: l.diffuse = glm::make_vec4(v); break;
    case GL_SPECULAR: l.specular = glm::make_vec4(v); break;
    case GL_POSITION: l.position = to_eye(v, v[3]); break;
    case GL_SPOT_DIRECTION: l.spot_direction = direction_to_eye(v); break;
    case GL_SPOT_EXPONENT: l.spot_exponent = v[0]; break;
    case GL_SPOT_CUTOFF: l.spot_cutoff = v[0]; break;
    case GL_CONSTANT_ATTENUATION: l.constant_attenuation = v[0]; break;
    case GL_LINEAR_ATTENUATION: l.linear_attenuation = v[0]; break;
    case GL_QUADRATIC_ATTENUATION: l.quadratic_attenuation = v[0]; break;
  }
  constants_dirty_ = true;
}

void Context::Lightfv(GLenum light, GLenum pname, const GLfloat* params) {
  if (!outside_begin_end()) return;
  const int i = light_index(light), n = light_param_count(pname);
  if (i < 0 || n == 0) return error(GL_INVALID_ENUM);
  double v[4] = {0, 0, 0, 0};
  for (int k = 0; k < n; ++k) v[k] = params[k];
  // Mesa's tests, as written in its light.c: a NaN passes all of them (GL 2.1 does not say).
  const double x = v[0];
  if (pname == GL_SPOT_EXPONENT && (x < 0 || x > 128)) return error(GL_INVALID_VALUE);
  if (pname == GL_SPOT_CUTOFF && (x < 0 || x > 90) && x != 180) return error(GL_INVALID_VALUE);
  if ((pname == GL_CONSTANT_ATTENUATION || pname == GL_LINEAR_ATTENUATION || pname == GL_QUADRATIC_ATTENUATION) &&
      x < 0)
    return error(GL_INVALID_VALUE);
  set_light(i, pname, v);
}

// The scalar calls pass (param, 0, 0, 0) to the vector ones, as Mesa's light.c does: a vector
// parameter (GL_AMBIENT, GL_POSITION, ...) through glLightf / glLighti is accepted and set, where
// GL 2.1 says GL_INVALID_ENUM. Likewise glLightModelf / glLightModeli with GL_LIGHT_MODEL_AMBIENT.
void Context::Lightf(GLenum light, GLenum pname, GLfloat param) {
  const GLfloat f[4] = {param, 0, 0, 0};
  Lightfv(light, pname, f);
}

void Context::Lightiv(GLenum light, GLenum pname, const GLint* params) {
  // Integer colours map [-2^31, 2^31-1] to [-1, 1]; positions and scalars convert directly.
  GLfloat f[4] = {0, 0, 0, 0};
  const int n = std::max(1, light_param_count(pname));
  const bool color = pname == GL_AMBIENT || pname == GL_DIFFUSE || pname == GL_SPECULAR;
  for (int k = 0; k < n; ++k) f[k] = color ? int_to_float(params[k]) : GLfloat(params[k]);
  Lightfv(light, pname, f);
}

void Context::Lighti(GLenum light, GLenum pname, GLint param) {
  const GLint i[4] = {param, 0, 0, 0};
  Lightiv(light, pname, i);
}

void Context::LightModelfv(GLenum pname, const GLfloat* p) {
  if (!outside_begin_end()) return;
  switch (pname) {
    case GL_LIGHT_MODEL_AMBIENT: model_.ambient = glm::dvec4(p[0], p[1], p[2], p[3]); break;
    case GL_LIGHT_MODEL_LOCAL_VIEWER: model_.local_viewer = p[0] != 0; break;
    case GL_LIGHT_MODEL_TWO_SIDE: model_.two_side = p[0] != 0; break;
    case GL_LIGHT_MODEL_COLOR_CONTROL:
      if (p[0] == GL_SINGLE_COLOR) model_.separate_specular = false;
      else if (p[0] == GL_SEPARATE_SPECULAR_COLOR) model_.separate_specular = true;
      else return error(GL_INVALID_ENUM);
      break;
    default: return error(GL_INVALID_ENUM);
  }
  constants_dirty_ = true;
}

void Context::LightModelf(GLenum pname, GLfloat param) {
  const GLfloat f[4] = {param, 0, 0, 0};
  LightModelfv(pname, f);
}

void Context::LightModeli(GLenum pname, GLint param) {
  // As glLightModeliv with (param, 0, 0, 0): the ambient colour maps integers onto [-1, 1].
  GLfloat f[4] = {GLfloat(param), 0, 0, 0};
  if (pname == GL_LIGHT_MODEL_AMBIENT) f[0] = int_to_float(param), f[1] = f[2] = f[3] = int_to_float(0);
  LightModelfv(pname, f);
}

bool Context::set_material(GLenum face, GLenum pname, const double* v) {
  if (!valid_face(face)) return error(GL_INVALID_ENUM), false;
  undefer();  // the vertices so far are lit with the material as it was
  switch (pname) {
    case GL_AMBIENT: case GL_DIFFUSE: case GL_SPECULAR: case GL_EMISSION: case GL_AMBIENT_AND_DIFFUSE:
    case GL_COLOR_INDEXES: break;
    case GL_SHININESS:
      if (v[0] < 0 || v[0] > 128) return error(GL_INVALID_VALUE), false;  // Mesa's test: a NaN passes
      break;
    default: return error(GL_INVALID_ENUM), false;
  }
  for (int f = 0; f < 2; ++f) {
    if (f == 0 && face == GL_BACK) continue;
    if (f == 1 && face == GL_FRONT) continue;
    lighting::MaterialParams& m = materials_[f];
    const glm::dvec4 c(v[0], v[1], v[2], v[3]);
    // While GL_COLOR_MATERIAL is enabled, glMaterial leaves the parameters that track the colour
    // alone, as Mesa's vbo_Materialfv does (GL 2.1 does not say).
    const bool face_tracks = color_material_ && (model_.cm_faces >> f & 1);
    auto set = [&](glm::dvec4& dst, GLenum attr) {
      const bool tracks = face_tracks && (cm_mode_ == attr || (cm_mode_ == GL_AMBIENT_AND_DIFFUSE &&
                                                               (attr == GL_AMBIENT || attr == GL_DIFFUSE)));
      if (tracks) return;
      dst = c;
      if (in_begin_ || spec_) return;
      for (PendingMaterial& p : pending_materials_)
        if (p.dst == &dst) return void(p.value = c);
      pending_materials_.push_back({&dst, c});
    };
    switch (pname) {
      case GL_AMBIENT: set(m.ambient, GL_AMBIENT); break;
      case GL_DIFFUSE: set(m.diffuse, GL_DIFFUSE); break;
      case GL_SPECULAR: set(m.specular, GL_SPECULAR); break;
      case GL_EMISSION: set(m.emission, GL_EMISSION); break;
      case GL_AMBIENT_AND_DIFFUSE: set(m.ambient, GL_AMBIENT), set(m.diffuse, GL_DIFFUSE); break;
      case GL_SHININESS: m.shininess = v[0]; break;
      case GL_COLOR_INDEXES: color_indexes_[f] = glm::dvec3(v[0], v[1], v[2]); break;
    }
  }
  constants_dirty_ = true;
  return true;
}

void Context::Materialfv(GLenum face, GLenum pname, const GLfloat* params) {
  // Allowed between glBegin and glEnd: it changes the material of the vertices that follow.
  double v[4] = {params[0], 0, 0, 0};
  if (pname != GL_SHININESS)
    for (int k = 1; k < (pname == GL_COLOR_INDEXES ? 3 : 4); ++k) v[k] = params[k];
  set_material(face, pname, v);
}

void Context::Materialf(GLenum face, GLenum pname, GLfloat param) {
  // Mesa passes (param, ?, ?, ?) to glMaterialfv whatever the pname, without an error (GL 2.1:
  // GL_INVALID_ENUM unless GL_SHININESS); ours passes (param, 0, 0, 0). glMateriali converts the
  // integer directly, colours included.
  const GLfloat f[4] = {param, 0, 0, 0};
  Materialfv(face, pname, f);
}

void Context::Materiali(GLenum face, GLenum pname, GLint param) { Materialf(face, pname, GLfloat(param)); }

void Context::ColorMaterial(GLenum face, GLenum mode) {
  if (!outside_begin_end()) return;
  if (!valid_face(face)) return error(GL_INVALID_ENUM);
  if (mode != GL_EMISSION && mode != GL_AMBIENT && mode != GL_DIFFUSE && mode != GL_SPECULAR &&
      mode != GL_AMBIENT_AND_DIFFUSE)
    return error(GL_INVALID_ENUM);
  if (face == cm_face_ && mode == cm_mode_) return;  // as Mesa: no flush, no tracking
  cm_face_ = face, cm_mode_ = mode;
  model_.cm_faces = face == GL_FRONT ? 1 : face == GL_BACK ? 2 : 3;
  model_.cm_mode = mode;
  constants_dirty_ = true;
  if (color_material_) {
    flush_current();
    update_color_material();
  }
}

// ---------------------------------------------------------------- colour material, as Mesa tracks it
//
// GL 2.1 (2.14.3): while GL_COLOR_MATERIAL is enabled the chosen material parameters track the
// current colour, always. Mesa 22.3 tracks it in steps, and programs see the steps:
// - glColor and glMaterial outside glBegin/glEnd are held as pending values (vbo's current
//   attributes) and copied to the GL state at a flush: at glBegin, every draw, glGetMaterialfv,
//   the glGet of the current colour or normal, and the first state call after a glBegin/glEnd
//   (then the pending set is emptied); and at glEnable(GL_COLOR_MATERIAL) and glColorMaterial
//   (then it is kept: the next flush copies the same values again);
// - at a copy, a pending colour that differs from the last copied one updates the tracked
//   material, after the pending material values are copied; a glMaterial value, copied again at
//   the next flush, therefore overrides what glEnable(GL_COLOR_MATERIAL) tracked;
// - the lighting takes the tracked parameters from each vertex's colour only when the colour
//   varies per vertex (a colour array, or glColor inside glBegin/glEnd); otherwise from the
//   material state as tracked (ffvertex_prog.c).
// The spec mode tracks at once and per vertex, as GL 2.1 says.

void Context::update_color_material() {
  if (!color_material_) return;
  const glm::dvec4 c = flushed_color_;
  for (int f = 0; f < 2; ++f) {
    if (!(model_.cm_faces >> f & 1)) continue;
    lighting::MaterialParams& m = materials_[f];
    switch (cm_mode_) {
      case GL_AMBIENT: m.ambient = c; break;
      case GL_DIFFUSE: m.diffuse = c; break;
      case GL_SPECULAR: m.specular = c; break;
      case GL_EMISSION: m.emission = c; break;
      case GL_AMBIENT_AND_DIFFUSE: m.ambient = m.diffuse = c; break;
    }
  }
  constants_dirty_ = true;
}

void Context::copy_pending() {
  const bool color_changed = color_ != flushed_color_;
  flushed_color_ = color_;
  for (const PendingMaterial& p : pending_materials_)
    if (*p.dst != p.value) *p.dst = p.value, constants_dirty_ = true;
  if (color_changed) update_color_material();
}

void Context::flush_current() {
  if (!spec_) copy_pending();
}

void Context::flush_stored() {
  if (spec_) return;
  copy_pending();
  pending_materials_.clear();
  color_size_ = color_active_ = 0;  // the vbo's vertex format is reset
}

void Context::ShadeModel(GLenum mode) {
  if (!outside_begin_end()) return;
  if (mode != GL_FLAT && mode != GL_SMOOTH) return error(GL_INVALID_ENUM);
  shade_model_ = mode;
}

void Context::FrontFace(GLenum mode) {
  if (!outside_begin_end()) return;
  if (mode != GL_CW && mode != GL_CCW) return error(GL_INVALID_ENUM);
  front_face_ = mode;
}

void Context::CullFace(GLenum mode) {
  if (!outside_begin_end()) return;
  if (!valid_face(mode)) return error(GL_INVALID_ENUM);
  cull_mode_ = mode;
}

void Context::DepthFunc(GLenum func) {
  if (!outside_begin_end()) return;
  if (func < GL_NEVER || func > GL_ALWAYS) return error(GL_INVALID_ENUM);
  depth_func_ = func;
}

void Context::GetLightfv(GLenum light, GLenum pname, GLfloat* out) {
  if (!outside_begin_end()) return;
  const int i = light_index(light), n = light_param_count(pname);
  if (i < 0 || n == 0) return error(GL_INVALID_ENUM);
  const lighting::LightParams& l = lights_[i];
  glm::dvec4 v(0);
  switch (pname) {
    case GL_AMBIENT: v = l.ambient; break;
    case GL_DIFFUSE: v = l.diffuse; break;
    case GL_SPECULAR: v = l.specular; break;
    case GL_POSITION: v = l.position; break;
    case GL_SPOT_DIRECTION: v = glm::dvec4(l.spot_direction, 0); break;
    case GL_SPOT_EXPONENT: v.x = l.spot_exponent; break;
    case GL_SPOT_CUTOFF: v.x = l.spot_cutoff; break;
    case GL_CONSTANT_ATTENUATION: v.x = l.constant_attenuation; break;
    case GL_LINEAR_ATTENUATION: v.x = l.linear_attenuation; break;
    case GL_QUADRATIC_ATTENUATION: v.x = l.quadratic_attenuation; break;
  }
  for (int k = 0; k < n; ++k) out[k] = GLfloat(v[k]);
}

void Context::GetMaterialfv(GLenum face, GLenum pname, GLfloat* out) {
  if (!outside_begin_end()) return;
  flush_stored();  // Mesa: copied and emptied (measured: a glMaterial before it no longer overrides tracking)
  if (face != GL_FRONT && face != GL_BACK) return error(GL_INVALID_ENUM);
  const lighting::MaterialParams& m = materials_[face == GL_BACK];
  glm::dvec4 v;
  switch (pname) {
    case GL_AMBIENT: v = m.ambient; break;
    case GL_DIFFUSE: v = m.diffuse; break;
    case GL_SPECULAR: v = m.specular; break;
    case GL_EMISSION: v = m.emission; break;
    case GL_SHININESS: out[0] = GLfloat(m.shininess); return;
    case GL_COLOR_INDEXES: for (int k = 0; k < 3; ++k) out[k] = GLfloat(color_indexes_[face == GL_BACK][k]); return;
    default: return error(GL_INVALID_ENUM);
  }
  for (int k = 0; k < 4; ++k) out[k] = GLfloat(v[k]);
}

// ---------------------------------------------------------------- glGet

namespace {
// Mesa's FLOAT_TO_INT (main/macros.h): (GLint)(2147483647.0 * x), truncated, unclamped; out of
// range the x86-64 conversion (cvttsd2si) gives INT_MIN.
GLint float_to_int(double x) {
  const double d = 2147483647.0 * x;
  if (!(d > -2147483649.0 && d < 2147483648.0)) return std::numeric_limits<GLint>::min();
  return GLint(d);
}
}  // namespace

#define FFC_GET(...)                               \
  {                                                \
    const double vals[] = {__VA_ARGS__};           \
    n = int(sizeof vals / sizeof *vals);           \
    std::copy(vals, vals + n, out);                \
  }

// The one list of glGet values: writes up to 16 values to `out` and returns how many (0 after
// recording an error). `normalized` tells glGetIntegerv how to convert: kRound rounds to the
// nearest integer; kFromFloat / kFromDouble map the value's [-1, 1] onto the integer range
// (colours, normals, depth range and depth clear value, as GL 2.1 section 6.1.2 says; and the
// matrices, as Mesa does though the spec says they round: get.c's TYPE_MATRIX uses FLOAT_TO_INT),
// from the value as Mesa stores it: a float, or a double for the depth clear value.
int Context::get_values(GLenum pname, GLdouble* out, int& normalized) {
  normalized = kRound;
  if (!outside_begin_end()) return 0;
  int n = 0;
  auto vec4 = [&](const glm::dvec4& c, bool color) {
    for (int k = 0; k < 4; ++k) out[k] = c[k];
    n = 4, normalized = color ? kFromFloat : kRound;
  };
  auto mat = [&](const glm::dmat4& m) {
    std::copy(glm::value_ptr(m), glm::value_ptr(m) + 16, out);
    n = 16, normalized = kFromFloat;
  };
  if (pname == GL_CURRENT_COLOR || pname == GL_CURRENT_NORMAL) {  // as glGetMaterialfv, but the colour
    const int size = color_size_, active = color_active_;           // attribute keeps its sizes (measured)
    flush_stored();
    color_size_ = size, color_active_ = active;
  }
  switch (pname) {
    // The float context reports its float matrices, as Mesa does: the ones it draws with.
    case GL_MODELVIEW_MATRIX: mat(modelview()); break;
    case GL_TEXTURE_MATRIX: mat(texture()); break;
    case GL_PROJECTION_MATRIX: mat(projection()); break;
    case GL_MODELVIEW_STACK_DEPTH: FFC_GET(double(modelview_.size())); break;
    case GL_PROJECTION_STACK_DEPTH: FFC_GET(double(projection_.size())); break;
    case GL_MAX_MODELVIEW_STACK_DEPTH: case GL_MAX_PROJECTION_STACK_DEPTH: FFC_GET(double(kMaxStackDepth)); break;
    case GL_MAX_TEXTURE_STACK_DEPTH: FFC_GET(double(kMaxTextureStackDepth)); break;
    case GL_TEXTURE_STACK_DEPTH: FFC_GET(double(texture_.size())); break;
    case GL_MATRIX_MODE: FFC_GET(double(matrix_mode_)); break;
    case GL_VIEWPORT: FFC_GET(double(viewport_[0]), double(viewport_[1]), double(viewport_[2]), double(viewport_[3])); break;
    case GL_DEPTH_RANGE: FFC_GET(depth_range_.x, depth_range_.y); normalized = kFromFloat; break;
    case GL_MAX_LIGHTS: FFC_GET(8.0); break;
    case GL_LIGHT_MODEL_AMBIENT: vec4(model_.ambient, true); break;
    case GL_LIGHT_MODEL_LOCAL_VIEWER: FFC_GET(double(model_.local_viewer)); break;
    case GL_LIGHT_MODEL_TWO_SIDE: FFC_GET(double(model_.two_side)); break;
    case GL_LIGHT_MODEL_COLOR_CONTROL:
      FFC_GET(double(model_.separate_specular ? GL_SEPARATE_SPECULAR_COLOR : GL_SINGLE_COLOR)); break;
    case GL_SHADE_MODEL: FFC_GET(double(shade_model_)); break;
    case GL_COLOR_MATERIAL_FACE: FFC_GET(double(cm_face_)); break;
    case GL_COLOR_MATERIAL_PARAMETER: FFC_GET(double(cm_mode_)); break;
    case GL_FRONT_FACE: FFC_GET(double(front_face_)); break;
    case GL_CULL_FACE_MODE: FFC_GET(double(cull_mode_)); break;
    case GL_DEPTH_FUNC: FFC_GET(double(depth_func_)); break;
    case GL_CURRENT_COLOR: vec4(color_, true); break;
    case GL_CURRENT_NORMAL: FFC_GET(normal_.x, normal_.y, normal_.z); normalized = kFromFloat; break;
    case GL_COLOR_CLEAR_VALUE: vec4(glm::dvec4(clear_color_), true); break;
    case GL_DEPTH_CLEAR_VALUE: FFC_GET(clear_depth_); normalized = kFromDouble; break;
    case GL_LINE_WIDTH: FFC_GET(double(line_width_)); break;
    // llvmpipe's limits as Mesa 22.3 reports them: sizes 1 to 255 (LP_MAX_POINT_WIDTH), steps of 0.1.
    case GL_POINT_SIZE: FFC_GET(double(point_size_)); break;
    case GL_POINT_SIZE_RANGE: case GL_ALIASED_POINT_SIZE_RANGE: FFC_GET(1.0, 255.0); break;
    case GL_POINT_SIZE_GRANULARITY: FFC_GET(double(0.1f)); break;
    case GL_RENDER_MODE: FFC_GET(double(render_mode_)); break;
    case GL_DEPTH_BITS: FFC_GET(24.0); break;
    case GL_RED_BITS: case GL_GREEN_BITS: case GL_BLUE_BITS: case GL_ALPHA_BITS: FFC_GET(8.0); break;
    case GL_VERTEX_ARRAY_SIZE: FFC_GET(double(vertex_array_.size)); break;
    case GL_VERTEX_ARRAY_TYPE: FFC_GET(double(vertex_array_.type)); break;
    case GL_VERTEX_ARRAY_STRIDE: FFC_GET(double(vertex_array_.stride)); break;
    case GL_NORMAL_ARRAY_TYPE: FFC_GET(double(normal_array_.type)); break;
    case GL_NORMAL_ARRAY_STRIDE: FFC_GET(double(normal_array_.stride)); break;
    case GL_COLOR_ARRAY_SIZE: FFC_GET(double(color_array_.size)); break;
    case GL_COLOR_ARRAY_TYPE: FFC_GET(double(color_array_.type)); break;
    case GL_COLOR_ARRAY_STRIDE: FFC_GET(double(color_array_.stride)); break;
    case GL_VERTEX_ARRAY: FFC_GET(double(vertex_array_.enabled)); break;
    case GL_NORMAL_ARRAY: FFC_GET(double(normal_array_.enabled)); break;
    case GL_COLOR_ARRAY: FFC_GET(double(color_array_.enabled)); break;
    case GL_PACK_ALIGNMENT: FFC_GET(double(pack_alignment_)); break;
    case GL_UNPACK_ALIGNMENT: FFC_GET(double(unpack_alignment_)); break;
    case GL_PACK_SWAP_BYTES: case GL_PACK_LSB_FIRST: case GL_PACK_ROW_LENGTH: case GL_PACK_IMAGE_HEIGHT:
    case GL_PACK_SKIP_ROWS: case GL_PACK_SKIP_PIXELS: case GL_PACK_SKIP_IMAGES: case GL_UNPACK_SWAP_BYTES:
    case GL_UNPACK_LSB_FIRST: case GL_UNPACK_ROW_LENGTH: case GL_UNPACK_IMAGE_HEIGHT: case GL_UNPACK_SKIP_ROWS:
    case GL_UNPACK_SKIP_PIXELS: case GL_UNPACK_SKIP_IMAGES: {
      const auto it = pixel_store_.find(pname);
      FFC_GET(double(it == pixel_store_.end() ? 0 : it->second));
      break;
    }
    case GL_FEEDBACK_BUFFER_SIZE: FFC_GET(double(feedback_size_)); break;
    case GL_FEEDBACK_BUFFER_TYPE: FFC_GET(double(feedback_type_)); break;
    case GL_CURRENT_RASTER_POSITION:
      FFC_GET(raster_pos_.window.x, raster_pos_.window.y, raster_pos_.window.z, raster_pos_.window.w);
      break;
    case GL_CURRENT_RASTER_COLOR: vec4(raster_pos_.color, true); break;
    case GL_CURRENT_RASTER_POSITION_VALID: FFC_GET(double(raster_pos_.valid)); break;
    case GL_CURRENT_RASTER_DISTANCE: FFC_GET(raster_pos_.distance); break;
    default: {
      const int on = enabled_state(pname);  // every capability glIsEnabled knows is also a glGet value
      if (on >= 0) {
        FFC_GET(double(on));
        break;
      }
      n = fog_values(pname, out, normalized);
      if (n == 0) n = get_table_values(pname, out, normalized);
      if (n == 0) return error(GL_INVALID_ENUM), 0;
    }
  }
  return n;
}
#undef FFC_GET

void Context::GetDoublev(GLenum pname, GLdouble* out) {
  GLdouble v[16];
  int normalized;
  const int n = get_values(pname, v, normalized);
  std::copy(v, v + n, out);
}

void Context::GetFloatv(GLenum pname, GLfloat* out) {
  GLdouble v[16];
  int normalized;
  const int n = get_values(pname, v, normalized);
  for (int k = 0; k < n; ++k) out[k] = GLfloat(v[k]);
}

void Context::GetIntegerv(GLenum pname, GLint* out) {
  GLdouble v[16];
  int normalized;
  const int n = get_values(pname, v, normalized);
  // Other values round to the nearest integer, halves away from zero (Mesa's IROUND).
  for (int k = 0; k < n; ++k)
    out[k] = normalized == kFromFloat    ? float_to_int(double(float(v[k])))
             : normalized == kFromDouble ? float_to_int(v[k])
                                         : GLint(std::lround(v[k]));
}

// ---------------------------------------------------------------- matrices

std::vector<glm::dmat4>& Context::stack() {
  return matrix_mode_ == GL_PROJECTION ? projection_ : matrix_mode_ == GL_TEXTURE ? texture_ : modelview_;
}
std::vector<fmat::Matrix>& Context::stack_f() {
  return matrix_mode_ == GL_PROJECTION ? projection_f_ : matrix_mode_ == GL_TEXTURE ? texture_f_ : modelview_f_;
}

void Context::MatrixMode(GLenum mode) {
  if (!outside_begin_end()) return;
  // GL_TEXTURE has its stack (nothing here reads it: there is no texturing).
  if (mode != GL_MODELVIEW && mode != GL_PROJECTION && mode != GL_TEXTURE) return error(GL_INVALID_ENUM);
  matrix_mode_ = mode;
}

void Context::LoadIdentity() {
  if (!outside_begin_end()) return;
  stack().back() = glm::dmat4(1);
  stack_f().back().load_identity();
}

void Context::LoadMatrix(const glm::dmat4& m) {
  if (!outside_begin_end()) return;
  stack().back() = m;
  stack_f().back().load(glm::mat4(m));
}

void Context::MultMatrix(const glm::dmat4& m) {
  if (!outside_begin_end()) return;
  stack().back() = stack().back() * m;
  stack_f().back().multiply(glm::mat4(m));
}

void Context::validate_matrices() {
  modelview_f_.back().analyse();
  texture_f_.back().analyse();
  // Mesa's _ModelProjectMatrix, with the flags of both (three rows when both are affine).
  mvp_f_ = fmat::Matrix::product(projection_f_.back(), modelview_f_.back()).values();
}

void Context::PushMatrix() {
  if (!outside_begin_end()) return;
  auto& s = stack();
  if (s.size() >= (matrix_mode_ == GL_TEXTURE ? kMaxTextureStackDepth : kMaxStackDepth))
    return error(GL_STACK_OVERFLOW);
  s.push_back(s.back());
  auto& f = stack_f();
  f.back().analyse();  // Mesa makes the pushed matrix current first (_math_matrix_push_copy)
  f.push_back(f.back());
}

void Context::PopMatrix() {
  if (!outside_begin_end()) return;
  auto& s = stack();
  if (s.size() <= 1) return error(GL_STACK_UNDERFLOW);
  s.pop_back();
  stack_f().pop_back();
}

// Each transform updates the double matrix exactly and the float one as Mesa's float maths does.
void Context::Rotate(double angle, double x, double y, double z) {
  if (!outside_begin_end()) return;
  // An axis shorter than 1e-4 leaves the matrix unchanged, in double as in float (Mesa's
  // m_matrix.c rule, which GL 2.1 leaves open: the rotation of a zero axis is undefined).
  const double len = std::sqrt(x * x + y * y + z * z);
  if (len > 1e-4) stack().back() *= glm::rotate(glm::dmat4(1), glm::radians(angle), glm::dvec3(x, y, z) / len);
  stack_f().back().rotate(float(angle), float(x), float(y), float(z));
}

void Context::Scale(double x, double y, double z) {
  if (!outside_begin_end()) return;
  stack().back() *= glm::scale(glm::dmat4(1), glm::dvec3(x, y, z));
  stack_f().back().scale(float(x), float(y), float(z));
}

void Context::Translate(double x, double y, double z) {
  if (!outside_begin_end()) return;
  stack().back() *= glm::translate(glm::dmat4(1), glm::dvec3(x, y, z));
  stack_f().back().translate(float(x), float(y), float(z));
}

void Context::Ortho(double l, double r, double b, double t, double n, double f) {
  if (!outside_begin_end()) return;
  // Mesa checks the arguments once converted to float (so 1 and 1 + 1e-10 are equal there).
  const float fl = float(l), fr = float(r), fb = float(b), ft = float(t), fn = float(n), ff = float(f);
  if (fl == fr || fb == ft || fn == ff) return error(GL_INVALID_VALUE);
  stack().back() *= glm::orthoRH_NO(l, r, b, t, n, f);
  stack_f().back().ortho(fl, fr, fb, ft, fn, ff);
}

void Context::Frustum(double l, double r, double b, double t, double n, double f) {
  if (!outside_begin_end()) return;
  const float fl = float(l), fr = float(r), fb = float(b), ft = float(t), fn = float(n), ff = float(f);
  if (fn <= 0 || ff <= 0 || fl == fr || fb == ft || fn == ff) return error(GL_INVALID_VALUE);
  stack().back() *= glm::frustumRH_NO(l, r, b, t, n, f);
  stack_f().back().frustum(fl, fr, fb, ft, fn, ff);
}

void Context::Viewport(GLint x, GLint y, GLsizei w, GLsizei h) {
  if (!outside_begin_end()) return;
  if (w < 0 || h < 0) return error(GL_INVALID_VALUE);
  // Mesa clamps the size to GL_MAX_VIEWPORT_DIMS and the origin to its viewport bounds range
  // [-2 max, 2 max - 1] (viewport.c; GL 2.1 says only the size is clamped). Ours does the same:
  // window coordinates then stay far from the int range.
  x = std::clamp(x, -2 * kMaxViewport, 2 * kMaxViewport - 1), y = std::clamp(y, -2 * kMaxViewport, 2 * kMaxViewport - 1);
  viewport_ = {x, y, std::min(w, kMaxViewport), std::min(h, kMaxViewport)};
}

void Context::DepthRange(double n, double f) {
  if (!outside_begin_end()) return;
  depth_range_ = {clamp01(n), clamp01(f)};
}

void Context::ClearColor(float r, float g, float b, float a) {
  if (!outside_begin_end()) return;
  clear_color_ = glm::vec4(clamp01(r), clamp01(g), clamp01(b), clamp01(a));
}

void Context::ClearDepth(double d) {
  if (!outside_begin_end()) return;
  clear_depth_ = clamp01(d);
}

void Context::Clear(GLbitfield mask) {
  if (!outside_begin_end()) return;
  if (mask & ~GLbitfield(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT | GL_ACCUM_BUFFER_BIT))
    return error(GL_INVALID_VALUE);
  if (render_mode_ != GL_RENDER) return;
  raster::ClearRequest& c = pending_clear_;  // a later clear of the same buffer replaces an earlier one
  if (mask & GL_COLOR_BUFFER_BIT) c.color = true, c.clear_color = clear_color_;
  if (mask & GL_DEPTH_BUFFER_BIT) c.depth = true, c.clear_depth = clear_depth_;
}

void Context::flush_clear() {
  if (!pending_clear_.pending()) return;
  raster::clear(fb_, pending_clear_, workers());
  pending_clear_ = {};
}

// Nothing is left to do: every draw is finished when its call returns. Inside glBegin/glEnd both
// are errors (GL 2.1 section 2.6.3).
void Context::Finish() { outside_begin_end(); }
void Context::Flush() { outside_begin_end(); }

void Context::LineWidth(float w) {
  if (!outside_begin_end()) return;
  if (w <= 0) return error(GL_INVALID_VALUE);  // Mesa's test: a NaN passes
  line_width_ = w;
}

void Context::PointSize(float size) {
  if (!outside_begin_end()) return;
  if (size <= 0) return error(GL_INVALID_VALUE);  // as Mesa's points.c: a NaN passes
  point_size_ = size;
}

// ---------------------------------------------------------------- vertices

lighting::Key Context::key() const {
  if (!lighting_) return {};
  lighting::ModelParams m = model_;
  m.color_material = cm_per_vertex();
  m.cm_mode = cm_mode_;
  return lighting::make_key(lights_, materials_, m, normalize_, rescale_normal_);
}

void Context::prepare_lighting() {
  lighting::ModelParams m = model_;
  m.color_material = cm_per_vertex();
  const lighting::Key lk = key();
  const bool any_light = lk.any_light();
  if (any_light && model_.separate_specular)
    deviations_.insert("feedback reports only the primary colour under GL_SEPARATE_SPECULAR_COLOR");
  if (any_light && model_.two_side && m.color_material && cm_face_ != GL_FRONT)
    deviations_.insert("two-sided lighting with a GL_BACK colour material is broken in Mesa 22.3");
  // Shininess 0, found case by case against Mesa 22.3's feedback (ffvertex_prog.c). When every
  // lit face has shininess 0, Mesa builds its shininess-0 program: exact for a light without
  // attenuation or spot, but for an attenuated point light or a spot light it runs LIT on n.L in
  // every component, so the specular factor is pow(n.L, n.L) (0.71 at n.L = 0.5) instead of 1.
  // When one face has shininess 0 and the other not (two-sided lighting), the ordinary LIT path
  // takes pow(0, 0) as 0 where n.h <= 0 < n.L.
  const bool face_zero[2] = {materials_[0].shininess == 0, model_.two_side && materials_[1].shininess == 0};
  const bool all_zero = face_zero[0] && (!model_.two_side || face_zero[1]);
  if (all_zero && lk.specular())
    for (int i = 0; i < 8; ++i)
      if (lk.enabled(i) && (lk.spot(i) || lk.attenuated(i)))
        deviations_.insert("shininess 0 with an attenuated or spot light: Mesa's LIT path raises n.L to the power n.L "
                           "for the specular factor where the spec gives 1");
  if (any_light && lk.specular() && !all_zero && (face_zero[0] || face_zero[1]))
    deviations_.insert("shininess 0: Mesa's LIT path takes pow(0, 0) as 0 where the spec gives 1");
  // "Constants changed" re-prepares; the kernel for the pipeline's shape comes from the key.
  const lighting::Key& k = lk;
  if (precision_ == Precision::Float) {
    prepared_f_ = lighting::prepare<float>(lights_, materials_, m, k);
    kernel_f_ = lighting::specialised<float>(k);
  } else {
    prepared_d_ = lighting::prepare<double>(lights_, materials_, m, k);
    kernel_d_ = lighting::specialised<double>(k);
  }
  constants_dirty_ = false;
}

void Context::Normal(double x, double y, double z) { normal_ = {x, y, z}; }

void Context::Color(double r, double g, double b, double a, int components) {
  // glColor3 sets alpha to 1 (GL 2.1 section 2.7). Mesa's vbo keeps the colour attribute's size and
  // active size between flushes: a glColor3 that shrinks the active size fills alpha with 1, but
  // one at active size 3 in an attribute of size 4 (glColor4, glColor3, glColor4 since the last
  // flush) leaves alpha as the last glColor4 set it. Measured call by call; tested on generated
  // streams (ColorMaterialStreams).
  if (!spec_) {
    if (in_begin_ && prim_mode_ == GL_LINE_LOOP && components > color_size_ && !verts_.empty())
      deviations_.insert(kLineLoopWrap);  // docs/deviations.md row 48
    if (components > color_size_) color_size_ = color_active_ = components;
    else if (components < color_active_) {
      color_active_ = components;
      if (in_begin_) deviations_.insert(kColorShrinkInPrimitive);  // docs/deviations.md row 44
    }
    else if (components == 3) a = color_.a;
  }
  color_ = {r, g, b, a};
  if (in_begin_ && !color_varies_) color_varies_ = true, constants_dirty_ = true;
  if (!spec_) return;  // tracked at the next flush (see update_color_material)
  flushed_color_ = color_;  // GL 2.1: tracked at once
  update_color_material();
}

void Context::update_vertex_constants() {
  if (!lighting_) return;
  if (constants_dirty_) prepare_lighting();
  // Normals transform by the inverse transpose of the modelview's upper 3x3 (the float matrix in
  // the float context: the one positions and lights use).
  const glm::dmat4 mv = modelview();
  if (mv != normal_matrix_of_) {  // the inverse is per modelview, not per vertex
    normal_matrix_of_ = mv;
    // A singular modelview has no inverse: the transformed normal is undefined and the inverse's
    // entries arbitrary (2.11.3). Mesa (m_matrix.c) takes the identity; ours too, not infinities
    // or rounding noise. Singular: |det| within 1e-14 of its largest value for the rows' (or the
    // columns') lengths (Hadamard), a test that does not depend on scale (1e-30 I inverts).
    const glm::dmat3 m3(mv);
    double rows = 1, cols = 1;
    for (int i = 0; i < 3; ++i)
      cols *= glm::length(m3[i]), rows *= glm::length(glm::dvec3(m3[0][i], m3[1][i], m3[2][i]));
    const bool singular = !(std::abs(glm::determinant(m3)) > 1e-14 * std::min(rows, cols));
    normal_matrix_ = singular ? glm::dmat3(1) : glm::inverse(m3);
    // A projective modelview (bottom row not 0, 0, 0, 1): Mesa transforms normals by the upper 3x3
    // of the 4x4 inverse, where GL 2.1 inverts the upper 3x3 (the two agree for every affine matrix).
    if (!spec_ && (mv[0][3] != 0 || mv[1][3] != 0 || mv[2][3] != 0 || mv[3][3] != 1))
      normal_matrix_ = glm::dmat3(glm::inverse(mv));
    for (int k = 0; k < 9; ++k)
      if (!std::isfinite(normal_matrix_[k / 3][k % 3])) normal_matrix_ = glm::dmat3(1);
  }
}

raster::Vertex Context::vertex(const glm::dvec4& obj, const glm::dvec3& normal, const glm::dvec4& color,
                               bool* zero_normal) const {
  raster::Vertex v;
  glm::dvec4 eye;
  if (precision_ == Precision::Float) {  // positions rounded as Mesa rounds them
    const glm::vec4 of(obj);
    v.clip = fmat::transform(mvp_f_, of);
    eye = fmat::transform(modelview_f_.back().values(), of);
  } else {
    eye = modelview_.back() * obj;
    v.clip = projection_.back() * eye;
  }
  // Mesa's fixed-function vertex program (ffvertex_prog.c build_fog): |eye z| for
  // GL_FRAGMENT_DEPTH (its default distance mode, eye plane absolute); for GL_FOG_COORD the
  // current fog coordinate, which stays 0 here (no glFogCoord).
  if (fog_ && fog_coord_src_ == GL_FRAGMENT_DEPTH) v.fog = std::abs(eye.z);
  // GL 2.1 lights the vertex at its eye-space point (x/w, y/w, z/w); Mesa's fixed-function program
  // takes x, y, z as they are (docs/deviations.md). The lighting divides unless w is 1.
  if (!spec_) eye.w = 1;
  if (!lighting_) {
    // Clamped to [0,1]; a NaN (unspecified input, 2.1.1) to 1 as in Mesa, so none reaches the rasterizer.
    for (int k = 0; k < 4; ++k) v.front[k] = !(color[k] < 1) ? 1.0 : color[k] > 0 ? color[k] : 0.0;
    v.back = v.front;
    v.front_sec = v.back_sec = glm::dvec4(0);
    return v;
  }
  const glm::dmat3& inv = normal_matrix_;
  glm::dvec3 n = normal * inv;  // row vector times M^-1
  if (normalize_) {
    const double len = glm::length(n);
    if (len > 0) n /= len;  // a zero normal stays zero: ambient and emission only
    else *zero_normal = true;
  } else if (rescale_normal_) {
    const double f = glm::length(glm::dvec3(inv[0][2], inv[1][2], inv[2][2]));  // M^-1's third row
    if (f > 0) n /= f;
  }
  if (precision_ == Precision::Float) {
    const glm::vec4 pf(eye), cf(color);
    const glm::vec3 nf(n);
    lighting::Lit<float> lit;
    kernel_f_(prepared_f_, &pf, &nf, &cf, 1, &lit);
    v.front = lit.primary[0], v.back = lit.primary[1];
    v.front_sec = lit.secondary[0], v.back_sec = lit.secondary[1];
  } else {
    lighting::Lit<double> lit;
    kernel_d_(prepared_d_, &eye, &n, &color, 1, &lit);
    v.front = lit.primary[0], v.back = lit.primary[1];
    v.front_sec = lit.secondary[0], v.back_sec = lit.secondary[1];
  }
  return v;
}

void Context::process_vertex(const glm::dvec4& obj) {
  if (deferred_) {  // lit with the others at glEnd; only what the lighting reads is kept
    deferred_pos_.push_back(glm::vec4(obj));  // the float path rounds positions so anyway
    if (lighting_) deferred_normal_.push_back(normal_);
    if (!lighting_ || color_material_) deferred_color_.push_back(color_);
    return;
  }
  update_vertex_constants();
  bool zero_normal = false;
  verts_.push_back(vertex(obj, normal_, color_, &zero_normal));
  if (zero_normal) deviations_.insert(kZeroNormal);
  const bool finite = std::isfinite(obj.x) && std::isfinite(obj.y) && std::isfinite(obj.z) && std::isfinite(obj.w) &&
                      (!lighting_ || (std::isfinite(normal_.x) && std::isfinite(normal_.y) && std::isfinite(normal_.z)));
  if (!finite) deviations_.insert(kNonfiniteVertex);
}

// A large glDrawArrays / glDrawElements range: the vertices are independent, so both cores take
// half each.
void Context::fetch_range(GLint first, GLint count) {
  update_vertex_constants();
  verts_.resize(size_t(count));
  auto attribute = [](const ClientArray& a, GLint i, int n, Fixed normalized, glm::dvec4 v) {
    const uint8_t* p = element(a, i);
    for (int k = 0; k < n; ++k) v[k] = read_component(p, a.type, k, normalized);
    return v;
  };
  auto work = [&](GLint lo, GLint hi, bool* zero) {
    for (GLint i = lo; i < hi; ++i) {
      const glm::dvec3 n = normal_array_.enabled ? glm::dvec3(attribute(normal_array_, i, 3, draw_fixed(), glm::dvec4(0)))
                                                 : normal_;
      const glm::dvec4 c = color_array_.enabled ? attribute(color_array_, i, color_array_.size, draw_fixed(), glm::dvec4(1))
                                                : color_;
      verts_[size_t(i - first)] = vertex(attribute(vertex_array_, i, vertex_array_.size, Fixed::Raw, glm::dvec4(0, 0, 0, 1)), n, c, zero);
    }
  };
  raster::Workers& w = workers();
  bool zero[raster::Workers::kMax] = {};  // per share: a zero normal met
  w.run([&](int share) {
    bool z = false;
    work(first + GLint(int64_t(count) * share / w.size()), first + GLint(int64_t(count) * (share + 1) / w.size()), &z);
    zero[share] = z;
  });
  if (std::find(zero, zero + w.size(), true) != zero + w.size()) deviations_.insert(kZeroNormal);
}

void Context::Vertex(double x, double y, double z, double w) {
  if (!in_begin_) return;  // outside glBegin/glEnd a vertex has no effect (undefined in GL)
  process_vertex({x, y, z, w});
}

void Context::Begin(GLenum mode) {
  if (in_begin_) return error(GL_INVALID_OPERATION);
  validate_matrices();  // Mesa validates its state before it checks the mode
  if (!valid_primitive(mode)) return error(primitive_error(mode));
  flush_stored();
  set_color_varies(false);
  vertices_kept_ = !spec_;
  in_begin_ = true;
  prim_mode_ = mode;
  verts_.clear();
  // Triangles in immediate mode take the triangle-list path: the vertices are kept as sent and
  // lit together at glEnd, unless a glMaterial between them changes the lighting (undefer()).
  deferred_ = shaded_path(mode);
  deferred_pos_.clear(), deferred_normal_.clear(), deferred_color_.clear();
}

void Context::undefer() {
  if (!deferred_) return;
  deferred_ = false;
  for (size_t i = 0; i < deferred_pos_.size(); ++i) {
    const glm::dvec3 normal = normal_;
    const glm::dvec4 color = color_;
    // As they were at that glVertex (what was not kept is not read).
    if (!deferred_normal_.empty()) normal_ = deferred_normal_[i];
    if (!deferred_color_.empty()) color_ = deferred_color_[i];
    process_vertex(glm::dvec4(deferred_pos_[i]));
    normal_ = normal, color_ = color;
  }
}

void Context::End() {
  if (!in_begin_) return error(GL_INVALID_OPERATION);
  in_begin_ = false;
  if (!deferred_) {
    flush_primitive();
    return flush_stored();
  }
  deferred_ = false;
  // The kept vertices as client arrays for the triangle-list path (no GL call can change the
  // arrays between glBegin and glEnd, so borrowing them is safe).
  const ClientArray arrays[3] = {vertex_array_, normal_array_, color_array_};
  vertex_array_ = {true, 4, GL_FLOAT, sizeof(glm::vec4), deferred_pos_.data()};
  normal_array_ = {!deferred_normal_.empty(), 3, GL_DOUBLE, sizeof(glm::dvec3), deferred_normal_.data()};
  color_array_ = {!deferred_color_.empty(), 4, GL_DOUBLE, sizeof(glm::dvec4), deferred_color_.data()};
  shade_range(0, GLint(deferred_pos_.size()));
  vertex_array_ = arrays[0], normal_array_ = arrays[1], color_array_ = arrays[2];
  draw_shaded(nullptr, deferred_pos_.size() / 3);
  flush_stored();
}

// The array pointers check as Mesa's varray.c does: the stride first, then the type, then the size.
// A negative stride alone is recorded by Mesa and then the pointer is set all the same (stride -1
// read back); ours ignores the call, as GL 2.1 section 2.5 says.
void Context::VertexPointer(GLint size, GLenum type, GLsizei stride, const void* p) {
  if (!outside_begin_end()) return;
  if (stride < 0) return error(GL_INVALID_VALUE);
  if (type != GL_SHORT && type != GL_INT && type != GL_FLOAT && type != GL_DOUBLE) return error(GL_INVALID_ENUM);
  if (size < 2 || size > 4) return error(GL_INVALID_VALUE);
  vertex_array_ = {vertex_array_.enabled, size, type, stride, p};
}

void Context::NormalPointer(GLenum type, GLsizei stride, const void* p) {
  if (!outside_begin_end()) return;
  if (stride < 0) return error(GL_INVALID_VALUE);
  if (type != GL_BYTE && type != GL_SHORT && type != GL_INT && type != GL_FLOAT && type != GL_DOUBLE)
    return error(GL_INVALID_ENUM);
  normal_array_ = {normal_array_.enabled, 3, type, stride, p};
}

void Context::ColorPointer(GLint size, GLenum type, GLsizei stride, const void* p) {
  if (!outside_begin_end()) return;
  if (stride < 0) return error(GL_INVALID_VALUE);
  if (type_size(type) == 0) return error(GL_INVALID_ENUM);
  if (size != 3 && size != 4) return error(GL_INVALID_VALUE);
  color_array_ = {color_array_.enabled, size, type, stride, p};
}

void Context::fetch_vertex(GLint i, Fixed f) {
  if (normal_array_.enabled) {
    const uint8_t* p = element(normal_array_, i);
    Normal(read_component(p, normal_array_.type, 0, f), read_component(p, normal_array_.type, 1, f),
           read_component(p, normal_array_.type, 2, f));
  }
  if (color_array_.enabled) {
    const uint8_t* p = element(color_array_, i);
    const GLenum t = color_array_.type;
    Color(read_component(p, t, 0, f), read_component(p, t, 1, f), read_component(p, t, 2, f),
          color_array_.size == 4 ? read_component(p, t, 3, f) : 1.0, color_array_.size);
  }
  if (vertex_array_.enabled) {
    const uint8_t* p = element(vertex_array_, i);
    glm::dvec4 v(0, 0, 0, 1);
    for (int k = 0; k < vertex_array_.size; ++k) v[k] = read_component(p, vertex_array_.type, k, Fixed::Raw);
    process_vertex(v);
  }
}

// An enabled array that was never given a pointer: GL 2.1 leaves reading it undefined and Mesa
// reads address 0 (a crash); ours reads nothing: GL_INVALID_OPERATION, as core profiles say of a
// draw from no buffer.
bool Context::arrays_readable() {
  for (const ClientArray* a : {&vertex_array_, &normal_array_, &color_array_})
    if (a->enabled && !a->pointer) return error(GL_INVALID_OPERATION), false;
  return true;
}

void Context::ArrayElement(GLint i) {
  // GL 2.1 defines no error for a negative index, and Mesa raises none (it reads before the
  // arrays); ours ignores the call.
  if (i < 0 || !arrays_readable()) return;
  if (!in_begin_) {
    // Outside glBegin/glEnd the element still sets the current normal and colour (its vertex has
    // no effect), as in Mesa.
    const bool vertex = vertex_array_.enabled;
    vertex_array_.enabled = false;
    fetch_vertex(i, element_fixed());
    vertex_array_.enabled = vertex;
    return;
  }
  fetch_vertex(i, element_fixed());
}

// A draw from arrays: pending values copied first (Mesa's FLUSH_FOR_DRAW); the colour varies
// per vertex when it comes from an array.
void Context::begin_draw() {
  flush_stored();
  set_color_varies(color_array_.enabled);
}

void Context::set_color_varies(bool v) {
  if (color_varies_ != v) color_varies_ = v, constants_dirty_ = true;
}

// Whether a draw of n vertices (and as many indices) fits in memory: each costs at most this many
// bytes on any path. Over half of the machine's memory is GL_OUT_OF_MEMORY, before anything is
// allocated: a vector of billions of vertices would fail, or worse, be granted and then touched
// page by page until the kernel kills the process.
bool Context::fits_in_memory(uint64_t n) {
  constexpr uint64_t kBytesPerVertex = sizeof(raster::Vertex) + sizeof(raster::WindowVertex) + 64;
  static const uint64_t budget = [] {
    const long pages = sysconf(_SC_PHYS_PAGES), page = sysconf(_SC_PAGESIZE);
    return pages > 0 && page > 0 ? uint64_t(pages) * uint64_t(page) / 2 : uint64_t(1) << 32;
  }();
  if (n <= budget / kBytesPerVertex) return true;
  error(GL_OUT_OF_MEMORY);
  return false;
}

// With the vertex array disabled GL draws nothing. Mesa draws all the same, each vertex at the
// current position, which its vbo module never updates from glVertex: the object-space origin
// (0, 0, 0, 1) every time, the other attributes from their arrays or current values. The default
// mode does so too (a constant array of the origin stands in for the positions); spec mode draws
// nothing.
template <class Draw>
void Context::with_positions(Draw draw) {
  if (vertex_array_.enabled) return draw();
  if (spec_) return;
  static const float kOrigin[4] = {0, 0, 0, 1};
  const ClientArray kept = vertex_array_;
  vertex_array_ = {true, 4, GL_FLOAT, 0, kOrigin, true};
  draw();
  vertex_array_ = kept;
}

// glDrawArrays and glDrawElements check as Mesa's draw_validate.c does: the count, then the mode,
// then the index type.
void Context::DrawArrays(GLenum mode, GLint first, GLsizei count) {
  if (!outside_begin_end()) return;
  validate_matrices();  // before any argument is checked, as Mesa's draws
  if (count < 0) return error(GL_INVALID_VALUE);
  if (!valid_primitive(mode)) return error(primitive_error(mode));
  with_positions([&] { draw_arrays(mode, first, count); });
}

void Context::draw_arrays(GLenum mode, GLint first, GLsizei count) {
  // A negative first is no error in GL 2.1 nor in Mesa (which then reads before the arrays); ours
  // draws nothing.
  if (first < 0 || !arrays_readable() || !fits_in_memory(uint64_t(count))) return;
  begin_draw();
  prim_mode_ = mode;
  verts_.clear();
  if (shaded_path(mode)) {
    shade_range(first, count);
    return draw_shaded(nullptr, size_t(count) / 3);
  }
  const CurrentValues kept = current_values();
  if (count >= kParallelVertices && threads_ > 1)
    fetch_range(first, count);
  else
    for (GLint i = first; i < first + count; ++i) fetch_vertex(i, draw_fixed());
  restore(kept);
  flush_primitive();
}

void Context::DrawElements(GLenum mode, GLsizei count, GLenum type, const void* indices) {
  if (!outside_begin_end()) return;
  validate_matrices();  // before any argument is checked, as Mesa's draws
  if (count < 0) return error(GL_INVALID_VALUE);
  if (!valid_primitive(mode)) return error(primitive_error(mode));
  if (type != GL_UNSIGNED_BYTE && type != GL_UNSIGNED_SHORT && type != GL_UNSIGNED_INT) return error(GL_INVALID_ENUM);
  with_positions([&] { draw_elements(mode, count, type, indices); });
}

void Context::draw_elements(GLenum mode, GLsizei count, GLenum type, const void* indices) {
  if (!indices || !arrays_readable() || !fits_in_memory(uint64_t(count))) return;
  begin_draw();
  prim_mode_ = mode;
  verts_.clear();
  // Each array element in the indices' range is transformed and lit once, however often the
  // indices name it (a post-transform cache covering the whole draw).
  const uint8_t* p = static_cast<const uint8_t*>(indices);
  uint32_t lo = UINT32_MAX, hi = 0;
  if (type == GL_UNSIGNED_INT && count > 0 && shaded_path(mode)) {
    // The triangle-list path reads 32-bit indices in place when they start at 0.
    const auto* u = static_cast<const uint32_t*>(indices);
    index_range(u, size_t(count), lo, hi);
    if (lo == 0 && !fits_in_memory(uint64_t(hi) + 1)) return;
    if (lo == 0) {
      shade_range(0, GLint(hi) + 1);
      return draw_shaded(u, size_t(count) / 3);
    }
  }
  elements_.resize(size_t(count));
  for (GLsizei i = 0; i < count; ++i) elements_[i] = uint32_t(read_component(p, type, i, Fixed::Raw));
  if (count > 0) index_range(elements_.data(), elements_.size(), lo, hi);
  if (count > 0 && !fits_in_memory(uint64_t(hi - lo) + 1)) return elements_.clear();
  if (count > 0 && shaded_path(mode)) {
    shade_range(GLint(lo), GLint(hi - lo + 1));
    for (uint32_t& e : elements_) e -= lo;
    draw_shaded(elements_.data(), size_t(count) / 3);
    elements_.clear();
    return;
  }
  if (count > 0) {
    const CurrentValues kept = current_values();
    if (hi - lo + 1 >= kParallelVertices && threads_ > 1)
      fetch_range(GLint(lo), GLint(hi - lo + 1));
    else
      for (uint32_t i = lo; i <= hi; ++i) fetch_vertex(GLint(i), draw_fixed());
    restore(kept);
    for (uint32_t& e : elements_) e -= lo;
  }
  flush_primitive();
  elements_.clear();
}

// ---------------------------------------------------------------- primitives

// Whether a triangle's window-space area is 0 as Mesa's draw module computes it (float, edges
// from the third vertex).
static bool zero_area(const raster::WindowVertex* const* v) {
  const float ex = float(v[0]->pos.x) - float(v[2]->pos.x), ey = float(v[0]->pos.y) - float(v[2]->pos.y);
  const float fx = float(v[1]->pos.x) - float(v[2]->pos.x), fy = float(v[1]->pos.y) - float(v[2]->pos.y);
  return ex * fy - ey * fx == 0;
}

// A fed-back triangle's depths as the offset stage of Mesa's draw module leaves them
// (draw_pipe_offset.c): z + units + max(|dz/dx|, |dz/dy|) * factor in float, both terms 0 unless
// GL_POLYGON_OFFSET_FILL is on (polygons are filled), then clamped to [0, 1] by a clamp that takes
// NaN to 0. The slopes divide by the triangle's doubled area, so a triangle of zero area gets
// 0/0 or x/0 there, and 0 times that a NaN: its depths all become 0.
void Context::feedback_offset(const raster::WindowVertex* const* v, const raster::State& rs, float* z) const {
  float p[3][3];
  for (int k = 0; k < 3; ++k) p[k][0] = float(v[k]->pos.x), p[k][1] = float(v[k]->pos.y), p[k][2] = float(v[k]->pos.z);
  const float ex = p[0][0] - p[2][0], ey = p[0][1] - p[2][1], ez = p[0][2] - p[2][2];
  const float fx = p[1][0] - p[2][0], fy = p[1][1] - p[2][1], fz = p[1][2] - p[2][2];
  const float det = ex * fy - ey * fx, inv_det = 1.0f / det;
  const float dzdx = std::fabs((ey * fz - ez * fy) * inv_det), dzdy = std::fabs((ez * fx - ex * fz) * inv_det);
  const float scale = offset_fill_ ? offset_factor_ : 0.0f, units = offset_fill_ ? rs.offset_units : 0.0f;
  const float offset = units + (dzdx > dzdy ? dzdx : dzdy) * scale;
  for (int k = 0; k < 3; ++k) {
    const float d = p[k][2] + offset;
    z[k] = d > 0 ? (d > 1 ? 1.0f : d) : 0.0f;
  }
}

void Context::flush_primitive() {
  if (render_mode_ == GL_SELECT) {  // selection is not modelled: nothing is drawn
    verts_.clear();
    return;
  }
  const raster::State rs = raster_state();
  const bool feedback = render_mode_ == GL_FEEDBACK;
  const bool lines = prim_mode_ == GL_LINES || prim_mode_ == GL_LINE_STRIP || prim_mode_ == GL_LINE_LOOP;
  if (!feedback && lines && (elements_.empty() ? verts_.size() : elements_.size()) >= 2 && enabled_state(GL_LINE_SMOOTH) == 1) deviations_.insert(kLineSmooth);
  if (!feedback && prim_mode_ == GL_POINTS && !(elements_.empty() ? verts_.empty() : elements_.empty()) &&
      enabled_state(GL_POINT_SMOOTH) == 1)
    deviations_.insert(kPointSmooth);
  std::vector<raster::Triangle>& tris = triangles_;
  tris.clear();

  auto put = [&](double x) { feedback_put(x); };
  if (feedback) note_texgen_in_feedback();
  // A primitive as feedback reports it. A clipped triangle goes back as Mesa's clipper emits it
  // (emit_poly in draw_pipe_clip.c): a fan of triangles (v[i], v[i+1], v[0]), the first vertex
  // last, also when the clipped polygon is a triangle.
  // Any of the three polygon offset enables puts the offset stage of Mesa's draw module in the
  // feedback pipeline (feedback_offset).
  const bool offset_stage = feedback && (offset_fill_ || enabled_state(GL_POLYGON_OFFSET_LINE) == 1 ||
                                         enabled_state(GL_POLYGON_OFFSET_POINT) == 1);
  auto emit_feedback = [&](GLenum kind, const raster::WindowVertex* w, size_t count, bool clipped) {
    auto one = [&](std::initializer_list<const raster::WindowVertex*> vs) {
      // Mesa's cull stage runs after its clipper, on each triangle it passes on, and culls one of
      // zero area in window space (its float determinant 0) whichever faces are culled.
      if (kind == GL_POLYGON_TOKEN && rs.cull && zero_area(vs.begin())) return;
      put(kind);
      if (kind == GL_POLYGON_TOKEN) put(double(vs.size()));
      float z[3] = {};
      if (kind == GL_POLYGON_TOKEN && offset_stage) feedback_offset(vs.begin(), rs, z);
      int n = 0;
      for (const raster::WindowVertex* v : vs) {
        put(v->pos.x), put(v->pos.y);
        if (feedback_type_ != GL_2D) put(kind == GL_POLYGON_TOKEN && offset_stage ? double(z[n]) : v->pos.z);
        ++n;
        if (feedback_type_ == GL_4D_COLOR_TEXTURE) put(1 / v->inv_w);
        if (feedback_type_ == GL_3D_COLOR || feedback_type_ == GL_3D_COLOR_TEXTURE ||
            feedback_type_ == GL_4D_COLOR_TEXTURE)
          for (int k = 0; k < 4; ++k) put(v->color[k]);
        if (feedback_type_ == GL_3D_COLOR_TEXTURE || feedback_type_ == GL_4D_COLOR_TEXTURE)
          put(0), put(0), put(0), put(1);
      }
    };
    if (kind == GL_POINT_TOKEN) return one({&w[0]});
    if (kind != GL_POLYGON_TOKEN) return one({&w[0], &w[1]});
    if (!clipped) return one({&w[0], &w[1], &w[2]});
    for (size_t i = 1; i + 1 < count; ++i) one({&w[i], &w[i + 1], &w[0]});
  };

  raster::Fixed<raster::Vertex, 2> prim;
  auto index = [&](size_t i) { return elements_.empty() ? i : size_t(elements_[i]); };
  auto at = [&](size_t i) -> const raster::Vertex& { return verts_[index(i)]; };
  // Most triangles lie inside the view volume: their vertices map to the window once, however
  // many triangles share them, and they skip clipping.
  const bool triangles = prim_mode_ >= GL_TRIANGLES;
  bool any_outside = false;
  if (triangles) {
    outside_.resize(verts_.size());
    window_.resize(verts_.size());
    // Vertices past the last whole primitive are dropped before Mesa's draw module looks for
    // vertices outside the view volume (u_trim_pipe_prim): they do not choose the quads' split.
    // (Drawn from elements, every fetched vertex counts, as measured so far.)
    size_t whole = verts_.size();
    if (elements_.empty()) {
      if (prim_mode_ == GL_TRIANGLES) whole -= whole % 3;
      else if (prim_mode_ == GL_QUADS) whole -= whole % 4;
      else if (prim_mode_ == GL_QUAD_STRIP) whole = whole < 4 ? 0 : whole - whole % 2;
      else if (whole < 3) whole = 0;
    }
    for (size_t i = 0; i < verts_.size(); ++i)
      if ((outside_[i] = raster::outside_planes(verts_[i].clip)) == 0) {
        window_[i] = raster::map_to_window(verts_[i].clip, rs);
        window_[i].fog = verts_[i].fog;
      } else if (i < whole) {
        any_outside = true;
      }
  }
  // One triangle: inside the view volume from the per-vertex window positions, otherwise
  // clipped. Safe to run on several threads at once when not in feedback mode (only `out` and
  // `scratch` are written).
  struct Scratch {
    raster::WindowVertex inside[3];
    raster::Vertex prim[3];
  };
  auto emit_triangle = [&](size_t i0, size_t i1, size_t i2, size_t provoking, std::vector<raster::Triangle>& out,
                           Scratch& scratch) {
    const size_t v[3] = {index(i0), index(i1), index(i2)};
    if ((outside_[v[0]] | outside_[v[1]] | outside_[v[2]]) == 0) {
      const bool back = raster::back_facing_triangle(verts_[v[0]].clip, verts_[v[1]].clip, verts_[v[2]].clip, rs);
      if (raster::culled(back, rs)) return;
      const bool use_back = back && rs.two_side;
      if (feedback) {  // each vertex's own colour
        raster::WindowVertex* in = scratch.inside;
        // Mesa's two-side stage takes a triangle of zero area (determinant 0) as front-facing.
        const raster::WindowVertex* wv[3] = {&window_[v[0]], &window_[v[1]], &window_[v[2]]};
        const bool reported_back = use_back && !zero_area(wv);
        for (int k = 0; k < 3; ++k) {
          in[k] = window_[v[k]];
          in[k].color = reported_back ? verts_[v[k]].back : verts_[v[k]].front;
          in[k].sec = reported_back ? verts_[v[k]].back_sec : verts_[v[k]].front_sec;
        }
        return emit_feedback(GL_POLYGON_TOKEN, in, 3, false);
      }
      std::array<raster::SetupVertex, 3> sv;
      for (int k = 0; k < 3; ++k) {
        const raster::Vertex& src = rs.flat ? at(provoking) : verts_[v[k]];  // flat: the provoking colour
        sv[k] = {&window_[v[k]], use_back ? &src.back : &src.front, use_back ? &src.back_sec : &src.front_sec};
      }
      raster::Triangle t;
      if (raster::setup(sv, rs, t)) out.push_back(t);
      return;
    }
    for (int k = 0; k < 3; ++k) scratch.prim[k] = verts_[v[k]];
    const raster::WindowPolygon w = raster::clip_and_map(scratch.prim, 3, rs, &at(provoking), false, nullptr, feedback ? &clip_temps_ : nullptr);
    if (feedback && clip_temps_.read_unwritten) deviations_.insert(kClipTempsUnwritten);
    if (w.empty()) return;
    if (feedback) return emit_feedback(GL_POLYGON_TOKEN, w.begin(), w.size(), true);
    raster::Triangle t;
    for (size_t k = 1; k + 1 < w.size(); ++k)
      if (raster::setup(w[k], w[k + 1], w[0], rs, t)) out.push_back(t);
  };
  Scratch scratch;
  auto emit = [&](std::initializer_list<size_t> idx, size_t provoking, GLenum kind) {
    const size_t* i = idx.begin();
    if (kind == GL_POLYGON_TOKEN) return emit_triangle(i[0], i[1], i[2], provoking, tris, scratch);
    prim.clear();
    for (size_t k : idx) prim.push_back(at(k));
    const bool is_point = kind == GL_POINT_TOKEN;
    if (is_point) prim.push_back(prim[0]);  // a point clips like a degenerate line
    // Feedback reports each vertex's own colour (Mesa does not flatten there), but for the ends
    // that clipping makes (clip_and_map).
    const raster::WindowPolygon w = raster::clip_and_map(prim.begin(), 2, rs, &at(provoking), true, nullptr, feedback ? &clip_temps_ : nullptr);
    if (feedback && clip_temps_.read_unwritten) deviations_.insert(kClipTempsUnwritten);
    if (w.empty()) return;
    if (feedback) return emit_feedback(kind, w.begin(), w.size(), true);
    if (is_point) {
      flush_clear();
      raster::draw_point(fb_, w[0], rs);
    } else {
      flush_clear();
      raster::draw_line(fb_, w[0], w[1], rs);
    }
  };

  const size_t n = elements_.empty() ? verts_.size() : elements_.size();
  switch (prim_mode_) {
    case GL_POINTS:
      for (size_t i = 0; i < n; ++i) emit({i}, i, GL_POINT_TOKEN);
      break;
    case GL_LINES:
      for (size_t i = 0; i + 1 < n; i += 2) emit({i, i + 1}, i + 1, GL_LINE_TOKEN);
      break;
    case GL_LINE_STRIP:
    case GL_LINE_LOOP:
      for (size_t i = 0; i + 1 < n; ++i) emit({i, i + 1}, i + 1, GL_LINE_TOKEN);
      if (prim_mode_ == GL_LINE_LOOP && n >= 2) emit({n - 1, 0}, 0, GL_LINE_TOKEN);
      break;
    case GL_TRIANGLES:
      if (!feedback && threads_ > 1 && n >= 3 * 4096) {
        // Assembly and setup split in contiguous ranges, one per thread; the rasterizer takes
        // the ranges in order, so the picture is the same as from one thread.
        raster::Workers& w = workers();
        const size_t count = n / 3, parts = size_t(w.size());
        tri_parts_.resize(parts - 1);
        w.run([&](int share) {
          const size_t p = size_t(share);
          Scratch local;
          std::vector<raster::Triangle>& out = p == 0 ? tris : tri_parts_[p - 1];
          if (p > 0) out.clear();
          for (size_t t = count * p / parts; t < count * (p + 1) / parts; ++t)
            emit_triangle(3 * t, 3 * t + 1, 3 * t + 2, 3 * t + 2, out, p == 0 ? scratch : local);
        });
        const std::vector<raster::Triangle>* lists[raster::Workers::kMax] = {&tris};
        for (size_t p = 1; p < parts; ++p) lists[p] = &tri_parts_[p - 1];
        flush_clear();
        raster::draw_triangles(fb_, lists, parts, rs, w);
        verts_.clear();
        return;
      }
      for (size_t i = 0; i + 2 < n; i += 3) emit({i, i + 1, i + 2}, i + 2, GL_POLYGON_TOKEN);
      break;
    case GL_TRIANGLE_STRIP:
      for (size_t i = 0; i + 2 < n; ++i)
        if (i % 2 == 0) emit({i, i + 1, i + 2}, i + 2, GL_POLYGON_TOKEN);
        else emit({i + 1, i, i + 2}, i + 2, GL_POLYGON_TOKEN);
      break;
    case GL_TRIANGLE_FAN:
      for (size_t i = 1; i + 1 < n; ++i) emit({0, i, i + 1}, i + 1, GL_POLYGON_TOKEN);
      break;
    // Mesa splits quads and polygons one way when drawing and another in feedback (measured with
    // Mesa 22.3 in tests/raster/prims_test.cpp). Drawing smooth, the quad (q0, q1, q2, q3) is the
    // fan (q0, q1, q2), (q0, q2, q3); feedback, and drawing flat quads, take the draw module's
    // decomposition for the last vertex provoking: (q0, q1, q3), (q1, q2, q3); feedback gives a
    // polygon's fan with its first vertex last. GL 2.1 leaves the split open (section 2.6.1).
    // A draw with any vertex outside the view volume runs the draw module's pipeline (its clipper)
    // for all of its primitives, and so takes that decomposition too, drawing smooth.
    case GL_QUADS:  // the 4th vertex provokes
      for (size_t i = 0; i + 3 < n; i += 4) {
        if (feedback || rs.flat || any_outside) {
          emit({i, i + 1, i + 3}, i + 3, GL_POLYGON_TOKEN);
          emit({i + 1, i + 2, i + 3}, i + 3, GL_POLYGON_TOKEN);
        } else {
          emit({i, i + 1, i + 2}, i + 3, GL_POLYGON_TOKEN);
          emit({i, i + 2, i + 3}, i + 3, GL_POLYGON_TOKEN);
        }
      }
      break;
    case GL_QUAD_STRIP:  // quad (2i, 2i+1, 2i+3, 2i+2), as Mesa's feedback (2i+2, 2i, 2i+1, 2i+3); 2i+3 provokes
      for (size_t i = 0; i + 3 < n; i += 2) {
        if (feedback || any_outside) {
          emit({i + 2, i, i + 3}, i + 3, GL_POLYGON_TOKEN);
          emit({i, i + 1, i + 3}, i + 3, GL_POLYGON_TOKEN);
        } else {
          emit({i, i + 1, i + 3}, i + 3, GL_POLYGON_TOKEN);
          emit({i, i + 3, i + 2}, i + 3, GL_POLYGON_TOKEN);
        }
      }
      break;
    case GL_POLYGON:  // a fan from the first vertex, which provokes
      for (size_t i = 1; i + 1 < n; ++i)
        if (feedback) emit({i, i + 1, 0}, 0, GL_POLYGON_TOKEN);
        else emit({0, i, i + 1}, 0, GL_POLYGON_TOKEN);
      break;
  }
  const std::vector<raster::Triangle>* list = &tris;
  if (!tris.empty()) {
    flush_clear();
    raster::draw_triangles(fb_, &list, 1, rs, workers());
  }
  verts_.clear();
}

// ---------------------------------------------------------------- feedback and read-back

// Fed-back texture coordinates are the current ones: texture generation is not modelled.
void Context::note_texgen_in_feedback() {
  if (feedback_type_ != GL_3D_COLOR_TEXTURE && feedback_type_ != GL_4D_COLOR_TEXTURE) return;
  for (GLenum gen : {GL_TEXTURE_GEN_S, GL_TEXTURE_GEN_T, GL_TEXTURE_GEN_R, GL_TEXTURE_GEN_Q})
    if (enabled_state(gen) == 1) deviations_.insert(kTexGen);
}

void Context::feedback_put(double x) {
  if (feedback_count_ < feedback_size_) feedback_[feedback_count_] = GLfloat(x);
  else feedback_overflow_ = true;
  ++feedback_count_;
}

void Context::FeedbackBuffer(GLsizei size, GLenum type, GLfloat* buffer) {
  // Mesa's order (feedback.c): feedback mode, the size, a null buffer, then the type.
  if (!outside_begin_end()) return;
  if (render_mode_ == GL_FEEDBACK) return error(GL_INVALID_OPERATION);
  if (size < 0) return error(GL_INVALID_VALUE);
  if (!buffer && size > 0) return error(GL_INVALID_VALUE);
  if (type != GL_2D && type != GL_3D && type != GL_3D_COLOR && type != GL_3D_COLOR_TEXTURE &&
      type != GL_4D_COLOR_TEXTURE)
    return error(GL_INVALID_ENUM);
  feedback_ = buffer, feedback_size_ = size, feedback_type_ = type;
}

GLint Context::RenderMode(GLenum mode) {
  if (!outside_begin_end()) return 0;
  if (mode != GL_RENDER && mode != GL_FEEDBACK && mode != GL_SELECT) return error(GL_INVALID_ENUM), 0;
  // Feedback needs a buffer of non-zero size; selection a glSelectBuffer, which ours does not
  // provide. Mesa records GL_INVALID_OPERATION and then switches the mode all the same; ours
  // stays in its mode, as GL 2.1 section 2.5 says.
  if (mode == GL_FEEDBACK && feedback_size_ == 0) return error(GL_INVALID_OPERATION), 0;
  if (mode == GL_SELECT) return error(GL_INVALID_OPERATION), 0;
  GLint result = 0;
  if (render_mode_ == GL_FEEDBACK) result = feedback_overflow_ ? -1 : feedback_count_;
  render_mode_ = mode;
  feedback_count_ = 0;
  feedback_overflow_ = false;
  return result;
}

void Context::PixelStorei(GLenum pname, GLint param) {
  if (!outside_begin_end()) return;
  switch (pname) {
    case GL_PACK_ALIGNMENT: case GL_UNPACK_ALIGNMENT:
      if (param != 1 && param != 2 && param != 4 && param != 8) return error(GL_INVALID_VALUE);
      (pname == GL_PACK_ALIGNMENT ? pack_alignment_ : unpack_alignment_) = param;
      return;
    case GL_PACK_SWAP_BYTES: case GL_PACK_LSB_FIRST: case GL_UNPACK_SWAP_BYTES: case GL_UNPACK_LSB_FIRST:
      pixel_store_[pname] = param != 0;
      return;
    case GL_PACK_ROW_LENGTH: case GL_PACK_IMAGE_HEIGHT: case GL_PACK_SKIP_ROWS: case GL_PACK_SKIP_PIXELS:
    case GL_PACK_SKIP_IMAGES: case GL_UNPACK_ROW_LENGTH: case GL_UNPACK_IMAGE_HEIGHT: case GL_UNPACK_SKIP_ROWS:
    case GL_UNPACK_SKIP_PIXELS: case GL_UNPACK_SKIP_IMAGES:
      // Recorded and reported; glReadPixels honours the GL_PACK_* ones (read_pixels.cpp).
      if (param < 0) return error(GL_INVALID_VALUE);
      pixel_store_[pname] = param;
      return;
  }
  error(GL_INVALID_ENUM);
}

void Context::ReadPixels(GLint x, GLint y, GLsizei w, GLsizei h, GLenum format, GLenum type, void* pixels) {
  if (!outside_begin_end()) return;
  validate_matrices();
  if (w < 0 || h < 0) return error(GL_INVALID_VALUE);  // Mesa checks the size before the format
  if (const GLenum e = read_pixels_error(format, type)) return error(e);
  flush_clear();
  auto store = [this](GLenum p) {
    const auto it = pixel_store_.find(p);
    return it == pixel_store_.end() ? 0 : it->second;
  };
  PackState pack;
  pack.alignment = pack_alignment_;
  pack.row_length = store(GL_PACK_ROW_LENGTH), pack.skip_rows = store(GL_PACK_SKIP_ROWS);
  pack.skip_pixels = store(GL_PACK_SKIP_PIXELS), pack.swap_bytes = store(GL_PACK_SWAP_BYTES) != 0;
  pack_pixels(fb_, x, y, w, h, format, type, pack, pixels);
}

const GLubyte* Context::GetString(GLenum name) {
  if (!outside_begin_end()) return nullptr;
  switch (name) {
    case GL_VENDOR: return reinterpret_cast<const GLubyte*>("ffcompat");
    case GL_RENDERER: return reinterpret_cast<const GLubyte*>("ffcompat soft (fixed-function)");
    case GL_VERSION: return reinterpret_cast<const GLubyte*>("2.1 ffcompat");
    case GL_EXTENSIONS: return reinterpret_cast<const GLubyte*>("");
    case GL_SHADING_LANGUAGE_VERSION: return reinterpret_cast<const GLubyte*>("1.20");  // GL 2.1's
  }
  error(GL_INVALID_ENUM);
  return nullptr;
}

}  // namespace ffc::state
