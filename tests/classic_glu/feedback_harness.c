/* Runs a probe (glu_probe.c or glut_probe.c, its main renamed probe_main) on a real GL: Mesa's
 * OSMesa, in feedback mode, lit by three coloured lights along +x, +y and +z so that each vertex's
 * colour shows its normal, with its texture coordinates. Prints the probe's own lines, then the
 * feedback's length and a hash of its bytes: two builds that differ only in the GLU or GLUT
 * library must print the same. The recorder probes name any difference; this one shows that the
 * libraries work on a real GL, linked as a program links them (OSMesa's gl* first). */
#include <GL/gl.h>
#include <GL/osmesa.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>

int probe_main(int argc, char **argv);

int main(int argc, char **argv) {
  static unsigned char pixels[64 * 64 * 4];
  OSMesaContext context = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, NULL);
  if (!context || !OSMesaMakeCurrent(context, pixels, GL_UNSIGNED_BYTE, 64, 64)) {
    fprintf(stderr, "no OSMesa context\n");
    return 1;
  }
  const GLint capacity = 1 << 24;
  GLfloat *buffer = malloc(sizeof(GLfloat) * (size_t)capacity);
  glFeedbackBuffer(capacity, GL_4D_COLOR_TEXTURE, buffer);
  glRenderMode(GL_FEEDBACK);
  const GLfloat black[4] = {0, 0, 0, 1};
  glLightModelfv(GL_LIGHT_MODEL_AMBIENT, black);
  for (int i = 0; i < 3; ++i) {
    GLfloat direction[4] = {i == 0, i == 1, i == 2, 0}, colour[4] = {i == 0, i == 1, i == 2, 1};
    glLightfv(GL_LIGHT0 + i, GL_POSITION, direction);
    glLightfv(GL_LIGHT0 + i, GL_DIFFUSE, colour);
    glLightfv(GL_LIGHT0 + i, GL_SPECULAR, black);
    glEnable(GL_LIGHT0 + i);
  }
  glEnable(GL_LIGHTING);
  glMatrixMode(GL_PROJECTION);
  glOrtho(-4, 4, -4, 4, -20, 20);
  glMatrixMode(GL_MODELVIEW);
  glRasterPos2f(-3.5f, -3.5f);
  const int status = probe_main(argc, argv);
  const GLint count = glRenderMode(GL_RENDER);
  uint64_t hash = 1469598103934665603ull;  /* FNV-1a over the feedback's bytes */
  const unsigned char *bytes = (const unsigned char *)buffer;
  for (size_t i = 0; count > 0 && i < (size_t)count * sizeof(GLfloat); ++i) hash = (hash ^ bytes[i]) * 1099511628211ull;
  printf("feedback %d values, hash %016llx, error 0x%x\n", count, (unsigned long long)hash, glGetError());
  free(buffer);
  OSMesaDestroyContext(context);
  return status;
}
