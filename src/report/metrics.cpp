#include "report/metrics.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <stdexcept>

#include "image/compare.h"

namespace ffc::report {

namespace {
void check_size(const image::Image& picture, const Ideal& ideal) {
  if (picture.width != ideal.image.width || picture.height != ideal.image.height)
    throw std::invalid_argument("picture " + std::to_string(picture.width) + "x" + std::to_string(picture.height) +
                                " against an ideal of " + std::to_string(ideal.image.width) + "x" +
                                std::to_string(ideal.image.height));
}
}  // namespace

ShadingError shading_error(const image::Image& picture, const Ideal& ideal) {
  check_size(picture, ideal);
  ShadingError e;
  double sum = 0, sum_exact = 0;
  size_t either = 0;
  const size_t n = size_t(picture.width) * picture.height;
  for (size_t i = 0; i < n; ++i) {
    const uint8_t* p = &picture.rgba[4 * i];
    const uint8_t* q = &ideal.image.rgba[4 * i];
    const bool a = p[3] != 0, b = ideal.covered[i] != 0;
    if (a || b) ++either;
    if (a != b) {
      ++e.silhouette;
      continue;
    }
    if (!a) continue;
    ++e.both;
    for (int c = 0; c < 3; ++c) {
      const int d = int(p[c]) - int(q[c]);
      sum += double(d) * d;
      e.max_error = std::max(e.max_error, std::abs(d));
      const double x = p[c] - 255 * ideal.exact[i][c];
      sum_exact += x * x;
    }
  }
  if (e.both > 0) {
    e.rmse = std::sqrt(sum / (3.0 * e.both));
    e.rmse_exact = std::sqrt(sum_exact / (3.0 * e.both));
  }
  e.silhouette_share = either > 0 ? double(e.silhouette) / either : 0;
  return e;
}

double rounding_floor(const Ideal& ideal) {
  double sum = 0;
  size_t count = 0;
  for (size_t i = 0; i < ideal.covered.size(); ++i) {
    if (!ideal.covered[i]) continue;
    for (int c = 0; c < 3; ++c) {
      const double x = ideal.image.rgba[4 * i + size_t(c)] - 255 * ideal.exact[i][c];
      sum += x * x;
    }
    ++count;
  }
  return count ? std::sqrt(sum / (3.0 * count)) : 0;
}

image::Image error_map(const image::Image& picture, const Ideal& ideal) {
  check_size(picture, ideal);
  image::Image out = image::heat_map(picture, ideal.image);
  for (int y = 0; y < picture.height; ++y)
    for (int x = 0; x < picture.width; ++x) {
      const size_t i = size_t(y) * picture.width + x;
      const bool a = picture.at(x, y)[3] != 0, b = ideal.covered[i] != 0;
      if (a == b) continue;
      uint8_t* o = out.at(x, y);
      o[0] = a ? 255 : 0, o[1] = a ? 0 : 255, o[2] = 255, o[3] = 255;
    }
  return out;
}

}  // namespace ffc::report
