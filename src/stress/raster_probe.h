// The rasterizer's count of fragments written from a non-finite colour (a NaN or an infinity in
// any channel before the clamp to [0,1]). Defined in src/raster/raster.cpp, next to the code that
// counts; declared here because src/raster/raster.h belongs to the rasterizer's owner (this
// declaration can move there as is). The count is process-wide: reset it, draw, read it.
#pragma once
#include <cstdint>

namespace ffc::raster {

uint64_t nonfinite_fragments();
void reset_nonfinite_fragments();

}  // namespace ffc::raster
