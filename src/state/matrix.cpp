// The matrix stacks and the viewport transformation (GL 2.1 sections 2.11 and 2.12; Mesa's
// matrix.c and viewport.c): every stack is kept in double and, computed as Mesa computes it, in
// float (float_matrix.h); the context's precision says which one draws.
#include <algorithm>
#include <cmath>
#include <cstring>
#include <glm/gtc/matrix_transform.hpp>

#include "state/context.h"
#include "state/gl_rules.h"

namespace ffc::state {

glm::dmat4 Context::projection() const {
  return precision_ == Precision::Float ? glm::dmat4(projection_f_.back().values()) : projection_.back();
}
glm::dmat4 Context::texture() const {
  return precision_ == Precision::Float ? glm::dmat4(texture_f_.back().values()) : texture_.back();
}

glm::dmat4 Context::modelview() const {
  return precision_ == Precision::Float ? glm::dmat4(modelview_f_.back().values()) : modelview_.back();
}
std::vector<glm::dmat4>& Context::stack() {
  return matrix_mode_ == GL_PROJECTION ? projection_ : matrix_mode_ == GL_TEXTURE ? texture_ : modelview_;
}
std::vector<fmat::Matrix>& Context::stack_f() {
  return matrix_mode_ == GL_PROJECTION ? projection_f_ : matrix_mode_ == GL_TEXTURE ? texture_f_ : modelview_f_;
}

void Context::MatrixMode(GLenum mode) {
  if (!outside_begin_end_keeping_vertices()) return;
  // GL_TEXTURE has its stack (nothing here reads it: there is no texturing).
  if (mode != GL_MODELVIEW && mode != GL_PROJECTION && mode != GL_TEXTURE) return error(GL_INVALID_ENUM);
  matrix_mode_ = mode;
}

void Context::LoadIdentity() {
  if (!outside_begin_end()) return;
  stack().back() = glm::dmat4(1);
  stack_f().back().load_identity();
}

// Mesa's glLoadMatrix compares the floats with the top's, bit for bit, and flushes stored vertices
// only when they differ.
void Context::LoadMatrix(const glm::dmat4& m) {
  if (!outside_begin_end_keeping_vertices()) return;
  const glm::mat4 f(m);
  changes(std::memcmp(&f, &stack_f().back().values(), sizeof f) != 0);
  stack().back() = m;
  stack_f().back().load(glm::mat4(m));
}

// Mesa's glMultMatrix returns first for a matrix whose floats are the identity's, bit for bit
// (-0 is not 0): no flush of stored vertices, no multiply (measured: SetterFlush, Unchanged13).
void Context::MultMatrix(const glm::dmat4& m) {
  if (!outside_begin_end_keeping_vertices()) return;
  const glm::mat4 f(m), identity(1);
  if (std::memcmp(&f, &identity, sizeof f) == 0) return;
  flush_vertices();
  stack().back() = stack().back() * m;
  stack_f().back().multiply(glm::mat4(m));
}

void Context::validate_matrices() {
  early_join();  // immediate mode's early job reads them (a call inside glBegin/glEnd gets here before its error)
  modelview_f_.back().analyse();
  texture_f_.back().analyse();
  // Mesa's _ModelProjectMatrix, with the flags of both (three rows when both are affine).
  mvp_f_ = fmat::Matrix::product(projection_f_.back(), modelview_f_.back()).values();
}

void Context::PushMatrix() {
  if (!outside_begin_end_keeping_vertices()) return;
  auto& s = stack();
  if (s.size() >= (matrix_mode_ == GL_TEXTURE ? kMaxTextureStackDepth : kMaxStackDepth))
    return error(GL_STACK_OVERFLOW);
  s.push_back(s.back());
  auto& f = stack_f();
  f.back().analyse();  // Mesa makes the pushed matrix current first (_math_matrix_push_copy)
  f.push_back(f.back());
}

// Mesa 22.3 flushes (FLUSH_VERTICES) only where the matrix popped differs from the current one: an
// underflow or a pop to an equal matrix leaves the values a vertex list copied to its immediate-mode
// vbo unflushed, so a GL_COMPILE_AND_EXECUTE list's wrapped glBegin after it shows the current values
// from before them. Measured (seed 161803 stream 2503, repro list_pop_matrix_no_flush.txt): a
// GL_TRIANGLES with glNormal3f(.5, 0, 0), glPopMatrix, then a GL_TRIANGLES wrapped by its glNormal
// reads (0, 0, 1) there after an underflow or an equal matrix, (.5, 0, 0) after a different one.
void Context::PopMatrix() {
  if (in_begin_) return error(GL_INVALID_OPERATION);
  auto& s = stack();
  if (s.size() <= 1) return error(GL_STACK_UNDERFLOW);
  auto& f = stack_f();
  if (std::memcmp(&f[f.size() - 2].values(), &f.back().values(), sizeof(glm::mat4)) != 0) flush_vertices();
  s.pop_back();
  f.pop_back();
}

// Each transform updates the double matrix exactly and the float one as Mesa's float maths does.
void Context::Rotate(double angle, double x, double y, double z) {
  if (!outside_begin_end()) return;
  // An axis shorter than 1e-4 leaves the matrix unchanged, in double as in float (Mesa's
  // m_matrix.c rule, which GL 2.1 leaves open: the rotation of a zero axis is undefined).
  const double len = std::sqrt(x * x + y * y + z * z);
  if (len > 1e-4) stack().back() *= glm::rotate(glm::dmat4(1), glm::radians(angle), glm::dvec3(x, y, z) / len);
  stack_f().back().rotate(float(angle), float(x), float(y), float(z));
}

void Context::Scale(double x, double y, double z) {
  if (!outside_begin_end()) return;
  stack().back() *= glm::scale(glm::dmat4(1), glm::dvec3(x, y, z));
  stack_f().back().scale(float(x), float(y), float(z));
}

void Context::Translate(double x, double y, double z) {
  if (!outside_begin_end()) return;
  stack().back() *= glm::translate(glm::dmat4(1), glm::dvec3(x, y, z));
  stack_f().back().translate(float(x), float(y), float(z));
}

void Context::Ortho(double l, double r, double b, double t, double n, double f) {
  if (!outside_begin_end()) return;
  // Mesa checks the arguments once converted to float (so 1 and 1 + 1e-10 are equal there).
  const float fl = float(l), fr = float(r), fb = float(b), ft = float(t), fn = float(n), ff = float(f);
  if (fl == fr || fb == ft || fn == ff) return error(GL_INVALID_VALUE);
  stack().back() *= glm::orthoRH_NO(l, r, b, t, n, f);
  stack_f().back().ortho(fl, fr, fb, ft, fn, ff);
}

void Context::Frustum(double l, double r, double b, double t, double n, double f) {
  if (!outside_begin_end()) return;
  const float fl = float(l), fr = float(r), fb = float(b), ft = float(t), fn = float(n), ff = float(f);
  if (fn <= 0 || ff <= 0 || fl == fr || fb == ft || fn == ff) return error(GL_INVALID_VALUE);
  stack().back() *= glm::frustumRH_NO(l, r, b, t, n, f);
  stack_f().back().frustum(fl, fr, fb, ft, fn, ff);
}

// glViewport and glDepthRange flush stored vertices only on a change (Mesa's viewport.c compares
// the clamped viewport, and the depth range as given with the clamped one it keeps).
void Context::Viewport(GLint x, GLint y, GLsizei w, GLsizei h) {
  if (!outside_begin_end_keeping_vertices()) return;
  if (w < 0 || h < 0) return error(GL_INVALID_VALUE);
  // Mesa clamps the size to GL_MAX_VIEWPORT_DIMS and the origin to its viewport bounds range
  // [-2 max, 2 max - 1] (viewport.c; GL 2.1 says only the size is clamped). Ours does the same:
  // window coordinates then stay far from the int range.
  x = std::clamp(x, -2 * kMaxViewport, 2 * kMaxViewport - 1), y = std::clamp(y, -2 * kMaxViewport, 2 * kMaxViewport - 1);
  assign(viewport_, decltype(viewport_){x, y, std::min(w, kMaxViewport), std::min(h, kMaxViewport)});
}

void Context::DepthRange(double n, double f) {
  if (!outside_begin_end_keeping_vertices()) return;
  if (changes(!(depth_range_[0] == n && depth_range_[1] == f))) depth_range_ = {clamp01(n), clamp01(f)};
}
}  // namespace ffc::state
