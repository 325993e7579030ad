#include "backends/glsl/shader_features.h"

#include <cmath>

#include "raster/raster.h"

namespace ffc::glsl {

void feature_key(ProgramKey& k, const state::SinkState& s) {
  if (s.fog) k.fog = s.fog_mode, k.fog_depth = s.fog_coord_src == GL_FRAGMENT_DEPTH;
  const state::FragmentState* f = s.fragment;
  if (f && f->alpha_test) k.alpha_func = f->alpha_func;
}

namespace {

void add(std::vector<Uniform>& out, const char* name, const char* type, int size, const float* v) {
  Uniform u{name, type, size, {}};
  if (v)
    for (int i = 0; i < size; ++i) u.value[size_t(i)] = v[i];
  out.push_back(u);
}

}  // namespace

void feature_uniforms(const ProgramKey& k, const state::SinkState* s, std::vector<Uniform>& out) {
  if (k.fog) {
    add(out, "u_fog_params", "vec4", 4, s ? &s->fog_params[0] : nullptr);
    add(out, "u_fog_color", "vec3", 3, s ? &s->fog_color[0] : nullptr);
  }
  if (k.alpha_test()) {
    // The reference as the 8-bit value the test compares with (soft's FragmentState::alpha_ref
    // is kept clamped; to_unorm8 rounds it as llvmpipe does).
    const float ref = s && s->fragment ? float(raster::to_unorm8(s->fragment->alpha_ref)) : 0.0f;
    add(out, "u_alpha_ref", "float", 1, s ? &ref : nullptr);
  }
}

std::string fog_vertex_declarations(const ProgramKey& k) { return k.fog ? "out float v_fog;\n" : ""; }

std::string fog_vertex_code(const ProgramKey& k) {
  if (!k.fog) return "";
  // GL_FOG_COORD: the current fog coordinate, which nothing sets here (no glFogCoord): 0, as soft.
  return k.fog_depth ? "  v_fog = abs((u_modelview * a_position).z);\n" : "  v_fog = 0.0;\n";
}

std::string feature_fragment_declarations(const ProgramKey& k, bool uniforms) {
  std::string d = k.fog ? "in float v_fog;\n" : "";
  if (!uniforms) return d;
  std::vector<Uniform> us;
  feature_uniforms(k, nullptr, us);
  for (const Uniform& u : us) d += std::string("uniform ") + u.type + " " + u.name + ";\n";
  return d;
}

std::string feature_fragment_code(const ProgramKey& k) {
  std::string c;
  if (k.fog) {
    c += "  {  // fog: the factor from the interpolated coordinate, then rgb towards the fog colour\n";
    if (k.fog == GL_LINEAR) c += "    float f = v_fog * u_fog_params.x + u_fog_params.y;\n";
    else if (k.fog == GL_EXP) c += "    float f = exp2(-(v_fog * u_fog_params.z));\n";
    else c += "    float t = v_fog * u_fog_params.w;\n    float f = exp2(-(t * t));\n";
    c += "    f = isnan(f) ? 0.0 : clamp(f, 0.0, 1.0);\n";
    c += "    o_color.rgb = u_fog_color * (1.0 - f) + o_color.rgb * f;\n  }\n";
  }
  if (k.alpha_test()) {
    static const char* const ops[8] = {"false", "a < u_alpha_ref", "a == u_alpha_ref", "a <= u_alpha_ref",
                                       "a > u_alpha_ref", "a != u_alpha_ref", "a >= u_alpha_ref", "true"};
    const unsigned i = k.alpha_func - GL_NEVER;
    // The alpha at the buffer's 8 bits, rounded half to even as llvmpipe converts it.
    c += "  {  // the alpha test\n    float a = roundEven(clamp(o_color.a, 0.0, 1.0) * 255.0);\n";
    c += std::string("    if (!(") + (i < 8 ? ops[i] : "true") + ")) discard;\n  }\n";
  }
  return c;
}

}  // namespace ffc::glsl
