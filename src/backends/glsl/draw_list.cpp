#include "backends/glsl/draw_list.h"

namespace ffc::glsl {

DrawList listed(GLenum mode, const uint32_t* elements, size_t n, size_t vertices, const SplitRule& rule,
                std::vector<uint32_t>& scratch, std::vector<uint8_t>* edges) {
  DrawList d;
  d.vertices = vertices;
  const size_t per = mode == GL_POINTS ? 1 : mode == GL_LINES ? 2 : mode == GL_TRIANGLES ? 3 : 0;
  if (per && !edges) {  // an incomplete last primitive is dropped, as GL drops it
    d.mode = mode, d.indices = elements, d.count = n / per * per;
    return d;
  }
  d.mode = decompose(mode, elements, n, rule, scratch, edges);
  d.indices = scratch.data(), d.count = scratch.size();
  return d;
}

}  // namespace ffc::glsl
