// Differences between two pictures of the same size, in 8-bit steps over the RGB channels.
#pragma once
#include <array>

#include "image/image.h"

namespace ffc::image {

struct Diff {
  int max_diff = 0;            // largest |a-b| of any channel of any pixel
  double mean_diff = 0;        // mean |a-b| over every RGB channel of every pixel
  double differing_share = 0;  // share of pixels with any channel differing
  double rmse = 0;             // over every RGB channel
  double psnr = 0;             // 20 log10(255 / rmse); infinite for identical pictures
};

// Throws std::invalid_argument when the sizes differ.
Diff compare(const Image& a, const Image& b);

// The one heat-map scale of every picture ffcompat writes: black where equal, pure blue at 1 step,
// red at 4, yellow at 16 steps or more, spaced by log2 of the steps in between (so 1, 2, 4, 8 and
// 16 are evenly spaced: a 1-step rounding difference and a 100-step error both read at a glance).
// `steps` is the largest channel difference of a pixel; image::heat_legend draws this scale.
std::array<uint8_t, 3> heat_colour(double steps);

// A heat map of the largest channel difference per pixel, coloured by heat_colour.
Image heat_map(const Image& a, const Image& b);

}  // namespace ffc::image
