#include "image/compare.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace ffc::image {

static void check_sizes(const Image& a, const Image& b) {
  if (a.width != b.width || a.height != b.height)
    throw std::invalid_argument("images differ in size: " + std::to_string(a.width) + "x" +
                                std::to_string(a.height) + " and " + std::to_string(b.width) + "x" +
                                std::to_string(b.height));
}

Diff compare(const Image& a, const Image& b) {
  check_sizes(a, b);
  Diff d;
  const size_t pixels = size_t(a.width) * a.height;
  if (pixels == 0) return d;
  double sum = 0, sum_sq = 0;
  size_t differing = 0;
  for (size_t p = 0; p < pixels; ++p) {
    int worst = 0;
    for (int c = 0; c < 3; ++c) {
      const int e = std::abs(int(a.rgba[p * 4 + c]) - int(b.rgba[p * 4 + c]));
      worst = std::max(worst, e);
      sum += e;
      sum_sq += double(e) * e;
    }
    d.max_diff = std::max(d.max_diff, worst);
    differing += worst > 0;
  }
  d.mean_diff = sum / (3.0 * pixels);
  d.differing_share = double(differing) / pixels;
  d.rmse = std::sqrt(sum_sq / (3.0 * pixels));
  d.psnr = d.rmse > 0 ? 20 * std::log10(255.0 / d.rmse) : std::numeric_limits<double>::infinity();
  return d;
}

std::array<uint8_t, 3> heat_colour(double steps) {
  if (steps <= 0) return {0, 0, 0};
  // t in [0, 1]: 0 at 1 step (blue), 0.5 at 4 (red), 1 at 16 or more (yellow).
  const double t = std::clamp(std::log2(steps) / 4, 0.0, 1.0);
  if (t < 0.5) {
    const double s = t / 0.5;
    return {uint8_t(255 * s + 0.5), 0, uint8_t(255 * (1 - s) + 0.5)};
  }
  const double s = (t - 0.5) / 0.5;
  return {255, uint8_t(255 * s + 0.5), 0};
}

Image heat_map(const Image& a, const Image& b) {
  check_sizes(a, b);
  Image out(a.width, a.height);
  for (int y = 0; y < a.height; ++y)
    for (int x = 0; x < a.width; ++x) {
      int worst = 0;
      for (int c = 0; c < 3; ++c) worst = std::max(worst, std::abs(int(a.at(x, y)[c]) - int(b.at(x, y)[c])));
      const std::array<uint8_t, 3> rgb = heat_colour(worst);
      uint8_t* o = out.at(x, y);
      o[0] = rgb[0], o[1] = rgb[1], o[2] = rgb[2], o[3] = 255;
    }
  return out;
}

}  // namespace ffc::image
