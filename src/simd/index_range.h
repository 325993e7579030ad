// The smallest and largest of n 32-bit indices, a vector at a time on the dispatched Highway
// target (glDrawElements reads every index before anything else: state/draw.cpp).
#pragma once
#include <cstddef>
#include <cstdint>

namespace ffc::simd {

// lo = UINT32_MAX and hi = 0 when n is 0.
void index_range(const uint32_t* u, size_t n, uint32_t& lo, uint32_t& hi);

}  // namespace ffc::simd
