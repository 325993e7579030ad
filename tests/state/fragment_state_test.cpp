// The per-fragment operations' state against Mesa 22.3: glBlendFunc(Separate),
// glBlendEquation(Separate), glBlendColor, glAlphaFunc, glColorMask, glDepthMask, glScissor and
// their capabilities, each row's error pinned and every value read back (glGetIntegerv,
// glGetFloatv, glGetBooleanv, glIsEnabled) compared with Mesa's.
#include <algorithm>

#include "harness.h"

namespace ffc::state_test {
namespace {

constexpr GLenum OK = GL_NO_ERROR, IE = GL_INVALID_ENUM, IV = GL_INVALID_VALUE, IO = GL_INVALID_OPERATION;

// Every value of the fragment state, as observed values: each name through three glGets.
void observe_fragment_state() {
  const GLenum names[] = {GL_BLEND_SRC, GL_BLEND_DST, GL_BLEND_SRC_RGB, GL_BLEND_DST_RGB, GL_BLEND_SRC_ALPHA,
                          GL_BLEND_DST_ALPHA, GL_BLEND_EQUATION, GL_BLEND_EQUATION_ALPHA, GL_BLEND_COLOR,
                          GL_ALPHA_TEST_FUNC, GL_ALPHA_TEST_REF, GL_COLOR_WRITEMASK, GL_DEPTH_WRITEMASK,
                          GL_SCISSOR_BOX, GL_BLEND, GL_ALPHA_TEST, GL_SCISSOR_TEST, GL_LINE_STIPPLE,
                          GL_LINE_STIPPLE_PATTERN, GL_LINE_STIPPLE_REPEAT};
  for (GLenum n : names) {
    GLint i[4] = {-7, -7, -7, -7};
    GLfloat f[4] = {-7, -7, -7, -7};
    GLboolean b[4] = {7, 7, 7, 7};
    glGetIntegerv(n, i), glGetFloatv(n, f), glGetBooleanv(n, b);
    for (int k = 0; k < 4; ++k) {
      const std::string label = enum_name(n) + "[" + std::to_string(k) + "]";
      observe("int " + label, i[k]), observe("float " + label, f[k]), observe("bool " + label, b[k]);
    }
  }
  for (GLenum c : {GL_BLEND, GL_ALPHA_TEST, GL_SCISSOR_TEST, GL_LINE_STIPPLE}) observe("enabled " + enum_name(c), glIsEnabled(c));
}

// The call, then the state read back.
Calls then_observe(Calls c) {
  return [c] {
    c();
    observe_fragment_state();
  };
}

class FragmentState : public ::testing::TestWithParam<Case> {};
TEST_P(FragmentState, MatchesMesa) { check_case(GetParam()); }

std::vector<Case> cases() {
  std::vector<Case> v = {
      {"Defaults", nullptr, then_observe([] {}), OK},
      {"BlendFuncSrcAlpha", nullptr, then_observe([] { glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA); }), OK},
      {"BlendFuncSaturateAsDestination", nullptr, then_observe([] { glBlendFunc(GL_ONE, GL_SRC_ALPHA_SATURATE); }), OK},
      {"BlendFuncConstant", nullptr, then_observe([] { glBlendFunc(GL_CONSTANT_COLOR, GL_ONE_MINUS_CONSTANT_ALPHA); }), OK},
      {"BlendFuncDualSource", nullptr, then_observe([] { glBlendFunc(0x88F9 /* GL_SRC1_COLOR */, GL_ONE); }), OK},
      {"BlendFuncBadSource", nullptr, then_observe([] { glBlendFunc(GL_BLEND, GL_ONE); }), IE},
      {"BlendFuncBadDestination", nullptr, then_observe([] { glBlendFunc(GL_ONE, 0x1234); }), IE},
      {"BlendFuncSeparate", nullptr,
       then_observe([] { glBlendFuncSeparate(GL_DST_COLOR, GL_ZERO, GL_ONE, GL_ONE_MINUS_DST_ALPHA); }), OK},
      {"BlendFuncSeparateBadAlpha", nullptr,
       then_observe([] { glBlendFuncSeparate(GL_ONE, GL_ONE, GL_ONE, GL_FRONT); }), IE},
      {"BlendFuncInsideBeginEnd", nullptr, then_observe(inside([] { glBlendFunc(GL_ONE, GL_ONE); })), IO},
      {"BlendEquationMin", nullptr, then_observe([] { glBlendEquation(GL_MIN); }), OK},
      {"BlendEquationReverse", nullptr, then_observe([] { glBlendEquation(GL_FUNC_REVERSE_SUBTRACT); }), OK},
      {"BlendEquationBad", nullptr, then_observe([] { glBlendEquation(GL_ONE); }), IE},
      {"BlendEquationSeparate", nullptr, then_observe([] { glBlendEquationSeparate(GL_FUNC_SUBTRACT, GL_MAX); }), OK},
      {"BlendEquationSeparateBad", nullptr, then_observe([] { glBlendEquationSeparate(GL_FUNC_ADD, GL_ZERO); }), IE},
      {"BlendColorClamped", nullptr, then_observe([] { glBlendColor(-0.5f, 0.25f, 1.5f, 0.75f); }), OK},
      {"BlendColorInsideBeginEnd", nullptr, then_observe(inside([] { glBlendColor(1, 1, 1, 1); })), IO},
      {"AlphaFuncGreater", nullptr, then_observe([] { glAlphaFunc(GL_GREATER, 0.3f); }), OK},
      {"AlphaFuncRefAboveOne", nullptr, then_observe([] { glAlphaFunc(GL_LEQUAL, 1.5f); }), OK},
      {"AlphaFuncRefBelowZero", nullptr, then_observe([] { glAlphaFunc(GL_NOTEQUAL, -2); }), OK},
      {"AlphaFuncBad", nullptr, then_observe([] { glAlphaFunc(GL_NEVER - 1, 0.5f); }), IE},
      {"AlphaFuncBadAbove", nullptr, then_observe([] { glAlphaFunc(GL_ALWAYS + 1, 0.5f); }), IE},
      {"AlphaFuncInsideBeginEnd", nullptr, then_observe(inside([] { glAlphaFunc(GL_LESS, 0.5f); })), IO},
      {"ColorMask", nullptr, then_observe([] { glColorMask(GL_FALSE, GL_TRUE, GL_FALSE, GL_TRUE); }), OK},
      {"ColorMaskNonzeroIsTrue", nullptr, then_observe([] { glColorMask(2, 0, 255, 0); }), OK},
      {"ColorMaskInsideBeginEnd", nullptr, then_observe(inside([] { glColorMask(0, 0, 0, 0); })), IO},
      {"DepthMask", nullptr, then_observe([] { glDepthMask(GL_FALSE); }), OK},
      {"DepthMaskInsideBeginEnd", nullptr, then_observe(inside([] { glDepthMask(GL_FALSE); })), IO},
      {"Scissor", nullptr, then_observe([] { glScissor(1, 2, 3, 4); }), OK},
      {"ScissorNegativeCorner", nullptr, then_observe([] { glScissor(-5, -6, 100, 200); }), OK},
      {"ScissorNegativeWidth", nullptr, then_observe([] { glScissor(0, 0, -1, 4); }), IV},
      {"ScissorNegativeHeight", nullptr, then_observe([] { glScissor(0, 0, 4, -1); }), IV},
      {"ScissorInsideBeginEnd", nullptr, then_observe(inside([] { glScissor(1, 1, 1, 1); })), IO},
      {"LineStipple", nullptr, then_observe([] { glLineStipple(3, 0xF0F1); }), OK},
      {"LineStippleFactorClampedHigh", nullptr, then_observe([] { glLineStipple(1000, 0x1234); }), OK},
      {"LineStippleFactorClampedLow", nullptr, then_observe([] { glLineStipple(-5, 0x8001); }), OK},
      {"LineStippleInsideBeginEnd", nullptr, then_observe(inside([] { glLineStipple(2, 0x00FF); })), IO},
      {"EnableLineStipple", nullptr, then_observe([] { glEnable(GL_LINE_STIPPLE); }), OK},
      {"EnableAll", nullptr, then_observe([] { glEnable(GL_BLEND), glEnable(GL_ALPHA_TEST), glEnable(GL_SCISSOR_TEST); }), OK},
      {"DisableAgain", [] { glEnable(GL_BLEND), glEnable(GL_SCISSOR_TEST); },
       then_observe([] { glDisable(GL_BLEND), glDisable(GL_SCISSOR_TEST); }), OK},
  };
  // glBitmap in feedback mode: GL_BITMAP_TOKEN and the raster position, which each call moves.
  for (GLenum type : {GL_2D, GL_3D_COLOR, GL_4D_COLOR_TEXTURE})
    v.push_back({"BitmapFeedback" + std::to_string(type), nullptr, [type] {
                   static GLfloat buf[64];
                   std::fill(buf, buf + 64, -1.0f);
                   glFeedbackBuffer(64, type, buf);
                   glRenderMode(GL_FEEDBACK);
                   glColor4f(0.25f, 0.5f, 0.75f, 1);
                   glRasterPos2f(0.1f, -0.3f);
                   static const GLubyte bits[2] = {0xA5, 0x3C};
                   glBitmap(8, 2, 1.5f, 0, 9.25f, 1, bits);
                   glBitmap(0, 0, 0, 0, -3, 0.5f, nullptr);
                   observe("count", glRenderMode(GL_RENDER));
                   for (int i = 0; i < 64; ++i) observe("buf[" + std::to_string(i) + "]", buf[i]);
                   observe_fragment_state();
                 }, OK});
  // The raster position after glBitmap's moves, and a move from an invalid position (none).
  v.push_back({"BitmapMovesRasterPosition", nullptr, then_observe([] {
                 glRasterPos2f(0.2f, 0.1f);
                 glBitmap(0, 0, 0, 0, 3.5f, -2.25f, nullptr);
                 GLfloat p[4];
                 glGetFloatv(GL_CURRENT_RASTER_POSITION, p);
                 for (int k = 0; k < 4; ++k) observe("moved[" + std::to_string(k) + "]", p[k]);
                 glTranslatef(0, 0, 5), glRasterPos2f(0, 0);  // outside the view volume: invalid
                 glBitmap(0, 0, 0, 0, 3.5f, -2.25f, nullptr);
                 glGetFloatv(GL_CURRENT_RASTER_POSITION, p);
                 for (int k = 0; k < 4; ++k) observe("invalid[" + std::to_string(k) + "]", p[k]);
               }), OK});
  v.push_back({"BitmapNegativeSize", nullptr, then_observe([] { glBitmap(-1, 2, 0, 0, 1, 1, nullptr); }), IV});
  v.push_back({"BitmapInsideBeginEnd", nullptr, then_observe(inside([] { glBitmap(0, 0, 0, 0, 1, 1, nullptr); })), IO});
  return v;
}

INSTANTIATE_TEST_SUITE_P(State, FragmentState, ::testing::ValuesIn(cases()), case_name);

}  // namespace
}  // namespace ffc::state_test
