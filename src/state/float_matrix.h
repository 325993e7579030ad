// Matrix arithmetic in float, in the order Mesa's math/m_matrix.c does it. Our float path keeps
// these beside the double matrices so that its window positions round exactly as llvmpipe's: a
// vertex a 1/10000 pixel from an edge then lands on the same side, and coverage matches.
#pragma once
#include <xmmintrin.h>

#include <cmath>
#include <glm/glm.hpp>

namespace ffc::state::fmat {

// product = a * b, summed as Mesa's matmul4: ((a0 b0 + a1 b1) + a2 b2) + a3 b3.
inline glm::mat4 mul(const glm::mat4& a, const glm::mat4& b) {
  glm::mat4 p;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j)
      p[j][i] = a[0][i] * b[j][0] + a[1][i] * b[j][1] + a[2][i] * b[j][2] + a[3][i] * b[j][3];
  return p;
}

// m * v, summed left to right as the fixed-function vertex program's dot products.
// The four rows at once in SSE, each summed in the same order.
inline glm::vec4 transform(const glm::mat4& m, const glm::vec4& v) {
  const __m128 r = _mm_add_ps(_mm_add_ps(_mm_add_ps(_mm_mul_ps(_mm_loadu_ps(&m[0][0]), _mm_set1_ps(v.x)),
                                                    _mm_mul_ps(_mm_loadu_ps(&m[1][0]), _mm_set1_ps(v.y))),
                                         _mm_mul_ps(_mm_loadu_ps(&m[2][0]), _mm_set1_ps(v.z))),
                              _mm_mul_ps(_mm_loadu_ps(&m[3][0]), _mm_set1_ps(v.w)));
  glm::vec4 out;
  _mm_storeu_ps(&out[0], r);
  return out;
}

// glRotatef: axis-aligned rotations are built directly, others from the normalized axis; an axis
// shorter than 1e-4 leaves the matrix unchanged (returns identity).
inline glm::mat4 rotation(float angle, float x, float y, float z) {
  const float s = std::sin(float(angle * M_PI / 180.0)), c = std::cos(float(angle * M_PI / 180.0));
  glm::mat4 m(1.0f);
  auto M = [&](int r, int col) -> float& { return m[col][r]; };
  if (x == 0 && y == 0 && z != 0) {
    M(0, 0) = c, M(1, 1) = c;
    if (z < 0) M(0, 1) = s, M(1, 0) = -s;
    else M(0, 1) = -s, M(1, 0) = s;
    return m;
  }
  if (x == 0 && z == 0 && y != 0) {
    M(0, 0) = c, M(2, 2) = c;
    if (y < 0) M(0, 2) = -s, M(2, 0) = s;
    else M(0, 2) = s, M(2, 0) = -s;
    return m;
  }
  if (y == 0 && z == 0 && x != 0) {
    M(1, 1) = c, M(2, 2) = c;
    if (x < 0) M(1, 2) = s, M(2, 1) = -s;
    else M(1, 2) = -s, M(2, 1) = s;
    return m;
  }
  const float mag = std::sqrt(x * x + y * y + z * z);
  if (mag <= 1.0e-4f) return m;
  x /= mag, y /= mag, z /= mag;
  const float xx = x * x, yy = y * y, zz = z * z, xy = x * y, yz = y * z, zx = z * x;
  const float xs = x * s, ys = y * s, zs = z * s, one_c = 1.0f - c;
  M(0, 0) = (one_c * xx) + c, M(0, 1) = (one_c * xy) - zs, M(0, 2) = (one_c * zx) + ys;
  M(1, 0) = (one_c * xy) + zs, M(1, 1) = (one_c * yy) + c, M(1, 2) = (one_c * yz) - xs;
  M(2, 0) = (one_c * zx) - ys, M(2, 1) = (one_c * yz) + xs, M(2, 2) = (one_c * zz) + c;
  return m;
}

// glTranslatef applied in place: the last column becomes m * (x, y, z, 1).
inline void translate(glm::mat4& m, float x, float y, float z) {
  for (int i = 0; i < 4; ++i) m[3][i] = m[0][i] * x + m[1][i] * y + m[2][i] * z + m[3][i];
}

inline void scale(glm::mat4& m, float x, float y, float z) {
  for (int i = 0; i < 4; ++i) m[0][i] *= x, m[1][i] *= y, m[2][i] *= z;
}

inline glm::mat4 ortho(float l, float r, float b, float t, float n, float f) {
  glm::mat4 m(1.0f);
  m[0][0] = 2.0f / (r - l), m[3][0] = -(r + l) / (r - l);
  m[1][1] = 2.0f / (t - b), m[3][1] = -(t + b) / (t - b);
  m[2][2] = -2.0f / (f - n), m[3][2] = -(f + n) / (f - n);
  return m;
}

inline glm::mat4 frustum(float l, float r, float b, float t, float n, float f) {
  glm::mat4 m(0.0f);
  m[0][0] = (2.0f * n) / (r - l), m[2][0] = (r + l) / (r - l);
  m[1][1] = (2.0f * n) / (t - b), m[2][1] = (t + b) / (t - b);
  m[2][2] = -(f + n) / (f - n), m[3][2] = -(2.0f * f * n) / (f - n);
  m[2][3] = -1.0f;
  return m;
}

}  // namespace ffc::state::fmat
