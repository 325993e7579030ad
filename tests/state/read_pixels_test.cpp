// glReadPixels against Mesa: random pictures (random coloured triangles over a random clear
// colour, with the depth test on so that the depth buffer varies too), then every format x type
// (GL 2.1's, the errors around them included) over random rectangles, partly outside the
// framebuffer, with random GL_PACK_* settings; the whole output buffer, pre-filled with a
// sentinel, compared byte for byte, and the error codes.
#include <cstdint>
#include <cstdio>
#include <random>
#include <string>

#include "harness.h"

namespace ffc::state_test {
namespace {

constexpr int kW = 23, kH = 17;  // odd sizes: rows that need padding
constexpr size_t kOut = 16384;   // holds the largest read: 32-pixel rows of 16 bytes, 25 rows
constexpr uint8_t kFill = 0xA5;

#define E(x) {x, #x}
struct Named {
  GLenum e;
  const char* name;
};
const Named kFormats[] = {E(GL_RGBA), E(GL_RGB), E(GL_BGRA), E(GL_BGR), E(GL_RED), E(GL_GREEN), E(GL_BLUE),
                          E(GL_ALPHA), E(GL_LUMINANCE), E(GL_LUMINANCE_ALPHA), E(GL_DEPTH_COMPONENT),
                          // errors: no stencil buffer, RGBA mode, not a format
                          E(GL_STENCIL_INDEX), E(GL_COLOR_INDEX), {0x1234, "0x1234"}, {2, "2 (an internal format)"},
                          E(GL_RGBA8), E(GL_ALPHA4), E(GL_SRGB8_ALPHA8), E(GL_DEPTH_COMPONENT24)};
const Named kTypes[] = {E(GL_UNSIGNED_BYTE), E(GL_BYTE), E(GL_UNSIGNED_SHORT), E(GL_SHORT), E(GL_UNSIGNED_INT),
                        E(GL_INT), E(GL_FLOAT), E(GL_HALF_FLOAT), E(GL_UNSIGNED_BYTE_3_3_2), E(GL_UNSIGNED_BYTE_2_3_3_REV),
                        E(GL_UNSIGNED_SHORT_5_6_5), E(GL_UNSIGNED_SHORT_5_6_5_REV), E(GL_UNSIGNED_SHORT_4_4_4_4),
                        E(GL_UNSIGNED_SHORT_4_4_4_4_REV), E(GL_UNSIGNED_SHORT_5_5_5_1),
                        E(GL_UNSIGNED_SHORT_1_5_5_5_REV), E(GL_UNSIGNED_INT_8_8_8_8), E(GL_UNSIGNED_INT_8_8_8_8_REV),
                        E(GL_UNSIGNED_INT_10_10_10_2), E(GL_UNSIGNED_INT_2_10_10_10_REV),
                        // errors: GL_BITMAP with these formats, not a pixel type, GL 3.0's 24_8
                        E(GL_BITMAP), E(GL_DOUBLE), E(GL_UNSIGNED_INT_24_8), {0x1234, "0x1234"}};
#undef E

struct Tri {
  float xyz[3][3], rgba[3][4];
};
struct Picture {
  float clear[4];
  double clear_depth;
  std::vector<Tri> tris;
};
struct Read {
  int x, y, w, h, align, row_length, skip_rows, skip_pixels, swap;
  GLenum format, type;
};

Picture random_picture(std::mt19937& rng) {
  std::uniform_real_distribution<float> u(0, 1), pos(-1.3f, 1.3f);
  Picture p;
  for (float& c : p.clear) c = u(rng);
  p.clear_depth = u(rng);
  p.tris.resize(4);
  for (Tri& t : p.tris)
    for (int v = 0; v < 3; ++v) {
      for (int k = 0; k < 3; ++k) t.xyz[v][k] = pos(rng);
      for (int k = 0; k < 4; ++k) t.rgba[v][k] = u(rng);
    }
  return p;
}

void draw(const Picture& p) {
  glClearColor(p.clear[0], p.clear[1], p.clear[2], p.clear[3]);
  glClearDepth(p.clear_depth);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  // The depth test stays off: the depth buffer keeps the clear value. Drawn depths are not
  // bit-exact with llvmpipe's (the rasterizer's business, not glReadPixels'); the conversions of
  // many depth values are compared by DepthConversions below.
  glBegin(GL_TRIANGLES);
  for (const Tri& t : p.tris)
    for (int v = 0; v < 3; ++v) {
      glColor4f(t.rgba[v][0], t.rgba[v][1], t.rgba[v][2], t.rgba[v][3]);
      glVertex3f(t.xyz[v][0], t.xyz[v][1], t.xyz[v][2]);
    }
  glEnd();
}

// The output of each read (kOut bytes) and its error, on side s.
std::vector<std::pair<std::vector<uint8_t>, GLenum>> run_reads(Side s, const Picture& p, const std::vector<Read>& reads) {
  backend(s).begin(kW, kH);
  draw(p);
  EXPECT_EQ(enum_name(glGetError()), "GL_NO_ERROR") << side_name(s) << ": drawing";
  std::vector<std::pair<std::vector<uint8_t>, GLenum>> out;
  for (const Read& r : reads) {
    glPixelStorei(GL_PACK_ALIGNMENT, r.align);
    glPixelStorei(GL_PACK_ROW_LENGTH, r.row_length);
    glPixelStorei(GL_PACK_SKIP_ROWS, r.skip_rows);
    glPixelStorei(GL_PACK_SKIP_PIXELS, r.skip_pixels);
    glPixelStorei(GL_PACK_SWAP_BYTES, r.swap);
    // GL_PACK_LSB_FIRST concerns GL_BITMAP data only, which no read here returns: set, it must
    // change nothing.
    glPixelStorei(GL_PACK_LSB_FIRST, r.swap ^ 1);
    std::vector<uint8_t> buf(kOut, kFill);
    glReadPixels(r.x, r.y, r.w, r.h, r.format, r.type, buf.data());
    out.emplace_back(std::move(buf), glGetError());
  }
  return out;
}

std::string describe(const Read& r) {
  char b[200];
  std::snprintf(b, sizeof b, "(%d, %d, %d x %d) align %d row_length %d skip_rows %d skip_pixels %d swap %d", r.x, r.y,
                r.w, r.h, r.align, r.row_length, r.skip_rows, r.skip_pixels, r.swap);
  return b;
}

TEST(ReadPixels, EveryFormatAndTypeAgainstMesa) {
  std::mt19937 rng(20240611);
  std::uniform_int_distribution<int> align_i(0, 3), small(0, 3), coin(0, 1);
  int combos = 0, agree_combos = 0, reads_total = 0, reads_ok = 0, with_error = 0;
  constexpr int kPictures = 4, kTrials = 6;
  std::vector<int> combo_bad(std::size(kFormats) * std::size(kTypes), 0);
  for (int pic = 0; pic < kPictures; ++pic) {
    const Picture p = random_picture(rng);
    std::vector<Read> reads;
    for (const Named& f : kFormats)
      for (const Named& t : kTypes)
        for (int k = 0; k < kTrials; ++k) {
          Read r{};
          r.x = std::uniform_int_distribution<int>(-4, kW - 2)(rng);
          r.y = std::uniform_int_distribution<int>(-4, kH - 2)(rng);
          r.w = std::uniform_int_distribution<int>(0, kW + 4 - std::max(r.x, 0))(rng);
          r.h = std::uniform_int_distribution<int>(0, kH + 4 - std::max(r.y, 0))(rng);
          if (k == 0) r.x = 0, r.y = 0, r.w = kW, r.h = kH;  // the whole picture, defaults
          r.align = k == 0 ? 4 : 1 << align_i(rng);
          // GL_PACK_ROW_LENGTH 0 (the width), or a length from below the width (rows that
          // overlap, the later row winning) to beyond it.
          r.row_length = k == 0 || coin(rng) ? 0 : std::max(1, r.w - 2 + small(rng) * 2);
          r.skip_rows = k == 0 ? 0 : small(rng);
          r.skip_pixels = k == 0 ? 0 : small(rng);
          r.swap = k == 0 ? 0 : coin(rng);
          r.format = f.e, r.type = t.e;
          reads.push_back(r);
        }
    // First the whole colour and depth buffers, at their own precision: they must agree for the
    // packing to be compared.
    Read whole{0, 0, kW, kH, 4, 0, 0, 0, 0, GL_RGBA, GL_UNSIGNED_BYTE};
    reads.insert(reads.begin(), whole);
    whole.format = GL_DEPTH_COMPONENT, whole.type = GL_UNSIGNED_INT;
    reads.insert(reads.begin() + 1, whole);
    auto m = run_reads(kMesa, p, reads), s = run_reads(kSoft, p, reads);
    ASSERT_EQ(m[0].first, s[0].first) << "the colour buffers differ";
    ASSERT_EQ(m[1].first, s[1].first) << "the depth buffers differ";
    reads.erase(reads.begin(), reads.begin() + 2);
    m.erase(m.begin(), m.begin() + 2);
    s.erase(s.begin(), s.begin() + 2);
    for (size_t i = 0; i < reads.size(); ++i) {
      const Read& r = reads[i];
      ++reads_total;
      with_error += m[i].second != GL_NO_ERROR;
      size_t first = 0;
      while (first < kOut && m[i].first[first] == s[i].first[first]) ++first;
      const bool ok = m[i].second == s[i].second && first == kOut;
      reads_ok += ok;
      const size_t combo = i / kTrials % (std::size(kFormats) * std::size(kTypes));
      combo_bad[combo] += !ok;
      if (!ok && combo_bad[combo] <= 1) {
        ADD_FAILURE() << kFormats[combo / std::size(kTypes)].name << " / " << kTypes[combo % std::size(kTypes)].name
                      << " " << describe(r) << ": error mesa " << enum_name(m[i].second) << ", soft "
                      << enum_name(s[i].second)
                      << (first < kOut ? ", first differing byte " + std::to_string(first) + ": mesa " +
                                             std::to_string(m[i].first[first]) + ", soft " +
                                             std::to_string(s[i].first[first])
                                       : std::string());
      }
    }
  }
  for (int bad : combo_bad) ++combos, agree_combos += bad == 0;
  std::printf("[ ReadPix  ] %d of %d format x type combinations agree; %d of %d reads (%d of them errors)\n",
              agree_combos, combos, reads_ok, reads_total, with_error);
  // The reads Mesa answers with an error are pinned too: GL_STENCIL_INDEX, GL_COLOR_INDEX and
  // 0x1234 with every type, GL_BITMAP / GL_DOUBLE / 0x1234 / 24_8 with every format, and the
  // packed types with the wrong formats (228 pairs), and the five internal formats with every type
  // (120 pairs): 348 with GL_HALF_FLOAT among the types.
  EXPECT_EQ(with_error, kPictures * kTrials * 348);
}

// Every byte value through every readable format and type: the colour buffer cleared to 256
// colours that give each channel every value (R v, G 255 - v, B 7v, A 13v, modulo 256), one
// pixel read each time, compared with Mesa byte for byte (with and without byte swapping).
TEST(ReadPixels, EveryByteValue) {
  std::vector<uint8_t> got[2];
  std::vector<std::string> what;
  for (Side s : {kMesa, kSoft}) {
    backend(s).begin(3, 2);
    for (int v = 0; v < 256; ++v) {
      const int c[4] = {v, 255 - v, v * 7 % 256, v * 13 % 256};
      glClearColor(c[0] / 255.0f, c[1] / 255.0f, c[2] / 255.0f, c[3] / 255.0f);
      glClear(GL_COLOR_BUFFER_BIT);
      uint8_t rgba[4] = {};
      glReadPixels(2, 1, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
      for (int k = 0; k < 4; ++k) ASSERT_EQ(rgba[k], c[k]) << side_name(s) << ": the clear colour's bytes";
      for (const Named& f : kFormats) {
        if (f.e == GL_DEPTH_COMPONENT) break;  // the colour formats come first
        for (const Named& t : kTypes) {
          if (t.e == GL_BITMAP) break;  // the readable types come first
          for (int swap : {0, 1}) {
            glPixelStorei(GL_PACK_SWAP_BYTES, swap);
            uint8_t out[16];
            std::fill(out, out + 16, kFill);
            glReadPixels(2, 1, 1, 1, f.e, t.e, out);
            const GLenum e = glGetError();
            got[s].insert(got[s].end(), out, out + 16);
            got[s].push_back(uint8_t(e != GL_NO_ERROR));
            if (s == kMesa)
              what.push_back(std::string(f.name) + " / " + t.name + (swap ? " swapped" : "") + ", colour " +
                             std::to_string(v));
          }
        }
      }
    }
  }
  ASSERT_EQ(got[kSoft].size(), got[kMesa].size());
  int bad = 0, reads = int(what.size()), errors = 0;
  for (int r = 0; r < reads; ++r) {
    const auto m = got[kMesa].begin() + r * 17, s = got[kSoft].begin() + r * 17;
    errors += m[16];
    if (!std::equal(m, m + 17, s) && ++bad <= 10) {
      int k = 0;
      while (m[k] == s[k]) ++k;
      ADD_FAILURE() << what[r] << (k == 16 ? ": the error differs" : ": byte " + std::to_string(k) + ": mesa " +
                                                                        std::to_string(m[k]) + ", soft " +
                                                                        std::to_string(s[k]));
    }
  }
  std::printf("[ ReadPix  ] every byte value: %d of %d one-pixel reads agree\n", reads - bad, reads);
  // The packed types with the wrong format: the 4 RGB ones with the 9 colour formats other than
  // GL_RGB, the 8 RGBA ones with the 8 other than GL_RGBA and GL_BGRA; both swap settings, every
  // colour.
  EXPECT_EQ(errors, (9 * 4 + 8 * 8) * 2 * 256);
}

// The depth conversions over many depth values (one clear each), every type, bytes swapped or
// not (Mesa's GL_UNSIGNED_INT takes another path when they are), against Mesa.
TEST(ReadPixels, DepthConversions) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<double> depths = {0, 0.25, 0.5, 0.75, 1, 1.0 / 3, 2.0 / 3};
  while (depths.size() < 400) depths.push_back(u(rng));
  const GLenum types[] = {GL_UNSIGNED_BYTE, GL_BYTE, GL_UNSIGNED_SHORT, GL_SHORT, GL_UNSIGNED_INT, GL_INT, GL_FLOAT};
  std::vector<uint32_t> got[2];
  for (Side s : {kMesa, kSoft}) {
    backend(s).begin(4, 4);
    for (double d : depths) {
      glClearDepth(d);
      glClear(GL_DEPTH_BUFFER_BIT);
      for (int swap : {0, 1}) {
        glPixelStorei(GL_PACK_SWAP_BYTES, swap);
        for (GLenum t : types) {
          uint32_t v = 0xA5A5A5A5;
          glReadPixels(1, 2, 1, 1, GL_DEPTH_COMPONENT, t, &v);
          got[s].push_back(v);
        }
      }
    }
    EXPECT_EQ(enum_name(glGetError()), "GL_NO_ERROR") << side_name(s);
  }
  ASSERT_EQ(got[kSoft].size(), got[kMesa].size());
  int bad = 0;
  for (size_t i = 0; i < got[kMesa].size(); ++i)
    if (got[kSoft][i] != got[kMesa][i] && ++bad <= 10)
      ADD_FAILURE() << "depth " << num(depths[i / std::size(types) / 2]) << " as " << enum_name(types[i % std::size(types)])
                    << (i / std::size(types) % 2 ? " swapped" : "")
                    << ": mesa 0x" << std::hex << got[kMesa][i] << ", soft 0x" << got[kSoft][i];
}

// Two places where Mesa 22.3 departs from GL 2.1 and soft follows it, pinned on both sides so
// that a fixed Mesa shows here:
// - GL_LUMINANCE(_ALPHA) as GL_UNSIGNED_INT / GL_INT: Mesa converts its float 1.0 with a float
//   product, 1.0f * 4294967295 = 2^32 (or 2^31), which wraps: white reads back as 0 and
//   -2^31 (GL 2.1 section 4.3.2 and table 2.9: 2^32 - 1 and 2^31 - 1). GL_RGBA is not affected.
// - GL_DEPTH_COMPONENT as GL_UNSIGNED_INT: without byte swapping Mesa replicates the 24 bits
//   into 32 (0x400000 -> 0x40000040); with GL_PACK_SWAP_BYTES it goes through float and a
//   truncated double product (0x4000007F, swapped), so the setting changes the value and not
//   only the byte order (GL 2.1 section 4.3.2: swapping reorders the bytes only).
TEST(ReadPixels, MesaDeviationsFollowed) {
  for (Side s : {kMesa, kSoft}) {
    backend(s).begin(4, 4);
    glClearColor(1, 1, 1, 1);
    glClearDepth(0.25);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    GLuint u[2] = {7, 7};
    GLint i[2] = {7, 7};
    glReadPixels(0, 0, 1, 1, GL_LUMINANCE_ALPHA, GL_UNSIGNED_INT, u);
    glReadPixels(0, 0, 1, 1, GL_LUMINANCE_ALPHA, GL_INT, i);
    EXPECT_EQ(u[0], 0u) << side_name(s);
    EXPECT_EQ(u[1], 0u) << side_name(s);
    EXPECT_EQ(i[0], INT32_MIN) << side_name(s);
    EXPECT_EQ(i[1], INT32_MIN) << side_name(s);
    glReadPixels(0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_INT, u);  // the same white, as RGBA: no wrap
    EXPECT_EQ(u[0], 0xFFFFFFFFu) << side_name(s);
    GLuint z = 0, z_swapped = 0;
    glReadPixels(0, 0, 1, 1, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, &z);
    glPixelStorei(GL_PACK_SWAP_BYTES, 1);
    glReadPixels(0, 0, 1, 1, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, &z_swapped);
    EXPECT_EQ(z, 0x40000040u) << side_name(s);
    EXPECT_EQ(__builtin_bswap32(z_swapped), 0x4000007Fu) << side_name(s);
    EXPECT_EQ(enum_name(glGetError()), "GL_NO_ERROR") << side_name(s);
  }
}

// The size check comes before the format check (Mesa: GL_INVALID_VALUE for a negative size even
// with no format), and a zero-sized read writes nothing.
TEST(ReadPixels, SizeErrorsAndEmptyReads) {
  for (Side s : {kMesa, kSoft}) {
    backend(s).begin(kW, kH);
    std::vector<uint8_t> buf(64, kFill);
    glReadPixels(0, 0, -1, 2, 0x1234, GL_RGBA, buf.data());
    EXPECT_EQ(enum_name(glGetError()), "GL_INVALID_VALUE") << side_name(s);
    glReadPixels(0, 0, 0, 3, GL_RGBA, GL_UNSIGNED_BYTE, buf.data());
    glReadPixels(0, 0, 3, 0, GL_RGBA, GL_FLOAT, buf.data());
    EXPECT_EQ(enum_name(glGetError()), "GL_NO_ERROR") << side_name(s);
    EXPECT_EQ(buf, std::vector<uint8_t>(64, kFill)) << side_name(s);
    glBegin(GL_TRIANGLES);
    glReadPixels(0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, buf.data());
    glEnd();
    EXPECT_EQ(enum_name(glGetError()), "GL_INVALID_OPERATION") << side_name(s);
    EXPECT_EQ(buf, std::vector<uint8_t>(64, kFill)) << side_name(s);
  }
}

}  // namespace
}  // namespace ffc::state_test
