// glRasterPos and glDrawPixels (GL 2.1 sections 2.13 and 3.6.4): the current raster position is
// a vertex through the vertex stage (transformed, lit, clipped as a point), and glDrawPixels
// writes a rectangle of fragments from it, through the depth test, with pixel zoom 1.
//
// Implemented: the colour formats (GL_RGBA, GL_RGB, GL_BGRA, GL_BGR, GL_RED, GL_GREEN, GL_BLUE,
// GL_ALPHA, GL_LUMINANCE, GL_LUMINANCE_ALPHA) with GL_UNSIGNED_BYTE or GL_FLOAT, and the unpack
// alignment, row length and skips. Other valid formats and types (depth, stencil, colour index,
// the integer and packed types) are not: the call records GL_INVALID_OPERATION and says so once
// on stderr; it never draws something else in their place.
#include <cmath>
#include <limits>
#include <cstdio>
#include <cstring>
#include <set>
#include <utility>

#include <glm/gtc/type_ptr.hpp>

#include "raster/span.h"
#include "state/context.h"
#include "state/float_matrix.h"

namespace ffc::state {

void Context::RasterPos(double x, double y, double z, double w) {
  if (!outside_begin_end()) return;
  update_vertex_constants();
  validate_matrices();
  bool zero_normal = false;
  const raster::Vertex v = vertex({x, y, z, w}, normal_, color_, &zero_normal);
  const glm::dvec4& c = v.clip;
  // Clipped as a point against the six planes only, as Mesa does: a NaN coordinate compares false
  // and leaves the position valid (all NaN), w = 0 at the origin is valid, and an invalid position
  // keeps the last valid one (measured; GL 2.1 leaves both undefined).
  raster_pos_.valid = !(c.x > c.w || c.x < -c.w || c.y > c.w || c.y < -c.w || c.z > c.w || c.z < -c.w);
  if (!raster_pos_.valid) return;
  if (std::isnan(c.x) || std::isnan(c.y) || std::isnan(c.z) || std::isnan(c.w)) {
    raster_pos_.window = glm::dvec4(std::numeric_limits<double>::quiet_NaN());
  } else {
    // In float, as the viewport transform's scale and translate (Mesa: no divide by a zero w).
    const float inv = c.w != 0 ? 1.0f / float(c.w) : 1.0f;
    const glm::ivec4 vp = viewport_;
    const float sx = float(vp[2]) * 0.5f, sy = float(vp[3]) * 0.5f;
    const float sz = float((depth_range_.y - depth_range_.x) * 0.5), tz = float((depth_range_.y + depth_range_.x) * 0.5);
    raster_pos_.window = {float(c.x) * inv * sx + (float(vp[0]) + sx), float(c.y) * inv * sy + (float(vp[1]) + sy),
                          float(c.z) * inv * sz + tz, c.w};
  }
  raster_pos_.color = lighting_ ? v.front : color_;  // unlit: the current colour, unclamped (Mesa)
  const glm::dvec4 eye = to_eye(glm::value_ptr(glm::dvec4(x, y, z, w)), w);
  raster_pos_.distance = std::sqrt(eye.x * eye.x + eye.y * eye.y + eye.z * eye.z);
}

namespace {

// Components of a pixel for a colour format, as indices into RGBA; -1 for luminance (R = G = B).
struct Layout {
  int n;
  int channel[4];
};

bool color_layout(GLenum format, Layout& l) {
  switch (format) {
    case GL_RGBA: l = {4, {0, 1, 2, 3}}; return true;
    case GL_RGB: l = {3, {0, 1, 2, 0}}; return true;
    case GL_BGRA: l = {4, {2, 1, 0, 3}}; return true;
    case GL_BGR: l = {3, {2, 1, 0, 0}}; return true;
    case GL_RED: l = {1, {0}}; return true;
    case GL_GREEN: l = {1, {1}}; return true;
    case GL_BLUE: l = {1, {2}}; return true;
    case GL_ALPHA: l = {1, {3}}; return true;
    case GL_LUMINANCE: l = {1, {-1}}; return true;
    case GL_LUMINANCE_ALPHA: l = {2, {-1, 3}}; return true;
    default: return false;
  }
}

bool known_format(GLenum f) {
  Layout l;
  return color_layout(f, l) || f == GL_COLOR_INDEX || f == GL_STENCIL_INDEX || f == GL_DEPTH_COMPONENT;
}

bool known_type(GLenum t) {
  switch (t) {
    case GL_UNSIGNED_BYTE: case GL_BYTE: case GL_UNSIGNED_SHORT: case GL_SHORT: case GL_UNSIGNED_INT: case GL_INT:
    case GL_FLOAT: case GL_BITMAP: case GL_UNSIGNED_BYTE_3_3_2: case GL_UNSIGNED_BYTE_2_3_3_REV:
    case GL_UNSIGNED_SHORT_5_6_5: case GL_UNSIGNED_SHORT_5_6_5_REV: case GL_UNSIGNED_SHORT_4_4_4_4:
    case GL_UNSIGNED_SHORT_4_4_4_4_REV: case GL_UNSIGNED_SHORT_5_5_5_1: case GL_UNSIGNED_SHORT_1_5_5_5_REV:
    case GL_UNSIGNED_INT_8_8_8_8: case GL_UNSIGNED_INT_8_8_8_8_REV: case GL_UNSIGNED_INT_10_10_10_2:
    case GL_UNSIGNED_INT_2_10_10_10_REV:
      return true;
    default: return false;
  }
}

}  // namespace

void Context::DrawPixels(GLsizei w, GLsizei h, GLenum format, GLenum type, const void* pixels) {
  if (!outside_begin_end()) return;
  validate_matrices();
  if (w < 0 || h < 0) return error(GL_INVALID_VALUE);
  if (!known_format(format) || !known_type(type)) return error(GL_INVALID_ENUM);
  Layout layout;
  if (!color_layout(format, layout) || (type != GL_UNSIGNED_BYTE && type != GL_FLOAT)) {
    static std::set<std::pair<GLenum, GLenum>> said;
    if (said.insert({format, type}).second)
      std::fprintf(stderr, "ffcompat: glDrawPixels with format 0x%04X and type 0x%04X is not implemented "
                           "(GL_INVALID_OPERATION)\n", format, type);
    return error(GL_INVALID_OPERATION);
  }
  const glm::dvec4& rp = raster_pos_.window;
  if (!raster_pos_.valid || render_mode_ != GL_RENDER || !pixels) return;  // no fragments
  if (!(std::abs(rp.x) < 1e9 && std::abs(rp.y) < 1e9)) return;            // NaN or far away: none we can place
  flush_clear();
  // Unpacking (GL 2.1 section 3.6.4): rows of GL_UNPACK_ROW_LENGTH pixels (w when 0), each
  // starting at a multiple of GL_UNPACK_ALIGNMENT, after the skipped rows and pixels.
  auto store = [&](GLenum p) {
    const auto it = pixel_store_.find(p);
    return it == pixel_store_.end() ? 0 : it->second;
  };
  const size_t size = type == GL_FLOAT ? 4 : 1, pixel = size * size_t(layout.n);
  const size_t row_pixels = store(GL_UNPACK_ROW_LENGTH) > 0 ? size_t(store(GL_UNPACK_ROW_LENGTH)) : size_t(w);
  const size_t align = size_t(unpack_alignment_);
  const size_t row = size >= align ? row_pixels * pixel : (row_pixels * pixel + align - 1) / align * align;
  const auto* base = static_cast<const uint8_t*>(pixels) + size_t(store(GL_UNPACK_SKIP_ROWS)) * row +
                     size_t(store(GL_UNPACK_SKIP_PIXELS)) * pixel;
  auto component = [&](const uint8_t* p, int k) {
    if (type == GL_UNSIGNED_BYTE) return p[k] / 255.0;
    float f;
    std::memcpy(&f, p + 4 * k, 4);
    return double(f);
  };
  // Pixel (i, j) covers the window square with its lower-left corner at the raster position plus
  // (i, j); it makes the fragment whose centre lies inside.
  const int x0 = int(std::ceil(raster_pos_.window.x - 0.5)), y0 = int(std::ceil(raster_pos_.window.y - 0.5));
  const uint32_t z = raster::detail::depth24(float(raster_pos_.window.z));  // as llvmpipe converts depth
  for (GLsizei j = 0; j < h; ++j) {
    const int fy = y0 + j;
    if (fy < 0 || fy >= fb_.height) continue;
    for (GLsizei i = 0; i < w; ++i) {
      const int fx = x0 + i;
      if (fx < 0 || fx >= fb_.width) continue;
      const size_t at = size_t(fy) * size_t(fb_.width) + size_t(fx);
      if (depth_test_) {
        if (!raster::detail::depth_pass(depth_func_, z, fb_.depth[at])) continue;
        fb_.depth[at] = z;
      }
      const uint8_t* p = base + size_t(j) * row + size_t(i) * pixel;
      glm::dvec4 c(0, 0, 0, 1);
      for (int k = 0; k < layout.n; ++k) {
        const double v = component(p, k);
        if (layout.channel[k] < 0) c.r = c.g = c.b = v;
        else c[layout.channel[k]] = v;
      }
      for (int k = 0; k < 4; ++k) {
        // To 8 bits as Mesa's float_to_unorm: in float, halves to even; NaN to 0.
        const float v = float(c[k] > 0 ? (c[k] < 1 ? c[k] : 1) : 0);
        fb_.color[at * 4 + size_t(k)] = uint8_t(std::lrint(v * 255.0f));
      }
    }
  }
}

}  // namespace ffc::state
