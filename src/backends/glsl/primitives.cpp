#include "backends/glsl/primitives.h"

#include <initializer_list>

namespace ffc::glsl {

GLenum decompose(GLenum mode, const uint32_t* e, size_t n, const SplitRule& rule, std::vector<uint32_t>& out,
                 std::vector<uint8_t>* edges) {
  out.clear();
  if (edges) edges->clear();
  auto at = [e](size_t k) { return e ? e[k] : uint32_t(k); };
  // Whether vertices j and k (positions in the draw) are neighbours on their polygon's boundary.
  auto boundary = [mode, n](size_t j, size_t k) {
    const size_t lo = j < k ? j : k, hi = j < k ? k : j;
    switch (mode) {
      case GL_QUADS: return hi - lo == 1 || hi - lo == 3;  // within one quad: not the diagonal
      case GL_QUAD_STRIP: return hi - lo == 2 || (hi - lo == 1 && lo % 2 == 0);  // the sides and the rungs
      case GL_POLYGON: return hi - lo == 1 || (lo == 0 && hi == n - 1);
      default: return true;
    }
  };
  auto put = [&](std::initializer_list<size_t> ks) {
    for (size_t k : ks) out.push_back(at(k));
    if (edges && ks.size() == 3) {
      const size_t* t = ks.begin();
      edges->push_back(uint8_t(boundary(t[0], t[1]) | boundary(t[1], t[2]) << 1 | boundary(t[2], t[0]) << 2));
    }
  };
  switch (mode) {
    case GL_POINTS:
      for (size_t i = 0; i < n; ++i) put({i});
      return GL_POINTS;
    case GL_LINES:
      for (size_t i = 0; i + 1 < n; i += 2) put({i, i + 1});
      return GL_LINES;
    case GL_LINE_STRIP:
    case GL_LINE_LOOP:
      for (size_t i = 0; i + 1 < n; ++i) put({i, i + 1});
      if (mode == GL_LINE_LOOP && n >= 2) put({n - 1, 0});  // the first vertex provokes the closing segment
      return GL_LINES;
    case GL_TRIANGLES:
      for (size_t i = 0; i + 2 < n; i += 3) put({i, i + 1, i + 2});
      break;
    case GL_TRIANGLE_STRIP:  // every other triangle turned back to the strip's winding
      for (size_t i = 0; i + 2 < n; ++i) i % 2 == 0 ? put({i, i + 1, i + 2}) : put({i + 1, i, i + 2});
      break;
    case GL_TRIANGLE_FAN:
      for (size_t i = 1; i + 1 < n; ++i) put({0, i, i + 1});
      break;
    case GL_QUADS:  // the 4th vertex provokes
      for (size_t i = 0; i + 3 < n; i += 4) {
        if (rule.flat || rule.any_outside || rule.from_elements || rule.pipeline) put({i, i + 1, i + 3}), put({i + 1, i + 2, i + 3});
        else put({i, i + 1, i + 2}), put({i, i + 2, i + 3});  // smooth: the provoking vertex does not matter
      }
      break;
    case GL_QUAD_STRIP:  // quad (2i, 2i+1, 2i+3, 2i+2); 2i+3 provokes
      for (size_t i = 0; i + 3 < n; i += 2) {
        if (rule.any_outside || rule.pipeline) put({i + 2, i, i + 3}), put({i, i + 1, i + 3});
        else if (rule.flat) put({i, i + 1, i + 3}), put({i + 2, i, i + 3});  // the same two, 2i+3 last
        else put({i, i + 1, i + 3}), put({i, i + 3, i + 2});
      }
      break;
    case GL_POLYGON:  // a fan from the first vertex, which provokes: put last when flat
      for (size_t i = 1; i + 1 < n; ++i) rule.flat || rule.pipeline ? put({i, i + 1, 0}) : put({0, i, i + 1});
      break;
  }
  return GL_TRIANGLES;
}

}  // namespace ffc::glsl
