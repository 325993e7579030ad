// What a pixel gets, as llvmpipe gives it: which centres an edge owns, the depth test and the
// conversions of depth and colour to the buffers' integers. Every path (the reference, the row
// loop, the Highway kernels) computes these bits; the kernels' vector copies cite these.
#pragma once
#include "raster/isa.h"
#if FFCOMPAT_X86
#include <emmintrin.h>
#endif

#include <GL/gl.h>

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "raster/raster.h"

namespace ffc::raster::detail {

// Whether an edge owns the pixel centres exactly on it, from its direction (dx, dy) in the
// triangle's counter-clockwise order, y up (GL window coordinates): left and bottom edges do, so
// a centre on an edge two triangles share is drawn once. The rule every path follows
// (setup_edges; SetupEdges and SetupPlanes in wide/setup_group-inl.h, a triangle a lane).
inline bool owns_centres_on_edge(int64_t dx, int64_t dy) { return dy < 0 || (dy == 0 && dx > 0); }

// Edge i of a set-up triangle (from vertex i + 1 to vertex i + 2) as a function of the pixel
// centre (X + 0.5, Y + 0.5): twice the signed area of (edge, centre), in 1/256 pixel units,
// positive inside. `at` is its value at the centre of pixel (x0, y0), `per_x` and `per_y` its steps
// per pixel; a centre is covered when every edge's value is at least its `limit` (0 for an edge
// that owns the centres on it, else 1). Near (x0, y0) the values fit in 32 bits.
struct EdgeFunction {
  int64_t at, per_x, per_y, limit;
};
inline EdgeFunction edge_function(const Triangle& t, int i, int x0, int y0) {
  const int j = (i + 1) % 3, k = (i + 2) % 3;
  const int64_t dx = t.x[k] - t.x[j], dy = t.y[k] - t.y[j];
  const int64_t cx = int64_t(x0) * 256 + 128, cy = int64_t(y0) * 256 + 128;
  return {dx * (cy - t.y[j]) - dy * (cx - t.x[j]), -dy * 256, dx * 256, t.inclusive[i] ? 0 : 1};
}

inline bool depth_pass(GLenum func, uint32_t z, uint32_t stored) {
  switch (func) {
    case GL_NEVER: return false;
    case GL_LESS: return z < stored;
    case GL_EQUAL: return z == stored;
    case GL_LEQUAL: return z <= stored;
    case GL_GREATER: return z > stored;
    case GL_NOTEQUAL: return z != stored;
    case GL_GEQUAL: return z >= stored;
    default: return true;
  }
}

// Depth as llvmpipe computes it (Mesa 22.3, 24-bit unorm buffer): the fragment's z in float from
// a plane through the window positions (depth_plane), clamped to [0, 1] (lp_state_fs.c
// lp_build_depth_clamp; a NaN to 0: maxss gives its second operand), scaled by 2^24 - 1 in float
// and rounded half to even (lp_bld_conv.c lp_build_clamped_float_to_unsigned_norm, the branch for
// 24 bits = float's mantissa + 1). Ties between triangles are decided by these exact bits, so every
// copy (wide/kernels-inl.h Depth24, SetupEdges and SetupPlanes in wide/setup_group-inl.h) computes the same.
inline uint32_t depth24(float z) {
#if FFCOMPAT_X86
  const __m128 c = _mm_min_ss(_mm_max_ss(_mm_set_ss(z), _mm_setzero_ps()), _mm_set_ss(1.0f));
  return uint32_t(_mm_cvtss_si32(_mm_mul_ss(c, _mm_set_ss(16777215.0f))));
#else
  const float c = std::min(z > 0 ? z : 0.0f, 1.0f);  // maxss's order: a NaN (and -0) to +0
  return uint32_t(std::nearbyint(c * 16777215.0f));
#endif
}

// A colour channel to 8 bits as the SSE loops and the kernels do it: clamped to [0, 1] (a NaN to
// 0, as maxss), times 255, rounded half to even (the current rounding mode, as cvtps2dq).
inline uint8_t unorm8(float c) {
  const float clamped = std::min(c > 0 ? c : 0.0f, 1.0f);
  return uint8_t(std::nearbyint(clamped * 255.0f));
}

// The fragment's depth at pixel column X, row Y counted from the top: two multiply-adds, as
// lp_bld_interp.c's interp_attrib_linear (llvm.fmuladd: fused on a CPU with FMA, llvmpipe_fma()).
inline float depth_at(const float* z, int stride, float x, float y_down) {
  return llvmpipe_mul_add(z[2 * stride], y_down, llvmpipe_mul_add(z[stride], x, z[0]));
}

}  // namespace ffc::raster::detail
