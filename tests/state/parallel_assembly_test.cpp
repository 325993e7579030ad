// The general path's large GL_TRIANGLES draws are assembled and set up on the context's threads
// (Assembly::triangles_on_threads). What a thread meets there is named by the calling thread once
// they are done: the threads themselves once inserted into the context's set of deviations, two at
// once corrupting it (a rare crash; valgrind --tool=helgrind on the test reports the race: docs/testing.md).
#include <gtest/gtest.h>

#include "../clipped_sliver.h"
#include "state/context.h"

namespace ffc {
namespace {

TEST(ParallelAssembly, SliversMetOnEveryThreadAreNamedOnceByTheCaller) {
  for (int threads : {1, 2, 3}) {
    // Double precision: the general path (the triangle list is float only).
    state::Context ctx(32, 32, state::Precision::Double);
    state::Context::make_current(&ctx);
    ctx.set_threads(threads);
    // Every thread sets slivers up from its first triangle on: 4100 copies, above the 4096
    // triangles from which the threads share the work.
    test::draw_clipped_slivers(ctx, 4100);
    EXPECT_EQ(ctx.GetError(), GLenum(GL_NO_ERROR));
    EXPECT_EQ(ctx.deviations().count(state::kClippedSliver), 1u) << threads << " threads";
    state::Context::make_current(nullptr);
  }
  // Flat: no plane to be rounding noise, nothing named.
  state::Context flat(32, 32, state::Precision::Double);
  state::Context::make_current(&flat);
  flat.ShadeModel(GL_FLAT);
  test::draw_clipped_slivers(flat, 4100);
  EXPECT_EQ(flat.deviations().count(state::kClippedSliver), 0u);
  state::Context::make_current(nullptr);
}

}  // namespace
}  // namespace ffc
