// The per-vertex materials of a glBegin/glEnd that changed glMaterial between its vertices
// (state::SinkState::vertex_materials), streamed into a buffer of their own as attributes
// kMaterial .. kMaterial + 7 beside the vertices; for other draws those attributes are off.
#pragma once
#include <vector>

#include "backends/glsl/gl_core.h"
#include "state/draw_sink.h"

namespace ffc::glsl {

class MaterialStream {
 public:
  // With the draw's vertex array object bound: the materials' buffer filled and the attributes
  // pointed at it, or (null) the attributes turned off.
  void stream(const CoreGl& gl, const std::vector<state::SinkMaterial>* materials);
  void destroy(const CoreGl& gl);  // the context current

 private:
  GLuint buffer_ = 0;
  bool on_ = false;
};

}  // namespace ffc::glsl
