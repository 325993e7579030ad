#include "lab_scene.h"

#include <cmath>
#include <cstdio>

#include "gl/glu.h"

namespace lab {

bool Camera::on_key(int key) {
  const double ten_degrees = 10 * M_PI / 180;
  switch (key) {
    case '1': ang += -ten_degrees; return true;
    case '3': ang += ten_degrees; return true;
    case '2': height += .1; return true;
    case 'W': height += -.1; return true;
    default: return false;
  }
}

std::string Camera::describe() const {
  char b[64];
  std::snprintf(b, sizeof b, "%.0f deg, height %.1f", ang * 180 / M_PI, height);
  return b;
}

void drawFrame() {
  glBegin(GL_LINES);
  glColor3ub(255, 0, 0);
  glVertex3f(0, 0, 0);
  glVertex3f(1, 0, 0);
  glColor3ub(0, 255, 0);
  glVertex3f(0, 0, 0);
  glVertex3f(0, 1, 0);
  glColor3ub(0, 0, 255);
  glVertex3f(0, 0, 0);
  glVertex3f(0, 0, 1);
  glEnd();
}

void beginRender(const Camera& cam) {
  glClearColor(0, 0, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);

  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  gluPerspective(45, 1, 1, 10);

  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  gluLookAt(5 * std::sin(cam.ang), cam.height, 5 * std::cos(cam.ang), 0, 0, 0, 0, 1, 0);

  drawFrame();

  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  glEnable(GL_RESCALE_NORMAL);

  // The position is transformed by the modelview current now, so after gluLookAt the light stays
  // put in the world while the camera turns around it.
  glPushMatrix();
  const GLfloat lightPos[] = {3, 4, 5, 1};  // w = 1: a point light; 0 would make it directional
  glLightfv(GL_LIGHT0, GL_POSITION, lightPos);
  glPopMatrix();

  const GLfloat lightColor[] = {1, 1, 1, 1};
  const GLfloat ambientLightColor[] = {.1f, .1f, .1f, 1};
  glLightfv(GL_LIGHT0, GL_DIFFUSE, lightColor);
  glLightfv(GL_LIGHT0, GL_SPECULAR, lightColor);
  glLightfv(GL_LIGHT0, GL_AMBIENT, ambientLightColor);

  const GLfloat objectColor[] = {1, 0, 0, 1};
  const GLfloat specularObjectColor[] = {1, 1, 1, 1};
  glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, objectColor);
  glMaterialf(GL_FRONT, GL_SHININESS, 10);
  glMaterialfv(GL_FRONT, GL_SPECULAR, specularObjectColor);
}

// Counterclockwise seen from outside: the winding the face normals below agree with.
const GLfloat gVertexArraySeparate[36 * 6] = {
    0, 0, 1,   -1, 1, 1,    // v0 normal, v0 position
    0, 0, 1,   1, -1, 1,    // v2
    0, 0, 1,   1, 1, 1,     // v1

    0, 0, 1,   -1, 1, 1,    // v0
    0, 0, 1,   -1, -1, 1,   // v3
    0, 0, 1,   1, -1, 1,    // v2

    0, 0, -1,  -1, 1, -1,   // v4
    0, 0, -1,  1, 1, -1,    // v5
    0, 0, -1,  1, -1, -1,   // v6

    0, 0, -1,  -1, 1, -1,   // v4
    0, 0, -1,  1, -1, -1,   // v6
    0, 0, -1,  -1, -1, -1,  // v7

    0, 1, 0,   -1, 1, 1,    // v0
    0, 1, 0,   1, 1, 1,     // v1
    0, 1, 0,   1, 1, -1,    // v5

    0, 1, 0,   -1, 1, 1,    // v0
    0, 1, 0,   1, 1, -1,    // v5
    0, 1, 0,   -1, 1, -1,   // v4 (the handout's listing drops this normal; the stride needs it)

    0, -1, 0,  -1, -1, 1,   // v3
    0, -1, 0,  1, -1, -1,   // v6
    0, -1, 0,  1, -1, 1,    // v2

    0, -1, 0,  -1, -1, 1,   // v3
    0, -1, 0,  -1, -1, -1,  // v7
    0, -1, 0,  1, -1, -1,   // v6

    1, 0, 0,   1, 1, 1,     // v1
    1, 0, 0,   1, -1, 1,    // v2
    1, 0, 0,   1, -1, -1,   // v6

    1, 0, 0,   1, 1, 1,     // v1
    1, 0, 0,   1, -1, -1,   // v6
    1, 0, 0,   1, 1, -1,    // v5

    -1, 0, 0,  -1, 1, 1,    // v0
    -1, 0, 0,  -1, -1, -1,  // v7
    -1, 0, 0,  -1, -1, 1,   // v3

    -1, 0, 0,  -1, 1, 1,    // v0
    -1, 0, 0,  -1, 1, -1,   // v4
    -1, 0, 0,  -1, -1, -1,  // v7
};

void drawCube_glDrawArray() {
  const GLfloat* varr = gVertexArraySeparate;
  const GLsizei stride = 6 * sizeof(GLfloat);
  glEnableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_NORMAL_ARRAY);
  glNormalPointer(GL_FLOAT, stride, varr);
  glVertexPointer(3, GL_FLOAT, stride, varr + 3);
  glDrawArrays(GL_TRIANGLES, 0, sizeof(gVertexArraySeparate) / stride);
  // Client state outlives the call: switched off so nothing later draws from these pointers.
  glDisableClientState(GL_NORMAL_ARRAY);
  glDisableClientState(GL_VERTEX_ARRAY);
}

}  // namespace lab
