// glRasterPos and glDrawPixels (GL 2.1 sections 2.13 and 3.6.4): the current raster position is
// a vertex through the vertex stage (transformed, lit, clipped as a point), and glDrawPixels
// writes a rectangle of fragments from it, through the depth test, with pixel zoom 1.
//
// Implemented: the colour formats (GL_RGBA, GL_RGB, GL_BGRA, GL_BGR, GL_RED, GL_GREEN, GL_BLUE,
// GL_ALPHA, GL_LUMINANCE, GL_LUMINANCE_ALPHA) with GL_UNSIGNED_BYTE or GL_FLOAT, and the unpack
// alignment, row length and skips. Other valid formats and types (depth, stencil, colour index,
// the integer and packed types) are not: the call records GL_INVALID_OPERATION and says so once
// on stderr; it never draws something else in their place.
#include <array>
#include <cmath>
#include <limits>
#include <cstdio>
#include <cstring>
#include <set>
#include <utility>

#include <glm/gtc/type_ptr.hpp>

#include "raster/pixel_rules.h"
#include "state/context.h"
#include "state/float_matrix.h"

namespace ffc::state {

namespace {

// Mesa's float vector steps (main/macros.h), each in its order of operations: the raster position
// must round as Mesa's does.
using F3 = std::array<float, 3>;
float dot3(const F3& a, const F3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
void normalize3(F3& v) {  // a zero vector stays as it is
  float len = dot3(v, v);
  if (len != 0) {
    len = 1.0f / std::sqrt(len);
    for (float& c : v) c *= len;
  }
}
// n as a row vector times the matrix's upper 3x3 (TRANSFORM_NORMAL): m's transpose times n.
F3 row_times(const F3& n, const float* m) {
  return {n[0] * m[0] + n[1] * m[1] + n[2] * m[2], n[0] * m[4] + n[1] * m[5] + n[2] * m[6],
          n[0] * m[8] + n[1] * m[9] + n[2] * m[10]};
}
std::array<float, 4> times_point(const float* m, const float* p) {  // TRANSFORM_POINT
  std::array<float, 4> q;
  for (int i = 0; i < 4; ++i) q[size_t(i)] = m[i] * p[0] + m[4 + i] * p[1] + m[8 + i] * p[2] + m[12 + i] * p[3];
  return q;
}
F3 f3(const glm::dvec4& v) { return {float(v.x), float(v.y), float(v.z)}; }
float clamp01(float x) { return x > 0 ? (x > 1 ? 1 : x) : 0; }  // a NaN to 0, as Mesa's CLAMP

}  // namespace

// The raster position's colour as Mesa 22.3 lights it (main/rastpos.c, shade_rastpos), not through
// the vertex program that lights vertices: in float, the front material only, the current normal as
// it is (GL_NORMALIZE does not apply), and with Mesa's choice of space (light.c): eye space when a
// light is positional, the viewer is local or the modelview does not preserve lengths; otherwise
// object space, with the lights and the eye direction taken back through the modelview's inverse.
// Mesa's quirk: the vertex it lights is the object-space position in both spaces, so that in eye
// space a positional light is measured from the wrong point (docs/deviations.md).
glm::dvec4 Context::mesa_raster_color(const float obj[4]) {
  fmat::Matrix& modelview = modelview_f_.back();  // analysed (validate_matrices)
  const glm::mat4& inv4 = modelview.inverse();
  const bool rigid = modelview.length_preserving();
  const glm::mat4& mv4 = modelview.values();
  const float *mv = glm::value_ptr(mv4), *inv = glm::value_ptr(inv4);
  bool need_eye = model_.local_viewer || !rigid;
  for (const lighting::LightParams& l : lights_)
    if (l.enabled && float(l.position.w) != 0) need_eye = true;

  const F3 eye_z = need_eye ? F3{0, 0, 1} : row_times({0, 0, 1}, mv);
  const F3 objnorm{float(normal_.x), float(normal_.y), float(normal_.z)};
  const F3 normal = need_eye ? row_times(objnorm, inv) : objnorm;
  const F3 vertex{obj[0], obj[1], obj[2]};
  const lighting::MaterialParams& mat = materials_[0];
  const F3 mat_amb = f3(mat.ambient), mat_dif = f3(mat.diffuse), mat_spe = f3(mat.specular);
  const float shine = float(mat.shininess);

  F3 diffuse = f3(mat.emission), specular{0, 0, 0};
  const F3 model_amb = f3(model_.ambient);
  for (int k = 0; k < 3; ++k) diffuse[size_t(k)] += mat_amb[size_t(k)] * model_amb[size_t(k)];
  const float alpha = clamp01(float(mat.diffuse.w));

  for (const lighting::LightParams& l : lights_) {
    if (!l.enabled) continue;
    const float eye_pos[4] = {float(l.position.x), float(l.position.y), float(l.position.z), float(l.position.w)};
    std::array<float, 4> pos;
    if (need_eye) pos = {eye_pos[0], eye_pos[1], eye_pos[2], eye_pos[3]};
    else pos = times_point(inv, eye_pos);
    const bool positional = eye_pos[3] != 0, spot = float(l.spot_cutoff) != 180.0f;
    F3 vp_inf{0, 0, 0}, h_inf{0, 0, 0};
    float spot_inf = 1;
    if (!positional) {
      vp_inf = {pos[0], pos[1], pos[2]};
      normalize3(vp_inf);
      if (!model_.local_viewer) {
        h_inf = {vp_inf[0] + eye_z[0], vp_inf[1] + eye_z[1], vp_inf[2] + eye_z[2]};
        normalize3(h_inf);
      }
    } else {
      const float w_inv = 1.0f / pos[3];
      pos[0] *= w_inv, pos[1] *= w_inv, pos[2] *= w_inv;
    }
    float cos_cutoff = float(std::cos(double(float(l.spot_cutoff)) * M_PI / 180.0));
    if (cos_cutoff < 0) cos_cutoff = 0;
    const float exponent = float(l.spot_exponent);
    F3 spot_dir{0, 0, 0};
    if (spot) {
      spot_dir = f3(glm::dvec4(l.spot_direction, 0));
      normalize3(spot_dir);
      if (!need_eye) spot_dir = row_times(spot_dir, mv);
      normalize3(spot_dir);
      if (!positional) {
        const float pv_dot_dir = -dot3(vp_inf, spot_dir);
        spot_inf = pv_dot_dir > cos_cutoff ? std::pow(pv_dot_dir, exponent) : 0.0f;
      }
    }

    F3 vp;
    float attenuation;
    if (!positional) {
      vp = vp_inf, attenuation = spot_inf;
    } else {
      vp = {pos[0] - vertex[0], pos[1] - vertex[1], pos[2] - vertex[2]};
      const float d = std::sqrt(dot3(vp, vp));
      if (d > 1.0e-6f) {
        const float inv_d = 1.0f / d;
        for (float& c : vp) c *= inv_d;
      }
      attenuation = 1.0f / (float(l.constant_attenuation) +
                            d * (float(l.linear_attenuation) + d * float(l.quadratic_attenuation)));
      if (spot) {
        const float pv_dot_dir = -dot3(vp, spot_dir);
        if (pv_dot_dir < cos_cutoff) continue;
        attenuation *= std::pow(pv_dot_dir, exponent);
      }
    }
    if (attenuation < 1e-3f) continue;

    const F3 la = f3(l.ambient), ld = f3(l.diffuse), ls = f3(l.specular);
    F3 light_amb, light_dif, light_spe;
    for (size_t k = 0; k < 3; ++k)
      light_amb[k] = la[k] * mat_amb[k], light_dif[k] = ld[k] * mat_dif[k], light_spe[k] = ls[k] * mat_spe[k];
    const float n_dot_vp = dot3(normal, vp);
    if (n_dot_vp < 0) {
      for (size_t k = 0; k < 3; ++k) diffuse[k] += attenuation * light_amb[k];
      continue;
    }
    F3 contrib = light_amb, spec_contrib{0, 0, 0};
    for (size_t k = 0; k < 3; ++k) contrib[k] += n_dot_vp * light_dif[k];
    F3 h;
    if (model_.local_viewer) {
      F3 v = vertex;
      normalize3(v);
      h = {vp[0] - v[0], vp[1] - v[1], vp[2] - v[2]};
      normalize3(h);
    } else if (positional) {
      h = {vp[0] + eye_z[0], vp[1] + eye_z[1], vp[2] + eye_z[2]};
      normalize3(h);
    } else {
      h = h_inf;
    }
    const float n_dot_h = dot3(normal, h);
    if (n_dot_h > 0) {
      const float coef = std::pow(n_dot_h, shine);
      if (coef > 1.0e-10f) {
        F3& to = model_.separate_specular ? spec_contrib : contrib;
        for (size_t k = 0; k < 3; ++k) to[k] += coef * light_spe[k];
      }
    }
    for (size_t k = 0; k < 3; ++k) diffuse[k] += attenuation * contrib[k], specular[k] += attenuation * spec_contrib[k];
  }
  return {clamp01(diffuse[0]), clamp01(diffuse[1]), clamp01(diffuse[2]), alpha};
}

// In selection mode a valid raster position is a hit at its window depth (Mesa's rastpos.c).
void Context::RasterPos(double x, double y, double z, double w) {
  if (!outside_begin_end()) return;
  set_raster_pos(x, y, z, w);
  if (render_mode_ == GL_SELECT && raster_pos_.valid) select_hit(raster_pos_.window.z);
}

void Context::set_raster_pos(double x, double y, double z, double w) {
  flush_stored();  // Mesa: FLUSH_VERTICES and FLUSH_CURRENT first, then the state validated
  // The FLUSH_CURRENT copies a value a list left pending as a vertex list's first flush does, so the
  // next vertex list's forgets it (Context::flush_current). Measured (seed 577215 stream
  // 9649509103857847282, repro list_raster_pos_flushes_pending.txt): a list's glArrayElement of a
  // normal array outside glBegin, glRasterPos2f, then a GL_QUADS with glNormal3fv(0, 0, 0) reads back
  // the quad's normal.
  flush_current();
  validate_matrices();
  if (precision_ == Precision::Double || spec_) return raster_pos_spec(x, y, z, w);
  // Mesa (rastpos.c): in float, the modelview and then the projection, one after the other.
  const float obj[4] = {float(x), float(y), float(z), float(w)};
  const std::array<float, 4> eye = times_point(glm::value_ptr(modelview_f_.back().values()), obj);
  const std::array<float, 4> c = times_point(glm::value_ptr(projection_f_.back().values()), eye.data());
  // Clipped as a point against the six planes only: a NaN coordinate compares false and leaves
  // the position valid, w = 0 at the origin is valid, and an invalid position keeps the last
  // valid one (measured; GL 2.1 leaves both undefined).
  if (c[2] < -c[3] || c[2] > c[3] || c[0] > c[3] || c[0] < -c[3] || c[1] > c[3] || c[1] < -c[3]) {
    raster_pos_.valid = false;
    return;
  }
  raster_pos_.valid = true;
  const float d = c[3] == 0 ? 1.0f : 1.0f / c[3];  // no divide by a zero w
  const glm::ivec4 vp = viewport_;
  const float sx = float(vp[2]) * 0.5f, sy = float(vp[3]) * 0.5f;
  const float sz = float((depth_range_.y - depth_range_.x) * 0.5), tz = float((depth_range_.y + depth_range_.x) * 0.5);
  raster_pos_.window = {c[0] * d * sx + (float(vp[0]) + sx), c[1] * d * sy + (float(vp[1]) + sy), c[2] * d * sz + tz,
                        c[3]};
  raster_pos_.distance = std::sqrt(eye[0] * eye[0] + eye[1] * eye[1] + eye[2] * eye[2]);
  raster_pos_.color = lighting_ ? mesa_raster_color(obj) : color_;  // unlit: the current colour, unclamped
}

// GL 2.1 section 2.13: the raster position is a vertex through the vertex stage, lit as one.
void Context::raster_pos_spec(double x, double y, double z, double w) {
  update_vertex_constants();
  bool zero_normal = false;
  const raster::Vertex v = vertex({x, y, z, w}, normal_, color_, &zero_normal);
  const glm::dvec4& c = v.clip;
  raster_pos_.valid = !(c.x > c.w || c.x < -c.w || c.y > c.w || c.y < -c.w || c.z > c.w || c.z < -c.w);
  if (!raster_pos_.valid) return;
  if (std::isnan(c.x) || std::isnan(c.y) || std::isnan(c.z) || std::isnan(c.w)) {
    raster_pos_.window = glm::dvec4(std::numeric_limits<double>::quiet_NaN());
  } else {
    const float inv = c.w != 0 ? 1.0f / float(c.w) : 1.0f;
    const glm::ivec4 vp = viewport_;
    const float sx = float(vp[2]) * 0.5f, sy = float(vp[3]) * 0.5f;
    const float sz = float((depth_range_.y - depth_range_.x) * 0.5), tz = float((depth_range_.y + depth_range_.x) * 0.5);
    raster_pos_.window = {float(c.x) * inv * sx + (float(vp[0]) + sx), float(c.y) * inv * sy + (float(vp[1]) + sy),
                          float(c.z) * inv * sz + tz, c.w};
  }
  raster_pos_.color = lighting_ ? v.front : color_;
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

// Unpacking (GL 2.1 section 3.6.4): rows of GL_UNPACK_ROW_LENGTH pixels (w when 0), each starting
// at a multiple of GL_UNPACK_ALIGNMENT, after the skipped rows and pixels; a list's copy (packed)
// is rows of w pixels one after the other. False: a format or type soft does not draw.
bool Context::pixel_rows(GLsizei w, GLenum format, GLenum type, bool packed, PixelRows& out) const {
  Layout layout;
  if (!color_layout(format, layout) || (type != GL_UNSIGNED_BYTE && type != GL_FLOAT)) return false;
  auto store = [&](GLenum p) {
    const auto it = pixel_store_.find(p);
    return packed || it == pixel_store_.end() ? 0 : it->second;
  };
  const size_t size = type == GL_FLOAT ? 4 : 1, pixel = size * size_t(layout.n);
  const size_t row_pixels = store(GL_UNPACK_ROW_LENGTH) > 0 ? size_t(store(GL_UNPACK_ROW_LENGTH)) : size_t(w);
  const size_t align = packed ? 1 : size_t(unpack_alignment_);
  out.pixel = pixel;
  out.row = size >= align ? row_pixels * pixel : (row_pixels * pixel + align - 1) / align * align;
  out.skip = size_t(store(GL_UNPACK_SKIP_ROWS)) * out.row + size_t(store(GL_UNPACK_SKIP_PIXELS)) * pixel;
  return true;
}

// A glDrawPixels compiled into a list keeps its image as the unpack state reads it now (GL 2.1
// section 5.4), rows of whole pixels; empty for what soft does not draw (its error comes when the
// list runs) and for images too big to be meant (a shrunk stream's sizes).
std::vector<GLubyte> Context::list_image(GLsizei w, GLsizei h, GLenum format, GLenum type, const void* pixels) const {
  PixelRows r;
  if (!pixels || w <= 0 || h <= 0 || double(w) * double(h) > double(1 << 22) || !pixel_rows(w, format, type, false, r))
    return {};
  std::vector<GLubyte> out(size_t(w) * size_t(h) * r.pixel);
  const auto* in = static_cast<const uint8_t*>(pixels) + r.skip;
  for (GLsizei j = 0; j < h; ++j)
    std::memcpy(out.data() + size_t(j) * size_t(w) * r.pixel, in + size_t(j) * r.row, size_t(w) * r.pixel);
  return out;
}

void Context::DrawPixels(GLsizei w, GLsizei h, GLenum format, GLenum type, const void* pixels, bool packed) {
  if (!outside_begin_end()) return;
  const SinkPixels through_sink(*this);  // draw_sink.cpp: soft draws into the sink's picture
  // Mesa's FLUSH_VERTICES (outside_begin_end) flushes stored vertices only where a flush was asked
  // for: a pending glMaterial stays (measured; repro material_pending_through_pixels.txt).
  validate_matrices();
  if (w < 0 || h < 0) return error(GL_INVALID_VALUE);
  if (!known_format(format) || !known_type(type)) return error(GL_INVALID_ENUM);
  // A packed type needs a format of its number of components, as for glReadPixels (GL 2.1 section
  // 3.6.4): GL_RGB for the 3-component types, GL_RGBA or GL_BGRA for the others (measured on Mesa,
  // before anything else happens, in feedback mode too).
  switch (type) {
    case GL_UNSIGNED_BYTE_3_3_2: case GL_UNSIGNED_BYTE_2_3_3_REV: case GL_UNSIGNED_SHORT_5_6_5:
    case GL_UNSIGNED_SHORT_5_6_5_REV:
      if (format != GL_RGB) return error(GL_INVALID_OPERATION);
      break;
    case GL_UNSIGNED_SHORT_4_4_4_4: case GL_UNSIGNED_SHORT_4_4_4_4_REV: case GL_UNSIGNED_SHORT_5_5_5_1:
    case GL_UNSIGNED_SHORT_1_5_5_5_REV: case GL_UNSIGNED_INT_8_8_8_8: case GL_UNSIGNED_INT_8_8_8_8_REV:
    case GL_UNSIGNED_INT_10_10_10_2: case GL_UNSIGNED_INT_2_10_10_10_REV:
      if (format != GL_RGBA && format != GL_BGRA) return error(GL_INVALID_OPERATION);
      break;
  }
  if (render_mode_ == GL_FEEDBACK) {
    // Feedback gets the raster position as a vertex after GL_DRAW_PIXEL_TOKEN (GL 2.1 section 5.3),
    // its texture coordinates the texture matrix's last column (the current ones are (0, 0, 0, 1)).
    if (!raster_pos_.valid) return;
    return feedback_raster_position(GL_DRAW_PIXEL_TOKEN);  // bitmap.cpp
  }
  Layout layout;
  if (!color_layout(format, layout) || (type != GL_UNSIGNED_BYTE && type != GL_FLOAT)) {
    static std::set<std::pair<GLenum, GLenum>> said;
    if (said.insert({format, type}).second)
      std::fprintf(stderr, "ffcompat: glDrawPixels with format 0x%04X and type 0x%04X is not implemented "
                           "(GL_INVALID_OPERATION)\n", format, type);
    deviations_.insert(kDrawPixelsFormat);
    return error(GL_INVALID_OPERATION);
  }
  const glm::dvec4& rp = raster_pos_.window;
  if (!raster_pos_.valid || render_mode_ != GL_RENDER || !pixels) return;  // no fragments
  if (!(std::abs(rp.x) < 1e9 && std::abs(rp.y) < 1e9)) {                 // NaN or far away: none we can place
    if (!(std::isfinite(rp.x) && std::isfinite(rp.y)) && w > 0 && h > 0) deviations_.insert(kNonfiniteDrawPixels);
    return;
  }
  flush_clear();
  PixelRows rows;
  pixel_rows(w, format, type, packed, rows);
  const size_t row = rows.row, pixel = rows.pixel;
  const auto* base = static_cast<const uint8_t*>(pixels) + rows.skip;
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
  auto color_at = [&](GLsizei i, GLsizei j) {
    const uint8_t* p = base + size_t(j) * row + size_t(i) * pixel;
    glm::dvec4 c(0, 0, 0, 1);
    for (int k = 0; k < layout.n; ++k) {
      const double v = component(p, k);
      if (layout.channel[k] < 0) c.r = c.g = c.b = v;
      else c[layout.channel[k]] = v;
    }
    return c;
  };
  const raster::State rs = raster_state();
  for (GLsizei j = 0; j < h; ++j) {
    const int fy = y0 + j;
    if (fy < 0 || fy >= fb_.height) continue;
    for (GLsizei i = 0; i < w; ++i) {
      const int fx = x0 + i;
      if (fx < 0 || fx >= fb_.width) continue;
      if (rs.ops.any()) {  // scissor, alpha test, masks, blending (fragment.cpp) on each pixel
        raster::draw_fragment(fb_, fx, fy, raster_pos_.window.z, color_at(i, j), rs);
        continue;
      }
      const size_t at = size_t(fy) * size_t(fb_.width) + size_t(fx);
      if (depth_test_) {
        if (!raster::detail::depth_pass(depth_func_, z, fb_.depth[at])) continue;
        fb_.depth[at] = z;
      }
      const glm::dvec4 c = color_at(i, j);
      for (int k = 0; k < 4; ++k) {
        // To 8 bits as Mesa's float_to_unorm: in float, halves to even; NaN to 0.
        const float v = float(c[k] > 0 ? (c[k] < 1 ? c[k] : 1) : 0);
        fb_.color[at * 4 + size_t(k)] = uint8_t(std::lrint(v * 255.0f));
      }
    }
  }
}

}  // namespace ffc::state
