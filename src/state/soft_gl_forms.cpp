// More forms of calls soft already has: every glRasterPos, glGetLightiv and glGetMaterialiv,
// glPixelStoref, glDrawRangeElements and the transposed matrix loads (GL 1.3). Each converts its
// arguments as Mesa's entry points do and goes through the float or integer form.
#include <cmath>

#include "state/soft_gl_entries.h"

namespace ffc::state::entry {

// glRasterPos: integers, shorts and doubles become floats, as Mesa's glRasterPos* take them.
void APIENTRY RasterPos4f(GLfloat x, GLfloat y, GLfloat z, GLfloat w) {
  LISTABLE(RasterPos4f, x, y, z, w);
  if (Context* c = C()) c->RasterPos(x, y, z, w);
}
void APIENTRY RasterPos2d(GLdouble x, GLdouble y) { RasterPos4f(GLfloat(x), GLfloat(y), 0, 1); }
void APIENTRY RasterPos2i(GLint x, GLint y) { RasterPos4f(GLfloat(x), GLfloat(y), 0, 1); }
void APIENTRY RasterPos2s(GLshort x, GLshort y) { RasterPos4f(x, y, 0, 1); }
void APIENTRY RasterPos3d(GLdouble x, GLdouble y, GLdouble z) { RasterPos4f(GLfloat(x), GLfloat(y), GLfloat(z), 1); }
void APIENTRY RasterPos3f(GLfloat x, GLfloat y, GLfloat z) { RasterPos4f(x, y, z, 1); }
void APIENTRY RasterPos3i(GLint x, GLint y, GLint z) { RasterPos4f(GLfloat(x), GLfloat(y), GLfloat(z), 1); }
void APIENTRY RasterPos3s(GLshort x, GLshort y, GLshort z) { RasterPos4f(x, y, z, 1); }
void APIENTRY RasterPos4d(GLdouble x, GLdouble y, GLdouble z, GLdouble w) {
  RasterPos4f(GLfloat(x), GLfloat(y), GLfloat(z), GLfloat(w));
}
void APIENTRY RasterPos4i(GLint x, GLint y, GLint z, GLint w) { RasterPos4f(GLfloat(x), GLfloat(y), GLfloat(z), GLfloat(w)); }
void APIENTRY RasterPos4s(GLshort x, GLshort y, GLshort z, GLshort w) { RasterPos4f(x, y, z, w); }
void APIENTRY RasterPos2dv(const GLdouble* v) { RasterPos2d(v[0], v[1]); }
void APIENTRY RasterPos2fv(const GLfloat* v) { RasterPos4f(v[0], v[1], 0, 1); }
void APIENTRY RasterPos2iv(const GLint* v) { RasterPos2i(v[0], v[1]); }
void APIENTRY RasterPos2sv(const GLshort* v) { RasterPos2s(v[0], v[1]); }
void APIENTRY RasterPos3dv(const GLdouble* v) { RasterPos3d(v[0], v[1], v[2]); }
void APIENTRY RasterPos3fv(const GLfloat* v) { RasterPos4f(v[0], v[1], v[2], 1); }
void APIENTRY RasterPos3iv(const GLint* v) { RasterPos3i(v[0], v[1], v[2]); }
void APIENTRY RasterPos3sv(const GLshort* v) { RasterPos3s(v[0], v[1], v[2]); }
void APIENTRY RasterPos4dv(const GLdouble* v) { RasterPos4d(v[0], v[1], v[2], v[3]); }
void APIENTRY RasterPos4fv(const GLfloat* v) { RasterPos4f(v[0], v[1], v[2], v[3]); }
void APIENTRY RasterPos4iv(const GLint* v) { RasterPos4i(v[0], v[1], v[2], v[3]); }
void APIENTRY RasterPos4sv(const GLshort* v) { RasterPos4s(v[0], v[1], v[2], v[3]); }

// Colours as Mesa's FLOAT_TO_INT maps them (truncated, 1.0 to 2^31 - 1); positions, directions
// and the other scalars truncated; a material's shininess and colour indexes rounded.
namespace {
GLint colour_to_int(GLfloat f) { return GLint(2147483647.0 * double(f)); }
bool is_colour(GLenum p) { return p == GL_AMBIENT || p == GL_DIFFUSE || p == GL_SPECULAR || p == GL_EMISSION; }
}  // namespace

// The float query `get`, its error recorded as the integer call's (a first error before it stays).
template <class Get>
bool float_query(Context* c, Get get) {
  const GLenum before = c->GetError();
  get();
  const GLenum after = c->GetError();
  if (before != GL_NO_ERROR) c->record_error(before);
  if (after != GL_NO_ERROR) c->record_error(after);
  return after == GL_NO_ERROR;
}

void APIENTRY GetLightiv(GLenum light, GLenum p, GLint* out) {
  Context* c = C();
  GLfloat f[4] = {0, 0, 0, 0};
  if (!c || !float_query(c, [&] { c->GetLightfv(light, p, f); })) return;
  const int n = is_colour(p) || p == GL_POSITION ? 4 : p == GL_SPOT_DIRECTION ? 3 : 1;
  for (int k = 0; k < n; ++k) out[k] = is_colour(p) ? colour_to_int(f[k]) : GLint(f[k]);
}
void APIENTRY GetMaterialiv(GLenum face, GLenum p, GLint* out) {
  Context* c = C();
  GLfloat f[4] = {0, 0, 0, 0};
  if (!c || !float_query(c, [&] { c->GetMaterialfv(face, p, f); })) return;
  const int n = is_colour(p) ? 4 : p == GL_COLOR_INDEXES ? 3 : 1;
  for (int k = 0; k < n; ++k) out[k] = is_colour(p) ? colour_to_int(f[k]) : GLint(std::lround(f[k]));
}

// glPixelStoref: the value rounded, boolean names too (Mesa's IROUND; measured: GL_UNPACK_LSB_FIRST
// 0.25 reads back 0).
void APIENTRY PixelStoref(GLenum p, GLfloat v) { PixelStorei(p, GLint(std::lround(v))); }

// glDrawRangeElements: glDrawElements once start <= end (GL 1.2); the range is a promise the
// indices keep, which Mesa does not check either.
void APIENTRY DrawRangeElements(GLenum mode, GLuint start, GLuint end, GLsizei count, GLenum type, const GLvoid* indices) {
  Context* c = C();
  if (!c) return;
  if (end < start) return c->record_error(GL_INVALID_VALUE);
  DrawElements(mode, count, type, indices);
}

// GL 1.3's transposed matrices: the same matrix read by rows.
namespace {
template <typename T>
Floats<16, GLdouble> transposed(const T* m) {
  Floats<16, GLdouble> d;
  for (int r = 0; r < 4; ++r)
    for (int k = 0; k < 4; ++k) d.v[4 * k + r] = m[4 * r + k];
  return d;
}
}  // namespace
void APIENTRY LoadTransposeMatrixd(const GLdouble* m) { LoadMatrixValues(transposed(m)); }
void APIENTRY LoadTransposeMatrixf(const GLfloat* m) { LoadMatrixValues(transposed(m)); }
void APIENTRY MultTransposeMatrixd(const GLdouble* m) { MultMatrixValues(transposed(m)); }
void APIENTRY MultTransposeMatrixf(const GLfloat* m) { MultMatrixValues(transposed(m)); }

}  // namespace ffc::state::entry
