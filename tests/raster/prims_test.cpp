// Points, lines, quads, quad strips and polygons against Mesa 22.3 (llvmpipe), one generated
// primitive at a time: the picture (tests/prims' cases) and the feedback buffer. Each case is
// drawn alone on a cleared 64 x 64 framebuffer on both backends and compared pixel for pixel.
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

namespace ffc {
namespace {

constexpr int kSize = 64;

// One context per backend for the whole run (a context per case costs minutes); each case
// resets the state it uses.
struct Pair {
  std::unique_ptr<backends::Backend> mesa = backends::make("mesa"), soft = backends::make("soft");
  Pair() { mesa->begin(kSize, kSize), soft->begin(kSize, kSize); }
};
Pair& pair() {
  static Pair* p = new Pair;  // never destroyed: Mesa's exit handlers stop llvmpipe first
  return *p;
}
void use(backends::Backend& b) {
  b.resume();
  glPointSize(1), glLineWidth(1), glShadeModel(GL_SMOOTH);
}

// One picture on a backend: cleared, `draw`, the colour buffer.
image::Image picture(backends::Backend& b, const std::function<void()>& draw) {
  use(b);
  glClearColor(0, 0, 0, 0);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  draw();
  return b.read();
}

// Pixels whose channels differ by more than `tolerance`, and pixels drawn on one side only.
struct Diff {
  int pixels = 0, coverage = 0;
};
Diff diff(const image::Image& a, const image::Image& b, int tolerance) {
  Diff d;
  for (int y = 0; y < a.height; ++y)
    for (int x = 0; x < a.width; ++x) {
      const uint8_t *p = a.at(x, y), *q = b.at(x, y);
      const bool da = p[0] | p[1] | p[2] | p[3], db = q[0] | q[1] | q[2] | q[3];
      if (da != db) ++d.coverage;
      for (int k = 0; k < 4; ++k)
        if (std::abs(int(p[k]) - int(q[k])) > tolerance) {
          ++d.pixels;
          break;
        }
    }
  return d;
}

// A window position as a vertex: identity matrices, so NDC = window / 32 - 1 (in float, as given).
void vertex(float x, float y) { glVertex2f(x / (kSize / 2) - 1, y / (kSize / 2) - 1); }

struct Tally {
  int cases = 0, coverage = 0, colour = 0;
  std::string first;
};
void compare(Tally& t, const std::string& what, const std::function<void()>& draw, int tolerance) {
  const image::Image m = picture(*pair().mesa, draw), s = picture(*pair().soft, draw);
  const Diff d = diff(m, s, tolerance);
  ++t.cases;
  if (d.coverage) ++t.coverage;
  if (d.pixels) ++t.colour;
  if ((d.coverage || d.pixels) && t.first.empty()) t.first = what;
}

std::string fmt(const char* f, double a, double b, double c = 0, double d = 0, double e = 0) {
  char buf[256];
  std::snprintf(buf, sizeof buf, f, a, b, c, d, e);
  return buf;
}

// Window coordinates: uniform floats, or (every `grid`-th) on a quarter-pixel grid, where the
// rules' ties (pixel edges, centres, half-way snaps) lie.
float coord(std::mt19937& rng, float lo, float hi, bool on_grid) {
  const float v = std::uniform_real_distribution<float>(lo, hi)(rng);
  return on_grid ? std::floor(v * 4) / 4 : v;
}

TEST(Points, Size1MatchMesa) {
  // Issue 10: a size-1 point landed one pixel right when frac(x) > 0.5.
  std::mt19937 rng(101);
  Tally t;
  for (int i = 0; i < 1000; ++i) {
    const bool grid = i % 4 == 0;
    const float x = coord(rng, -2, 66, grid), y = coord(rng, -2, 66, grid);
    compare(t, fmt("point (%.9g, %.9g)", x, y), [&] {
      glColor3f(1, 0.5f, 0.25f);
      glBegin(GL_POINTS);
      vertex(x, y);
      glEnd();
    }, 0);
  }
  EXPECT_EQ(t.coverage + t.colour, 0) << t.coverage << " of " << t.cases << " differ in coverage, " << t.colour
                                      << " in colour; first: " << t.first;
}

TEST(Points, SizesMatchMesa) {
  std::mt19937 rng(102);
  Tally t;
  for (int i = 0; i < 1000; ++i) {
    const bool grid = i % 3 == 0;
    const float x = coord(rng, -4, 68, grid), y = coord(rng, -4, 68, grid);
    float size = std::uniform_real_distribution<float>(0.1f, 14)(rng);
    if (i % 5 == 0) size = std::floor(size) + 0.5f;  // half sizes round down
    compare(t, fmt("point (%.9g, %.9g) size %.9g", x, y, size), [&] {
      glPointSize(size);
      glColor3f(0.25f, 1, 0.5f);
      glBegin(GL_POINTS);
      vertex(x, y);
      glEnd();
    }, 0);
  }
  EXPECT_EQ(t.coverage + t.colour, 0) << t.coverage << " of " << t.cases << " differ in coverage, " << t.colour
                                      << " in colour; first: " << t.first;
}

void random_line(std::mt19937& rng, int i, float (&p)[4]) {
  const bool grid = i % 4 == 0;
  for (float& v : p) v = coord(rng, -6, 70, grid);
  if (i % 3 == 0) {  // short lines, where the end rules are most of the line
    p[2] = p[0] + coord(rng, -3, 3, grid), p[3] = p[1] + coord(rng, -3, 3, grid);
  }
}

TEST(Lines, Width1MatchMesa) {
  // Issue 10: the first fragment was dropped and the last drawn, the reverse of diamond exit.
  std::mt19937 rng(201);
  Tally t;
  for (int i = 0; i < 1000; ++i) {
    float p[4];
    random_line(rng, i, p);
    compare(t, fmt("line (%.9g, %.9g) - (%.9g, %.9g)", p[0], p[1], p[2], p[3]), [&] {
      glBegin(GL_LINES);
      glColor3f(1, 0, 0.5f);
      vertex(p[0], p[1]);
      glColor3f(0, 1, 0.25f);
      vertex(p[2], p[3]);
      glEnd();
    }, 1);
  }
  EXPECT_EQ(t.coverage + t.colour, 0) << t.coverage << " of " << t.cases << " differ in coverage, " << t.colour
                                      << " in colour by more than 1; first: " << t.first;
}

TEST(Lines, WideMatchMesa) {
  std::mt19937 rng(202);
  Tally t;
  for (int i = 0; i < 1000; ++i) {
    float p[4];
    random_line(rng, i, p);
    const float width = 1.5f + float(i % 4);  // 2 to 5 pixels once rounded (half away from zero)
    compare(t, fmt("line (%.9g, %.9g) - (%.9g, %.9g) width %.9g", p[0], p[1], p[2], p[3], width), [&] {
      glLineWidth(width);
      glShadeModel(GL_FLAT);
      glColor3f(0.5f, 0.5f, 1);
      glBegin(GL_LINES);
      vertex(p[0], p[1]);
      vertex(p[2], p[3]);
      glEnd();
    }, 0);
  }
  EXPECT_EQ(t.coverage + t.colour, 0) << t.coverage << " of " << t.cases << " differ in coverage, " << t.colour
                                      << " in colour; first: " << t.first;
}

// Mesa's state tracker clamps the width to llvmpipe's aliased range [1, 255] (a NaN passes and
// draws 1 wide): a horizontal line 100 pixels below the framebuffer, inside a viewport that
// reaches there, shows the clamp in how far up its width reaches. Before, soft drew nothing for
// an infinite or 1e30 width (the whole-pixel conversion overflowed; fuzz seed 31337 stream 135).
TEST(Lines, WidthsOutsideTheRangeClampAsMesa) {
  Tally t;
  for (const float width : {200.0f, 255.0f, 255.4f, 256.0f, 300.0f, 1e30f, INFINITY, NAN, 0.4f}) {
    compare(t, fmt("width %.9g, a line at window y %g", width, -100.25), [&] {
      glViewport(-200, -200, 464, 464);
      glLineWidth(width);
      glBegin(GL_LINES);
      glVertex2f(-0.5f, (200.0f - 100.25f) / 232 - 1);
      glVertex2f(0.7f, (200.0f - 100.25f) / 232 - 1);
      glEnd();
      glViewport(0, 0, kSize, kSize);
    }, 0);
  }
  EXPECT_EQ(t.coverage + t.colour, 0) << t.coverage << " of " << t.cases << " differ in coverage, " << t.colour
                                      << " in colour; first: " << t.first;
}

// Quads, quad strips and polygons inside the view volume, smooth with a colour per vertex and
// flat: the split decides which colours meet inside, and for a concave quad which pixels are drawn.
TEST(Polygons, PicturesMatchMesa) {
  std::mt19937 rng(301);
  Tally t;
  const GLenum modes[] = {GL_QUADS, GL_QUAD_STRIP, GL_POLYGON};
  for (int i = 0; i < 1200; ++i) {
    const GLenum mode = modes[i % 3];
    const bool flat = i % 6 >= 3;
    const int n = mode == GL_QUADS ? 4 : 6;
    float v[6][2], c[6][3];
    for (int k = 0; k < n; ++k) {
      v[k][0] = coord(rng, 0.5f, 63.5f, false), v[k][1] = coord(rng, 0.5f, 63.5f, false);
      for (float& ch : c[k]) ch = std::uniform_real_distribution<float>(0, 1)(rng);
    }
    compare(t, fmt("mode %g case %g", mode, i), [&] {
      glShadeModel(flat ? GL_FLAT : GL_SMOOTH);
      glBegin(mode);
      for (int k = 0; k < n; ++k) glColor3fv(c[k]), vertex(v[k][0], v[k][1]);
      glEnd();
    }, 1);
  }
  EXPECT_EQ(t.coverage + t.colour, 0) << t.coverage << " of " << t.cases << " differ in coverage, " << t.colour
                                      << " in colour by more than 1; first: " << t.first;
}

// Triangles, strips, fans, quads, quad strips and polygons reaching past the window and past the
// near and far planes, smooth and flat: Mesa's clipper (draw_pipe_clip.c) makes the vertices that
// are drawn, so their positions and colours, and the fan of the clipped polygon, decide the pixels.
TEST(Polygons, ClippedPicturesMatchMesa) {
  std::mt19937 rng(302);
  Tally t;
  const GLenum modes[] = {GL_TRIANGLES, GL_TRIANGLE_STRIP, GL_TRIANGLE_FAN, GL_QUADS, GL_QUAD_STRIP, GL_POLYGON};
  for (int i = 0; i < 1200; ++i) {
    const GLenum mode = modes[i % 6];
    const bool flat = i % 12 >= 6, deep = i / 12 % 3 == 0;  // deep: z from -2 to 2, clipped by near and far
    const int n = mode == GL_QUADS ? 4 : 6;
    float v[6][3], c[6][3];
    for (int k = 0; k < n; ++k) {
      v[k][0] = coord(rng, -40, 104, false), v[k][1] = coord(rng, -40, 104, false);
      v[k][2] = deep ? std::uniform_real_distribution<float>(-2, 2)(rng) : 0;
      for (float& ch : c[k]) ch = std::uniform_real_distribution<float>(0, 1)(rng);
    }
    compare(t, fmt("mode %g case %g", mode, i), [&] {
      glShadeModel(flat ? GL_FLAT : GL_SMOOTH);
      glBegin(mode);
      for (int k = 0; k < n; ++k) glColor3fv(c[k]), glVertex3f(v[k][0] / (kSize / 2) - 1, v[k][1] / (kSize / 2) - 1, v[k][2]);
      glEnd();
    }, 1);
  }
  EXPECT_EQ(t.coverage + t.colour, 0) << t.coverage << " of " << t.cases << " differ in coverage, " << t.colour
                                      << " in colour by more than 1; first: " << t.first;
}

// The feedback buffer: which triangles, in which vertex order, with which positions and colours.
std::vector<float> feedback(backends::Backend& b, const std::function<void()>& draw) {
  use(b);
  static GLfloat buf[4096];
  glFeedbackBuffer(4096, GL_3D_COLOR, buf);
  glRenderMode(GL_FEEDBACK);
  draw();
  const GLint n = glRenderMode(GL_RENDER);
  return std::vector<float>(buf, buf + std::max(0, n));
}

void feedback_cases(bool clipped, int& cases, int& differ, std::string& first) {
  std::mt19937 rng(clipped ? 402 : 401);
  const GLenum modes[] = {GL_QUADS, GL_QUAD_STRIP, GL_POLYGON, GL_TRIANGLES, GL_TRIANGLE_STRIP, GL_TRIANGLE_FAN,
                          GL_LINES, GL_LINE_LOOP, GL_POINTS};
  for (int i = 0; i < 900; ++i) {
    const GLenum mode = modes[i % 9];
    const bool flat = (i / 9) % 2;
    const int n = 6;
    float v[6][2], c[6][3];
    for (int k = 0; k < n; ++k) {
      const float lo = clipped ? -40 : 1, hi = clipped ? 104 : 63;
      v[k][0] = coord(rng, lo, hi, false), v[k][1] = coord(rng, lo, hi, false);
      for (float& ch : c[k]) ch = std::uniform_real_distribution<float>(0, 1)(rng);
    }
    auto draw = [&] {
      glShadeModel(flat ? GL_FLAT : GL_SMOOTH);
      glBegin(mode);
      for (int k = 0; k < n; ++k) glColor3fv(c[k]), vertex(v[k][0], v[k][1]);
      glEnd();
    };
    const std::vector<float> m = feedback(*pair().mesa, draw), s = feedback(*pair().soft, draw);
    ++cases;
    if (m != s) {
      ++differ;
      if (first.empty()) {
        first = fmt("mode %g flat %g: mesa %g values, soft %g", mode, flat, m.size(), s.size());
        for (size_t k = 0; k < std::max(m.size(), s.size()) && k < 60; ++k)
          first += fmt(" [%g] %.9g/%.9g", k, k < m.size() ? m[k] : -1, k < s.size() ? s[k] : -1);
      }
    }
  }
}

TEST(Feedback, UnclippedOrderMatchesMesa) {
  int cases = 0, differ = 0;
  std::string first;
  feedback_cases(false, cases, differ, first);
  EXPECT_EQ(differ, 0) << differ << " of " << cases << " feedback buffers differ; first: " << first;
}

// Every mode, smooth and flat, with vertices well outside the window: positions and colours that
// Mesa's clipper makes, bit for bit, zero-length clipped lines dropped, and flat primitives'
// colours as its clipper leaves them (clip_and_map). Flat clipped triangles report colours left in
// the clipper's temporaries by earlier primitives: the cases run in order on one context each.
TEST(Feedback, ClippedMatchesMesa) {
  int cases = 0, differ = 0;
  std::string first;
  feedback_cases(true, cases, differ, first);
  EXPECT_EQ(differ, 0) << differ << " of " << cases << " feedback buffers differ; first: " << first;
}

// Hand-made cases for what the generated ones seldom reach. A line from the window's right edge
// (x = w exactly) outward clips to zero length, which Mesa's do_clip_line drops; a flat triangle
// clipped after a smooth one reports, at its clip-made vertices, the colours the smooth one left
// in the clipper's temporaries.
TEST(Feedback, ClippedSpecialCasesMatchMesa) {
  const float c[4][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 0}};
  const float d[3][3] = {{0.5f, 0.5f, 0.5f}, {0.25f, 0.25f, 0.25f}, {0.75f, 0.125f, 0.5f}};
  auto line = [&](float x0, float y0, float x1, float y1, bool flat) {
    return [=] {
      glShadeModel(flat ? GL_FLAT : GL_SMOOTH);
      glBegin(GL_LINES);
      glColor3fv(c[0]), vertex(x0, y0);
      glColor3fv(c[1]), vertex(x1, y1);
      glEnd();
    };
  };
  auto triangle = [&](const float (*col)[3], bool flat) {
    return [=] {
      glShadeModel(flat ? GL_FLAT : GL_SMOOTH);
      glBegin(GL_TRIANGLES);
      glColor3fv(col[0]), vertex(-40, 10);
      glColor3fv(col[1]), vertex(30, 90);
      glColor3fv(col[2]), vertex(50, 5);
      glEnd();
    };
  };
  struct Step {
    const char* name;
    std::function<void()> draw;
    size_t mesa_values;  // pinned: what Mesa 22.3 feeds back (GL_3D_COLOR: 2 + 2 x 7 a line)
  };
  const Step steps[] = {
      {"zero-length line from the right edge", line(64, 10, 80, 10, false), 0},
      {"zero-length line to the top edge", line(20, 90, 20, 64, true), 0},
      {"line clipped at both ends, flat", line(-40, 10, 80, 90, true), 15},
      {"line clipped at its first end, flat", line(-40, 10, 30, 50, true), 15},
      {"smooth triangle clipped into three", triangle(c, false), 69},
      {"flat triangle after it", triangle(d, true), 69},
  };
  for (const Step& st : steps) {
    const std::vector<float> m = feedback(*pair().mesa, st.draw), s = feedback(*pair().soft, st.draw);
    EXPECT_EQ(m.size(), st.mesa_values) << st.name;
    EXPECT_EQ(m, s) << st.name;
  }
}

// The lighting where Mesa's program multiplies a zero by something not finite (docs/deviations.md
// row 69), generated: shininess up to 128, normals up to 3 long under a modelview scaling up to 4.5
// (GL_NORMALIZE now and then), directional, point and spot lights, two sides, a local viewer,
// separate specular, a black or grey specular, colour material tracking GL_SPECULAR. Fed back
// (GL_3D_COLOR) within 1e-5 of Mesa, value for value. (An infinite tracked colour with a spot light
// still differs at one vertex in 400 cases: docs/fidelity.md, not traced.)
TEST(LightingSweep, OverflowsAndZeroFactorsMatchMesa) {
  std::mt19937 rng(69);
  auto u = [&](float lo, float hi) { return std::uniform_real_distribution<float>(lo, hi)(rng); };
  int cases = 0, differ = 0, white = 0;
  std::string first;
  for (int i = 0; i < 400; ++i) {
    const float shininess = i % 5 == 0 ? 128 : u(0, 128), sign = i % 2 ? -1.0f : 1.0f;
    const float sx = i % 3 == 0 ? 1 : sign * u(0.2f, 4.5f), sz = i % 3 == 0 ? 1 : u(0.2f, 4.5f);
    const bool local = i % 4 >= 1, spot = i % 4 == 1, two = i % 7 == 3, viewer = i % 6 == 2,
               separate = i % 5 == 4, normalize = i % 9 == 8, track = i % 8 == 5;
    const GLfloat light_pos[4] = {u(-2, 2), u(-2, 2), u(-2, 2), local ? 1.0f : 0.0f};
    const GLfloat diffuse[4] = {u(0, 1), 0, 0, 1}, spec_mat[4] = {i % 2 ? 0.0f : 0.5f, 0, 0, 1};
    const GLfloat color[4] = {u(0, 1), u(0, 1), u(0, 1), 1};
    const float cutoff = u(5, 90);
    float n[3][3], p[3][2];
    for (int k = 0; k < 3; ++k) {
      for (float& c : n[k]) c = u(-3, 3);
      p[k][0] = u(4, 60), p[k][1] = u(4, 60);
    }
    auto draw = [&] {
      glMatrixMode(GL_MODELVIEW);
      glScalef(sx, 1, sz);
      glEnable(GL_LIGHTING), glEnable(GL_LIGHT0);
      glLightfv(GL_LIGHT0, GL_POSITION, light_pos);
      glLightfv(GL_LIGHT0, GL_DIFFUSE, diffuse);
      if (spot) glLightf(GL_LIGHT0, GL_SPOT_CUTOFF, cutoff);
      glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, two);
      glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, viewer);
      glLightModeli(GL_LIGHT_MODEL_COLOR_CONTROL, separate ? GL_SEPARATE_SPECULAR_COLOR : GL_SINGLE_COLOR);
      glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, shininess);
      glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, spec_mat);
      if (normalize) glEnable(GL_NORMALIZE);
      if (track) glColorMaterial(GL_FRONT_AND_BACK, GL_SPECULAR), glEnable(GL_COLOR_MATERIAL);
      glColor4fv(color);
      glBegin(GL_TRIANGLES);
      for (int k = 0; k < 3; ++k) glNormal3fv(n[k]), glVertex2f((p[k][0] / 32 - 1) / sx, p[k][1] / 32 - 1);
      glEnd();
      // Back to GL's defaults for the next case.
      const GLfloat def_pos[4] = {0, 0, 1, 0}, one[4] = {1, 1, 1, 1}, black[4] = {0, 0, 0, 1};
      glLoadIdentity();
      glDisable(GL_COLOR_MATERIAL), glDisable(GL_NORMALIZE), glDisable(GL_LIGHTING), glDisable(GL_LIGHT0);
      glLightfv(GL_LIGHT0, GL_POSITION, def_pos), glLightfv(GL_LIGHT0, GL_DIFFUSE, one);
      glLightf(GL_LIGHT0, GL_SPOT_CUTOFF, 180);
      glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, 0), glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, 0);
      glLightModeli(GL_LIGHT_MODEL_COLOR_CONTROL, GL_SINGLE_COLOR);
      glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 0), glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, black);
      glColorMaterial(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE), glColor4fv(one);
    };
    const std::vector<float> m = feedback(*pair().mesa, draw), s = feedback(*pair().soft, draw);
    ++cases;
    bool same = m.size() == s.size();
    for (size_t k = 0; same && k < m.size(); ++k) same = std::fabs(m[k] - s[k]) <= 1e-5f;
    for (size_t k = 0; k + 3 < m.size(); ++k) white += m[k] == 1 && m[k + 1] == 1 && m[k + 2] == 1;
    if (!same && ++differ == 1) {
      first = fmt("case %g: mesa %g values, soft %g", i, m.size(), s.size());
      for (size_t k = 0; k < std::max(m.size(), s.size()) && k < 40; ++k)
        first += fmt(" [%g] %.9g/%.9g", k, k < m.size() ? m[k] : -1, k < s.size() ? s[k] : -1);
    }
  }
  EXPECT_EQ(differ, 0) << differ << " of " << cases << " feedback buffers differ; first: " << first;
  EXPECT_GT(white, 20);  // the overflowing cases are among them (white lit colours)
}

}  // namespace
}  // namespace ffc
