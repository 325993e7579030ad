// The box kernel (raster/box.h: boxes of at most 8x8 pixel centres, 16 pixels at a time), the span
// kernel (long rows of large triangles) and the eight-triangle setup of triangle lists draw what
// the scalar row loop draws, bit for bit: many
// small triangles of random size, place, depth, 1/w and colour, under every depth function, with
// 1 to 3 threads (rows in bands of 64), cut by the framebuffer's edges.
#include <gtest/gtest.h>

#include <random>

#include "backends/backend.h"
#include "gl/dispatch.h"
#include "image/compare.h"
#include "raster/box.h"
#include "raster/raster.h"
#include "state/context.h"

namespace ffc {
namespace {

constexpr int kWidth = 150, kHeight = 141;  // three bands of rows; odd sizes: boxes at the edges

struct Triangles {
  std::vector<float> xyzw, rgba;
};

// n triangles, each within `size` pixels: its corners around a random centre (some beyond the
// framebuffer's edges), depths and w (perspective: colour / w interpolated) random per corner.
// across_bands: centres within two rows of a band's edge (rows 64 and 128), where two threads
// share a triangle's rows.
Triangles random_triangles(int n, float size, unsigned seed, bool across_bands = false) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(0, 1);
  Triangles t;
  for (int i = 0; i < n; ++i) {
    const float cx = -8 + u(rng) * (kWidth + 16), z = u(rng) * 1.8f - 0.9f;
    const float cy = across_bands ? (i % 2 ? 64 : 128) + 4 * (u(rng) - 0.5f) : -8 + u(rng) * (kHeight + 16);
    for (int k = 0; k < 3; ++k) {
      const float w = 0.5f + 2 * u(rng);
      const float x = cx + (u(rng) - 0.5f) * size, y = cy + (u(rng) - 0.5f) * size;
      // Window (x, y) from clip coordinates over the whole framebuffer, times w.
      t.xyzw.insert(t.xyzw.end(), {(2 * x / kWidth - 1) * w, (2 * y / kHeight - 1) * w, (z + 0.1f * (u(rng) - 0.5f)) * w, w});
      t.rgba.insert(t.rgba.end(), {u(rng), u(rng), u(rng), u(rng)});
    }
  }
  return t;
}

struct Drawn {
  image::Image picture;
  std::vector<uint32_t> depth;  // the depth buffer as drawn: rounding shows here before in colour
};

Drawn draw(const Triangles& t, GLenum depth_func, int threads, bool wide, bool lists) {
  raster::detail::set_wide_kernels(wide);
  auto soft = backends::make("soft");
  soft->begin(kWidth, kHeight);
  state::Context::current()->set_threads(threads);
  state::Context::current()->set_triangle_lists(lists);
  glClearColor(0.1f, 0.2f, 0.3f, 1);
  glClearDepth(0.5);  // GL_GREATER and friends draw too
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  if (depth_func == 0) {  // no depth test: primitive order alone decides
    glDisable(GL_DEPTH_TEST);
  } else {
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(depth_func);
  }
  glShadeModel(GL_SMOOTH);
  glEnableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_COLOR_ARRAY);
  glVertexPointer(4, GL_FLOAT, 0, t.xyzw.data());
  glColorPointer(4, GL_FLOAT, 0, t.rgba.data());
  glDrawArrays(GL_TRIANGLES, 0, GLsizei(t.xyzw.size() / 4));
  Drawn out{soft->read(), state::Context::current()->framebuffer().depth};
  raster::detail::set_wide_kernels(true);
  return out;
}

class BoxKernel : public ::testing::TestWithParam<GLenum> {
 protected:
  void SetUp() override {
    if (!raster::detail::wide_kernels()) GTEST_SKIP() << "this CPU has no AVX-512VL: the kernel does not run";
  }
};

TEST_P(BoxKernel, DrawsWhatTheScalarRowLoopDraws) {
  const GLenum func = GetParam();
  // Sizes: mostly boxes of 4x4 and 8x2 blocks, some larger (the other loops), some slivers; at 40
  // pixels rows of 16 and more (the span kernel).
  for (float size : {3.0f, 6.0f, 9.0f, 14.0f, 40.0f}) {
    const Triangles t = random_triangles(3000, size, unsigned(func) * 31 + unsigned(size));
    const Drawn scalar = draw(t, func, 1, false, false);
    for (int threads : {1, 2, 3})
      for (bool lists : {true, false}) {
        const Drawn wide = draw(t, func, threads, true, lists);
        EXPECT_EQ(image::compare(scalar.picture, wide.picture).max_diff, 0) << lists << ", " << size << " px, " << threads;
        EXPECT_TRUE(scalar.depth == wide.depth) << lists << ", " << size << " px, " << threads;
      }
  }
}

// Triangles across the bands' edges: each thread draws its own rows of them, no more, no fewer.
TEST(BoxKernelBands, TrianglesAcrossBandEdgesDrawEachRowOnce) {
  if (!raster::detail::wide_kernels()) GTEST_SKIP() << "this CPU has no AVX-512VL: the kernel does not run";
  for (float size : {2.0f, 3.0f, 6.0f}) {
    const Triangles t = random_triangles(4000, size, 11 + unsigned(size), true);
    for (GLenum func : {GL_LESS, GL_ALWAYS}) {
      const Drawn scalar = draw(t, func, 1, false, false);
      for (int threads : {2, 3}) {
        const Drawn wide = draw(t, func, threads, true, true);
        EXPECT_EQ(image::compare(scalar.picture, wide.picture).max_diff, 0) << size << " px, " << threads;
        EXPECT_TRUE(scalar.depth == wide.depth) << size << " px, " << threads;
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
