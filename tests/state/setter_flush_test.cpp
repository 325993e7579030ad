// Mesa's rule of flushing stored vertices only when a setter changes its value, one setter at a
// time: after glColor4, glColor3, glColor4 and a draw (vertices stored, the vbo format holding a
// 4-component colour), each of the fifteen setters of setter_calls.h is called once with the
// value it already has or with another, and a glColor3 follows. Whether the setter flushed shows
// in the alpha glColor3 leaves (deviations.md row 16) and in the lit colour of the next draw.
// Every read-back must be Mesa's; the unchanged calls failed before soft followed the rule
// (Context::changes).
#include <string>

#include "harness.h"
#include "setter_calls.h"

namespace ffc::state_test {
namespace {

GLfloat g_feedback[64];

void read_colour(const std::string& at) {
  GLfloat c[4];
  glGetFloatv(GL_CURRENT_COLOR, c);
  for (int k = 0; k < 4; ++k) observe(at + "[" + std::to_string(k) + "]", c[k]);
}

void lit_point(const std::string& at) {
  glFeedbackBuffer(64, GL_3D_COLOR, g_feedback);
  glRenderMode(GL_FEEDBACK);
  glBegin(GL_POINTS);
  glVertex3f(0, 0, 0);
  glEnd();
  const GLint n = glRenderMode(GL_RENDER);
  observe(at + " count", n);
  for (GLint i = 0; i < n && i < 64; ++i) observe(at + "[" + std::to_string(i) + "]", g_feedback[i]);
}

// The stream: vertices stored, colours of 4, 3 and 4 components (the format's colour has 4, its
// active size 3), the setter,
// then glColor3, a read-back and a point fed back. Unlit, the point carries the current colour;
// lit with colour material on the diffuse, the colour lands in the material at the flush.
Case one_setter(int which, bool changed, bool color_material) {
  const std::string name = std::string(changed ? "Changed" : "Unchanged") + (color_material ? "Tracked" : "") +
                           std::to_string(which);
  return {name, [color_material] {
            if (!color_material) return;
            glEnable(GL_LIGHTING), glEnable(GL_LIGHT0);
            glColorMaterial(GL_FRONT_AND_BACK, GL_DIFFUSE), glEnable(GL_COLOR_MATERIAL);
          }, [which, changed] {
            glBegin(GL_POINTS), glVertex3f(0, 0, 0), glEnd();
            glColor4f(0.5f, 0.5f, 0.5f, 0.25f);
            glColor3f(0.25f, 0.5f, 0.75f);
            glColor4f(0.125f, 0.25f, 0.375f, 0.75f);
            setter_call(which, changed);
            glColor3f(0.6f, 0.3f, 0.9f);
            read_colour("after");
            lit_point("draw");
          }, GL_NO_ERROR};
}

std::vector<Case> setter_cases() {
  std::vector<Case> rows;
  for (int cm = 0; cm < 2; ++cm)
    for (int changed = 0; changed < 2; ++changed)
      for (int which = 0; which < 15; ++which) rows.push_back(one_setter(which, changed != 0, cm != 0));
  return rows;
}

class SetterFlush : public ::testing::TestWithParam<Case> {};
TEST_P(SetterFlush, MatchesMesa) { check_case(GetParam(), 2e-6); }
INSTANTIATE_TEST_SUITE_P(EachSetter, SetterFlush, ::testing::ValuesIn(setter_cases()), case_name);

// A setter refused for a bad value flushes nothing either (Mesa checks before FLUSH_VERTICES), so
// the glColor3 after it keeps the last glColor4's alpha, 0.75, as after an unchanged setter (a
// flush would empty the format: alpha 1). The errors are read inside the stream: check_case
// would take the state between a setup and the call, and its glGetMaterialfv flushes.
TEST(SetterFlushErrors, RefusedSetterFlushesNothing) {
  const Calls stream = [] {
    glBegin(GL_POINTS), glVertex3f(0, 0, 0), glEnd();
    glColor4f(0.5f, 0.5f, 0.5f, 0.25f);
    glColor3f(0.25f, 0.5f, 0.75f);
    glColor4f(0.125f, 0.25f, 0.375f, 0.75f);
    glShadeModel(GL_LINE);  // GL_INVALID_ENUM
    observe("shade model error", glGetError());
    glLineWidth(-1);
    observe("line width error", glGetError());
    glColor3f(0.6f, 0.3f, 0.9f);
    read_colour("after");
  };
  for (Side side : {kMesa, kSoft}) {
    const Outcome o = run(side, [] {}, stream);
    ASSERT_EQ(o.observed.values.size(), 6u) << side_name(side);
    EXPECT_EQ(o.observed.values[0].second, GL_INVALID_ENUM) << side_name(side);
    EXPECT_EQ(o.observed.values[1].second, GL_INVALID_VALUE) << side_name(side);
    EXPECT_FLOAT_EQ(o.observed.values[2].second, 0.6f) << side_name(side);
    EXPECT_FLOAT_EQ(o.observed.values[5].second, 0.75f) << side_name(side) << ": the refused calls flushed";
  }
}

}  // namespace
}  // namespace ffc::state_test
