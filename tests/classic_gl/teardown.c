/* Surfaces torn down with drawing still queued. Mesa 22.3 crashes in OSMesaDestroyContext when
 * the context is destroyed with llvmpipe still holding unflushed immediate-mode vertices (measured:
 * this program without the library's glFinish before destroying dies with SIGSEGV): the current
 * mesa surface destroyed and made anew 20 times, as a program re-making its window does; a
 * surface destroyed while another is current; then leaving without finishing or destroying
 * anything, as a GLUT program calling exit() from its keyboard callback does. Passes when the
 * process exits 0. */
#include "classic_test.h"

static void draw(void) {
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  glBegin(GL_TRIANGLES);
  for (int i = 0; i < 300; ++i) {
    const float x = (i % 30) / 15.0f - 1, y = (i / 30) / 5.0f - 1;
    glNormal3f(0, 0, 1);
    glVertex2f(x, y);
    glVertex2f(x + 0.05f, y);
    glVertex2f(x, y + 0.1f);
  }
  glEnd();
}

int main(void) {
  require_ffcompat();
  ffcompat_surface* a = surface_on("mesa", 64, 64);
  draw();
  for (int k = 0; k < 20; ++k) {
    ffcompat_surface_destroy(a);
    a = surface_on("mesa", 64 + k, 64);
    draw();
  }
  ffcompat_surface* b = surface_on("mesa", 32, 32);
  draw();
  ffcompat_surface_make_current(a);
  draw();
  ffcompat_surface_destroy(b); /* not current, drawing queued */
  draw();
  surface_on("soft", 64, 64);
  draw();
  ffcompat_surface_make_current(a);
  glBegin(GL_TRIANGLES);
  glVertex2f(0, 0);
  glVertex2f(1, 0); /* left open */
  printf("leaving without finishing\n");
  exit(0);
}
