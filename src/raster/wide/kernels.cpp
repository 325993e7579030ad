// The kernels of kernels.h, compiled once per Highway target (hwy/foreach_target.h re-includes
// this file), and the dispatch to the one the CPU runs.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "raster/wide/kernels.cpp"
#include "simd/targets.h"  // before Highway: the targets we compile
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include <algorithm>
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

// Depth's fused multiply-add on this target, a vector at a time, as FusedMulAdd or (row) as
// FusedRow, whose product is made first (its own test: kernels_test).
void FusedMulAddArrays(const float* a, const float* b, const float* c, float* out, size_t n, bool row) {
  const hn::ScalableTag<float> df;
  const size_t lanes = hn::Lanes(df);
  alignas(64) float x[kMaxLanes32], y[kMaxLanes32], z[kMaxLanes32];
  for (size_t i = 0; i < n; i += lanes) {
    const size_t m = std::min(lanes, n - i);
    for (size_t k = 0; k < lanes; ++k) x[k] = k < m ? a[i + k] : 0, y[k] = k < m ? b[i + k] : 0, z[k] = k < m ? c[i + k] : 0;
    const auto va = hn::Load(df, x), vb = hn::Load(df, y), vc = hn::Load(df, z);
    hn::Store(row ? FusedRow<hn::ScalableTag<float>>(df, va, vb)(df, vc) : FusedMulAdd(df, va, vb, vc), df, x);
    for (size_t k = 0; k < m; ++k) out[i + k] = x[k];
  }
}

}  // namespace ffc::raster::detail::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace ffc::raster::detail {

HWY_EXPORT(RasterizeWide);
HWY_EXPORT(FusedMulAddArrays);

void fused_mul_add_wide(const float* a, const float* b, const float* c, float* out, size_t n, bool row) {
  HWY_DYNAMIC_DISPATCH(FusedMulAddArrays)(a, b, c, out, n, row);
}

bool g_kernels_allowed = true;

uint64_t rasterize_wide(DepthMode mode, Framebuffer& fb, Triangle& t, GLenum func, const Bands& bands, PlanesRef planes) {
  return HWY_DYNAMIC_DISPATCH(RasterizeWide)(mode, fb, t, func, bands, planes);
}

static_assert(offsetof(Triangle, cy) + 4 * sizeof(float) == offsetof(Triangle, inv_w) + kPlaneFloats * sizeof(float),
              "Triangle's planes are read as one array of floats");

}  // namespace ffc::raster::detail
#endif  // HWY_ONCE
