/* A lit smooth-shaded sphere and a lit quad (immediate mode), a lit flat-shaded pyramid
 * (glDrawElements) and a colour-interpolated triangle (glDrawArrays) drawn on soft, soft-double
 * and mesa through the plain gl* exports: each of ours within 1 step of Mesa's picture, and a
 * pixel of the quad at its hand-derived value on both. Two surfaces
 * alive at once, switched with make_current, each keeping its own state. The first argument names
 * the backend in soft's place ("glsl": two EGL contexts, one core and one compatibility, switched). */
#include <math.h>
#include <string.h>

#include "classic_test.h"

enum { W = 96, H = 96 };

static void view(void) {
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(-1, 1, -1, 1, -10, 10);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
}

/* Facing the viewer with GL's default light 0 (directional, along +z, diffuse 1) and default
 * material (diffuse 0.8, ambient 0.2 under the global ambient 0.2): 0.8 + 0.04 = 0.84 of 255,
 * 214.2, stored as 214 on each channel. */
static void lit_quad(void) {
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  glBegin(GL_QUADS);
  glNormal3f(0, 0, 1);
  glVertex2f(-1, -1);
  glVertex2f(-0.5f, -1);
  glVertex2f(-0.5f, -0.5f);
  glVertex2f(-1, -0.5f);
  glEnd();
}

/* A sphere of quad strips, each vertex's normal its direction from the centre. */
static void sphere(float cx, float cy, float r, int stacks, int slices) {
  const float light_pos[4] = {1, 1, 2, 0};
  const float white[4] = {1, 1, 1, 1};
  const float red[4] = {0.8f, 0.2f, 0.1f, 1};
  glLightfv(GL_LIGHT0, GL_POSITION, light_pos);
  glLightfv(GL_LIGHT0, GL_SPECULAR, white);
  glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE, red);
  glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, white);
  glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 20);
  glShadeModel(GL_SMOOTH);
  glEnable(GL_DEPTH_TEST);
  for (int i = 0; i < stacks; ++i) {
    const double a0 = M_PI * i / stacks - M_PI / 2, a1 = M_PI * (i + 1) / stacks - M_PI / 2;
    glBegin(GL_QUAD_STRIP);
    for (int j = 0; j <= slices; ++j) {
      const double b = 2 * M_PI * j / slices;
      const double x0 = cos(a0) * cos(b), y0 = sin(a0), z0 = cos(a0) * sin(b);
      const double x1 = cos(a1) * cos(b), y1 = sin(a1), z1 = cos(a1) * sin(b);
      glNormal3d(x1, y1, z1);
      glVertex3d(cx + r * x1, cy + r * y1, r * z1);
      glNormal3d(x0, y0, z0);
      glVertex3d(cx + r * x0, cy + r * y0, r * z0);
    }
    glEnd();
  }
}

static void array_triangle(void) {
  static const float pos[] = {0.2f, -0.9f, 0.9f, -0.9f, 0.55f, -0.2f};
  static const float col[] = {1, 0, 0, 0, 1, 0, 0, 0, 1};
  glDisable(GL_LIGHTING);
  glEnableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_COLOR_ARRAY);
  glVertexPointer(2, GL_FLOAT, 0, pos);
  glColorPointer(3, GL_FLOAT, 0, col);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glDisableClientState(GL_COLOR_ARRAY);
  glDisableClientState(GL_VERTEX_ARRAY);
}

/* A hexagonal pyramid seen from above, flat-shaded, lit, from client arrays by glDrawElements:
 * each triangle's colour is its last vertex's (the provoking one). */
static void lit_elements(void) {
  float pos[7 * 3], nrm[7 * 3];
  GLushort idx[6 * 3];
  pos[0] = -0.6f, pos[1] = 0.6f, pos[2] = 0.3f;
  nrm[0] = 0, nrm[1] = 0, nrm[2] = 1;
  for (int i = 0; i < 6; ++i) {
    const double a = M_PI / 3 * i;
    pos[3 + 3 * i] = (float)(-0.6 + 0.3 * cos(a)), pos[4 + 3 * i] = (float)(0.6 + 0.3 * sin(a)), pos[5 + 3 * i] = 0;
    nrm[3 + 3 * i] = (float)cos(a), nrm[4 + 3 * i] = (float)sin(a), nrm[5 + 3 * i] = 1;
    idx[3 * i] = 0, idx[3 * i + 1] = (GLushort)(1 + i), idx[3 * i + 2] = (GLushort)(1 + (i + 1) % 6);
  }
  glEnable(GL_LIGHTING);
  glEnable(GL_NORMALIZE);
  glShadeModel(GL_FLAT);
  glEnableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_NORMAL_ARRAY);
  glVertexPointer(3, GL_FLOAT, 0, pos);
  glNormalPointer(GL_FLOAT, 0, nrm);
  glDrawElements(GL_TRIANGLES, 18, GL_UNSIGNED_SHORT, idx);
  glDisableClientState(GL_NORMAL_ARRAY);
  glDisableClientState(GL_VERTEX_ARRAY);
  glShadeModel(GL_SMOOTH);
}

/* The rest of the picture, after lit_quad. */
static void rest(void) {
  sphere(0.3f, 0.35f, 0.55f, 16, 24);
  lit_elements();
  array_triangle();
}

static void clear(void) {
  glClearColor(0.1f, 0.2f, 0.3f, 1);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
}

static const unsigned char* px(const unsigned char* img, int x, int y_from_bottom) {
  return img + ((size_t)(H - 1 - y_from_bottom) * W + x) * 4;
}

int main(int argc, char** argv) {
  require_ffcompat();
  static unsigned char soft_img[W * H * 4], mesa_img[W * H * 4], double_img[W * H * 4];
  const char* ours = argc > 1 ? argv[1] : "soft";

  ffcompat_surface* soft = surface_on(ours, W, H);
  CHECK(strcmp(ffcompat_surface_backend(soft), ours) == 0, "backend %s", ffcompat_surface_backend(soft));
  CHECK(ffcompat_surface_width(soft) == W && ffcompat_surface_height(soft) == H, "size");
  view();
  clear();
  lit_quad();  /* leaves lighting on, for after the switch below */

  ffcompat_surface* mesa = surface_on("mesa", W, H);  /* now current */
  CHECK(strcmp(ffcompat_surface_backend(mesa), "mesa") == 0, "backend %s", ffcompat_surface_backend(mesa));
  view();
  clear();
  lit_quad();
  rest();
  CHECK(glGetError() == GL_NO_ERROR, "a GL error on mesa");

  ffcompat_surface_make_current(soft);
  CHECK(glIsEnabled(GL_LIGHTING) == GL_TRUE, "%s's state did not survive the switch to mesa", ours);
  rest();
  CHECK(glGetError() == GL_NO_ERROR, "a GL error on %s", ours);

  /* Our double-precision reference, the whole picture at once. */
  ffcompat_surface* dbl = surface_on("soft-double", W, H);
  view();
  clear();
  lit_quad();
  rest();
  ffcompat_surface_read_rgba(dbl, double_img);
  ffcompat_surface_destroy(dbl);

  ffcompat_surface_read_rgba(soft, soft_img);
  ffcompat_surface_read_rgba(mesa, mesa_img);

  /* Within the quad, on each. */
  for (int k = 0; k < 3; ++k) {
    CHECK(px(soft_img, 10, 10)[k] == 214, "%s quad channel %d = %d", ours, k, px(soft_img, 10, 10)[k]);
    CHECK(px(mesa_img, 10, 10)[k] == 214, "mesa quad channel %d = %d", k, px(mesa_img, 10, 10)[k]);
  }
  /* The clear colour in a corner no shape covers: 0.1, 0.2, 0.3 of 255 round to 26, 51, 76. */
  CHECK(px(soft_img, 1, H - 2)[0] == 26 && px(soft_img, 1, H - 2)[1] == 51 && px(soft_img, 1, H - 2)[2] == 76,
        "%s clear colour", ours);

  int max_diff = 0, drawn = 0, apart = 0, double_diff = 0;
  for (int i = 0; i < W * H * 4; ++i) {
    const int d = abs(soft_img[i] - mesa_img[i]);
    if (d > max_diff) max_diff = d;
    if (d) ++apart;
    if (abs(double_img[i] - mesa_img[i]) > double_diff) double_diff = abs(double_img[i] - mesa_img[i]);
  }
  for (int i = 0; i < W * H; ++i)
    if (soft_img[4 * i] != 26 || soft_img[4 * i + 1] != 51 || soft_img[4 * i + 2] != 76) ++drawn;
  printf("%s against mesa: largest difference %d steps, %d channels apart; soft-double %d steps; %d pixels drawn\n",
         ours, max_diff, apart, double_diff, drawn);
  CHECK(max_diff <= 1, "%s and mesa %d steps apart", ours, max_diff);
  CHECK(double_diff <= 1, "soft-double and mesa %d steps apart", double_diff);
  /* The sphere (radius 26 pixels) alone covers over 2,000 pixels. */
  CHECK(drawn > 2000, "only %d pixels drawn", drawn);

  ffcompat_surface_destroy(mesa);
  ffcompat_surface_destroy(soft);
  return finish();
}
