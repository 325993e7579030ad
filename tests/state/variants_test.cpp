// Every immediate-mode variant against Mesa: glVertex, glNormal, glColor and glTexCoord in each
// type and count, scalar and vector, with the integer extremes (the conversions are Mesa's, colour
// alpha included); glEdgeFlag; glRect; glHint; glTexCoordPointer and glInterleavedArrays in all 14
// formats; the current texture coordinates in feedback.
#include <climits>
#include <cstdint>
#include <cstring>

#include "gl/dispatch.h"
#include "harness.h"
#include "state/context.h"

namespace ffc::state_test {
namespace {

constexpr GLenum OK = GL_NO_ERROR, IO = GL_INVALID_OPERATION, IE = GL_INVALID_ENUM, IV = GL_INVALID_VALUE;

class Variants : public ::testing::TestWithParam<Case> {};
TEST_P(Variants, MatchesMesa) { check_case(GetParam()); }

// Values of each type: its extremes, zero and one in between.
template <typename T>
std::vector<T> samples() {
  if constexpr (std::is_floating_point_v<T>) return {T(0.25), T(-1.5), T(0), T(3)};
  else return {std::numeric_limits<T>::min(), std::numeric_limits<T>::max(), T(0), T(std::numeric_limits<T>::max() / 3)};
}

// The colour then the normal then the texture coordinates, set by the variant under test, with the
// current values read back (the state) and fed back through a point in GL_4D_COLOR_TEXTURE.
std::vector<Case> attribute_cases() {
  std::vector<Case> v;
  auto add = [&](const std::string& name, std::function<void()> set) {
    v.push_back({name, [] { glColor4f(0.5f, 0.5f, 0.5f, 0.25f); }, set, OK});
    v.push_back({name + "InFeedback", [] { glColor4f(0.5f, 0.5f, 0.5f, 0.25f); },
                 feedback_into(24, GL_4D_COLOR_TEXTURE, [set] { glBegin(GL_POINTS); set(); glVertex2f(0.5f, 0.25f); glEnd(); }), OK});
  };
#define FFC_TYPED(T, s)                                                                                          \
  {                                                                                                              \
    const std::vector<T> x = samples<T>();                                                                       \
    add("Color3" #s, [x] { glColor3##s(x[0], x[1], x[3]); });                                                   \
    add("Color3" #s "v", [x] { glColor3##s##v(x.data() + 1); });                                                 \
    add("Color4" #s, [x] { glColor4##s(x[3], x[0], x[1], x[2]); });                                             \
    add("Color4" #s "v", [x] { glColor4##s##v(x.data()); });                                                     \
  }
  FFC_TYPED(GLbyte, b) FFC_TYPED(GLshort, s) FFC_TYPED(GLint, i) FFC_TYPED(GLfloat, f) FFC_TYPED(GLdouble, d)
  FFC_TYPED(GLubyte, ub) FFC_TYPED(GLushort, us) FFC_TYPED(GLuint, ui)
#undef FFC_TYPED
#define FFC_NORMAL(T, s)                                                 \
  {                                                                      \
    const std::vector<T> x = samples<T>();                               \
    add("Normal3" #s, [x] { glNormal3##s(x[0], x[3], x[1]); });          \
    add("Normal3" #s "v", [x] { glNormal3##s##v(x.data() + 1); });       \
  }
  FFC_NORMAL(GLbyte, b) FFC_NORMAL(GLshort, s) FFC_NORMAL(GLint, i) FFC_NORMAL(GLfloat, f) FFC_NORMAL(GLdouble, d)
#undef FFC_NORMAL
#define FFC_TEX(T, s)                                                                   \
  {                                                                                     \
    const std::vector<T> x = {T(1), T(-2), T(3), T(5)};                                 \
    add("TexCoord1" #s, [x] { glTexCoord1##s(x[0]); });                                 \
    add("TexCoord1" #s "v", [x] { glTexCoord1##s##v(x.data() + 1); });                  \
    add("TexCoord2" #s, [x] { glTexCoord2##s(x[0], x[1]); });                           \
    add("TexCoord2" #s "v", [x] { glTexCoord2##s##v(x.data() + 1); });                  \
    add("TexCoord3" #s, [x] { glTexCoord3##s(x[0], x[1], x[2]); });                     \
    add("TexCoord3" #s "v", [x] { glTexCoord3##s##v(x.data() + 1); });                  \
    add("TexCoord4" #s, [x] { glTexCoord4##s(x[0], x[1], x[2], x[3]); });               \
    add("TexCoord4" #s "v", [x] { glTexCoord4##s##v(x.data()); });                      \
  }
  FFC_TEX(GLshort, s) FFC_TEX(GLint, i) FFC_TEX(GLfloat, f) FFC_TEX(GLdouble, d)
#undef FFC_TEX
  return v;
}

// Vertices of every count and type, fed back with their clip w.
std::vector<Case> vertex_cases() {
  std::vector<Case> v;
  auto add = [&](const std::string& name, std::function<void()> vertex) {
    v.push_back({name, nullptr, feedback_into(24, GL_4D_COLOR_TEXTURE, [vertex] { glBegin(GL_POINTS); vertex(); glEnd(); }), OK});
  };
#define FFC_VERTEX(T, s)                                                          \
  {                                                                               \
    const T x[4] = {T(1), T(-1), T(0), T(2)};                                      \
    add("Vertex2" #s, [x] { glVertex2##s(x[0], x[1]); });                          \
    add("Vertex2" #s "v", [x] { glVertex2##s##v(x); });                            \
    add("Vertex3" #s, [x] { glVertex3##s(x[1], x[0], x[2]); });                    \
    add("Vertex3" #s "v", [x] { glVertex3##s##v(x); });                            \
    add("Vertex4" #s, [x] { glVertex4##s(x[0], x[1], x[2], x[3]); });              \
    add("Vertex4" #s "v", [x] { glVertex4##s##v(x); });                            \
  }
  FFC_VERTEX(GLshort, s) FFC_VERTEX(GLint, i) FFC_VERTEX(GLfloat, f) FFC_VERTEX(GLdouble, d)
#undef FFC_VERTEX
  return v;
}

std::vector<Case> other_cases() {
  static const GLshort rs[2][2] = {{-1, 0}, {1, 1}};
  static const GLdouble rd[2][2] = {{-0.5, -0.75}, {0.25, 0.5}};
  return {
    {"EdgeFlag", nullptr, [] { glEdgeFlag(GL_FALSE); }, OK},
    {"EdgeFlagv", nullptr, [] { static const GLboolean f = GL_FALSE; glEdgeFlagv(&f); }, OK},
    {"EdgeFlagInsideBeginEnd", nullptr, inside([] { glEdgeFlag(GL_FALSE); }), OK},
    {"RectfPicture", nullptr, [] { glColor3f(1, 0.5f, 0); glRectf(-0.5f, -0.75f, 0.25f, 0.5f); observe_picture("px"); }, OK},
    {"RectiPicture", nullptr, [] { glRecti(1, 1, 0, 0); observe_picture("px"); }, OK},
    {"RectsvFeedback", nullptr, feedback_into(40, GL_3D_COLOR, [] { glRectsv(rs[0], rs[1]); }), OK},
    {"RectdvFeedback", nullptr, feedback_into(40, GL_3D_COLOR, [] { glRectdv(rd[0], rd[1]); }), OK},
    {"RectdReversed", nullptr, feedback_into(40, GL_3D_COLOR, [] { glRectd(0.5, 0.5, -0.5, -0.5); }), OK},
    {"RectCulled", [] { glEnable(GL_CULL_FACE); }, feedback_into(40, GL_3D_COLOR, [] { glRectf(0.5f, 0, 0, 0.5f); }), OK},
    {"RectInsideBeginEnd", nullptr, inside([] { glRectf(0, 0, 1, 1); }), IO},
    {"RectInList", nullptr, feedback_into(40, GL_2D, [] {
       glNewList(1, GL_COMPILE), glRectf(0, 0, 0.5f, 0.5f), glEndList();
       glCallList(1);
     }), OK},
    {"HintEach", nullptr, [] {
       glHint(GL_PERSPECTIVE_CORRECTION_HINT, GL_NICEST), glHint(GL_POINT_SMOOTH_HINT, GL_FASTEST);
       glHint(GL_LINE_SMOOTH_HINT, GL_NICEST), glHint(GL_POLYGON_SMOOTH_HINT, GL_FASTEST);
       glHint(GL_FOG_HINT, GL_NICEST), glHint(GL_GENERATE_MIPMAP_HINT, GL_FASTEST);
       glHint(GL_TEXTURE_COMPRESSION_HINT, GL_NICEST), glHint(GL_FRAGMENT_SHADER_DERIVATIVE_HINT, GL_FASTEST);
     }, OK},
    {"HintBackToDontCare", [] { glHint(GL_FOG_HINT, GL_NICEST); }, [] { glHint(GL_FOG_HINT, GL_DONT_CARE); }, OK},
    {"HintBadMode", nullptr, [] { glHint(GL_FOG_HINT, GL_RGBA); }, IE},
    {"HintBadTarget", nullptr, [] { glHint(GL_FOG, GL_NICEST); }, IE},
    {"HintBadTargetBadMode", nullptr, [] { glHint(GL_FOG, 0); }, IE},
    {"HintInsideBeginEnd", nullptr, inside([] { glHint(GL_FOG_HINT, GL_NICEST); }), IO},
    {"HintInList", nullptr, [] { glNewList(1, GL_COMPILE), glHint(GL_FOG_HINT, GL_NICEST), glEndList(); glCallList(1); }, OK},
    {"TexCoordPointer", nullptr, [] { static const GLshort t[4] = {}; glTexCoordPointer(2, GL_SHORT, 6, t); }, OK},
    {"TexCoordPointerBadSize", nullptr, [] { static const GLshort t[4] = {}; glTexCoordPointer(5, GL_SHORT, 6, t); }, IV},
    {"TexCoordPointerBadType", nullptr, [] { static const GLshort t[4] = {}; glTexCoordPointer(2, GL_UNSIGNED_BYTE, 6, t); }, IE},
    // Mesa records the error and sets the pointer all the same, as for the other arrays.
    {"TexCoordPointerNegativeStride", nullptr, [] { static const GLshort t[4] = {}; glTexCoordPointer(2, GL_SHORT, -6, t); }, IV,
     Deviation::MesaAppliesOnError},
    {"TexCoordArrayElement", nullptr, [] {
       static const GLfloat t[] = {0.5f, 0.25f, 2, 3, 4, 5};
       glEnableClientState(GL_TEXTURE_COORD_ARRAY);
       glTexCoordPointer(3, GL_FLOAT, 0, t);
       glArrayElement(1);
     }, OK},
    // Fed back as set: the texture matrix is not applied.
    {"TexCoordMatrixFeedback", nullptr, feedback_into(40, GL_4D_COLOR_TEXTURE, [] {
       glMatrixMode(GL_TEXTURE), glTranslatef(1, 2, 3), glScalef(2, 2, 2), glMatrixMode(GL_MODELVIEW);
       glBegin(GL_POINTS), glTexCoord2f(0.5f, 0.25f), glVertex2f(0, 0), glEnd();
       glBegin(GL_POINTS), glTexCoord3f(1, 2, 3), glVertex2f(0.5f, 0), glEnd();
     }), OK},
    {"InterleavedBadFormat", nullptr, [] { static const GLfloat d[16] = {}; glInterleavedArrays(GL_RGBA, 0, d); }, IE},
    {"InterleavedNegativeStride", nullptr, [] { static const GLfloat d[16] = {}; glInterleavedArrays(GL_V3F, -4, d); }, IV},
    {"InterleavedNegativeStrideBadFormat", nullptr, [] { static const GLfloat d[16] = {}; glInterleavedArrays(GL_RGBA, -4, d); }, IV},
    {"InterleavedInsideBeginEnd", nullptr, inside([] { static const GLfloat d[16] = {}; glInterleavedArrays(GL_V3F, 0, d); }), IO},
  };
}

// All 14 formats of glInterleavedArrays: the arrays it sets (read back) and three elements drawn
// as a triangle and fed back, tightly packed and with a stride of its own; over arrays enabled before.
std::vector<Case> interleaved_cases() {
  struct F {
    const char* name;
    GLenum format;
    int floats;  // an element's size in floats (a C4UB colour counts as one)
  };
  static const F kFormats[] = {
      {"V2F", GL_V2F, 2}, {"V3F", GL_V3F, 3}, {"C4UB_V2F", GL_C4UB_V2F, 3}, {"C4UB_V3F", GL_C4UB_V3F, 4},
      {"C3F_V3F", GL_C3F_V3F, 6}, {"N3F_V3F", GL_N3F_V3F, 6}, {"C4F_N3F_V3F", GL_C4F_N3F_V3F, 10},
      {"T2F_V3F", GL_T2F_V3F, 5}, {"T4F_V4F", GL_T4F_V4F, 8}, {"T2F_C4UB_V3F", GL_T2F_C4UB_V3F, 6},
      {"T2F_C3F_V3F", GL_T2F_C3F_V3F, 8}, {"T2F_N3F_V3F", GL_T2F_N3F_V3F, 8},
      {"T2F_C4F_N3F_V3F", GL_T2F_C4F_N3F_V3F, 12}, {"T4F_C4F_N3F_V4F", GL_T4F_C4F_N3F_V4F, 15}};
  // Plausible values for every slot: 0.1 steps, so that positions stay inside the view volume;
  // the bytes of a C4UB colour read whatever the float there holds.
  static GLfloat data[3 * 20];
  for (int i = 0; i < 3 * 20; ++i) data[i] = 0.05f * float(i % 13) - 0.3f;
  std::vector<Case> v;
  for (const F& f : kFormats) {
    for (int extra : {0, 2}) {
      const GLsizei stride = extra ? GLsizei((f.floats + extra) * sizeof(GLfloat)) : 0;
      const GLenum format = f.format;
      auto setup = [] {
        static const GLfloat junk[8] = {};
        glEnableClientState(GL_COLOR_ARRAY), glColorPointer(4, GL_FLOAT, 0, junk);
        glEnableClientState(GL_EDGE_FLAG_ARRAY), glEnableClientState(GL_INDEX_ARRAY);
        glEnable(GL_LIGHTING), glEnable(GL_LIGHT0);
      };
      const std::string name = std::string("Interleaved") + f.name + (extra ? "Strided" : "");
      v.push_back({name, setup, [=] { glInterleavedArrays(format, stride, data); }, OK});
      // GL_3D_COLOR: soft feeds back the current texture coordinates, not the array's (see
      // TexCoordsVaryingAreNamed).
      v.push_back({name + "Feedback", setup, feedback_into(80, GL_3D_COLOR, [=] {
                     glInterleavedArrays(format, stride, data);
                     glDisableClientState(GL_INDEX_ARRAY);
                     glDrawArrays(GL_TRIANGLES, 0, 3);
                   }), OK});
    }
  }
  return v;
}

// Texture coordinates that vary between the vertices of a draw are fed back as the current ones,
// a difference from Mesa that soft names (docs/deviations.md), for glTexCoord between vertices
// and for a texture coordinate array; one value for the whole primitive is exact (above).
TEST(VariantsSoft, TexCoordsVaryingAreNamed) {
  auto named = [] {
    return backends_env().soft && state::Context::current()->deviations().count(state::kTexCoordVarying) > 0;
  };
  static GLfloat buf[64];
  fresh_context(kSoft);
  glFeedbackBuffer(64, GL_3D_COLOR_TEXTURE, buf);
  glRenderMode(GL_FEEDBACK);
  glBegin(GL_POINTS), glTexCoord2f(1, 0), glVertex2f(0, 0), glTexCoord2f(1, 0), glVertex2f(0.5f, 0), glEnd();
  EXPECT_FALSE(named());
  glBegin(GL_POINTS), glTexCoord2f(0, 0), glVertex2f(0, 0), glTexCoord2f(1, 0), glVertex2f(0.5f, 0), glEnd();
  EXPECT_TRUE(named());
  glRenderMode(GL_RENDER);
}

INSTANTIATE_TEST_SUITE_P(Attributes, Variants, ::testing::ValuesIn(attribute_cases()), case_name);
INSTANTIATE_TEST_SUITE_P(Vertices, Variants, ::testing::ValuesIn(vertex_cases()), case_name);
INSTANTIATE_TEST_SUITE_P(Others, Variants, ::testing::ValuesIn(other_cases()), case_name);
INSTANTIATE_TEST_SUITE_P(Interleaved, Variants, ::testing::ValuesIn(interleaved_cases()), case_name);

}  // namespace
}  // namespace ffc::state_test
