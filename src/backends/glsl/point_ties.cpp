#include "backends/glsl/point_ties.h"

#include <algorithm>
#include <cmath>

#include "raster/raster.h"

namespace ffc::glsl {

bool point_on_tie(const state::SinkState& s, const state::SinkVertex* v, size_t count, const uint32_t* elements, size_t n,
                  int fb_height) {
  raster::State rs;
  rs.viewport = s.viewport, rs.depth_range = s.depth_range, rs.fb_height = fb_height, rs.float_window = true;
  // The size as llvmpipe rounds it (half down, at least 1, at most 255: raster::draw_point).
  const float size = std::min(s.point_size, 255.0f);
  const int width = std::max(1, int(std::floor((size > 0 ? size : 1) + 127.0f / 256.0f)));
  const float tie = width % 2 ? 0.0f : 0.5f;  // the centre's fraction that puts an edge on a pixel centre
  for (size_t k = 0; k < n; ++k) {
    const size_t i = elements ? elements[k] : k;
    if (i >= count) continue;
    const glm::vec4 clip = s.mvp * v[i].position;
    if (raster::outside_planes(glm::dvec4(clip)) != 0) continue;
    const raster::FloatWindow f = raster::map_float(clip, rs);
    if (f.x - std::floor(f.x) == tie || f.y_down - std::floor(f.y_down) == tie) return true;
  }
  return false;
}

}  // namespace ffc::glsl
