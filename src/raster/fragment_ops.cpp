// The general path's row loop for triangles under per-fragment operations (State::fragment_ops:
// fog, polygon offset, scissor, alpha test, depth mask, blending, colour mask): the same
// coverage, depth and colour arithmetic as row_loop.h's rasterize (whose scalar row loop this
// follows operation by operation), plus the fog coordinate's plane, the depth offset and the
// operations of fragment.h per fragment. Kept apart so that the fast loops and kernels stay as
// they are.
#include <algorithm>
#include <cmath>

#include "raster/fragment.h"
#include "raster/row_loop.h"

namespace ffc::raster::detail {

namespace {

// Blending as llvmpipe does it for an RGBA8 buffer (lp_bld_blend_aos.c), measured bit for bit
// against Mesa 22.3 over every source and destination byte, every GL 1.4 factor pair and every
// equation: the source colour is first converted to unorm8 (round half to even), the factors
// are unorm8 values (1 - x as 255 - x, the constant colour converted as the source), each
// product a * f is divided by 255 rounding to nearest as (p + (p >> 8) + 128) >> 8, and the two
// terms are added (or subtracted) with saturation to [0, 255]. GL_MIN and GL_MAX take no factors.
int factor(GLenum f, int k, const int* s, const int* d, const uint8_t* c) {
  switch (f) {
    case GL_ZERO: return 0;
    case GL_ONE: return 255;
    case GL_SRC_COLOR: return s[k];
    case GL_ONE_MINUS_SRC_COLOR: return 255 - s[k];
    case GL_DST_COLOR: return d[k];
    case GL_ONE_MINUS_DST_COLOR: return 255 - d[k];
    case GL_SRC_ALPHA: return s[3];
    case GL_ONE_MINUS_SRC_ALPHA: return 255 - s[3];
    case GL_DST_ALPHA: return d[3];
    case GL_ONE_MINUS_DST_ALPHA: return 255 - d[3];
    case GL_SRC_ALPHA_SATURATE: return k == 3 ? 255 : std::min(s[3], 255 - d[3]);
    case GL_CONSTANT_COLOR: return c[k];
    case GL_ONE_MINUS_CONSTANT_COLOR: return 255 - c[k];
    case GL_CONSTANT_ALPHA: return c[3];
    case GL_ONE_MINUS_CONSTANT_ALPHA: return 255 - c[3];
    default: return 0;
  }
}

int mul255(int a, int f) {
  const int p = a * f;
  return (p + (p >> 8) + 128) >> 8;
}

int blend_channel(GLenum eq, GLenum sf, GLenum df, int k, const int* s, const int* d, const uint8_t* c) {
  int r;
  switch (eq) {
    case GL_MIN: return std::min(s[k], d[k]);
    case GL_MAX: return std::max(s[k], d[k]);
    case GL_FUNC_SUBTRACT: r = mul255(s[k], factor(sf, k, s, d, c)) - mul255(d[k], factor(df, k, s, d, c)); break;
    case GL_FUNC_REVERSE_SUBTRACT: r = mul255(d[k], factor(df, k, s, d, c)) - mul255(s[k], factor(sf, k, s, d, c)); break;
    default: r = mul255(s[k], factor(sf, k, s, d, c)) + mul255(d[k], factor(df, k, s, d, c)); break;
  }
  return std::clamp(r, 0, 255);
}

}  // namespace

void write_color(const State::Ops& o, uint8_t* dst, const glm::dvec4& color) {
  int s[4], d[4];
  for (int k = 0; k < 4; ++k) s[k] = to_unorm8(color[k]), d[k] = dst[k];
  int out[4] = {s[0], s[1], s[2], s[3]};
  if (o.blend) {
    for (int k = 0; k < 3; ++k) out[k] = blend_channel(o.eq_rgb, o.src_rgb, o.dst_rgb, k, s, d, o.blend_color);
    out[3] = blend_channel(o.eq_alpha, o.src_alpha, o.dst_alpha, 3, s, d, o.blend_color);
  }
  for (int k = 0; k < 4; ++k)
    if (o.color_mask >> k & 1) dst[k] = uint8_t(out[k]);
}

void rasterize_fragment_ops(Framebuffer& fb, const Triangle& t, const State& s, const Bands& bands) {
  for_each_row_span(t, bands, [&](int py, int lo, int hi) {
    const float fy = float(py + 0.5), y_down = float(fb.height - 1 - py);
    const float iwy = t.inv_w[2] * fy;
    for (int px = lo; px <= hi; ++px) {
      const size_t i = size_t(py) * fb.width + px;
      const float fx = float(px + 0.5), iw = t.inv_w[0] + t.inv_w[1] * fx + iwy;
      const float rw = 1.0f / iw;
      glm::dvec4 col;
      for (int k = 0; k < 4; ++k) col[k] = ((t.c0[k] + t.cx[k] * fx) + t.cy[k] * fy) * rw;
      if (s.fog) {
        const float fw = t.fog_w[0] + t.fog_w[1] * fx + t.fog_w[2] * fy;
        col = apply_fog(col, ((t.fog[0] + t.fog[1] * fx) + t.fog[2] * fy) * (1.0f / fw), s);
      }
      if (!alpha_pass(s.ops, col[3])) continue;  // before the depth test: a failing fragment writes no depth
      if (s.depth_test) {
        const uint32_t zi = depth24(depth_at(t.z, 1, float(px), y_down) + t.offset);
        if (!depth_pass(s.depth_func, zi, fb.depth[i])) continue;
        if (s.ops.depth_write) fb.depth[i] = zi;
      }
      write_color(s.ops, &fb.color[i * 4], col);
    }
    return true;
  });
}

}  // namespace ffc::raster::detail
