// Each context counts its own draws (raster::Counters): two contexts drawing at once on two threads
// must not name, for one picture, what only the other drew. With one count for the process (as
// before) the first test fails every time (its threads take turns), the second whenever the two
// threads' draws overlap (6 runs of 8 at a fifth of its draws, tried).
#include <gtest/gtest.h>

#include <atomic>
#include <condition_variable>
#include <limits>
#include <mutex>
#include <thread>
#include <vector>

#include "../clipped_sliver.h"
#include "gl/dispatch.h"
#include "counted_raster.h"
#include "raster/raster.h"
#include "state/context.h"
#include "stress/stress.h"

namespace ffc {
namespace {

// One thread waits for the other's signal.
struct Signal {
  std::mutex m;
  std::condition_variable cv;
  bool set = false;
  void raise() {
    std::lock_guard<std::mutex> lock(m);
    set = true;
    cv.notify_all();
  }
  void wait() {
    std::unique_lock<std::mutex> lock(m);
    cv.wait(lock, [&] { return set; });
  }
};

// Soft never writes a fragment from a non-finite colour through GL (the stress suite's point):
// another context's draw that does is made on the raster itself, a line whose first vertex has an
// infinite green, counted where its State says, as a context's draws are.
uint64_t draw_infinite_line() {
  raster::Framebuffer fb(16, 16);
  raster::Counters counts;
  const raster::State s = test::counted_state(counts);
  raster::WindowVertex a{}, b{};
  a.pos = {1, 1, 0.5}, b.pos = {15, 2, 0.5};
  a.fx = 1, a.y_down = 15, b.fx = 15, b.y_down = 14;  // the position line setup reads (rows counted down)
  a.inv_w = b.inv_w = 1;
  a.color = b.color = {0.5, 0.5, 0.5, 1};
  a.color.g = std::numeric_limits<double>::infinity();
  raster::draw_line(fb, a, b, s);
  return counts.nonfinite_fragments.load();
}

TEST(Counters, NonFiniteFragmentsAreCountedPerContext) {
  // The stress runner draws a clean case on this thread; halfway through its soft picture (the
  // first draw() call), the other thread draws the line and this one waits for it. With one count
  // for the process, the clean case's picture had the line's fragments.
  Signal drawing, drawn;
  uint64_t other_count = 0;
  std::thread other([&] {
    drawing.wait();
    other_count = draw_infinite_line();
    drawn.raise();
  });
  stress::Case c;
  c.name = "clean_triangle";
  c.width = c.height = 32;
  int calls = 0;
  c.draw = [&] {
    glBegin(GL_TRIANGLES);
    glColor3f(0.2f, 0.4f, 0.6f);
    glVertex2f(-0.8f, -0.8f), glVertex2f(0.8f, -0.8f), glVertex2f(0, 0.8f);
    glEnd();
    if (calls++ == 0) drawing.raise(), drawn.wait();
  };
  const stress::Result r = stress::run(c, {false, false, 60}, true);
  other.join();
  EXPECT_GT(other_count, 5u);  // the count means something: the line was counted, in its own
  EXPECT_EQ(r.observed.soft.nonfinite_fragments, 0u);
  EXPECT_EQ(r.nan_pixels, 0u) << r.verdict;
  EXPECT_EQ(r.verdict.find("non-finite"), std::string::npos) << r.verdict;
}

// A clean triangle list: a grid of smooth triangles over the whole window, none clipped.
void draw_grid(state::Context& ctx, std::vector<GLfloat>& pos, std::vector<GLfloat>& col) {
  if (pos.empty()) {
    const int n = 48;
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const float x0 = -0.95f + 1.9f * i / n, x1 = -0.95f + 1.9f * (i + 1) / n;
        const float y0 = -0.95f + 1.9f * j / n, y1 = -0.95f + 1.9f * (j + 1) / n;
        for (float v : {x0, y0, x1, y0, x1, y1, x0, y0, x1, y1, x0, y1}) pos.push_back(v);
        for (int k = 0; k < 6; ++k) col.insert(col.end(), {float(i) / n, float(j) / n, 0.5f, 1});
      }
  }
  ctx.VertexPointer(2, GL_FLOAT, 0, pos.data());
  ctx.ColorPointer(4, GL_FLOAT, 0, col.data());
  ctx.EnableClientState(GL_VERTEX_ARRAY);
  ctx.EnableClientState(GL_COLOR_ARRAY);
  ctx.DrawArrays(GL_TRIANGLES, 0, GLsizei(pos.size() / 2));
}

TEST(Counters, ClippedSliversAreNamedOnlyWhereDrawn) {
  // Alone: the sliver's context names it, the grid's does not.
  {
    state::Context sliver(32, 32), grid(256, 256);
    state::Context::make_current(&sliver);
    test::draw_clipped_slivers(sliver);
    EXPECT_EQ(sliver.deviations().count(state::kClippedSliver), 1u);
    std::vector<GLfloat> pos, col;
    state::Context::make_current(&grid);
    draw_grid(grid, pos, col);
    EXPECT_EQ(grid.deviations().count(state::kClippedSliver), 0u);
    state::Context::make_current(nullptr);
  }
  // At once, on two threads, each context its own: the slivers drawn meanwhile on the other
  // thread are not named for the grid. Each thread goes on until the other has drawn enough that
  // their draws overlap (a count shared by the process named them in the grid's context).
  std::atomic<int> slivers_drawn{0}, grids_drawn{0};
  std::atomic<bool> failed{false};
  std::thread other([&] {
    for (int i = 0; i < 100000 && !failed.load() && (i < 1000 || grids_drawn.load() < 200); ++i) {
      state::Context ctx(32, 32);
      state::Context::make_current(&ctx);
      test::draw_clipped_slivers(ctx);
      EXPECT_EQ(ctx.deviations().count(state::kClippedSliver), 1u);
      state::Context::make_current(nullptr);
      slivers_drawn.fetch_add(1);
    }
  });
  std::vector<GLfloat> pos, col;
  for (int i = 0; i < 100000 && (i < 200 || slivers_drawn.load() < 1000); ++i) {
    state::Context grid(256, 256);
    state::Context::make_current(&grid);
    draw_grid(grid, pos, col);
    const bool named = grid.deviations().count(state::kClippedSliver) != 0;
    state::Context::make_current(nullptr);
    grids_drawn.fetch_add(1);
    if (named) {
      ADD_FAILURE() << "the grid's draw " << i << " named clipped-sliver-planes (slivers drawn: " << slivers_drawn.load() << ")";
      failed = true;
      break;
    }
  }
  other.join();
}

}  // namespace
}  // namespace ffc
