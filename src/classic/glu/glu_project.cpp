// gluPerspective, gluLookAt, gluOrtho2D, gluPickMatrix, gluProject, gluUnProject, gluUnProject4:
// the same arithmetic as SGI's GLU (Mesa libGLU 9.0.2), operation for operation, so that the
// matrices a program builds are bit for bit those it gets with the system library. Column-major
// 4x4 matrices throughout, as OpenGL stores them.
#include "glu_export.h"

#include <cmath>

namespace {

constexpr double kPi = 3.14159265358979323846;

// out = m * v for a column-major m.
void transform(const GLdouble m[16], const double v[4], double out[4]) {
  for (int row = 0; row < 4; ++row)
    out[row] = v[0] * m[row] + v[1] * m[4 + row] + v[2] * m[8 + row] + v[3] * m[12 + row];
}

// r = a * b in GLU's own index order (row i of r takes a's row-major row i): with column-major
// storage this is the product projection * modelview that unprojection inverts.
void multiply(const GLdouble a[16], const GLdouble b[16], double r[16]) {
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j)
      r[i * 4 + j] =
          a[i * 4 + 0] * b[j] + a[i * 4 + 1] * b[4 + j] + a[i * 4 + 2] * b[8 + j] + a[i * 4 + 3] * b[12 + j];
}

// The inverse through cofactors (the adjugate over the determinant), each cofactor summed in the
// same term order as GLU so that rounding matches. False when the matrix is singular.
bool invert(const double m[16], double out[16]) {
  double c[16];
  c[0] = m[5] * m[10] * m[15] - m[5] * m[11] * m[14] - m[9] * m[6] * m[15] + m[9] * m[7] * m[14] +
         m[13] * m[6] * m[11] - m[13] * m[7] * m[10];
  c[4] = -m[4] * m[10] * m[15] + m[4] * m[11] * m[14] + m[8] * m[6] * m[15] - m[8] * m[7] * m[14] -
         m[12] * m[6] * m[11] + m[12] * m[7] * m[10];
  c[8] = m[4] * m[9] * m[15] - m[4] * m[11] * m[13] - m[8] * m[5] * m[15] + m[8] * m[7] * m[13] +
         m[12] * m[5] * m[11] - m[12] * m[7] * m[9];
  c[12] = -m[4] * m[9] * m[14] + m[4] * m[10] * m[13] + m[8] * m[5] * m[14] - m[8] * m[6] * m[13] -
          m[12] * m[5] * m[10] + m[12] * m[6] * m[9];
  c[1] = -m[1] * m[10] * m[15] + m[1] * m[11] * m[14] + m[9] * m[2] * m[15] - m[9] * m[3] * m[14] -
         m[13] * m[2] * m[11] + m[13] * m[3] * m[10];
  c[5] = m[0] * m[10] * m[15] - m[0] * m[11] * m[14] - m[8] * m[2] * m[15] + m[8] * m[3] * m[14] +
         m[12] * m[2] * m[11] - m[12] * m[3] * m[10];
  c[9] = -m[0] * m[9] * m[15] + m[0] * m[11] * m[13] + m[8] * m[1] * m[15] - m[8] * m[3] * m[13] -
         m[12] * m[1] * m[11] + m[12] * m[3] * m[9];
  c[13] = m[0] * m[9] * m[14] - m[0] * m[10] * m[13] - m[8] * m[1] * m[14] + m[8] * m[2] * m[13] +
          m[12] * m[1] * m[10] - m[12] * m[2] * m[9];
  c[2] = m[1] * m[6] * m[15] - m[1] * m[7] * m[14] - m[5] * m[2] * m[15] + m[5] * m[3] * m[14] +
         m[13] * m[2] * m[7] - m[13] * m[3] * m[6];
  c[6] = -m[0] * m[6] * m[15] + m[0] * m[7] * m[14] + m[4] * m[2] * m[15] - m[4] * m[3] * m[14] -
         m[12] * m[2] * m[7] + m[12] * m[3] * m[6];
  c[10] = m[0] * m[5] * m[15] - m[0] * m[7] * m[13] - m[4] * m[1] * m[15] + m[4] * m[3] * m[13] +
          m[12] * m[1] * m[7] - m[12] * m[3] * m[5];
  c[14] = -m[0] * m[5] * m[14] + m[0] * m[6] * m[13] + m[4] * m[1] * m[14] - m[4] * m[2] * m[13] -
          m[12] * m[1] * m[6] + m[12] * m[2] * m[5];
  c[3] = -m[1] * m[6] * m[11] + m[1] * m[7] * m[10] + m[5] * m[2] * m[11] - m[5] * m[3] * m[10] -
         m[9] * m[2] * m[7] + m[9] * m[3] * m[6];
  c[7] = m[0] * m[6] * m[11] - m[0] * m[7] * m[10] - m[4] * m[2] * m[11] + m[4] * m[3] * m[10] +
         m[8] * m[2] * m[7] - m[8] * m[3] * m[6];
  c[11] = -m[0] * m[5] * m[11] + m[0] * m[7] * m[9] + m[4] * m[1] * m[11] - m[4] * m[3] * m[9] -
          m[8] * m[1] * m[7] + m[8] * m[3] * m[5];
  c[15] = m[0] * m[5] * m[10] - m[0] * m[6] * m[9] - m[4] * m[1] * m[10] + m[4] * m[2] * m[9] +
          m[8] * m[1] * m[6] - m[8] * m[2] * m[5];
  double det = m[0] * c[0] + m[1] * c[4] + m[2] * c[8] + m[3] * c[12];
  if (det == 0) return false;
  det = 1.0 / det;
  for (int i = 0; i < 16; ++i) out[i] = c[i] * det;
  return true;
}

// GLU normalizes in single precision, with the square root taken in double.
void normalize(float v[3]) {
  float length = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
  if (length == 0.0) return;
  v[0] /= length;
  v[1] /= length;
  v[2] /= length;
}

void cross(const float a[3], const float b[3], float out[3]) {
  out[0] = a[1] * b[2] - a[2] * b[1];
  out[1] = a[2] * b[0] - a[0] * b[2];
  out[2] = a[0] * b[1] - a[1] * b[0];
}

// Shared by gluUnProject and gluUnProject4: window coordinates back through the inverse of
// projection * modelview. False when that product is singular or w comes out 0.
bool unproject(const double window[4], const GLdouble model[16], const GLdouble proj[16],
               double out[4]) {
  double combined[16];
  multiply(model, proj, combined);
  if (!invert(combined, combined)) return false;
  transform(combined, window, out);
  return out[3] != 0.0;
}

}  // namespace

FFC_GLU_EXPORT void GLAPIENTRY gluOrtho2D(GLdouble left, GLdouble right, GLdouble bottom, GLdouble top) {
  glOrtho(left, right, bottom, top, -1, 1);
}

FFC_GLU_EXPORT void GLAPIENTRY gluPerspective(GLdouble fovy, GLdouble aspect, GLdouble zNear, GLdouble zFar) {
  const double half_angle = fovy / 2 * kPi / 180;
  const double depth = zFar - zNear;
  const double sine = std::sin(half_angle);
  // A degenerate frustum leaves the matrix alone, as GLU does (no GL error either).
  if (depth == 0 || sine == 0 || aspect == 0) return;
  const double cotangent = std::cos(half_angle) / sine;
  GLdouble m[16] = {0};
  m[0] = cotangent / aspect;
  m[5] = cotangent;
  m[10] = -(zFar + zNear) / depth;
  m[11] = -1;
  m[14] = -2 * zNear * zFar / depth;
  glMultMatrixd(m);
}

FFC_GLU_EXPORT void GLAPIENTRY gluLookAt(GLdouble eyeX, GLdouble eyeY, GLdouble eyeZ, GLdouble centerX,
                                         GLdouble centerY, GLdouble centerZ, GLdouble upX, GLdouble upY,
                                         GLdouble upZ) {
  // GLU builds the view basis in single precision: the floats below are part of its output.
  float forward[3] = {float(centerX - eyeX), float(centerY - eyeY), float(centerZ - eyeZ)};
  float up[3] = {float(upX), float(upY), float(upZ)};
  float side[3];
  normalize(forward);
  cross(forward, up, side);
  normalize(side);
  cross(side, forward, up);  // the true up, orthogonal to both
  GLfloat m[16] = {side[0], up[0], -forward[0], 0, side[1], up[1], -forward[1], 0,
                   side[2], up[2], -forward[2], 0, 0,       0,     0,           1};
  glMultMatrixf(m);
  glTranslated(-eyeX, -eyeY, -eyeZ);
}

FFC_GLU_EXPORT void GLAPIENTRY gluPickMatrix(GLdouble x, GLdouble y, GLdouble delX, GLdouble delY, GLint *viewport) {
  if (delX <= 0 || delY <= 0 || viewport == nullptr) return;
  // Maps the pick region onto the whole clip volume: a translation, then a scale (floats, as GLU).
  glTranslatef((viewport[2] - 2 * (x - viewport[0])) / delX, (viewport[3] - 2 * (y - viewport[1])) / delY, 0);
  glScalef(viewport[2] / delX, viewport[3] / delY, 1.0);
}

FFC_GLU_EXPORT GLint GLAPIENTRY gluProject(GLdouble objX, GLdouble objY, GLdouble objZ, const GLdouble *model,
                                           const GLdouble *proj, const GLint *view, GLdouble *winX,
                                           GLdouble *winY, GLdouble *winZ) {
  // Missing arrays make the call fail as a singular matrix would (GLU itself would crash).
  if (model == nullptr || proj == nullptr || view == nullptr || winX == nullptr || winY == nullptr || winZ == nullptr)
    return GL_FALSE;
  const double object[4] = {objX, objY, objZ, 1.0};
  double eye[4], clip[4];
  transform(model, object, eye);
  transform(proj, eye, clip);
  if (clip[3] == 0.0) return GL_FALSE;
  double ndc[3] = {clip[0] / clip[3], clip[1] / clip[3], clip[2] / clip[3]};
  for (double &c : ndc) c = c * 0.5 + 0.5;  // to [0, 1]
  *winX = ndc[0] * view[2] + view[0];
  *winY = ndc[1] * view[3] + view[1];
  *winZ = ndc[2];
  return GL_TRUE;
}

FFC_GLU_EXPORT GLint GLAPIENTRY gluUnProject(GLdouble winX, GLdouble winY, GLdouble winZ, const GLdouble *model,
                                             const GLdouble *proj, const GLint *view, GLdouble *objX,
                                             GLdouble *objY, GLdouble *objZ) {
  if (model == nullptr || proj == nullptr || view == nullptr || objX == nullptr || objY == nullptr || objZ == nullptr)
    return GL_FALSE;
  double window[4] = {(winX - view[0]) / view[2], (winY - view[1]) / view[3], winZ, 1.0};
  for (int i = 0; i < 3; ++i) window[i] = window[i] * 2 - 1;  // to [-1, 1]
  double out[4];
  if (!unproject(window, model, proj, out)) return GL_FALSE;
  *objX = out[0] / out[3];
  *objY = out[1] / out[3];
  *objZ = out[2] / out[3];
  return GL_TRUE;
}

FFC_GLU_EXPORT GLint GLAPIENTRY gluUnProject4(GLdouble winX, GLdouble winY, GLdouble winZ, GLdouble clipW,
                                              const GLdouble *model, const GLdouble *proj, const GLint *view,
                                              GLdouble nearVal, GLdouble farVal, GLdouble *objX,
                                              GLdouble *objY, GLdouble *objZ, GLdouble *objW) {
  if (model == nullptr || proj == nullptr || view == nullptr || objX == nullptr || objY == nullptr ||
      objZ == nullptr || objW == nullptr)
    return GL_FALSE;
  double window[4] = {(winX - view[0]) / view[2], (winY - view[1]) / view[3],
                      (winZ - nearVal) / (farVal - nearVal), clipW};
  for (int i = 0; i < 3; ++i) window[i] = window[i] * 2 - 1;
  double out[4];
  if (!unproject(window, model, proj, out)) return GL_FALSE;
  // Homogeneous: GLU leaves the division by w to the caller here.
  *objX = out[0];
  *objY = out[1];
  *objZ = out[2];
  *objW = out[3];
  return GL_TRUE;
}
