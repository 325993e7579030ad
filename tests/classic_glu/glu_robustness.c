/* Bad input and the unimplemented parts of ffcompat's libGLU, where the system GLU has nothing to
 * compare with (it crashes on null arrays, it implements the tessellator): each line printed is
 * checked by glu_robustness_test.cpp. */
#include <GL/glu.h>
#include <stdio.h>

int main(void) {
  GLdouble m[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1}, x = 0, y = 0, z = 0, w = 0;
  GLint view[4] = {0, 0, 100, 100};
  /* No quadric: nothing drawn, nothing reported. */
  gluSphere(NULL, 1, 8, 8);
  gluCylinder(NULL, 1, 1, 1, 8, 2);
  gluDisk(NULL, 0, 1, 8, 2);
  gluQuadricNormals(NULL, GLU_FLAT);
  gluDeleteQuadric(NULL);
  /* Missing arrays: the call fails, nothing is written. */
  printf("project %d\n", gluProject(1, 2, 3, NULL, m, view, &x, &y, &z));
  printf("project out %d\n", gluProject(1, 2, 3, m, m, view, NULL, &y, &z));
  printf("unproject %d\n", gluUnProject(1, 2, 0.5, m, NULL, view, &x, &y, &z));
  printf("unproject4 %d\n", gluUnProject4(1, 2, 0.5, 1, m, m, NULL, 0, 1, &x, &y, &z, &w));
  gluPickMatrix(1, 2, 3, 4, NULL);
  printf("no such error %d\n", gluErrorString(12345) == NULL);
  printf("null extension %d\n", gluCheckExtension(NULL, (const GLubyte *)"a"));
  /* The tessellator and NURBS: objects exist, calls do nothing, each name is reported once. */
  GLUtesselator *tess = gluNewTess();
  GLdouble vertex[3] = {0, 0, 0}, property = -1;
  printf("tess %d\n", tess != NULL);
  gluTessBeginPolygon(tess, NULL);
  gluTessVertex(tess, vertex, vertex);
  gluTessVertex(tess, vertex, vertex);
  gluGetTessProperty(tess, GLU_TESS_WINDING_RULE, &property);
  printf("tess property %g\n", property);
  gluDeleteTess(tess);
  GLUnurbs *nurbs = gluNewNurbsRenderer();
  printf("nurbs %d\n", nurbs != NULL);
  gluDeleteNurbsRenderer(nurbs);
  unsigned char pixels[16] = {0};
  printf("mipmaps %d\n", gluBuild2DMipmaps(GL_TEXTURE_2D, GL_RGBA, 2, 2, GL_RGBA, GL_UNSIGNED_BYTE, pixels));
  printf("scale %d\n", gluScaleImage(GL_RGBA, 2, 2, GL_UNSIGNED_BYTE, pixels, 1, 1, GL_UNSIGNED_BYTE, pixels));
  printf("done\n");
  return 0;
}
