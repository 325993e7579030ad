// Frames as PNG files: what a window showed, RGB (a window on a screen has no transparency).
#include <png.h>

#include <cstdio>
#include <vector>

#include "glut_state.h"

namespace ffc::glut {

void write_frame(const std::string& out, int id, int index, int width, int height, const unsigned char* rgba) {
  char name[64];
  if (id == 1) std::snprintf(name, sizeof name, "/frame-%03d.png", index);
  else std::snprintf(name, sizeof name, "/window-%d-frame-%03d.png", id, index);
  const std::string path = out + name;
  std::vector<unsigned char> rgb(size_t(width) * height * 3);
  for (size_t i = 0, n = size_t(width) * height; i < n; ++i)
    for (int c = 0; c < 3; ++c) rgb[i * 3 + c] = rgba[i * 4 + c];
  png_image img{};
  img.version = PNG_IMAGE_VERSION;
  img.width = unsigned(width), img.height = unsigned(height);
  img.format = PNG_FORMAT_RGB;
  if (!png_image_write_to_file(&img, path.c_str(), 0, rgb.data(), 0, nullptr))
    error("cannot write frame %s: %s", path.c_str(), img.message);
}

}  // namespace ffc::glut
