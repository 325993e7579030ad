// Known deviations: named, documented places where the two sides are expected to differ (Mesa 22.3
// departing from GL 2.1, as pinned by tests/state and reported by soft's Context::deviations()).
// A mismatch one of them explains is counted under its name, not as a failure.
#pragma once
#include <functional>
#include <string>
#include <vector>

#include "difftest/compare.h"

namespace ffc::difftest {

struct KnownDeviation {
  std::string name;         // short, stable: what --json counts under
  std::string description;  // one line: what Mesa does and what the spec says
  std::function<bool(const Stream&, const Mismatch&, const SideResult& mesa, const SideResult& soft)> explains;
  // Whether it may explain a crash: only a Mesa crash pinned to the exact calls that cause it (a
  // hang is never explained, nor any crash of soft's).
  bool mesa_crash = false;
};

const std::vector<KnownDeviation>& known_deviations();
// The first deviation that explains m, or nullptr.
const KnownDeviation* explain(const Stream& s, const Mismatch& m, const SideResult& mesa, const SideResult& soft);

}  // namespace ffc::difftest
