// Delta debugging of a failing stream: drop chunks of calls, then single calls, while the stream
// still fails the same way; then simplify the numbers that are left (0, 1, rounded) and shorten
// the arrays. The test is a predicate, so the shrinker knows nothing of GL (and its tests can plant
// a failure without one).
#pragma once
#include <functional>

#include "difftest/stream.h"

namespace ffc::difftest {

using StillFails = std::function<bool(const Stream&)>;

// A smaller stream that still fails; at most `budget` calls of `fails`.
Stream shrink(Stream s, const StillFails& fails, int budget = 400);

}  // namespace ffc::difftest
