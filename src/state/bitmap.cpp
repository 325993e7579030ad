// glBitmap (GL 2.1 section 3.7): a rectangle of bits unpacked by the GL_UNPACK_* state, each set
// bit a fragment of the current raster colour and depth through the per-fragment operations;
// then the raster position moves by (xmove, ymove). GLUT's bitmap fonts draw text this way.
#include <algorithm>
#include <cmath>

#include "state/context.h"

namespace ffc::state {

namespace {
constexpr int kCacheWidth = 512, kCacheHeight = 32;  // st_cb_bitmap.c's BITMAP_CACHE_WIDTH, _HEIGHT

bool same_ops(const raster::State::Ops& a, const raster::State::Ops& b) {
  return a.scissor == b.scissor && a.scissor_x0 == b.scissor_x0 && a.scissor_y0 == b.scissor_y0 &&
         a.scissor_x1 == b.scissor_x1 && a.scissor_y1 == b.scissor_y1 && a.alpha_test == b.alpha_test &&
         a.alpha_func == b.alpha_func && a.alpha_ref == b.alpha_ref && a.depth_write == b.depth_write &&
         a.blend == b.blend && a.src_rgb == b.src_rgb && a.dst_rgb == b.dst_rgb && a.src_alpha == b.src_alpha &&
         a.dst_alpha == b.dst_alpha && a.eq_rgb == b.eq_rgb && a.eq_alpha == b.eq_alpha &&
         std::equal(a.blend_color, a.blend_color + 4, b.blend_color) && a.color_mask == b.color_mask;
}
}  // namespace

// Where in Mesa's bitmap cache a w x h bitmap at (x0, y0) goes: the row of flags for its first
// row (kCacheWidth apart), or null when it is drawn on its own (too large for the cache). A run
// goes on while nothing else drew, the raster colour, depth and fragment state are the same and
// the bitmap fits in the cache's window (placed at the run's first bitmap, its rows half above);
// else a new run starts (Mesa flushes the cache and starts it again).
uint8_t* Context::bitmap_cache(int x0, int y0, int w, int h, const raster::State& rs) {
  BitmapRun& r = bitmap_run_;
  if (w > kCacheWidth || h > kCacheHeight) return r.active = false, nullptr;
  const bool fits = x0 >= r.xpos && x0 + w <= r.xpos + kCacheWidth && y0 >= r.ypos && y0 + h <= r.ypos + kCacheHeight;
  if (!(r.active && fits && r.writes == fb_.writes && r.color == raster_pos_.color && r.z == raster_pos_.window.z &&
        same_ops(r.ops, rs.ops) && r.depth_test == rs.depth_test && r.depth_func == rs.depth_func)) {
    r.active = true;
    r.color = raster_pos_.color, r.z = raster_pos_.window.z, r.ops = rs.ops;
    r.depth_test = rs.depth_test, r.depth_func = rs.depth_func;
    r.xpos = x0, r.ypos = y0 - kCacheHeight / 2;
    r.drawn.assign(size_t(kCacheWidth) * kCacheHeight, 0);
    if (y0 + h > r.ypos + kCacheHeight) return r.active = false, nullptr;  // taller than half the cache
  }
  return &r.drawn[size_t(y0 - r.ypos) * kCacheWidth + size_t(x0 - r.xpos)];
}

// Feedback of glBitmap and glDrawPixels (GL 2.1 section 5.3): the token, then the raster position
// as a vertex, its texture coordinates the texture matrix's last column (the current ones are
// (0, 0, 0, 1)).
void Context::feedback_raster_position(GLenum token) {
  note_texgen_in_feedback();
  feedback_put(token);
  const glm::dvec4& p = raster_pos_.window;
  feedback_put(p.x), feedback_put(p.y);
  if (feedback_type_ != GL_2D) feedback_put(p.z);
  if (feedback_type_ == GL_4D_COLOR_TEXTURE) feedback_put(p.w);
  if (feedback_type_ != GL_2D && feedback_type_ != GL_3D)
    for (int k = 0; k < 4; ++k) feedback_put(raster_pos_.color[k]);
  if (feedback_type_ == GL_3D_COLOR_TEXTURE || feedback_type_ == GL_4D_COLOR_TEXTURE)
    for (int k = 0; k < 4; ++k) feedback_put(texture_f_.back().values()[3][k]);
}

// How the bits of a w-wide bitmap lie in memory: rows of GL_UNPACK_ROW_LENGTH bits (w when 0), each
// a whole number of GL_UNPACK_ALIGNMENT bytes; GL_UNPACK_SKIP_ROWS and _SKIP_PIXELS skip rows and
// bits; bits read from the most significant one unless GL_UNPACK_LSB_FIRST. Packed: whole bytes a
// row, nothing skipped, the most significant bit first.
Context::BitmapLayout Context::bitmap_layout(GLsizei w, bool packed) const {
  if (packed) return {(size_t(w) + 7) / 8, 0, 0, false};
  auto store = [&](GLenum p) {
    const auto it = pixel_store_.find(p);
    return it == pixel_store_.end() ? 0 : it->second;
  };
  const size_t row_bits = store(GL_UNPACK_ROW_LENGTH) > 0 ? size_t(store(GL_UNPACK_ROW_LENGTH)) : size_t(w);
  const size_t align = size_t(unpack_alignment_);
  return {((row_bits + 7) / 8 + align - 1) / align * align, size_t(store(GL_UNPACK_SKIP_ROWS)),
          size_t(store(GL_UNPACK_SKIP_PIXELS)), store(GL_UNPACK_LSB_FIRST) != 0};
}

bool Context::BitmapLayout::bit(const GLubyte* bits, GLsizei i, GLsizei j) const {
  const GLubyte* r = bits + (skip_rows + size_t(j)) * row;
  const size_t b = skip_bits + size_t(i);
  return lsb_first ? (r[b / 8] >> (b % 8)) & 1 : (r[b / 8] >> (7 - b % 8)) & 1;
}

std::vector<GLubyte> Context::pack_bitmap(GLsizei w, GLsizei h, const GLubyte* bits) const {
  if (!bits || w <= 0 || h <= 0) return {};
  const BitmapLayout in = bitmap_layout(w, false), out = bitmap_layout(w, true);
  std::vector<GLubyte> packed(out.row * size_t(h), 0);
  for (GLsizei j = 0; j < h; ++j)
    for (GLsizei i = 0; i < w; ++i)
      if (in.bit(bits, i, j)) packed[size_t(j) * out.row + size_t(i) / 8] |= GLubyte(0x80u >> (i % 8));
  return packed;
}

void Context::Bitmap(GLsizei w, GLsizei h, float xorig, float yorig, float xmove, float ymove, const GLubyte* bits,
                     bool packed) {
  if (!outside_begin_end()) return;
  const SinkPixels through_sink(*this);  // draw_sink.cpp: soft draws into the sink's picture
  // Mesa's FLUSH_VERTICES (outside_begin_end) flushes stored vertices only where a flush was asked
  // for: a pending glMaterial stays (measured; repro material_pending_through_pixels.txt).
  validate_matrices();
  if (w < 0 || h < 0) return error(GL_INVALID_VALUE);
  if (!raster_pos_.valid) return;  // no fragments, and the position stays (invalid)
  if (render_mode_ == GL_FEEDBACK) {
    feedback_raster_position(GL_BITMAP_TOKEN);
  } else if (render_mode_ == GL_RENDER && bits && w > 0 && h > 0) {
    flush_clear();
    // Mesa's drawpix.c: the first pixel's lower-left corner at floor(raster position - origin),
    // with 1e-4 added in float so that a position a rounding below a whole number is not moved a
    // pixel down.
    const int x0 = int(std::floor(float(raster_pos_.window.x) + 0.0001f - xorig));
    const int y0 = int(std::floor(float(raster_pos_.window.y) + 0.0001f - yorig));
    const BitmapLayout layout = bitmap_layout(w, packed);
    const raster::State rs = raster_state();
    uint8_t* cached = bitmap_cache(x0, y0, w, h, rs);  // null: drawn on its own
    for (GLsizei j = 0; j < h; ++j) {
      for (GLsizei i = 0; i < w; ++i) {
        if (!layout.bit(bits, i, j)) continue;
        if (cached) {
          uint8_t& done = cached[size_t(j) * kCacheWidth + size_t(i)];
          if (done) continue;
          done = 1;
        }
        raster::draw_fragment(fb_, x0 + i, y0 + j, raster_pos_.window.z, raster_pos_.color, rs);
      }
    }
    bitmap_run_.writes = fb_.writes;
  }
  raster_pos_.window.x += xmove;  // in float, as Mesa keeps the position
  raster_pos_.window.y += ymove;
  raster_pos_.window.x = float(raster_pos_.window.x), raster_pos_.window.y = float(raster_pos_.window.y);
}

}  // namespace ffc::state
