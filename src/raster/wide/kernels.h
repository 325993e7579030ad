// The rasterizer's vector kernels, written once with Highway (hwy/highway.h) and compiled for
// every target it has (AVX-512, AVX2, SSE4 on x86; NEON or SVE on ARM), the best the CPU runs
// chosen at the first call (HWY_DYNAMIC_DISPATCH; src/simd/target.h narrows the choice). Each
// pixel gets the bits the row loop (raster/row_loop.h) gives it: planes evaluated at its centre as
// (p0 + px X) + py Y, the rules of raster/pixel_rules.h, products and sums apart (never fused,
// except depth's two fused multiply-adds, as llvmpipe's).
//   box    a triangle whose box of pixel centres is at most 8x8 (nearly all of a subdivided
//          sphere's): coverage of the whole box first, then depth and colour row by row for the
//          covered rows;
//   span   one row's covered pixels lo..hi: the long rows of large triangles;
//   rows   a triangle with edge functions in 32 bits and a larger box, in rows of a vector.
// Where the dispatch picks the portable target ("scalar"), none of them runs: the row loop does.
// Their per-target code: kernels-inl.h; the triangle lists' draw loop around them:
// triangle_list_wide.cpp.
#pragma once
#include <GL/gl.h>

#include <cstddef>
#include <cstdint>

#include "raster/raster.h"
#include "simd/target.h"

namespace ffc::raster::detail {

struct Bands;
enum DepthMode : int;

// Whether the kernels run: the dispatch picks a vector target (simd::vector_target()) and tests
// have not turned them off (set_wide_kernels(false), to hold them to the row loop, bit for bit).
extern bool g_kernels_allowed;
inline bool wide_kernels() { return g_kernels_allowed && simd::vector_target(); }
inline void set_wide_kernels(bool on) { g_kernels_allowed = on; }

// A triangle's inputs, read in place: field k at base[k * stride].
//
// Edges, 16 int32 fields: the box of pixel centres (within the framebuffer), then per
// edge its function at the box's first pixel centre in 1/256 pixel, its steps per pixel in x and
// y, and its limit: a centre is covered when every e > limit (-1 for an edge that owns the centres
// exactly on it, 0 otherwise).
enum KernelEdgeField { kXmin, kYmin, kXmax, kYmax, kE0, kPerX = kE0 + 3, kPerY = kPerX + 3, kLimit = kPerY + 3, kEdgeFields = kLimit + 3 };
struct KernelEdges {
  const int32_t* base;
  int stride;
  int32_t operator()(int field) const { return base[field * stride]; }
};
// Planes, value at pixel centre (X, Y) = (p0 + px X) + py Y: depth as 3 floats (llvmpipe's, see
// depth_at), then 15 floats: 1/w's p0, px, py, then colour / w as p0 (r, g, b, a), px (r, g, b, a), py (r, g, b, a).
constexpr int kPlaneFloats = 15;
struct KernelPlanes {
  const float* z;  // llvmpipe's depth plane (setup.h depth_plane)
  const float* f;
  int stride;
};

// A triangle's planes, filled on demand (the row loop's `planes()`), as a plain function pointer
// so that the dispatched code takes any caller's.
struct PlanesRef {
  bool (*call)(void*);
  void* self;
  bool operator()() const { return call(self); }
  template <typename F>
  static PlanesRef of(F& f) {
    return {[](void* p) { return (*static_cast<F*>(p))(); }, &f};
  }
};

// The row loop's rasterize() on the dispatched target: the rows of t (edges set up, box within the
// framebuffer) in this thread's bands. Returns the drawn pixels whose colour was not finite.
uint64_t rasterize_wide(DepthMode mode, Framebuffer& fb, Triangle& t, GLenum depth_func, const Bands& bands, PlanesRef planes);

// out[i] = a[i] * b[i] + c[i] rounded once, by the dispatched target's vector code for depth (one
// instruction, or in double with a check for halfway cases; with `row`, the code that makes the
// product once for a row's pixels): for tests against std::fma.
void fused_mul_add_wide(const float* a, const float* b, const float* c, float* out, size_t n, bool row);

}  // namespace ffc::raster::detail
