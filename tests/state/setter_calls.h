// State setters for the flush streams (color_material_test.cpp, setter_flush_test.cpp): setter
// `which` (0 to 14) called with its default value (`other` false) or another one. Mesa runs
// FLUSH_VERTICES at a setter only when the call changes the state, so a stream that calls one
// twice with the same value shows whether soft flushes stored vertices where Mesa does (the
// pending colour, its alpha, a pending glMaterial). None of them changes what the streams' draws
// feed back but through that flush: the tests, the blend and the fog are off.
#pragma once
#include <GL/gl.h>

namespace ffc::state_test {

inline void setter_call(int which, bool other) {
  const GLfloat white[4] = {1, 1, 1, 1}, tint[4] = {0.9f, 0.8f, 0.7f, 1};
  const GLfloat ambient[4] = {0.2f, 0.2f, 0.2f, 1}, dim[4] = {0.1f, 0.15f, 0.2f, 1};
  const GLfloat z_axis[4] = {0, 0, 1, 0}, slanted[4] = {0.6f, 0, 0.8f, 0};
  const GLfloat black[4] = {0, 0, 0, 0}, grey[4] = {0.5f, 0.5f, 0.5f, 1};
  switch (which) {
    case 0: glShadeModel(other ? GL_FLAT : GL_SMOOTH); break;
    case 1: glFrontFace(other ? GL_CW : GL_CCW); break;
    case 2: glCullFace(other ? GL_FRONT : GL_BACK); break;
    case 3: glPolygonMode(GL_BACK, other ? GL_LINE : GL_FILL); break;
    case 4: glLightfv(GL_LIGHT0, GL_DIFFUSE, other ? tint : white); break;
    case 5:
      glLightModelf(GL_LIGHT_MODEL_LOCAL_VIEWER, other ? 1.0f : 0.0f);
      glLightModelfv(GL_LIGHT_MODEL_AMBIENT, other ? dim : ambient);
      break;
    case 6:
      glFogf(GL_FOG_START, other ? 0.5f : 0.0f);
      glFogfv(GL_FOG_COLOR, other ? grey : black);
      break;
    case 7:
      glAlphaFunc(other ? GL_GREATER : GL_ALWAYS, other ? 0.25f : 0.0f);
      glBlendColor(other ? 0.5f : 0.0f, 0, 0, 0);
      break;
    case 8:
      glBlendFunc(other ? GL_SRC_ALPHA : GL_ONE, other ? GL_ONE_MINUS_SRC_ALPHA : GL_ZERO);
      glBlendEquation(other ? GL_FUNC_SUBTRACT : GL_FUNC_ADD);
      break;
    case 9:
      glDepthFunc(other ? GL_LEQUAL : GL_LESS);
      glViewport(0, 0, other ? 8 : 16, 16);  // the harness's window: 16 by 16
      glDepthRange(0, other ? 0.5 : 1.0);
      break;
    case 10:
      glLineWidth(other ? 2.0f : 1.0f);
      glLineStipple(other ? 2 : 1, other ? 0xF0F0 : 0xFFFF);
      break;
    case 11:
      glPointSize(other ? 2.0f : 1.0f);
      glPolygonOffset(other ? 1.0f : 0.0f, other ? 2.0f : 0.0f);
      break;
    case 12:
      glDepthMask(other ? GL_FALSE : GL_TRUE);
      glColorMask(GL_TRUE, other ? GL_FALSE : GL_TRUE, GL_TRUE, GL_TRUE);
      break;
    case 13: {
      glHint(GL_FOG_HINT, other ? GL_NICEST : GL_DONT_CARE);
      const GLfloat identity[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
      const GLfloat scaled[16] = {2, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
      glMatrixMode(GL_TEXTURE);  // a matrix the draws do not read
      glLoadMatrixf(other ? scaled : identity);
      glMultMatrixf(identity);  // Mesa skips an identity (no flush)
      glMatrixMode(GL_MODELVIEW);
      break;
    }
    case 14: glLightfv(GL_LIGHT0, GL_POSITION, other ? slanted : z_axis); break;
  }
}

}  // namespace ffc::state_test
