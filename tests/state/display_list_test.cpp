// Display lists against Mesa (GL 2.1 section 5.4): the name space, compiling and executing, the
// errors and when they are raised, glCallLists with every type, the nesting limit, what executes
// at once while compiling, vertex arrays read at compile time, and pictures and feedback of lists
// (materials, colours and normals in lists, lists calling lists, a glBegin left open by a list).
#include <algorithm>
#include <cstring>

#include "harness.h"

namespace ffc::state_test {
namespace {

constexpr GLenum OK = GL_NO_ERROR, IO = GL_INVALID_OPERATION, IE = GL_INVALID_ENUM, IV = GL_INVALID_VALUE;

class DisplayLists : public ::testing::TestWithParam<Case> {};
TEST_P(DisplayLists, MatchesMesa) { check_case(GetParam()); }

void observe_error(const char* label) { observe(label, glGetError()); }

// Compiles `body` into list `name` in `mode`.
void compile(GLuint name, GLenum mode, void (*body)()) {
  glNewList(name, mode);
  body();
  glEndList();
}

void lit_scene() {
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  glEnable(GL_DEPTH_TEST);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
}

// A lit fan with normals set between its vertices, and its material.
void first_fan() {
  material4(GL_FRONT_AND_BACK, GL_DIFFUSE, 0.8f, 0.3f, 0.2f, 1);
  glBegin(GL_TRIANGLE_FAN);
  glNormal3f(0, 0, 1), glVertex3f(-0.9f, -0.9f, 0);
  glNormal3f(0.3f, 0, 1), glVertex3f(0.9f, -0.8f, 0.2f);
  glNormal3f(0, 0.5f, 1), glVertex3f(0.7f, 0.9f, -0.3f);
  glEnd();
}

// The first fan, then a second with another material (set outside glBegin/glEnd: inside, see
// MaterialInsideBeginEndInList).
void lit_fan() {
  first_fan();
  material4(GL_FRONT, GL_DIFFUSE, 0.1f, 0.9f, 0.2f, 1);
  glMaterialf(GL_FRONT, GL_SHININESS, 20);
  material4(GL_FRONT, GL_SPECULAR, 1, 1, 1, 1);
  glBegin(GL_TRIANGLE_FAN);
  glNormal3f(-0.4f, 0.2f, 1), glVertex3f(-0.8f, 0.6f, 0);
  glNormal3f(0, 0, 1), glVertex3f(-0.9f, -0.9f, 0);
  glNormal3f(0, 0.5f, 1), glVertex3f(0.7f, 0.9f, -0.3f);
  glEnd();
}

// A glMaterial between glBegin and glEnd in a list: Mesa's compiled vertex list splits the fan
// where the material appears and plays it back as four triangles, not two, and leaves the
// material state at the value set outside the primitive (docs/deviations.md). Soft replays the
// calls as made. Pinned here so that a Mesa that changes shows.
TEST(DisplayListsKnown, MaterialInsideBeginEndInList) {
  auto fan = [] {
    glEnable(GL_LIGHTING), glEnable(GL_LIGHT0);
    glNewList(1, GL_COMPILE);
    material4(GL_FRONT_AND_BACK, GL_DIFFUSE, 0.8f, 0.3f, 0.2f, 1);
    glBegin(GL_TRIANGLE_FAN);
    glNormal3f(0, 0, 1), glVertex3f(-0.9f, -0.9f, 0);
    glNormal3f(0.3f, 0, 1), glVertex3f(0.9f, -0.8f, 0.2f);
    material4(GL_FRONT_AND_BACK, GL_DIFFUSE, 0.1f, 0.9f, 0.2f, 1);
    glNormal3f(0, 0.5f, 1), glVertex3f(0.7f, 0.9f, -0.3f);
    glNormal3f(-0.4f, 0.2f, 1), glVertex3f(-0.8f, 0.6f, 0);
    glEnd();
    glEndList();
  };
  GLint count[2];
  GLfloat diffuse[2][4];
  for (Side s : {kMesa, kSoft}) {
    fresh_context(s);
    fan();
    static GLfloat buf[256];
    glFeedbackBuffer(256, GL_3D_COLOR, buf);
    glRenderMode(GL_FEEDBACK);
    glCallList(1);
    count[s] = glRenderMode(GL_RENDER);
    glGetMaterialfv(GL_FRONT, GL_DIFFUSE, diffuse[s]);
  }
  EXPECT_EQ(count[kSoft], 2 * 23) << "two triangles of GL_3D_COLOR";
  EXPECT_EQ(count[kMesa], 4 * 23) << "Mesa's split fan no longer plays back as four triangles";
  EXPECT_FLOAT_EQ(diffuse[kSoft][1], 0.9f);
  EXPECT_FLOAT_EQ(diffuse[kMesa][1], 0.3f) << "Mesa now leaves the material set inside the primitive";
}

void coloured_triangles() {
  glBegin(GL_TRIANGLES);
  glColor3f(1, 0, 0), glVertex2f(-1, -1);
  glColor4f(0, 1, 0, 0.5f), glVertex2f(1, -1);
  glColor3ub(0, 0, 255), glVertex2f(0, 1);
  glEnd();
}

// List k (k = 1..n) translates by 1 along x and calls list k + 1: how many ran shows in the matrix.
void chain(int n) {
  for (int k = 1; k <= n; ++k) {
    glNewList(GLuint(k), GL_COMPILE);
    glTranslatef(1, 0, 0);
    glCallList(GLuint(k + 1));
    glEndList();
  }
}

// glCallLists over lists 10..13 (each a translation by 1, 10, 100, 1000 along x) with base 10:
// the names as `type` spells 0, 1, 2, 3, 2 (the matrix then says which ran, and how often).
template <typename T>
Calls call_lists(GLenum type, std::vector<T> names) {
  return [=] {
    const float steps[4] = {1, 10, 100, 1000};
    for (int k = 0; k < 4; ++k) {
      glNewList(GLuint(10 + k), GL_COMPILE);
      glTranslatef(steps[k], 0, 0);
      glEndList();
    }
    glListBase(10);
    glCallLists(GLsizei(names.size() * sizeof(T) / (type == GL_2_BYTES ? 2 : type == GL_3_BYTES ? 3 : type == GL_4_BYTES ? 4 : sizeof(T))),
                type, names.data());
  };
}

const GLfloat kPositions[] = {-1, -1, 0, 1, -1, 0, 0, 1, 0, -1, 1, 0};
const GLfloat kColours[] = {1, 0, 0, 1, 0, 1, 0, 1, 0, 0, 1, 1, 1, 1, 0, 1};
const GLshort kNormals[] = {0, 0, 32767, 0, 20000, 20000, -3000, 0, 32767, 0, 0, 32767};

// Arrays enabled over a copy that the case overwrites after compiling: the list keeps the old values.
void arrays_on(GLfloat* positions) {
  std::memcpy(positions, kPositions, sizeof kPositions);
  glEnableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_COLOR_ARRAY);
  glEnableClientState(GL_NORMAL_ARRAY);
  glVertexPointer(3, GL_FLOAT, 0, positions);
  glColorPointer(4, GL_FLOAT, 0, kColours);
  glNormalPointer(GL_SHORT, 0, kNormals);
}

std::vector<Case> cases() {
  std::vector<Case> v = {
    // The name space.
    {"GenListsReturnsFirst", nullptr, [] { observe("a", glGenLists(3)); observe("b", glGenLists(2)); }, OK},
    {"GenListsZero", nullptr, [] { observe("a", glGenLists(0)); }, OK},
    {"GenListsNegative", nullptr, [] { observe("a", glGenLists(-1)); }, IV},
    {"GenListsSkipsUsedNames", nullptr, [] {
       compile(2, GL_COMPILE, [] { glColor3f(1, 0, 0); });
       observe("a", glGenLists(1)), observe("b", glGenLists(2));
     }, OK},
    {"GenListsAfterDelete", nullptr, [] {
       const GLuint a = glGenLists(5);
       glDeleteLists(a + 1, 2);
       observe("a", glGenLists(2)), observe("b", glGenLists(1));
     }, OK},
    {"IsList", nullptr, [] {
       const GLuint a = glGenLists(2);
       observe("generated", glIsList(a));
       compile(7, GL_COMPILE, [] {});
       observe("empty compiled", glIsList(7)), observe("zero", glIsList(0)), observe("unused", glIsList(99));
       glDeleteLists(7, 1);
       observe("deleted", glIsList(7));
     }, OK},
    {"IsListWhileCompilingIt", nullptr, [] {
       glNewList(4, GL_COMPILE);
       observe("compiling", glIsList(4));
       glEndList();
       observe("after", glIsList(4));
     }, OK},
    {"DeleteListsNegative", nullptr, [] { glDeleteLists(1, -1); }, IV},
    {"DeleteListsUnused", nullptr, [] { glDeleteLists(0, 5); }, OK},
    // Compiling: the state reported, and the errors.
    {"ListIndexAndModeWhileCompiling", nullptr, [] { glNewList(5, GL_COMPILE); }, OK},
    {"ListModeCompileAndExecute", nullptr, [] { glNewList(6, GL_COMPILE_AND_EXECUTE); }, OK},
    {"ListBase", nullptr, [] { glListBase(42); }, OK},
    {"NewListZero", nullptr, [] { glNewList(0, GL_COMPILE); }, IV},
    {"NewListBadMode", nullptr, [] { glNewList(1, GL_RENDER); }, IE},
    {"NewListZeroBadMode", nullptr, [] { glNewList(0, GL_RENDER); }, IV},
    {"NewListWhileCompiling", [] { glNewList(1, GL_COMPILE); }, [] { glNewList(2, GL_COMPILE); }, IO},
    {"EndListWithoutNewList", nullptr, [] { glEndList(); }, IO},
    {"NewListInsideBeginEnd", nullptr, inside([] { glNewList(1, GL_COMPILE); }), IO},
    {"GenListsInsideBeginEnd", nullptr, inside([] { observe("a", glGenLists(1)); }), IO},
    {"ListBaseInsideBeginEnd", nullptr, inside([] { glListBase(3); }), IO},
    {"CallListsBadType", nullptr, [] { const GLuint n[1] = {1}; glCallLists(1, GL_DOUBLE, n); }, IE},
    {"CallListsNegative", nullptr, [] { const GLuint n[1] = {1}; glCallLists(-1, GL_UNSIGNED_INT, n); }, IV},
    {"CallListsNegativeBadType", nullptr, [] { const GLuint n[1] = {1}; glCallLists(-1, GL_DOUBLE, n); }, IE},
    {"CallListUnknownName", nullptr, [] { glCallList(12345); }, OK},
    {"CallListZero", nullptr, [] { glCallList(0); }, IV},
    {"CallListZeroInList", nullptr, [] {
       compile(1, GL_COMPILE, [] { glCallList(0); glTranslatef(1, 0, 0); });
       observe_error("compile");
       glCallList(1);
     }, OK},
    // (glCallList(0) inside the list's glBegin crashes Mesa 22.3 at glEndList: not a row.)
    {"StateCallInsideListBegin", nullptr, [] {
       glNewList(1, GL_COMPILE_AND_EXECUTE);
       glBegin(GL_TRIANGLES);
       glEnable(GL_LIGHTING);
       observe_error("enable");
       observe("enabled", glIsEnabled(GL_LIGHTING));
       glEnd();
       glEndList();
       glCallList(1);
     }, IO},
    // GL_COMPILE records without executing; GL_COMPILE_AND_EXECUTE does both.
    {"CompileDoesNotExecute", nullptr, [] {
       compile(1, GL_COMPILE, [] { glColor4f(0.1f, 0.2f, 0.3f, 0.4f); glEnable(GL_LIGHTING); glTranslatef(1, 2, 3); });
     }, OK},
    {"CompileAndExecute", nullptr, [] {
       compile(1, GL_COMPILE_AND_EXECUTE, [] { glColor4f(0.1f, 0.2f, 0.3f, 0.4f); glEnable(GL_LIGHTING); glTranslatef(1, 2, 3); });
     }, OK},
    {"CompiledThenCalledTwice", nullptr, [] {
       compile(1, GL_COMPILE, [] { glTranslatef(1, 2, 3); glRotatef(30, 0, 0, 1); glNormal3f(0, 1, 0); });
       glCallList(1), glCallList(1);
     }, OK},
    {"EveryRecordedKind", nullptr, [] {
       compile(3, GL_COMPILE, [] {
         glMatrixMode(GL_PROJECTION), glLoadIdentity(), glOrtho(-2, 2, -2, 2, -3, 3), glMatrixMode(GL_MODELVIEW);
         const GLdouble m[16] = {1, 0, 0, 0, 0, 2, 0, 0, 0, 0, 1, 0, 0.5, 0, 0, 1};
         glPushMatrix(), glMultMatrixd(m), glScalef(1, 2, 3), glPopMatrix(), glLoadMatrixd(m);
         light4(GL_LIGHT1, GL_POSITION, 1, 2, 3, 0), light1(GL_LIGHT1, GL_SPOT_CUTOFF, 30);
         model4(GL_LIGHT_MODEL_AMBIENT, 0.3f, 0.2f, 0.1f, 1), glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, 1);
         material4(GL_BACK, GL_SPECULAR, 0.5f, 0.5f, 0.1f, 1), glMaterialf(GL_FRONT, GL_SHININESS, 17);
         const GLfloat fog[4] = {0.1f, 0.2f, 0.3f, 0.4f};
         glFogfv(GL_FOG_COLOR, fog), glFogi(GL_FOG_MODE, GL_LINEAR), glFogf(GL_FOG_END, 7);
         glShadeModel(GL_FLAT), glCullFace(GL_FRONT), glFrontFace(GL_CW), glDepthFunc(GL_GEQUAL);
         glDepthRange(0.2, 0.7), glViewport(1, 2, 3, 4), glPointSize(3), glLineWidth(2), glPolygonOffset(1, 2);
         glClearColor(0.5f, 0.25f, 0, 1), glClearDepth(0.5), glColorMaterial(GL_FRONT, GL_EMISSION);
         glEnable(GL_NORMALIZE), glDisable(GL_DITHER), glRasterPos2f(0.25f, 0.5f);
       });
       observe_error("after compile");
       glCallList(3);
     }, OK},
    // Errors of recorded calls are raised when the list runs, not while it is compiled.
    {"RecordedErrorAtCompile", nullptr, [] { compile(1, GL_COMPILE, [] { glEnable(0x1234); glMatrixMode(7); }); }, OK},
    {"RecordedErrorAtExecution", nullptr, [] {
       compile(1, GL_COMPILE, [] { glEnable(0x1234); glMatrixMode(7); });
       glCallList(1);
     }, IE},
    {"RecordedErrorCompileAndExecute", nullptr, [] { compile(1, GL_COMPILE_AND_EXECUTE, [] { glShadeModel(0); }); }, IE},
    {"BeginBadModeInList", nullptr, [] {
       compile(1, GL_COMPILE, [] { glBegin(0x55); glEnd(); });
       observe_error("compile");
       glCallList(1);
     }, IE},
    {"NestedBeginInList", nullptr, [] {
       compile(1, GL_COMPILE, [] { glBegin(GL_POINTS); glBegin(GL_POINTS); glEnd(); });
       observe_error("compile");
       glCallList(1);
     }, IO},
    {"EndWithoutBeginInList", nullptr, [] {
       compile(1, GL_COMPILE, [] { glEnd(); });
       observe_error("compile");
       glCallList(1);
     }, IO},
    // Executed at once, not compiled (section 5.4).
    {"ImmediateWhileCompiling", nullptr, [] {
       static GLfloat fb[8];
       glNewList(1, GL_COMPILE);
       glEnableClientState(GL_VERTEX_ARRAY), glVertexPointer(2, GL_FLOAT, 8, kPositions);
       glPixelStorei(GL_PACK_ALIGNMENT, 2), glFeedbackBuffer(8, GL_3D, fb), glFlush(), glFinish();
       observe("gen", glGenLists(2));
       observe("islist", glIsList(1));
       observe("enabled", glIsEnabled(GL_VERTEX_ARRAY));
       glEndList();
       glDisableClientState(GL_VERTEX_ARRAY);
       glCallList(1);
     }, OK},
    {"RenderModeWhileCompiling", nullptr, [] {
       static GLfloat fb[8];
       glFeedbackBuffer(8, GL_3D, fb);
       glNewList(1, GL_COMPILE);
       observe("enter", glRenderMode(GL_FEEDBACK));
       glEndList();
     }, OK},
    {"DeleteListsWhileCompilingIt", nullptr, [] {
       compile(1, GL_COMPILE, [] { glTranslatef(5, 0, 0); });
       glNewList(1, GL_COMPILE);
       glTranslatef(0, 1, 0);
       glDeleteLists(1, 1);
       glCallList(1);
       glEndList();
       glCallList(1);
     }, OK},
    {"CallListOfListBeingCompiled", nullptr, [] {
       compile(1, GL_COMPILE, [] { glTranslatef(5, 0, 0); });
       glNewList(1, GL_COMPILE_AND_EXECUTE);
       glScalef(2, 2, 2);
       glCallList(1);  // the old list 1, then (when the new one runs) the new one, which is not itself
       glEndList();
     }, OK},
    // Lists calling lists, glListBase compiled, the nesting limit.
    {"ListsCallLists", nullptr, [] {
       compile(2, GL_COMPILE, [] { glTranslatef(0, 1, 0); });
       compile(1, GL_COMPILE, [] { glScalef(2, 2, 2); glCallList(2); glCallList(2); });
       compile(3, GL_COMPILE_AND_EXECUTE, [] { glCallList(1); glRotatef(90, 0, 0, 1); glCallList(2); });
       glCallList(3);
     }, OK},
    {"CallListLaterDefined", nullptr, [] {
       compile(1, GL_COMPILE, [] { glCallList(2); });
       compile(2, GL_COMPILE, [] { glTranslatef(3, 0, 0); });
       glCallList(1);
     }, OK},
    {"NestingLimit", nullptr, [] { chain(70); glCallList(1); }, OK},
    {"NestingLimitFromCompileAndExecute", nullptr, [] {
       chain(70);
       compile(100, GL_COMPILE_AND_EXECUTE, [] { glCallList(1); });
       glCallList(100);
     }, OK},
    {"SelfCallingList", nullptr, [] {
       compile(1, GL_COMPILE, [] { glTranslatef(0.5f, 0, 0); glCallList(1); });
       glCallList(1);
     }, OK},
    {"ListBaseInList", nullptr, [] {
       compile(1, GL_COMPILE, [] { glListBase(7); });
       observe_error("compile");
       glCallList(1);
     }, OK},
    {"CallListsCompiledUsesBaseAtExecution", nullptr, [] {
       compile(10, GL_COMPILE, [] { glTranslatef(1, 0, 0); });
       compile(20, GL_COMPILE, [] { glTranslatef(0, 1, 0); });
       glListBase(10);
       compile(1, GL_COMPILE, [] { const GLubyte n[2] = {0, 0}; glCallLists(2, GL_UNSIGNED_BYTE, n); });
       glListBase(20);
       glCallList(1);
     }, OK},
    {"CallListsByte", nullptr, call_lists<GLbyte>(GL_BYTE, {0, 1, 2, 3, 2, -1}), OK},
    {"CallListsUnsignedByte", nullptr, call_lists<GLubyte>(GL_UNSIGNED_BYTE, {0, 1, 2, 3, 2}), OK},
    {"CallListsShort", nullptr, call_lists<GLshort>(GL_SHORT, {0, 1, 2, 3, 2, -10}), OK},
    {"CallListsUnsignedShort", nullptr, call_lists<GLushort>(GL_UNSIGNED_SHORT, {0, 1, 2, 3, 2}), OK},
    {"CallListsInt", nullptr, call_lists<GLint>(GL_INT, {0, 1, 2, 3, 2}), OK},
    {"CallListsUnsignedInt", nullptr, call_lists<GLuint>(GL_UNSIGNED_INT, {0, 1, 2, 3, 2}), OK},
    {"CallListsFloat", nullptr, call_lists<GLfloat>(GL_FLOAT, {0, 1.75f, 2.5f, 3, -0.5f}), OK},
    {"CallLists2Bytes", nullptr, call_lists<GLubyte>(GL_2_BYTES, {0, 0, 0, 1, 0, 2, 0, 3, 1, 0}), OK},
    {"CallLists3Bytes", nullptr, call_lists<GLubyte>(GL_3_BYTES, {0, 0, 3, 0, 0, 1, 0, 1, 0}), OK},
    {"CallLists4Bytes", nullptr, call_lists<GLubyte>(GL_4_BYTES, {0, 0, 0, 2, 0, 0, 0, 1, 1, 0, 0, 0}), OK},
    // Pictures and feedback of lists.
    {"LitFanFromList", lit_scene, [] { compile(1, GL_COMPILE, lit_fan); glCallList(1); observe_picture("px"); }, OK},
    // GL_COMPILE_AND_EXECUTE holds the vertex stream back until the next state call: a glMaterial
    // between two primitives executes before the first is drawn (docs/deviations.md row 50), and
    // a query inside glBegin/glEnd finds no glBegin executed yet.
    {"MaterialBetweenPrimitivesCompileAndExecute", lit_scene, feedback_into(200, GL_3D_COLOR, [] {
       compile(1, GL_COMPILE_AND_EXECUTE, lit_fan);
     }), OK},
    {"MaterialBetweenPrimitivesCompileAndExecutePicture", lit_scene, [] {
       compile(1, GL_COMPILE_AND_EXECUTE, lit_fan);
       observe_picture("px");
     }, OK},
    {"QueryInsideBeginCompileAndExecute", nullptr, [] {
       glNewList(1, GL_COMPILE_AND_EXECUTE);
       glBegin(GL_TRIANGLES);
       glColor3f(1, 0, 0);
       GLfloat c[4];
       glGetFloatv(GL_CURRENT_COLOR, c);
       observe("red", c[0]);
       observe_error("inside");
       glVertex2f(0, 0), glVertex2f(1, 0), glVertex2f(0, 1);
       glEnd();
       glGetFloatv(GL_CURRENT_COLOR, c);
       observe("red after", c[0]);
       glEnable(GL_DEPTH_TEST);
       glGetFloatv(GL_CURRENT_COLOR, c);
       observe("red after a state call", c[0]);
       glEndList();
     }, OK},
    {"DrawArraysCompileAndExecute", [] { static GLfloat pos[12]; arrays_on(pos); }, feedback_into(120, GL_3D_COLOR, [] {
       glNewList(1, GL_COMPILE_AND_EXECUTE);
       glDrawArrays(GL_TRIANGLES, 0, 3);
       glArrayElement(3);
       glTranslatef(0.5f, 0, 0);
       glDrawArrays(GL_POINTS, 1, 2);
       glEndList();
     }), OK},
    {"LitFanCompileAndExecute", lit_scene, [] {
       compile(1, GL_COMPILE_AND_EXECUTE, [] {
         first_fan();
         glDisable(GL_LIGHTING);
         coloured_triangles();
       });
       glCallList(1);
       observe_picture("px");
     }, OK},
    {"LitFanCompileAndExecuteFeedback", lit_scene, feedback_into(200, GL_3D_COLOR, [] {
       material4(GL_FRONT, GL_DIFFUSE, 0.1f, 0.9f, 0.2f, 1);
       compile(1, GL_COMPILE_AND_EXECUTE, [] {
         glBegin(GL_TRIANGLES), glNormal3f(0, 0, 1), glVertex2f(0, 0), glVertex2f(1, 0), glNormal3f(0, 1, 1), glVertex2f(0, 1), glEnd();
         glTranslatef(0.1f, 0, 0);
         coloured_triangles();
       });
     }), OK},
    {"LitFanColourMaterialFromList", [] { lit_scene(); glEnable(GL_COLOR_MATERIAL); }, [] {
       compile(1, GL_COMPILE, [] { glShadeModel(GL_SMOOTH); coloured_triangles(); glColorMaterial(GL_FRONT, GL_DIFFUSE); lit_fan(); });
       glCallList(1);
       observe_picture("px");
     }, OK},
    {"ColouredTrianglesFeedback", nullptr, feedback_into(80, GL_3D_COLOR, [] {
       compile(1, GL_COMPILE, coloured_triangles);
       glCallList(1);
       glTranslatef(0.1f, 0, 0);
       glCallList(1);
     }), OK},
    {"LitFanFeedback", lit_scene, feedback_into(120, GL_3D_COLOR, [] { compile(1, GL_COMPILE, lit_fan); glCallList(1); }), OK},
    {"ListsCallingListsFeedback", nullptr, feedback_into(200, GL_3D_COLOR, [] {
       compile(2, GL_COMPILE, coloured_triangles);
       compile(1, GL_COMPILE, [] { glCallList(2); glRotatef(90, 0, 0, 1); glCallList(2); });
       glCallList(1);
     }), OK},
    {"BeginLeftOpenByList", nullptr, feedback_into(80, GL_3D_COLOR, [] {
       compile(1, GL_COMPILE, [] { glBegin(GL_TRIANGLES); glColor3f(1, 0, 0); glVertex2f(-1, -1); glVertex2f(1, -1); });
       glCallList(1);
       glColor3f(0, 1, 0), glVertex2f(0, 1);
       glEnd();
     }), OK},
    {"EndInAnotherList", nullptr, feedback_into(80, GL_3D_COLOR, [] {
       compile(1, GL_COMPILE, [] { glBegin(GL_LINES); glColor3f(1, 0, 0); glVertex2f(-1, -1); });
       compile(2, GL_COMPILE, [] { glColor3f(0, 0, 1); glVertex2f(1, 0.5f); glEnd(); });
       glCallList(1), glCallList(2);
     }), OK},
    {"CallListInsideBeginEnd", nullptr, feedback_into(80, GL_3D_COLOR, [] {
       compile(1, GL_COMPILE, [] { glColor3f(0, 0, 1); glVertex2f(1, 0.5f); });
       glBegin(GL_TRIANGLES);
       glColor3f(1, 0, 0), glVertex2f(-1, -1);
       glCallList(1);
       glVertex2f(0, 1);
       glEnd();
     }), OK},
    {"ListWithBeginCalledInsideBeginEnd", nullptr, [] {
       compile(1, GL_COMPILE, [] { glBegin(GL_POINTS); glVertex2f(0, 0); glEnd(); });
       glBegin(GL_POINTS);
       glCallList(1);
       glEnd();
     }, IO},
    // Vertex arrays are read when the list is compiled.
    {"DrawArraysReadAtCompile", lit_scene, [] {
       static GLfloat pos[12];
       arrays_on(pos);
       glNewList(1, GL_COMPILE);
       glDrawArrays(GL_TRIANGLE_FAN, 0, 4);
       glEndList();
       for (GLfloat& p : pos) p *= 0.5f;
       glCallList(1);
       observe_picture("px");
     }, OK},
    {"DrawElementsReadAtCompile", nullptr, feedback_into(80, GL_3D_COLOR, [] {
       static GLfloat pos[12];
       arrays_on(pos);
       static const GLushort idx[] = {0, 1, 2, 2, 3, 0};
       glNewList(1, GL_COMPILE);
       glDrawElements(GL_TRIANGLES, 6, GL_UNSIGNED_SHORT, idx);
       glEndList();
       pos[0] = 0.25f;
       glDisableClientState(GL_COLOR_ARRAY);
       glCallList(1);
     }), OK},
    {"ArrayElementReadAtCompile", nullptr, feedback_into(80, GL_3D_COLOR, [] {
       static GLfloat pos[12];
       arrays_on(pos);
       glNewList(1, GL_COMPILE);
       glBegin(GL_TRIANGLES), glArrayElement(2), glArrayElement(0), glArrayElement(1), glEnd();
       glEndList();
       pos[3] = 0.75f;
       glCallList(1);
     }), OK},
    {"DrawArraysBadModeInList", [] { static GLfloat pos[12]; arrays_on(pos); }, [] {
       compile(1, GL_COMPILE, [] { glDrawArrays(0x77, 0, 3); });
       observe_error("compile");
       glCallList(1);
     }, IE},
    {"DrawElementsBadTypeInList", [] { static GLfloat pos[12]; arrays_on(pos); }, [] {
       static const GLint idx[] = {0, 1, 2};
       compile(1, GL_COMPILE, [] { glDrawElements(GL_TRIANGLES, 3, GL_INT, idx); });
       observe_error("compile");
       glCallList(1);
     }, IV},
  };
  return v;
}

INSTANTIATE_TEST_SUITE_P(State, DisplayLists, ::testing::ValuesIn(cases()), case_name);

}  // namespace
}  // namespace ffc::state_test
