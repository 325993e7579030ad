// RGBA8 images, top row first, and the PNG files they come from and go to.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

namespace ffc::image {

struct Image {
  int width = 0, height = 0;
  std::vector<uint8_t> rgba;  // width*height*4, top row first
  Image() = default;
  Image(int w, int h, uint8_t fill = 0) : width(w), height(h), rgba(size_t(w) * h * 4, fill) {}
  uint8_t* at(int x, int y) { return &rgba[(size_t(y) * width + x) * 4]; }
  const uint8_t* at(int x, int y) const { return &rgba[(size_t(y) * width + x) * 4]; }
};

// Throw std::runtime_error naming the file on failure.
void write_png(const std::string& path, const Image& img);
Image read_png(const std::string& path);

// Images laid out in rows (each row left to right), separated by `gap` pixels of `background`
// grey. Null entries leave their cell empty.
Image grid(const std::vector<std::vector<const Image*>>& rows, int gap = 8, uint8_t background = 64);

}  // namespace ffc::image
