// Text on pictures: the labels and legend of contact sheets, so a sheet says what each row and
// column is and what the heat map's colours mean without a README beside it.
#pragma once
#include <string>
#include <vector>

#include "image/image.h"

namespace ffc::image {

// Draws `text` (printable ASCII, '\n' for new lines) with its top left corner at (x, y), each font
// pixel `scale` x `scale` pixels, in colour rgb. Clipped to the image. The glyphs are
// stb_easy_font's (Debian libstb-dev): segments, about 6 x 7 font pixels a character.
void draw_text(Image& img, int x, int y, const std::string& text, int scale, const uint8_t rgb[3]);
// The size draw_text covers.
int text_width(const std::string& text, int scale);
int text_height(const std::string& text, int scale);

// The heat map's legend (image::heat_map): a bar from 1 to 16 steps with ticks at 1, 2, 4, 8 and
// 16+, black for 0 before it, and a line saying what the colours measure; `width` wide, its text
// at `scale` (smaller if the line would not fit).
Image heat_legend(int width, int scale = 2);

// A contact sheet: the cells in rows (null leaves a cell empty), a title over them, a label over
// each column and left of each row, and optionally the heat map's legend under them.
struct Sheet {
  std::string title;
  std::vector<std::string> columns, rows;
  std::vector<std::vector<const Image*>> cells;
  bool heat_legend = false;
};
Image labelled_grid(const Sheet& sheet);

}  // namespace ffc::image
