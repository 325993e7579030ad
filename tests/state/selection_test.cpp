// Selection and glPassThrough against Mesa (GL 2.1 sections 5.2 and 5.3): the select buffer, the
// name stack and its errors, hit records (their depth range as Mesa scales it to unsigned int)
// for primitives inside, outside and across the view volume, a picking probe through a
// gluPickMatrix-style projection, overflow, lists of names; glPassThrough in feedback.
#include <algorithm>

#include "harness.h"

namespace ffc::state_test {
namespace {

constexpr GLenum OK = GL_NO_ERROR, IO = GL_INVALID_OPERATION, IV = GL_INVALID_VALUE;

class Selection : public ::testing::TestWithParam<Case> {};
TEST_P(Selection, MatchesMesa) { check_case(GetParam()); }

// Selection into a buffer of `size` values: glRenderMode's count on leaving GL_SELECT and the
// buffer with 8 values past its end, which must stay untouched.
Calls select_into(GLsizei size, const Calls& draw) {
  return [=] {
    static GLuint buf[264];
    std::fill(std::begin(buf), std::end(buf), 0xdeadbeefu);
    glSelectBuffer(size, buf);
    observe("enter", glRenderMode(GL_SELECT));
    draw();
    observe("hits", glRenderMode(GL_RENDER));
    for (GLsizei i = 0; i < size + 8; ++i) observe("buf[" + std::to_string(i) + "]", buf[i]);
  };
}

void triangle(float x, float y, float z, float s = 0.3f) {
  glBegin(GL_TRIANGLES);
  glVertex3f(x - s, y - s, z), glVertex3f(x + s, y - s, z + 0.2f), glVertex3f(x, y + s, z - 0.1f);
  glEnd();
}

// Three named objects under a perspective camera: two triangles at different depths, a line,
// a point, and one object wholly outside the view volume.
void named_scene() {
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glFrustum(-1, 1, -1, 1, 1, 10);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glInitNames();
  glPushName(1);
  triangle(0, 0, -2);
  glLoadName(2);
  triangle(0.2f, 0.1f, -5);
  glPushName(20);
  glBegin(GL_LINES), glVertex3f(-1, 0, -3), glVertex3f(1, 0.5f, -4), glEnd();
  glPopName();
  glLoadName(3);
  triangle(30, 0, -2);  // outside: no hit
  glLoadName(4);
  glBegin(GL_POINTS), glVertex3f(0.1f, 0.1f, -1.5f), glEnd();
  glLoadName(5);
  triangle(1, 0, -3, 0.8f);  // across the right plane: clipped, a hit
}

// A gluPickMatrix-style probe: a 3x3 pixel region around (x, y) of a 16x16 viewport.
void pick(float x, float y) {
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  const float w = 3, h = 3;
  glTranslatef((kWidth - 2 * (x - 0)) / w, (kHeight - 2 * (y - 0)) / h, 0);
  glScalef(kWidth / w, kHeight / h, 1);
  glFrustum(-1, 1, -1, 1, 1, 10);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glInitNames();
  glPushName(0);
  for (GLuint k = 0; k < 4; ++k) {
    glLoadName(100 + k);
    triangle(-0.6f + 0.4f * float(k), -0.2f + 0.3f * float(k), -2 - float(k), 0.25f);
  }
}

void in_select() {
  static GLuint b[16];
  glSelectBuffer(16, b);
  glRenderMode(GL_SELECT);
}

std::vector<Case> cases() {
  return {
    {"SelectBuffer", nullptr, [] { static GLuint b[4]; glSelectBuffer(4, b); }, OK},
    {"SelectBufferNegative", nullptr, [] { static GLuint b[4]; glSelectBuffer(-1, b); }, IV},
    {"SelectBufferInSelectMode", [] { static GLuint b[4]; glSelectBuffer(4, b); glRenderMode(GL_SELECT); },
     [] { static GLuint b[8]; glSelectBuffer(8, b); }, IO},
    {"SelectBufferInsideBeginEnd", nullptr, inside([] { static GLuint b[4]; glSelectBuffer(4, b); }), IO},
    {"EnterSelect", [] { static GLuint b[4]; glSelectBuffer(4, b); }, [] { observe("r", glRenderMode(GL_SELECT)); }, OK},
    {"NameStackOutsideSelectIgnored", nullptr, [] { glInitNames(); glPushName(3); glPushName(4); glPopName(); glPopName(); glPopName(); glLoadName(2); }, OK},
    {"PushNameInsideBeginEnd", nullptr, inside([] { glPushName(3); }), IO},
    {"LoadNameEmptyStack", in_select, [] { glLoadName(3); }, IO},
    {"PopNameUnderflow", in_select, [] { glPopName(); }, GL_STACK_UNDERFLOW},
    {"PushNameOverflow", [] { in_select(); for (GLuint k = 0; k < 64; ++k) glPushName(k); }, [] { glPushName(64); }, GL_STACK_OVERFLOW},
    {"LoadNameEmptyStackAfterHit", nullptr, select_into(16, [] {
       glBegin(GL_POINTS), glVertex3d(0, 0, 0), glEnd();
       glLoadName(0);
       observe("load", glGetError());
       triangle(0, 0, 0.5f);
       glPushName(3);
       glPopName();
       glPopName();
       observe("pop", glGetError());
       triangle(0, 0, 0.25f);
     }), OK},
    {"NameStackErrorsThenHits", nullptr, select_into(200, [] {
       glLoadName(3);
       observe("load", glGetError());
       glPopName();
       observe("pop", glGetError());
       glPushName(1), triangle(0, 0, 0);
       for (GLuint k = 0; k < 70; ++k) glPushName(k);
       observe("push", glGetError());
       triangle(0, 0, 0.5f);
       glInitNames();
     }), OK},
    {"NameStackDepth", [] { static GLuint b[4]; glSelectBuffer(4, b); glRenderMode(GL_SELECT); },
     [] { glPushName(3); glPushName(4); glLoadName(5); }, OK},
    {"NamedScene", nullptr, select_into(64, named_scene), OK},
    {"NamedSceneOverflow", nullptr, select_into(9, named_scene), OK},
    {"NamedSceneCulled", [] { glEnable(GL_CULL_FACE); glCullFace(GL_FRONT); }, select_into(64, named_scene), OK},
    {"NamedSceneDepthRange", [] { glDepthRange(0.25, 0.5); }, select_into(64, named_scene), OK},
    {"NamedSceneOffset", [] { glEnable(GL_POLYGON_OFFSET_FILL); glPolygonOffset(2, 3); }, select_into(64, named_scene), OK},
    {"HitAtDepthOne", nullptr, select_into(16, [] {
       glPushName(9);
       glBegin(GL_TRIANGLES), glVertex3f(-1, -1, 1), glVertex3f(1, -1, 1), glVertex3f(0, 1, 1), glEnd();
       glLoadName(10);
       glBegin(GL_TRIANGLES), glVertex3f(-1, -1, -1), glVertex3f(1, -1, 0), glVertex3f(0, 1, 0.5f), glEnd();
     }), OK},
    {"HitWithoutNames", nullptr, select_into(16, [] { triangle(0, 0, 0); }), OK},
    {"HitThenInitNames", nullptr, select_into(16, [] { glPushName(1); triangle(0, 0, 0); glInitNames(); triangle(0, 0, 0.5f); }), OK},
    {"PickProbeCentre", nullptr, select_into(64, [] { pick(8, 8); }), OK},
    {"PickProbeCorner", nullptr, select_into(64, [] { pick(3, 5); }), OK},
    {"NamesInList", nullptr, select_into(64, [] {
       glNewList(1, GL_COMPILE);
       glInitNames(), glPushName(7), triangle(0, 0, 0), glLoadName(8), glPushName(9), triangle(0, 0, 0.5f), glPopName();
       glEndList();
       glCallList(1);
     }), OK},
    {"RasterPosHit", nullptr, select_into(16, [] { glPushName(4); glRasterPos2f(0.25f, 0.5f); glLoadName(5); }), OK},
    // glDrawPixels in selection mode is no hit in Mesa (its raster position was one already).
    {"DrawPixelsHit", nullptr, select_into(16, [] {
       glPushName(4);
       glRasterPos2f(0.25f, 0.5f);
       glLoadName(5);
       static const GLubyte px[4] = {1, 2, 3, 4};
       glDrawPixels(1, 1, GL_RGBA, GL_UNSIGNED_BYTE, px);
       glLoadName(6);
     }), OK},
    {"ArraysHit", nullptr, select_into(16, [] {
       static const GLfloat p[] = {-0.5f, -0.5f, 0.1f, 0.5f, -0.5f, 0.3f, 0, 0.5f, -0.2f};
       glEnableClientState(GL_VERTEX_ARRAY);
       glVertexPointer(3, GL_FLOAT, 0, p);
       glPushName(2);
       glDrawArrays(GL_TRIANGLES, 0, 3);
       glDisableClientState(GL_VERTEX_ARRAY);
     }), OK},
    {"NothingDrawnInSelectMode", nullptr, [] {
       static GLuint b[8];
       glSelectBuffer(8, b);
       glRenderMode(GL_SELECT);
       triangle(0, 0, 0, 0.9f);
       glRenderMode(GL_RENDER);
       observe_picture("px");
     }, OK},
    {"SelectAgainInSelect", nullptr, select_into(16, [] { glPushName(1); triangle(0, 0, 0); observe("again", glRenderMode(GL_SELECT)); triangle(0, 0, 0); }), OK},
    // glPassThrough.
    {"PassThroughFeedback", nullptr, feedback_into(24, GL_3D, [] { glPassThrough(7.5f); triangle(0, 0, 0); glPassThrough(-2); }), OK},
    {"PassThroughOverflow", nullptr, feedback_into(1, GL_2D, [] { glPassThrough(1); }), OK},
    {"PassThroughRender", nullptr, [] { glPassThrough(3); }, OK},
    {"PassThroughInsideBeginEnd", nullptr, inside([] { glPassThrough(3); }), IO},
    {"PassThroughInList", nullptr, feedback_into(24, GL_2D, [] {
       glNewList(1, GL_COMPILE);
       glPassThrough(5);
       glEndList();
       glCallList(1), glCallList(1);
     }), OK},
  };
}

INSTANTIATE_TEST_SUITE_P(State, Selection, ::testing::ValuesIn(cases()), case_name);

}  // namespace
}  // namespace ffc::state_test
