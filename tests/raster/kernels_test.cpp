// The Highway kernels (raster/wide/: the box kernel for boxes of at most 8x8 pixel centres, the
// span kernel for long rows of large triangles, the rows kernel, the triangle lists' draw loop),
// on every vector target this CPU runs (AVX-512, AVX2, SSE4, SSSE3; NEON), draw what the scalar
// row loop draws, bit for bit: many small triangles of random size, place, depth, 1/w and colour,
// under every depth function, with 1 to 3 threads (rows in bands of 64), cut by the
// framebuffer's edges.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <random>

#include "raster/row_loop.h"
#include "raster/triangle_list_parts.h"
#include "raster/wide/kernels.h"
#include "triangles.h"

namespace ffc {
namespace {

using namespace raster_test;

// Band b belongs to thread b % count; next[b] is a thread's first band at or after b.
TEST(Bands, NextIsTheFirstBandAtOrAfterThatTheThreadOwns) {
  for (int count = 1; count <= 5; ++count)
    for (int mine = 0; mine < count; ++mine) {
      const raster::detail::Bands bands(mine, count);
      for (int b = 0; b <= raster::detail::Bands::kMax; ++b) {
        int want = b;
        while (want % count != mine) ++want;
        ASSERT_EQ(bands.next[size_t(b)], want) << "band " << b << ", thread " << mine << " of " << count;
        EXPECT_EQ(bands.owns(b), b % count == mine);
      }
    }
}

// The list's vertices mapped to the window a vector at a time (map_list_wide) on every vector
// target: map_one's bits, snapped positions and x, y, z, w (and the front colours given as
// columns, each vertex its own), for random clip positions inside and
// outside each plane, with w tiny, huge, zero or negative, NaN and infinite coordinates, and
// positions whose snapped coordinates leave 32 bits, under random viewports and depth ranges.
TEST(MapListVertices, GiveMapOnesBitsOnEveryTarget) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> u(-1, 1);
  const float specials[] = {0.0f, -0.0f, 1e-40f, 0x1p-127f, 0x1p127f, 1e30f, -1e30f, INFINITY, -INFINITY, NAN};
  constexpr size_t kCount = 4099;  // not a whole number of vectors
  std::vector<glm::vec4> clip(kCount);
  for (size_t i = 0; i < kCount; ++i) {
    const float w = 0.1f + 3 * std::abs(u(rng));
    glm::vec4 c{u(rng) * 1.3f * w, u(rng) * 1.3f * w, u(rng) * 1.3f * w, w};
    if (i % 7 == 3) c[int(i / 7 % 4)] = specials[i / 3 % std::size(specials)];
    if (i % 11 == 5) c *= 1e7f;  // far out, still inside where |x| <= w: snapped beyond 2^29
    if (i % 13 == 1) c.w = -c.w;
    clip[i] = c;
  }
  for (int round = 0; round < 20; ++round) {
    raster::State s;
    s.fb_height = 64 + int(rng() % 2000);
    s.viewport = {int(rng() % 200) - 100, int(rng() % 200) - 100, 1 + int(rng() % 4000), 1 + int(rng() % 4000)};
    s.depth_range = {std::abs(u(rng)), std::abs(u(rng))};
    const auto fresh = [&] {
      raster::ListVertices vs;
      vs.resize(kCount, false, false);
      vs.clip = clip;
      return vs;
    };
    raster::ListVertices want = fresh();
    for (size_t i = 0; i < kCount; ++i) raster::detail::map_one(want, i, s);
    size_t mapped = 0;
    for (const raster::Snapped& p : want.snapped) mapped += p.x != raster::kNotMapped;
    EXPECT_GT(mapped, kCount / 3);
    EXPECT_LT(mapped, kCount);
    for (const std::string& target : vector_targets()) {
      const OnTarget on(target);
      for (const size_t first : {size_t(0), size_t(3)}) {
        raster::ListVertices got = fresh();
        // With the front colours from columns on every other round: each vertex's own.
        const bool colours = round % 2;
        std::vector<float> columns[4];
        for (int k = 0; k < 4; ++k)
          for (size_t i = first; i < kCount; ++i) columns[k].push_back(float(i) + 0.25f * float(k));
        const float* const front[4] = {columns[0].data(), columns[1].data(), columns[2].data(), columns[3].data()};
        raster::map_list_vertices(got, first, kCount - first, s, colours ? front : nullptr);
        for (size_t i = first; i < kCount; ++i) {
          if (colours) ASSERT_EQ(got.hot[i].color, glm::vec4(float(i), float(i) + 0.25f, float(i) + 0.5f, float(i) + 0.75f)) << target << ", vertex " << i;
          else ASSERT_EQ(got.hot[i].color, glm::vec4(0)) << target << ", vertex " << i;
          ASSERT_EQ(got.snapped[i].x, want.snapped[i].x) << target << ", vertex " << i << ", round " << round;
          if (want.snapped[i].x == raster::kNotMapped) {
            ASSERT_EQ(std::memcmp(&got.hot[i].w, &want.hot[i].w, 4), 0) << target << ", vertex " << i;
            continue;
          }
          ASSERT_EQ(got.snapped[i].y, want.snapped[i].y) << target << ", vertex " << i << ", round " << round;
          ASSERT_EQ(std::memcmp(&got.hot[i].x, &want.hot[i].x, 16), 0) << target << ", vertex " << i << ", round " << round;
        }
      }
    }
  }
}

class BoxKernel : public ::testing::TestWithParam<GLenum> {
 protected:
  void SetUp() override {
    if (vector_targets().empty()) GTEST_SKIP() << "no vector target: Highway's portable one only";
  }
};

TEST_P(BoxKernel, DrawsWhatTheScalarRowLoopDraws) {
  const GLenum func = GetParam();
  // Sizes: mostly boxes of 4x4 and 8x2 blocks, some larger (the other loops), some slivers; at 40
  // pixels rows of 16 and more (the span kernel).
  for (float size : {3.0f, 6.0f, 9.0f, 14.0f, 40.0f}) {
    const Triangles t = random_triangles(3000, size, unsigned(func) * 31 + unsigned(size));
    const Drawn scalar = draw(t, func, 1, false, false);
    for (const std::string& target : vector_targets()) {
      const OnTarget on(target);
      for (int threads : {1, 2, 3})
        for (bool lists : {true, false}) {
          const Drawn wide = draw(t, func, threads, true, lists);
          EXPECT_EQ(image::compare(scalar.picture, wide.picture).max_diff, 0) << target << ", " << lists << ", " << size << " px, " << threads;
          EXPECT_TRUE(scalar.depth == wide.depth) << target << ", " << lists << ", " << size << " px, " << threads;
        }
    }
  }
}

// Triangles across the bands' edges: each thread draws its own rows of them, no more, no fewer.
TEST(BoxKernelBands, TrianglesAcrossBandEdgesDrawEachRowOnce) {
  if (vector_targets().empty()) GTEST_SKIP() << "no vector target: Highway's portable one only";
  for (float size : {2.0f, 3.0f, 6.0f}) {
    const Triangles t = random_triangles(4000, size, 11 + unsigned(size), true);
    for (GLenum func : {GL_LESS, GL_ALWAYS}) {
      const Drawn scalar = draw(t, func, 1, false, false);
      for (const std::string& target : vector_targets()) {
        const OnTarget on(target);
        for (int threads : {2, 3}) {
          const Drawn wide = draw(t, func, threads, true, true);
          EXPECT_EQ(image::compare(scalar.picture, wide.picture).max_diff, 0) << target << ", " << size << " px, " << threads;
          EXPECT_TRUE(scalar.depth == wide.depth) << target << ", " << size << " px, " << threads;
        }
      }
    }
  }
}

// Triangles wider than the large-triangle paths' column caches (kCachedColumns, 1024 columns): rows
// that reach past them make their own columns' terms. The scalar loops and every target against
// the reference rasterizer.
TEST(LargeTriangles, RowsPastTheColumnCacheDrawWhatTheReferenceDraws) {
  const int width = 2300, height = 70;
  const Triangles t = random_triangles(60, 2600, 5, false, width, height);
  const Drawn reference = draw(t, GL_LESS, 1, false, false, true, false, width, height);
  const Drawn scalar = draw(t, GL_LESS, 2, false, false, false, false, width, height);
  EXPECT_EQ(image::compare(reference.picture, scalar.picture).max_diff, 0);
  EXPECT_TRUE(reference.depth == scalar.depth);
  for (const std::string& target : vector_targets()) {
    const OnTarget on(target);
    for (int threads : {1, 2}) {
      const Drawn wide = draw(t, GL_LESS, threads, true, false, false, false, width, height);
      EXPECT_EQ(image::compare(reference.picture, wide.picture).max_diff, 0) << target << ", " << threads;
      EXPECT_TRUE(reference.depth == wide.depth) << target << ", " << threads;
    }
  }
}

// The depth function is applied, not ignored: each one gives its own picture.
TEST(BoxKernelDepth, EachFunctionGivesItsOwnPicture) {
  const Triangles t = random_triangles(3000, 6, 7);
  std::vector<image::Image> pictures;
  for (GLenum func : {GL_LESS, GL_LEQUAL, GL_GREATER, GL_GEQUAL, GL_NOTEQUAL, GL_ALWAYS})
    pictures.push_back(draw(t, func, 2, true, true).picture);
  for (size_t i = 0; i < pictures.size(); ++i)
    for (size_t j = i + 1; j < pictures.size(); ++j) {
      // LESS and LEQUAL (GREATER and GEQUAL, NOTEQUAL and ALWAYS) differ only where two depths
      // are equal: rare here.
      if ((i == 0 && j == 1) || (i == 2 && j == 3) || (i == 4 && j == 5)) continue;
      EXPECT_GT(image::compare(pictures[i], pictures[j]).differing_share, 0.01) << i << " " << j;
    }
}

std::string func_name(const ::testing::TestParamInfo<GLenum>& info) {
  static const char* const names[] = {"never", "less", "equal", "lequal", "greater", "notequal", "gequal", "always"};
  return info.param == 0 ? "no_depth_test" : names[info.param - GL_NEVER];
}

INSTANTIATE_TEST_SUITE_P(DepthFunctions, BoxKernel,
                         ::testing::Values(GLenum(0), GL_NEVER, GL_LESS, GL_EQUAL, GL_LEQUAL, GL_GREATER, GL_NOTEQUAL, GL_GEQUAL,
                                           GL_ALWAYS),
                         func_name);

}  // namespace
// Depth is llvmpipe's fused multiply-add. Targets without the instruction (SSE4, SSSE3) work in
// double: exact products, one rounding of the sum, a second to float that is right unless the
// double is exactly halfway between two floats. Those cases, built here, must still give std::fma's
// bits, as must random ones (depth-like values and wide exponents).
TEST(FusedMulAdd, EveryTargetRoundsOnceAsStdFma) {
  std::vector<float> a, b, c;
  // (1 + 2^-12)^2 = 1 + 2^-11 + 2^-24: halfway between two floats. A tiny c decides the rounding
  // (up for c > 0, down for c < 0) but vanishes in double, whose tie would round to even (down).
  for (float tiny : {0x1p-60f, -0x1p-60f, 0x1p-40f, 0.0f}) {
    a.push_back(1.0f + 0x1p-12f), b.push_back(1.0f + 0x1p-12f), c.push_back(tiny);
    a.push_back(-(1.0f + 0x1p-12f)), b.push_back(1.0f + 0x1p-12f), c.push_back(tiny);
  }
  a.push_back(0x1p-70f), b.push_back(0x1p-60f), c.push_back(0x1p-149f);  // float's subnormals
  a.push_back(3e38f), b.push_back(2.0f), c.push_back(-3e38f);              // beyond float's range in between
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
  std::uniform_int_distribution<int> exponent(-30, 30);
  for (int i = 0; i < 20000; ++i) {
    a.push_back(std::ldexp(unit(rng), exponent(rng))), b.push_back(std::ldexp(unit(rng), exponent(rng)));
    c.push_back(i % 2 ? unit(rng) : std::ldexp(unit(rng), exponent(rng)));
  }
  std::vector<float> want(a.size()), got(a.size());
  for (size_t i = 0; i < a.size(); ++i) want[i] = std::fma(a[i], b[i], c[i]);
  ASSERT_NE(want[0], float(double(a[0]) * double(b[0]) + double(c[0])))
      << "the first case no longer needs the halfway check: pick another";
  const std::vector<std::string> targets = vector_targets();  // none: the scalar forms alone
  // Fused (the default), and as llvmpipe without FMA rounds them: a product, then a sum
  // (raster::llvmpipe_fma; FFCOMPAT_LLVMPIPE_FMA=0 runs this test in CTest raster_test_unfused).
  const bool was = raster::llvmpipe_fma();
  for (bool fused : {true, false}) {
    raster::set_llvmpipe_fma(fused);
    for (size_t i = 0; i < a.size(); ++i) want[i] = fused ? std::fma(a[i], b[i], c[i]) : a[i] * b[i] + c[i];
    for (size_t i = 0; i < a.size(); ++i) {
      const float row = raster::detail::FusedRowScalar(a[i], b[i])(c[i]);
      ASSERT_EQ(std::memcmp(&want[i], &row, 4), 0) << "row loop, fused " << fused << ": " << a[i] << " * " << b[i] << " + " << c[i];
      const float one = raster::llvmpipe_mul_add(a[i], b[i], c[i]);
      ASSERT_EQ(std::memcmp(&want[i], &one, 4), 0) << "llvmpipe_mul_add, fused " << fused;
    }
    for (const std::string& target : targets) {
      const OnTarget on(target);
      for (bool row : {false, true}) {  // the product made with the sum, or first (a row's)
        raster::detail::fused_mul_add_wide(a.data(), b.data(), c.data(), got.data(), a.size(), row);
        for (size_t i = 0; i < a.size(); ++i)
          ASSERT_EQ(std::memcmp(&want[i], &got[i], 4), 0) << target << (row ? " (row)" : "") << ", fused " << fused << ": fma(" << a[i]
                                                          << ", " << b[i] << ", " << c[i] << ") = " << want[i] << ", got " << got[i];
      }
    }
  }
  raster::set_llvmpipe_fma(was);
}

}  // namespace ffc
