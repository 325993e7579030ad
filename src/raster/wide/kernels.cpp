// The kernels of kernels.h, compiled once per Highway target (hwy/foreach_target.h re-includes
// this file), and the dispatch to the one the CPU runs.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "raster/wide/kernels.cpp"
#include "simd/targets.h"  // before Highway: the targets we compile
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include <cstddef>

#include "raster/wide/kernels-inl.h"

HWY_BEFORE_NAMESPACE();
namespace ffc::raster::detail::HWY_NAMESPACE {

uint64_t RasterizeWide(DepthMode mode, Framebuffer& fb, Triangle& t, GLenum func, const Bands& bands, PlanesRef planes) {
  switch (mode) {
    case kNoDepth: return Rasterize<kNoDepth>(fb, t, func, bands, planes);
    case kLess: return Rasterize<kLess>(fb, t, func, bands, planes);
    case kLequal: return Rasterize<kLequal>(fb, t, func, bands, planes);
    case kAnyDepth: return Rasterize<kAnyDepth>(fb, t, func, bands, planes);
  }
  return 0;
}

}  // namespace ffc::raster::detail::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace ffc::raster::detail {

HWY_EXPORT(RasterizeWide);

bool g_kernels_allowed = true;

uint64_t rasterize_wide(DepthMode mode, Framebuffer& fb, Triangle& t, GLenum func, const Bands& bands, PlanesRef planes) {
  return HWY_DYNAMIC_DISPATCH(RasterizeWide)(mode, fb, t, func, bands, planes);
}

static_assert(offsetof(Triangle, cy) + 4 * sizeof(float) == offsetof(Triangle, inv_w) + kPlaneFloats * sizeof(float),
              "Triangle's planes are read as one array of floats");

}  // namespace ffc::raster::detail
#endif  // HWY_ONCE
