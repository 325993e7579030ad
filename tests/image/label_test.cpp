// Labels and legends on contact sheets: text lands where asked and nowhere else, the cells are
// copied untouched beside their labels, and the legend shows heat_map's own colours.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>

#include "image/compare.h"
#include "image/label.h"

namespace ffc::image {
namespace {

const uint8_t kWhite[3] = {255, 255, 255};

// The bounding box of the pixels that are not black.
struct Box {
  int x0 = 1 << 30, y0 = 1 << 30, x1 = -1, y1 = -1;
};
Box ink(const Image& img) {
  Box b;
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x)
      if (img.at(x, y)[0] || img.at(x, y)[1] || img.at(x, y)[2])
        b.x0 = std::min(b.x0, x), b.y0 = std::min(b.y0, y), b.x1 = std::max(b.x1, x), b.y1 = std::max(b.y1, y);
  return b;
}

TEST(Label, TextIsDrawnInsideItsMeasuredBoxAtItsScale) {
  Image img(100, 60);
  draw_text(img, 10, 20, "H1", 2, kWhite);
  const Box b = ink(img);
  ASSERT_GE(b.x1, 0) << "nothing drawn";
  EXPECT_GE(b.x0, 10);
  EXPECT_GE(b.y0, 20);
  EXPECT_LT(b.x1, 10 + text_width("H1", 2));
  EXPECT_LT(b.y1, 20 + text_height("H1", 2));
  // Twice the scale, twice the width; two lines are taller than one.
  EXPECT_EQ(text_width("H1", 2), 2 * text_width("H1", 1));
  EXPECT_GT(text_height("a\nb", 1), text_height("a", 1));
}

TEST(Label, TextIsClippedAndOddCharactersAreSafe) {
  Image img(8, 8);
  draw_text(img, 4, 4, "WWWW\t\x7f\xff", 3, kWhite);  // runs off the image; tab and 8-bit bytes
  EXPECT_EQ(img.width, 8);
}

TEST(Label, SheetKeepsEachCellIntactAndLabelsOutsideThem) {
  Image red(40, 30), blue(40, 30);
  for (int y = 0; y < 30; ++y)
    for (int x = 0; x < 40; ++x) red.at(x, y)[0] = 200, blue.at(x, y)[2] = 200;
  Sheet s;
  s.title = "T";
  s.columns = {"a", "b"};
  s.rows = {"row"};
  s.cells = {{&red, &blue}};
  const Image out = labelled_grid(s);
  // The red cell's top left corner is somewhere right of the row label and below the column
  // labels: find it, then both cells must be there pixel for pixel, 8 pixels apart.
  int cx = -1, cy = -1;
  for (int y = 0; y < out.height && cx < 0; ++y)
    for (int x = 0; x < out.width; ++x)
      if (out.at(x, y)[0] == 200 && out.at(x, y)[2] == 0) {
        cx = x, cy = y;
        break;
      }
  ASSERT_GE(cx, text_width("row", 1) + 8);  // 40-pixel cells: labels at the font's own size
  ASSERT_GT(cy, text_height("T", 1) + text_height("a", 1));
  for (int y = 0; y < 30; ++y)
    for (int x = 0; x < 40; ++x) {
      ASSERT_EQ(out.at(cx + x, cy + y)[0], 200);
      ASSERT_EQ(out.at(cx + 48 + x, cy + y)[2], 200);
    }
  EXPECT_EQ(out.width, cx + 40 + 8 + 40 + 8);
}

TEST(Label, LegendShowsTheHeatMapsOwnColours) {
  const Image legend = heat_legend(600);
  EXPECT_EQ(legend.width, 600);
  bool blue = false, red = false, yellow = false, black = false;
  for (int y = 0; y < legend.height; ++y)
    for (int x = 0; x < legend.width; ++x) {
      const uint8_t* p = legend.at(x, y);
      const std::array<uint8_t, 3> c = {p[0], p[1], p[2]};
      blue |= c == heat_colour(1), yellow |= c == heat_colour(16);
      red |= c[0] == 255 && c[1] == 0 && c[2] <= 3;  // about 4 steps (the bar is continuous)
      black |= c == heat_colour(0);
    }
  EXPECT_TRUE(blue && red && yellow && black);
}

}  // namespace
}  // namespace ffc::image
