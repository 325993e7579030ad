// index_range.h's scan, compiled once per Highway target (hwy/foreach_target.h re-includes this
// file) and dispatched to the one the CPU runs.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "simd/index_range.cpp"
#include "simd/targets.h"  // before Highway: the targets we compile
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include <algorithm>

#include "simd/index_range.h"

HWY_BEFORE_NAMESPACE();
namespace ffc::simd::HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

void IndexRange(const uint32_t* u, size_t n, uint32_t& lo, uint32_t& hi) {
  const hn::ScalableTag<uint32_t> d;
  const size_t lanes = hn::Lanes(d);
  auto vlo = hn::Set(d, UINT32_MAX), vhi = hn::Zero(d);
  size_t i = 0;
  for (; i + lanes <= n; i += lanes) {
    const auto v = hn::LoadU(d, u + i);
    vlo = hn::Min(vlo, v), vhi = hn::Max(vhi, v);
  }
  lo = hn::GetLane(hn::MinOfLanes(d, vlo)), hi = hn::GetLane(hn::MaxOfLanes(d, vhi));
  for (; i < n; ++i) lo = std::min(lo, u[i]), hi = std::max(hi, u[i]);
}

}  // namespace ffc::simd::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace ffc::simd {

HWY_EXPORT(IndexRange);

void index_range(const uint32_t* u, size_t n, uint32_t& lo, uint32_t& hi) { HWY_DYNAMIC_DISPATCH(IndexRange)(u, n, lo, hi); }

}  // namespace ffc::simd
#endif  // HWY_ONCE
