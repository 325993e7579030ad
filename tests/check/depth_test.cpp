// Depth as Mesa's llvmpipe computes it: which of two triangles at (nearly) the same depth covers
// a pixel depends on the exact float bits of llvmpipe's depth plane and of its conversion to the
// 24-bit buffer (raster/setup.h depth_plane, raster/pixel_rules.h depth_at, depth24), so the depth buffer itself is
// compared with Mesa's, value for value. Generated cases: random triangles in random vertex order
// (clockwise and counter-clockwise) under random perspective cameras and random depth ranges,
// reversed ones among them.
#include <gtest/gtest.h>

#include <cstdlib>
#include <random>

#include "backends/backend.h"
#include "gl/dispatch.h"
#include "state/context.h"

namespace ffc {
namespace {

constexpr int kSize = 64;

// One random triangle (inside the view volume: clipped vertices are computed otherwise, see the
// report) drawn with GL_ALWAYS; the depth buffer as 24-bit values, bottom row first.
std::vector<uint32_t> depth_of(backends::Backend& be, int seed, bool soft) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(-0.5f, 0.5f), r(0, 1);
  be.begin(kSize, kSize);
  glClear(GL_DEPTH_BUFFER_BIT | GL_COLOR_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_ALWAYS);
  double n = r(rng), f = r(rng);
  if (seed % 3 == 0) n = 1, f = 0;  // glDepthRange(1, 0)
  glDepthRange(n, f);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  if (seed % 4 == 0) glOrtho(-1, 1, -1, 1, -1, 1);
  else glFrustum(-0.6, 0.6, -0.6, 0.6, 1, 4);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  if (seed % 4) glTranslatef(u(rng) * 0.2f, u(rng) * 0.2f, -2.2f + u(rng));
  glRotatef(360 * r(rng), u(rng), u(rng), u(rng));
  glBegin(GL_TRIANGLES);
  for (int k = 0; k < 3; ++k) glVertex3f(u(rng), u(rng), u(rng));
  glEnd();
  std::vector<uint32_t> out(kSize * kSize);
  if (soft) {
    const raster::Framebuffer& fb = state::Context::current()->framebuffer();
    out.assign(fb.depth.begin(), fb.depth.end());
  } else {
    glReadPixels(0, 0, kSize, kSize, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, out.data());
    for (uint32_t& v : out) v >>= 8;  // 24 bits in the high end
  }
  return out;
}

TEST(Depth, BufferMatchesMesaValueForValue) {
  auto mesa = backends::make("mesa"), soft = backends::make("soft");
  size_t pixels = 0, off = 0;
  constexpr int kCases = 300;
  for (int seed = 0; seed < kCases; ++seed) {
    const std::vector<uint32_t> a = depth_of(*mesa, seed, false), b = depth_of(*soft, seed, true);
    for (size_t i = 0; i < a.size(); ++i) {
      if (a[i] == 0xFFFFFF && b[i] == 0xFFFFFF) continue;  // the clear value: not drawn
      ++pixels;
      if (a[i] != b[i] && ++off <= 5)
        ADD_FAILURE() << "case " << seed << " pixel " << i % kSize << "," << i / kSize << ": Mesa " << a[i]
                      << ", ours " << b[i];
    }
  }
  EXPECT_EQ(off, 0u) << "of " << pixels << " pixels";
  EXPECT_GT(pixels, size_t(kCases) * 50);  // the triangles cover something
}

}  // namespace
}  // namespace ffc
