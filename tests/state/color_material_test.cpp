// Colour material against Mesa over generated call streams: glColor, glMaterial, glColorMaterial,
// glEnable/glDisable(GL_COLOR_MATERIAL), draws (immediate mode with and without glColor inside,
// arrays with and without a colour array, in feedback and in render mode) and glGetMaterialfv, in
// random orders. Mesa tracks the colour in steps (see Context::update_color_material); every fed-back
// colour, every material read back and the final state must agree with Mesa's.
#include <random>
#include <string>

#include "harness.h"
#include "setter_calls.h"

namespace ffc::state_test {
namespace {

constexpr GLenum OK = GL_NO_ERROR;

const GLfloat kPalette[3][4] = {{0.5f, 0.6f, 0.7f, 1}, {0.2f, 0.3f, 0.4f, 1}, {0.9f, 0.1f, 0.3f, 0.5f}};
const GLenum kFaces[3] = {GL_FRONT, GL_BACK, GL_FRONT_AND_BACK};
const GLenum kModes[5] = {GL_AMBIENT, GL_DIFFUSE, GL_SPECULAR, GL_EMISSION, GL_AMBIENT_AND_DIFFUSE};
const GLfloat kPositions[9] = {0, 0, 0, 0.5f, 0, 0, 0, 0.5f, 0};
const GLfloat kNormals[9] = {0, 0, 1, 0, 0.6f, 0.8f, 0.6f, 0, 0.8f};
const GLfloat kColours[12] = {0.1f, 0.8f, 0.3f, 1, 0.7f, 0.2f, 0.9f, 1, 0.4f, 0.4f, 0.1f, 1};
GLfloat g_buffer[256];

// One step of a stream: a letter and three small numbers that pick its arguments.
struct Step {
  char op;
  int a, b, c;
};

void feedback(const std::string& label, const std::function<void()>& draw) {
  glFeedbackBuffer(256, GL_3D_COLOR, g_buffer);
  glRenderMode(GL_FEEDBACK);
  draw();
  const GLint n = glRenderMode(GL_RENDER);
  observe(label + " count", n);
  for (GLint i = 0; i < n && i < 256; ++i) observe(label + "[" + std::to_string(i) + "]", g_buffer[i]);
}

void run_step(const Step& s, int index) {
  const std::string at = std::to_string(index) + s.op;
  switch (s.op) {
    case 'c': glColor4fv(kPalette[s.a]); break;
    case 't': glColor3fv(kPalette[s.a]); break;  // alpha: see Context::Color
    case 'm': glMaterialfv(kFaces[s.b], kModes[s.c], kPalette[s.a]); break;
    case 'M': glColorMaterial(kFaces[s.b], kModes[s.c]); break;
    case 'e': glEnable(GL_COLOR_MATERIAL); break;
    case 'x': glDisable(GL_COLOR_MATERIAL); break;
    case 'd':  // immediate mode, no glColor inside
      feedback(at, [] {
        glBegin(GL_POINTS);
        glNormal3f(0, 0.6f, 0.8f);
        glVertex3f(0, 0, 0);
        glEnd();
      });
      break;
    case 'i':  // immediate mode with a glColor inside
      feedback(at, [s] {
        glBegin(GL_TRIANGLES);
        glNormal3f(0, 0, 1);
        glVertex3f(0, 0, 0);
        glColor4fv(kPalette[s.a]);
        glVertex3f(0.5f, 0, 0);
        glVertex3f(0, 0.5f, 0);
        glEnd();
      });
      break;
    case 'a':  // arrays, the colour from an array or not
      feedback(at, [s] {
        glVertexPointer(3, GL_FLOAT, 0, kPositions);
        glNormalPointer(GL_FLOAT, 0, kNormals);
        glColorPointer(4, GL_FLOAT, 0, kColours);
        glEnableClientState(GL_VERTEX_ARRAY);
        glEnableClientState(GL_NORMAL_ARRAY);
        if (s.a == 0) glEnableClientState(GL_COLOR_ARRAY);
        glDrawArrays(GL_TRIANGLES, 0, 3);
        glDisableClientState(GL_COLOR_ARRAY);
      });
      break;
    case 'r':  // a draw in render mode
      glBegin(GL_POINTS);
      glVertex3f(0, 0, 0);
      glEnd();
      break;
    case 'g': {
      GLfloat v[4];
      glGetMaterialfv(kFaces[s.b % 2], kModes[s.c % 4], v);
      for (int k = 0; k < 4; ++k) observe(at + "[" + std::to_string(k) + "]", v[k]);
      break;
    }
    case 'q': {  // FLUSH_CURRENT without FLUSH_VERTICES
      GLfloat v[4];
      glGetFloatv(GL_CURRENT_COLOR, v);
      for (int k = 0; k < 4; ++k) observe(at + "[" + std::to_string(k) + "]", v[k]);
      break;
    }
    case 'h': glShadeModel(s.a == 0 ? GL_FLAT : GL_SMOOTH); break;  // FLUSH_VERTICES when it changes
    case 'n': glNormal3fv(kNormals + 3 * s.a); break;                // joins the vbo format
    case 's': setter_call(s.b * 5 + s.c, s.a == 1); break;          // FLUSH_VERTICES on a change only
  }
}

// A stream as a case, named by its steps: the letter (K for M: names are case-blind on some
// systems), then a, b, c.
Case stream_case(const std::string& prefix, const std::vector<Step>& steps) {
  std::string name = prefix;
  for (const Step& s : steps)
    name += std::string(1, s.op == 'M' ? 'K' : s.op) + char('0' + s.a) + char('0' + s.b) + char('0' + s.c);
  return {name, [] { glEnable(GL_LIGHTING); glEnable(GL_LIGHT0); }, [steps] {
            for (size_t i = 0; i < steps.size(); ++i) run_step(steps[i], int(i));
          }, OK};
}

// `count` streams of 3 to 12 steps drawn from `ops` (a letter twice is twice as likely), each
// ending with a draw.
std::vector<Case> random_streams(const std::string& prefix, uint32_t seed, const std::string& ops, int count) {
  std::vector<Case> rows;
  std::mt19937 rng(seed);
  for (int n = 0; n < count; ++n) {
    std::vector<Step> steps;
    const int length = 3 + int(rng() % 10);
    for (int k = 0; k < length; ++k)
      steps.push_back({ops[rng() % ops.size()], int(rng() % 3), int(rng() % 3), int(rng() % 5)});
    steps.push_back({'d', 0, 0, 0});
    rows.push_back(stream_case(prefix + std::to_string(n) + "_", steps));
  }
  return rows;
}

std::vector<Case> generated_streams() { return random_streams("Stream", 20261124, "ccmmmMMeexddiargg", 400); }

// All 400 agree. Stream 397 (m211 m004 g023 K021 m124 e112 K224 m014 d000) disagreed until soft
// modelled Mesa's NeedFlush after a FLUSH_CURRENT (Context::flush_current): the glGetMaterialfv
// and the glEnable copy the pending values and leave Mesa asking for a flush of stored vertices,
// so the next glColorMaterial copies the glMaterial values once more and empties the vbo format;
// the tracking then overwrites them for good (soft copied them again at the draw). Measured one
// call at a time in MaterialBeforeEnableDroppedAfterFlushCurrent below.

// glColorMaterial changed while enabled, with a colour pending (Context::ColorMaterial), measured
// with Mesa 22.3: after a copy of the format's colour (here at an earlier glColorMaterial), a new
// glColor is tracked with the replaced mode too (the emission takes palette 0: failed before);
// the first colour since the format's reset only with the new mode, whether alone or twice in a row.
std::vector<Case> measured_streams() {
  return {
      stream_case("TrackedWithOldMode_", {{'M', 0, 2, 3}, {'e', 0, 0, 0}, {'c', 2, 0, 0}, {'M', 0, 0, 3},
                                          {'c', 0, 0, 0}, {'M', 0, 2, 0}, {'g', 0, 0, 3}, {'d', 0, 0, 0}}),
      stream_case("FirstColourNewModeOnly_",
                  {{'M', 0, 2, 3}, {'e', 0, 0, 0}, {'c', 0, 0, 0}, {'M', 0, 2, 0}, {'g', 0, 0, 3}, {'d', 0, 0, 0}}),
      stream_case("TwoColoursNewModeOnly_", {{'M', 0, 2, 3}, {'e', 0, 0, 0}, {'c', 2, 0, 0}, {'c', 0, 0, 0},
                                             {'M', 0, 2, 0}, {'g', 0, 0, 3}, {'d', 0, 0, 0}}),
      // A FLUSH_CURRENT (here glEnable(GL_COLOR_MATERIAL)) leaves Mesa asking for a flush of stored
      // vertices: the glColorMaterial after it copies the glMaterial (palette 1) once more and
      // empties the format, then tracks white over it; the draw copies nothing. Soft copied
      // palette 1 again at the draw (stream 397's cause; failed before).
      stream_case("MaterialBeforeEnableDroppedAfterFlushCurrent_",
                  {{'M', 0, 2, 1}, {'m', 1, 2, 4}, {'e', 0, 0, 0}, {'M', 0, 2, 4}, {'d', 0, 0, 0}, {'g', 0, 0, 1}}),
      // glGetMaterialfv copies the pending colour without emptying the format (FLUSH_CURRENT after
      // FLUSH_VERTICES): a colour set after it is tracked with the mode a glColorMaterial replaces
      // (the emission takes palette 0) as after a glColorMaterial. Soft emptied the format there
      // (failed before).
      stream_case("ColourAfterGetMaterialTrackedWithOldMode_",
                  {{'M', 0, 2, 3}, {'e', 0, 0, 0}, {'c', 2, 0, 0}, {'g', 0, 0, 0}, {'c', 0, 0, 0},
                   {'M', 0, 2, 0}, {'g', 0, 0, 3}, {'d', 0, 0, 0}}),
  };
}
// The flush rule (Context::flush_current) over streams that also query the current colour
// (FLUSH_CURRENT alone), change the shade model (a FLUSH_VERTICES when it changes) and send normals
// (another attribute in the vbo format, copied at the same flushes).
std::vector<Case> flush_streams() { return random_streams("Flush", 20261125, "ccmmMMeexdiqqhhng", 300); }
class ColorMaterialFlushStreams : public ::testing::TestWithParam<Case> {};
TEST_P(ColorMaterialFlushStreams, MatchesMesa) { check_case(GetParam(), 2e-6); }
INSTANTIATE_TEST_SUITE_P(Generated, ColorMaterialFlushStreams, ::testing::ValuesIn(flush_streams()), case_name);

// Mesa's rule of flushing only when a setter changes its value, over fifteen setters (light.c,
// polygon.c, fog.c, blend.c, depth.c, lines.c, points.c, hint.c; tests/state/setter_calls.h), each
// called with its default or one other value, so that most calls change nothing, among colours of
// 4 and 3 components, glMaterial, colour material, draws and reads of the current colour.
std::vector<Case> setter_streams() { return random_streams("Setter", 20261126, "ccttmmMedirqqsssssss", 300); }
class SetterFlushStreams : public ::testing::TestWithParam<Case> {};
TEST_P(SetterFlushStreams, MatchesMesa) { check_case(GetParam(), 2e-6); }
INSTANTIATE_TEST_SUITE_P(Generated, SetterFlushStreams, ::testing::ValuesIn(setter_streams()), case_name);

class ColorMaterialMeasured : public ::testing::TestWithParam<Case> {};
TEST_P(ColorMaterialMeasured, MatchesMesa) { check_case(GetParam(), 2e-6); }
INSTANTIATE_TEST_SUITE_P(Sequences, ColorMaterialMeasured, ::testing::ValuesIn(measured_streams()), case_name);

class ColorMaterialStreams : public ::testing::TestWithParam<Case> {};
TEST_P(ColorMaterialStreams, MatchesMesa) { check_case(GetParam(), 2e-6); }
INSTANTIATE_TEST_SUITE_P(Generated, ColorMaterialStreams, ::testing::ValuesIn(generated_streams()), case_name);

// glColor3's alpha over generated streams of glColor4 / glColor3, draws, flushes (a state change, a
// glGet of the current colour) and glArrayElement with 3- and 4-component colour arrays: the current
// colour read back after each step must be Mesa's (see Context::Color).
std::vector<Case> alpha_streams() {
  static const GLfloat colours4[8] = {0.1f, 0.2f, 0.3f, 0.25f, 0.4f, 0.5f, 0.6f, 0.75f};
  std::vector<Case> rows;
  std::mt19937 rng(33);
  const std::string ops = "443333bgeAa";
  for (int n = 0; n < 300; ++n) {
    std::string steps;
    const int length = 2 + int(rng() % 9);
    for (int k = 0; k < length; ++k) steps += ops[rng() % ops.size()];
    rows.push_back({"Alpha" + std::to_string(n) + "_" + steps, nullptr, [steps] {
                      int k = 0;
                      for (char op : steps) {
                        const GLfloat v = 0.125f * GLfloat(++k % 8);
                        switch (op) {
                          case '4': glColor4f(v, 0.5f, 0.25f, v); break;
                          case '3': glColor3f(0.5f, v, 0.75f); break;
                          case 'b': glBegin(GL_POINTS), glVertex3f(0, 0, 0), glEnd(); break;
                          case 'e': glEnable(GL_DEPTH_TEST), glDisable(GL_DEPTH_TEST); break;
                          case 'A': case 'a':  // a colour array of 4 or 3 components, one element
                            glColorPointer(op == 'A' ? 4 : 3, GL_FLOAT, 16, colours4);
                            glEnableClientState(GL_COLOR_ARRAY);
                            glArrayElement(k % 2);
                            glDisableClientState(GL_COLOR_ARRAY);
                            break;
                          case 'g': {
                            GLfloat c[4];
                            glGetFloatv(GL_CURRENT_COLOR, c);
                            observe(std::to_string(k) + " alpha", c[3]);
                            break;
                          }
                        }
                      }
                    }, OK});
  }
  return rows;
}
// All 300 agree since soft keeps Mesa's vertex format where Mesa keeps it: through glBegin once a
// glVertex was sent, through glEnd, queries and client-state calls (four streams, e.g.
// Alpha128_b434g3, disagreed before).

// glColor3ub among glColor4f / glColor3f (no glBegin/glEnd): Mesa's vbo takes glColor3ub as a
// 4-component colour, alpha 1, so it never keeps the old alpha as glColor3f may.
std::vector<Case> ub_alpha_streams() {
  std::vector<Case> rows;
  std::mt19937 rng(34);
  const std::string ops = "4433uueg";
  for (int n = 0; n < 100; ++n) {
    std::string steps;
    const int length = 3 + int(rng() % 8);
    for (int k = 0; k < length; ++k) steps += ops[rng() % ops.size()];
    steps += 'g';
    rows.push_back({"UbAlpha" + std::to_string(n) + "_" + steps, nullptr, [steps] {
                      int k = 0;
                      for (char op : steps) {
                        const GLfloat v = 0.125f * GLfloat(++k % 8);
                        switch (op) {
                          case '4': glColor4f(v, 0.5f, 0.25f, v); break;
                          case '3': glColor3f(0.5f, v, 0.75f); break;
                          case 'u': glColor3ub(GLubyte(32 * (k % 8)), 128, 64); break;
                          case 'e': glEnable(GL_DEPTH_TEST), glDisable(GL_DEPTH_TEST); break;
                          case 'g': {
                            GLfloat c[4];
                            glGetFloatv(GL_CURRENT_COLOR, c);
                            observe(std::to_string(k) + " alpha", c[3]);
                            break;
                          }
                        }
                      }
                    }, OK});
  }
  return rows;
}
class ColorUbAlphaStreams : public ::testing::TestWithParam<Case> {};
TEST_P(ColorUbAlphaStreams, MatchesMesa) { check_case(GetParam()); }
INSTANTIATE_TEST_SUITE_P(Generated, ColorUbAlphaStreams, ::testing::ValuesIn(ub_alpha_streams()), case_name);

class ColorAlphaStreams : public ::testing::TestWithParam<Case> {};
TEST_P(ColorAlphaStreams, MatchesMesa) { check_case(GetParam()); }
INSTANTIATE_TEST_SUITE_P(Generated, ColorAlphaStreams, ::testing::ValuesIn(alpha_streams()), case_name);

// The case, by hand: a glMaterial before glEnable(GL_COLOR_MATERIAL) with no glColor keeps
// the material (Mesa), where GL 2.1 tracks the current colour (white) at once.
TEST(ColorMaterial, MaterialBeforeEnableWithoutColorIsKept) {
  check_case({"MaterialBeforeEnable", [] { glEnable(GL_LIGHTING); glEnable(GL_LIGHT0); }, [] {
                run_step({'m', 1, 0, 1}, 0);
                run_step({'M', 0, 0, 1}, 1);
                run_step({'e', 0, 0, 0}, 2);
                run_step({'d', 0, 0, 0}, 3);
              }, OK});
}

}  // namespace
}  // namespace ffc::state_test
