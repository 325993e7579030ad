// Seed 004: a sphere approximated by subdividing an icosahedron, drawn in immediate mode. Each
// subdivision bisects the edges and pushes the midpoints out onto the unit sphere, so the faces
// multiply by 4 while every vertex stays on the sphere.
//   keys: +/- subdivision depth (0..8), F GL_FLAT, S GL_SMOOTH, N face/sphere normals
// The normals cycle between two sources only: the face's own (normCrossProd, so faceted whatever
// the shade model) and the sphere's (the unit vertex itself). An "average of adjacent faces"
// needs to know a vertex's neighbours, which this recursion never has: it draws each triangle
// as soon as it makes it.
#include <algorithm>
#include <cmath>

#include "gl/glu.h"
#include "harness.h"

#define X .525731112119133606f
#define Z .850650808352039932f

static GLfloat vdata[12][3] = {
    {-X, 0.0, Z}, {X, 0.0, Z},   {-X, 0.0, -Z}, {X, 0.0, -Z}, {0.0, Z, X},  {0.0, Z, -X},
    {0.0, -Z, X}, {0.0, -Z, -X}, {Z, X, 0.0},   {-Z, X, 0.0}, {Z, -X, 0.0}, {-Z, -X, 0.0}};

// Counterclockwise seen from outside, so normCrossProd points out and GL_FRONT is lit. The
// handout's third triangle, {4,9,5}, is clockwise ("be careful about orientation!"); it is
// {4,5,9} here, or that face would turn its normal inward and show only ambient light.
static GLuint tindices[20][3] = {
    {1, 4, 0},  {4, 9, 0},  {4, 5, 9},  {8, 5, 4},  {1, 8, 4},  {1, 10, 8}, {10, 3, 8},
    {8, 3, 5},  {3, 2, 5},  {3, 7, 2},  {3, 10, 7}, {10, 6, 7}, {6, 11, 7}, {6, 0, 11},
    {6, 1, 0},  {10, 1, 6}, {11, 0, 9}, {2, 11, 9}, {5, 2, 9},  {11, 2, 7}};

enum Normals { kFace, kSphere };
static int gDepth = 3;
static bool gSmooth = true;
static int gNormals = kFace;

static void normalize(float v[3]) {
  GLfloat d = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
  v[0] /= d;
  v[1] /= d;
  v[2] /= d;
}

static void normCrossProd(float u[3], float v[3], float out[3]) {
  out[0] = u[1] * v[2] - u[2] * v[1];
  out[1] = u[2] * v[0] - u[0] * v[2];
  out[2] = u[0] * v[1] - u[1] * v[0];
  normalize(out);
}

static void drawTriangle(GLfloat v1[3], GLfloat v2[3], GLfloat v3[3]) {
  if (gNormals == kFace) {
    GLfloat d1[3], d2[3], n[3];
    for (int k = 0; k < 3; k++) {
      d1[k] = v1[k] - v2[k];
      d2[k] = v2[k] - v3[k];
    }
    normCrossProd(d1, d2, n);
    glNormal3fv(n);
    glVertex3fv(v1);
    glVertex3fv(v2);
    glVertex3fv(v3);
  } else {  // a unit sphere's normal is the point itself
    glNormal3fv(v1);
    glVertex3fv(v1);
    glNormal3fv(v2);
    glVertex3fv(v2);
    glNormal3fv(v3);
    glVertex3fv(v3);
  }
}

static void subdivide(GLfloat v1[3], GLfloat v2[3], GLfloat v3[3], int depth) {
  GLfloat v12[3], v23[3], v31[3];
  if (depth == 0) {
    drawTriangle(v1, v2, v3);
    return;  // the handout's listing omits it and would recurse forever
  }
  for (int i = 0; i < 3; i++) {
    v12[i] = (v1[i] + v2[i]) / 2.0f;
    v23[i] = (v2[i] + v3[i]) / 2.0f;
    v31[i] = (v3[i] + v1[i]) / 2.0f;
  }
  normalize(v12);
  normalize(v23);
  normalize(v31);
  subdivide(v1, v12, v31, depth - 1);
  subdivide(v2, v23, v12, depth - 1);
  subdivide(v3, v31, v23, depth - 1);
  subdivide(v12, v23, v31, depth - 1);
}

static void display(int, int) {
  glClearColor(0, 0, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);  // the far side is drawn too; depth keeps it behind

  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  gluPerspective(45, 1, 1, 10);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  gluLookAt(0, 0, 4, 0, 0, 0, 0, 1, 0);

  // Light 0 keeps its default position (0,0,1,0): a directional light shining from the viewer.
  GLfloat light_ambient[] = {0.2f, 0.2f, 0.2f, 1.0f};
  GLfloat light_diffuse[] = {1.0f, 1.0f, 1.0f, 1.0f};
  GLfloat light_specular[] = {0.0f, 0.0f, 0.0f, 1.0f};
  glLightfv(GL_LIGHT0, GL_AMBIENT, light_ambient);
  glLightfv(GL_LIGHT0, GL_DIFFUSE, light_diffuse);
  glLightfv(GL_LIGHT0, GL_SPECULAR, light_specular);

  GLfloat mat_specular[] = {0.0f, 0.0f, 0.0f, 1.0f};
  GLfloat mat_diffuse[] = {0.8f, 0.6f, 0.4f, 1.0f};
  GLfloat mat_ambient[] = {0.8f, 0.6f, 0.4f, 1.0f};
  GLfloat mat_shininess = 20.0f;
  glMaterialfv(GL_FRONT, GL_SPECULAR, mat_specular);
  glMaterialfv(GL_FRONT, GL_AMBIENT, mat_ambient);
  glMaterialfv(GL_FRONT, GL_DIFFUSE, mat_diffuse);
  glMaterialf(GL_FRONT, GL_SHININESS, mat_shininess);

  glShadeModel(gSmooth ? GL_SMOOTH : GL_FLAT);
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);

  glBegin(GL_TRIANGLES);
  for (int i = 0; i < 20; i++)
    subdivide(&vdata[tindices[i][0]][0], &vdata[tindices[i][1]][0], &vdata[tindices[i][2]][0], gDepth);
  glEnd();
  glFlush();
}

static void keyboard(int key) {
  if (ffc::examples::key::is_plus(key)) gDepth = std::min(gDepth + 1, 8);
  if (ffc::examples::key::is_minus(key)) gDepth = std::max(gDepth - 1, 0);
  if (key == 'F') gSmooth = false;
  if (key == 'S') gSmooth = true;
  if (key == 'N') gNormals = gNormals == kFace ? kSphere : kFace;
}

int main(int argc, char** argv) {
  ffc::examples::Example ex;
  ex.name = "icosphere";
  ex.title = "icosphere: subdivided icosahedron (+/- depth, F/S shade model, N normals)";
  ex.width = ex.height = 512;
  ex.draw = display;
  ex.on_key = keyboard;
  ex.state = [] {
    return std::string(gSmooth ? "GL_SMOOTH" : "GL_FLAT") + (gNormals == kSphere ? ", sphere normals" : ", face normals") +
           ", depth " + std::to_string(gDepth) + ", glBegin/glVertex, no GL_NORMALIZE or GL_RESCALE_NORMAL";
  };
  ex.add_options = [](CLI::App& app) {
    app.add_option("--depth", gDepth, "Subdivision depth")->check(CLI::Range(0, 8))->capture_default_str();
    static std::string shade = "smooth", normals = "face";
    app.add_option("--shade", shade, "glShadeModel")
        ->check(CLI::IsMember({"flat", "smooth"}))
        ->capture_default_str()
        ->each([](const std::string& s) { gSmooth = s == "smooth"; });
    app.add_option("--normals", normals, "face (normCrossProd) or sphere (the vertex itself)")
        ->check(CLI::IsMember({"face", "sphere"}))
        ->capture_default_str()
        ->each([](const std::string& n) { gNormals = n == "sphere" ? kSphere : kFace; });
  };
  return ffc::examples::run_example(argc, argv, ex);
}
