// Matrix arithmetic in float, in the order Mesa's math/m_matrix.c does it. Our float path keeps
// these beside the double matrices so that its window positions round exactly as llvmpipe's: a
// vertex a 1/10000 pixel from an edge then lands on the same side, and coverage matches.
#pragma once
#include "raster/isa.h"
#if FFCOMPAT_X86
#include <xmmintrin.h>
#endif

#include <cmath>
#include <cstring>
#include <utility>
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
// On x86 the four rows at once in SSE, each summed in the same order.
inline glm::vec4 transform(const glm::mat4& m, const glm::vec4& v) {
#if FFCOMPAT_X86
  const __m128 r = _mm_add_ps(_mm_add_ps(_mm_add_ps(_mm_mul_ps(_mm_loadu_ps(&m[0][0]), _mm_set1_ps(v.x)),
                                                    _mm_mul_ps(_mm_loadu_ps(&m[1][0]), _mm_set1_ps(v.y))),
                                         _mm_mul_ps(_mm_loadu_ps(&m[2][0]), _mm_set1_ps(v.z))),
                              _mm_mul_ps(_mm_loadu_ps(&m[3][0]), _mm_set1_ps(v.w)));
  glm::vec4 out;
  _mm_storeu_ps(&out[0], r);
  return out;
#else
  glm::vec4 out;
  for (int r = 0; r < 4; ++r) out[r] = ((m[0][r] * v.x + m[1][r] * v.y) + m[2][r] * v.z) + m[3][r] * v.w;
  return out;
#endif
}

// glRotatef's matrix: axis-aligned rotations are built directly, others from the normalized axis.
// An axis no longer than 1e-4 builds nothing (false): the matrix stays as it is, flags included.
inline bool rotation(glm::mat4& m, float angle, float x, float y, float z) {
  const float s = std::sin(float(angle * M_PI / 180.0)), c = std::cos(float(angle * M_PI / 180.0));
  m = glm::mat4(1.0f);
  auto M = [&](int r, int col) -> float& { return m[col][r]; };
  if (x == 0 && y == 0 && z != 0) {
    M(0, 0) = c, M(1, 1) = c;
    if (z < 0) M(0, 1) = s, M(1, 0) = -s;
    else M(0, 1) = -s, M(1, 0) = s;
    return true;
  }
  if (x == 0 && z == 0 && y != 0) {
    M(0, 0) = c, M(2, 2) = c;
    if (y < 0) M(0, 2) = -s, M(2, 0) = s;
    else M(0, 2) = s, M(2, 0) = -s;
    return true;
  }
  if (y == 0 && z == 0 && x != 0) {
    M(1, 1) = c, M(2, 2) = c;
    if (x < 0) M(1, 2) = s, M(2, 1) = -s;
    else M(1, 2) = -s, M(2, 1) = s;
    return true;
  }
  const float mag = std::sqrt(x * x + y * y + z * z);
  if (mag <= 1.0e-4f) return false;
  x /= mag, y /= mag, z /= mag;
  const float xx = x * x, yy = y * y, zz = z * z, xy = x * y, yz = y * z, zx = z * x;
  const float xs = x * s, ys = y * s, zs = z * s, one_c = 1.0f - c;
  M(0, 0) = (one_c * xx) + c, M(0, 1) = (one_c * xy) - zs, M(0, 2) = (one_c * zx) + ys;
  M(1, 0) = (one_c * xy) + zs, M(1, 1) = (one_c * yy) + c, M(1, 2) = (one_c * yz) - xs;
  M(2, 0) = (one_c * zx) - ys, M(2, 1) = (one_c * yz) + xs, M(2, 2) = (one_c * zz) + c;
  return true;
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

// ---------------------------------------------------------------- Mesa's GLmatrix
//
// A matrix as Mesa's math/m_matrix.c keeps it: the values, what is known of them (flags, gathered
// as each glRotate/glScale/... tells, or found by looking at the values after glLoadMatrix and
// glMultMatrix), a type decided from them, and an inverse by the type. What is known decides how
// a product is computed: when neither side can hold a projective bottom row, only the top three
// rows are computed and the bottom one is written as 0 0 0 1. So an infinity never reaches the
// bottom row as 0 * inf = NaN, and a NaN already there stays put until a 4x4 product.
// The flags are brought up to date ("analysed") only where Mesa does: at glPushMatrix, at
// glLight(GL_SPOT_DIRECTION), and when its state is validated (draws, glRasterPos, glReadPixels,
// glDrawPixels: Context::validate_matrices).

enum Flag : unsigned {
  kGeneral = 0x1,
  kRotation = 0x2,
  kTranslation = 0x4,
  kUniformScale = 0x8,
  kGeneralScale = 0x10,
  kGeneral3D = 0x20,
  kPerspective = 0x40,
  kSingular = 0x80,
  kDirtyType = 0x100,
  kDirtyFlags = 0x200,
  kDirtyInverse = 0x400,
};
constexpr unsigned kGeometry = 0xff;
constexpr unsigned kDirty = kDirtyType | kDirtyFlags | kDirtyInverse;
constexpr unsigned kAffine = kRotation | kTranslation | kUniformScale | kGeneralScale | kGeneral3D;
constexpr unsigned kAnglePreserving = kRotation | kTranslation | kUniformScale;
constexpr unsigned kLengthPreserving = kRotation | kTranslation;

// The matrix kinds, in the order of Mesa's enum (its inverse table is indexed by it).
enum class Type { General, Identity, NoRot3D, Perspective, Plane, NoRotPlane, Affine };

// True when every geometry flag set is among those of mask.
inline bool flags_within(unsigned flags, unsigned mask) { return (flags & kGeometry & ~mask) == 0; }

// product = a * b over all four rows, each sum left to right (matmul4).
inline void mul4(glm::mat4& p, const glm::mat4& a, const glm::mat4& b) {
  glm::mat4 r;
  for (int i = 0; i < 4; ++i) {
    const float a0 = a[0][i], a1 = a[1][i], a2 = a[2][i], a3 = a[3][i];
    for (int j = 0; j < 4; ++j) r[j][i] = a0 * b[j][0] + a1 * b[j][1] + a2 * b[j][2] + a3 * b[j][3];
  }
  p = r;
}

// product = a * b for two matrices whose bottom rows are taken to be 0 0 0 1 (matmul34).
inline void mul34(glm::mat4& p, const glm::mat4& a, const glm::mat4& b) {
  glm::mat4 r;
  for (int i = 0; i < 3; ++i) {
    const float a0 = a[0][i], a1 = a[1][i], a2 = a[2][i], a3 = a[3][i];
    for (int j = 0; j < 3; ++j) r[j][i] = a0 * b[j][0] + a1 * b[j][1] + a2 * b[j][2];
    r[3][i] = a0 * b[3][0] + a1 * b[3][1] + a2 * b[3][2] + a3;
  }
  r[0][3] = 0, r[1][3] = 0, r[2][3] = 0, r[3][3] = 1;
  p = r;
}

// A general 4x4 inverse by Gauss-Jordan elimination with partial pivoting, in float, the steps
// as Mesa's util_invert_mat4x4 takes them (an exact zero pivot: singular).
inline bool invert_general(glm::mat4& out, const glm::mat4& m) {
  float rows[4][8];
  for (int r = 0; r < 4; ++r) {
    for (int c = 0; c < 4; ++c) rows[r][c] = m[c][r];
    for (int c = 4; c < 8; ++c) rows[r][c] = c - 4 == r ? 1.0f : 0.0f;
  }
  float* r0 = rows[0];
  float* r1 = rows[1];
  float* r2 = rows[2];
  float* r3 = rows[3];
  // Column by column: the largest remaining entry moves up (only when strictly larger), then is
  // eliminated below; the right half is touched only where the pivot row holds a non-zero.
  if (std::fabs(r3[0]) > std::fabs(r2[0])) std::swap(r3, r2);
  if (std::fabs(r2[0]) > std::fabs(r1[0])) std::swap(r2, r1);
  if (std::fabs(r1[0]) > std::fabs(r0[0])) std::swap(r1, r0);
  if (r0[0] == 0.0f) return false;
  {
    const float m1 = r1[0] / r0[0], m2 = r2[0] / r0[0], m3 = r3[0] / r0[0];
    for (int c = 1; c < 4; ++c) {
      const float s = r0[c];
      r1[c] -= m1 * s, r2[c] -= m2 * s, r3[c] -= m3 * s;
    }
    for (int c = 4; c < 8; ++c) {
      const float s = r0[c];
      if (s != 0.0f) r1[c] -= m1 * s, r2[c] -= m2 * s, r3[c] -= m3 * s;
    }
  }
  if (std::fabs(r3[1]) > std::fabs(r2[1])) std::swap(r3, r2);
  if (std::fabs(r2[1]) > std::fabs(r1[1])) std::swap(r2, r1);
  if (r1[1] == 0.0f) return false;
  {
    const float m2 = r2[1] / r1[1], m3 = r3[1] / r1[1];
    for (int c = 2; c < 4; ++c) r2[c] -= m2 * r1[c], r3[c] -= m3 * r1[c];
    for (int c = 4; c < 8; ++c) {
      const float s = r1[c];
      if (s != 0.0f) r2[c] -= m2 * s, r3[c] -= m3 * s;
    }
  }
  if (std::fabs(r3[2]) > std::fabs(r2[2])) std::swap(r3, r2);
  if (r2[2] == 0.0f) return false;
  {
    const float m3 = r3[2] / r2[2];
    for (int c = 3; c < 8; ++c) r3[c] -= m3 * r2[c];
  }
  if (r3[3] == 0.0f) return false;
  // Back substitution, the last row first.
  float s = 1.0f / r3[3];
  for (int c = 4; c < 8; ++c) r3[c] *= s;
  float k = r2[3];
  s = 1.0f / r2[2];
  for (int c = 4; c < 8; ++c) r2[c] = s * (r2[c] - r3[c] * k);
  k = r1[3];
  for (int c = 4; c < 8; ++c) r1[c] -= r3[c] * k;
  k = r0[3];
  for (int c = 4; c < 8; ++c) r0[c] -= r3[c] * k;
  k = r1[2];
  s = 1.0f / r1[1];
  for (int c = 4; c < 8; ++c) r1[c] = s * (r1[c] - r2[c] * k);
  k = r0[2];
  for (int c = 4; c < 8; ++c) r0[c] -= r2[c] * k;
  k = r0[1];
  s = 1.0f / r0[0];
  for (int c = 4; c < 8; ++c) r0[c] = s * (r0[c] - r1[c] * k);
  const float* done[4] = {r0, r1, r2, r3};
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) out[c][r] = done[r][c + 4];
  return true;
}

class Matrix {
 public:
  const glm::mat4& values() const { return m_; }
  unsigned flags() const { return flags_; }
  Type type() const { return type_; }
  bool dirty() const { return (flags_ & kDirty) != 0; }

  // glLoadMatrix: the same bits as already held change nothing (not even the flags).
  void load(const glm::mat4& v) {
    if (std::memcmp(&v[0][0], &m_[0][0], sizeof(float) * 16) == 0) return;
    m_ = v;
    flags_ = kGeneral | kDirty;
  }
  // glLoadIdentity: values, inverse and type reset; the geometry flags are kept as they were.
  void load_identity() {
    m_ = inv_ = glm::mat4(1.0f);
    type_ = Type::Identity;
    flags_ &= ~kDirty;
  }
  // glMultMatrix: skipped for the exact identity; otherwise always a full product, and the values
  // are to be analysed afresh.
  void multiply(const glm::mat4& b) {
    static const glm::mat4 kIdentity(1.0f);
    if (std::memcmp(&b[0][0], &kIdentity[0][0], sizeof(float) * 16) == 0) return;
    flags_ |= kGeneral | kDirty;
    mul4(m_, m_, b);
  }
  void rotate(float angle, float x, float y, float z) {
    if (angle == 0.0f) return;  // glRotate(0, ...) is no change at all
    glm::mat4 r;
    if (rotation(r, angle, x, y, z)) multiply_known(r, kRotation);
  }
  void scale(float x, float y, float z) {
    for (int i = 0; i < 4; ++i) m_[0][i] *= x, m_[1][i] *= y, m_[2][i] *= z;
    flags_ |= std::fabs(x - y) < 1e-8f && std::fabs(x - z) < 1e-8f ? kUniformScale : kGeneralScale;
    flags_ |= kDirtyType | kDirtyInverse;
  }
  // The last column becomes m * (x, y, z, 1), the bottom row's entry included.
  void translate(float x, float y, float z) {
    for (int i = 0; i < 4; ++i) m_[3][i] = m_[0][i] * x + m_[1][i] * y + m_[2][i] * z + m_[3][i];
    flags_ |= kTranslation | kDirtyType | kDirtyInverse;
  }
  void ortho(float l, float r, float b, float t, float n, float f) {
    multiply_known(fmat::ortho(l, r, b, t, n, f), kGeneralScale | kTranslation);
  }
  void frustum(float l, float r, float b, float t, float n, float f) {
    multiply_known(fmat::frustum(l, r, b, t, n, f), kPerspective);
  }

  // Brings the type, the flags (when the values must be looked at) and the inverse up to date.
  void analyse() {
    if (flags_ & kDirtyType) {
      if (flags_ & kDirtyFlags) analyse_values();
      else analyse_flags();
    }
    if (flags_ & kDirtyInverse) {
      if (invert()) flags_ &= ~kSingular;
      else flags_ |= kSingular, inv_ = glm::mat4(1.0f);
      flags_ &= ~kDirtyInverse;
    }
    flags_ &= ~(kDirtyFlags | kDirtyType);
  }

  // The inverse as Mesa computes it for this matrix's type (the identity where it finds the
  // matrix singular), analysing the matrix first as Mesa's users do. The normal matrix is its
  // upper 3x3, transposed.
  const glm::mat4& inverse() {
    if (dirty()) analyse();
    return inv_;
  }
  // _math_matrix_is_length_preserving: only rotations and translations are known to have been
  // applied (read from the flags as they stand: analyse() first to have them current).
  bool length_preserving() const { return flags_within(flags_, kLengthPreserving); }

  // _math_matrix_mul_matrix: a * b with the flags of both, three rows when both are affine.
  static Matrix product(const Matrix& a, const Matrix& b) {
    Matrix p;
    p.flags_ = a.flags_ | b.flags_ | kDirtyType | kDirtyInverse;
    if (flags_within(p.flags_, kAffine)) mul34(p.m_, a.m_, b.m_);
    else mul4(p.m_, a.m_, b.m_);
    return p;
  }

 private:
  float at(int r, int c) const { return m_[c][r]; }
  static float& at(glm::mat4& m, int r, int c) { return m[c][r]; }

  // matrix_multf: the flags of the right-hand matrix join ours, then the product.
  void multiply_known(const glm::mat4& b, unsigned flags) {
    flags_ |= flags | kDirtyType | kDirtyInverse;
    if (flags_within(flags_, kAffine)) mul34(m_, m_, b);
    else mul4(m_, m_, b);
  }

  // The type from the flags, checking only what the flags cannot tell.
  void analyse_flags() {
    const float* m = &m_[0][0];
    if (flags_within(flags_, 0)) type_ = Type::Identity;
    else if (flags_within(flags_, kTranslation | kUniformScale | kGeneralScale))
      type_ = m[10] == 1.0f && m[14] == 0.0f ? Type::NoRotPlane : Type::NoRot3D;
    else if (flags_within(flags_, kAffine))
      type_ = m[8] == 0.0f && m[9] == 0.0f && m[2] == 0.0f && m[6] == 0.0f && m[10] == 1.0f && m[14] == 0.0f
                  ? Type::Plane
                  : Type::Affine;
    else if (m[4] == 0.0f && m[12] == 0.0f && m[1] == 0.0f && m[13] == 0.0f && m[2] == 0.0f && m[6] == 0.0f &&
             m[3] == 0.0f && m[7] == 0.0f && m[11] == -1.0f && m[15] == 0.0f)
      type_ = Type::Perspective;
    else type_ = Type::General;
  }

  // Flags and type from the values alone: which entries are exactly 0 (bit i) and which diagonal
  // entries exactly 1 (bit 16 + i), then tolerances of 1e-6 on lengths and angles.
  void analyse_values() {
    const float* m = &m_[0][0];
    auto zero = [](int i) { return 1u << i; };
    auto one = [](int i) { return 1u << (i + 16); };
    unsigned mask = 0;
    for (int i = 0; i < 16; ++i)
      if (m[i] == 0.0f) mask |= zero(i);
    for (int i : {0, 5, 10, 15})
      if (m[i] == 1.0f) mask |= one(i);
    const unsigned no_translation = zero(12) | zero(13) | zero(14);
    const unsigned no_2d_scale = one(0) | one(5);
    const unsigned bottom = zero(3) | zero(7) | zero(11) | one(15);
    const unsigned identity =
        one(0) | zero(4) | zero(8) | zero(12) | zero(1) | one(5) | zero(9) | zero(13) | zero(2) | zero(6) | one(10) |
        zero(14) | bottom;
    const unsigned plane = zero(8) | zero(9) | zero(2) | zero(6) | one(10) | zero(14) | bottom;
    const unsigned plane_no_rot = plane | zero(4) | zero(1);
    const unsigned no_rot_3d = zero(4) | zero(8) | zero(1) | zero(9) | zero(2) | zero(6) | bottom;
    const unsigned perspective =
        zero(4) | zero(12) | zero(1) | zero(13) | zero(2) | zero(6) | zero(3) | zero(7) | zero(15);
    const float tol = 1e-6f * 1e-6f;
    auto sq = [](float v) { return v * v; };

    flags_ &= ~kGeometry;
    if ((mask & no_translation) != no_translation) flags_ |= kTranslation;
    if (mask == identity) {
      type_ = Type::Identity;
    } else if ((mask & plane_no_rot) == plane_no_rot) {
      type_ = Type::NoRotPlane;
      if ((mask & no_2d_scale) != no_2d_scale) flags_ |= kGeneralScale;
    } else if ((mask & plane) == plane) {
      const float mm = m[0] * m[0] + m[1] * m[1];
      const float m4m4 = m[4] * m[4] + m[5] * m[5];
      const float mm4 = m[0] * m[4] + m[1] * m[5];
      type_ = Type::Plane;
      if (sq(mm - 1) > tol || sq(m4m4 - 1) > tol) flags_ |= kGeneralScale;
      flags_ |= sq(mm4) > tol ? kGeneral3D : kRotation;
    } else if ((mask & no_rot_3d) == no_rot_3d) {
      type_ = Type::NoRot3D;
      if (sq(m[0] - m[5]) < tol && sq(m[0] - m[10]) < tol) {
        if (sq(m[0] - 1.0f) > tol) flags_ |= kUniformScale;
      } else {
        flags_ |= kGeneralScale;
      }
    } else if ((mask & bottom) == bottom) {
      const float c1 = m[0] * m[0] + m[1] * m[1] + m[2] * m[2];
      const float c2 = m[4] * m[4] + m[5] * m[5] + m[6] * m[6];
      const float c3 = m[8] * m[8] + m[9] * m[9] + m[10] * m[10];
      const float d1 = m[0] * m[4] + m[1] * m[5] + m[2] * m[6];
      type_ = Type::Affine;
      if (sq(c1 - c2) < tol && sq(c1 - c3) < tol) {
        if (sq(c1 - 1.0f) > tol) flags_ |= kUniformScale;
      } else {
        flags_ |= kGeneralScale;
      }
      if (sq(d1) < tol) {
        // Is the third column the cross product of the first two (a rotation, not a mirror)?
        float cp[3] = {m[1] * m[6] - m[2] * m[5], m[2] * m[4] - m[0] * m[6], m[0] * m[5] - m[1] * m[4]};
        cp[0] -= m[8], cp[1] -= m[9], cp[2] -= m[10];
        flags_ |= cp[0] * cp[0] + cp[1] * cp[1] + cp[2] * cp[2] < tol ? kRotation : kGeneral3D;
      } else {
        flags_ |= kGeneral3D;  // shear
      }
    } else if ((mask & perspective) == perspective && m[11] == -1.0f) {
      type_ = Type::Perspective;
      flags_ |= kGeneral;
    } else {
      type_ = Type::General;
      flags_ |= kGeneral;
    }
  }

  // The inverse by type (Mesa's table: the general one for general and perspective matrices, the
  // affine one, lazily, for plane ones). False for a matrix found singular.
  bool invert() {
    switch (type_) {
      case Type::General:
      case Type::Perspective: return invert_general(inv_, m_);
      case Type::Identity: inv_ = glm::mat4(1.0f); return true;
      case Type::NoRot3D: return invert_no_rot(3);
      case Type::NoRotPlane: return invert_no_rot(2);
      case Type::Plane:
      case Type::Affine: return invert_affine();
    }
    return false;
  }

  // Diagonal scales and a translation.
  bool invert_no_rot(int n) {
    for (int i = 0; i < n; ++i)
      if (at(i, i) == 0) return false;
    glm::mat4 out(1.0f);
    for (int i = 0; i < n; ++i) at(out, i, i) = 1.0f / at(i, i);
    if (flags_ & kTranslation)
      for (int i = 0; i < n; ++i) at(out, i, 3) = -(at(i, 3) * at(out, i, i));
    inv_ = out;
    return true;
  }

  // Affine matrices: transposes for rotations (scaled back for a uniform scale), the adjugate
  // over the determinant otherwise; then the translation.
  bool invert_affine() {
    glm::mat4 out = inv_;
    if (!flags_within(flags_, kAnglePreserving)) return invert_affine_general();
    if (flags_ & kUniformScale) {
      float s = at(0, 0) * at(0, 0) + at(0, 1) * at(0, 1) + at(0, 2) * at(0, 2);
      if (s == 0.0f) return false;
      s = 1.0f / s;
      for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) at(out, c, r) = s * at(r, c);
    } else if (flags_ & kRotation) {
      for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) at(out, c, r) = at(r, c);
    } else {  // a translation only
      out = glm::mat4(1.0f);
      for (int r = 0; r < 3; ++r) at(out, r, 3) = -at(r, 3);
      inv_ = out;
      return true;
    }
    if (flags_ & kTranslation) translation_part(out);
    else at(out, 0, 3) = at(out, 1, 3) = at(out, 2, 3) = 0.0f;
    inv_ = out;
    return true;
  }

  // -(upper 3x3 inverse) * translation, each sum left to right.
  void translation_part(glm::mat4& out) const {
    for (int r = 0; r < 3; ++r)
      at(out, r, 3) = -(at(0, 3) * at(out, r, 0) + at(1, 3) * at(out, r, 1) + at(2, 3) * at(out, r, 2));
  }

  bool invert_affine_general() {
    // The determinant of the upper 3x3, its positive and negative terms summed apart.
    float pos = 0.0f, neg = 0.0f;
    auto add = [&](float t) {
      if (t >= 0.0f) pos += t;
      else neg += t;
    };
    add(at(0, 0) * at(1, 1) * at(2, 2));
    add(at(1, 0) * at(2, 1) * at(0, 2));
    add(at(2, 0) * at(0, 1) * at(1, 2));
    add(-at(2, 0) * at(1, 1) * at(0, 2));
    add(-at(1, 0) * at(0, 1) * at(2, 2));
    add(-at(0, 0) * at(2, 1) * at(1, 2));
    float det = pos + neg;
    if (std::fabs(det) < 1e-25f) return false;
    det = 1.0f / det;
    glm::mat4 out = inv_;
    at(out, 0, 0) = (at(1, 1) * at(2, 2) - at(2, 1) * at(1, 2)) * det;
    at(out, 0, 1) = -(at(0, 1) * at(2, 2) - at(2, 1) * at(0, 2)) * det;
    at(out, 0, 2) = (at(0, 1) * at(1, 2) - at(1, 1) * at(0, 2)) * det;
    at(out, 1, 0) = -(at(1, 0) * at(2, 2) - at(2, 0) * at(1, 2)) * det;
    at(out, 1, 1) = (at(0, 0) * at(2, 2) - at(2, 0) * at(0, 2)) * det;
    at(out, 1, 2) = -(at(0, 0) * at(1, 2) - at(1, 0) * at(0, 2)) * det;
    at(out, 2, 0) = (at(1, 0) * at(2, 1) - at(2, 0) * at(1, 1)) * det;
    at(out, 2, 1) = -(at(0, 0) * at(2, 1) - at(2, 0) * at(0, 1)) * det;
    at(out, 2, 2) = (at(0, 0) * at(1, 1) - at(1, 0) * at(0, 1)) * det;
    translation_part(out);
    inv_ = out;
    return true;
  }

  glm::mat4 m_{1.0f};
  glm::mat4 inv_{1.0f};
  unsigned flags_ = 0;
  Type type_ = Type::Identity;
};

}  // namespace ffc::state::fmat
