// The built-in scenes' GL calls exactly as src/scene/scene.cpp issued them before scenes became
// Descriptions (the seed programs 000 and 004 as written), kept as the reference the built-in
// Descriptions are checked against.
#pragma once
#include <cmath>

#include "gl/glu.h"
#include "scene/scene.h"

namespace ffc::scene_test::seed {

using scene::Shade;
using scene::Spec;

inline void draw_mesh(const mesh::DrawArrays& d) {
  glEnableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_NORMAL_ARRAY);
  glVertexPointer(3, GL_FLOAT, 0, d.positions.data());
  glNormalPointer(GL_FLOAT, 0, d.normals.data());
  if (d.indexed())
    glDrawElements(GL_TRIANGLES, GLsizei(d.indices.size()), GL_UNSIGNED_INT, d.indices.data());
  else
    glDrawArrays(GL_TRIANGLES, 0, GLsizei(d.vertex_count()));
  glDisableClientState(GL_NORMAL_ARRAY);
  glDisableClientState(GL_VERTEX_ARRAY);
}

inline void draw_frame() {
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

inline void draw_cube(const Spec& spec, const mesh::DrawArrays& d) {
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  gluPerspective(45, double(spec.width) / spec.height, 1, 10);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  const double a = spec.cam_angle_deg * M_PI / 180;
  gluLookAt(5 * std::sin(a), spec.cam_height, 5 * std::cos(a), 0, 0, 0, 0, 1, 0);
  draw_frame();

  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  glEnable(GL_RESCALE_NORMAL);
  glShadeModel(spec.shade == Shade::Flat ? GL_FLAT : GL_SMOOTH);
  glPushMatrix();
  const GLfloat light_pos[] = {3, 4, 5, 1};
  glLightfv(GL_LIGHT0, GL_POSITION, light_pos);
  glPopMatrix();
  const GLfloat light_color[] = {1, 1, 1, 1}, ambient_light[] = {.1f, .1f, .1f, 1};
  glLightfv(GL_LIGHT0, GL_DIFFUSE, light_color);
  glLightfv(GL_LIGHT0, GL_SPECULAR, light_color);
  glLightfv(GL_LIGHT0, GL_AMBIENT, ambient_light);
  const GLfloat object_color[] = {1, 0, 0, 1}, specular_color[] = {1, 1, 1, 1};
  glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, object_color);
  glMaterialf(GL_FRONT, GL_SHININESS, 10);
  glMaterialfv(GL_FRONT, GL_SPECULAR, specular_color);
  glPushMatrix();
  glColor3ub(0, 0, 255);
  draw_mesh(d);
  glPopMatrix();
  glDisable(GL_LIGHTING);
}

inline void draw_icosphere(const Spec& spec, const mesh::DrawArrays& d) {
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  gluPerspective(45, double(spec.width) / spec.height, 1, 10);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  gluLookAt(0, 0, 4, 0, 0, 0, 0, 1, 0);
  const GLfloat light_ambient[] = {.2f, .2f, .2f, 1}, light_diffuse[] = {1, 1, 1, 1},
                light_specular[] = {0, 0, 0, 1};
  glLightfv(GL_LIGHT0, GL_AMBIENT, light_ambient);
  glLightfv(GL_LIGHT0, GL_DIFFUSE, light_diffuse);
  glLightfv(GL_LIGHT0, GL_SPECULAR, light_specular);
  const GLfloat mat_specular[] = {0, 0, 0, 1}, mat_color[] = {.8f, .6f, .4f, 1};
  glMaterialfv(GL_FRONT, GL_SPECULAR, mat_specular);
  glMaterialfv(GL_FRONT, GL_AMBIENT, mat_color);
  glMaterialfv(GL_FRONT, GL_DIFFUSE, mat_color);
  glMaterialf(GL_FRONT, GL_SHININESS, 20);
  glShadeModel(spec.shade == Shade::Flat ? GL_FLAT : GL_SMOOTH);
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  draw_mesh(d);
}

// The seed program for a spec, on the current context.
inline void draw(const Spec& spec) {
  const mesh::DrawArrays d = mesh::draw_arrays(scene::build_mesh(spec), spec.normals);
  if (spec.name == "cube")
    draw_cube(spec, d);
  else
    draw_icosphere(spec, d);
}

}  // namespace ffc::scene_test::seed
