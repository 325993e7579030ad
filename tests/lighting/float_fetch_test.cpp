// The float stage reads GL_FLOAT client arrays straight into its columns (vertex_stage.cpp's
// fetch_float_arrays); any other type goes through array_vertex's record in double. The same
// values held as GL_DOUBLE take the second way, so each picture and depth buffer drawn from float
// arrays must be the bytes drawn from double ones: every vertex size, the colour array of 3 or 4
// components or the current colour, the normal array or the current normal, lit or not, on the
// triangle list (GL_TRIANGLES) and on the general path (a strip long enough for the threads).
#include "gl/dispatch.h"  // the gl* names reach the current backend
#include <gtest/gtest.h>

#include <random>
#include <string>
#include <vector>

#include "backends/backend.h"
#include "state/context.h"

namespace ffc {
namespace {

struct Arrays {
  std::vector<float> pos, normal, color;
};

Arrays random_arrays(size_t n, int vsize, int csize, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(-1, 1), c(-0.2f, 1.2f), w(0.8f, 1.3f);
  Arrays a;
  for (size_t i = 0; i < n; ++i) {
    for (int k = 0; k < vsize; ++k) a.pos.push_back(k == 3 ? w(rng) : u(rng));
    for (int k = 0; k < 3; ++k) a.normal.push_back(u(rng));
    for (int k = 0; k < csize; ++k) a.color.push_back(c(rng));
  }
  return a;
}

struct Picture {
  std::vector<uint8_t> color;
  std::vector<uint32_t> depth;
};

// Draws `a` as `type` (GL_FLOAT or GL_DOUBLE) arrays.
Picture draw(const Arrays& a, GLenum type, GLenum mode, int vsize, int csize, bool normals, bool lit) {
  std::vector<double> pos(a.pos.begin(), a.pos.end()), normal(a.normal.begin(), a.normal.end()),
      color(a.color.begin(), a.color.end());
  auto ptr = [type](const std::vector<float>& f, const std::vector<double>& d) -> const void* {
    return type == GL_FLOAT ? static_cast<const void*>(f.data()) : static_cast<const void*>(d.data());
  };
  glClearColor(0, 0, 0, 0);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  lit ? glEnable(GL_LIGHTING) : glDisable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  glEnable(GL_NORMALIZE);
  glEnable(GL_COLOR_MATERIAL);
  glColor4f(0.3f, 0.6f, 0.9f, 0.7f);
  glNormal3f(0.2f, 0.3f, 0.9f);
  glEnableClientState(GL_VERTEX_ARRAY);
  glVertexPointer(vsize, type, 0, ptr(a.pos, pos));
  normals ? glEnableClientState(GL_NORMAL_ARRAY) : glDisableClientState(GL_NORMAL_ARRAY);
  glNormalPointer(type, 0, ptr(a.normal, normal));
  csize ? glEnableClientState(GL_COLOR_ARRAY) : glDisableClientState(GL_COLOR_ARRAY);
  if (csize) glColorPointer(csize, type, 0, ptr(a.color, color));
  glDrawArrays(mode, 0, GLsizei(a.pos.size() / size_t(vsize)));
  glDisableClientState(GL_VERTEX_ARRAY), glDisableClientState(GL_NORMAL_ARRAY), glDisableClientState(GL_COLOR_ARRAY);
  const raster::Framebuffer& fb = state::Context::current()->framebuffer();
  return {fb.color, fb.depth};
}

TEST(FloatFetch, FloatArraysDrawTheBytesOfTheSameValuesInDouble) {
  auto soft = backends::make("soft");
  soft->begin(96, 96);
  unsigned seed = 1;
  for (GLenum mode : {GLenum(GL_TRIANGLES), GLenum(GL_TRIANGLE_STRIP)})
    for (int vsize : {2, 3, 4})
      for (int csize : {0, 3, 4})
        for (bool normals : {false, true})
          for (bool lit : {false, true}) {
            // A strip of 9000 vertices reaches the threads' path (arrays_to_vertices).
            const Arrays a = random_arrays(mode == GL_TRIANGLES ? 300 : 9000, vsize, csize, seed++);
            const std::string what = std::string(mode == GL_TRIANGLES ? "triangles" : "strip") + " size " +
                                     std::to_string(vsize) + " colour " + std::to_string(csize) +
                                     (normals ? " normals" : "") + (lit ? " lit" : "");
            const Picture want = draw(a, GL_DOUBLE, mode, vsize, csize, normals, lit);
            const Picture got = draw(a, GL_FLOAT, mode, vsize, csize, normals, lit);
            size_t drawn = 0;
            for (size_t i = 0; i < want.color.size(); i += 4) drawn += (want.color[i] | want.color[i + 1] | want.color[i + 2]) != 0;
            EXPECT_GT(drawn, 0u) << what;
            EXPECT_TRUE(got.color == want.color) << what;
            EXPECT_TRUE(got.depth == want.depth) << what;
          }
}

}  // namespace
}  // namespace ffc
