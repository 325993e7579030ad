// Mesa's matrix model (fmat::Matrix, float_matrix.h) against Mesa itself: generated sequences of
// matrix calls with NaN, infinities, huge and exact values, mixed with the calls at which Mesa
// analyses its matrices (glPushMatrix, glLight(GL_SPOT_DIRECTION), draws, glRasterPos,
// glReadPixels) and with glLight(GL_POSITION / GL_SPOT_DIRECTION) under the result. The matrices, light positions and spot
// directions must be Mesa's bit for bit, NaN where Mesa has NaN (matrix_state); the rest of
// the state as the other state tests compare it. Hand-written rows pin the
// individual rules first.
#include <cstdint>
#include <cstring>
#include <limits>
#include <random>

#include "harness.h"
#include "state/float_matrix.h"

namespace ffc::state_test {
namespace {

constexpr GLenum OK = GL_NO_ERROR;
constexpr float kInf = std::numeric_limits<float>::infinity();
constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();

void load(std::initializer_list<float> v) {
  GLfloat m[16];
  std::copy(v.begin(), v.end(), m);
  glLoadMatrixf(m);
}
void translation_inf() { load({1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, kInf, 0, 0, 1}); }
void draw_nothing() {
  glBegin(GL_POINTS);
  glEnd();
}

// The matrices, light positions and spot directions glGetFloatv / glGetLightfv return, read on
// each side after the case's calls, compared bit for bit (any NaN matching any NaN); the rest of
// the state as check_case compares it.
std::vector<float> matrix_state() {
  std::vector<float> out;
  for (GLenum p : {GL_MODELVIEW_MATRIX, GL_PROJECTION_MATRIX, GL_TEXTURE_MATRIX}) {
    GLfloat m[16];
    glGetFloatv(p, m);
    out.insert(out.end(), m, m + 16);
  }
  for (int l = 0; l < 8; ++l)
    for (GLenum p : {GL_POSITION, GL_SPOT_DIRECTION}) {
      GLfloat v[4] = {0, 0, 0, 0};
      glGetLightfv(GLenum(GL_LIGHT0 + l), p, v);
      out.insert(out.end(), v, v + (p == GL_POSITION ? 4 : 3));
    }
  return out;
}

// The raster position and distance under non-finite matrices are left out: glRasterPos's own
// treatment of NaN and infinite coordinates is not this model's (the fuzzer's `rasterpos`
// category, not yet held by the fuzz_agreeing CTest). The matrices it leaves behind are compared.
std::vector<std::string> raster_slots() {
  std::vector<std::string> out;
  size_t n = 0;
  for (const Probe& p : probes()) n += size_t(p.slots);
  for (size_t i = 0; i < n; ++i) {
    const std::string name = slot_name(i);
    if (name.find("RASTER") != std::string::npos || name.find("0x0B09") != std::string::npos) out.push_back(name);
  }
  return out;
}

void check_exactly(Case c) {
  static const std::vector<std::string> raster = raster_slots();
  c.unchecked = raster;
  check_case(c);
  std::vector<float> got[2];
  for (Side s : {kMesa, kSoft}) {
    fresh_context(s);
    if (c.setup) c.setup();
    c.call();
    got[s] = matrix_state();
  }
  ASSERT_EQ(got[kMesa].size(), got[kSoft].size());
  int bad = 0;
  for (size_t i = 0; i < got[kMesa].size(); ++i) {
    const float a = got[kMesa][i], b = got[kSoft][i];
    const bool same = (std::isnan(a) && std::isnan(b)) || std::memcmp(&a, &b, sizeof a) == 0;
    if (!same && ++bad <= 8) ADD_FAILURE() << "value " << i << ": mesa " << num(a) << ", soft " << num(b);
  }
  EXPECT_EQ(bad, 0);
}

class MatrixRules : public ::testing::TestWithParam<Case> {};
TEST_P(MatrixRules, MatchMesaExactly) { check_exactly(GetParam()); }

INSTANTIATE_TEST_SUITE_P(Rules, MatrixRules, ::testing::ValuesIn(std::vector<Case>{
  // A loaded matrix is general until analysed: a rotation then takes the 4x4 product (inf * 0).
  {"LoadedThenRotatedIsGeneral", nullptr, [] { translation_inf(); glRotatef(30, 0, 0, 1); }, OK},
  // Analysed (by a draw, glPushMatrix, a spot direction, glReadPixels, glRasterPos): affine, 3x4.
  {"AnalysedByDrawIsAffine", nullptr, [] { translation_inf(); draw_nothing(); glRotatef(30, 0, 0, 1); }, OK},
  {"AnalysedByPush", nullptr, [] { translation_inf(); glPushMatrix(); glPopMatrix(); glRotatef(30, 0, 0, 1); }, OK},
  {"AnalysedBySpotDirection", nullptr, [] {
     translation_inf();
     light4(GL_LIGHT1, GL_SPOT_DIRECTION, 0, 0, -1, 0);
     glRotatef(30, 0, 0, 1);
   }, OK},
  {"AnalysedByReadPixels", nullptr, [] {
     translation_inf();
     GLubyte p[4];
     glReadPixels(0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, p);
     glRotatef(30, 0, 0, 1);
   }, OK},
  {"AnalysedByRasterPos", nullptr, [] { translation_inf(); glRasterPos2f(0, 0); glRotatef(30, 0, 0, 1); }, OK},
  // Not analysed by glClear, glGet, glFlush, nor a light position.
  {"NotAnalysedByClear", nullptr, [] { translation_inf(); glClear(GL_COLOR_BUFFER_BIT); glRotatef(30, 0, 0, 1); }, OK},
  {"NotAnalysedByLightPosition", nullptr, [] {
     translation_inf();
     light4(GL_LIGHT2, GL_POSITION, 1, 2, 3, 1);
     glRotatef(30, 0, 0, 1);
   }, OK},
  // The projection is not analysed by a draw (no clip planes), the texture matrix is.
  {"ProjectionNotAnalysedByDraw", nullptr, [] {
     glMatrixMode(GL_PROJECTION);
     translation_inf();
     draw_nothing();
     glRotatef(30, 0, 0, 1);
   }, OK},
  {"TextureAnalysedByDraw", nullptr, [] {
     glMatrixMode(GL_TEXTURE);
     translation_inf();
     draw_nothing();
     glRotatef(30, 0, 0, 1);
   }, OK},
  // The same values loaded again change nothing; an identity glMultMatrix is skipped; so is a
  // rotation by 0 degrees.
  {"SameLoadKeepsFlags", nullptr, [] { translation_inf(); draw_nothing(); translation_inf(); glRotatef(30, 0, 0, 1); }, OK},
  {"IdentityMultSkipped", nullptr, [] {
     translation_inf();
     draw_nothing();
     const GLfloat id[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
     glMultMatrixf(id);
     glRotatef(30, 0, 0, 1);
   }, OK},
  {"ZeroAngleRotationSkipped", nullptr, [] {
     translation_inf();
     draw_nothing();
     glRotatef(0, 1, 2, 3);
     glRotatef(30, 0, 0, 1);
   }, OK},
  // glLoadIdentity keeps the flags gathered before it: still general.
  {"LoadIdentityKeepsFlags", nullptr, [] {
     glFrustum(-1, 1, -1, 1, 1, 10);
     glLoadIdentity();
     glTranslatef(kInf, 0, 0);
     glRotatef(30, 0, 0, 1);
   }, OK},
  // A singular matrix, once analysed, multiplies as a general one.
  {"SingularAfterAnalysisIsGeneral", nullptr, [] {
     glScalef(0, 1, 1);
     glTranslatef(kInf, 0, 0);
     draw_nothing();
     glRotatef(30, 0, 0, 1);
   }, OK},
  // A spot direction ignores the modelview's translation, infinite or not.
  {"SpotDirectionIgnoresInfiniteTranslation", [] { glTranslatef(kInf, 0, 0); },
   [] { light4(GL_LIGHT3, GL_SPOT_DIRECTION, 1, 2, 3, 0); }, OK},
  {"PositionUnderNaN", [] { glRotatef(kNaN, 0, 0, 1); }, [] { light4(GL_LIGHT3, GL_POSITION, 1, 2, 3, 1); }, OK},
  // Mesa checks glFrustum's and glOrtho's arguments once converted to float.
  {"FrustumNearUnderflowsToZero", nullptr, [] { glFrustum(-1, 1, -1, 1, 1e-50, 10); }, GL_INVALID_VALUE},
  {"OrthoEqualInFloat", nullptr, [] { glOrtho(1, 1 + 1e-10, -1, 1, 1, 10); }, GL_INVALID_VALUE},
}), case_name);

// ---------------------------------------------------------------- generated sequences

// One generated sequence, a pure function of its seed (so both sides make the same calls).
void sequence(uint32_t seed) {
  std::mt19937 rng(seed);
  auto pick = [&](int n) { return int(rng() % uint32_t(n)); };
  auto value = [&]() -> float {
    switch (pick(12)) {
      case 0: return kInf;
      case 1: return -kInf;
      case 2: return kNaN;
      case 3: return 0.0f;
      case 4: return -0.0f;
      case 5: return 1.0f;
      case 6: return 3e38f;
      case 7: return -1e30f;
      case 8: return 1e-30f;
      default: return std::uniform_real_distribution<float>(-4, 4)(rng);
    }
  };
  // Mostly plain values, a special one now and then.
  auto arg = [&]() { return pick(4) == 0 ? value() : std::uniform_real_distribution<float>(-3, 3)(rng); };
  int depth[3] = {0, 0, 0};  // modelview, projection, texture
  const GLenum modes[3] = {GL_MODELVIEW, GL_PROJECTION, GL_TEXTURE};
  const int max_depth[3] = {31, 31, 9};
  int mode = 0;
  const int n = 8 + pick(20);
  for (int i = 0; i < n; ++i) {
    switch (pick(17)) {
      case 0: glLoadIdentity(); break;
      case 1:
      case 2: {
        GLfloat m[16];
        // An affine matrix most of the time (bottom row 0 0 0 1), so that analysis finds types.
        for (int k = 0; k < 16; ++k) m[k] = (k % 4 == 3) ? (k == 15 ? 1.0f : 0.0f) : arg();
        if (pick(3) == 0) m[3 + 4 * pick(4)] = arg();
        if (pick(3) == 0)  // diagonal only, now and then
          for (int k : {1, 2, 4, 6, 8, 9}) m[k] = 0;
        if (pick(2)) glLoadMatrixf(m);
        else glMultMatrixf(m);
        break;
      }
      case 3: glRotatef(pick(5) == 0 ? 0.0f : arg() * 60, pick(3) ? 0.0f : arg(), pick(3) ? 0.0f : arg(), arg()); break;
      case 4: {
        const float s = arg();
        if (pick(2)) glScalef(s, s, s);
        else glScalef(arg(), arg(), arg());
        break;
      }
      case 5: glTranslatef(arg(), arg(), arg()); break;
      case 6: {
        // Finite sides (an infinite one would equal its partner: GL_INVALID_VALUE); a special far.
        const float l = std::uniform_real_distribution<float>(-3, 3)(rng), b = std::uniform_real_distribution<float>(-3, 3)(rng);
        glOrtho(l, l + 1 + pick(3), b, b + 2, 0.5, pick(2) ? value() : 7.0f);
        break;
      }
      case 7: glFrustum(-1, 1 + pick(2), -1, 1, 0.5 + pick(3), 20); break;
      case 8:
        if (depth[mode] < max_depth[mode]) glPushMatrix(), ++depth[mode];
        break;
      case 9:
        if (depth[mode] > 0) glPopMatrix(), --depth[mode];
        break;
      case 10: mode = pick(3), glMatrixMode(modes[mode]); break;
      case 11: draw_nothing(); break;
      case 12: glRasterPos2f(0.25f, 0.5f); break;
      case 13: {
        GLubyte p[4];
        glReadPixels(0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, p);
        break;
      }
      case 14: light4(GLenum(GL_LIGHT0 + pick(8)), GL_POSITION, arg(), arg(), arg(), pick(2) ? 1.0f : arg()); break;
      case 15: light4(GLenum(GL_LIGHT0 + pick(8)), GL_SPOT_DIRECTION, arg(), arg(), arg(), 0); break;
      case 16: glClear(GL_COLOR_BUFFER_BIT); break;
    }
  }
  glMatrixMode(GL_MODELVIEW);
  light4(GL_LIGHT7, GL_POSITION, 1, -2, 3, 1);
  light4(GL_LIGHT6, GL_SPOT_DIRECTION, -1, 0.5f, 2, 0);
}

std::vector<Case> generated(int count) {
  std::vector<Case> cases;
  for (int i = 0; i < count; ++i) {
    const uint32_t seed = 0x6d61u * 1000u + uint32_t(i);
    cases.push_back({"Seq" + std::to_string(i), nullptr, [seed] { sequence(seed); }, OK});
  }
  return cases;
}

class MatrixSequences : public ::testing::TestWithParam<Case> {};
TEST_P(MatrixSequences, MatchMesaExactly) { check_exactly(GetParam()); }
INSTANTIATE_TEST_SUITE_P(Generated, MatrixSequences, ::testing::ValuesIn(generated(400)), case_name);

// ---------------------------------------------------------------- the inverse, for its users

// M^-1 M within float rounding of the identity.
void expect_inverts(state::fmat::Matrix m, const char* what) {
  const glm::mat4 p = m.inverse() * m.values();
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) EXPECT_NEAR(p[c][r], c == r ? 1.0f : 0.0f, 1e-5f) << what << " [" << c << "][" << r << "]";
}

TEST(MatrixInverse, ByType) {
  using state::fmat::Matrix;
  using state::fmat::Type;
  Matrix rigid;
  rigid.translate(1, -2, 3), rigid.rotate(30, 1, 1, 0);
  rigid.analyse();
  EXPECT_EQ(rigid.type(), Type::Affine);
  EXPECT_TRUE(rigid.length_preserving());
  expect_inverts(rigid, "rotation and translation");

  Matrix uniform = rigid;
  uniform.scale(2, 2, 2);
  uniform.analyse();
  EXPECT_FALSE(uniform.length_preserving());
  expect_inverts(uniform, "uniform scale");

  Matrix skew = rigid;
  skew.scale(2, 0.5f, 1.5f);
  expect_inverts(skew, "general scale");

  Matrix no_rot;
  no_rot.translate(4, 5, 6), no_rot.scale(2, 3, 4);
  no_rot.analyse();
  EXPECT_EQ(no_rot.type(), Type::NoRot3D);
  expect_inverts(no_rot, "scale and translation");

  Matrix persp;
  persp.frustum(-1, 1, -1, 1, 1, 10);
  persp.analyse();
  EXPECT_EQ(persp.type(), Type::Perspective);
  expect_inverts(persp, "frustum");

  // Values loaded are looked at when analysed: a rotation's values give the rotation flag back.
  Matrix loaded;
  loaded.load(rigid.values());
  loaded.analyse();
  EXPECT_EQ(loaded.type(), Type::Affine);
  EXPECT_TRUE(loaded.length_preserving());

  // A singular matrix: flagged, and its inverse is the identity (as Mesa leaves it).
  Matrix flat;
  flat.scale(0, 1, 1);
  flat.analyse();
  EXPECT_NE(flat.flags() & state::fmat::kSingular, 0u);
  EXPECT_EQ(flat.inverse(), glm::mat4(1.0f));
}

}  // namespace
}  // namespace ffc::state_test
