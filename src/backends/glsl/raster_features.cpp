#include "backends/glsl/raster_features.h"

#include <utility>

namespace ffc::glsl {

void apply_raster_features(const CoreGl& gl, const state::SinkState& s) {
  const std::pair<GLenum, bool> offsets[] = {
      {GL_POLYGON_OFFSET_FILL, s.offset_fill}, {GL_POLYGON_OFFSET_LINE, s.offset_line}, {GL_POLYGON_OFFSET_POINT, s.offset_point}};
  for (const auto& [cap, on] : offsets) on ? gl.Enable(cap) : gl.Disable(cap);
  gl.PolygonOffset(s.offset_factor, s.offset_units);
}

}  // namespace ffc::glsl
