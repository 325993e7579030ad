// Random GL call streams, deterministic per seed. A stream sets a random camera (projection and
// modelview) and lighting, then draws and changes state at random: immediate mode and client
// arrays of every type, size and stride, every primitive, feedback of each type, glReadPixels,
// glGet of any name, with valid and invalid enums and values and NaN/Inf where the categories
// allow; a checkpoint (compare every glGet value) every few calls and at the end.
//
// Categories switch parts of the generator on and off, so that a run can leave out what is known
// to differ today (and a fix can be checked by switching its category back on).
#pragma once
#include <cstdint>
#include <set>
#include <string>
#include <vector>

#include "difftest/stream.h"

namespace ffc::difftest {

struct Category {
  std::string name, what;
};
// Every category, with a line on what it adds.
const std::vector<Category>& categories();

struct GenOptions {
  int calls = 60;                    // about this many calls, checkpoints not counted
  std::set<std::string> categories;  // empty: all of them
  bool has(const std::string& c) const { return categories.empty() || categories.count(c) > 0; }
};

// The categories left after --only (empty: all) and --exclude; throws std::invalid_argument for
// an unknown name.
std::set<std::string> select_categories(const std::vector<std::string>& only, const std::vector<std::string>& exclude);

Stream generate(uint64_t seed, const GenOptions& o);

// The seed of stream `index` of a run started with `seed`.
uint64_t stream_seed(uint64_t seed, uint64_t index);

}  // namespace ffc::difftest
