// pixel_dump A.png [B.png ...]: writes A.png.rgba next to each picture: "WxH\n" and the RGBA8
// pixels, top row first. The pictures test hashes these rather than the PNG files, so that a
// change of PNG encoder settings (compression level, filters, metadata) does not read as a
// change of picture: only the pixels and the size count.
#include <cstdio>
#include <exception>
#include <fstream>
#include <string>

#include "image/image.h"

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: pixel_dump A.png [B.png ...]\n");
    return 1;
  }
  try {
    for (int i = 1; i < argc; ++i) {
      const ffc::image::Image img = ffc::image::read_png(argv[i]);
      std::ofstream out(std::string(argv[i]) + ".rgba", std::ios::binary);
      out << img.width << 'x' << img.height << '\n';
      out.write(reinterpret_cast<const char*>(img.rgba.data()), std::streamsize(img.rgba.size()));
      if (!out) throw std::runtime_error(std::string("cannot write ") + argv[i] + ".rgba");
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "pixel_dump: %s\n", e.what());
    return 1;
  }
  return 0;
}
