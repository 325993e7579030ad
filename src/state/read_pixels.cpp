// glReadPixels: which formats and types it takes, and how it packs them (see read_pixels.h).
#include "state/read_pixels.h"

#include "state/context.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>

namespace ffc::state {
namespace {

bool is_plain_type(GLenum t) {
  switch (t) {
    case GL_UNSIGNED_BYTE: case GL_BYTE: case GL_UNSIGNED_SHORT: case GL_SHORT: case GL_UNSIGNED_INT: case GL_INT:
    case GL_FLOAT: case GL_HALF_FLOAT: return true;  // GL_HALF_FLOAT: GL 3.0, which Mesa takes here
  }
  return false;
}

// The packed types: the components' widths, the first component's at the most significant end
// (GL 2.1 table 3.10's layouts) or, for the _REV types, at the least significant end.
struct Packed {
  GLenum type;
  int bytes, components;
  bool reversed;
  int bits[4];
};
constexpr Packed kPacked[] = {
    {GL_UNSIGNED_BYTE_3_3_2, 1, 3, false, {3, 3, 2}},
    {GL_UNSIGNED_BYTE_2_3_3_REV, 1, 3, true, {3, 3, 2}},
    {GL_UNSIGNED_SHORT_5_6_5, 2, 3, false, {5, 6, 5}},
    {GL_UNSIGNED_SHORT_5_6_5_REV, 2, 3, true, {5, 6, 5}},
    {GL_UNSIGNED_SHORT_4_4_4_4, 2, 4, false, {4, 4, 4, 4}},
    {GL_UNSIGNED_SHORT_4_4_4_4_REV, 2, 4, true, {4, 4, 4, 4}},
    {GL_UNSIGNED_SHORT_5_5_5_1, 2, 4, false, {5, 5, 5, 1}},
    {GL_UNSIGNED_SHORT_1_5_5_5_REV, 2, 4, true, {5, 5, 5, 1}},
    {GL_UNSIGNED_INT_8_8_8_8, 4, 4, false, {8, 8, 8, 8}},
    {GL_UNSIGNED_INT_8_8_8_8_REV, 4, 4, true, {8, 8, 8, 8}},
    {GL_UNSIGNED_INT_10_10_10_2, 4, 4, false, {10, 10, 10, 2}},
    {GL_UNSIGNED_INT_2_10_10_10_REV, 4, 4, true, {10, 10, 10, 2}},
};
const Packed* find_packed(GLenum t) {
  for (const Packed& p : kPacked)
    if (p.type == t) return &p;
  return nullptr;
}

// The framebuffer channels (0 R, 1 G, 2 B, 3 A) a colour format returns, in order; 0 for a
// format that is not a colour format of GL 2.1. Luminance is computed (see below), not a channel.
int colour_channels(GLenum format, int* ch) {
  auto set = [ch](std::initializer_list<int> c) {
    std::copy(c.begin(), c.end(), ch);
    return int(c.size());
  };
  switch (format) {
    case GL_RGBA: return set({0, 1, 2, 3});
    case GL_RGB: return set({0, 1, 2});
    case GL_BGRA: return set({2, 1, 0, 3});
    case GL_BGR: return set({2, 1, 0});
    case GL_RED: return set({0});
    case GL_GREEN: return set({1});
    case GL_BLUE: return set({2});
    case GL_ALPHA: return set({3});
    case GL_LUMINANCE: return set({-1});
    case GL_LUMINANCE_ALPHA: return set({-1, 3});
  }
  return 0;
}

int type_size(GLenum t) {
  switch (t) {
    case GL_UNSIGNED_BYTE: case GL_BYTE: return 1;
    case GL_UNSIGNED_SHORT: case GL_SHORT: case GL_HALF_FLOAT: return 2;
    default: return 4;
  }
}

// Rounding of Mesa's float-to-integer conversions (F_TO_I: to nearest, halves to even), kept in
// 64 bits and then narrowed by the caller as Mesa narrows it.
int64_t round_even(float x) { return int64_t(std::nearbyint(x)); }

// A byte of the colour buffer (unsigned normalised, 8 bits) as each type, as Mesa's
// _mesa_swizzle_and_convert converts it (format_utils.h): to fewer bits with rounding
// ((x * max_dst + 127) / 255), to more bits by replicating the bit pattern
// (EXTEND_NORMALIZED_INT), to the signed types as unsigned values of one bit less, to float as
// x * (1 / 255).
unsigned unorm8_to_unorm(unsigned x, int bits) {
  if (bits == 8) return x;
  if (bits < 8) return (x * ((1u << bits) - 1) + 127) / 255;
  const uint64_t max = (uint64_t(1) << bits) - 1;
  const unsigned whole = unsigned(max / 255), rest = bits % 8;
  return x * whole + (rest ? x >> (8 - rest) : 0);
}

// Mesa's float-to-normalised conversions (_mesa_float_to_unorm / _mesa_float_to_snorm) for the
// luminance path's float values: clamped, scaled by the float maximum, rounded, then narrowed to
// the destination's width (the 32-bit ones wrap at 1.0, where the float product is 2^32 or 2^31).
uint32_t float_to_unorm(float v, int bits) {
  const uint64_t max = (uint64_t(1) << bits) - 1;
  if (v < 0) return 0;
  if (v > 1) return uint32_t(max);
  return uint32_t(round_even(v * float(max)));
}
int32_t float_to_snorm(float v, int bits) {
  const int64_t max = (int64_t(1) << (bits - 1)) - 1;
  if (v < -1) return int32_t(-max);
  if (v > 1) return int32_t(max);
  return int32_t(round_even(v * float(max)));
}

template <typename T>
void put(uint8_t* p, T v) {
  std::memcpy(p, &v, sizeof v);
}

// A float as a half float, rounded to nearest, ties to even (Mesa packs GL_HALF_FLOAT as it
// packs GL_FLOAT, then converts each value so: measured, colour, luminance and depth alike).
uint16_t to_half(float f) {
  uint32_t u;
  std::memcpy(&u, &f, sizeof u);
  const uint16_t sign = uint16_t((u >> 16) & 0x8000u);
  const uint32_t abs = u & 0x7FFFFFFFu;
  if (abs >= 0x7F800000u) return uint16_t(sign | (abs > 0x7F800000u ? 0x7E00u : 0x7C00u));  // NaN, infinity
  if (abs >= 0x477FF000u) return uint16_t(sign | 0x7C00u);  // rounds past the largest half
  const int exp = int(abs >> 23) - 127;
  if (exp < -25) return sign;  // below half the smallest subnormal
  uint32_t mant = (abs & 0x7FFFFFu) | 0x800000u;
  // Shift the 24-bit significand down to the half's 11 bits (fewer for subnormals), rounding.
  const int shift = exp < -14 ? 13 + (-14 - exp) : 13;
  const uint32_t kept = mant >> shift, rest = mant & ((1u << shift) - 1), half = 1u << (shift - 1);
  uint32_t h = kept + (rest > half || (rest == half && (kept & 1u)) ? 1u : 0u);
  if (exp >= -14) h = (uint32_t(exp + 15) << 10) + (h - 0x400u);  // normal: the carry may bump the exponent
  return uint16_t(sign | h);
}

// One component of `type` from a colour byte.
void put_from_byte(uint8_t* p, GLenum type, unsigned x) {
  switch (type) {
    case GL_UNSIGNED_BYTE: return put(p, uint8_t(x));
    case GL_BYTE: return put(p, int8_t(unorm8_to_unorm(x, 7)));
    case GL_UNSIGNED_SHORT: return put(p, uint16_t(unorm8_to_unorm(x, 16)));
    case GL_SHORT: return put(p, int16_t(unorm8_to_unorm(x, 15)));
    case GL_UNSIGNED_INT: return put(p, uint32_t(unorm8_to_unorm(x, 32)));
    case GL_INT: return put(p, int32_t(unorm8_to_unorm(x, 31)));
    case GL_FLOAT: return put(p, float(x) * (1.0f / 255.0f));
    case GL_HALF_FLOAT: return put(p, to_half(float(x) * (1.0f / 255.0f)));
  }
}

// One component of `type` from a float in [0, 1] (the luminance path).
void put_from_float(uint8_t* p, GLenum type, float v) {
  switch (type) {
    case GL_UNSIGNED_BYTE: return put(p, uint8_t(float_to_unorm(v, 8)));
    case GL_BYTE: return put(p, int8_t(float_to_snorm(v, 8)));
    case GL_UNSIGNED_SHORT: return put(p, uint16_t(float_to_unorm(v, 16)));
    case GL_SHORT: return put(p, int16_t(float_to_snorm(v, 16)));
    case GL_UNSIGNED_INT: return put(p, float_to_unorm(v, 32));
    case GL_INT: return put(p, float_to_snorm(v, 32));
    case GL_FLOAT: return put(p, v);
    case GL_HALF_FLOAT: return put(p, to_half(v));
  }
}

// One depth value of `type` from the 24-bit depth buffer, as Mesa's read_depth_pixels does:
// GL_UNSIGNED_INT straight from the integer (the 24 bits, then their top 8 again: Mesa's
// _mesa_unpack_uint_z_row) unless the bytes are to be swapped, which that fast path does not
// do; the rest from the float z / (2^24 - 1) through the macros of
// _mesa_pack_depth_span (main/macros.h): GL_UNSIGNED_BYTE truncates (FLOAT_TO_UBYTE),
// GL_UNSIGNED_SHORT rounds (CLAMPED_FLOAT_TO_USHORT), GL_BYTE and GL_SHORT take the unsigned
// value of twice the bits, truncated, less one, halved ((int(65535 z) - 1) / 2: FLOAT_TO_SHORT),
// GL_UNSIGNED_INT and GL_INT truncate the double product (FLOAT_TO_UINT, FLOAT_TO_INT_TEX).
// Checked against Mesa over 3000 clear depths.
void put_depth(uint8_t* p, GLenum type, uint32_t z, bool swapped) {
  const float d = float(double(z) * (1.0 / double(0xFFFFFF)));
  switch (type) {
    case GL_UNSIGNED_BYTE: return put(p, uint8_t(int32_t(d * 255.0f)));
    case GL_BYTE: return put(p, int8_t((int32_t(d * 255.0f) - 1) / 2));
    case GL_UNSIGNED_SHORT: return put(p, uint16_t(round_even(std::clamp(d, 0.0f, 1.0f) * 65535.0f)));
    case GL_SHORT: return put(p, int16_t((int32_t(d * 65535.0f) - 1) / 2));
    case GL_UNSIGNED_INT:
      return put(p, swapped ? uint32_t(4294967295.0 * double(d)) : uint32_t(z << 8 | z >> 16));
    case GL_INT: return put(p, int32_t(2147483647.0 * double(d)));
    case GL_FLOAT: return put(p, d);
    case GL_HALF_FLOAT: return put(p, to_half(d));
  }
}

void swap_bytes(uint8_t* p, int size) {
  if (size == 2) std::swap(p[0], p[1]);
  if (size == 4) std::swap(p[0], p[3]), std::swap(p[1], p[2]);
}

}  // namespace

GLenum read_pixels_error(GLenum format, GLenum type) {
  // Mesa 22.3 (observed through OSMesa): with no stencil buffer, and in RGBA mode, it answers
  // GL_STENCIL_INDEX and GL_COLOR_INDEX with GL_INVALID_OPERATION whatever the type (GL 2.1
  // section 4.3.2), and a name that is no format at all the same way (GL 2.1 says
  // GL_INVALID_ENUM).
  // But an internal format (1 to 4 components, GL 1.1's sized formats GL_ALPHA4 .. GL_RGBA16, GL
  // 2.1's sRGB ones, the sized depth formats) is GL_INVALID_ENUM there, whatever the type (measured).
  const bool internal_format = (format >= 1 && format <= 4) || (format >= 0x803B && format <= 0x805B) ||
                               (format >= 0x8C40 && format <= 0x8C4B) || (format >= 0x81A5 && format <= 0x81A7);
  if (internal_format) {
    const Packed* p = find_packed(type);
    return p || type == GL_UNSIGNED_INT_24_8 ? GL_INVALID_OPERATION : GL_INVALID_ENUM;  // a packed type first
  }
  int ch[4];
  if (format != GL_DEPTH_COMPONENT && colour_channels(format, ch) == 0) return GL_INVALID_OPERATION;
  if (is_plain_type(type)) return GL_NO_ERROR;
  if (const Packed* p = find_packed(type)) {
    // A packed type needs a format of its number of components (GL 2.1 section 3.6.4); RGB's
    // types take GL_RGB only, as GL 2.1 table 3.8 lists them (Mesa: GL_BGR too is refused).
    const bool fits = p->components == 3 ? format == GL_RGB : format == GL_RGBA || format == GL_BGRA;
    return fits ? GL_NO_ERROR : GL_INVALID_OPERATION;
  }
  // GL 3.0's GL_UNSIGNED_INT_24_8 belongs to GL_DEPTH_STENCIL: with any other format Mesa calls
  // it a mismatch, not an unknown type.
  if (type == GL_UNSIGNED_INT_24_8) return GL_INVALID_OPERATION;
  return GL_INVALID_ENUM;  // GL_BITMAP (colour-index and stencil data only), GL_DOUBLE, others
}

void pack_pixels(const raster::Framebuffer& fb, int x, int y, int w, int h, GLenum format, GLenum type,
                 const PackState& pack, void* out) {
  int ch[4] = {0, 0, 0, 0};
  const bool depth = format == GL_DEPTH_COMPONENT;
  const int n = depth ? 1 : colour_channels(format, ch);
  const Packed* packed = find_packed(type);
  const int elem = packed ? packed->bytes : type_size(type);     // the unit GL_PACK_SWAP_BYTES swaps
  const size_t pixel = packed ? size_t(packed->bytes) : size_t(n) * elem;
  // GL 2.1 section 4.3.2 / 3.6.4: rows of GL_PACK_ROW_LENGTH pixels (the width when 0), each
  // padded to a multiple of GL_PACK_ALIGNMENT bytes; the first row after GL_PACK_SKIP_ROWS rows,
  // the first pixel after GL_PACK_SKIP_PIXELS pixels.
  const size_t row_pixels = size_t(pack.row_length > 0 ? pack.row_length : w);
  const size_t a = size_t(pack.alignment);
  const size_t stride = (row_pixels * pixel + a - 1) / a * a;
  auto* base = static_cast<uint8_t*>(out) + size_t(pack.skip_rows) * stride + size_t(pack.skip_pixels) * pixel;
  // GL_PACK_SWAP_BYTES. Mesa swaps a colour read's bytes once the whole rectangle is packed
  // (readpix.c, then _mesa_swap_bytes_2d_image), row after row over the part inside the
  // framebuffer: where GL_PACK_ROW_LENGTH below the width makes rows overlap, the shared bytes
  // are swapped twice. Two cases swap as they go, pixel by pixel in effect: depth, span by span
  // (_mesa_pack_depth_span), and GL_RGBA / GL_UNSIGNED_INT_8_8_8_8, whose swapped layout is the
  // colour buffer's own, so that Mesa copies the rows (readpixels_memcpy).
  const bool swap = pack.swap_bytes && elem > 1;
  const bool swap_each = swap && (depth || (format == GL_RGBA && type == GL_UNSIGNED_INT_8_8_8_8));
  const bool swap_at_end = swap && !swap_each;
  for (int j = 0; j < h; ++j) {
    const int fy = y + j;
    if (fy < 0 || fy >= fb.height) continue;
    for (int i = 0; i < w; ++i) {
      const int fx = x + i;
      if (fx < 0 || fx >= fb.width) continue;  // outside the framebuffer: left as it was
      uint8_t* p = base + size_t(j) * stride + size_t(i) * pixel;
      const size_t at = size_t(fy) * fb.width + fx;
      const uint8_t* c = &fb.color[at * 4];
      if (depth) {
        put_depth(p, type, fb.depth[at], pack.swap_bytes);
      } else if (packed) {
        // Mesa packs the bytes through its ubyte packers: _mesa_unorm_to_unorm to each width.
        uint32_t word = 0;
        int shift = 0;
        for (int k = 0; k < packed->components; ++k) {
          const int kk = packed->reversed ? k : packed->components - 1 - k;  // least significant first
          const int bits = packed->bits[kk];
          const unsigned v = c[ch[kk]];
          word |= uint32_t(unorm8_to_unorm(v, bits)) << shift;
          shift += bits;
        }
        if (packed->bytes == 1) put(p, uint8_t(word));
        else if (packed->bytes == 2) put(p, uint16_t(word));
        else put(p, word);
      } else if (ch[0] < 0) {
        // GL_LUMINANCE(_ALPHA): Mesa converts to float (x / 255), sums R + G + B in that order
        // and clamps the sum to [0, 1] (readpix.c, _mesa_pack_luminance_from_rgba_float), then
        // converts the floats to the type.
        const float r = float(c[0]) * (1.0f / 255.0f), g = float(c[1]) * (1.0f / 255.0f),
                    b = float(c[2]) * (1.0f / 255.0f);
        put_from_float(p, type, std::clamp(r + g + b, 0.0f, 1.0f));
        if (n == 2) put_from_float(p + elem, type, float(c[3]) * (1.0f / 255.0f));
      } else {
        for (int k = 0; k < n; ++k) put_from_byte(p + size_t(k) * elem, type, c[ch[k]]);
      }
      if (swap_each) swap_bytes(p, elem);
    }
  }
  if (!swap_at_end) return;
  const int i0 = std::max(0, -x), i1 = std::min(w, fb.width - x);
  const int j0 = std::max(0, -y), j1 = std::min(h, fb.height - y);
  const size_t per_pixel = pixel / elem;
  for (int j = j0; j < j1; ++j)
    for (int i = i0; i < i1; ++i)
      for (size_t k = 0; k < per_pixel; ++k)
        swap_bytes(base + size_t(j) * stride + size_t(i) * pixel + k * elem, elem);
}

// ---------------------------------------------------------------- the entry points

void Context::PixelStorei(GLenum pname, GLint param) {
  if (!outside_begin_end_keeping_vertices()) return;
  switch (pname) {
    case GL_PACK_ALIGNMENT: case GL_UNPACK_ALIGNMENT:
      if (param != 1 && param != 2 && param != 4 && param != 8) return error(GL_INVALID_VALUE);
      (pname == GL_PACK_ALIGNMENT ? pack_alignment_ : unpack_alignment_) = param;
      return;
    case GL_PACK_SWAP_BYTES: case GL_PACK_LSB_FIRST: case GL_UNPACK_SWAP_BYTES: case GL_UNPACK_LSB_FIRST:
      pixel_store_[pname] = param != 0;
      return;
    case GL_PACK_ROW_LENGTH: case GL_PACK_IMAGE_HEIGHT: case GL_PACK_SKIP_ROWS: case GL_PACK_SKIP_PIXELS:
    case GL_PACK_SKIP_IMAGES: case GL_UNPACK_ROW_LENGTH: case GL_UNPACK_IMAGE_HEIGHT: case GL_UNPACK_SKIP_ROWS:
    case GL_UNPACK_SKIP_PIXELS: case GL_UNPACK_SKIP_IMAGES:
      // Recorded and reported; glReadPixels honours the GL_PACK_* ones (read_pixels.cpp).
      if (param < 0) return error(GL_INVALID_VALUE);
      pixel_store_[pname] = param;
      return;
  }
  error(GL_INVALID_ENUM);
}

void Context::ReadPixels(GLint x, GLint y, GLsizei w, GLsizei h, GLenum format, GLenum type, void* pixels) {
  if (!outside_begin_end_or_compiling()) return;
  validate_matrices();
  if (w < 0 || h < 0) return error(GL_INVALID_VALUE);  // Mesa checks the size before the format
  if (const GLenum e = read_pixels_error(format, type)) return error(e);
  sink_read_back();  // draw_sink.cpp: a sink's picture is read, not soft's
  flush_clear();
  auto store = [this](GLenum p) {
    const auto it = pixel_store_.find(p);
    return it == pixel_store_.end() ? 0 : it->second;
  };
  PackState pack;
  pack.alignment = pack_alignment_;
  pack.row_length = store(GL_PACK_ROW_LENGTH), pack.skip_rows = store(GL_PACK_SKIP_ROWS);
  pack.skip_pixels = store(GL_PACK_SKIP_PIXELS), pack.swap_bytes = store(GL_PACK_SWAP_BYTES) != 0;
  pack_pixels(fb_, x, y, w, h, format, type, pack, pixels);
}

void Context::read_top_down(uint8_t* out) {
  flush_clear();
  const size_t row = size_t(fb_.width) * 4;
  pool::Workers& w = workers();
  const int shares = 4 * w.size();
  w.run([&](int share) {
    for (int y = fb_.height * share / shares; y < fb_.height * (share + 1) / shares; ++y)  // GL's row 0 is the bottom one
      std::memcpy(out + size_t(y) * row, &fb_.color[size_t(fb_.height - 1 - y) * row], row);
  }, shares);
}

}  // namespace ffc::state
