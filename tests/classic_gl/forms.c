/* The other forms of calls soft has (every glRasterPos, glGetLightiv, glGetMaterialiv, glPixelStoref,
 * the transposed matrix loads, glDrawRangeElements's error) give what Mesa gives, through the plain gl*
 * exports: integer conversions, raster positions, matrices. */
#define _POSIX_C_SOURCE 200809L
#include "classic_test.h"
#include <string.h>
static void probe(const char* backend, GLint li[32], GLfloat rp[16], GLdouble mv[16], GLint* err) {
  surface_on(backend, 32, 32);
  GLfloat pos[4] = {1.5f, -2.25f, 3.75f, 1}, dif[4] = {0.25f, 0.5f, 1.0f, 0.75f};
  glLightfv(GL_LIGHT1, GL_POSITION, pos); glLightfv(GL_LIGHT1, GL_DIFFUSE, dif); glLightf(GL_LIGHT1, GL_SPOT_CUTOFF, 45.7f);
  glMaterialf(GL_FRONT, GL_SHININESS, 12.6f);
  glGetLightiv(GL_LIGHT1, GL_POSITION, li); glGetLightiv(GL_LIGHT1, GL_DIFFUSE, li + 4);
  glGetLightiv(GL_LIGHT1, GL_SPOT_CUTOFF, li + 8); glGetMaterialiv(GL_FRONT, GL_SHININESS, li + 9);
  glGetMaterialiv(GL_FRONT, GL_AMBIENT, li + 10); glGetMaterialiv(GL_BACK, GL_COLOR_INDEXES, li + 14);
  glGetLightiv(GL_LIGHT1, GL_SPOT_DIRECTION, li + 17);
  glRasterPos2i(0, 0); glGetFloatv(GL_CURRENT_RASTER_POSITION, rp);
  glRasterPos3s(-1, 0, 1); glGetFloatv(GL_CURRENT_RASTER_POSITION, rp + 4);
  glRasterPos4dv((const GLdouble[]){0.5, 0.25, 0.125, 2}); glGetFloatv(GL_CURRENT_RASTER_POSITION, rp + 8);
  glPixelStoref(GL_UNPACK_ROW_LENGTH, 2.6f); glGetFloatv(GL_UNPACK_ROW_LENGTH, rp + 12);
  glPixelStoref(GL_UNPACK_LSB_FIRST, 0.25f); glGetFloatv(GL_UNPACK_LSB_FIRST, rp + 13);
  GLfloat t[16] = {1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16};
  glLoadTransposeMatrixf(t); glMultTransposeMatrixd((const GLdouble[]){1,0,0,2, 0,1,0,3, 0,0,1,4, 0,0,0,1});
  glGetDoublev(GL_MODELVIEW_MATRIX, mv);
  glDrawRangeElements(GL_TRIANGLES, 3, 1, 0, GL_UNSIGNED_INT, 0); *err = glGetError();
}
int main(void) {
  require_ffcompat();
  GLint a[32] = {0}, b[32] = {0}; GLfloat ra[16], rb[16]; GLdouble ma[16], mb[16]; GLint ea, eb;
  probe("mesa", a, ra, ma, &ea); probe("soft", b, rb, mb, &eb);
  for (int k = 0; k < 20; ++k) CHECK(a[k] == b[k], "int %d: mesa %d soft %d", k, a[k], b[k]);
  for (int k = 0; k < 14; ++k) CHECK(ra[k] == rb[k], "float %d: mesa %g soft %g", k, ra[k], rb[k]);
  for (int k = 0; k < 16; ++k) CHECK(ma[k] == mb[k], "matrix %d: mesa %g soft %g", k, ma[k], mb[k]);
  CHECK(ea == eb && ea == GL_INVALID_VALUE, "error mesa %x soft %x", ea, eb);
  return finish();
}
