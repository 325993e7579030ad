#include "backends/glsl/shader_gen.h"

#include <GL/gl.h>

#include <cmath>
#include <cstdio>
#include <glm/gtc/type_ptr.hpp>

#include "backends/glsl/shader_features.h"
#include "backends/glsl/points.h"
#include "backends/glsl/unfilled.h"

namespace ffc::glsl {

namespace {

bool tracks(const ProgramKey& k, int face, GLenum what) {
  if (!(k.cm_faces >> face & 1)) return false;
  return k.cm_mode == what || (k.cm_mode == GL_AMBIENT_AND_DIFFUSE && (what == GL_AMBIENT || what == GL_DIFFUSE));
}

std::string light_name(int i, const char* field) { return "u_light" + std::to_string(i) + "_" + field; }
const char* face_name(int f) { return f == 0 ? "front" : "back"; }

// The half vector of a directional light seen from an infinite viewer is the same for every vertex.
bool constant_half(const ProgramKey& k, int i) { return !k.key.local(i) && !k.key.local_viewer(); }

struct UniformList {
  const state::SinkState* s;
  std::vector<Uniform> out;
  void add(const std::string& name, const char* type, int size, const float* v) {
    Uniform u{name, type, size, {}};
    if (s && v)
      for (int k = 0; k < size; ++k) u.value[size_t(k)] = v[k];
    out.push_back(u);
  }
  void vec3(const std::string& name, const glm::dvec3& v) {
    const glm::vec3 f(v);
    add(name, "vec3", 3, glm::value_ptr(f));
  }
  void vec4(const std::string& name, const glm::dvec4& v) {
    const glm::vec4 f(v);
    add(name, "vec4", 4, glm::value_ptr(f));
  }
  void scalar(const std::string& name, double v) {
    const float f = float(v);
    add(name, "float", 1, &f);
  }
};

}  // namespace

ProgramKey ProgramKey::of(const state::SinkState& s, bool phong) {
  ProgramKey k;
  k.lit = s.lighting;
  k.vertex_material = s.lighting && s.vertex_materials;
  unfilled_key(k, s);
  // GL_FLAT keeps one colour per primitive; a material per vertex stays per vertex.
  k.phong = phong && s.lighting && !s.flat && !k.vertex_material && !k.unfilled;
  k.key = s.lighting ? s.key : lighting::Key{};
  k.flat = s.flat;
  if (k.lit && k.key.color_material()) k.cm_faces = unsigned(s.model.cm_faces), k.cm_mode = s.model.cm_mode;
  feature_key(k, s);
  return k;
}

uint64_t ProgramKey::packed() const {
  // Only the bits a program's code depends on: the shininess-0 bit changes no code here.
  const uint64_t extra = key.extra & ~(1u << lighting::Key::kShininessZero);
  // Colour material's mode and fog's mode as small numbers (0 for none).
  const GLenum cm_modes[] = {GL_AMBIENT, GL_DIFFUSE, GL_SPECULAR, GL_EMISSION, GL_AMBIENT_AND_DIFFUSE};
  uint64_t cm = 0;
  for (uint64_t i = 0; i < 5; ++i)
    if (cm_mode == cm_modes[i]) cm = i + 1;
  const uint64_t fog_mode = fog == GL_LINEAR ? 1 : fog == GL_EXP ? 2 : fog == GL_EXP2 ? 3 : 0;
  return uint64_t(key.bits) | extra << 32 | uint64_t(lit) << 42 | uint64_t(flat) << 43 | uint64_t(cm_faces & 3) << 44 |
         cm << 46 | uint64_t(phong) << 49 | fog_mode << 50 | uint64_t(fog_depth) << 52 |
         uint64_t((alpha_func - GL_NEVER) & 7) << 53 | uint64_t(vertex_material) << 56 |
         uint64_t(unfilled == GL_LINE ? 1 : unfilled == GL_POINT ? 2 : 0) << 57 | uint64_t(unfilled_faces & 3) << 59 |
         uint64_t(front_cw) << 61 | uint64_t(points) << 62;
}

bool ProgramKey::needs_eye_position() const {
  if (!lit) return false;
  if (phong) return true;
  if (key.local_viewer()) return true;
  for (int i = 0; i < 8; ++i)
    if (key.enabled(i) && key.local(i)) return true;
  return false;
}

std::vector<Uniform> uniforms(const ProgramKey& k, const state::SinkState* s) {
  UniformList u{s, {}};
  u.add("u_mvp", "mat4", 16, s ? glm::value_ptr(s->mvp) : nullptr);
  if (k.needs_eye_position() || (k.fog && k.fog_depth))
    u.add("u_modelview", "mat4", 16, s ? glm::value_ptr(s->modelview) : nullptr);
  feature_uniforms(k, s, u.out);
  point_uniforms(k, s, u.out);
  if (!k.lit) return u.out;
  const glm::mat3 inv = s ? glm::mat3(s->normal_inverse) : glm::mat3(1);
  u.add("u_normal_inverse", "mat3", 9, glm::value_ptr(inv));
  if (k.key.rescale() && !k.key.normalize()) u.scalar("u_rescale", s ? s->rescale : 0);
  u.vec3("u_global_ambient", s ? glm::dvec3(s->model.ambient) : glm::dvec3(0));
  const int faces = k.two_side() ? 2 : 1;
  for (int f = 0; f < faces && !k.vertex_material; ++f) {
    const lighting::MaterialParams m = s ? s->materials[f] : lighting::MaterialParams{};
    const std::string p = std::string("u_") + face_name(f) + "_";
    if (!tracks(k, f, GL_AMBIENT)) u.vec3(p + "ambient", m.ambient);
    if (!tracks(k, f, GL_DIFFUSE)) u.vec4(p + "diffuse", m.diffuse);
    if (k.key.specular() && !tracks(k, f, GL_SPECULAR)) u.vec3(p + "specular", m.specular);
    if (!tracks(k, f, GL_EMISSION)) u.vec3(p + "emission", m.emission);
    if (k.key.specular()) u.scalar(p + "shininess", m.shininess);
  }
  int n = 0;  // the enabled lights, in order, as prepare() packs them
  for (int i = 0; i < 8; ++i) {
    if (!k.key.enabled(i)) continue;
    const lighting::LightParams l = s ? s->lights[i] : lighting::LightParams{};
    u.vec3(light_name(n, "ambient"), l.ambient);
    u.vec3(light_name(n, "diffuse"), l.diffuse);
    if (k.key.specular()) u.vec3(light_name(n, "specular"), l.specular);
    // Local: the eye-space position with w divided out; directional: the unit direction to it.
    glm::dvec3 pos(l.position);
    if (k.key.local(i)) pos /= l.position.w;
    else if (glm::length(pos) > 0) pos /= glm::length(pos);
    u.vec3(light_name(n, "position"), pos);
    if (k.key.specular() && constant_half(k, i)) {
      const glm::dvec3 h = glm::dvec3(glm::vec3(pos)) + glm::dvec3(0, 0, 1);
      u.vec3(light_name(n, "half"), glm::length(h) > 0 ? h / glm::length(h) : h);
    }
    if (k.key.spot(i)) {
      const double len = glm::length(l.spot_direction);
      u.vec3(light_name(n, "spot_direction"), len > 0 ? l.spot_direction / len : glm::dvec3(0));
      // cos 90 is 0 exactly, as in prepare(): a vertex on a 90-degree cone's boundary is lit.
      u.scalar(light_name(n, "spot_cos"), l.spot_cutoff == 90 ? 0.0 : std::cos(l.spot_cutoff * M_PI / 180));
      u.scalar(light_name(n, "spot_exponent"), l.spot_exponent);
    }
    if (k.key.attenuated(i))
      u.vec3(light_name(n, "attenuation"),
             glm::dvec3(l.constant_attenuation, l.linear_attenuation, l.quadratic_attenuation));
    ++n;
  }
  return u.out;
}

namespace {

// One face's colour: emission and the scene's ambient, then each enabled light's term.
std::string face_code(const ProgramKey& k, int f) {
  const lighting::Key& key = k.key;
  const std::string p = std::string("u_") + face_name(f) + "_";
  // A material parameter: the colour when colour material tracks it, else its uniform or, when
  // the material comes per vertex, its attribute (a vec4 each).
  const std::string src = k.vertex_material ? std::string("a_") + face_name(f) + "_" : p;
  auto mat = [&](GLenum what, const char* name) {
    return tracks(k, f, what) ? std::string("a_color.rgb")
                              : src + name + (what == GL_DIFFUSE || k.vertex_material ? ".rgb" : "");
  };
  const std::string shininess = k.vertex_material ? src + "ambient.a" : p + "shininess";
  std::string c;
  c += "  {  // the " + std::string(face_name(f)) + " face\n";
  c += std::string("    vec3 n = ") + (f == 0 ? "normal" : "-normal") + ";\n";
  c += "    vec3 ma = " + mat(GL_AMBIENT, "ambient") + ", md = " + mat(GL_DIFFUSE, "diffuse") + ";\n";
  if (key.specular()) c += "    vec3 ms = " + mat(GL_SPECULAR, "specular") + ";\n";
  c += "    vec3 color = " + mat(GL_EMISSION, "emission") + " + ma * u_global_ambient;\n";
  if (k.secondary()) c += "    vec3 secondary = vec3(0.0);\n";
  int n = 0;
  for (int i = 0; i < 8; ++i) {
    if (!key.enabled(i)) continue;
    auto L = [&](const char* field) { return light_name(n, field); };
    c += "    {  // light " + std::to_string(i) + (key.local(i) ? ", local" : ", directional") +
         (key.spot(i) ? ", spot" : "") + (key.attenuated(i) ? ", attenuated" : "") + "\n";
    c += "      vec3 vp = " + L("position") + ";\n      float att = 1.0;\n";
    if (key.local(i)) {
      c += "      vec3 d = " + L("position") + " - eye;\n      float dist = length(d);\n";
      c += "      vp = dist > 0.0 ? d / dist : vec3(0.0);\n";
      if (key.attenuated(i))
        c += "      att = 1.0 / (" + L("attenuation") + ".x + " + L("attenuation") + ".y * dist + " + L("attenuation") +
             ".z * dist * dist);\n";
    }
    std::string indent = "      ";
    if (key.spot(i)) {
      c += "      float cos_angle = dot(-vp, " + L("spot_direction") + ");\n";
      c += "      if (cos_angle >= " + L("spot_cos") + ") {  // inside the cone; outside it, no term at all\n";
      c += "        att *= power(max(0.0, cos_angle), " + L("spot_exponent") + ");\n";
      indent = "        ";
    }
    c += indent + "float nl = dot(n, vp);\n";
    c += indent + "vec3 sum = " + L("ambient") + " * ma + max(0.0, nl) * (" + L("diffuse") + " * md);\n";
    if (key.specular()) {
      c += indent + "if (nl > 0.0) {\n";
      if (constant_half(k, i)) {
        c += indent + "  vec3 h = " + L("half") + ";\n";
      } else {
        c += indent + "  vec3 h = vp + to_eye;\n";
        c += indent + "  float hl = length(h);\n";
        c += indent + "  h = hl > 0.0 ? h / hl : vec3(0.0);\n";
      }
      c += indent + "  vec3 s = power(max(0.0, dot(n, h)), " + shininess + ") * (" + L("specular") + " * ms);\n";
      c += indent + (k.secondary() ? "  secondary += att * s;\n" : "  sum += s;\n");
      c += indent + "}\n";
    }
    c += indent + "color += att * sum;\n";
    if (key.spot(i)) c += "      }\n";
    c += "    }\n";
    ++n;
  }
  const std::string alpha = tracks(k, f, GL_DIFFUSE) ? "a_color.a" : src + "diffuse.a";
  c += std::string("    v_") + face_name(f) + " = saturate(vec4(color, " + alpha + "));\n";
  if (k.secondary()) c += std::string("    v_") + face_name(f) + "_secondary = saturate(vec4(secondary, 0.0));\n";
  c += "  }\n";
  return c;
}

}  // namespace

namespace {

std::string header(const ProgramKey& k) {
  char b[64];
  std::snprintf(b, sizeof b, "%08x/%03x", k.key.bits, k.key.extra);
  return std::string("#version 330 core\n// ffcompat: generated from lighting key ") + b +
         (k.lit ? ", lighting on" : ", lighting off") + (k.flat ? ", GL_FLAT" : ", GL_SMOOTH") +
         (k.phong ? ", per fragment (phong)" : "") + "\n";
}

// The helpers the lighting code calls, and every uniform (a stage ignores those it does not read).
std::string declarations(const ProgramKey& k) {
  std::string d;
  for (const Uniform& u : uniforms(k, nullptr)) d += std::string("uniform ") + u.type + " " + u.name + ";\n";
  // Clamped to [0, 1]; a NaN to 1, as the fixed-function clamp does.
  d += "vec4 saturate(vec4 c) {\n"
       "  return mix(clamp(c, 0.0, 1.0), vec4(1.0), isnan(c));\n"
       "}\n";
  bool spot = false;
  for (int i = 0; i < 8; ++i) spot |= k.key.enabled(i) && k.key.spot(i);
  if (k.lit && (k.key.specular() || spot))
    // pow(x, 0) is 1 for every x, and pow(0, e > 0) is 0, as C's pow: GLSL leaves both open.
    d += "float power(float x, float e) {\n"
         "  return e == 0.0 ? 1.0 : x <= 0.0 ? 0.0 : pow(x, e);\n"
         "}\n";
  return d;
}

// The eye-space normal from a_normal (normalized or rescaled as the key says).
std::string eye_normal(const ProgramKey& k) {
  // A row vector times M^-1: the normal by the inverse transpose of the modelview.
  std::string c = "  vec3 normal = a_normal * u_normal_inverse;\n";
  if (k.key.normalize()) c += "  float len = length(normal);\n  normal = len > 0.0 ? normal / len : normal;\n";
  else if (k.key.rescale()) c += "  normal /= u_rescale;\n";
  return c;
}

// The lighting of both faces from `eye` and `normal`, into v_front (v_back, the secondaries).
std::string lighting_code(const ProgramKey& k) {
  std::string c;
  if (k.key.local_viewer())
    c += "  float eye_len = length(eye);\n  vec3 to_eye = eye_len > 0.0 ? -eye / eye_len : vec3(0.0);\n";
  else
    c += "  const vec3 to_eye = vec3(0.0, 0.0, 1.0);\n";
  c += face_code(k, 0);
  if (k.two_side()) c += face_code(k, 1);
  return c;
}

std::vector<std::string> colour_varyings(const ProgramKey& k) {
  std::vector<std::string> outs = {"v_front"};
  if (k.two_side()) outs.push_back("v_back");
  if (k.secondary()) {
    outs.push_back("v_front_secondary");
    if (k.two_side()) outs.push_back("v_back_secondary");
  }
  return outs;
}

// The fragment's colour from v_front (v_back, the secondaries), varyings or locals.
std::string colour_sum(const ProgramKey& k) {
  std::string fr = k.two_side() ? "  o_color = gl_FrontFacing ? v_front : v_back;\n" : "  o_color = v_front;\n";
  if (k.secondary()) {
    // The colour sum (GL 2.1 section 3.9): the secondary colour's rgb added after interpolation.
    fr += k.two_side() ? "  vec4 secondary = gl_FrontFacing ? v_front_secondary : v_back_secondary;\n"
                       : "  vec4 secondary = v_front_secondary;\n";
    fr += "  o_color = clamp(o_color + vec4(secondary.rgb, 0.0), 0.0, 1.0);\n";
  }
  return fr;
}

// Per fragment: the vertex shader hands on the eye-space position and normal and the colour; the
// fragment shader runs the same equation on them, interpolated, the normal made unit again.
Sources generate_phong(const ProgramKey& k) {
  Sources s;
  std::string v = header(k) + "layout(location = 0) in vec4 a_position;\nlayout(location = 1) in vec3 a_normal;\n"
                              "layout(location = 2) in vec4 a_color;\n";
  v += declarations(k) + fog_vertex_declarations(k) + "out vec3 v_eye;\nout vec3 v_normal;\nout vec4 v_color;\n";
  v += "void main() {\n  gl_Position = u_mvp * a_position;\n  v_eye = (u_modelview * a_position).xyz;\n";
  v += eye_normal(k) + "  v_normal = normal;\n  v_color = a_color;\n" + fog_vertex_code(k) + "}\n";
  std::string fr = header(k) + declarations(k) + feature_fragment_declarations(k, false) +
                   "in vec3 v_eye;\nin vec3 v_normal;\nin vec4 v_color;\n";
  fr += "out vec4 o_color;\nvoid main() {\n  vec3 eye = v_eye;\n  vec3 normal = v_normal;\n  vec4 a_color = v_color;\n";
  // Interpolation shortens unit normals between the vertices: made unit again (Phong's shading).
  fr += "  float len = length(normal);\n  normal = len > 0.0 ? normal / len : normal;\n";
  for (const std::string& o : colour_varyings(k)) fr += "  vec4 " + o + ";\n";
  fr += lighting_code(k) + colour_sum(k) + feature_fragment_code(k) + "}\n";
  s.vertex = v, s.fragment = fr;
  s.feedback = {"gl_Position", "v_color"};
  return s;
}

}  // namespace

Sources generate(const ProgramKey& k) {
  if (k.phong && k.lit) return generate_phong(k);
  Sources s;
  const std::string q = k.flat ? "flat " : "";
  std::string v = header(k) + unfilled_vertex_renames(k, colour_varyings(k)) + point_vertex_renames(k, colour_varyings(k)) + "layout(location = 0) in vec4 a_position;\n";
  if (k.lit) v += "layout(location = 1) in vec3 a_normal;\n";
  if (k.vertex_material)
    for (int f = 0; f < (k.two_side() ? 2 : 1); ++f)
      for (int i = 0; i < 4; ++i) {
        static const char* const names[4] = {"ambient", "diffuse", "specular", "emission"};
        v += "layout(location = " + std::to_string(kMaterial + 4 * f + i) + ") in vec4 a_" + face_name(f) + "_" +
             names[i] + ";\n";
      }
  v += "layout(location = 2) in vec4 a_color;\n" + declarations(k);
  const std::vector<std::string> outs = colour_varyings(k);
  for (const std::string& o : outs) v += q + "out vec4 " + o + ";\n";
  v += fog_vertex_declarations(k) + "void main() {\n  gl_Position = u_mvp * a_position;\n" + fog_vertex_code(k);
  if (!k.lit) {
    v += "  v_front = saturate(a_color);\n}\n";
  } else {
    if (k.needs_eye_position()) v += "  vec3 eye = (u_modelview * a_position).xyz;\n";
    v += eye_normal(k) + lighting_code(k) + "}\n";
  }
  std::string fr = "#version 330 core\n" + feature_fragment_declarations(k, true);
  for (const std::string& o : outs) fr += q + "in vec4 " + o + ";\n";
  fr += "out vec4 o_color;\nvoid main() {\n" + colour_sum(k) + feature_fragment_code(k) + "}\n";
  s.vertex = v, s.fragment = fr;
  s.geometry = k.points ? point_geometry(k, colour_varyings(k)) : unfilled_geometry(k, colour_varyings(k));
  s.feedback = {"gl_Position", "v_front"};
  if (k.two_side()) s.feedback.push_back("v_back");
  return s;
}

}  // namespace ffc::glsl
