// The AVX-512 kernels (x86-64 with AVX-512F/VL/DQ, chosen at run time; not built without x86
// intrinsics, raster/isa.h). Three kernels, sixteen pixels a vector, each pixel getting the bits
// the row loop (raster/row_loop.h) gives it: planes evaluated at its centre as (p0 + px X) + py Y,
// the rules of raster/pixel_rules.h.
//   box    a triangle whose box of pixel centres is at most 8x8 (nearly all of a subdivided
//          sphere's), in blocks of 4x4 (box at most 4 wide) or 8x2: coverage first for the whole
//          box, then depth and colour for the blocks with a covered pixel, written through masks;
//   span   one row's covered pixels lo..hi: the long rows of large triangles;
//   rows   a triangle with edge functions in 32 bits and a larger box, in rows of sixteen.
// Their parts, inline, for code compiled for AVX-512: kernels_inline.h. The triangle lists' own
// eight-triangle setup and sixteen-triangle binning: triangle_list_avx512.cpp.
#pragma once
#include <GL/gl.h>

#include <cstdint>

#include "raster/isa.h"
#include "raster/raster.h"

namespace ffc::raster::detail {

struct Bands;
enum DepthMode : int;

// Whether the kernels and the triangle lists' AVX-512 setup and binning run: built with x86
// intrinsics, the CPU has AVX-512VL, FFCOMPAT_SCALAR=1 is not in the environment, and tests have
// not turned them off (to hold them to the row loop, bit for bit).
#if FFCOMPAT_X86
extern bool g_wide_kernels;
inline bool wide_kernels() { return g_wide_kernels; }
void set_wide_kernels(bool on);
#else
constexpr bool wide_kernels() { return false; }  // not built: no x86 intrinsics
inline void set_wide_kernels(bool) {}
#endif

// A triangle's inputs, read in place: field k at base[k * stride] (stride 1: one triangle's own
// arrays; 8: one lane of eight triangles set up together).
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

// The edge fields of a set-up triangle (counter-clockwise, box within the framebuffer, vertex
// extents below 31 pixels so that the edge functions fit in 32 bits): pixel_rules.h's edge_function.
void kernel_edges(const Triangle& t, int32_t (&out)[kEdgeFields]);

// The lanes covered in each block, and which blocks have any (bit b for block b).
struct BoxCoverage {
  uint16_t lanes[4];
  unsigned blocks;
  bool wide;  // 8x2 blocks (box wider than 4), else 4x4
};

// The covered centres in this thread's rows.
BoxCoverage box_coverage(const KernelEdges& e, const Bands& bands);
// Depth test and colour for the covered lanes; returns the number of drawn pixels whose colour
// was not finite.
template <DepthMode D>
uint64_t box_shade(Framebuffer& fb, const KernelPlanes& p, int xmin, int ymin, GLenum depth_func, const BoxCoverage& c);

// Both in one, inline, for callers compiled for AVX-512: kernels_inline.h.

// Pixels lo..hi of row y, sixteen at a time, the same bits: for the long spans of large triangles.
template <DepthMode D>
uint64_t span_shade(Framebuffer& fb, const KernelPlanes& p, int y, int lo, int hi, GLenum depth_func);

// A triangle with vertex extents below 31 pixels (edge functions in 32 bits) and any box, in rows
// of sixteen pixels, its planes broadcast once: rows of this thread's bands.
template <DepthMode D>
uint64_t rows_shade(Framebuffer& fb, const KernelEdges& e, const KernelPlanes& p, const Bands& bands, GLenum depth_func);

}  // namespace ffc::raster::detail
