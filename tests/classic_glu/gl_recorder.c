/* A stand-in for the handful of gl* entry points that GLU quadrics, GLUT shapes and GLUT text
 * call: each call is written to stdout as one line, floats in hexadecimal (exact), and the client
 * arrays of glDrawArrays/glDrawElements are expanded vertex by vertex. Linked into a probe
 * executable, these definitions take precedence over libGL's for the GLU or GLUT library the
 * probe loads, so two probes that differ only in that library print the same lines exactly when
 * the library makes the same calls with the same values. No GL context is needed. */
#include <GL/gl.h>
#include <stdio.h>
#include <string.h>

#define EXPORT __attribute__((visibility("default")))

struct client_array {
  int enabled;
  GLint size;
  GLenum type;
  GLsizei stride;
  const GLvoid *pointer;
};
static struct client_array vertex_array, normal_array, texcoord_array;

static struct client_array *array_for(GLenum cap) {
  switch (cap) {
    case GL_VERTEX_ARRAY: return &vertex_array;
    case GL_NORMAL_ARRAY: return &normal_array;
    case GL_TEXTURE_COORD_ARRAY: return &texcoord_array;
    default: return NULL;
  }
}

EXPORT void glEnableClientState(GLenum cap) {
  struct client_array *a = array_for(cap);
  printf("EnableClientState 0x%x\n", cap);
  if (a) a->enabled = 1;
}
EXPORT void glDisableClientState(GLenum cap) {
  struct client_array *a = array_for(cap);
  printf("DisableClientState 0x%x\n", cap);
  if (a) a->enabled = 0;
}
static void set_array(struct client_array *a, const char *name, GLint size, GLenum type, GLsizei stride,
                      const GLvoid *pointer) {
  printf("%s %d 0x%x %d\n", name, size, type, stride);
  a->size = size;
  a->type = type;
  a->stride = stride;
  a->pointer = pointer;
}
EXPORT void glVertexPointer(GLint size, GLenum type, GLsizei stride, const GLvoid *p) {
  set_array(&vertex_array, "VertexPointer", size, type, stride, p);
}
EXPORT void glNormalPointer(GLenum type, GLsizei stride, const GLvoid *p) {
  set_array(&normal_array, "NormalPointer", 3, type, stride, p);
}
EXPORT void glTexCoordPointer(GLint size, GLenum type, GLsizei stride, const GLvoid *p) {
  set_array(&texcoord_array, "TexCoordPointer", size, type, stride, p);
}

/* Only float arrays are used by the libraries under test; anything else is printed as such. */
static void print_element(const char *tag, const struct client_array *a, GLint index) {
  if (!a->enabled) return;
  if (a->type != GL_FLOAT) {
    printf(" %s(type 0x%x)", tag, a->type);
    return;
  }
  const GLsizei stride = a->stride ? a->stride : a->size * (GLsizei)sizeof(GLfloat);
  const GLfloat *v = (const GLfloat *)((const char *)a->pointer + (size_t)index * stride);
  printf(" %s", tag);
  for (GLint c = 0; c < a->size; ++c) printf(" %a", v[c]);
}
static void print_array_vertex(GLint index) {
  printf("  [%d]", index);
  print_element("v", &vertex_array, index);
  print_element("n", &normal_array, index);
  print_element("t", &texcoord_array, index);
  printf("\n");
}
EXPORT void glDrawArrays(GLenum mode, GLint first, GLsizei count) {
  printf("DrawArrays 0x%x %d %d\n", mode, first, count);
  for (GLint i = first; i < first + count; ++i) print_array_vertex(i);
}
EXPORT void glDrawElements(GLenum mode, GLsizei count, GLenum type, const GLvoid *indices) {
  printf("DrawElements 0x%x %d 0x%x\n", mode, count, type);
  for (GLsizei i = 0; i < count; ++i) {
    GLint index = type == GL_UNSIGNED_SHORT ? ((const GLushort *)indices)[i]
                  : type == GL_UNSIGNED_INT ? (GLint)((const GLuint *)indices)[i]
                                            : ((const GLubyte *)indices)[i];
    print_array_vertex(index);
  }
}

EXPORT void glBegin(GLenum mode) { printf("Begin 0x%x\n", mode); }
EXPORT void glEnd(void) { printf("End\n"); }
EXPORT void glVertex2f(GLfloat x, GLfloat y) { printf("  Vertex2f %a %a\n", x, y); }
EXPORT void glVertex3f(GLfloat x, GLfloat y, GLfloat z) { printf("  Vertex3f %a %a %a\n", x, y, z); }
EXPORT void glNormal3f(GLfloat x, GLfloat y, GLfloat z) { printf("  Normal3f %a %a %a\n", x, y, z); }
EXPORT void glTexCoord2f(GLfloat s, GLfloat t) { printf("  TexCoord2f %a %a\n", s, t); }

EXPORT void glMultMatrixd(const GLdouble *m) {
  printf("MultMatrixd");
  for (int i = 0; i < 16; ++i) printf(" %a", m[i]);
  printf("\n");
}
EXPORT void glMultMatrixf(const GLfloat *m) {
  printf("MultMatrixf");
  for (int i = 0; i < 16; ++i) printf(" %a", m[i]);
  printf("\n");
}
EXPORT void glTranslated(GLdouble x, GLdouble y, GLdouble z) { printf("Translated %a %a %a\n", x, y, z); }
EXPORT void glTranslatef(GLfloat x, GLfloat y, GLfloat z) { printf("Translatef %a %a %a\n", x, y, z); }
EXPORT void glScalef(GLfloat x, GLfloat y, GLfloat z) { printf("Scalef %a %a %a\n", x, y, z); }
EXPORT void glOrtho(GLdouble l, GLdouble r, GLdouble b, GLdouble t, GLdouble n, GLdouble f) {
  printf("Ortho %a %a %a %a %a %a\n", l, r, b, t, n, f);
}

/* Text: the glyph itself is what matters; how the unpack state is saved around it is not. */
EXPORT void glBitmap(GLsizei w, GLsizei h, GLfloat xorig, GLfloat yorig, GLfloat xmove, GLfloat ymove,
                     const GLubyte *bitmap) {
  printf("Bitmap %d %d %a %a %a %a", w, h, xorig, yorig, xmove, ymove);
  if (bitmap) {
    const int bytes = h * ((w + 7) / 8);
    printf(" ");
    for (int i = 0; i < bytes; ++i) printf("%02x", bitmap[i]);
  }
  printf("\n");
}
EXPORT void glPixelStorei(GLenum pname, GLint param) { (void)pname; (void)param; }
EXPORT void glPushClientAttrib(GLbitfield mask) { (void)mask; }
EXPORT void glPopClientAttrib(void) {}
EXPORT void glGetIntegerv(GLenum pname, GLint *params) {
  (void)pname;
  if (params) *params = 0;
}
