// The general path's row loop for triangles under fog or polygon offset: the same coverage,
// depth and colour arithmetic as row_loop.h's rasterize (whose scalar row loop this follows
// operation by operation), plus the fog coordinate's plane and the depth offset per fragment.
// Kept apart so that the fast loops and kernels stay as they are.
#include <cmath>

#include "raster/row_loop.h"

namespace ffc::raster::detail {

void rasterize_fragment_ops(Framebuffer& fb, const Triangle& t, const State& s, const Bands& bands) {
  for_each_row_span(t, bands, [&](int py, int lo, int hi) {
    const float fy = float(py + 0.5), y_down = float(fb.height - 1 - py);
    const float iwy = t.inv_w[2] * fy;
    for (int px = lo; px <= hi; ++px) {
      const size_t i = size_t(py) * fb.width + px;
      if (s.depth_test) {
        const uint32_t zi = depth24(depth_at(t.z, 1, float(px), y_down) + t.offset);
        if (!depth_pass(s.depth_func, zi, fb.depth[i])) continue;
        fb.depth[i] = zi;
      }
      const float fx = float(px + 0.5), iw = t.inv_w[0] + t.inv_w[1] * fx + iwy;
      const float rw = 1.0f / iw;
      glm::dvec4 col;
      for (int k = 0; k < 4; ++k) col[k] = ((t.c0[k] + t.cx[k] * fx) + t.cy[k] * fy) * rw;
      if (s.fog) {
        const float fw = t.fog_w[0] + t.fog_w[1] * fx + t.fog_w[2] * fy;
        col = apply_fog(col, ((t.fog[0] + t.fog[1] * fx) + t.fog[2] * fy) * (1.0f / fw), s);
      }
      uint8_t* o = &fb.color[i * 4];
      for (int k = 0; k < 4; ++k) o[k] = to_unorm8(col[k]);
    }
    return true;
  });
}

}  // namespace ffc::raster::detail
