// Reading client vertex arrays (glVertexPointer, glNormalPointer, glColorPointer): one element's
// components in double, as the vertex stage takes them.
#pragma once
#include <GL/gl.h>

#include <emmintrin.h>

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

// Reads component k of an array element; `normalized` maps integers to [-1,1] or [0,1] as GL 2.1
// does for normals and colours: signed (2c+1)/(2^b-1), unsigned c/(2^b-1).
inline double read_component(const uint8_t* p, GLenum type, int k, bool normalized) {
  switch (type) {
    case GL_BYTE: { int8_t v; std::memcpy(&v, p + k, 1); return normalized ? (2.0 * v + 1) / 255.0 : v; }
    case GL_UNSIGNED_BYTE: { uint8_t v = p[k]; return normalized ? v / 255.0 : v; }
    case GL_SHORT: { int16_t v; std::memcpy(&v, p + 2 * k, 2); return normalized ? (2.0 * v + 1) / 65535.0 : v; }
    case GL_UNSIGNED_SHORT: { uint16_t v; std::memcpy(&v, p + 2 * k, 2); return normalized ? v / 65535.0 : v; }
    case GL_INT: { int32_t v; std::memcpy(&v, p + 4 * k, 4); return normalized ? (2.0 * v + 1) / 4294967295.0 : v; }
    case GL_UNSIGNED_INT: { uint32_t v; std::memcpy(&v, p + 4 * k, 4); return normalized ? v / 4294967295.0 : v; }
    case GL_FLOAT: { float v; std::memcpy(&v, p + 4 * k, 4); return v; }
    case GL_DOUBLE: { double v; std::memcpy(&v, p + 8 * k, 8); return v; }
    default: return 0;
  }
}

inline const uint8_t* element(const ClientArray& a, GLint i) {
  const size_t stride = a.stride ? size_t(a.stride) : a.size * type_size(a.type);
  return static_cast<const uint8_t*>(a.pointer) + stride * size_t(i);
}

// The smallest and largest of n indices (n > 0), four at a time in SSE2 (which compares signed:
// the top bit is flipped first). A draw of a million indices reads them all before anything else.
inline void index_range(const uint32_t* u, size_t n, uint32_t& lo, uint32_t& hi) {
  const __m128i flip = _mm_set1_epi32(INT32_MIN);
  __m128i vlo = _mm_set1_epi32(INT32_MAX), vhi = _mm_set1_epi32(INT32_MIN);
  size_t i = 0;
  for (; i + 4 <= n; i += 4) {
    const __m128i v = _mm_xor_si128(_mm_loadu_si128(reinterpret_cast<const __m128i*>(u + i)), flip);
    const __m128i less = _mm_cmplt_epi32(v, vlo), more = _mm_cmpgt_epi32(v, vhi);
    vlo = _mm_or_si128(_mm_and_si128(less, v), _mm_andnot_si128(less, vlo));
    vhi = _mm_or_si128(_mm_and_si128(more, v), _mm_andnot_si128(more, vhi));
  }
  alignas(16) uint32_t l[4], h[4];
  _mm_store_si128(reinterpret_cast<__m128i*>(l), _mm_xor_si128(vlo, flip));
  _mm_store_si128(reinterpret_cast<__m128i*>(h), _mm_xor_si128(vhi, flip));
  lo = UINT32_MAX, hi = 0;
  for (int k = 0; k < 4 && i >= 4; ++k) lo = std::min(lo, l[k]), hi = std::max(hi, h[k]);
  for (; i < n; ++i) lo = std::min(lo, u[i]), hi = std::max(hi, u[i]);
}

}  // namespace ffc::state
