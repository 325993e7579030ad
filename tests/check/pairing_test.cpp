// The vertex check pairs Mesa's fed-back vertices with ours primitive by primitive. Vertices that
// share a window position but not a colour must still find their own partners.
#include <gtest/gtest.h>

#include <cmath>

#include "check/vertex_check.h"
#include "gl/dispatch.h"

namespace ffc {
namespace {

// A cone drawn as a triangle strip between the base ring and its apex, the apex sent once per
// slice with the normal of its own side (as gluCylinder with a top radius of 0 sends it). Every
// other triangle of the strip has two vertices at the apex's window position, lit differently.
void cone() {
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(-1.5, 1.5, -1.5, 1.5, -5, 5);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glRotatef(-70, 1, 0, 0);  // the apex toward the viewer's top, the sides facing different ways
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  const float light[] = {1, 0.5f, 1, 0};
  glLightfv(GL_LIGHT0, GL_POSITION, light);
  glShadeModel(GL_SMOOTH);
  const int slices = 12;
  const double pi = std::acos(-1.0), slope = 1.0 / std::sqrt(2.0);  // height 1, radius 1
  glBegin(GL_TRIANGLE_STRIP);
  for (int i = 0; i <= slices; ++i) {
    const double a = 2 * pi * i / slices;
    const float nx = float(std::cos(a) * slope), ny = float(std::sin(a) * slope), nz = float(slope);
    glNormal3f(nx, ny, nz);
    glVertex3f(float(std::cos(a)), float(std::sin(a)), 0);
    glNormal3f(nx, ny, nz);
    glVertex3f(0, 0, 1);  // the apex, once per slice
  }
  glEnd();
}

TEST(Pairing, ConeApexVerticesFindTheirOwnPartners) {
  const check::VertexReport r = check::compare_vertices(64, 64, cone);
  ASSERT_GT(r.vertices, 0u);
  EXPECT_EQ(r.max_position, 0.0);
  // Paired by nearest position alone, an apex vertex took the other apex copy's colour: a
  // difference of about 0.2 where the lighting agrees to 1e-6.
  EXPECT_LE(r.max_abs, 1e-5);
  EXPECT_TRUE(r.known_mesa_deviations.empty());
}

// The apex copies' colours really differ, or the test above would pass with any pairing.
TEST(Pairing, TheConesApexCopiesDifferInColour) {
  auto mesa = backends::make("mesa");
  const auto prims = check::capture(*mesa, 64, 64, cone);
  double largest = 0;
  for (const auto& p : prims)
    for (size_t i = 0; i < p.vertices.size(); ++i)
      for (size_t j = i + 1; j < p.vertices.size(); ++j)
        if (p.vertices[i].position == p.vertices[j].position)
          largest = std::max(largest, glm::length(p.vertices[i].color - p.vertices[j].color));
  EXPECT_GT(largest, 0.05);
}

}  // namespace
}  // namespace ffc
