// The per-fragment operations' state (GL 2.1 sections 4.1.2 to 4.1.8 and 4.2.2): glScissor,
// glAlphaFunc, glBlendFunc(Separate), glBlendEquation(Separate), glBlendColor, glColorMask and
// glDepthMask, with Mesa 22.3's errors and glGet values, what the rasterizer is handed of them
// (raster::State::Ops) and glClear under the masks and the scissor box.
#include <algorithm>

#include "state/context.h"
#include "state/gl_rules.h"

namespace ffc::state {

namespace {

// The blend factors Mesa's blend.c accepts on a desktop context with ARB_blend_func_extended
// (llvmpipe has it): GL 1.4's fifteen, GL_SRC_ALPHA_SATURATE as a destination factor too, and the
// dual-source ones (accepted; with no second colour output in the fixed-function pipeline they
// are drawn as GL_ZERO, see raster/fragment_ops.cpp).
bool valid_factor(GLenum f) {
  switch (f) {
    case GL_ZERO: case GL_ONE: case GL_SRC_COLOR: case GL_ONE_MINUS_SRC_COLOR: case GL_DST_COLOR:
    case GL_ONE_MINUS_DST_COLOR: case GL_SRC_ALPHA: case GL_ONE_MINUS_SRC_ALPHA: case GL_DST_ALPHA:
    case GL_ONE_MINUS_DST_ALPHA: case GL_SRC_ALPHA_SATURATE: case GL_CONSTANT_COLOR:
    case GL_ONE_MINUS_CONSTANT_COLOR: case GL_CONSTANT_ALPHA: case GL_ONE_MINUS_CONSTANT_ALPHA:
    case 0x88F9 /* GL_SRC1_COLOR */: case 0x8589 /* GL_SRC1_ALPHA */: case 0x88FA /* GL_ONE_MINUS_SRC1_COLOR */:
    case 0x88FB /* GL_ONE_MINUS_SRC1_ALPHA */:
      return true;
    default: return false;
  }
}

bool valid_equation(GLenum e) {
  return e == GL_FUNC_ADD || e == GL_FUNC_SUBTRACT || e == GL_FUNC_REVERSE_SUBTRACT || e == GL_MIN || e == GL_MAX;
}

}  // namespace

// Every setter here flushes stored vertices only when it changes the state (Context::changes), as
// Mesa's blend.c, depth.c, lines.c and scissor.c do; the alpha reference and the blend colour are
// compared as given, before clamping, as Mesa compares them.
void Context::AlphaFunc(GLenum func, GLfloat ref) {
  if (!outside_begin_end_keeping_vertices()) return;
  if (func < GL_NEVER || func > GL_ALWAYS) return error(GL_INVALID_ENUM);
  if (!changes(frag_.alpha_func != func || !(frag_.alpha_ref_given == ref))) return;
  frag_.alpha_func = func;
  frag_.alpha_ref = clamp01(ref), frag_.alpha_ref_given = ref;
}

void Context::BlendFuncSeparate(GLenum src_rgb, GLenum dst_rgb, GLenum src_alpha, GLenum dst_alpha) {
  if (!outside_begin_end_keeping_vertices()) return;
  if (!valid_factor(src_rgb) || !valid_factor(dst_rgb) || !valid_factor(src_alpha) || !valid_factor(dst_alpha))
    return error(GL_INVALID_ENUM);
  if (!changes(frag_.src_rgb != src_rgb || frag_.dst_rgb != dst_rgb || frag_.src_alpha != src_alpha || frag_.dst_alpha != dst_alpha))
    return;
  frag_.src_rgb = src_rgb, frag_.dst_rgb = dst_rgb, frag_.src_alpha = src_alpha, frag_.dst_alpha = dst_alpha;
}

void Context::BlendEquationSeparate(GLenum rgb, GLenum alpha) {
  if (!outside_begin_end_keeping_vertices()) return;
  if (!valid_equation(rgb) || !valid_equation(alpha)) return error(GL_INVALID_ENUM);
  if (!changes(frag_.eq_rgb != rgb || frag_.eq_alpha != alpha)) return;
  frag_.eq_rgb = rgb, frag_.eq_alpha = alpha;
}

void Context::BlendColor(float r, float g, float b, float a) {
  if (!outside_begin_end_keeping_vertices()) return;
  const glm::vec4 given(r, g, b, a);
  if (!changes(frag_.blend_color_given != given)) return;
  frag_.blend_color_given = given;
  frag_.blend_color = glm::vec4(clamp01(r), clamp01(g), clamp01(b), clamp01(a));
}

void Context::ColorMask(bool r, bool g, bool b, bool a) {
  if (!outside_begin_end_keeping_vertices()) return;
  const bool* m = frag_.color_mask;
  if (!changes(m[0] != r || m[1] != g || m[2] != b || m[3] != a)) return;
  frag_.color_mask[0] = r, frag_.color_mask[1] = g, frag_.color_mask[2] = b, frag_.color_mask[3] = a;
}

void Context::DepthMask(bool on) {
  if (!outside_begin_end_keeping_vertices()) return;
  assign(frag_.depth_mask, on);
}

void Context::LineStipple(GLint factor, GLushort pattern) {
  if (!outside_begin_end_keeping_vertices()) return;
  factor = std::clamp(factor, 1, 256);
  if (!changes(frag_.stipple_factor != factor || frag_.stipple_pattern != pattern)) return;
  frag_.stipple_factor = factor;
  frag_.stipple_pattern = pattern;
}

void Context::Scissor(GLint x, GLint y, GLsizei w, GLsizei h) {
  if (!outside_begin_end_keeping_vertices()) return;
  if (w < 0 || h < 0) return error(GL_INVALID_VALUE);
  if (changes(scissor_box() != glm::ivec4(x, y, w, h))) frag_.scissor_box = {x, y, w, h};
}

glm::ivec4 Context::scissor_box() const {
  const glm::ivec4& b = frag_.scissor_box;
  return b[2] < 0 ? glm::ivec4(0, 0, fb_.width, fb_.height) : b;
}

bool* Context::fragment_capability(GLenum cap) {
  switch (cap) {
    case GL_SCISSOR_TEST: return &frag_.scissor_test;
    case GL_ALPHA_TEST: return &frag_.alpha_test;
    case GL_BLEND: return &frag_.blend;
    case GL_LINE_STIPPLE: return &frag_.line_stipple;
    default: return nullptr;
  }
}

int Context::fragment_values(GLenum pname, GLdouble* out, int& normalized) {
  normalized = kRound;
  auto color = [&](const glm::vec4& c) {
    for (int k = 0; k < 4; ++k) out[k] = c[k];
    normalized = kFromFloat;
    return 4;
  };
  switch (pname) {
    case GL_SCISSOR_BOX: {
      const glm::ivec4 b = scissor_box();
      for (int k = 0; k < 4; ++k) out[k] = b[k];
      return 4;
    }
    case GL_ALPHA_TEST_FUNC: out[0] = frag_.alpha_func; return 1;
    case GL_ALPHA_TEST_REF: out[0] = frag_.alpha_ref, normalized = kFromFloat; return 1;
    case GL_BLEND_SRC: case GL_BLEND_SRC_RGB: out[0] = frag_.src_rgb; return 1;
    case GL_BLEND_DST: case GL_BLEND_DST_RGB: out[0] = frag_.dst_rgb; return 1;
    case GL_BLEND_SRC_ALPHA: out[0] = frag_.src_alpha; return 1;
    case GL_BLEND_DST_ALPHA: out[0] = frag_.dst_alpha; return 1;
    case GL_BLEND_EQUATION: out[0] = frag_.eq_rgb; return 1;  // GL_BLEND_EQUATION_RGB
    case GL_BLEND_EQUATION_ALPHA: out[0] = frag_.eq_alpha; return 1;
    case GL_BLEND_COLOR: return color(frag_.blend_color);
    case GL_COLOR_WRITEMASK:
      for (int k = 0; k < 4; ++k) out[k] = frag_.color_mask[k];
      return 4;
    case GL_DEPTH_WRITEMASK: out[0] = frag_.depth_mask; return 1;
    case GL_LINE_STIPPLE_PATTERN: out[0] = frag_.stipple_pattern; return 1;
    case GL_LINE_STIPPLE_REPEAT: out[0] = frag_.stipple_factor; return 1;
    case GL_ATTRIB_STACK_DEPTH: out[0] = double(attrib_stack_.size()); return 1;
    case GL_CLIENT_ATTRIB_STACK_DEPTH: out[0] = double(client_attrib_stack_.size()); return 1;
    default: return 0;
  }
}

bool Context::fragment_ops_default() const {
  raster::State rs;
  fragment_raster_state(rs);
  return !rs.ops.any();
}

void Context::fragment_raster_state(raster::State& rs) const {
  raster::State::Ops& o = rs.ops;
  const glm::ivec4 b = scissor_box();
  // A box that holds the whole window scissors nothing: the fast paths stay open.
  o.scissor = frag_.scissor_test && (b[0] > 0 || b[1] > 0 || int64_t(b[0]) + b[2] < fb_.width ||
                                     int64_t(b[1]) + b[3] < fb_.height);
  o.scissor_x0 = b[0], o.scissor_y0 = b[1];
  o.scissor_x1 = int(std::min<int64_t>(int64_t(b[0]) + b[2], INT32_MAX));
  o.scissor_y1 = int(std::min<int64_t>(int64_t(b[1]) + b[3], INT32_MAX));
  o.alpha_test = frag_.alpha_test && frag_.alpha_func != GL_ALWAYS;
  o.alpha_func = frag_.alpha_func;
  o.alpha_ref = raster::to_unorm8(frag_.alpha_ref);
  o.depth_write = frag_.depth_mask;
  o.blend = frag_.blend;
  o.src_rgb = frag_.src_rgb, o.dst_rgb = frag_.dst_rgb, o.src_alpha = frag_.src_alpha, o.dst_alpha = frag_.dst_alpha;
  o.eq_rgb = frag_.eq_rgb, o.eq_alpha = frag_.eq_alpha;
  for (int k = 0; k < 4; ++k) o.blend_color[k] = raster::to_unorm8(frag_.blend_color[k]);
  rs.line_stipple = frag_.line_stipple;
  rs.stipple_factor = frag_.stipple_factor, rs.stipple_pattern = frag_.stipple_pattern;
  rs.stipple_counter = &stipple_counter_;
  o.color_mask = 0;
  for (int k = 0; k < 4; ++k) o.color_mask |= unsigned(frag_.color_mask[k]) << k;
}

bool Context::clear_with_fragment_ops(GLbitfield mask) {
  raster::State rs;
  fragment_raster_state(rs);
  if (!rs.ops.scissor && rs.ops.color_mask == 0xF && rs.ops.depth_write) return false;
  flush_clear();  // an earlier clear, under its own masks
  raster::ClearRequest c;
  if (mask & GL_COLOR_BUFFER_BIT) c.color = true, c.clear_color = clear_color_;
  if (mask & GL_DEPTH_BUFFER_BIT) c.depth = true, c.clear_depth = clear_depth_;
  raster::clear_masked(fb_, c, rs.ops);
  return true;
}

}  // namespace ffc::state
