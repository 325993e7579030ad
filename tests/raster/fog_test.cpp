// Fog and polygon offset against Mesa 22.3 (llvmpipe), generated cases: fog's pictures (random
// modes, parameters, colours and cameras; flat and smooth, lit and unlit; triangles, lines and
// points) compared pixel for pixel within one step, fed-back colours (fog is applied to
// fragments only), and the depth buffer under GL_POLYGON_OFFSET_FILL value for value (random
// factors and units of either sign, both windings, reversed depth ranges).
#include <GL/gl.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <functional>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "backends/backend.h"
#include "gl/dispatch.h"
#include "state/context.h"

namespace ffc {
namespace {

constexpr int kSize = 64;

struct Pair {
  std::unique_ptr<backends::Backend> mesa = backends::make("mesa"), soft = backends::make("soft");
  Pair() { mesa->begin(kSize, kSize), soft->begin(kSize, kSize); }
};
Pair& pair() {
  static Pair* p = new Pair;  // never destroyed: Mesa's exit handlers stop llvmpipe first
  return *p;
}

// The state a case sets, back to GL's defaults.
void reset() {
  glDisable(GL_FOG), glDisable(GL_LIGHTING), glDisable(GL_LIGHT0), glDisable(GL_DEPTH_TEST);
  glDisable(GL_POLYGON_OFFSET_FILL), glDisable(GL_CULL_FACE);
  glPolygonOffset(0, 0);
  glFogi(GL_FOG_MODE, GL_EXP), glFogf(GL_FOG_DENSITY, 1), glFogf(GL_FOG_START, 0), glFogf(GL_FOG_END, 1);
  const GLfloat black[4] = {0, 0, 0, 0};
  glFogfv(GL_FOG_COLOR, black);
  glFogi(GL_FOG_COORD_SRC, GL_FRAGMENT_DEPTH);
  glShadeModel(GL_SMOOTH), glPointSize(1), glLineWidth(1);
  glDepthFunc(GL_LESS), glDepthRange(0, 1);
  glMatrixMode(GL_PROJECTION), glLoadIdentity();
  glMatrixMode(GL_MODELVIEW), glLoadIdentity();
}

float uni(std::mt19937& rng, float lo, float hi) { return std::uniform_real_distribution<float>(lo, hi)(rng); }

// One random fogged case: camera, fog state, then a primitive of random kind and vertices.
void fog_case(int seed, bool fog = true) {
  std::mt19937 rng(seed);
  const int kind = seed % 3;  // triangles, lines, points
  glMatrixMode(GL_PROJECTION);
  if (seed % 4 == 0) glOrtho(-1, 1, -1, 1, uni(rng, -3, 0), uni(rng, 4, 8));
  else glFrustum(-0.6, 0.6, -0.6, 0.6, uni(rng, 0.5f, 1.0f), uni(rng, 4, 10));
  glMatrixMode(GL_MODELVIEW);
  glTranslatef(uni(rng, -0.2f, 0.2f), uni(rng, -0.2f, 0.2f), uni(rng, -3.0f, -1.5f));
  glRotatef(uni(rng, 0, 360), uni(rng, -1, 1), uni(rng, -1, 1), uni(rng, -1, 1) + 0.01f);
  const GLenum modes[] = {GL_LINEAR, GL_EXP, GL_EXP2};
  if (fog) glEnable(GL_FOG);
  glFogi(GL_FOG_MODE, modes[(seed / 3) % 3]);
  glFogf(GL_FOG_DENSITY, uni(rng, 0, 1.5f));
  const float start = uni(rng, -1, 2.5f);
  glFogf(GL_FOG_START, start);
  glFogf(GL_FOG_END, seed % 17 == 0 ? start : start + uni(rng, -1, 3));
  GLfloat color[4] = {uni(rng, -0.2f, 1.2f), uni(rng, 0, 1), uni(rng, 0, 1), uni(rng, 0, 1)};
  glFogfv(GL_FOG_COLOR, color);
  if (seed % 23 == 0) glFogi(GL_FOG_COORD_SRC, GL_FOG_COORD);  // the current coordinate: 0
  glShadeModel(seed % 2 ? GL_FLAT : GL_SMOOTH);
  const bool lit = (seed / 2) % 2;
  if (lit) {
    glEnable(GL_LIGHTING), glEnable(GL_LIGHT0);
    const GLfloat pos[4] = {uni(rng, -1, 1), uni(rng, -1, 1), 1, 0};
    glLightfv(GL_LIGHT0, GL_POSITION, pos);
  }
  if (kind == 1) glLineWidth(float(1 + seed % 3));
  if (kind == 2) glPointSize(float(1 + seed % 5));
  glBegin(kind == 0 ? GL_TRIANGLES : kind == 1 ? GL_LINES : GL_POINTS);
  const int n = kind == 0 ? 6 : kind == 1 ? 6 : 8;
  for (int k = 0; k < n; ++k) {
    glColor3f(uni(rng, 0, 1), uni(rng, 0, 1), uni(rng, 0, 1));
    glNormal3f(uni(rng, -1, 1), uni(rng, -1, 1), 1);
    glVertex3f(uni(rng, -0.9f, 0.9f), uni(rng, -0.9f, 0.9f), uni(rng, -0.9f, 0.9f));
  }
  glEnd();
}

image::Image picture(backends::Backend& b, int seed) {
  b.resume();
  reset();
  glClearColor(0, 0, 0, 0);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  fog_case(seed);
  return b.read();
}

TEST(Fog, PicturesMatchMesa) {
  constexpr int kCases = 600;
  int differ = 0, fogged = 0;
  long pixels = 0;
  std::string first;
  for (int seed = 0; seed < kCases; ++seed) {
    const image::Image m = picture(*pair().mesa, seed), s = picture(*pair().soft, seed);
    int off = 0;
    for (int y = 0; y < kSize; ++y)
      for (int x = 0; x < kSize; ++x) {
        const uint8_t *p = m.at(x, y), *q = s.at(x, y);
        pixels += (p[0] | p[1] | p[2] | p[3]) != 0;
        for (int k = 0; k < 4; ++k)
          if (std::abs(int(p[k]) - int(q[k])) > 1) {
            if (first.empty())
              first = "case " + std::to_string(seed) + " pixel " + std::to_string(x) + "," + std::to_string(y) +
                      ": Mesa " + std::to_string(p[0]) + " " + std::to_string(p[1]) + " " + std::to_string(p[2]) +
                      ", ours " + std::to_string(q[0]) + " " + std::to_string(q[1]) + " " + std::to_string(q[2]);
            ++off;
            break;
          }
      }
    differ += off > 0;
    fogged += 1;
  }
  EXPECT_EQ(differ, 0) << differ << " of " << fogged << " cases differ by more than 1; first: " << first;
  EXPECT_GT(pixels, long(kCases) * 20);  // the cases draw something
}

// Fog does not touch what feedback reports (Mesa's feedback takes the vertex colours; fog is a
// per-fragment operation): on either backend the buffer with fog on equals the one with fog off,
// and soft's equals Mesa's wherever it does without fog.
TEST(Fog, FeedbackUnchanged) {
  int compared = 0;
  for (int seed = 0; seed < 120; ++seed) {
    std::vector<GLfloat> out[2][2];  // backend, fog
    backends::Backend* be[2] = {pair().mesa.get(), pair().soft.get()};
    for (int b = 0; b < 2; ++b)
      for (int fog = 0; fog < 2; ++fog) {
        be[b]->resume();
        reset();
        std::vector<GLfloat>& buf = out[b][fog];
        buf.assign(4096, -1);
        glFeedbackBuffer(GLsizei(buf.size()), GL_3D_COLOR, buf.data());
        glRenderMode(GL_FEEDBACK);
        fog_case(seed, fog);
        buf.resize(size_t(std::max(0, glRenderMode(GL_RENDER))));
      }
    ASSERT_FALSE(out[0][1].empty()) << "case " << seed;
    EXPECT_EQ(out[0][1], out[0][0]) << "case " << seed;
    EXPECT_EQ(out[1][1], out[1][0]) << "case " << seed;
    auto close = [](const std::vector<GLfloat>& a, const std::vector<GLfloat>& b) {
      if (a.size() != b.size()) return false;
      for (size_t i = 0; i < a.size(); ++i)
        if (!(std::abs(a[i] - b[i]) <= 1e-3f * (1 + std::abs(a[i])))) return false;
      return true;
    };
    if (!close(out[0][0], out[1][0])) continue;  // a difference of feedback itself, not of fog
    ++compared;
    EXPECT_TRUE(close(out[0][1], out[1][1])) << "case " << seed;
  }
  EXPECT_GT(compared, 100);
}

// The depth buffer under polygon offset: one random triangle (inside the view volume) drawn with
// GL_ALWAYS, random factor and units, perspective or orthographic, random and reversed depth
// ranges; 24-bit values, bottom row first.
std::vector<uint32_t> offset_depth(backends::Backend& be, int seed, bool soft, bool offset = true) {
  std::mt19937 rng(seed);
  be.resume();
  reset();
  glClearDepth(seed % 5 == 0 ? 0.5 : 1);
  glClear(GL_DEPTH_BUFFER_BIT | GL_COLOR_BUFFER_BIT);
  glClearDepth(1);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_ALWAYS);
  double n = uni(rng, 0, 1), f = uni(rng, 0, 1);
  if (seed % 3 == 0) n = 1, f = 0;
  glDepthRange(n, f);
  glMatrixMode(GL_PROJECTION);
  if (seed % 4 == 0) glOrtho(-1, 1, -1, 1, -1, 1);
  else glFrustum(-0.6, 0.6, -0.6, 0.6, 1, 4);
  glMatrixMode(GL_MODELVIEW);
  if (seed % 4) glTranslatef(uni(rng, -0.1f, 0.1f), uni(rng, -0.1f, 0.1f), -2.2f + uni(rng, -0.5f, 0.5f));
  glRotatef(uni(rng, 0, 360), uni(rng, -0.5f, 0.5f), uni(rng, -0.5f, 0.5f), uni(rng, -0.5f, 0.5f));
  if (offset) glEnable(GL_POLYGON_OFFSET_FILL);
  const float factor = seed % 7 == 0 ? 0 : uni(rng, -4, 4);
  float units = seed % 11 == 0 ? 0 : seed % 5 == 1 ? uni(rng, -100000, 100000) : uni(rng, -8, 8);
  if (seed % 13 == 2) units = uni(rng, -1.2e7f, 1.2e7f);  // past the buffer's range: the clamp
  glPolygonOffset(factor, units);
  glBegin(GL_TRIANGLES);
  for (int k = 0; k < 3; ++k) glVertex3f(uni(rng, -0.5f, 0.5f), uni(rng, -0.5f, 0.5f), uni(rng, -0.5f, 0.5f));
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

TEST(PolygonOffset, DepthMatchesMesaValueForValue) {
  size_t pixels = 0, off = 0, moved = 0;
  constexpr int kCases = 400;
  for (int seed = 0; seed < kCases; ++seed) {
    const std::vector<uint32_t> a = offset_depth(*pair().mesa, seed, false), b = offset_depth(*pair().soft, seed, true);
    const std::vector<uint32_t> c = offset_depth(*pair().mesa, seed, false, false);
    for (size_t i = 0; i < a.size(); ++i) {
      ++pixels;
      moved += a[i] != c[i];
      if (a[i] != b[i] && ++off <= 5)
        ADD_FAILURE() << "case " << seed << " pixel " << i % kSize << "," << i / kSize << ": Mesa " << a[i]
                      << ", ours " << b[i];
    }
  }
  EXPECT_EQ(off, 0u) << "of " << pixels << " pixels";
  EXPECT_GT(moved, size_t(kCases) * 20);  // the offset moves most cases' depth
}

}  // namespace
}  // namespace ffc
