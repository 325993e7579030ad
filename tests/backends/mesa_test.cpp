// Mesa's fixed-function output probed at pixels whose colour follows by hand from the lighting
// equation (OpenGL 2.1, section 2.14.1). Under GL_FLAT a triangle takes the colour of its last
// vertex, so a probe inside it checks one evaluation of the equation exactly.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "backends/backend.h"
#include "gl/dispatch.h"
#include "mesh/icosphere.h"
#include "scene/scene.h"

namespace ffc {
namespace {

using glm::dvec3;

// Window position (x right, y down, in pixels) of a world point seen through gluPerspective(45,
// aspect, 1, 10) and gluLookAt(eye, origin, +y).
glm::ivec2 project(dvec3 world, dvec3 eye, int w, int h) {
  const glm::dmat4 mvp = glm::perspectiveRH_NO(glm::radians(45.0), double(w) / h, 1.0, 10.0) *
                         glm::lookAtRH(eye, dvec3(0), dvec3(0, 1, 0));
  const glm::dvec4 c = mvp * glm::dvec4(world, 1);
  const double x = (c.x / c.w * 0.5 + 0.5) * w, y = (c.y / c.w * 0.5 + 0.5) * h;
  return {int(std::floor(x)), h - 1 - int(std::floor(y))};
}

int to_unorm8(double c) { return int(std::lround(std::clamp(c, 0.0, 1.0) * 255)); }

void expect_pixel(const image::Image& img, glm::ivec2 p, glm::ivec3 want) {
  const uint8_t* px = img.at(p.x, p.y);
  SCOPED_TRACE("pixel (" + std::to_string(p.x) + "," + std::to_string(p.y) + ")");
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(int(px[c]), want[c], 1) << "channel " << c;
}

class MesaRender : public ::testing::Test {
 protected:
  std::unique_ptr<backends::Backend> mesa = backends::make("mesa");
};

// Seed 000's cube: light (3,4,5,1) in the world, camera (0,1,5), infinite viewer, so the eye
// direction is the camera's backward axis. Material red, specular white, shininess 10; light
// ambient .1, diffuse and specular 1; global ambient .2.
TEST_F(MesaRender, FlatCubeTriangleHasItsLastVertexsLitColour) {
  scene::Spec spec = scene::builtin("cube");
  spec.shade = scene::Shade::Flat;
  const image::Image img = scene::render(spec, *mesa);
  ASSERT_EQ(img.width, 640);

  // Front face triangle {0,2,1}: its last vertex v1 = (1,1,1) provokes the colour.
  const dvec3 eye(0, 1, 5), v1(1, 1, 1), n(0, 0, 1);
  const dvec3 l = glm::normalize(dvec3(3, 4, 5) - v1);
  const dvec3 h = glm::normalize(l + glm::normalize(eye));
  const double diffuse = std::max(glm::dot(n, l), 0.0);
  const double spec_term = std::pow(std::max(glm::dot(n, h), 0.0), 10);
  const glm::ivec3 want(to_unorm8(0.2 + 0.1 + diffuse + spec_term), to_unorm8(spec_term), to_unorm8(spec_term));
  EXPECT_EQ(want.x, 255);
  EXPECT_EQ(want.y, 88);  // (N.H)^10 = 0.3446
  // Three probes inside the triangle, near each corner, get the same colour.
  for (dvec3 p : {dvec3(0.6, 0.8, 1), dvec3(-0.7, 0.85, 1), dvec3(0.85, -0.6, 1)})
    expect_pixel(img, project(p, eye, 640, 640), want);
}

TEST_F(MesaRender, SmoothCubeWithFaceNormalsStillVariesAcrossAFace) {
  // Seed 001's remark: one normal per face, but the light direction differs per vertex.
  const image::Image img = scene::render(scene::builtin("cube"), *mesa);
  const dvec3 eye(0, 1, 5);
  const uint8_t* a = img.at(project({0.6, 0.8, 1}, eye, 640, 640).x, project({0.6, 0.8, 1}, eye, 640, 640).y);
  const auto pb = project({0.85, -0.6, 1}, eye, 640, 640);
  const uint8_t* b = img.at(pb.x, pb.y);
  EXPECT_GT(std::abs(int(a[1]) - int(b[1])), 10);
  EXPECT_EQ(a[0], 255);  // red saturates everywhere on the lit front face
}

TEST_F(MesaRender, SmoothIcosphereCentreIsLitHeadOn) {
  // From depth 1 on, (0,0,1) is a vertex (the midpoint of vdata 0 and 1) and projects to the
  // centre. Sphere normal (0,0,1), light (0,0,1,0): colour = (.2 + .2 + 1) * (.8,.6,.4), clamped.
  scene::Spec spec = scene::builtin("icosphere");
  const image::Image img = scene::render(spec, *mesa);
  ASSERT_EQ(img.width, 512);
  expect_pixel(img, {256, 256}, {to_unorm8(1.4 * .8), to_unorm8(1.4 * .6), to_unorm8(1.4 * .4)});
  expect_pixel(img, {256, 256}, {255, 214, 143});
  expect_pixel(img, {2, 2}, {0, 0, 0});  // background
}

TEST_F(MesaRender, FlatIcosahedronFaceHasTheFaceNormalsColour) {
  scene::Spec spec = scene::builtin("icosphere");
  spec.depth = 0;
  spec.shade = scene::Shade::Flat;
  spec.normals = mesh::NormalSource::Face;
  const image::Image img = scene::render(spec, *mesa);
  const auto& p = mesh::icosahedron_positions();
  // Every face the camera sees; the eye space is the world moved by -4 in z, so n is unchanged.
  int probed = 0;
  for (const mesh::Tri& t : mesh::icosahedron_triangles()) {
    const dvec3 a(p[t[0]][0], p[t[0]][1], p[t[0]][2]), b(p[t[1]][0], p[t[1]][1], p[t[1]][2]),
        c(p[t[2]][0], p[t[2]][1], p[t[2]][2]);
    const dvec3 n = glm::normalize(glm::cross(b - a, c - a));
    if (n.z < 0.3) continue;  // edge-on or hidden
    const double k = 0.4 + n.z;  // ambients .2 + .2, diffuse n.L with L = (0,0,1)
    expect_pixel(img, project((a + b + c) / 3.0, {0, 0, 4}, 512, 512),
                 {to_unorm8(k * .8), to_unorm8(k * .6), to_unorm8(k * .4)});
    ++probed;
  }
  EXPECT_GE(probed, 5);
}

TEST(MesaBackend, RejectsAnImpossibleFramebuffer) {
  auto mesa = backends::make("mesa");
  EXPECT_THROW(mesa->begin(0, 10), std::runtime_error);
  EXPECT_THROW(backends::make("vulkan"), std::invalid_argument);
}

// Immediate-mode vertices Mesa has queued but not drawn, then the context goes away: a second
// begin() (a fresh context) or the backend's destruction. Before the backend finished the
// context first, Mesa 22.3 crashed inside OSMesaDestroyContext. Each case runs in a child
// process (a death test's fork), so a crash fails the case instead of ending the test binary.
void draw_unflushed_triangles() {
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  glBegin(GL_TRIANGLES);
  for (int i = 0; i < 300; ++i) {
    const float x = float(i % 20) / 10 - 1, y = float(i / 20) / 15 - 1;
    glNormal3f(0, 0, 1);
    glVertex3f(x, y, 0);
    glVertex3f(x + 0.1f, y, 0);
    glVertex3f(x, y + 0.1f, 0);
  }
  glEnd();  // no glFinish, no read-back
}

TEST(MesaBackendDeathTest, UnflushedImmediateModeThenBeginAgain) {
  EXPECT_EXIT(
      {
        auto mesa = backends::make("mesa");
        mesa->begin(64, 64);
        draw_unflushed_triangles();
        mesa->begin(32, 32);
        draw_unflushed_triangles();
        mesa.reset();
        std::exit(0);
      },
      ::testing::ExitedWithCode(0), "");
}

TEST(MesaBackendDeathTest, UnflushedImmediateModeThenDestroyWhileAnotherIsCurrent) {
  EXPECT_EXIT(
      {
        auto a = backends::make("mesa");
        auto b = backends::make("mesa");
        a->begin(64, 64);
        draw_unflushed_triangles();
        b->begin(64, 64);  // now b is current, a still holds its queue
        a.reset();
        // b is current again and still draws.
        glClearColor(1, 0, 0, 1);
        glClear(GL_COLOR_BUFFER_BIT);
        const image::Image img = b->read();
        std::exit(img.at(5, 5)[0] == 255 ? 0 : 3);
      },
      ::testing::ExitedWithCode(0), "");
}

}  // namespace
}  // namespace ffc
