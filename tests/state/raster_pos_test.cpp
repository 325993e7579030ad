// The raster position against Mesa over generated lighting states: Mesa lights it with its own C
// code (rastpos.c), not with the vertex program, so its colour follows rules of its own (object
// space when it can, the object-space vertex even in eye space, no GL_NORMALIZE, the front face).
// Every case compares the whole read-back (GL_CURRENT_RASTER_POSITION, _COLOR, _DISTANCE, _VALID)
// and the vertex that glDrawPixels feeds back after GL_DRAW_PIXEL_TOKEN.
#include <array>
#include <random>
#include <string>

#include "harness.h"

namespace ffc::state_test {
namespace {

GLfloat g_buffer[64];

// A lighting state, a modelview and a raster position drawn from the seed.
Case generated(unsigned seed) {
  std::mt19937 rng(seed);
  auto uni = [&](float a, float b) { return std::uniform_real_distribution<float>(a, b)(rng); };
  auto coin = [&](double p) { return std::bernoulli_distribution(p)(rng); };
  struct Light {
    GLfloat pos[4], dir[4], amb[4], dif[4], spe[4];
    float cutoff, exponent, k0, k1, k2;
  };
  const int lights = std::uniform_int_distribution<int>(1, 3)(rng);
  std::vector<Light> ls(static_cast<size_t>(lights));
  for (Light& l : ls) {
    const bool positional = coin(0.5);
    for (int k = 0; k < 3; ++k) {
      l.pos[k] = uni(-4, 4), l.dir[k] = uni(-1, 1);
      l.amb[k] = uni(0, 0.3f), l.dif[k] = uni(0, 1), l.spe[k] = uni(0, 1);
    }
    l.pos[3] = positional ? (coin(0.8) ? 1.0f : uni(0.5f, 2)) : 0.0f;
    l.dir[3] = l.amb[3] = l.dif[3] = l.spe[3] = 1;
    l.cutoff = coin(0.6) ? 180.0f : uni(5, 90);
    l.exponent = uni(0, 20);
    l.k0 = coin(0.7) ? 1.0f : uni(0.5f, 2), l.k1 = coin(0.7) ? 0.0f : uni(0, 0.5f), l.k2 = coin(0.8) ? 0.0f : uni(0, 0.2f);
  }
  GLfloat mat_amb[4] = {uni(0, 1), uni(0, 1), uni(0, 1), 1}, mat_dif[4] = {uni(0, 1), uni(0, 1), uni(0, 1), uni(0, 1)},
          mat_spe[4] = {uni(0, 1), uni(0, 1), uni(0, 1), 1}, mat_emi[4] = {uni(0, 0.2f), uni(0, 0.2f), uni(0, 0.2f), 1};
  const float shininess = coin(0.1) ? 0.0f : uni(1, 128);
  const bool local_viewer = coin(0.3), separate = coin(0.2), normalize = coin(0.3);
  // The modelview: a rigid motion (Mesa lights in object space), sometimes scaled (eye space).
  const float angle = uni(-180, 180), ax = uni(-1, 1), ay = uni(-1, 1), az = uni(-1, 1);
  const float tx = uni(-1, 1), ty = uni(-1, 1), tz = uni(-6, -3);
  const int scaled = std::uniform_int_distribution<int>(0, 3)(rng);  // 0 none, 1 uniform, 2 general
  const float s = uni(0.5f, 2);
  const float nx = uni(-1, 1), ny = uni(-1, 1), nz = uni(-1, 1), nscale = coin(0.5) ? 1.0f : uni(0.3f, 3);
  const float rx = uni(-0.5f, 0.5f), ry = uni(-0.5f, 0.5f);
  const GLenum type = std::array<GLenum, 5>{GL_2D, GL_3D, GL_3D_COLOR, GL_3D_COLOR_TEXTURE, GL_4D_COLOR_TEXTURE}[seed % 5];

  Case c;
  c.name = "seed" + std::to_string(seed);
  c.mesa_error = GL_NO_ERROR;
  c.setup = [=] {
    glMatrixMode(GL_PROJECTION);
    glFrustum(-1, 1, -1, 1, 1, 20);
    glMatrixMode(GL_MODELVIEW);
    glEnable(GL_LIGHTING);
    for (int i = 0; i < lights; ++i) {
      const Light& l = ls[size_t(i)];
      const GLenum L = GLenum(GL_LIGHT0 + i);
      glEnable(L);
      glLightfv(L, GL_POSITION, l.pos);  // under the identity: the eye position is as given
      glLightfv(L, GL_SPOT_DIRECTION, l.dir);
      glLightfv(L, GL_AMBIENT, l.amb), glLightfv(L, GL_DIFFUSE, l.dif), glLightfv(L, GL_SPECULAR, l.spe);
      glLightf(L, GL_SPOT_CUTOFF, l.cutoff), glLightf(L, GL_SPOT_EXPONENT, l.exponent);
      glLightf(L, GL_CONSTANT_ATTENUATION, l.k0), glLightf(L, GL_LINEAR_ATTENUATION, l.k1);
      glLightf(L, GL_QUADRATIC_ATTENUATION, l.k2);
    }
    glMaterialfv(GL_FRONT, GL_AMBIENT, mat_amb), glMaterialfv(GL_FRONT, GL_DIFFUSE, mat_dif);
    glMaterialfv(GL_FRONT, GL_SPECULAR, mat_spe), glMaterialfv(GL_FRONT, GL_EMISSION, mat_emi);
    glMaterialf(GL_FRONT, GL_SHININESS, shininess);
    glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, local_viewer);
    glLightModeli(GL_LIGHT_MODEL_COLOR_CONTROL, separate ? GL_SEPARATE_SPECULAR_COLOR : GL_SINGLE_COLOR);
    if (normalize) glEnable(GL_NORMALIZE);
    glTranslatef(tx, ty, tz);
    glRotatef(angle, ax, ay, az);
    if (scaled == 1) glScalef(s, s, s);
    if (scaled == 2) glScalef(s, 1, 1 / s);
    glNormal3f(nx * nscale, ny * nscale, nz * nscale);
  };
  c.call = [=] {
    glRasterPos2f(rx, ry);
    glFeedbackBuffer(64, type, g_buffer);
    glRenderMode(GL_FEEDBACK);
    const GLubyte pixel[4] = {1, 2, 3, 4};
    glDrawPixels(1, 1, GL_RGBA, GL_UNSIGNED_BYTE, pixel);
    const GLint n = glRenderMode(GL_RENDER);
    observe("feedback count", n);
    for (GLint i = 0; i < n && i < 64; ++i) observe("feedback[" + std::to_string(i) + "]", g_buffer[i]);
  };
  return c;
}

TEST(RasterPos, LitAsMesaLightsIt) {
  for (unsigned seed = 1; seed <= 300; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    check_case(generated(seed), 1e-5);
  }
}

}  // namespace
}  // namespace ffc::state_test
