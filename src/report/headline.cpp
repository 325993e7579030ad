#include "report/headline.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace ffc::report {

Reach triangles_to_reach(std::vector<CurvePoint> c, double target) {
  Reach r;
  r.triangles = std::numeric_limits<double>::quiet_NaN();
  c.erase(std::remove_if(c.begin(), c.end(), [](const CurvePoint& p) { return !(p.triangles > 0) || !(p.rmse >= 0); }),
          c.end());
  if (c.empty() || !(target > 0)) return r;
  std::sort(c.begin(), c.end(), [](const CurvePoint& a, const CurvePoint& b) { return a.triangles < b.triangles; });
  if (c[0].rmse <= target) {
    r.triangles = c[0].triangles, r.ms = c[0].ms, r.reached = r.at_start = true;
    return r;
  }
  // Interpolates log T (and log ms) in log e between a (above the target) and b.
  auto between = [&](const CurvePoint& a, const CurvePoint& b) {
    // A picture that matches exactly (b.rmse 0) has no logarithm: linear in e then.
    const double s = b.rmse <= 0 ? (a.rmse - target) / (a.rmse - b.rmse)
                                 : (std::log(a.rmse) - std::log(target)) / (std::log(a.rmse) - std::log(b.rmse));
    auto lerp_log = [&](double x, double y) { return std::exp(std::log(x) + s * (std::log(y) - std::log(x))); };
    r.triangles = lerp_log(a.triangles, b.triangles);
    r.ms = a.ms > 0 && b.ms > 0 ? lerp_log(a.ms, b.ms) : 0;
  };
  for (size_t i = 1; i < c.size(); ++i)
    if (c[i].rmse <= target) {
      between(c[i - 1], c[i]);
      r.reached = true;
      return r;
    }
  if (c.size() >= 2) {
    const CurvePoint &a = c[c.size() - 2], &b = c.back();
    if (b.rmse < a.rmse && b.triangles > a.triangles) {
      between(a, b);
      r.extrapolated = true;
    }
  }
  return r;
}

std::string ratio_text(double ratio) {
  char b[32];
  if (!(ratio > 0) || !std::isfinite(ratio)) return "n/a";
  std::snprintf(b, sizeof b, ratio < 1 ? "%.2f" : ratio < 10 ? "%.1f" : "%.0f", ratio);
  return b;
}

std::vector<CurvePoint> curve(const std::vector<Row>& rows, const std::string& scene, const std::string& shading,
                              const std::string& backend) {
  std::vector<CurvePoint> c;
  for (const Row& r : rows)
    if (r.scene == scene && r.shading == shading && r.backend == backend)
      c.push_back({double(r.triangles), r.rmse, r.ms_per_frame});
  std::sort(c.begin(), c.end(), [](const CurvePoint& a, const CurvePoint& b) { return a.triangles < b.triangles; });
  return c;
}

std::vector<Headline> headlines(const std::vector<Row>& rows, const std::string& backend) {
  std::vector<std::string> scenes;
  for (const Row& r : rows)
    if (std::find(scenes.begin(), scenes.end(), r.scene) == scenes.end()) scenes.push_back(r.scene);
  std::vector<Headline> out;
  for (const std::string& scene : scenes) {
    Headline h;
    h.scene = scene, h.backend = backend;
    const auto flat = curve(rows, scene, "flat", backend), smooth = curve(rows, scene, "smooth-average", backend);
    if (flat.empty() || smooth.empty()) continue;
    bool have_extrapolated = false;
    Crossing fallback;
    for (double target : {16.0, 8.0, 4.0, 2.0, 1.0, 0.5}) {
      Crossing x;
      x.target_rmse = target;
      x.flat = triangles_to_reach(flat, target);
      x.smooth = triangles_to_reach(smooth, target);
      if (std::isnan(x.flat.triangles) || std::isnan(x.smooth.triangles)) continue;
      // Both at the start of their curves says nothing about the difference.
      if (x.flat.at_start) continue;
      x.ratio = x.flat.triangles / x.smooth.triangles;
      h.crossings.push_back(x);
      if (x.flat.reached && x.smooth.reached) {
        h.main = x;
        h.found = true;
      } else if (!have_extrapolated) {
        fallback = x;
        have_extrapolated = true;
      }
    }
    if (!h.found && have_extrapolated) h.main = fallback;
    out.push_back(h);
  }
  return out;
}

}  // namespace ffc::report
