#include "../temp_dir.h"
#include "image/compare.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>

namespace ffc::image {
namespace {

Image solid(int w, int h, uint8_t r, uint8_t g, uint8_t b) {
  Image img(w, h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      uint8_t* p = img.at(x, y);
      p[0] = r, p[1] = g, p[2] = b, p[3] = 255;
    }
  return img;
}

TEST(Compare, IdenticalPicturesHaveNoDifferenceAndInfinitePsnr) {
  const Image a = solid(4, 3, 10, 20, 30);
  const Diff d = compare(a, a);
  EXPECT_EQ(d.max_diff, 0);
  EXPECT_EQ(d.mean_diff, 0);
  EXPECT_EQ(d.differing_share, 0);
  EXPECT_TRUE(std::isinf(d.psnr));
}

TEST(Compare, OneChannelOfOnePixel) {
  const Image a = solid(10, 10, 0, 0, 0);
  Image b = a;
  b.at(3, 7)[1] = 30;
  const Diff d = compare(a, b);
  EXPECT_EQ(d.max_diff, 30);
  EXPECT_DOUBLE_EQ(d.mean_diff, 30.0 / 300);
  EXPECT_DOUBLE_EQ(d.differing_share, 0.01);
  EXPECT_DOUBLE_EQ(d.rmse, std::sqrt(900.0 / 300));
  EXPECT_NEAR(d.psnr, 20 * std::log10(255 / std::sqrt(3.0)), 1e-12);
}

TEST(Compare, AlphaIsIgnored) {
  const Image a = solid(2, 2, 1, 2, 3);
  Image b = a;
  b.at(0, 0)[3] = 0;
  EXPECT_EQ(compare(a, b).max_diff, 0);
}

TEST(Compare, SizesMustMatch) {
  EXPECT_THROW(compare(solid(2, 2, 0, 0, 0), solid(2, 3, 0, 0, 0)), std::invalid_argument);
}

TEST(HeatMap, OneScaleBlackEqualPureBlueAtOneRedAtFourYellowFromSixteen) {
  const Image a = solid(6, 1, 100, 100, 100);
  Image b = a;
  b.at(1, 0)[0] = 101;  // 1 step
  b.at(2, 0)[1] = 102;  // 2 steps: halfway from blue to red on the log2 scale
  b.at(3, 0)[2] = 96;   // 4 steps
  b.at(4, 0)[0] = 116;  // 16 steps
  b.at(5, 0)[2] = 200;  // 100 steps: as 16
  const Image h = heat_map(a, b);
  auto rgb = [&](int x) { return std::array<int, 3>{h.at(x, 0)[0], h.at(x, 0)[1], h.at(x, 0)[2]}; };
  EXPECT_EQ(rgb(0), (std::array<int, 3>{0, 0, 0}));
  EXPECT_EQ(rgb(1), (std::array<int, 3>{0, 0, 255}));  // blue, not purple
  EXPECT_EQ(rgb(2), (std::array<int, 3>{128, 0, 128}));
  EXPECT_EQ(rgb(3), (std::array<int, 3>{255, 0, 0}));
  EXPECT_EQ(rgb(4), (std::array<int, 3>{255, 255, 0}));
  EXPECT_EQ(rgb(5), (std::array<int, 3>{255, 255, 0}));
  EXPECT_EQ(h.at(3, 0)[3], 255);
  // 8 steps: halfway from red to yellow.
  EXPECT_EQ(heat_colour(8), (std::array<uint8_t, 3>{255, 128, 0}));
}

TEST(Png, RoundTripsExactly) {
  Image a(5, 4);
  for (size_t i = 0; i < a.rgba.size(); ++i) a.rgba[i] = uint8_t(i * 37);
  const std::string path = test::temp_path("roundtrip.png").string();
  write_png(path, a);
  const Image b = read_png(path);
  EXPECT_EQ(b.width, 5);
  EXPECT_EQ(b.height, 4);
  EXPECT_EQ(a.rgba, b.rgba);
  std::remove(path.c_str());
}

TEST(Png, BadFilesNameThemselves) {
  const std::string path = test::temp_path("not_a.png").string();
  std::ofstream(path) << "this is not a PNG";
  try {
    read_png(path);
    FAIL() << "no exception";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
  }
  EXPECT_THROW(read_png("/nonexistent/dir/x.png"), std::runtime_error);
  std::remove(path.c_str());
}

TEST(Grid, PlacesCellsWithGaps) {
  const Image r = solid(2, 2, 255, 0, 0), g = solid(3, 1, 0, 255, 0);
  const Image out = grid({{&r, &g}, {&g, nullptr}}, 1, 7);
  EXPECT_EQ(out.width, 3 + 1 + 3);  // column widths 3 (max of 2, 3) and 3
  EXPECT_EQ(out.height, 2 + 1 + 1);
  EXPECT_EQ(out.at(0, 0)[0], 255);
  EXPECT_EQ(out.at(4, 0)[1], 255);  // second column starts after width 3 + gap 1
  EXPECT_EQ(out.at(3, 0)[0], 7);    // the gap
  EXPECT_EQ(out.at(0, 3)[1], 255);  // second row
}

}  // namespace
}  // namespace ffc::image
