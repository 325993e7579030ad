// Shared by the scene tests: where the shipped scenes are, temporary files, picture checks.
#pragma once
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "../temp_dir.h"
#include "image/image.h"

namespace ffc::scene_test {

namespace fs = std::filesystem;

// The repository's scenes/ folder, found from this file's own path.
inline fs::path scenes_dir() { return fs::path(__FILE__).parent_path().parent_path().parent_path() / "scenes"; }

// This test binary run's own folder (tests/temp_dir.h).
inline fs::path temp_dir() { return test::temp_path(""); }

inline fs::path write_file(const std::string& name, const std::string& text) {
  const fs::path p = temp_dir() / name;
  fs::create_directories(p.parent_path());
  std::ofstream(p, std::ios::binary) << text;
  return p;
}

// Share of pixels whose brightest RGB channel exceeds `level`.
inline double lit_share(const image::Image& img, int level = 24) {
  size_t n = 0;
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x) {
      const uint8_t* p = img.at(x, y);
      if (p[0] > level || p[1] > level || p[2] > level) ++n;
    }
  return double(n) / (double(img.width) * img.height);
}

inline bool identical(const image::Image& a, const image::Image& b) {
  return a.width == b.width && a.height == b.height && a.rgba == b.rgba;
}

}  // namespace ffc::scene_test
