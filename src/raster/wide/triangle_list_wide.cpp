// The triangle lists' draw loop (triangle_list.cpp's draw_bins) compiled once per Highway target,
// so that the kernels of kernels-inl.h are inlined into it: no call per triangle.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "raster/wide/triangle_list_wide.cpp"
#include "raster/wide/targets.h"  // before Highway: the targets we compile
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include "raster/triangle_list_parts.h"
#include "raster/wide/kernels-inl.h"

HWY_BEFORE_NAMESPACE();
namespace ffc::raster::detail::HWY_NAMESPACE {

template <DepthMode Mode>
void DrawBins(const List& l, const Bands& mine, const uint32_t* const* in, const size_t* counts, int shares) {
  uint64_t nonfinite = 0;
  for_each_binned(l, mine, in, counts, shares, [&](const std::array<size_t, 3>& vi, const Snapped (&p)[3]) {
    Triangle t;
    bool back, swapped;
    std::array<size_t, 3> order;
    if (!setup_one(l, vi, p, t, back, swapped, order)) return;
    nonfinite += Rasterize<Mode>(l.fb, t, l.s.depth_func, mine, [&] { return list_planes(l, vi, t, back, swapped, order); });
  });
  if (nonfinite) g_nonfinite_fragments.fetch_add(nonfinite, std::memory_order_relaxed);
}

void DrawBinsWide(DepthMode mode, const List& l, const Bands& mine, const uint32_t* const* in, const size_t* counts, int shares) {
  switch (mode) {
    case kNoDepth: return DrawBins<kNoDepth>(l, mine, in, counts, shares);
    case kLess: return DrawBins<kLess>(l, mine, in, counts, shares);
    case kLequal: return DrawBins<kLequal>(l, mine, in, counts, shares);
    case kAnyDepth: return DrawBins<kAnyDepth>(l, mine, in, counts, shares);
  }
}

}  // namespace ffc::raster::detail::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace ffc::raster::detail {

HWY_EXPORT(DrawBinsWide);

void draw_bins_wide(DepthMode mode, const List& l, const Bands& mine, const uint32_t* const* in, const size_t* counts, int shares) {
  HWY_DYNAMIC_DISPATCH(DrawBinsWide)(mode, l, mine, in, counts, shares);
}

}  // namespace ffc::raster::detail
#endif  // HWY_ONCE
