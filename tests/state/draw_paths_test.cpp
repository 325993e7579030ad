// Immediate mode's corner cache and glDrawArrays' shared corners (immediate.cpp, draw.cpp): a
// repeated corner is lit once, and the picture is the one the general path draws lighting every
// corner on its own (set_triangle_lists(false)), byte for byte, colour and depth.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <vector>

#include "backends/backend.h"
#include "gl/dispatch.h"
#include "state/context.h"

namespace ffc {
namespace {

constexpr int kSize = 256;

struct Picture {
  std::vector<uint8_t> color;
  std::vector<uint32_t> depth;
};

// A fan of triangles round a centre, as a soup: every rim corner twice, the centre in each.
struct Soup {
  std::vector<float> pos, normal, color;
  void corner(float x, float y, float z, float nx, float ny, float nz, float r, float g) {
    pos.insert(pos.end(), {x, y, z});
    normal.insert(normal.end(), {nx, ny, nz});
    color.insert(color.end(), {r, g, 0.5f, 1});
  }
  size_t size() const { return pos.size() / 3; }
};

// An n x n grid of quads (two triangles each) over the picture, as a soup: an inner corner is sent
// six times. `split_normals` / `split_colours`: the upper triangles' corners get another normal
// or colour than the lower ones' at the same position (a pair that must not be shared).
Soup grid(int n, bool split_normals, bool split_colours) {
  Soup s;
  auto corner = [&](int i, int j, bool upper) {
    const float x = -0.9f + 1.8f * float(i) / float(n), y = -0.9f + 1.8f * float(j) / float(n);
    // The split varies over the grid: a hash of sums meets each pair's difference afresh.
    const float nz = split_normals && upper ? 0.5f + 0.3f * x * y : 0.9f;
    const float g = split_colours && upper ? 0.6f + 0.3f * x * y : 0.3f;
    s.corner(x, y, 0.2f * x * y, 0.3f * x, 0.3f * y, nz, 0.5f + 0.4f * x, g);
  };
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      corner(i, j, false), corner(i + 1, j, false), corner(i + 1, j + 1, false);
      corner(i, j, true), corner(i + 1, j + 1, true), corner(i, j + 1, true);
    }
  return s;
}

// `split_normals`: the rim corners' second use gets another normal (same position: no sharing);
// `split_colours`: the same with the colour.
Soup fan(int n, bool split_normals, bool split_colours) {
  Soup s;
  const float pi = 3.14159265f;
  auto rim = [&](int k, bool second) {
    const float a = 2 * pi * float(k % n) / float(n);
    const float nz = split_normals && second ? 0.6f : 0.8f;
    const float g = split_colours && second ? 0.9f : 0.2f;
    s.corner(0.8f * std::cos(a), 0.8f * std::sin(a), 0.1f * float(k % 3), 0.6f * std::cos(a), 0.6f * std::sin(a), nz,
             0.5f + 0.4f * std::cos(a), g);
  };
  for (int k = 0; k < n; ++k) {
    s.corner(0, 0, -0.2f, 0, 0, 1, 1, 1);
    rim(k, true);
    rim(k + 1, false);
  }
  return s;
}

void set_up(bool color_material) {
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  const float light[4] = {0.3f, 0.5f, 1, 0};
  glLightfv(GL_LIGHT0, GL_POSITION, light);
  const float spec[4] = {1, 1, 1, 1};
  glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, spec);
  glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 12);
  if (color_material) glEnable(GL_COLOR_MATERIAL);
}

enum class Path { Immediate, Arrays };

// colour_size: 4, or 3 (the alpha left out: glColor3fv, glColorPointer(3) over the same floats).
void send(const Soup& s, Path path, bool colours, int colour_size = 4) {
  if (path == Path::Immediate) {
    glBegin(GL_TRIANGLES);
    for (size_t i = 0; i < s.size(); ++i) {
      if (colours && colour_size == 4) glColor4fv(&s.color[4 * i]);
      if (colours && colour_size == 3) glColor3fv(&s.color[4 * i]);
      glNormal3fv(&s.normal[3 * i]);
      glVertex3fv(&s.pos[3 * i]);
    }
    glEnd();
    return;
  }
  glEnableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_NORMAL_ARRAY);
  if (colours) glEnableClientState(GL_COLOR_ARRAY);
  glVertexPointer(3, GL_FLOAT, 0, s.pos.data());
  glNormalPointer(GL_FLOAT, 0, s.normal.data());
  glColorPointer(colour_size, GL_FLOAT, 4 * sizeof(float), s.color.data());
  glDrawArrays(GL_TRIANGLES, 0, GLsizei(s.size()));
  glDisableClientState(GL_COLOR_ARRAY);
  glDisableClientState(GL_NORMAL_ARRAY);
  glDisableClientState(GL_VERTEX_ARRAY);
}

// The soups drawn one after another (each its own glBegin or draw), on the triangle list or not.
Picture draw(const std::vector<Soup>& soups, Path path, bool lists, bool color_material, int colour_size = 4) {
  auto soft = backends::make("soft");
  soft->begin(kSize, kSize);
  state::Context* c = state::Context::current();
  c->set_triangle_lists(lists);
  set_up(color_material);
  for (const Soup& s : soups) {
    if (&s != &soups.front()) {  // each soup drawn whole, moved: its corners light and land elsewhere
      glClear(GL_DEPTH_BUFFER_BIT);
      glTranslatef(0.15f, -0.1f, 0);
      glRotatef(20, 0, 1, 0);
    }
    send(s, path, color_material, colour_size);
  }
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  const raster::Framebuffer& fb = c->framebuffer();
  return {fb.color, fb.depth};
}

void expect_same(const std::vector<Soup>& soups, bool color_material, int colour_size = 4) {
  for (Path path : {Path::Immediate, Path::Arrays}) {
    const Picture want = draw(soups, path, false, color_material, colour_size);
    size_t drawn = 0;
    for (size_t i = 0; i < want.color.size(); i += 4) drawn += want.color[i] != 0;
    EXPECT_GT(drawn, want.color.size() / 4 / 4) << "the fan covers the middle of the picture";
    const Picture got = draw(soups, path, true, color_material, colour_size);
    EXPECT_TRUE(got.color == want.color) << (path == Path::Immediate ? "immediate" : "arrays");
    EXPECT_TRUE(got.depth == want.depth) << (path == Path::Immediate ? "immediate" : "arrays");
  }
}

TEST(DrawPaths, RepeatedCornersDrawAsEveryCornerLitAlone) {
  expect_same({fan(100, false, false)}, false);
  // Large enough that many corners fall into one slot of the cache, and that glDrawArrays finds
  // the repeats on both threads (several thousand corners).
  expect_same({fan(3000, false, false)}, false);
  expect_same({grid(120, false, false)}, false);
}

TEST(DrawPaths, ACornerWithTheSamePositionButAnotherNormalOrColourIsNotShared) {
  // Immediate mode does not hash the colour: both colours of a corner meet in one slot. It hashes
  // the normal, and glDrawArrays every attribute: among 30000 pairs some collide, one replacing
  // the other in the slot.
  expect_same({fan(100, false, true)}, true);
  expect_same({grid(120, true, false)}, false);
  expect_same({grid(120, false, true)}, true);
  // Three colour components: glDrawArrays' key of nine words, its last pair half empty.
  expect_same({grid(120, false, true)}, true, 3);
  expect_same({grid(120, true, false)}, true, 3);
}

TEST(DrawPaths, NothingIsSharedWithAnEarlierGlBegin) {
  // The second fan sends the first's corners in another order, drawn over the first: an entry of
  // the first glBegin taken for the second would place a corner wrongly.
  Soup a = fan(100, false, false), b = fan(100, false, false);
  std::vector<float> pos, normal, color;
  for (size_t t = b.size() / 3; t-- > 0;)
    for (size_t k = 0; k < 3; ++k) {
      const size_t i = 3 * t + k;
      pos.insert(pos.end(), b.pos.begin() + long(3 * i), b.pos.begin() + long(3 * i + 3));
      normal.insert(normal.end(), b.normal.begin() + long(3 * i), b.normal.begin() + long(3 * i + 3));
      color.insert(color.end(), b.color.begin() + long(4 * i), b.color.begin() + long(4 * i + 4));
    }
  b.pos = pos, b.normal = normal, b.color = color;
  expect_same({a, b}, false);
  expect_same({a, b}, true);
}

// Immediate mode's early draws (Context::early_handoff): a long glBegin(GL_TRIANGLES) hands its
// complete triangles to a worker every few corners. Whatever the interval, and whatever comes
// between the corners (a glMaterial that leaves the triangle list mid-triangle, a colour growing
// from 3 to 4 components, which wraps and rewrites the unfinished triangle's corners, the first
// glColor under colour material), the picture, the depth buffer and the state after it are those
// of the same calls drawn at glEnd.
struct Breaks {
  size_t material_at = SIZE_MAX;  // glMaterial(GL_DIFFUSE) before this corner
  size_t color4_at = SIZE_MAX;    // corners before it send glColor3f, from it on glColor4f
  size_t first_color_at = 0;      // no glColor before this corner
};

Picture draw_early(const std::vector<Soup>& soups, size_t early, size_t chunk, bool color_material, const Breaks& br,
                   std::vector<double>* after, size_t* stops = nullptr) {
  auto soft = backends::make("soft");
  soft->begin(kSize, kSize);
  state::Context* c = state::Context::current();
  c->set_threads(2);
  c->set_early_corners(early);
  c->set_early_chunk(chunk);
  set_up(color_material);
  for (const Soup& s : soups) {
    if (&s != &soups.front()) glRotatef(25, 0.3f, 1, 0);
    glBegin(GL_TRIANGLES);
    for (size_t i = 0; i < s.size(); ++i) {
      if (i == br.material_at) {
        const float red[4] = {0.9f, 0.1f, 0.1f, 1};
        glMaterialfv(GL_FRONT_AND_BACK, GL_DIFFUSE, red);
      }
      if (i >= br.first_color_at) {
        const float* k = &s.color[4 * i];
        if (i < br.color4_at) glColor3f(k[0], k[1], k[2]);
        else glColor4f(k[0], k[1], k[2], 0.5f);
      }
      glNormal3fv(&s.normal[3 * i]);
      glVertex3fv(&s.pos[3 * i]);
    }
    glEnd();
  }
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  after->assign(12, 0);
  glGetDoublev(GL_CURRENT_COLOR, after->data());
  glGetDoublev(GL_CURRENT_NORMAL, after->data() + 4);
  GLfloat diffuse[4];
  glGetMaterialfv(GL_FRONT, GL_DIFFUSE, diffuse);
  for (int k = 0; k < 4; ++k) (*after)[8 + size_t(k)] = diffuse[k];
  if (stops) *stops += c->early_stops();
  const raster::Framebuffer& fb = c->framebuffer();
  return {fb.color, fb.depth};
}

// Returns the joins that stopped a job.
size_t expect_early_same(const std::vector<Soup>& soups, bool color_material, const Breaks& br) {
  std::vector<double> want_after, got_after;
  const Picture want = draw_early(soups, 0, 1, color_material, br, &want_after);
  size_t drawn = 0;
  for (size_t i = 0; i < want.color.size(); i += 4) drawn += want.color[i] != 0;
  EXPECT_GT(drawn, want.color.size() / 4 / 4);
  // Chunks of one triangle: nearly every join finds the job with triangles left and stops it,
  // leaving them to the caller.
  size_t stops = 0;
  for (const auto& [early, chunk] : {std::pair<size_t, size_t>{3, 1}, {4, 512}, {7, 2}, {100, 1}, {3072, 1}, {3072, 7},
                                     {3072, 512}}) {
    const Picture got = draw_early(soups, early, chunk, color_material, br, &got_after, &stops);
    EXPECT_TRUE(got.color == want.color) << "every " << early << " corners, chunks of " << chunk;
    EXPECT_TRUE(got.depth == want.depth) << "every " << early << " corners, chunks of " << chunk;
    EXPECT_EQ(got_after, want_after) << "every " << early << " corners, chunks of " << chunk;
  }
  return stops;
}

TEST(DrawPaths, EarlyDrawsGiveThePictureOfADrawAtGlEnd) {
  const Soup g = grid(40, false, false), f = fan(500, false, false);
  const auto breaks = [](size_t material_at, size_t color4_at, size_t first_color_at) {
    Breaks b;
    b.material_at = material_at, b.color4_at = color4_at, b.first_color_at = first_color_at;
    return b;
  };
  constexpr size_t kNever = SIZE_MAX;
  size_t stops = 0;
  stops += expect_early_same({g}, false, {});
  stops += expect_early_same({g, f}, false, {});                              // two glBegins
  stops += expect_early_same({g}, false, breaks(4001, kNever, 0));            // the general path from mid-triangle
  stops += expect_early_same({g}, false, breaks(3, kNever, 0));
  stops += expect_early_same({g}, false, breaks(kNever, 5000, 0));            // a wrap with alpha 1
  stops += expect_early_same({g}, true, breaks(kNever, 2002, 0));             // colour material, the wrap
  stops += expect_early_same({g}, true, breaks(kNever, kNever, 6000));        // colour material, no colour until late
  stops += expect_early_same({g, f}, true, breaks(7000, 3000, 0));
  EXPECT_GT(stops, 0U);  // the stopped jobs' rest drawn by the caller
}

}  // namespace
}  // namespace ffc
