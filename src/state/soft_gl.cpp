// The gl* entry points of our context, for the dispatch: each forwards to the current Context.
#include "state/soft_gl.h"

#include <cstring>
#include <glm/gtc/type_ptr.hpp>

#include "state/context.h"
#include "state/gl_rules.h"
#include "state/soft_gl_fragment.h"

namespace ffc::state {
namespace {

Context* C() { return Context::current(); }

#define FWD(call) \
  if (Context* ctx_ = C()) ctx_->call

void APIENTRY ArrayElement(GLint i) { FWD(ArrayElement(i)); }
void APIENTRY Begin(GLenum m) { FWD(Begin(m)); }
void APIENTRY Clear(GLbitfield m) { FWD(Clear(m)); }
void APIENTRY ClearColor(GLclampf r, GLclampf g, GLclampf b, GLclampf a) { FWD(ClearColor(r, g, b, a)); }
void APIENTRY ClearDepth(GLclampd d) { FWD(ClearDepth(d)); }
void APIENTRY Color3f(GLfloat r, GLfloat g, GLfloat b) { FWD(Color(r, g, b, 1, 3)); }
void APIENTRY Color3fv(const GLfloat* v) { FWD(Color(v[0], v[1], v[2], 1, 3)); }
// Mesa's vbo takes glColor3ub (as every glColor3 but the float ones) as a 4-component colour with
// alpha 1, so it never keeps an old alpha (Context::Color).
void APIENTRY Color3ub(GLubyte r, GLubyte g, GLubyte b) { FWD(Color(r / 255.0, g / 255.0, b / 255.0, 1, 4)); }
void APIENTRY Color4f(GLfloat r, GLfloat g, GLfloat b, GLfloat a) { FWD(Color(r, g, b, a)); }
void APIENTRY Color4fv(const GLfloat* v) { FWD(Color(v[0], v[1], v[2], v[3])); }
void APIENTRY ColorMaterial(GLenum f, GLenum m) { FWD(ColorMaterial(f, m)); }
void APIENTRY ColorPointer(GLint s, GLenum t, GLsizei st, const GLvoid* p) { FWD(ColorPointer(s, t, st, p)); }
void APIENTRY CullFace(GLenum m) { FWD(CullFace(m)); }
void APIENTRY DepthFunc(GLenum f) { FWD(DepthFunc(f)); }
void APIENTRY DepthRange(GLclampd n, GLclampd f) { FWD(DepthRange(n, f)); }
void APIENTRY Disable(GLenum c) { FWD(Disable(c)); }
void APIENTRY DisableClientState(GLenum a) { FWD(DisableClientState(a)); }
void APIENTRY DrawArrays(GLenum m, GLint f, GLsizei n) { FWD(DrawArrays(m, f, n)); }
void APIENTRY DrawElements(GLenum m, GLsizei n, GLenum t, const GLvoid* i) { FWD(DrawElements(m, n, t, i)); }
void APIENTRY Enable(GLenum c) { FWD(Enable(c)); }
void APIENTRY EnableClientState(GLenum a) { FWD(EnableClientState(a)); }
void APIENTRY End() { FWD(End()); }
void APIENTRY FeedbackBuffer(GLsizei s, GLenum t, GLfloat* b) { FWD(FeedbackBuffer(s, t, b)); }
void APIENTRY Finish() { FWD(Finish()); }
void APIENTRY Flush() { FWD(Flush()); }
// glFogf and glFogi pass one value through glFogfv, the other three 0 (Mesa's fog.c); glFogiv
// maps a colour's integers onto [-1, 1] and converts the rest directly, an unknown pname passing
// zeros on for glFogfv to reject.
void APIENTRY Fogf(GLenum p, GLfloat v) {
  const GLfloat f[4] = {v, 0, 0, 0};
  FWD(Fogfv(p, f));
}
void APIENTRY Fogfv(GLenum p, const GLfloat* v) { FWD(Fogfv(p, v)); }
void APIENTRY Fogi(GLenum p, GLint v) {
  const GLfloat f[4] = {GLfloat(v), 0, 0, 0};
  FWD(Fogfv(p, f));
}
void APIENTRY Fogiv(GLenum p, const GLint* v) {
  GLfloat f[4] = {0, 0, 0, 0};
  if (p == GL_FOG_COLOR)
    for (int k = 0; k < 4; ++k) f[k] = int_to_float(v[k]);
  else if (p == GL_FOG_MODE || p == GL_FOG_DENSITY || p == GL_FOG_START || p == GL_FOG_END || p == GL_FOG_INDEX ||
           p == GL_FOG_COORD_SRC)
    f[0] = GLfloat(v[0]);
  FWD(Fogfv(p, f));
}
void APIENTRY FrontFace(GLenum m) { FWD(FrontFace(m)); }
void APIENTRY Frustum(GLdouble l, GLdouble r, GLdouble b, GLdouble t, GLdouble n, GLdouble f) { FWD(Frustum(l, r, b, t, n, f)); }
void APIENTRY GetBooleanv(GLenum p, GLboolean* v) { FWD(GetBooleanv(p, v)); }
void APIENTRY GetDoublev(GLenum p, GLdouble* v) { FWD(GetDoublev(p, v)); }
GLenum APIENTRY GetError() { return C() ? C()->GetError() : GL_NO_ERROR; }
void APIENTRY GetFloatv(GLenum p, GLfloat* v) { FWD(GetFloatv(p, v)); }
void APIENTRY GetIntegerv(GLenum p, GLint* v) { FWD(GetIntegerv(p, v)); }
void APIENTRY GetPointerv(GLenum p, GLvoid** v) { FWD(GetPointerv(p, v)); }
void APIENTRY GetLightfv(GLenum l, GLenum p, GLfloat* v) { FWD(GetLightfv(l, p, v)); }
void APIENTRY GetMaterialfv(GLenum f, GLenum p, GLfloat* v) { FWD(GetMaterialfv(f, p, v)); }
const GLubyte* APIENTRY GetString(GLenum n) { return C() ? C()->GetString(n) : nullptr; }
GLboolean APIENTRY IsEnabled(GLenum c) { return C() ? C()->IsEnabled(c) : GL_FALSE; }
void APIENTRY LightModelf(GLenum p, GLfloat v) { FWD(LightModelf(p, v)); }
void APIENTRY LightModelfv(GLenum p, const GLfloat* v) { FWD(LightModelfv(p, v)); }
void APIENTRY LightModeli(GLenum p, GLint v) { FWD(LightModeli(p, v)); }
void APIENTRY Lightf(GLenum l, GLenum p, GLfloat v) { FWD(Lightf(l, p, v)); }
void APIENTRY Lightfv(GLenum l, GLenum p, const GLfloat* v) { FWD(Lightfv(l, p, v)); }
void APIENTRY Lighti(GLenum l, GLenum p, GLint v) { FWD(Lighti(l, p, v)); }
void APIENTRY Lightiv(GLenum l, GLenum p, const GLint* v) { FWD(Lightiv(l, p, v)); }
// glLightModeliv and glMaterialiv convert as Mesa's do (light.c, api_loopback.c): colours map
// onto [-1, 1], other values convert directly; an unknown pname passes through to the float call,
// which raises the error.
void APIENTRY LightModeliv(GLenum p, const GLint* v) {
  GLfloat f[4] = {0, 0, 0, 0};
  if (p == GL_LIGHT_MODEL_AMBIENT)
    for (int k = 0; k < 4; ++k) f[k] = int_to_float(v[k]);
  else if (p == GL_LIGHT_MODEL_LOCAL_VIEWER || p == GL_LIGHT_MODEL_TWO_SIDE || p == GL_LIGHT_MODEL_COLOR_CONTROL)
    f[0] = GLfloat(v[0]);
  FWD(LightModelfv(p, f));
}
void APIENTRY Materialiv(GLenum face, GLenum p, const GLint* v) {
  GLfloat f[4] = {0, 0, 0, 0};
  switch (p) {
    case GL_AMBIENT: case GL_DIFFUSE: case GL_SPECULAR: case GL_EMISSION: case GL_AMBIENT_AND_DIFFUSE:
      for (int k = 0; k < 4; ++k) f[k] = int_to_float(v[k]);
      break;
    case GL_SHININESS: f[0] = GLfloat(v[0]); break;
    case GL_COLOR_INDEXES: for (int k = 0; k < 3; ++k) f[k] = GLfloat(v[k]); break;
  }
  FWD(Materialfv(face, p, f));
}
void APIENTRY LineWidth(GLfloat w) { FWD(LineWidth(w)); }
void APIENTRY LoadIdentity() { FWD(LoadIdentity()); }
void APIENTRY LoadMatrixd(const GLdouble* m) { FWD(LoadMatrix(glm::make_mat4(m))); }
void APIENTRY LoadMatrixf(const GLfloat* m) { FWD(LoadMatrix(glm::dmat4(glm::make_mat4(m)))); }
void APIENTRY Materialf(GLenum f, GLenum p, GLfloat v) { FWD(Materialf(f, p, v)); }
void APIENTRY Materialfv(GLenum f, GLenum p, const GLfloat* v) { FWD(Materialfv(f, p, v)); }
void APIENTRY Materiali(GLenum f, GLenum p, GLint v) { FWD(Materiali(f, p, v)); }
void APIENTRY MatrixMode(GLenum m) { FWD(MatrixMode(m)); }
void APIENTRY MultMatrixd(const GLdouble* m) { FWD(MultMatrix(glm::make_mat4(m))); }
void APIENTRY MultMatrixf(const GLfloat* m) { FWD(MultMatrix(glm::dmat4(glm::make_mat4(m)))); }
void APIENTRY Normal3d(GLdouble x, GLdouble y, GLdouble z) { FWD(Normal(x, y, z)); }
void APIENTRY Normal3dv(const GLdouble* v) { FWD(Normal(v[0], v[1], v[2])); }
void APIENTRY Normal3f(GLfloat x, GLfloat y, GLfloat z) { FWD(Normal(x, y, z)); }
void APIENTRY Normal3fv(const GLfloat* v) { FWD(Normal(v[0], v[1], v[2])); }
void APIENTRY NormalPointer(GLenum t, GLsizei s, const GLvoid* p) { FWD(NormalPointer(t, s, p)); }
void APIENTRY Ortho(GLdouble l, GLdouble r, GLdouble b, GLdouble t, GLdouble n, GLdouble f) { FWD(Ortho(l, r, b, t, n, f)); }
void APIENTRY PixelStorei(GLenum p, GLint v) { FWD(PixelStorei(p, v)); }
void APIENTRY PointSize(GLfloat s) { FWD(PointSize(s)); }
void APIENTRY PolygonOffset(GLfloat f, GLfloat u) { FWD(PolygonOffset(f, u)); }
void APIENTRY PopMatrix() { FWD(PopMatrix()); }
void APIENTRY PushMatrix() { FWD(PushMatrix()); }
void APIENTRY ReadPixels(GLint x, GLint y, GLsizei w, GLsizei h, GLenum f, GLenum t, GLvoid* p) { FWD(ReadPixels(x, y, w, h, f, t, p)); }
GLint APIENTRY RenderMode(GLenum m) { return C() ? C()->RenderMode(m) : 0; }
void APIENTRY RasterPos2f(GLfloat x, GLfloat y) { FWD(RasterPos(x, y, 0, 1)); }
void APIENTRY DrawPixels(GLsizei w, GLsizei h, GLenum f, GLenum t, const GLvoid* p) { FWD(DrawPixels(w, h, f, t, p)); }
void APIENTRY Rotated(GLdouble a, GLdouble x, GLdouble y, GLdouble z) { FWD(Rotate(a, x, y, z)); }
// glRotatef and friends build their matrices from float arguments; the double maths after that
// differs from Mesa's float maths by rounding only.
void APIENTRY Rotatef(GLfloat a, GLfloat x, GLfloat y, GLfloat z) { FWD(Rotate(a, x, y, z)); }
void APIENTRY Scaled(GLdouble x, GLdouble y, GLdouble z) { FWD(Scale(x, y, z)); }
void APIENTRY Scalef(GLfloat x, GLfloat y, GLfloat z) { FWD(Scale(x, y, z)); }
void APIENTRY ShadeModel(GLenum m) { FWD(ShadeModel(m)); }
void APIENTRY Translated(GLdouble x, GLdouble y, GLdouble z) { FWD(Translate(x, y, z)); }
void APIENTRY Translatef(GLfloat x, GLfloat y, GLfloat z) { FWD(Translate(x, y, z)); }
void APIENTRY Vertex2f(GLfloat x, GLfloat y) { FWD(Vertex(x, y, 0, 1)); }
void APIENTRY Vertex3d(GLdouble x, GLdouble y, GLdouble z) { FWD(Vertex(x, y, z, 1)); }
void APIENTRY Vertex3dv(const GLdouble* v) { FWD(Vertex(v[0], v[1], v[2], 1)); }
void APIENTRY Vertex3f(GLfloat x, GLfloat y, GLfloat z) { FWD(Vertex(x, y, z, 1)); }
void APIENTRY Vertex3fv(const GLfloat* v) { FWD(Vertex(v[0], v[1], v[2], 1)); }
void APIENTRY VertexPointer(GLint s, GLenum t, GLsizei st, const GLvoid* p) { FWD(VertexPointer(s, t, st, p)); }
void APIENTRY Viewport(GLint x, GLint y, GLsizei w, GLsizei h) { FWD(Viewport(x, y, w, h)); }
#undef FWD

template <typename F>
void* entry(F* f) {
  return reinterpret_cast<void*>(f);
}

}  // namespace

void* proc_address(const char* name) {
  if (void* f = fragment_proc_address(name)) return f;  // soft_gl_fragment.cpp
#define FFC_GL_FUNCTION(ret, fn, params) \
  if (std::strcmp(name, "gl" #fn) == 0) return entry(fn);
#include "gl/gl_functions.inc"
#undef FFC_GL_FUNCTION
  // Entry points outside the dispatch's list, for callers that load them by name.
  if (std::strcmp(name, "glLightiv") == 0) return reinterpret_cast<void*>(&Lightiv);
  if (std::strcmp(name, "glLightModeliv") == 0) return reinterpret_cast<void*>(&LightModeliv);
  if (std::strcmp(name, "glMaterialiv") == 0) return reinterpret_cast<void*>(&Materialiv);
  return nullptr;
}

}  // namespace ffc::state
