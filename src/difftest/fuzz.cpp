#include "difftest/fuzz.h"

#include <chrono>
#include <set>

#include "difftest/known.h"
#include "difftest/shrink.h"

namespace ffc::difftest {

Checked check(const Stream& s, const RunOptions& o) {
  Checked c;
  c.mesa = run_side(s, Side::Mesa, o);
  c.soft = run_side(s, Side::Soft, o);
  for (Mismatch& m : compare(s, c.mesa, c.soft)) {
    if (const KnownDeviation* d = explain(s, m, c.mesa, c.soft)) c.explained.emplace_back(std::move(m), d->name);
    else c.unexplained.push_back(std::move(m));
  }
  return c;
}

namespace {

// Whether a draw reads a client array that is enabled but was never given memory: GL leaves that
// undefined (either side may crash), so the shrinker must not reach it by dropping a gl*Pointer.
bool reads_unset_array(const Stream& s) {
  bool enabled[3] = {}, set[3] = {};
  auto slot = [](double cap) { return cap == GL_VERTEX_ARRAY ? 0 : cap == GL_NORMAL_ARRAY ? 1 : cap == GL_COLOR_ARRAY ? 2 : -1; };
  for (const Call& c : s) {
    const std::string& n = name_of(c);
    if (n == "glEnableClientState" || n == "glDisableClientState") {
      if (const int i = slot(c.args[0].num); i >= 0) enabled[i] = n == "glEnableClientState";
    } else if (n == "glVertexPointer" || n == "glNormalPointer" || n == "glColorPointer") {
      // Only a call GL accepts sets the pointer: sizes 2-4 (colours 3-4), a type of the array's,
      // a stride of at least 0 (the generator's types are all legal ones).
      const bool normal = n == "glNormalPointer";
      const double size = normal ? 3 : c.args[0].num, type = c.args[normal ? 0 : 1].num, stride = c.args[normal ? 1 : 2].num;
      const bool ok = size >= (n == "glColorPointer" ? 3 : 2) && size <= 4 && type_size(GLenum(type)) > 0 && type >= 0 &&
                      stride >= 0 && c.args.back().kind == Arg::Kind::Blob;
      set[n == "glVertexPointer" ? 0 : normal ? 1 : 2] = ok;
    } else if (n == "glDrawArrays" || n == "glDrawElements" || n == "glArrayElement") {
      for (int i = 0; i < 3; ++i)
        if (enabled[i] && !set[i]) return true;
    }
  }
  return false;
}

// Whether a stream still shows an unexplained mismatch with this key.
bool shows(const Stream& s, const std::string& key, const RunOptions& o, Mismatch* found = nullptr) {
  if (reads_unset_array(s)) return false;
  const Checked c = check(s, o);
  for (const Mismatch& m : c.unexplained)
    if (m.key == key) {
      if (found) *found = m;
      return true;
    }
  return false;
}

// Counts one stream into the summary; new keys become findings (shrunk).
void record(Summary& sum, const Stream& s, uint64_t seed, const Checked& c, const FuzzOptions& o, const Log& log) {
  ++sum.streams;
  sum.calls += int(s.size());
  std::set<std::string> kinds, names;
  for (const auto& [m, name] : c.explained) names.insert(name);
  for (const auto& n : names) ++sum.known_by_name[n];
  if (!c.unexplained.empty()) {
    ++sum.unexplained_streams;
    // One line per such stream (its index in the run, its seed, its first mismatch), for triage:
    // the findings below keep only the first stream of each key.
    if (log)
      log("unexplained: stream " + std::to_string(sum.streams - 1) + " seed " + std::to_string(seed) + ": " +
          std::to_string(c.unexplained.size()) + " mismatches, first " + c.unexplained.front().key + " (" +
          c.unexplained.front().detail + ")");
  }
  for (const Mismatch& m : c.unexplained) {
    if (kinds.insert(m.kind).second) ++sum.mismatches_by_kind[m.kind];
    Finding* f = nullptr;
    for (Finding& x : sum.findings)
      if (x.mismatch.key == m.key) f = &x;
    if (f) {
      ++f->streams;
      continue;
    }
    Finding nf{m, seed, 1, s};
    if (log) log("new: " + m.key + " (" + m.detail + "), stream seed " + std::to_string(seed) + ", " + std::to_string(s.size()) + " calls");
    if (o.shrink) {
      nf.stream = shrink(s, [&](const Stream& t) { return shows(t, m.key, o.run); }, o.shrink_budget);
      shows(nf.stream, m.key, o.run, &nf.mismatch);
      if (log) log("  shrunk to " + std::to_string(nf.stream.size()) + " calls");
    }
    sum.findings.push_back(std::move(nf));
  }
  if (c.mesa.status == SideResult::Status::Crashed || c.soft.status == SideResult::Status::Crashed) ++sum.crashes;
  if (c.mesa.status == SideResult::Status::Hung || c.soft.status == SideResult::Status::Hung) ++sum.hangs;
}

}  // namespace

Summary fuzz(const FuzzOptions& o, const Log& log) {
  Summary sum;
  const auto t0 = std::chrono::steady_clock::now();
  auto minutes = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count() / 60; };
  for (int i = 0; i < o.streams && (o.minutes <= 0 || minutes() < o.minutes); ++i) {
    const uint64_t seed = stream_seed(o.seed, uint64_t(i));
    const Stream s = generate(seed, o.gen);
    record(sum, s, seed, check(s, o.run), o, log);
  }
  sum.seconds = minutes() * 60;
  return sum;
}

Summary replay(const Stream& s, const FuzzOptions& o, const Log& log) {
  Summary sum;
  const auto t0 = std::chrono::steady_clock::now();
  record(sum, s, 0, check(s, o.run), o, log);
  sum.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return sum;
}

}  // namespace ffc::difftest
