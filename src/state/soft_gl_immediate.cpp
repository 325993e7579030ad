// The immediate-mode entry points in every variant classic programs call (GL 2.1 section 2.7):
// glVertex{2,3,4}, glNormal3, glColor{3,4}, glTexCoord{1,2,3,4} in each type, scalar and vector,
// glEdgeFlag and glRect. Each family is written once as a macro over its types; the integer
// conversions are Mesa's (main/macros.h, api_loopback.c): colours and normals map a signed
// integer c of b bits to (2c + 1) / (2^b - 1) and an unsigned one to c / (2^b - 1), in float;
// positions and texture coordinates convert directly. Every variant ends in one by-value call
// that display lists record (LISTABLE).
#include "state/soft_gl_entries.h"

namespace ffc::state::entry {
namespace {

// Mesa's BYTE_TO_FLOAT, SHORT_TO_FLOAT, INT_TO_FLOAT, UBYTE/USHORT/UINT_TO_FLOAT; floats unchanged.
GLfloat unit(GLbyte c) { return (2.0F * GLfloat(c) + 1.0F) * (1.0F / 255.0F); }
GLfloat unit(GLshort c) { return (2.0F * GLfloat(c) + 1.0F) * (1.0F / 65535.0F); }
GLfloat unit(GLint c) { return GLfloat((2.0F * GLfloat(c) + 1.0F) * (1.0F / 4294967294.0)); }
GLfloat unit(GLubyte c) { return GLfloat(c) / 255.0F; }
GLfloat unit(GLushort c) { return GLfloat(c) / 65535.0F; }
GLfloat unit(GLuint c) { return GLfloat(c * (1.0 / 4294967295.0)); }
GLfloat unit(GLfloat c) { return c; }
// glColor*d and glNormal3b..d: Mesa passes doubles on as floats. (glNormal3d and glVertex*d keep
// their doubles here, as they always have: the double pipeline reads them.)
GLfloat unit(GLdouble c) { return GLfloat(c); }

}  // namespace

// The by-value calls that every variant ends in, and that lists record.
// The first test is immediate mode's store (Context::store_vertex), which stands for the rest
// inside a glBegin(GL_TRIANGLES) on the triangle list. `size`: the components the call gave (the
// vbo format grows with them: Context::position_size).
void APIENTRY VertexValues(GLdouble x, GLdouble y, GLdouble z, GLdouble w, GLint size) {
  if (Context* c = C(); c && c->store_vertex(float(x), float(y), float(z), float(w), size)) return;
  LISTABLE_VERTEX(VertexValues, x, y, z, w, size);
  if (Context* c = C()) c->Vertex(x, y, z, w, size);
}
void APIENTRY NormalValues(GLdouble x, GLdouble y, GLdouble z) {
  if (Context* c = C(); c && c->store_normal(x, y, z)) return;
  LISTABLE_VERTEX(NormalValues, x, y, z);
  if (Context* c = C()) c->Normal(x, y, z);
}
// `components`: 3 for glColor3f/glColor3fv only. Mesa's vbo takes every other glColor3 (the integer
// and double ones) as a 4-component colour with alpha 1, so it never keeps an old alpha
// (Context::Color).
void APIENTRY ColorValues(GLdouble r, GLdouble g, GLdouble b, GLdouble a, GLint components) {
  LISTABLE_VERTEX(ColorValues, r, g, b, a, components);
  if (Context* c = C()) c->Color(r, g, b, a, components);
}
void APIENTRY TexCoordValues(GLfloat s, GLfloat t, GLfloat r, GLfloat q) {
  LISTABLE_VERTEX(TexCoordValues, s, t, r, q);
  if (Context* c = C()) c->TexCoord(s, t, r, q);
}

// glVertex: positions convert directly; missing z is 0, missing w is 1.
#define FFC_VERTEX(T, s)                                                                                   \
  void APIENTRY Vertex2##s(T x, T y) { VertexValues(x, y, 0, 1, 2); }                                     \
  void APIENTRY Vertex2##s##v(const T* v) { VertexValues(v[0], v[1], 0, 1, 2); }                         \
  void APIENTRY Vertex3##s(T x, T y, T z) { VertexValues(x, y, z, 1, 3); }                                \
  void APIENTRY Vertex3##s##v(const T* v) { VertexValues(v[0], v[1], v[2], 1, 3); }                       \
  void APIENTRY Vertex4##s(T x, T y, T z, T w) { VertexValues(x, y, z, w, 4); }                           \
  void APIENTRY Vertex4##s##v(const T* v) { VertexValues(v[0], v[1], v[2], v[3], 4); }
FFC_VERTEX(GLshort, s)
FFC_VERTEX(GLint, i)
FFC_VERTEX(GLdouble, d)
#undef FFC_VERTEX
// The float forms try the store themselves: VertexValues' own test comes after a conversion to
// double and a call.
#define FFC_STORE_VERTEX(x, y, z, w, size) \
  if (Context* c = C(); c && c->store_vertex(x, y, z, w, size)) return
void APIENTRY Vertex2f(GLfloat x, GLfloat y) { VertexValues(x, y, 0, 1, 2); }
void APIENTRY Vertex2fv(const GLfloat* v) { VertexValues(v[0], v[1], 0, 1, 2); }
void APIENTRY Vertex3f(GLfloat x, GLfloat y, GLfloat z) {
  FFC_STORE_VERTEX(x, y, z, 1, 3);
  VertexValues(x, y, z, 1, 3);
}
void APIENTRY Vertex3fv(const GLfloat* v) {
  FFC_STORE_VERTEX(v[0], v[1], v[2], 1, 3);
  VertexValues(v[0], v[1], v[2], 1, 3);
}
void APIENTRY Vertex4f(GLfloat x, GLfloat y, GLfloat z, GLfloat w) { VertexValues(x, y, z, w, 4); }
void APIENTRY Vertex4fv(const GLfloat* v) { VertexValues(v[0], v[1], v[2], v[3], 4); }
#undef FFC_STORE_VERTEX

// glNormal3: integers onto [-1, 1].
#define FFC_NORMAL(T, s)                                                                       \
  void APIENTRY Normal3##s(T x, T y, T z) {                                                   \
    if (Context* c = C(); c && c->store_normal(unit(x), unit(y), unit(z))) return;           \
    NormalValues(unit(x), unit(y), unit(z));                                                  \
  }                                                                                           \
  void APIENTRY Normal3##s##v(const T* v) { Normal3##s(v[0], v[1], v[2]); }
FFC_NORMAL(GLbyte, b)
FFC_NORMAL(GLshort, s)
FFC_NORMAL(GLint, i)
FFC_NORMAL(GLfloat, f)
#undef FFC_NORMAL
void APIENTRY Normal3d(GLdouble x, GLdouble y, GLdouble z) { NormalValues(x, y, z); }
void APIENTRY Normal3dv(const GLdouble* v) { NormalValues(v[0], v[1], v[2]); }

// glColor: integers onto [0, 1] or [-1, 1]; glColor3 of any type but float as four components.
#define FFC_COLOR(T, s, three)                                                                                     \
  void APIENTRY Color3##s(T r, T g, T b) { ColorValues(unit(r), unit(g), unit(b), 1, three); }                    \
  void APIENTRY Color3##s##v(const T* v) { ColorValues(unit(v[0]), unit(v[1]), unit(v[2]), 1, three); }           \
  void APIENTRY Color4##s(T r, T g, T b, T a) { ColorValues(unit(r), unit(g), unit(b), unit(a), 4); }             \
  void APIENTRY Color4##s##v(const T* v) { ColorValues(unit(v[0]), unit(v[1]), unit(v[2]), unit(v[3]), 4); }
FFC_COLOR(GLbyte, b, 4)
FFC_COLOR(GLshort, s, 4)
FFC_COLOR(GLint, i, 4)
FFC_COLOR(GLfloat, f, 3)
FFC_COLOR(GLdouble, d, 4)
FFC_COLOR(GLubyte, ub, 4)
FFC_COLOR(GLushort, us, 4)
FFC_COLOR(GLuint, ui, 4)
#undef FFC_COLOR

// glTexCoord: direct conversion to float; missing t and r are 0, missing q is 1.
#define FFC_TEXCOORD(T, s)                                                                                     \
  void APIENTRY TexCoord1##s(T a) { TexCoordValues(GLfloat(a), 0, 0, 1); }                                    \
  void APIENTRY TexCoord1##s##v(const T* v) { TexCoordValues(GLfloat(v[0]), 0, 0, 1); }                       \
  void APIENTRY TexCoord2##s(T a, T b) { TexCoordValues(GLfloat(a), GLfloat(b), 0, 1); }                      \
  void APIENTRY TexCoord2##s##v(const T* v) { TexCoordValues(GLfloat(v[0]), GLfloat(v[1]), 0, 1); }           \
  void APIENTRY TexCoord3##s(T a, T b, T c) { TexCoordValues(GLfloat(a), GLfloat(b), GLfloat(c), 1); }        \
  void APIENTRY TexCoord3##s##v(const T* v) { TexCoordValues(GLfloat(v[0]), GLfloat(v[1]), GLfloat(v[2]), 1); } \
  void APIENTRY TexCoord4##s(T a, T b, T c, T d) { TexCoordValues(GLfloat(a), GLfloat(b), GLfloat(c), GLfloat(d)); } \
  void APIENTRY TexCoord4##s##v(const T* v) {                                                                  \
    TexCoordValues(GLfloat(v[0]), GLfloat(v[1]), GLfloat(v[2]), GLfloat(v[3]));                               \
  }
FFC_TEXCOORD(GLshort, s)
FFC_TEXCOORD(GLint, i)
FFC_TEXCOORD(GLfloat, f)
FFC_TEXCOORD(GLdouble, d)
#undef FFC_TEXCOORD

void APIENTRY EdgeFlag(GLboolean flag) {
  LISTABLE_VERTEX(EdgeFlag, flag);
  if (Context* c = C()) c->EdgeFlag(flag);
}
void APIENTRY EdgeFlagv(const GLboolean* flag) { EdgeFlag(*flag); }

// glRect: a quad (x1, y1), (x2, y1), (x2, y2), (x1, y2) at z = 0, as Mesa draws it (GL 2.1 section
// 2.10); an error inside glBegin/glEnd. Recorded whole, it checks when the list runs.
void APIENTRY RectValues(GLfloat x1, GLfloat y1, GLfloat x2, GLfloat y2) {
  LISTABLE_VERTEX(RectValues, x1, y1, x2, y2);
  if (Context* c = C()) c->Rect(x1, y1, x2, y2);
}
#define FFC_RECT(T, s)                                                                                     \
  void APIENTRY Rect##s(T x1, T y1, T x2, T y2) { RectValues(GLfloat(x1), GLfloat(y1), GLfloat(x2), GLfloat(y2)); } \
  void APIENTRY Rect##s##v(const T* a, const T* b) { RectValues(GLfloat(a[0]), GLfloat(a[1]), GLfloat(b[0]), GLfloat(b[1])); }
FFC_RECT(GLshort, s)
FFC_RECT(GLint, i)
FFC_RECT(GLfloat, f)
FFC_RECT(GLdouble, d)
#undef FFC_RECT

void APIENTRY Hint(GLenum target, GLenum mode) {
  LISTABLE(Hint, target, mode);
  if (Context* c = C()) c->Hint(target, mode);
}
void APIENTRY TexCoordPointer(GLint size, GLenum type, GLsizei stride, const GLvoid* p) {
  if (Context* c = C()) c->TexCoordPointer(size, type, stride, p);
}
void APIENTRY InterleavedArrays(GLenum format, GLsizei stride, const GLvoid* p) {
  if (Context* c = C()) c->InterleavedArrays(format, stride, p);
}

}  // namespace ffc::state::entry
