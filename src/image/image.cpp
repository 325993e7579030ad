#include "image/image.h"

#include <png.h>

#include <algorithm>
#include <cstring>
#include <stdexcept>

namespace ffc::image {

void write_png(const std::string& path, const Image& img) {
  png_image p{};
  p.version = PNG_IMAGE_VERSION;
  p.width = img.width;
  p.height = img.height;
  p.format = PNG_FORMAT_RGBA;
  if (!png_image_write_to_file(&p, path.c_str(), 0, img.rgba.data(), 0, nullptr))
    throw std::runtime_error(path + ": cannot write PNG: " + p.message);
}

Image read_png(const std::string& path) {
  png_image p{};
  p.version = PNG_IMAGE_VERSION;
  if (!png_image_begin_read_from_file(&p, path.c_str()))
    throw std::runtime_error(path + ": cannot read PNG: " + p.message);
  p.format = PNG_FORMAT_RGBA;
  Image img(int(p.width), int(p.height));
  if (!png_image_finish_read(&p, nullptr, img.rgba.data(), 0, nullptr))
    throw std::runtime_error(path + ": cannot decode PNG: " + p.message);
  return img;
}

Image grid(const std::vector<std::vector<const Image*>>& rows, int gap, uint8_t background) {
  std::vector<int> col_w, row_h(rows.size(), 0);
  for (size_t r = 0; r < rows.size(); ++r)
    for (size_t c = 0; c < rows[r].size(); ++c) {
      if (col_w.size() <= c) col_w.push_back(0);
      if (!rows[r][c]) continue;
      col_w[c] = std::max(col_w[c], rows[r][c]->width);
      row_h[r] = std::max(row_h[r], rows[r][c]->height);
    }
  int w = 0, h = 0;
  for (int cw : col_w) w += cw + gap;
  for (int rh : row_h) h += rh + gap;
  Image out(std::max(0, w - gap), std::max(0, h - gap), background);
  for (size_t i = 3; i < out.rgba.size(); i += 4) out.rgba[i] = 255;
  int y0 = 0;
  for (size_t r = 0; r < rows.size(); ++r) {
    int x0 = 0;
    for (size_t c = 0; c < rows[r].size(); ++c) {
      if (const Image* im = rows[r][c])
        for (int y = 0; y < im->height; ++y)
          std::memcpy(out.at(x0, y0 + y), im->at(0, y), size_t(im->width) * 4);
      x0 += col_w[c] + gap;
    }
    y0 += row_h[r] + gap;
  }
  return out;
}

}  // namespace ffc::image
