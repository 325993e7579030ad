// Draws one lit triangle through ffcompat's public header and checks a pixel against the colour
// derived by hand below. Exit status 0 when it matches on every backend named on the command line
// (default: soft).
//
// The lit colour (GL 2.1, 2.14.1), everything but the material's diffuse colour at its default:
//   c = e_m + a_m * a_s + att * (a_m * a_l + max(n.L, 0) * d_m * d_l + specular)
//   e_m = 0 (emission), a_s = (0.2, 0.2, 0.2) (light model ambient), a_m = (0.2, 0.2, 0.2)
//   (material ambient), a_l = 0 (light 0's ambient), att = 1 (directional light),
//   d_l = (1, 1, 1) (light 0's diffuse, also set below), d_m = (0.5, 0.25, 0) (set below),
//   n = (0, 0, 1), L = (0, 0, 1) (light 0 at (0, 0, 1, 0), set below): n.L = 1,
//   specular = 0 (material specular (0, 0, 0)); alpha = d_m's alpha = 1.
//   c = (0.04 + 0.5, 0.04 + 0.25, 0.04 + 0) = (0.54, 0.29, 0.04)
//   * 255 = (137.7, 73.95, 10.2), rounded (138, 74, 10), alpha 255.
#include <ffcompat/ffcompat.h>

#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

namespace {

bool draw_and_check(const std::string& backend) {
  ffcompat::Context ctx(backend, 16, 16);
  const GLfloat position[] = {0, 0, 1, 0}, white[] = {1, 1, 1, 1}, diffuse[] = {0.5f, 0.25f, 0, 1};
  glClearColor(0, 0, 0, 0);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  glLightfv(GL_LIGHT0, GL_POSITION, position);  // identity modelview: stays (0, 0, 1, 0)
  glLightfv(GL_LIGHT0, GL_DIFFUSE, white);
  glMaterialfv(GL_FRONT, GL_DIFFUSE, diffuse);
  glBegin(GL_TRIANGLES);  // covers the whole viewport
  glNormal3f(0, 0, 1);
  glVertex3f(-1, -1, 0);
  glVertex3f(3, -1, 0);
  glVertex3f(-1, 3, 0);
  glEnd();
  if (GLenum e = glGetError(); e != GL_NO_ERROR) {
    std::fprintf(stderr, "%s: GL error 0x%x\n", backend.c_str(), e);
    return false;
  }
  const std::vector<std::uint8_t> rgba = ctx.read_pixels();
  const std::uint8_t* p = &rgba[(8 * 16 + 8) * 4];
  const int expected[4] = {138, 74, 10, 255};
  bool ok = rgba.size() == 16 * 16 * 4;
  for (int i = 0; i < 4; ++i) ok = ok && std::abs(p[i] - expected[i]) <= 1;
  std::printf("%s: pixel (8, 8) = (%d, %d, %d, %d), expected (138, 74, 10, 255) +-1: %s\n", backend.c_str(), p[0],
              p[1], p[2], p[3], ok ? "ok" : "WRONG");
  return ok;
}

}  // namespace

int main(int argc, char** argv) {
  std::printf("ffcompat %s, backends:", ffcompat::version());
  for (const std::string& name : ffcompat::backends()) std::printf(" %s", name.c_str());
  std::printf("\n");
  std::vector<std::string> backends(argv + 1, argv + argc);
  if (backends.empty()) backends = {"soft"};
  bool ok = true;
  try {
    for (const std::string& b : backends) ok = draw_and_check(b) && ok;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "consumer: %s\n", e.what());
    return 1;
  }
  return ok ? 0 : 1;
}
