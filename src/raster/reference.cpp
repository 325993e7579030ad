#include "raster/reference.h"

#include <algorithm>
#include <cmath>

#include "raster/pixel_rules.h"

namespace ffc::raster {

namespace {
bool g_reference = false;
}  // namespace

void set_reference_rasterizer(bool on) { g_reference = on; }
bool reference_rasterizer() { return g_reference; }

void draw_reference(Framebuffer& fb, const Triangle& t, const State& s) {
  // Which pixels. Positions are snapped to 1/256 pixel (8 subpixel bits, as llvmpipe); the
  // pixel (X, Y) is sampled at its centre (256 X + 128, 256 Y + 128). Edge i runs from vertex
  // i+1 to vertex i+2 of the counter-clockwise triangle; its edge function is twice the signed
  // area of (edge, centre): positive inside. A centre exactly on an edge (function 0) belongs to
  // the triangle only when the edge is a left or a bottom edge (Triangle::inclusive), so a pixel on
  // an edge two triangles share is drawn once.
  auto covered = [&](int X, int Y) {
    const int64_t cx = int64_t(X) * 256 + 128, cy = int64_t(Y) * 256 + 128;
    for (int i = 0; i < 3; ++i) {
      const int j = (i + 1) % 3, k = (i + 2) % 3;
      const int64_t e = (t.x[k] - t.x[j]) * (cy - t.y[j]) - (t.y[k] - t.y[j]) * (cx - t.x[j]);
      if (e < (t.inclusive[i] ? 0 : 1)) return false;
    }
    return true;
  };
  uint64_t nonfinite = 0;
  const int x0 = std::max(t.xmin, 0), x1 = std::min(t.xmax, fb.width - 1);
  const int y0 = std::max(t.ymin, 0), y1 = std::min(t.ymax, fb.height - 1);
  for (int Y = y0; Y <= y1; ++Y) {
    for (int X = x0; X <= x1; ++X) {
      if (!covered(X, Y)) continue;
      const size_t at = size_t(Y) * size_t(fb.width) + size_t(X);
      // Depth: llvmpipe's float plane, at the pixel's column and its row counted from the top,
      // two fused multiply-adds, clamped and converted to 24 bits (depth_at, depth24). A fragment
      // that fails the test is dropped; one that passes writes its depth.
      if (s.depth_test) {
        const uint32_t z = detail::depth24(detail::depth_at(t.z, 1, float(X), float(fb.height - 1 - Y)));
        if (!detail::depth_pass(s.depth_func, z, fb.depth[at])) continue;
        fb.depth[at] = z;
      }
      // Colour: perspective-correct, from the planes of colour / w and of 1/w at the pixel's
      // centre, each plane evaluated as (p0 + px x) + py y in float; the colour is their quotient,
      // colour / w times 1 / (1/w). Flat triangles have 1/w = 1 and constant colour planes.
      const float x = float(X + 0.5), y = float(Y + 0.5);
      const float inv_w = (t.inv_w[0] + t.inv_w[1] * x) + t.inv_w[2] * y;
      const float scale = 1.0f / inv_w;
      bool finite = true;
      for (int k = 0; k < 4; ++k) {
        const float c = ((t.c0[k] + t.cx[k] * x) + t.cy[k] * y) * scale;
        finite &= std::isfinite(c);
        fb.color[at * 4 + size_t(k)] = detail::unorm8(c);  // clamped, a NaN to 0, half to even
      }
      nonfinite += !finite;
    }
  }
  count_nonfinite(s, nonfinite);
}

}  // namespace ffc::raster
