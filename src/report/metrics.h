// A rendered picture against the ideal: the shading error over the pixels both cover, apart from
// the silhouette error (pixels only one of them covers). A picture covers a pixel where its alpha
// is not 0 (the sweep clears to (0,0,0,0) and lights with diffuse alpha 1).
#pragma once
#include <cstddef>

#include "image/image.h"
#include "report/ideal.h"

namespace ffc::report {

struct ShadingError {
  double rmse = 0;         // 8-bit steps, over the RGB channels of the pixels both cover, against the ideal's 8 bits
  int max_error = 0;       // largest |a-b| of a channel there
  double rmse_exact = 0;   // the same against the ideal before conversion (floor: about 0.29, rounding alone)
  size_t both = 0;         // pixels both cover
  size_t silhouette = 0;   // pixels exactly one covers
  double silhouette_share = 0;  // silhouette / pixels either covers
};

// Throws std::invalid_argument when the sizes differ.
ShadingError shading_error(const image::Image& picture, const Ideal& ideal);

// The RMSE, in 8-bit steps, that rounding alone leaves: the ideal's 8 bits against its exact
// colours (about sqrt(1/12) = 0.29 where nothing clamps).
double rounding_floor(const Ideal& ideal);

// image::heat_map of the picture against the ideal (the one scale: black equal, blue 1 step, red
// 4, yellow 16 or more), with the silhouette pixels magenta (picture only) and cyan (ideal only).
image::Image error_map(const image::Image& picture, const Ideal& ideal);

}  // namespace ffc::report
