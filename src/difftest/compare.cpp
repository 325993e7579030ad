#include "difftest/compare.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <set>

#include "difftest/probes.h"

namespace ffc::difftest {

namespace {

std::string num(double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.9g", v);
  return buf;
}

bool within(double a, double b, double tol, bool relative) {
  if (std::isnan(a) || std::isnan(b)) return std::isnan(a) && std::isnan(b);
  if (a == b) return true;
  return std::fabs(a - b) <= tol * (relative ? std::max({1.0, std::fabs(a), std::fabs(b)}) : 1.0);
}

}  // namespace

std::vector<Mismatch> compare(const Stream& s, const SideResult& mesa, const SideResult& soft) {
  std::vector<Mismatch> out;
  std::set<std::string> seen;
  auto add = [&](std::string kind, std::string what, int call, std::string detail) {
    std::string key = kind + " " + what;
    if (!seen.insert(key).second) return;
    out.push_back({std::move(kind), std::move(key), call, std::move(detail)});
  };
  bool broken = false;
  for (const SideResult* r : {&mesa, &soft}) {
    if (r->status == SideResult::Status::Ok) continue;
    broken = true;
    const char* side = r == &mesa ? "mesa" : "soft";
    const char* kind = r->status == SideResult::Status::Hung ? "hang" : "crash";
    const std::string where = r->call >= 0 && size_t(r->call) < s.size() ? name_of(s[size_t(r->call)])
                              : r->call < 0 ? "context creation" : "the read-back at the end";
    add(kind, std::string(side) + " " + where, r->call, "call " + std::to_string(r->call) + ": " + r->what);
  }
  if (broken) return out;

  for (size_t i = 0; i < s.size() && i < mesa.errors.size() && i < soft.errors.size(); ++i) {
    if (mesa.errors[i] != soft.errors[i])
      add("error", name_of(s[i]), int(i),
          "call " + std::to_string(i) + ": mesa " + error_name(mesa.errors[i]) + ", soft " + error_name(soft.errors[i]));
    const double a = mesa.returns[i], b = soft.returns[i];
    if (!(std::isnan(a) && std::isnan(b)) && a != b)
      add("return", name_of(s[i]), int(i), "call " + std::to_string(i) + ": mesa " + num(a) + ", soft " + num(b));
  }
  // Checkpoints, in order: a checkpoint's index in the stream is the n-th checkpoint call.
  std::vector<int> checkpoint_calls;
  for (size_t i = 0; i < s.size(); ++i)
    if (s[i].fn == checkpoint_fn()) checkpoint_calls.push_back(int(i));
  for (size_t c = 0; c < mesa.checkpoints.size() && c < soft.checkpoints.size(); ++c) {
    const auto &a = mesa.checkpoints[c], &b = soft.checkpoints[c];
    for (size_t k = 0; k + 1 < a.size() && k + 1 < b.size(); ++k) {
      if (slot_close(k, a[k], b[k])) continue;
      const Probe* p = probe_of(k);
      add("state", p ? probe_name(*p) : "?", checkpoint_calls[c],
          "checkpoint at call " + std::to_string(checkpoint_calls[c]) + ", value " + std::to_string(k) + ": mesa " +
              num(a[k]) + ", soft " + num(b[k]));
    }
  }
  for (size_t o = 0; o < mesa.outputs.size() && o < soft.outputs.size(); ++o) {
    const Output &a = mesa.outputs[o], &b = soft.outputs[o];
    const Call& c = s[size_t(a.call)];
    const std::string& fn = name_of(c);
    std::string kind = "output", what = fn + "(" + (c.args.empty() ? "" : enum_name(GLenum(c.args[0].num))) + ")";
    double tol = 1e-6;
    bool relative = true;
    if (fn == "glFeedbackBuffer") kind = "feedback", what = enum_name(GLenum(c.args[1].num)), tol = 1e-5;
    if (fn == "glReadPixels")
      kind = "readpixels", what = enum_name(GLenum(c.args[4].num)) + " " + enum_name(GLenum(c.args[5].num)),
      tol = 1.0 / 255 + 1e-9, relative = false;
    for (size_t k = 0; k < a.values.size() && k < b.values.size(); ++k)
      if (!within(a.values[k], b.values[k], tol, relative)) {
        add(kind, what, a.call,
            "buffer of call " + std::to_string(a.call) + ", value " + std::to_string(k) + ": mesa " +
                num(a.values[k]) + ", soft " + num(b.values[k]));
        break;
      }
  }
  if (mesa.pixels.size() == soft.pixels.size()) {
    int worst = 0, differing = 0;
    size_t first = 0;
    for (size_t i = 0; i < mesa.pixels.size(); ++i) {
      const int d = std::abs(int(mesa.pixels[i]) - int(soft.pixels[i]));
      if (d > 1 && differing++ == 0) first = i;
      worst = std::max(worst, d);
    }
    if (differing) {
      const size_t px = first / 4;
      const int w = std::max(mesa.width, 1);
      add("pixels", "picture", -1,
          std::to_string(differing) + " channels more than 1 step apart (max " + std::to_string(worst) +
              "), first at x " + std::to_string(px % size_t(w)) + ", row " + std::to_string(px / size_t(w)) +
              " from the top: mesa " + std::to_string(mesa.pixels[first]) + ", soft " +
              std::to_string(soft.pixels[first]));
    }
  }
  return out;
}

}  // namespace ffc::difftest
