// The Highway kernels (raster/wide/: the box kernel for boxes of at most 8x8 pixel centres, the
// span kernel for long rows of large triangles, the rows kernel, the triangle lists' draw loop),
// on every vector target this CPU runs (AVX-512, AVX2, SSE4, SSSE3; NEON), draw what the scalar
// row loop draws, bit for bit: many small triangles of random size, place, depth, 1/w and colour,
// under every depth function, with 1 to 3 threads (rows in bands of 64), cut by the
// framebuffer's edges.
#include <gtest/gtest.h>

#include "triangles.h"

namespace ffc {
namespace {

using namespace raster_test;

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
}  // namespace ffc
