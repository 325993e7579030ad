/* ffcompat_surface_resize, as GLUT uses it for a resized window: on soft and on mesa, a 32x24
 * surface with lighting set up grows to 80x48 (while the other surface is current) and keeps its
 * state, viewport included; drawn over the whole new area with the new viewport, the two pictures
 * agree within 1 step and the lit quad's hand-derived 214 is found where the old buffer ended.
 * Then shrinks to 16x16 and draws again. Bad sizes: -1, the surface unchanged. The first argument
 * names the backend in soft's place ("glsl"). */
#include <string.h>

#include "classic_test.h"

enum { W = 80, H = 48 };

static void setup(void) {
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  glClearColor(0.1f, 0.2f, 0.3f, 1);
}

/* Facing the viewer under GL's default light 0 and material: 0.84 of 255, 214 (draw_compare.c). */
static void draw(int w, int h) {
  glViewport(0, 0, w, h);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glBegin(GL_TRIANGLES);
  glNormal3f(0, 0, 1);
  glVertex2f(-1, -1);
  glVertex2f(1, -1);
  glVertex2f(1, 1);
  glEnd();
}

int main(int argc, char** argv) {
  require_ffcompat();
  static unsigned char img[2][W * H * 4], small[2][16 * 16 * 4];
  const char* names[2] = {argc > 1 ? argv[1] : "soft", "mesa"};
  ffcompat_surface* s[2];
  for (int b = 0; b < 2; ++b) {
    s[b] = surface_on(names[b], 32, 24);
    setup();
  }
  for (int b = 0; b < 2; ++b) {
    ffcompat_surface_make_current(s[1 - b]); /* resized while not current */
    CHECK(ffcompat_surface_resize(s[b], W, H) == 0, "%s: resize failed", names[b]);
    CHECK(ffcompat_surface_width(s[b]) == W && ffcompat_surface_height(s[b]) == H, "%s: size", names[b]);
    CHECK(ffcompat_surface_resize(s[b], 0, 10) == -1 && ffcompat_surface_resize(s[b], 10, 20000) == -1,
          "%s: a bad size accepted", names[b]);
    CHECK(ffcompat_surface_width(s[b]) == W, "%s: a bad size changed the surface", names[b]);
    ffcompat_surface_make_current(s[b]);
    GLint vp[4] = {0, 0, 0, 0};
    glGetIntegerv(GL_VIEWPORT, vp);
    CHECK(vp[2] == 32 && vp[3] == 24, "%s: the viewport became %dx%d", names[b], vp[2], vp[3]);
    CHECK(glIsEnabled(GL_LIGHTING), "%s: lighting lost", names[b]);
    draw(W, H);
    CHECK(glGetError() == GL_NO_ERROR, "%s: a GL error", names[b]);
    ffcompat_surface_read_rgba(s[b], img[b]);
    /* Lower right, beyond the old 32x24 buffer: inside the triangle. Upper left: the clear colour. */
    const unsigned char* in = img[b] + ((size_t)(H - 1 - 4) * W + (W - 4)) * 4;
    const unsigned char* out = img[b] + ((size_t)2 * W + 2) * 4;
    CHECK(in[0] == 214 && in[1] == 214 && in[2] == 214, "%s: lit pixel %d %d %d", names[b], in[0], in[1], in[2]);
    CHECK(out[0] == 26 && out[1] == 51 && out[2] == 76, "%s: clear pixel %d %d %d", names[b], out[0], out[1], out[2]);

    CHECK(ffcompat_surface_resize(s[b], 16, 16) == 0, "%s: shrinking failed", names[b]);
    draw(16, 16);
    ffcompat_surface_read_rgba(s[b], small[b]);
  }
  int max_diff = 0;
  for (int i = 0; i < W * H * 4; ++i)
    if (abs(img[0][i] - img[1][i]) > max_diff) max_diff = abs(img[0][i] - img[1][i]);
  for (int i = 0; i < 16 * 16 * 4; ++i)
    if (abs(small[0][i] - small[1][i]) > max_diff) max_diff = abs(small[0][i] - small[1][i]);
  printf("resized %s against mesa: largest difference %d steps\n", names[0], max_diff);
  CHECK(max_diff <= 1, "%d steps apart", max_diff);
  CHECK(small[0][(15 * 16 + 14) * 4] == 214, "%s after shrinking: %d", names[0], small[0][(15 * 16 + 14) * 4]);
  ffcompat_surface_destroy(s[0]);
  ffcompat_surface_destroy(s[1]);
  CHECK(ffcompat_surface_resize(NULL, 8, 8) == -1, "resizing NULL");
  return finish();
}
