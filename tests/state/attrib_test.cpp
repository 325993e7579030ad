// glPushAttrib / glPopAttrib and glPushClientAttrib / glPopClientAttrib against Mesa 22.3: a
// state set, pushed under one group's bit, everything changed, popped; then every value the
// harness reads back (lights, materials, matrices, viewport, fog, enables ...) and the fragment
// state compared with Mesa's, so that each group restores what Mesa restores and keeps the rest.
// Also the stacks' depth (16), GL_STACK_OVERFLOW and GL_STACK_UNDERFLOW.
#include "harness.h"

namespace ffc::state_test {
namespace {

constexpr GLenum OK = GL_NO_ERROR;

// Sets most of the state this context models to values of variant v (0 or 1).
void set_everything(int v) {
  const float a = v ? 0.7f : 0.2f, b = v ? 0.1f : 0.6f;
  glColor4f(a, b, a, b), glNormal3f(b, a, 0.5f);
  glRasterPos2f(a - 0.5f, b - 0.5f);
  auto on = [&](GLenum cap, bool state) { state ? glEnable(cap) : glDisable(cap); };
  for (GLenum cap : {GL_LIGHTING, GL_LIGHT1, GL_NORMALIZE, GL_CULL_FACE, GL_DEPTH_TEST, GL_FOG, GL_BLEND,
                     GL_ALPHA_TEST, GL_SCISSOR_TEST, GL_POLYGON_OFFSET_FILL, GL_COLOR_MATERIAL, GL_LINE_SMOOTH,
                     GL_RESCALE_NORMAL, GL_POINT_SMOOTH, GL_POLYGON_SMOOTH, GL_CLIP_PLANE2, GL_COLOR_LOGIC_OP,
                     GL_LINE_STIPPLE})
    on(cap, (cap + v) % 2);
  on(GL_DITHER, v == 0);
  light4(GL_LIGHT1, GL_POSITION, a, b, 1, v);
  light4(GL_LIGHT1, GL_DIFFUSE, b, a, b, 1);
  material4(GL_FRONT, GL_SPECULAR, a, a, b, 1);
  material4(GL_BACK, GL_SHININESS, 10 + 20 * a, 0, 0, 0);
  model4(GL_LIGHT_MODEL_AMBIENT, b, b, a, 1);
  glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, v);
  glShadeModel(v ? GL_FLAT : GL_SMOOTH);
  glColorMaterial(v ? GL_BACK : GL_FRONT, v ? GL_SPECULAR : GL_DIFFUSE);
  glLineWidth(1 + 2 * a), glPointSize(1 + 3 * b), glLineStipple(1 + 3 * v, GLushort(0x0F0F + v));
  glFogi(GL_FOG_MODE, v ? GL_LINEAR : GL_EXP2), glFogf(GL_FOG_DENSITY, a), glFogf(GL_FOG_START, b);
  glFogf(GL_FOG_END, 2 + a);
  const GLfloat fog_color[4] = {a, b, a, b};
  glFogfv(GL_FOG_COLOR, fog_color);
  glPolygonOffset(a, -b), glCullFace(v ? GL_FRONT : GL_FRONT_AND_BACK), glFrontFace(v ? GL_CW : GL_CCW);
  glScissor(v, 2 * v, 5 + v, 7 - v);
  glViewport(v, v, 12 + v, 10 - v), glDepthRange(b, a);
  glClearColor(a, b, a, b), glClearDepth(b), glDepthFunc(v ? GL_GEQUAL : GL_NOTEQUAL);
  glBlendFuncSeparate(v ? GL_DST_COLOR : GL_SRC_ALPHA, GL_ONE, GL_ZERO, v ? GL_ONE : GL_SRC_COLOR);
  glBlendEquationSeparate(v ? GL_MIN : GL_FUNC_SUBTRACT, v ? GL_FUNC_ADD : GL_MAX);
  glBlendColor(a, b, a, b), glAlphaFunc(v ? GL_LESS : GL_GEQUAL, a);
  glColorMask(v, 1 - v, v, 1), glDepthMask(GLboolean(v));
  glMatrixMode(v ? GL_PROJECTION : GL_TEXTURE);
  glPixelStorei(GL_UNPACK_ALIGNMENT, v ? 2 : 8), glPixelStorei(GL_PACK_ROW_LENGTH, 3 + v);
  glPixelStorei(GL_UNPACK_LSB_FIRST, v);
  // A draw: the glMaterial values above are no longer pending in Mesa's vbo (which would copy
  // them again at a later flush, after a pop).
  glBegin(GL_POINTS), glVertex2f(0, 0), glEnd();
}

void observe_fragment() {
  const GLenum names[] = {GL_BLEND_SRC_RGB, GL_BLEND_DST_RGB, GL_BLEND_SRC_ALPHA, GL_BLEND_DST_ALPHA,
                          GL_BLEND_EQUATION, GL_BLEND_EQUATION_ALPHA, GL_BLEND_COLOR, GL_ALPHA_TEST_FUNC,
                          GL_ALPHA_TEST_REF, GL_COLOR_WRITEMASK, GL_DEPTH_WRITEMASK, GL_SCISSOR_BOX,
                          GL_ATTRIB_STACK_DEPTH, GL_CLIENT_ATTRIB_STACK_DEPTH, GL_LOGIC_OP, GL_DITHER,
                          GL_LINE_STIPPLE, GL_LINE_STIPPLE_PATTERN, GL_LINE_STIPPLE_REPEAT};
  for (GLenum n : names) {
    GLfloat f[4] = {-7, -7, -7, -7};
    glGetFloatv(n, f);
    for (int k = 0; k < 4; ++k) observe(enum_name(n) + "[" + std::to_string(k) + "]", f[k]);
  }
}

Calls push_change_pop(GLbitfield mask) {
  return [mask] {
    set_everything(0);
    glPushAttrib(mask);
    set_everything(1);
    glPopAttrib();
    observe_fragment();
  };
}

Calls client_push_change_pop(GLbitfield mask) {
  return [mask] {
    set_everything(0);
    glEnableClientState(GL_NORMAL_ARRAY), glEnableClientState(GL_TEXTURE_COORD_ARRAY);
    static const GLfloat data[4] = {};
    glColorPointer(3, GL_FLOAT, 8, data);
    glPushClientAttrib(mask);
    set_everything(1);
    glDisableClientState(GL_NORMAL_ARRAY), glDisableClientState(GL_TEXTURE_COORD_ARRAY);
    glEnableClientState(GL_VERTEX_ARRAY);
    glColorPointer(4, GL_UNSIGNED_BYTE, 0, data);
    glPopClientAttrib();
    observe_fragment();
  };
}

class Attrib : public ::testing::TestWithParam<Case> {};
TEST_P(Attrib, MatchesMesa) { check_case(GetParam()); }

std::vector<Case> cases() {
  const std::pair<const char*, GLbitfield> bits[] = {
      {"Current", GL_CURRENT_BIT},       {"Enable", GL_ENABLE_BIT},     {"ColorBuffer", GL_COLOR_BUFFER_BIT},
      {"DepthBuffer", GL_DEPTH_BUFFER_BIT}, {"Fog", GL_FOG_BIT},        {"Lighting", GL_LIGHTING_BIT},
      {"Line", GL_LINE_BIT},             {"Point", GL_POINT_BIT},       {"Polygon", GL_POLYGON_BIT},
      {"Scissor", GL_SCISSOR_BIT},       {"Transform", GL_TRANSFORM_BIT}, {"Viewport", GL_VIEWPORT_BIT},
      {"None", 0},                       {"All", GL_ALL_ATTRIB_BITS}};
  std::vector<Case> v;
  for (const auto& [name, bit] : bits) v.push_back({std::string("Push") + name, nullptr, push_change_pop(bit), OK});
  v.push_back({"PushSixteen", nullptr, [] {
                 for (int i = 0; i < 16; ++i) glPushAttrib(GL_ALL_ATTRIB_BITS);
                 observe_fragment();
               }, OK});
  v.push_back({"PushSeventeenOverflows", nullptr, [] {
                 for (int i = 0; i < 17; ++i) glPushAttrib(GL_ALL_ATTRIB_BITS);
                 observe_fragment();
               }, GL_STACK_OVERFLOW});
  v.push_back({"PopEmptyUnderflows", nullptr, [] { glPopAttrib(); }, GL_STACK_UNDERFLOW});
  v.push_back({"PushInsideBeginEnd", nullptr, inside([] { glPushAttrib(GL_ALL_ATTRIB_BITS); }), GL_INVALID_OPERATION});
  v.push_back({"PopInsideBeginEnd", [] { glPushAttrib(GL_ALL_ATTRIB_BITS); }, inside([] { glPopAttrib(); }),
               GL_INVALID_OPERATION});
  v.push_back({"ClientPixelStore", nullptr, client_push_change_pop(GL_CLIENT_PIXEL_STORE_BIT), OK});
  v.push_back({"ClientVertexArray", nullptr, client_push_change_pop(GL_CLIENT_VERTEX_ARRAY_BIT), OK});
  v.push_back({"ClientAll", nullptr, client_push_change_pop(GL_CLIENT_ALL_ATTRIB_BITS), OK});
  v.push_back({"ClientPushSeventeenOverflows", nullptr, [] {
                 for (int i = 0; i < 17; ++i) glPushClientAttrib(GL_CLIENT_ALL_ATTRIB_BITS);
                 observe_fragment();
               }, GL_STACK_OVERFLOW});
  v.push_back({"ClientPopEmptyUnderflows", nullptr, [] { glPopClientAttrib(); }, GL_STACK_UNDERFLOW});
  return v;
}

INSTANTIATE_TEST_SUITE_P(State, Attrib, ::testing::ValuesIn(cases()), case_name);

}  // namespace
}  // namespace ffc::state_test
