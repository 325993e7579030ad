// The differential tester's loop: generate streams, run each on Mesa and on soft (forked children),
// compare, explain what the known deviations explain, shrink the first stream of each new kind of
// unexplained mismatch, and sum it all up.
#pragma once
#include <cstdint>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "difftest/compare.h"
#include "difftest/generator.h"
#include "difftest/runner.h"

namespace ffc::difftest {

// One stream's verdict.
struct Checked {
  SideResult mesa, soft;
  std::vector<Mismatch> unexplained;
  std::vector<std::pair<Mismatch, std::string>> explained;  // and the deviation's name
};
Checked check(const Stream& s, const RunOptions& o);

struct Finding {
  Mismatch mismatch;  // as the shrunk stream shows it
  uint64_t seed = 0;  // the stream's seed (generate(seed, ...) rebuilds it); 0 for a replay
  int streams = 0;    // streams that showed this key
  Stream stream;      // shrunk
};

struct Summary {
  int streams = 0, calls = 0;
  int unexplained_streams = 0;  // streams with at least one mismatch no known deviation explains
  double seconds = 0;
  std::map<std::string, int> mismatches_by_kind;  // unexplained, a stream counted once per kind
  std::map<std::string, int> known_by_name;       // streams explained by each known deviation
  int crashes = 0, hangs = 0;                     // streams where a side crashed or hung
  std::vector<Finding> findings;                  // one per key, first seen first
  bool failed() const { return !findings.empty(); }
};

struct FuzzOptions {
  uint64_t seed = 1;
  int streams = 100;     // at most this many
  double minutes = 0;    // and at most this long (0: no limit)
  GenOptions gen;
  RunOptions run;
  bool shrink = true;
  int shrink_budget = 300;  // runs of a stream (both sides) per finding
};

using Log = std::function<void(const std::string&)>;

Summary fuzz(const FuzzOptions& o, const Log& log = {});
// Runs one stream (a repro file) and shrinks what it shows.
Summary replay(const Stream& s, const FuzzOptions& o, const Log& log = {});

}  // namespace ffc::difftest
