#include "image/label.h"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "image/compare.h"

// stb_easy_font is a header of static functions, some of which we do not call.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
#include <stb/stb_easy_font.h>
#pragma GCC diagnostic pop

namespace ffc::image {

namespace {

constexpr uint8_t kBackground = 64;  // the sheet's grey, as image::grid's default
constexpr uint8_t kInk[3] = {235, 235, 235};
constexpr int kGap = 8;

// stb_easy_font takes a mutable char* (it does not write to it) and has glyphs for printable
// ASCII only: anything else would index outside its table, so it becomes '?'.
std::vector<char> c_text(const std::string& text) {
  std::vector<char> s;
  for (char c : text) s.push_back(c == '\n' || (c >= 32 && c < 127) ? c : '?');
  s.push_back('\0');
  return s;
}

void fill(Image& img, int x0, int y0, int x1, int y1, const uint8_t rgb[3]) {
  x0 = std::max(x0, 0), y0 = std::max(y0, 0), x1 = std::min(x1, img.width), y1 = std::min(y1, img.height);
  for (int y = y0; y < y1; ++y)
    for (int x = x0; x < x1; ++x) {
      uint8_t* p = img.at(x, y);
      p[0] = rgb[0], p[1] = rgb[1], p[2] = rgb[2], p[3] = 255;
    }
}

void blit(Image& dst, const Image& src, int x0, int y0) {
  for (int y = 0; y < src.height; ++y)
    std::memcpy(dst.at(x0, y0 + y), src.at(0, y), size_t(src.width) * 4);
}

}  // namespace

void draw_text(Image& img, int x, int y, const std::string& text, int scale, const uint8_t rgb[3]) {
  // Each quad: four vertices of 16 bytes (x, y, z as float, then an RGBA colour), axis-aligned
  // rectangles in font pixels: filled as rectangles, no rasterizer needed.
  std::vector<char> s = c_text(text);
  std::vector<float> buffer(text.size() * 270 + 64);  // stb's bound: about 270 bytes a character
  const int quads = stb_easy_font_print(0, 0, s.data(), nullptr, buffer.data(), int(buffer.size() * sizeof(float)));
  for (int q = 0; q < quads; ++q) {
    const float* v = &buffer[size_t(q) * 16];  // vertex 0 at v[0..1], vertex 2 at v[8..9]
    fill(img, x + int(v[0] * scale), y + int(v[1] * scale), x + int(v[8] * scale), y + int(v[9] * scale), rgb);
  }
}

int text_width(const std::string& text, int scale) {
  std::vector<char> s = c_text(text);
  return stb_easy_font_width(s.data()) * scale;
}

int text_height(const std::string& text, int scale) {
  std::vector<char> s = c_text(text);
  return stb_easy_font_height(s.data()) * scale;
}

Image heat_legend(int width, int scale) {
  const std::string what = "difference per pixel: largest RGB channel, in 8-bit steps (same scale on every picture)";
  while (scale > 1 && width < text_width(what, scale) + 2 * kGap) --scale;
  const int bar_h = 12 * scale, text_h = text_height("0", scale);
  Image out(width, kGap + text_h + kGap + bar_h + 4 + text_h + kGap, kBackground);
  for (size_t i = 3; i < out.rgba.size(); i += 4) out.rgba[i] = 255;
  draw_text(out, kGap, kGap, what, scale, kInk);
  // "equal" (black) then the bar from 1 to 16 steps, spaced as heat_map spaces them (log2).
  const int y0 = kGap + text_h + kGap, x_equal = kGap, equal_w = std::max(40, width / 12);
  const int x0 = x_equal + equal_w + kGap, x1 = width - kGap - text_width("16+", scale);
  const uint8_t black[3] = {0, 0, 0};
  fill(out, x_equal, y0, x_equal + equal_w, y0 + bar_h, black);
  draw_text(out, x_equal, y0 + bar_h + 4, "0", scale, kInk);
  for (int x = x0; x < x1; ++x) {
    const double steps = std::exp2(4.0 * (x - x0) / std::max(1, x1 - 1 - x0));  // 1 .. 16
    fill(out, x, y0, x + 1, y0 + bar_h, heat_colour(steps).data());
  }
  for (int k = 0; k <= 4; ++k) {
    const int x = x0 + (x1 - 1 - x0) * k / 4;
    const std::string tick = k == 4 ? "16+" : std::to_string(1 << k);
    fill(out, x, y0 + bar_h, x + 1, y0 + bar_h + 3, kInk);
    draw_text(out, std::min(x, width - text_width(tick, scale)), y0 + bar_h + 4, tick, scale, kInk);
  }
  return out;
}

Image labelled_grid(const Sheet& sheet) {
  const Image cells = grid(sheet.cells, kGap, kBackground);
  // Labels grow with the cells (a font pixel per 200 picture pixels, 1 to 3) while they fit.
  int col_w = 0;
  for (const auto& row : sheet.cells)
    for (const Image* im : row)
      if (im) col_w = std::max(col_w, im->width);
  int scale = std::clamp(col_w / 200, 1, 3);
  for (const std::string& c : sheet.columns)
    while (scale > 1 && text_width(c, scale) > col_w) --scale;
  int left = 0;
  for (const std::string& r : sheet.rows) left = std::max(left, text_width(r, scale));
  left += left ? 2 * kGap : kGap;
  const int title_h = sheet.title.empty() ? 0 : text_height(sheet.title, scale) + kGap;
  const int head_h = text_height("X", scale) + kGap;
  const Image legend = sheet.heat_legend ? heat_legend(left + cells.width + kGap, scale) : Image();
  Image out(left + cells.width + kGap, kGap + title_h + head_h + cells.height + kGap + legend.height, kBackground);
  for (size_t i = 3; i < out.rgba.size(); i += 4) out.rgba[i] = 255;
  if (!sheet.title.empty()) draw_text(out, kGap, kGap, sheet.title, scale, kInk);
  const int top = kGap + title_h + head_h;
  blit(out, cells, left, top);
  // Column labels centred over their cells; row labels at the top of theirs.
  size_t columns = 0;
  for (const auto& row : sheet.cells) columns = std::max(columns, row.size());
  std::vector<int> widths(columns, 0), heights(sheet.cells.size(), 0);
  for (size_t r = 0; r < sheet.cells.size(); ++r)
    for (size_t c = 0; c < sheet.cells[r].size(); ++c)
      if (const Image* im = sheet.cells[r][c])
        widths[c] = std::max(widths[c], im->width), heights[r] = std::max(heights[r], im->height);
  for (size_t c = 0, x = left; c < columns; x += widths[c] + kGap, ++c)
    if (c < sheet.columns.size())
      draw_text(out, int(x) + (widths[c] - text_width(sheet.columns[c], scale)) / 2, top - head_h,
                sheet.columns[c], scale, kInk);
  for (size_t r = 0, y = top; r < sheet.cells.size(); y += heights[r] + kGap, ++r)
    if (r < sheet.rows.size()) draw_text(out, kGap, int(y) + kGap, sheet.rows[r], scale, kInk);
  if (sheet.heat_legend) blit(out, legend, 0, top + cells.height + kGap);
  return out;
}

}  // namespace ffc::image
