// Differences between two pictures of the same size, in 8-bit steps over the RGB channels.
#pragma once
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

// A heat map of the largest channel difference per pixel: black where equal, then blue, red and
// yellow as the difference grows; full yellow at `saturate` steps or more.
Image heat_map(const Image& a, const Image& b, int saturate = 16);

}  // namespace ffc::image
