// The general path's row loop for triangles under fog or polygon offset: the same coverage,
// depth and colour arithmetic as span.h's rasterize (whose scalar row loop this follows
// operation by operation), plus the fog coordinate's plane and the depth offset per fragment.
// Kept apart so that the fast loops and kernels stay as they are.
#include <cmath>

#include "raster/span.h"

namespace ffc::raster::detail {

void rasterize_fragment_ops(Framebuffer& fb, const Triangle& t, const State& s, const Bands& bands) {
  int64_t thr[3], a[3], b[3], c[3];
  for (int i = 0; i < 3; ++i) {
    thr[i] = t.inclusive[i] ? 0 : 1;
    const int j = (i + 1) % 3, k = (i + 2) % 3;
    a[i] = -(t.y[k] - t.y[j]) * 256;  // per pixel in x
    b[i] = (t.x[k] - t.x[j]) * 256;   // per pixel in y
    c[i] = (t.x[k] - t.x[j]) * (128 - t.y[j]) - (t.y[k] - t.y[j]) * (128 - t.x[j]);
  }
  const int first_band = bands.next[size_t(t.ymin / kBandRows)];
  for (int by = first_band; by * kBandRows <= t.ymax; by += bands.count) {
    const int row_end = std::min(by * kBandRows + kBandRows - 1, t.ymax);
    for (int py = std::max(by * kBandRows, t.ymin); py <= row_end; ++py) {
      int lo = t.xmin, hi = t.xmax;
      for (int i = 0; i < 3; ++i) span(c[i] + b[i] * py, a[i], thr[i], lo, hi);
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
    }
  }
}

}  // namespace ffc::raster::detail
