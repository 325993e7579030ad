// Depth ties as Mesa's llvmpipe decides them: a mesh drawn a second time over itself, triangles
// overlapping in one plane, and lines and points lying on triangles, under every depth function.
// Where two fragments have (nearly) the same depth, which one stays depends on the exact bits of
// llvmpipe's float depth planes (triangles: raster/setup.h, raster/pixel_rules.h; lines: draw_line), on the vertex order
// it sets up and on the 24-bit conversion; the colour and the depth buffers must both equal
// Mesa's, value for value. Each draw has one colour from glColor3ub, which interpolates to itself,
// so any difference is a coverage or depth decision.
//
// Generated cases: random height fields (a grid of shared vertices, glDrawElements) drawn twice
// with a random second depth function, random sets of triangles lying in one random plane
// (glBegin), and lines and points lying on such triangles, each under random perspective or
// orthographic cameras and random depth ranges, reversed ones among them; each also drawn by the
// scalar path. The geometry stays inside the view volume: a triangle clipped by the near plane
// gets depths a unit or a few from Mesa's (its new vertices are computed in double, Mesa's
// clipper in float).
#include <gtest/gtest.h>

#include <cstdio>
#include <cstring>
#include <random>
#include <string>

#include "backends/backend.h"
#include "gl/dispatch.h"
#include "image/image.h"
#include "raster/wide/kernels.h"
#include "state/context.h"

namespace ffc {
namespace {

constexpr int kSize = 128;
constexpr GLenum kFuncs[] = {GL_NEVER, GL_LESS, GL_EQUAL, GL_LEQUAL, GL_GREATER, GL_NOTEQUAL, GL_GEQUAL, GL_ALWAYS};

struct Buffers {
  std::vector<uint8_t> color;
  std::vector<uint32_t> depth;  // 24-bit values, bottom row first
};

Buffers read_back(backends::Backend& be, bool soft) {
  Buffers b;
  b.color.resize(size_t(kSize) * kSize * 4);
  b.depth.resize(size_t(kSize) * kSize);
  if (soft) {
    const raster::Framebuffer& fb = state::Context::current()->framebuffer();
    b.depth.assign(fb.depth.begin(), fb.depth.end());
  } else {
    glFinish();
    glReadPixels(0, 0, kSize, kSize, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, b.depth.data());
    for (uint32_t& v : b.depth) v >>= 8;  // 24 bits in the high end
  }
  glReadPixels(0, 0, kSize, kSize, GL_RGBA, GL_UNSIGNED_BYTE, b.color.data());
  (void)be;
  return b;
}

// The camera, depth range and first depth function of a case.
void set_up(std::mt19937& rng, int seed) {
  std::uniform_real_distribution<float> u(-0.5f, 0.5f), r(0, 1);
  glClearDepth(seed % 5 == 0 ? 0.0 : 1.0);
  glClear(GL_DEPTH_BUFFER_BIT | GL_COLOR_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  // Smooth colour (constant per draw, so exact after rounding) takes the triangle list's
  // eight-at-a-time set-up (setup8), flat the one-by-one set-up: each has its own depth plane copy.
  glShadeModel(seed % 2 ? GL_SMOOTH : GL_FLAT);
  double n = r(rng), f = r(rng);
  if (seed % 3 == 0) n = 1, f = 0;  // reversed
  if (seed % 7 == 0) n = 0, f = 1;
  glDepthRange(n, f);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  const bool ortho = seed % 4 == 0;
  if (ortho) glOrtho(-1, 1, -1, 1, -2, 2);
  else glFrustum(-0.6, 0.6, -0.6, 0.6, 1, 5);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  if (!ortho) glTranslatef(u(rng) * 0.2f, u(rng) * 0.2f, -2.5f + u(rng));
  glRotatef(360 * r(rng), u(rng), u(rng), u(rng));
}

// A height field of (g+1)^2 shared vertices over [-0.7, 0.7]^2, drawn with glDrawElements, then
// drawn again in another colour under a random depth function.
Buffers height_field(backends::Backend& be, int seed, bool soft, std::string* what) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> r(0, 1);
  be.begin(kSize, kSize);
  set_up(rng, seed);
  const int g = 1 + int(rng() % 8);
  std::vector<float> v;
  for (int j = 0; j <= g; ++j)
    for (int i = 0; i <= g; ++i) v.insert(v.end(), {-0.7f + 1.4f * i / g, -0.7f + 1.4f * j / g, 0.5f * (r(rng) - 0.5f)});
  std::vector<GLuint> idx;
  for (int j = 0; j < g; ++j)
    for (int i = 0; i < g; ++i) {
      const GLuint a = GLuint(j * (g + 1) + i), b = a + 1, c = a + GLuint(g + 1), d = c + 1;
      if (rng() % 2) idx.insert(idx.end(), {a, b, d, a, d, c});
      else idx.insert(idx.end(), {a, b, c, b, d, c});
    }
  glEnableClientState(GL_VERTEX_ARRAY);
  glVertexPointer(3, GL_FLOAT, 0, v.data());
  const GLenum first = rng() % 2 ? GL_LESS : kFuncs[rng() % 8], second = kFuncs[rng() % 8];
  glDepthFunc(first);
  glColor3ub(200, 40, 0);
  glDrawElements(GL_TRIANGLES, GLsizei(idx.size()), GL_UNSIGNED_INT, idx.data());
  glDepthFunc(second);
  glColor3ub(0, 90, 250);
  if (rng() % 2) {  // the same triangles, or each one's vertices rotated (another set-up order)
    for (size_t t = 0; t < idx.size(); t += 3) std::swap(idx[t], idx[t + 1]), std::swap(idx[t + 1], idx[t + 2]);
  }
  glDrawElements(GL_TRIANGLES, GLsizei(idx.size()), GL_UNSIGNED_INT, idx.data());
  glDisableClientState(GL_VERTEX_ARRAY);
  *what = "height field " + std::to_string(g) + "x" + std::to_string(g) + ", depth functions 0x" +
          [](unsigned x) { char s[16]; std::snprintf(s, sizeof s, "%x/%x", x & 0xffff, x >> 16); return std::string(s); }(first | second << 16);
  return read_back(be, soft);
}

// Triangles with random vertices in one random plane, each in its own colour, under random depth
// functions: every overlap is a tie up to the planes' rounding.
Buffers coplanar(backends::Backend& be, int seed, bool soft, std::string* what) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(-0.7f, 0.7f), r(0, 1);
  be.begin(kSize, kSize);
  set_up(rng, seed);
  const float tilt_x = 0.6f * (r(rng) - 0.5f), tilt_y = 0.6f * (r(rng) - 0.5f);
  const int count = 2 + int(rng() % 5);
  *what = "coplanar " + std::to_string(count) + " triangles, depth functions";
  for (int k = 0; k < count; ++k) {
    const GLenum f = k == 0 ? GL_LESS : kFuncs[rng() % 8];
    glDepthFunc(f);
    char s[12];
    std::snprintf(s, sizeof s, " 0x%x", f);
    *what += s;
    glColor3ub(uint8_t(40 * k + 30), uint8_t(255 - 50 * k), uint8_t(rng() % 256));
    glBegin(GL_TRIANGLES);
    for (int i = 0; i < 3; ++i) {
      const float x = u(rng), y = u(rng);
      glVertex3f(x, y, tilt_x * x + tilt_y * y);
    }
    glEnd();
  }
  return read_back(be, soft);
}

// Triangles in one random plane, then lines and points (random sizes) lying in it, as seed 000's
// axes end on the cube's faces: a line's and a point's depth against a triangle's.
Buffers lines_on_plane(backends::Backend& be, int seed, bool soft, std::string* what) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(-0.7f, 0.7f), r(0, 1);
  be.begin(kSize, kSize);
  set_up(rng, seed);
  const float tilt_x = 0.6f * (r(rng) - 0.5f), tilt_y = 0.6f * (r(rng) - 0.5f);
  auto vertex = [&](float x, float y) { glVertex3f(x, y, tilt_x * x + tilt_y * y); };
  glDepthFunc(GL_LESS);
  glColor3ub(200, 40, 0);
  glBegin(GL_TRIANGLES);
  for (int i = 0; i < 6; ++i) vertex(u(rng), u(rng));
  glEnd();
  const GLenum f = kFuncs[rng() % 8];
  glDepthFunc(f);
  *what = "lines on a plane, depth function 0x" + [f] { char t[8]; std::snprintf(t, sizeof t, "%x", f); return std::string(t); }();
  glColor3ub(0, 255, 0);
  glBegin(GL_LINES);
  for (int i = 0; i < 16; ++i) vertex(u(rng), u(rng));
  glEnd();
  glColor3ub(250, 0, 200);
  glPointSize(float(1 + rng() % 4));
  glBegin(GL_POINTS);
  for (int i = 0; i < 16; ++i) vertex(u(rng), u(rng));
  glEnd();
  return read_back(be, soft);
}

template <typename Case>
void compare(Case draw, int cases, int first_seed) {
  auto mesa = backends::make("mesa"), soft = backends::make("soft");
  const bool wide = raster::detail::wide_kernels();
  size_t drawn = 0, failed_cases = 0;
  for (int seed = first_seed; seed < first_seed + cases; ++seed) {
    std::string what;
    const Buffers a = draw(*mesa, seed, false, &what), b = draw(*soft, seed, true, &what);
    // The scalar path (no AVX-512 kernels) decides every tie as the kernels do.
    raster::detail::set_wide_kernels(false);
    const Buffers scalar = draw(*soft, seed, true, &what);
    raster::detail::set_wide_kernels(wide);
    EXPECT_TRUE(scalar.color == b.color && scalar.depth == b.depth) << "case " << seed << ": scalar path differs";
    size_t color_off = 0, depth_off = 0, first = SIZE_MAX;
    for (size_t i = 0; i < a.depth.size(); ++i) {
      const bool c = std::memcmp(&a.color[4 * i], &b.color[4 * i], 4) != 0, d = a.depth[i] != b.depth[i];
      color_off += c, depth_off += d;
      if ((c || d) && first == SIZE_MAX) first = i;
      drawn += a.color[4 * i] | a.color[4 * i + 1] | a.color[4 * i + 2];
    }
    if (color_off || depth_off) {
      if (++failed_cases <= 5)
        ADD_FAILURE() << "case " << seed << " (" << what << "): " << color_off << " colours, " << depth_off
                      << " depths differ; first at " << first % kSize << "," << first / kSize << ": Mesa depth "
                      << a.depth[first] << " colour " << int(a.color[4 * first]) << "," << int(a.color[4 * first + 1])
                      << ", ours " << b.depth[first] << " colour " << int(b.color[4 * first]) << ","
                      << int(b.color[4 * first + 1]);
    }
  }
  EXPECT_EQ(failed_cases, 0u) << "of " << cases << " cases";
  EXPECT_GT(drawn, size_t(cases) * 100);  // the draws cover something
}

TEST(DepthTies, MeshDrawnTwiceMatchesMesa) { compare(height_field, 120, 0); }

TEST(DepthTies, CoplanarTrianglesMatchMesa) { compare(coplanar, 120, 1000); }

TEST(DepthTies, LinesAndPointsOnTrianglesMatchMesa) { compare(lines_on_plane, 120, 2000); }

}  // namespace
}  // namespace ffc

