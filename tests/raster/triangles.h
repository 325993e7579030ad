// Random triangles drawn through a soft context under a chosen rasterizer configuration: shared by
// the tests that hold the fast paths to the scalar row loop and to the reference rasterizer.
#pragma once
#include <random>
#include <vector>

#include "backends/backend.h"
#include "gl/dispatch.h"
#include "image/compare.h"
#include "raster/wide/kernels.h"
#include "simd/target.h"
#include "raster/raster.h"
#include "raster/reference.h"
#include "state/context.h"

namespace ffc::raster_test {

inline constexpr int kWidth = 150, kHeight = 141;  // three bands of rows; odd sizes: boxes at the edges

struct Triangles {
  std::vector<float> xyzw, rgba;
};

// n triangles, each within `size` pixels: its corners around a random centre (some beyond the
// framebuffer's edges), depths and w (perspective: colour / w interpolated) random per corner.
// across_bands: centres within two rows of a band's edge (rows 64 and 128), where two threads
// share a triangle's rows. width, height: the framebuffer's.
inline Triangles random_triangles(int n, float size, unsigned seed, bool across_bands = false, int width = kWidth, int height = kHeight) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(0, 1);
  Triangles t;
  for (int i = 0; i < n; ++i) {
    const float cx = -8 + u(rng) * float(width + 16), z = u(rng) * 1.8f - 0.9f;
    const float cy = across_bands ? (i % 2 ? 64 : 128) + 4 * (u(rng) - 0.5f) : -8 + u(rng) * float(height + 16);
    for (int k = 0; k < 3; ++k) {
      const float w = 0.5f + 2 * u(rng);
      const float x = cx + (u(rng) - 0.5f) * size, y = cy + (u(rng) - 0.5f) * size;
      // Window (x, y) from clip coordinates over the whole framebuffer, times w.
      t.xyzw.insert(t.xyzw.end(), {(2 * x / float(width) - 1) * w, (2 * y / float(height) - 1) * w, (z + 0.1f * (u(rng) - 0.5f)) * w, w});
      t.rgba.insert(t.rgba.end(), {u(rng), u(rng), u(rng), u(rng)});
    }
  }
  return t;
}

// The vector targets this CPU runs (simd::available() but the portable "scalar", whose draws
// are the scalar loops'), best first: each is held to the scalar loops in turn.
inline std::vector<std::string> vector_targets() {
  std::vector<std::string> out;
  for (const std::string& t : simd::available())
    if (t != "scalar") out.push_back(t);
  return out;
}
// Dispatches to `target` (and worse) while it lives.
struct OnTarget {
  explicit OnTarget(const std::string& target) { EXPECT_TRUE(simd::restrict(target)) << target; }
  ~OnTarget() { simd::restrict(""); }
  OnTarget(const OnTarget&) = delete;
  OnTarget& operator=(const OnTarget&) = delete;
};

struct Drawn {
  image::Image picture;
  std::vector<uint32_t> depth;  // the depth buffer as drawn: rounding shows here before in colour
};

// Drawn with `threads` threads, the wide kernels on or off, triangle lists on or off, the reference
// rasterizer on or off (it needs lists off: triangle lists have their own setup), flat or smooth,
// on a framebuffer of width x height.
inline Drawn draw(const Triangles& t, GLenum depth_func, int threads, bool wide, bool lists, bool reference = false,
                  bool flat = false, int width = kWidth, int height = kHeight) {
  raster::detail::set_wide_kernels(wide);
  raster::set_reference_rasterizer(reference);
  auto soft = backends::make("soft");
  soft->begin(width, height);
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
  glShadeModel(flat ? GL_FLAT : GL_SMOOTH);
  glEnableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_COLOR_ARRAY);
  glVertexPointer(4, GL_FLOAT, 0, t.xyzw.data());
  glColorPointer(4, GL_FLOAT, 0, t.rgba.data());
  glDrawArrays(GL_TRIANGLES, 0, GLsizei(t.xyzw.size() / 4));
  Drawn out{soft->read(), state::Context::current()->framebuffer().depth};
  raster::detail::set_wide_kernels(true);
  raster::set_reference_rasterizer(false);
  return out;
}

}  // namespace ffc::raster_test
