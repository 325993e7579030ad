// The gl* entry points of our context, for the dispatch: each forwards to the current Context.
#include "state/soft_gl.h"

#include <cstring>
#include <glm/gtc/type_ptr.hpp>

#include "state/context.h"
#include "state/gl_rules.h"
#include "state/soft_gl_entries.h"

namespace ffc::state::entry {

#define FWD(call) \
  if (Context* ctx_ = C()) ctx_->call

// Draws from arrays compile as the values they read now (Context::compile_elements).
void APIENTRY ArrayElement(GLint i) {
  Context* c = C();
  if (!c) return;
  if (DisplayList* l = c->list_recording()) {
    if (!c->list_state().open) c->end_list_node();  // its values compile as opcodes: a flush
    if (i >= 0) c->compile_element(*l, i);
    if (!c->list_executes() || i < 0) return;
    if (c->list_state().open && !c->list_state().fallback) return c->compile_element(c->list_held_back(), i);  // held back
    if (!c->list_state().open) c->run_held_back();  // outside the list's glBegin: executed at once (soft_gl_entries.h)
  }
  c->ArrayElement(i);
}
void APIENTRY Begin(GLenum m) { LISTABLE_VERTEX(Begin, m); FWD(Begin(m)); }
void APIENTRY Clear(GLbitfield m) { LISTABLE(Clear, m); FWD(Clear(m)); }
void APIENTRY ClearColor(GLclampf r, GLclampf g, GLclampf b, GLclampf a) { LISTABLE(ClearColor, r, g, b, a); FWD(ClearColor(r, g, b, a)); }
void APIENTRY ClearDepth(GLclampd d) { LISTABLE(ClearDepth, d); FWD(ClearDepth(d)); }
void APIENTRY ColorMaterial(GLenum f, GLenum m) { LISTABLE(ColorMaterial, f, m); FWD(ColorMaterial(f, m)); }
void APIENTRY ColorPointer(GLint s, GLenum t, GLsizei st, const GLvoid* p) { FWD(ColorPointer(s, t, st, p)); }
void APIENTRY CullFace(GLenum m) { LISTABLE(CullFace, m); FWD(CullFace(m)); }
void APIENTRY DepthFunc(GLenum f) { LISTABLE(DepthFunc, f); FWD(DepthFunc(f)); }
void APIENTRY DepthRange(GLclampd n, GLclampd f) { LISTABLE(DepthRange, n, f); FWD(DepthRange(n, f)); }
void APIENTRY Disable(GLenum c) { LISTABLE(Disable, c); FWD(Disable(c)); }
void APIENTRY DisableClientState(GLenum a) { FWD(DisableClientState(a)); }
void APIENTRY DrawArrays(GLenum m, GLint f, GLsizei n) {
  Context* c = C();
  if (!c) return;
  if (DisplayList* l = c->list_recording()) {
    c->compile_elements(*l, m, n, nullptr, f);
    if (c->list_executes()) c->compile_elements(c->list_held_back(), m, n, nullptr, f);  // held back
    return;
  }
  c->DrawArrays(m, f, n);
}
void APIENTRY DrawElements(GLenum m, GLsizei n, GLenum t, const GLvoid* i) {
  Context* c = C();
  if (!c) return;
  if (DisplayList* l = c->list_recording()) {
    c->compile_draw_elements(*l, m, n, t, i);
    if (c->list_executes()) c->compile_draw_elements(c->list_held_back(), m, n, t, i);  // held back
    return;
  }
  c->DrawElements(m, n, t, i);
}
void APIENTRY Enable(GLenum c) { LISTABLE(Enable, c); FWD(Enable(c)); }
void APIENTRY EnableClientState(GLenum a) { FWD(EnableClientState(a)); }
void APIENTRY End() { LISTABLE_VERTEX(End); FWD(End()); }
void APIENTRY FeedbackBuffer(GLsizei s, GLenum t, GLfloat* b) { FWD(FeedbackBuffer(s, t, b)); }
void APIENTRY Finish() { FWD(Finish()); }
void APIENTRY Flush() { FWD(Flush()); }
// glFogf and glFogi pass one value through glFogfv, the other three 0 (Mesa's fog.c); glFogiv
// maps a colour's integers onto [-1, 1] and converts the rest directly, an unknown pname passing
// zeros on for glFogfv to reject.
// Pointer arguments are copied (as many values as the name takes) into a by-value twin that
// display lists record.
void APIENTRY FogValues(GLenum p, Floats<4> f) { LISTABLE(FogValues, p, f); FWD(Fogfv(p, f.v)); }
void APIENTRY Fogf(GLenum p, GLfloat v) { FogValues(p, {{v, 0, 0, 0}}); }
void APIENTRY Fogfv(GLenum p, const GLfloat* v) {
  Floats<4> f{};
  std::copy(v, v + (p == GL_FOG_COLOR ? 4 : 1), f.v);
  FogValues(p, f);
}
void APIENTRY Fogi(GLenum p, GLint v) { FogValues(p, {{GLfloat(v), 0, 0, 0}}); }
void APIENTRY Fogiv(GLenum p, const GLint* v) {
  GLfloat f[4] = {0, 0, 0, 0};
  if (p == GL_FOG_COLOR)
    for (int k = 0; k < 4; ++k) f[k] = int_to_float(v[k]);
  else if (p == GL_FOG_MODE || p == GL_FOG_DENSITY || p == GL_FOG_START || p == GL_FOG_END || p == GL_FOG_INDEX ||
           p == GL_FOG_COORD_SRC)
    f[0] = GLfloat(v[0]);
  FogValues(p, {{f[0], f[1], f[2], f[3]}});
}
void APIENTRY FrontFace(GLenum m) { LISTABLE(FrontFace, m); FWD(FrontFace(m)); }
void APIENTRY Frustum(GLdouble l, GLdouble r, GLdouble b, GLdouble t, GLdouble n, GLdouble f) { LISTABLE(Frustum, l, r, b, t, n, f); FWD(Frustum(l, r, b, t, n, f)); }
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
void APIENTRY LightModelf(GLenum p, GLfloat v) { LISTABLE(LightModelf, p, v); FWD(LightModelf(p, v)); }
void APIENTRY LightModelValues(GLenum p, Floats<4> f) { LISTABLE(LightModelValues, p, f); FWD(LightModelfv(p, f.v)); }
void APIENTRY LightModelfv(GLenum p, const GLfloat* v) {
  Floats<4> f{};
  std::copy(v, v + (p == GL_LIGHT_MODEL_AMBIENT ? 4 : 1), f.v);
  LightModelValues(p, f);
}
void APIENTRY LightModeli(GLenum p, GLint v) { LISTABLE(LightModeli, p, v); FWD(LightModeli(p, v)); }
void APIENTRY Lightf(GLenum l, GLenum p, GLfloat v) { LISTABLE(Lightf, l, p, v); FWD(Lightf(l, p, v)); }
void APIENTRY LightValues(GLenum l, GLenum p, Floats<4> f) { LISTABLE(LightValues, l, p, f); FWD(Lightfv(l, p, f.v)); }
void APIENTRY Lightfv(GLenum l, GLenum p, const GLfloat* v) {
  Floats<4> f{};
  std::copy(v, v + light_param_count(p), f.v);
  LightValues(l, p, f);
}
void APIENTRY Lighti(GLenum l, GLenum p, GLint v) { LISTABLE(Lighti, l, p, v); FWD(Lighti(l, p, v)); }
void APIENTRY LightIntValues(GLenum l, GLenum p, Floats<4, GLint> f) {
  LISTABLE(LightIntValues, l, p, f);
  FWD(Lightiv(l, p, f.v));
}
void APIENTRY Lightiv(GLenum l, GLenum p, const GLint* v) {
  Floats<4, GLint> f{};
  std::copy(v, v + light_param_count(p), f.v);
  LightIntValues(l, p, f);
}
int material_param_count(GLenum p) {
  switch (p) {
    case GL_AMBIENT: case GL_DIFFUSE: case GL_SPECULAR: case GL_EMISSION: case GL_AMBIENT_AND_DIFFUSE: return 4;
    case GL_SHININESS: return 1;
    case GL_COLOR_INDEXES: return 3;
  }
  return 0;
}
void APIENTRY MaterialValues(GLenum face, GLenum p, Floats<4> v) {
  // While a list compiles, a bad face or pname is a compile error and nothing more: Mesa's vbo
  // Materialfv returns before anything else, so what the list holds is not flushed (measured, seed
  // 161803 stream 532: after a GL_COMPILE_AND_EXECUTE list's wrapped glBegin/glEnd the executing side
  // stays inside the primitive; repro list_material_bad_face_no_flush.txt).
  if (Context* c = C(); c && c->list_recording() && (!valid_face(face) || material_param_count(p) == 0))
    return c->record_list_error(GL_INVALID_ENUM);
  LISTABLE_MATERIAL(MaterialValues, face, p, v);
  FWD(Materialfv(face, p, v.v));
}
// glLightModeliv and glMaterialiv convert as Mesa's do (light.c, api_loopback.c): colours map
// onto [-1, 1], other values convert directly; an unknown pname passes through to the float call,
// which raises the error.
void APIENTRY LightModeliv(GLenum p, const GLint* v) {
  GLfloat f[4] = {0, 0, 0, 0};
  if (p == GL_LIGHT_MODEL_AMBIENT)
    for (int k = 0; k < 4; ++k) f[k] = int_to_float(v[k]);
  else if (p == GL_LIGHT_MODEL_LOCAL_VIEWER || p == GL_LIGHT_MODEL_TWO_SIDE || p == GL_LIGHT_MODEL_COLOR_CONTROL)
    f[0] = GLfloat(v[0]);
  LightModelValues(p, {{f[0], f[1], f[2], f[3]}});
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
  MaterialValues(face, p, {{f[0], f[1], f[2], f[3]}});
}
void APIENTRY LineWidth(GLfloat w) { LISTABLE(LineWidth, w); FWD(LineWidth(w)); }
void APIENTRY LoadIdentity() { LISTABLE(LoadIdentity); FWD(LoadIdentity()); }
void APIENTRY LoadMatrixValues(Floats<16, GLdouble> m) { LISTABLE(LoadMatrixValues, m); FWD(LoadMatrix(glm::make_mat4(m.v))); }
void APIENTRY MultMatrixValues(Floats<16, GLdouble> m) { LISTABLE(MultMatrixValues, m); FWD(MultMatrix(glm::make_mat4(m.v))); }
Floats<16, GLdouble> matrix_values(const GLdouble* m) {
  Floats<16, GLdouble> d;
  std::copy(m, m + 16, d.v);
  return d;
}
Floats<16, GLdouble> matrix_values(const GLfloat* m) {
  Floats<16, GLdouble> d;
  std::copy(m, m + 16, d.v);
  return d;
}
void APIENTRY LoadMatrixd(const GLdouble* m) { LoadMatrixValues(matrix_values(m)); }
void APIENTRY LoadMatrixf(const GLfloat* m) { LoadMatrixValues(matrix_values(m)); }
// glMaterialf and glMateriali reach Mesa's glMaterialfv (its loopback): inside a list's glBegin they
// enter the vertex store as it does, not a state call's flush (measured, seed 161803 stream 2269:
// glMaterialf(GL_FRONT, GL_SHININESS) inside a list's glBegin raised nothing when the list ran, soft
// GL_INVALID_OPERATION; repro list_materialf_inside_begin.txt). (param, 0, 0, 0), as Context::Materialf.
void APIENTRY Materialf(GLenum f, GLenum p, GLfloat v) { MaterialValues(f, p, {{v, 0, 0, 0}}); }
void APIENTRY Materialfv(GLenum f, GLenum p, const GLfloat* v) {
  Floats<4> c{};
  std::copy(v, v + material_param_count(p), c.v);
  MaterialValues(f, p, c);
}
void APIENTRY Materiali(GLenum f, GLenum p, GLint v) { MaterialValues(f, p, {{GLfloat(v), 0, 0, 0}}); }
void APIENTRY MatrixMode(GLenum m) { LISTABLE(MatrixMode, m); FWD(MatrixMode(m)); }
void APIENTRY MultMatrixd(const GLdouble* m) { MultMatrixValues(matrix_values(m)); }
void APIENTRY MultMatrixf(const GLfloat* m) { MultMatrixValues(matrix_values(m)); }
void APIENTRY NormalPointer(GLenum t, GLsizei s, const GLvoid* p) { FWD(NormalPointer(t, s, p)); }
void APIENTRY Ortho(GLdouble l, GLdouble r, GLdouble b, GLdouble t, GLdouble n, GLdouble f) { LISTABLE(Ortho, l, r, b, t, n, f); FWD(Ortho(l, r, b, t, n, f)); }
void APIENTRY PixelStorei(GLenum p, GLint v) { FWD(PixelStorei(p, v)); }
void APIENTRY PointSize(GLfloat s) { LISTABLE(PointSize, s); FWD(PointSize(s)); }
void APIENTRY PolygonOffset(GLfloat f, GLfloat u) { LISTABLE(PolygonOffset, f, u); FWD(PolygonOffset(f, u)); }
void APIENTRY PolygonMode(GLenum f, GLenum m) { LISTABLE(PolygonMode, f, m); FWD(PolygonMode(f, m)); }
void APIENTRY PopMatrix() { LISTABLE(PopMatrix); FWD(PopMatrix()); }
void APIENTRY PushMatrix() { LISTABLE(PushMatrix); FWD(PushMatrix()); }
void APIENTRY ReadPixels(GLint x, GLint y, GLsizei w, GLsizei h, GLenum f, GLenum t, GLvoid* p) { FWD(ReadPixels(x, y, w, h, f, t, p)); }
GLint APIENTRY RenderMode(GLenum m) { return C() ? C()->RenderMode(m) : 0; }
void APIENTRY RasterPos2f(GLfloat x, GLfloat y) { LISTABLE(RasterPos2f, x, y); FWD(RasterPos(x, y, 0, 1)); }
// A glDrawPixels in a list: its image copied as the unpack state reads it now (Context::list_image).
void APIENTRY PackedDrawPixels(GLsizei w, GLsizei h, GLenum f, GLenum t, PackedBits p) { FWD(DrawPixels(w, h, f, t, p.data, true)); }
void APIENTRY DrawPixels(GLsizei w, GLsizei h, GLenum f, GLenum t, const GLvoid* p) {
  Context* c = C();
  if (!c) return;
  if (DisplayList* l = c->list_recording()) {
    const PackedBits image = l->keep(c->list_image(w, h, f, t, p));
    if (compiled_only<ListKind::State, PackedDrawPixels>(w, h, f, t, image)) return;
    return c->DrawPixels(w, h, f, t, image.data, true);
  }
  c->DrawPixels(w, h, f, t, p);
}
void APIENTRY Rotated(GLdouble a, GLdouble x, GLdouble y, GLdouble z) { LISTABLE(Rotated, a, x, y, z); FWD(Rotate(a, x, y, z)); }
// glRotatef and friends build their matrices from float arguments; the double maths after that
// differs from Mesa's float maths by rounding only.
void APIENTRY Rotatef(GLfloat a, GLfloat x, GLfloat y, GLfloat z) { LISTABLE(Rotatef, a, x, y, z); FWD(Rotate(a, x, y, z)); }
void APIENTRY Scaled(GLdouble x, GLdouble y, GLdouble z) { LISTABLE(Scaled, x, y, z); FWD(Scale(x, y, z)); }
void APIENTRY Scalef(GLfloat x, GLfloat y, GLfloat z) { LISTABLE(Scalef, x, y, z); FWD(Scale(x, y, z)); }
void APIENTRY ShadeModel(GLenum m) { LISTABLE(ShadeModel, m); FWD(ShadeModel(m)); }
void APIENTRY Translated(GLdouble x, GLdouble y, GLdouble z) { LISTABLE(Translated, x, y, z); FWD(Translate(x, y, z)); }
void APIENTRY Translatef(GLfloat x, GLfloat y, GLfloat z) { LISTABLE(Translatef, x, y, z); FWD(Translate(x, y, z)); }
void APIENTRY VertexPointer(GLint s, GLenum t, GLsizei st, const GLvoid* p) { FWD(VertexPointer(s, t, st, p)); }
void APIENTRY Viewport(GLint x, GLint y, GLsizei w, GLsizei h) { LISTABLE(Viewport, x, y, w, h); FWD(Viewport(x, y, w, h)); }
// Display lists (display_list.cpp). glCallList and glListBase compile; glCallLists records its
// names itself; the others execute at once.
// glCallList flushes what GL_COMPILE_AND_EXECUTE held back (soft_gl_entries.h), but not inside the
// list's open glBegin (measured), and executes. List 0 is GL_INVALID_VALUE when called, but
// compiled it does nothing (Mesa).
void APIENTRY CallListRecorded(GLuint l) { FWD(CallList(l)); }
void APIENTRY CallList(GLuint l) {
  Context* c = C();
  if (!c) return;
  if (DisplayList* rec = c->list_recording()) {
    // Mesa's compiler forgets what the list compiled outside its glBegin (invalidate_saved_current_state),
    // and inside the list's glBegin falls back to replaying the list through immediate mode.
    if (c->list_state().open) c->list_fallback();
    c->end_list_node();
    rec->record<CallListRecorded>(l);
    rec->calls.push_back(l);
    c->list_state().outside_attributes = 0, c->list_state().shade_model = 0;
    if (!c->list_executes()) return;
    c->run_held_back();
    c->fallen_back_run();  // inside the list's glBegin: Mesa's executing side is left inside it
  }
  if (l == 0) return c->record_error(GL_INVALID_VALUE);
  c->CallList(l);
}
void APIENTRY CallLists(GLsizei n, GLenum t, const GLvoid* l) { FWD(CallLists(n, t, l)); }
void APIENTRY DeleteLists(GLuint l, GLsizei r) { FWD(DeleteLists(l, r)); }
void APIENTRY EndList() { FWD(EndList()); }
GLuint APIENTRY GenLists(GLsizei r) { return C() ? C()->GenLists(r) : 0; }
GLboolean APIENTRY IsList(GLuint l) { return C() ? C()->IsList(l) : GL_FALSE; }
void APIENTRY ListBase(GLuint b) { LISTABLE(ListBase, b); FWD(ListBase(b)); }
void APIENTRY NewList(GLuint l, GLenum m) { FWD(NewList(l, m)); }
// Selection (selection.cpp): the name stack compiles into lists, glSelectBuffer does not.
void APIENTRY InitNames() { LISTABLE(InitNames); FWD(InitNames()); }
void APIENTRY LoadName(GLuint n) { LISTABLE(LoadName, n); FWD(LoadName(n)); }
void APIENTRY PassThrough(GLfloat t) { LISTABLE(PassThrough, t); FWD(PassThrough(t)); }
void APIENTRY PopName() { LISTABLE(PopName); FWD(PopName()); }
void APIENTRY PushName(GLuint n) { LISTABLE(PushName, n); FWD(PushName(n)); }
void APIENTRY SelectBuffer(GLsizei s, GLuint* b) { FWD(SelectBuffer(s, b)); }
#undef FWD

}  // namespace ffc::state::entry

namespace ffc::state {
namespace {
template <typename F>
void* address(F* f) {
  return reinterpret_cast<void*>(f);
}
}  // namespace

void* proc_address(const char* name) {
  using namespace entry;
#define FFC_GL_FUNCTION(ret, fn, params) \
  if (std::strcmp(name, "gl" #fn) == 0) return address(fn);
#include "gl/gl_functions.inc"
#undef FFC_GL_FUNCTION
  // Entry points outside the dispatch's list, for callers that load them by name.
  if (std::strcmp(name, "glLightiv") == 0) return reinterpret_cast<void*>(&Lightiv);
  if (std::strcmp(name, "glLightModeliv") == 0) return reinterpret_cast<void*>(&LightModeliv);
  if (std::strcmp(name, "glMaterialiv") == 0) return reinterpret_cast<void*>(&Materialiv);
  return nullptr;
}

}  // namespace ffc::state
