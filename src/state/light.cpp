// Lights, materials, the light model and colour material (GL 2.1 section 2.14; Mesa's light.c):
// validation, storage, the glGet of lights and materials, and the lighting constants and key
// prepared from them before a draw (the kernels themselves are in lighting/).
#include <algorithm>
#include <glm/gtc/type_ptr.hpp>

#include "state/context.h"
#include "state/float_matrix.h"
#include "state/gl_rules.h"

namespace ffc::state {

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

// As Mesa's do_light: a parameter is compared with its value (a position or direction once
// transformed) and flushes stored vertices only when it changes.
void Context::set_light(int i, GLenum pname, const double* v) {
  lighting::LightParams& l = lights_[i];
  switch (pname) {
    case GL_AMBIENT: assign(l.ambient, glm::make_vec4(v)); break;
    case GL_DIFFUSE: assign(l.diffuse, glm::make_vec4(v)); break;
    case GL_SPECULAR: assign(l.specular, glm::make_vec4(v)); break;
    case GL_POSITION: assign(l.position, to_eye(v, v[3])); break;
    case GL_SPOT_DIRECTION: assign(l.spot_direction, direction_to_eye(v)); break;
    case GL_SPOT_EXPONENT: assign(l.spot_exponent, v[0]); break;
    case GL_SPOT_CUTOFF: assign(l.spot_cutoff, v[0]); break;
    case GL_CONSTANT_ATTENUATION: assign(l.constant_attenuation, v[0]); break;
    case GL_LINEAR_ATTENUATION: assign(l.linear_attenuation, v[0]); break;
    case GL_QUADRATIC_ATTENUATION: assign(l.quadratic_attenuation, v[0]); break;
  }
  constants_dirty_ = true;
}

void Context::Lightfv(GLenum light, GLenum pname, const GLfloat* params) {
  if (!outside_begin_end_keeping_vertices()) return;
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

// Each parameter flushes stored vertices only when it changes (Mesa's light.c).
void Context::LightModelfv(GLenum pname, const GLfloat* p) {
  if (!outside_begin_end_keeping_vertices()) return;
  switch (pname) {
    case GL_LIGHT_MODEL_AMBIENT:  // compared in float, as Mesa keeps it (the default 0.2 is not 0.2f)
      if (changes(glm::vec4(model_.ambient) != glm::vec4(p[0], p[1], p[2], p[3])))
        model_.ambient = glm::dvec4(p[0], p[1], p[2], p[3]);
      break;
    case GL_LIGHT_MODEL_LOCAL_VIEWER: assign(model_.local_viewer, p[0] != 0); break;
    case GL_LIGHT_MODEL_TWO_SIDE: assign(model_.two_side, p[0] != 0); break;
    case GL_LIGHT_MODEL_COLOR_CONTROL:
      if (p[0] == GL_SINGLE_COLOR) assign(model_.separate_specular, false);
      else if (p[0] == GL_SEPARATE_SPECULAR_COLOR) assign(model_.separate_specular, true);
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
  if (in_begin_ && sink_draws()) sink_material_changes();  // draw_sink.cpp
  leave_triangle_list();  // the vertices so far are lit with the material as it was
  switch (pname) {
    case GL_AMBIENT: case GL_DIFFUSE: case GL_SPECULAR: case GL_EMISSION: case GL_AMBIENT_AND_DIFFUSE:
    case GL_COLOR_INDEXES: break;
    case GL_SHININESS:
      if (v[0] < 0 || v[0] > 128) return error(GL_INVALID_VALUE), false;  // Mesa's test: a NaN passes
      break;
    default: return error(GL_INVALID_ENUM), false;
  }
  // Each face's parameter is an attribute of Mesa's vbo format (MAT_ATTR): one joining inside
  // glBegin/glEnd wraps as a normal or colour joining does (vbo_wrap), so the vertices before it are
  // drawn, and glEnd then finds none stored to ask a flush for. Measured (seed 244949 stream
  // 14039353168182627223, repro material_joins_format_in_begin.txt): a GL_COMPILE_AND_EXECUTE list's
  // glMaterialiv on the executing side inside a wrapped GL_POINTS, then glEnd and a state call: the
  // state call flushes nothing, the material stays in the format, and a glBegin after it copies
  // nothing (glGetMaterialfv inside it reads the material from before).
  if (!spec_) {
    uint32_t joining = 0;
    for (int f = 0; f < 2; ++f) {
      if ((f == 0 && face == GL_BACK) || (f == 1 && face == GL_FRONT)) continue;
      const auto bit = [f](int k) { return 1u << (f * 8 + k); };
      switch (pname) {
        case GL_AMBIENT: joining |= bit(0); break;
        case GL_DIFFUSE: joining |= bit(1); break;
        case GL_SPECULAR: joining |= bit(2); break;
        case GL_EMISSION: joining |= bit(3); break;
        case GL_AMBIENT_AND_DIFFUSE: joining |= bit(0) | bit(1); break;
        case GL_SHININESS: joining |= bit(4); break;
        case GL_COLOR_INDEXES: joining |= bit(5); break;
      }
    }
    if (in_begin_ && (joining & ~material_attrs_)) vbo_wrap(false);
    material_attrs_ |= joining;
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
      material_in_format_ = true;
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
      case GL_SHININESS: m.shininess = v[0], material_in_format_ |= !in_begin_ && !spec_; break;
      case GL_COLOR_INDEXES: color_indexes_[f] = glm::dvec3(v[0], v[1], v[2]); break;
    }
  }
  constants_dirty_ = true;
  // A glMaterial a list runs asks Mesa's vbo for FLUSH_UPDATE_CURRENT as a glColor does, so a
  // glEnable(GL_COLOR_MATERIAL) after it (a FLUSH_CURRENT) leaves a flush of stored vertices asked
  // for, which forgets the list's pending colour at the next vertex list (Context::flush_pending).
  // Measured (seed 173205 stream 10873261804190826188 shrunk, repro list_material_then_pending_colour.txt):
  // glMaterialfv(GL_BACK, GL_SHININESS), glEnable(GL_COLOR_MATERIAL), glColor3fv, then glBegin, glColor3fv,
  // glVertex, glEnd: the current colour after glCallList is the vertex's; without the glMaterialfv,
  // the pending one.
  if (!in_begin_ && !spec_ && lists_.calling && !lists_.replaying_loopback) lists_.need_update = true;
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
  if (!outside_begin_end_keeping_vertices()) return;
  if (!valid_face(face)) return error(GL_INVALID_ENUM);
  if (mode != GL_EMISSION && mode != GL_AMBIENT && mode != GL_DIFFUSE && mode != GL_SPECULAR &&
      mode != GL_AMBIENT_AND_DIFFUSE)
    return error(GL_INVALID_ENUM);
  if (face == cm_face_ && mode == cm_mode_) return;  // as Mesa: no flush, no tracking
  // Mesa's FLUSH_VERTICES comes after the test above. When an earlier FLUSH_CURRENT left it asking
  // for a flush of stored vertices (flush_current), a colour set since is copied and tracked with
  // the mode being replaced, and the format emptied; the new mode then tracks the colour again.
  // The first colour since the format's reset goes to the new mode only (measured:
  // tests/state/color_material_test.cpp, ColorMaterialMeasured).
  flush_vertices();
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
  note_materials_flushed();  // written directly (or by a copy: copy_pending)
}

void Context::copy_pending() {
  mesa_normal_ = normal_, mesa_color_ = color_;
  const bool color_changed = color_ != flushed_color_;
  flushed_color_ = color_;
  for (const PendingMaterial& p : pending_materials_)
    if (*p.dst != p.value) *p.dst = p.value, constants_dirty_ = true;
  if (color_changed) update_color_material();
  note_materials_flushed();
}

// Mesa's FLUSH_CURRENT copies the values set since the last flush and keeps them in its vbo format;
// it then leaves NeedFlush set to ~FLUSH_UPDATE_CURRENT (vbo_exec_FlushVertices_internal), which asks
// for a flush of stored vertices. So the next call that flushes stored vertices (FLUSH_VERTICES:
// nearly every state change, outside_begin_end) copies the format's values again, glMaterial ones
// included, and empties the format, even where no vertex was stored. This explains colour-material
// stream 397 (a glMaterial before glEnable(GL_COLOR_MATERIAL) is copied once more at the next
// glColorMaterial, then tracked over, and never copied again) and why a colour copied by a glGet
// or glGetMaterialfv is tracked with the mode a glColorMaterial replaces.
void Context::flush_current() {
  if (spec_) return;
  if (color_size_ > 0 || normal_in_format_ || !pending_materials_.empty()) vertices_kept_ = true;
  copy_pending();
  // Inside glCallList, a value a list left pending (Context::flush_pending) is copied here as at a
  // vertex list's first flush, and NeedFlush left as ~FLUSH_UPDATE_CURRENT: the next vertex list's
  // FLUSH_FOR_DRAW forgets it. Measured (seed 271828 stream 936, repro list_pending_flushed_by_enable.txt):
  // a list's glColor4fv(0, 0, 0, 0), glEnable(GL_COLOR_MATERIAL), then glBegin, glColor3ub, glVertex,
  // glEnd reads back alpha 1 (the vertex list's), where glEnable(GL_LIGHTING) (no FLUSH_CURRENT)
  // leaves the pending 0.
  if (lists_.calling && lists_.need_update && !lists_.replaying_loopback && !lists_.mesa_inside)
    apply_pending(), lists_.need_update = false, lists_.stored_bit = true;
}

void Context::flush_stored() {
  if (spec_) return;
  copy_pending();
  pending_materials_.clear(), material_in_format_ = false, material_attrs_ = 0;
  color_size_ = color_active_ = 0, normal_in_format_ = false;  // the vbo's vertex format is reset
  format_has_position_ = false;
}
void Context::GetLightfv(GLenum light, GLenum pname, GLfloat* out) {
  if (!query_allowed()) return;
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
  if (in_begin_ && !query_allowed()) return;  // inside a list's wrapped primitive: answered, nothing flushed
  // FLUSH_VERTICES, then FLUSH_CURRENT: copied, kept in the format until the next flush of stored vertices
  if (!in_begin_) outside_begin_end(), flush_current();
  if (face != GL_FRONT && face != GL_BACK) return error(GL_INVALID_ENUM);
  // Inside a list's wrapped primitive Mesa answers from its materials as the last copy left them
  // (mesa_materials_): a glMaterial or a colour tracked by colour material since then is in its vbo.
  // While a list left CurrentExecPrimitive set, as they were then (inside_materials_).
  const lighting::MaterialParams& m = (exec_inside_ ? inside_materials_ : lists_.shown ? mesa_materials_ : materials_)[face == GL_BACK];
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

// ---------------------------------------------------------------- prepared for the vertex stage

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
}  // namespace ffc::state
