// The reference rasterizer (raster/reference.h) is the rule book; every fast path must draw its
// pictures and depth buffers bit for bit: the scalar row loop, the box and span kernels, the
// triangle lists' own setup, on 1 to 3 threads, flat and smooth, under every depth function, for
// slivers, small, large and huge triangles cut by the framebuffer's edges. And the rules
// themselves, on a triangle worked out by hand.
#include <gtest/gtest.h>

#include "triangles.h"

namespace ffc {
namespace {

using namespace raster_test;

class Reference : public ::testing::TestWithParam<GLenum> {};

TEST_P(Reference, EveryFastPathDrawsWhatTheReferenceDraws) {
  const GLenum func = GetParam();
  for (float size : {1.5f, 5.0f, 12.0f, 40.0f, 400.0f}) {
    const int n = size > 100 ? 40 : 1500;
    const Triangles t = random_triangles(n, size, unsigned(func) * 7 + unsigned(size * 2), size == 5.0f);
    for (bool flat : {false, true}) {
      const Drawn reference = draw(t, func, 1, false, false, true, flat);
      for (bool wide : {false, true})
        for (bool lists : {false, true})
          for (int threads : {1, 3}) {
            const Drawn fast = draw(t, func, threads, wide, lists, false, flat);
            EXPECT_EQ(image::compare(reference.picture, fast.picture).max_diff, 0)
                << size << " px, flat " << flat << ", wide " << wide << ", lists " << lists << ", threads " << threads;
            EXPECT_TRUE(reference.depth == fast.depth)
                << size << " px, flat " << flat << ", wide " << wide << ", lists " << lists << ", threads " << threads;
          }
    }
  }
}

std::string func_name(const ::testing::TestParamInfo<GLenum>& info) {
  static const char* const names[] = {"never", "less", "equal", "lequal", "greater", "notequal", "gequal", "always"};
  return info.param == 0 ? "no_depth_test" : names[info.param - GL_NEVER];
}

INSTANTIATE_TEST_SUITE_P(DepthFunctions, Reference,
                         ::testing::Values(GLenum(0), GL_LESS, GL_EQUAL, GL_LEQUAL, GL_GREATER, GL_ALWAYS), func_name);

// The triangle with corners on the pixel centres (0.5, 0.5), (4.5, 0.5), (0.5, 4.5) of a 16x16
// window. Its left edge (x = 0.5) and bottom edge (y = 0.5) own the centres on them; its
// hypotenuse (x + y = 5) is a right/top edge and owns none. So pixel (X, Y) is drawn exactly when
// X + Y <= 3: 4 + 3 + 2 + 1 = 10 pixels, on every path.
TEST(ReferenceRules, CentresOnEdgesBelongToLeftAndBottomEdgesOnly) {
  for (bool reference : {true, false})
    for (bool lists : {false, true}) {
      if (reference && lists) continue;
      raster::set_reference_rasterizer(reference);
      auto soft = backends::make("soft");
      soft->begin(16, 16);
      state::Context::current()->set_triangle_lists(lists);
      glClearColor(0, 0, 0, 0);
      glClear(GL_COLOR_BUFFER_BIT);
      glMatrixMode(GL_PROJECTION);
      glOrtho(0, 16, 0, 16, -1, 1);
      glColor4f(1, 1, 1, 1);
      const GLfloat xy[6] = {0.5f, 0.5f, 4.5f, 0.5f, 0.5f, 4.5f};
      glEnableClientState(GL_VERTEX_ARRAY);
      glVertexPointer(2, GL_FLOAT, 0, xy);
      glDrawArrays(GL_TRIANGLES, 0, 3);
      const raster::Framebuffer& fb = state::Context::current()->framebuffer();
      for (int Y = 0; Y < 16; ++Y)
        for (int X = 0; X < 16; ++X)
          EXPECT_EQ(fb.color[(size_t(Y) * 16 + size_t(X)) * 4], X + Y <= 3 && X >= 0 && Y >= 0 ? 255 : 0)
              << "pixel " << X << ", " << Y << (reference ? " (reference)" : lists ? " (lists)" : " (row loop)");
      raster::set_reference_rasterizer(false);
    }
}

}  // namespace
}  // namespace ffc
