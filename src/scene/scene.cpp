#include "scene/scene.h"

#include <cmath>
#include <stdexcept>

#include "gl/glu.h"
#include "mesh/cube.h"
#include "mesh/icosphere.h"

namespace ffc::scene {

Shade parse_shade(const std::string& s) {
  if (s == "flat") return Shade::Flat;
  if (s == "smooth") return Shade::Smooth;
  throw std::invalid_argument("unknown shade model '" + s + "' (flat or smooth)");
}

const char* to_string(Shade s) { return s == Shade::Flat ? "flat" : "smooth"; }

Spec builtin(const std::string& name) {
  Spec s;
  s.name = name;
  if (name == "cube") {
    s.width = s.height = 640;
    s.normals = mesh::NormalSource::Face;
  } else if (name == "icosphere") {
    s.width = s.height = 512;
    s.depth = 3;
    s.normals = mesh::NormalSource::Sphere;
  } else {
    throw std::invalid_argument("unknown scene '" + name + "' (cube or icosphere)");
  }
  return s;
}

mesh::Mesh build_mesh(const Spec& spec) {
  if (spec.name == "cube") return mesh::make_cube();
  if (spec.name == "icosphere") return mesh::make_icosphere(spec.depth);
  throw std::invalid_argument("unknown scene '" + spec.name + "' (cube or icosphere)");
}

// Client vertex arrays as the seeds draw them: glDrawArrays over unshared corners for face
// normals, glDrawElements over shared vertices otherwise.
static void draw_mesh(const mesh::DrawArrays& d) {
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

// Seed 000's drawFrame: the unit axes, unlit, red x, green y, blue z.
static void draw_frame() {
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

static void draw_cube(const Spec& spec, const mesh::DrawArrays& d) {
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
  const GLfloat light_pos[] = {3, 4, 5, 1};  // set after the camera: a point fixed in the world
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
  glColor3ub(0, 0, 255);  // ignored while lighting is on, as the seed points out
  draw_mesh(d);
  glPopMatrix();
  glDisable(GL_LIGHTING);
}

static void draw_icosphere(const Spec& spec, const mesh::DrawArrays& d) {
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  gluPerspective(45, double(spec.width) / spec.height, 1, 10);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  gluLookAt(0, 0, 4, 0, 0, 0, 0, 1, 0);
  // Seed 004's settings; light 0 keeps its default position, (0,0,1,0) in eye space.
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

static void draw_with(const Spec& spec, const mesh::DrawArrays& d) {
  if (spec.name == "cube")
    draw_cube(spec, d);
  else
    draw_icosphere(spec, d);
}

void draw(const Spec& spec) { draw_with(spec, mesh::draw_arrays(build_mesh(spec), spec.normals)); }

image::Image render(const Spec& spec, backends::Backend& backend) {
  const mesh::DrawArrays d = mesh::draw_arrays(build_mesh(spec), spec.normals);
  backend.begin(spec.width, spec.height);
  draw_with(spec, d);
  return backend.read();
}

}  // namespace ffc::scene
