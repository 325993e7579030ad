#include "report/report.h"

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "backends/backend.h"
#include "image/compare.h"
#include "report/ideal.h"
#include "report/metrics.h"
#include "report/paths.h"
#include "report/plot.h"

namespace ffc::report {

namespace fs = std::filesystem;

namespace {

// The square around what the ideal covers, with a margin: the page shows the sphere, not the
// black around it.
struct Box {
  int x = 0, y = 0, side = 0;
};
Box disc_box(const Ideal& ideal, int margin = 8) {
  const int w = ideal.image.width, h = ideal.image.height;
  int x0 = w, y0 = h, x1 = -1, y1 = -1;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      if (ideal.covered[size_t(y) * w + x]) x0 = std::min(x0, x), x1 = std::max(x1, x), y0 = std::min(y0, y), y1 = std::max(y1, y);
  if (x1 < 0) return {0, 0, std::min(w, h)};
  const int side = std::min(std::min(w, h), std::max(x1 - x0, y1 - y0) + 1 + 2 * margin);
  const int cx = (x0 + x1 + 1) / 2, cy = (y0 + y1 + 1) / 2;
  return {std::clamp(cx - side / 2, 0, w - side), std::clamp(cy - side / 2, 0, h - side), side};
}
image::Image crop(const image::Image& img, const Box& b) {
  image::Image out(b.side, b.side);
  for (int y = 0; y < b.side; ++y)
    std::copy_n(img.at(b.x, b.y + y), size_t(b.side) * 4, out.at(0, y));
  return out;
}

void write_text(const fs::path& p, const std::string& text) {
  std::ofstream f(p, std::ios::binary);
  if (!f) throw std::runtime_error("cannot write " + p.string());
  f << text;
  if (!f) throw std::runtime_error("cannot write " + p.string());
}

}  // namespace

std::string picture_path(const std::string& scene, int depth, const std::string& shading, bool error) {
  return "images/" + scene + "_d" + std::to_string(depth) + "_" + shading + (error ? "_error" : "") + ".png";
}
std::string ideal_path(const std::string& scene) { return "images/" + scene + "_ideal.png"; }
std::string regression_path(size_t index, const std::string& name, const std::string& what) {
  std::string safe;
  for (char c : name) safe += std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_' ? c : '_';
  return "images/check_" + std::to_string(index) + "_" + safe + "_" + what + ".png";
}

ReportOptions default_options(bool quick) {
  ReportOptions o;
  o.quick = quick;
  // Phong shading (the GL equation per fragment, the GLSL backend's glsl-phong) beside flat and
  // Gouraud, where this program has that backend (EGL).
  const std::vector<std::string> known = backends::names();
  if (std::find(known.begin(), known.end(), "glsl-phong") != known.end()) o.sweep.backends.push_back("glsl-phong");
  if (quick) {
    o.sweep.min_depth = 0, o.sweep.max_depth = 4;
    o.sweep.backends = {"mesa", "soft"};
    o.sweep.size = 256;
    o.sweep.frames = o.sweep.frames_deep = 1;
    o.sweep.min_timed_ms = 0;
    o.sweep.keep_depths = {1, 3};
  }
  return o;
}

const std::vector<std::string>& csv_columns() {
  static const std::vector<std::string> c = {
      "depth",     "triangles",   "vertices",        "shading",          "shade_model",       "normals",
      "scene",     "backend",     "rmse",            "max_error",        "rmse_exact",        "both_pixels",
      "silhouette_pixels", "silhouette_share", "ms_per_frame", "frames", "normals_ms"};
  return c;
}

std::string to_csv(const std::vector<Row>& rows) {
  std::ostringstream s;
  for (size_t i = 0; i < csv_columns().size(); ++i) s << (i ? "," : "") << csv_columns()[i];
  s << "\n";
  char b[512];
  for (const Row& r : rows) {
    std::snprintf(b, sizeof b, "%d,%zu,%zu,%s,%s,%s,%s,%s,%.6f,%d,%.6f,%zu,%zu,%.6f,%.4f,%d,%.4f\n", r.depth, r.triangles,
                  r.vertices, r.shading.c_str(), r.shade_model.c_str(), r.normals.c_str(), r.scene.c_str(),
                  r.backend.c_str(), r.rmse, r.max_error, r.rmse_exact, r.both_pixels, r.silhouette_pixels,
                  r.silhouette_share, r.ms_per_frame, r.frames, r.normals_ms);
    s << b;
  }
  return s.str();
}

std::string short_count(double n) {
  char b[32];
  if (std::isnan(n)) return "n/a";
  if (n >= 1e6)
    std::snprintf(b, sizeof b, "%.3gM", n / 1e6);
  else if (n >= 1e4)
    std::snprintf(b, sizeof b, "%.3gk", n / 1e3);
  else
    std::snprintf(b, sizeof b, "%.0f", n);
  return b;
}

Report run(const ReportOptions& o, const Progress& progress) {
  using Clock = std::chrono::steady_clock;
  const auto t0 = Clock::now();
  Report r;
  r.options = o;
  const fs::path out(o.out);
  fs::create_directories(out / "images");
  r.sweep = run_sweep(o.sweep, progress);
  r.headlines = headlines(r.sweep.rows, o.sweep.keep_backend);

  // The pictures the page shows: the ideal, then flat and smooth-average with their error maps.
  // Cropped to the sphere.
  for (const auto& [name, ideal] : r.sweep.ideals)
    image::write_png((out / ideal_path(name)).string(), crop(ideal.image, disc_box(ideal)));
  for (const Kept& k : r.sweep.kept) {
    size_t i = 0;
    while (i < r.sweep.ideals.size() && r.sweep.ideals[i].first != k.scene) ++i;
    if (i == r.sweep.ideals.size()) continue;
    const Ideal& ideal = r.sweep.ideals[i].second;
    const Box box = disc_box(ideal);
    image::write_png((out / picture_path(k.scene, k.depth, k.shading, false)).string(), crop(k.picture, box));
    image::write_png((out / picture_path(k.scene, k.depth, k.shading, true)).string(), crop(error_map(k.picture, ideal), box));
  }

  if (o.regression) {
    const auto tr = Clock::now();
    if (progress) progress(1, 1, "regression checks");
    r.scenes_dir = find_scenes_dir(o.scenes_dir);
    r.checks = check_scenes(r.scenes_dir);
    for (size_t i = 0; i < r.checks.size(); ++i) {
      const SceneCheck& c = r.checks[i];
      if (!c.error.empty()) continue;
      image::write_png((out / regression_path(i, c.name, "mesa")).string(), c.mesa);
      image::write_png((out / regression_path(i, c.name, "diff")).string(), image::heat_map(c.mesa, c.soft));
    }
    r.regression_seconds = std::chrono::duration<double>(Clock::now() - tr).count();
  }

  r.files.csv = (out / "results.csv").string();
  r.files.svg = (out / "error_vs_time.svg").string();
  r.files.svg_triangles = (out / "error_vs_triangles.svg").string();
  r.files.html = (out / "index.html").string();
  r.files.images = (out / "images").string();
  write_text(r.files.csv, to_csv(r.sweep.rows));
  write_text(r.files.svg, error_vs_time_svg(r.sweep.rows, r.sweep.floors));
  write_text(r.files.svg_triangles,
             error_vs_triangles_svg(r.sweep.rows, r.sweep.floors, o.sweep.keep_backend, r.headlines));
  r.seconds = std::chrono::duration<double>(Clock::now() - t0).count();
  write_text(r.files.html, html_page(r));
  return r;
}

namespace {

std::string reach_text(const Reach& x) {
  if (std::isnan(x.triangles)) return "not reached";
  std::string s = short_count(x.triangles) + " triangles";
  if (x.at_start) s = "<= " + s;
  if (x.extrapolated) s = "~" + s + " (extrapolated)";
  if (x.ms > 0) {
    char b[48];
    std::snprintf(b, sizeof b, " (%.3g ms/frame)", x.ms);
    s += b;
  }
  return s;
}

}  // namespace

std::string summary_text(const Report& r) {
  std::ostringstream s;
  char b[512];
  const SweepOptions& w = r.options.sweep;
  std::snprintf(b, sizeof b, "report: %zu pictures (icosphere depths %d-%d, %zu lighting setups, %zu backends, %dx%d) in %.1f s",
                r.sweep.rows.size(), w.min_depth, w.max_depth, w.lightings.size(), w.backends.size(), w.size, w.size,
                r.sweep.seconds);
  s << b << "\n";
  for (const auto& [name, f] : r.sweep.floors) {
    std::snprintf(b, sizeof b, "  %s: 8-bit rounding alone leaves %.3f steps RMSE against the exact colours\n", name.c_str(), f);
    s << b;
  }
  s << "headline (" << w.keep_backend << "): triangles GL_FLAT needs against GL_SMOOTH with averaged normals, same shading RMSE\n";
  for (const Headline& h : r.headlines) {
    if (h.crossings.empty()) {
      s << "  " << h.scene << ": no common RMSE within the sweep\n";
      continue;
    }
    const Crossing& m = h.main;
    std::snprintf(b, sizeof b, "  %-9s RMSE %g steps: flat %s, smooth-average %s: %sx the triangles\n",
                  (h.scene + ":").c_str(), m.target_rmse, reach_text(m.flat).c_str(), reach_text(m.smooth).c_str(),
                  ratio_text(m.ratio).c_str());
    s << b;
    for (const Crossing& x : h.crossings) {
      if (x.target_rmse == m.target_rmse) continue;
      std::snprintf(b, sizeof b, "            RMSE %g: flat %s, smooth-average %s: %sx\n", x.target_rmse,
                    reach_text(x.flat).c_str(), reach_text(x.smooth).c_str(), ratio_text(x.ratio).c_str());
      s << b;
    }
  }
  // A few rows: the deepest and a middle depth on the kept backend.
  s << "selected rows (" << w.keep_backend << "):\n";
  std::snprintf(b, sizeof b, "  %-9s %5s %9s %-15s %7s %5s %9s %11s\n", "scene", "depth", "triangles", "shading", "rmse",
                "max", "ms/frame", "silhouette");
  s << b;
  const int mid = (w.min_depth + w.max_depth + 1) / 2;
  for (const Row& row : r.sweep.rows) {
    if (row.backend != w.keep_backend || (row.depth != mid && row.depth != w.max_depth)) continue;
    if (row.shading != "flat" && row.shading != "smooth-average" && row.shading != "smooth-sphere") continue;
    std::snprintf(b, sizeof b, "  %-9s %5d %9zu %-15s %7.3f %5d %9.2f %11zu\n", row.scene.c_str(), row.depth,
                  row.triangles, row.shading.c_str(), row.rmse, row.max_error, row.ms_per_frame, row.silhouette_pixels);
    s << b;
  }
  if (r.options.regression) {
    size_t pass = 0;
    for (const SceneCheck& c : r.checks) pass += c.pass();
    std::snprintf(b, sizeof b, "regression: %zu of %zu scenes pass against Mesa (vertex and pixel) in %.1f s%s\n", pass,
                  r.checks.size(), r.regression_seconds,
                  r.scenes_dir.empty() ? "; no shipped scenes found, built-ins only" : "");
    s << b;
    for (const SceneCheck& c : r.checks)
      if (!c.pass()) s << "  FAIL " << c.name << " (" << c.source << ")" << (c.error.empty() ? "" : ": " + c.error) << "\n";
  }
  s << "files: " << r.files.csv << ", " << r.files.svg << ", " << r.files.svg_triangles << ", " << r.files.html << "\n";
  std::snprintf(b, sizeof b, "total %.1f s\n", r.seconds);
  s << b;
  return s.str();
}

}  // namespace ffc::report
