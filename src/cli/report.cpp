// ffcompat report: the shading error of flat and smooth icospheres against the ray-cast ideal,
// against run time, over depths, lighting setups, normal weightings and backends; plus the
// regression checks of every scene against Mesa. Writes results.csv, the charts and index.html.
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
#include <sstream>

#include "cli/common.h"
#include "report/report.h"

namespace ffc::cli {

namespace {

std::vector<std::string> split(const std::string& s) {
  std::vector<std::string> out;
  std::stringstream in(s);
  for (std::string item; std::getline(in, item, ',');)
    if (!item.empty()) out.push_back(item);
  return out;
}

nlohmann::json reach_json(const report::Reach& x) {
  return {{"triangles", std::isnan(x.triangles) ? nlohmann::json(nullptr) : nlohmann::json(x.triangles)},
          {"ms_per_frame", x.ms > 0 ? nlohmann::json(x.ms) : nlohmann::json(nullptr)},
          {"reached", x.reached},
          {"at_start", x.at_start},
          {"extrapolated", x.extrapolated}};
}

nlohmann::json crossing_json(const report::Crossing& c) {
  return {{"target_rmse", c.target_rmse},
          {"flat_triangles", reach_json(c.flat)["triangles"]},
          {"smooth_average_triangles", reach_json(c.smooth)["triangles"]},
          {"ratio", c.ratio},
          {"flat_ms_per_frame", c.flat.ms > 0 ? nlohmann::json(c.flat.ms) : nlohmann::json(nullptr)},
          {"smooth_average_ms_per_frame", c.smooth.ms > 0 ? nlohmann::json(c.smooth.ms) : nlohmann::json(nullptr)},
          {"flat", reach_json(c.flat)},
          {"smooth_average", reach_json(c.smooth)}};
}

// A one-line progress bar on stderr, redrawn in place.
class Bar {
 public:
  void operator()(size_t done, size_t total, const std::string& now) {
    const double share = total ? double(done) / double(total) : 1;
    const int width = 30, filled = int(share * width + 0.5);
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    std::string bar(size_t(filled), '#');
    bar += std::string(size_t(width - filled), '-');
    char eta[32] = "";
    if (share > 0.02 && share < 1) std::snprintf(eta, sizeof eta, ", ~%.0fs left", s / share - s);
    std::fprintf(stderr, "\r[%s] %3.0f%% %4.0fs%-14s %-60.60s", bar.c_str(), 100 * share, s, eta, now.c_str());
    std::fflush(stderr);
  }
  void finish() {
    std::fprintf(stderr, "\r%*s\r", 125, "");
    std::fflush(stderr);
  }

 private:
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

}  // namespace

void add_report(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "report",
      "Shading error against run time, flat vs smooth: the icosphere at each depth against the ray-cast "
      "ideal sphere, over lighting setups, normal weightings and backends; plus every scene's regression "
      "checks against Mesa. Writes results.csv, error_vs_time.svg and index.html");
  struct Args {
    std::string out = "report", backends, lightings, shadings, scenes;
    int min_depth = -1, max_depth = -1, size = 0, frames = 0;
    bool quick = false, json = false, no_regression = false, no_progress = false;
  };
  auto a = std::make_shared<Args>();
  cmd->add_option("--out", a->out, "Folder for the files")->capture_default_str();
  cmd->add_flag("--quick", a->quick, "A small sweep: depths 0..4, mesa and soft, 256x256, one timed frame");
  cmd->add_flag("--json", a->json, "Print a summary object instead of the text summary");
  cmd->add_option("--min-depth", a->min_depth, "Shallowest icosphere depth (default 0)");
  cmd->add_option("--max-depth", a->max_depth, "Deepest icosphere depth (default 8; quick 4)");
  cmd->add_option("--size", a->size, "Picture side in pixels (default 512; quick 256)");
  cmd->add_option("--frames", a->frames, "Timed frames per picture, exactly (default 5, 3 from depth 7, more for fast pictures; quick 1)");
  cmd->add_option("--backends", a->backends, "Comma-separated backends (default mesa,soft,soft-double; quick mesa,soft)");
  cmd->add_option("--lightings", a->lightings, "Comma-separated lighting setups: seed, specular (default both)");
  cmd->add_option("--shadings", a->shadings,
                  "Comma-separated shadings (default all: flat, smooth-average, smooth-area, smooth-angle, "
                  "smooth-max, smooth-sphere)");
  cmd->add_option("--scenes", a->scenes, "Folder of the shipped scene files (default: ./scenes or beside the executable)");
  cmd->add_flag("--no-regression", a->no_regression, "Leave out the regression checks of the scenes");
  cmd->add_flag("--no-progress", a->no_progress, "No progress bar (it is only drawn when stderr is a terminal)");
  cmd->callback([a] {
    report::ReportOptions o = report::default_options(a->quick);
    o.out = a->out;
    if (a->min_depth >= 0) o.sweep.min_depth = a->min_depth;
    if (a->max_depth >= 0) o.sweep.max_depth = a->max_depth;
    if (a->size > 0) o.sweep.size = a->size;
    if (a->frames > 0) {  // exactly that many: no extra frames for fast pictures
      o.sweep.frames = a->frames, o.sweep.frames_deep = std::min(o.sweep.frames_deep, a->frames);
      o.sweep.min_timed_ms = 0;
    }
    if (!a->backends.empty()) o.sweep.backends = split(a->backends);
    if (!a->lightings.empty()) o.sweep.lightings = split(a->lightings);
    if (!a->shadings.empty()) o.sweep.shadings = split(a->shadings);
    if (!o.sweep.shadings.empty()) {  // the headline and the page's pictures need these two
      for (const char* must : {"flat", "smooth-average"})
        if (std::find(o.sweep.shadings.begin(), o.sweep.shadings.end(), must) == o.sweep.shadings.end())
          o.sweep.shadings.insert(o.sweep.shadings.begin(), must);
    }
    if (std::find(o.sweep.backends.begin(), o.sweep.backends.end(), o.sweep.keep_backend) == o.sweep.backends.end() &&
        !o.sweep.backends.empty())
      o.sweep.keep_backend = o.sweep.backends.front();
    o.scenes_dir = a->scenes;
    o.regression = !a->no_regression;
    for (const auto& b : o.sweep.backends) backends::make(b);  // unknown names fail before the sweep
    for (const auto& l : o.sweep.lightings) report::lighting(l, 1);
    for (const auto& s : o.sweep.shadings) report::shading(s);

    const bool bar = !a->no_progress && isatty(STDERR_FILENO);
    auto b = std::make_shared<Bar>();
    report::Progress progress;
    if (bar) progress = [b](size_t done, size_t total, const std::string& now) { (*b)(done, total, now); };
    const report::Report r = report::run(o, progress);
    if (bar) b->finish();

    if (!a->json) {
      std::fputs(report::summary_text(r).c_str(), stdout);
      return;
    }
    nlohmann::json j;
    j["rows"] = r.sweep.rows.size();
    j["quick"] = o.quick;
    j["files"] = {{"csv", r.files.csv},
                  {"svg", r.files.svg},
                  {"svg_triangles", r.files.svg_triangles},
                  {"html", r.files.html},
                  {"images", r.files.images}};
    j["sweep"] = {{"min_depth", o.sweep.min_depth}, {"max_depth", o.sweep.max_depth}, {"size", o.sweep.size},
                  {"backends", o.sweep.backends},   {"lightings", o.sweep.lightings}, {"frames", o.sweep.frames},
                  {"frames_deep", o.sweep.frames_deep}};
    j["headline"] = nlohmann::json::object();
    for (const report::Headline& h : r.headlines) {
      nlohmann::json x = h.crossings.empty() ? nlohmann::json::object() : crossing_json(h.main);
      x["backend"] = h.backend;
      x["found"] = h.found;
      x["crossings"] = nlohmann::json::array();
      for (const auto& c : h.crossings) x["crossings"].push_back(crossing_json(c));
      j["headline"][h.scene] = x;
    }
    j["rounding_floor"] = nlohmann::json::object();
    for (const auto& [name, f] : r.sweep.floors) j["rounding_floor"][name] = f;
    size_t pass = 0;
    nlohmann::json failed = nlohmann::json::array();
    for (const auto& c : r.checks) {
      if (c.pass())
        ++pass;
      else
        failed.push_back({{"scene", c.name}, {"source", c.source}, {"error", c.error}});
    }
    j["regression"] = {{"run", o.regression}, {"scenes_dir", r.scenes_dir}, {"scenes", r.checks.size()},
                       {"pass", pass},        {"failed", failed},          {"seconds", r.regression_seconds}};
    j["sweep_seconds"] = r.sweep.seconds;
    j["seconds"] = r.seconds;
    print_json(j);
  });
}

}  // namespace ffc::cli
