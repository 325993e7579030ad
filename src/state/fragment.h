// The state of the per-fragment operations (GL 2.1 sections 4.1.2 to 4.1.8 and 4.2.2): scissor,
// alpha test, blending, the depth and colour write masks, with GL's defaults (tables 6.20 to
// 6.22). One struct, so that glPushAttrib can keep it whole (attrib.cpp).
#pragma once
#include <GL/gl.h>

#include <glm/glm.hpp>

namespace ffc::state {

struct FragmentState {
  bool scissor_test = false, alpha_test = false, blend = false;
  // The scissor box; a width of -1: not set yet, the window's size (Mesa sets the box when the
  // context is first made current).
  glm::ivec4 scissor_box{0, 0, -1, -1};
  GLenum alpha_func = GL_ALWAYS;
  float alpha_ref = 0;  // clamped to [0, 1], as Mesa keeps and reports it for a fixed-point buffer
  float alpha_ref_given = 0;  // as given: Mesa compares a new reference with it (a change flushes)
  GLenum src_rgb = GL_ONE, dst_rgb = GL_ZERO, src_alpha = GL_ONE, dst_alpha = GL_ZERO;
  GLenum eq_rgb = GL_FUNC_ADD, eq_alpha = GL_FUNC_ADD;
  glm::vec4 blend_color{0};  // clamped to [0, 1], as the alpha reference
  glm::vec4 blend_color_given{0};
  bool color_mask[4] = {true, true, true, true};
  bool depth_mask = true;
  // Line stipple (section 3.4.2), rasterization state kept here with the others of this helper.
  bool line_stipple = false;
  GLint stipple_factor = 1;  // clamped to [1, 256]
  GLushort stipple_pattern = 0xFFFF;
};

}  // namespace ffc::state
