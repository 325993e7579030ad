// Reading client vertex arrays (glVertexPointer, glNormalPointer, glColorPointer): one element's
// components in double, as the vertex stage takes them.
#pragma once
#include <GL/gl.h>


#include <algorithm>
#include <climits>
#include <cstdint>
#include <cstring>

#include "state/context.h"

namespace ffc::state {

inline size_t type_size(GLenum t) {
  switch (t) {
    case GL_BYTE: case GL_UNSIGNED_BYTE: return 1;
    case GL_SHORT: case GL_UNSIGNED_SHORT: return 2;
    case GL_INT: case GL_UNSIGNED_INT: case GL_FLOAT: return 4;
    case GL_DOUBLE: return 8;
    default: return 0;
  }
}

template <typename T>
double signed_to_unit(T c, Fixed f) {
  constexpr double max = double(T(~0u >> (32 - 8 * sizeof(T) + 1)));  // 2^(b-1) - 1
  switch (f) {
    case Fixed::Raw: return c;
    case Fixed::Gl42: return std::max(c / max, -1.0);
    case Fixed::MesaCall:
      if (sizeof(T) == 4) return float((2.0f * float(c) + 1.0f) * (1.0f / 4294967294.0));  // INT_TO_FLOAT
      return (2.0f * float(c) + 1.0f) * (1.0f / float(2 * max + 1));
    default: return (2.0 * c + 1) / (2 * max + 1);
  }
}

// Component k of an array element, in double.
inline double read_component(const uint8_t* p, GLenum type, int k, Fixed f) {
  const bool unit = f != Fixed::Raw;
  switch (type) {
    case GL_BYTE: { int8_t v; std::memcpy(&v, p + k, 1); return signed_to_unit(v, f); }
    case GL_UNSIGNED_BYTE: { uint8_t v = p[k]; return unit ? v / 255.0 : v; }
    case GL_SHORT: { int16_t v; std::memcpy(&v, p + 2 * k, 2); return signed_to_unit(v, f); }
    case GL_UNSIGNED_SHORT: { uint16_t v; std::memcpy(&v, p + 2 * k, 2); return unit ? v / 65535.0 : v; }
    case GL_INT: { int32_t v; std::memcpy(&v, p + 4 * k, 4); return signed_to_unit(v, f); }
    case GL_UNSIGNED_INT: { uint32_t v; std::memcpy(&v, p + 4 * k, 4); return unit ? v / 4294967295.0 : v; }
    case GL_FLOAT: { float v; std::memcpy(&v, p + 4 * k, 4); return v; }
    case GL_DOUBLE: { double v; std::memcpy(&v, p + 8 * k, 8); return v; }
    default: return 0;
  }
}

inline const uint8_t* element(const ClientArray& a, GLint i) {
  if (a.repeated) return static_cast<const uint8_t*>(a.pointer);
  const size_t stride = a.stride ? size_t(a.stride) : a.size * type_size(a.type);
  return static_cast<const uint8_t*>(a.pointer) + stride * size_t(i);
}

// Components [0, n) of an element of T, the others from `v`, a fixed-size copy each: straight to
// registers (a copy of a run-time size is a library call, and one copy of several components
// to the stack, read back one by one, stalls on store forwarding).
template <typename T>
glm::dvec4 direct(const uint8_t* p, int n, glm::dvec4 v) {
  auto at = [p](int k) {
    T t;
    std::memcpy(&t, p + size_t(k) * sizeof(T), sizeof(T));
    return double(t);
  };
  switch (n) {
    case 4: v.w = at(3); [[fallthrough]];
    case 3: v.z = at(2); [[fallthrough]];
    case 2: v.y = at(1); [[fallthrough]];
    default: v.x = at(0);
  }
  return v;
}

// Components [0, n) of element i in double, the others from `v`: the one reader of the client
// arrays. Float and double arrays (immediate mode's kept vertices among them) read directly.
inline glm::dvec4 attribute(const ClientArray& a, GLint i, int n, Fixed normalized, glm::dvec4 v) {
  const uint8_t* p = element(a, i);
  if (a.type == GL_FLOAT) return direct<float>(p, n, v);
  if (a.type == GL_DOUBLE) return direct<double>(p, n, v);
  for (int k = 0; k < n; ++k) v[k] = read_component(p, a.type, k, normalized);
  return v;
}

// The smallest and largest of n indices (n > 0): a draw of a million indices reads them all
// before anything else (draw.cpp).
void index_range(const uint32_t* u, size_t n, uint32_t& lo, uint32_t& hi);

}  // namespace ffc::state
