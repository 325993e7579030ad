#include "report/plot.h"

#include "report/headline.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <sstream>

namespace ffc::report {

namespace {

std::string num(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%.1f", v);
  return b;
}

// 0.01, 0.1, 1, 10, 100, 1k, 10k, 100k, 1M, ... for a decade value; 2, 5, 20, 0.5, 2k for others.
std::string tick_label(double v) {
  char b[32];
  if (v >= 1e6)
    std::snprintf(b, sizeof b, "%gM", v / 1e6);
  else if (v >= 1e3)
    std::snprintf(b, sizeof b, "%gk", v / 1e3);
  else
    std::snprintf(b, sizeof b, "%g", v);
  return b;
}

struct Axis {
  double lo = 0, hi = 1;  // log10 range
  double to(double v, double a, double b) const { return a + (std::log10(v) - lo) / (hi - lo) * (b - a); }
};

Axis axis_for(double mn, double mx) {
  Axis a;
  if (!(mn > 0) || !(mx > 0)) return a;
  a.lo = std::floor(std::log10(mn) * 2 - 0.05) / 2;
  a.hi = std::ceil(std::log10(mx) * 2 + 0.05) / 2;
  if (a.hi - a.lo < 1) a.lo -= 0.5, a.hi += 0.5;
  return a;
}

void marker(std::ostringstream& s, const std::string& kind, double x, double y, const std::string& color) {
  if (kind == "square")
    s << "<rect x=\"" << num(x - 3.5) << "\" y=\"" << num(y - 3.5) << "\" width=\"7\" height=\"7\" fill=\"" << color
      << "\"/>";
  else if (kind == "triangle")
    s << "<path d=\"M" << num(x) << " " << num(y - 4.5) << " L" << num(x + 4.5) << " " << num(y + 3.5) << " L"
      << num(x - 4.5) << " " << num(y + 3.5) << " Z\" fill=\"" << color << "\"/>";
  else if (kind == "diamond")
    s << "<path d=\"M" << num(x) << " " << num(y - 4.5) << " L" << num(x + 4.5) << " " << num(y) << " L" << num(x)
      << " " << num(y + 4.5) << " L" << num(x - 4.5) << " " << num(y) << " Z\" fill=\"" << color << "\"/>";
  else if (kind == "open")
    s << "<circle cx=\"" << num(x) << "\" cy=\"" << num(y) << "\" r=\"3.5\" fill=\"white\" stroke=\"" << color
      << "\" stroke-width=\"1.5\"/>";
  else if (!kind.empty())
    s << "<circle cx=\"" << num(x) << "\" cy=\"" << num(y) << "\" r=\"3.5\" fill=\"" << color << "\"/>";
}

}  // namespace

std::string xml_escape(const std::string& in) {
  std::string out;
  for (char c : in) switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      default: out += c;
    }
  return out;
}

std::string log_log_chart(const std::vector<Panel>& panels, const ChartOptions& o) {
  double xmin = std::numeric_limits<double>::infinity(), xmax = 0, ymin = xmin, ymax = 0;
  for (const Panel& p : panels) {
    for (const Series& s : p.series)
      for (auto [x, y] : s.points)
        if (x > 0 && y > 0) xmin = std::min(xmin, x), xmax = std::max(xmax, x), ymin = std::min(ymin, y), ymax = std::max(ymax, y);
    if (p.hline > 0) ymin = std::min(ymin, p.hline), ymax = std::max(ymax, p.hline);
  }
  const Axis ax = axis_for(xmin, xmax), ay = axis_for(ymin, ymax);
  const int n = std::max<int>(1, int(panels.size()));
  const int cols = o.columns > 0 ? std::min(o.columns, n) : n, rows = (n + cols - 1) / cols;
  const int left = 80, gap = 80, row_gap = 96, right = 30, top = o.title.empty() ? 40 : 74;
  const int width = left + cols * o.panel_width + (cols - 1) * gap + right;
  const int legend_top = top + rows * o.panel_height + (rows - 1) * row_gap + 66;
  const int height = legend_top + int(o.legend_rows.size()) * 24 + (o.note.empty() ? 10 : 34);
  std::ostringstream s;
  s << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
    << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << width << "\" height=\"" << height << "\" viewBox=\"0 0 "
    << width << " " << height << "\" font-family=\"DejaVu Sans, Helvetica, Arial, sans-serif\" font-size=\"12\">\n"
    << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  if (!o.title.empty())
    s << "<text x=\"" << width / 2 << "\" y=\"26\" text-anchor=\"middle\" font-size=\"17\" font-weight=\"bold\">"
      << xml_escape(o.title) << "</text>\n";
  const double span_x = ax.hi - ax.lo, span_y = ay.hi - ay.lo;
  for (int pi = 0; pi < int(panels.size()); ++pi) {
    const Panel& p = panels[size_t(pi)];
    const int col = pi % cols, row = pi / cols;
    const double x0 = left + col * (o.panel_width + gap), x1 = x0 + o.panel_width;
    const double y1 = top + row * (o.panel_height + row_gap), y0 = y1 + o.panel_height;  // y0: bottom
    auto X = [&](double v) { return ax.to(v, x0, x1); };
    auto Y = [&](double v) { return ay.to(v, y0, y1); };
    s << "<g>\n<text x=\"" << num((x0 + x1) / 2) << "\" y=\"" << num(y1 - 10)
      << "\" text-anchor=\"middle\" font-size=\"14\" font-weight=\"bold\">" << xml_escape(p.title) << "</text>\n";
    s << "<clipPath id=\"clip" << pi << "\"><rect x=\"" << num(x0) << "\" y=\"" << num(y1) << "\" width=\""
      << o.panel_width << "\" height=\"" << o.panel_height << "\"/></clipPath>\n";
    // Grid and ticks: decades (labelled), 2..9 (faint; labelled at 2 and 5 over short ranges).
    auto ticks = [&](const Axis& a, double span, bool is_x) {
      for (int e = int(std::floor(a.lo)); e <= int(std::ceil(a.hi)); ++e)
        for (int m = 1; m <= 9; ++m) {
          const double v = m * std::pow(10.0, e), lv = std::log10(v);
          if (lv < a.lo - 1e-9 || lv > a.hi + 1e-9) continue;
          const bool major = m == 1, labelled = major || (span <= 2.01 && (m == 2 || m == 5));
          const std::string stroke = major ? "#c8c8c8" : "#ececec";
          if (is_x) {
            const double x = X(v);
            s << "<line x1=\"" << num(x) << "\" y1=\"" << num(y1) << "\" x2=\"" << num(x) << "\" y2=\"" << num(y0)
              << "\" stroke=\"" << stroke << "\"/>";
            s << "<line x1=\"" << num(x) << "\" y1=\"" << num(y0) << "\" x2=\"" << num(x) << "\" y2=\""
              << num(y0 + (major ? 6 : 3)) << "\" stroke=\"#333\"/>";
            if (labelled)
              s << "<text x=\"" << num(x) << "\" y=\"" << num(y0 + 20) << "\" text-anchor=\"middle\""
                << (major ? "" : " fill=\"#666\" font-size=\"11\"") << ">" << tick_label(v) << "</text>";
          } else {
            const double y = Y(v);
            s << "<line x1=\"" << num(x0) << "\" y1=\"" << num(y) << "\" x2=\"" << num(x1) << "\" y2=\"" << num(y)
              << "\" stroke=\"" << stroke << "\"/>";
            s << "<line x1=\"" << num(x0 - (major ? 6 : 3)) << "\" y1=\"" << num(y) << "\" x2=\"" << num(x0)
              << "\" y2=\"" << num(y) << "\" stroke=\"#333\"/>";
            if (labelled)
              s << "<text x=\"" << num(x0 - 9) << "\" y=\"" << num(y + 4) << "\" text-anchor=\"end\""
                << (major ? "" : " fill=\"#666\" font-size=\"11\"") << ">" << tick_label(v) << "</text>";
          }
          s << "\n";
        }
    };
    ticks(ax, span_x, true);
    ticks(ay, span_y, false);
    s << "<rect x=\"" << num(x0) << "\" y=\"" << num(y1) << "\" width=\"" << o.panel_width << "\" height=\""
      << o.panel_height << "\" fill=\"none\" stroke=\"#333\"/>\n";
    s << "<text x=\"" << num((x0 + x1) / 2) << "\" y=\"" << num(y0 + 42) << "\" text-anchor=\"middle\" font-size=\"13\">"
      << xml_escape(o.x_label) << "</text>\n";
    if (col == 0)
      s << "<text transform=\"translate(" << num(x0 - 52) << "," << num((y0 + y1) / 2)
        << ") rotate(-90)\" text-anchor=\"middle\" font-size=\"13\">" << xml_escape(o.y_label) << "</text>\n";
    if (p.hline > 0) {
      const double y = Y(p.hline);
      s << "<line x1=\"" << num(x0) << "\" y1=\"" << num(y) << "\" x2=\"" << num(x1) << "\" y2=\"" << num(y)
        << "\" stroke=\"#888\" stroke-dasharray=\"8 4\" stroke-width=\"1.2\"/>";
      s << "<text x=\"" << num(x0 + 6) << "\" y=\"" << num(y + 14) << "\" fill=\"#555\" font-size=\"11\">"
        << xml_escape(p.hline_label) << "</text>\n";
    }
    s << "<g clip-path=\"url(#clip" << pi << ")\">\n";
    for (const Series& se : p.series) {
      std::vector<std::pair<double, double>> pts;
      for (auto [x, y] : se.points)
        if (x > 0 && y > 0) pts.push_back({X(x), Y(y)});
      if (pts.empty()) continue;
      s << "<polyline fill=\"none\" stroke=\"" << se.color << "\" stroke-width=\"" << num(se.width) << "\"";
      if (!se.dash.empty()) s << " stroke-dasharray=\"" << se.dash << "\"";
      s << " points=\"";
      for (auto [x, y] : pts) s << num(x) << "," << num(y) << " ";
      s << "\"><title>" << xml_escape(se.label) << "</title></polyline>\n";
      for (auto [x, y] : pts) marker(s, se.marker, x, y, se.color);
      s << "\n";
    }
    s << "</g>\n";
    // Point labels outside the clip, so a label at the edge stays readable.
    for (const Series& se : p.series)
      for (size_t i = 0; i < se.points.size() && i < se.point_labels.size(); ++i) {
        const auto [x, y] = se.points[i];
        if (!(x > 0 && y > 0) || se.point_labels[i].empty()) continue;
        if (se.labels_below_left)
          s << "<text x=\"" << num(X(x) - 6) << "\" y=\"" << num(Y(y) + 15) << "\" text-anchor=\"end\"";
        else
          s << "<text x=\"" << num(X(x) + 6) << "\" y=\"" << num(Y(y) - 6) << "\"";
        s << " font-size=\"10\" fill=\"" << se.color << "\">" << xml_escape(se.point_labels[i]) << "</text>";
      }
    for (const Measure& m : p.measures) {
      if (!(m.x_from > 0 && m.x_to > 0 && m.y > 0)) continue;
      const double a = X(std::min(m.x_from, m.x_to)), b = X(std::max(m.x_from, m.x_to)), y = Y(m.y);
      s << "<g stroke=\"#333\" stroke-width=\"1.3\" fill=\"#333\"><line x1=\"" << num(a) << "\" y1=\"" << num(y)
        << "\" x2=\"" << num(b) << "\" y2=\"" << num(y) << "\"/>"
        << "<path d=\"M" << num(a) << " " << num(y) << " l7 -4 v8 Z\"/><path d=\"M" << num(b) << " " << num(y)
        << " l-7 -4 v8 Z\"/></g><text x=\"" << num((a + b) / 2) << "\" y=\"" << num(y - 7)
        << "\" text-anchor=\"middle\" font-size=\"12\" font-weight=\"bold\" fill=\"#222\">" << xml_escape(m.label)
        << "</text>\n";
    }
    s << "\n</g>\n";
  }
  // Legend rows, centred.
  for (size_t r = 0; r < o.legend_rows.size(); ++r) {
    const auto& lrow = o.legend_rows[r];
    double w = 0;
    for (const LegendEntry& e : lrow) w += (e.color.empty() ? 0 : 46) + 7.0 * double(e.label.size()) + 18;
    double x = std::max(10.0, (width - w) / 2);
    const double y = legend_top + 24.0 * double(r);
    for (const LegendEntry& e : lrow) {
      if (e.color.empty()) {  // a heading
        s << "<text x=\"" << num(x) << "\" y=\"" << num(y + 4) << "\" font-weight=\"bold\">" << xml_escape(e.label)
          << "</text>";
        x += 7.0 * double(e.label.size()) + 18;
        continue;
      }
      s << "<line x1=\"" << num(x) << "\" y1=\"" << num(y) << "\" x2=\"" << num(x + 36) << "\" y2=\"" << num(y)
        << "\" stroke=\"" << e.color << "\" stroke-width=\"1.8\"";
      if (!e.dash.empty()) s << " stroke-dasharray=\"" << e.dash << "\"";
      s << "/>";
      marker(s, e.marker, x + 18, y, e.color);
      s << "<text x=\"" << num(x + 44) << "\" y=\"" << num(y + 4) << "\">" << xml_escape(e.label) << "</text>\n";
      x += 46 + 7.0 * double(e.label.size()) + 18;
    }
  }
  if (!o.note.empty())
    s << "<text x=\"" << width / 2 << "\" y=\"" << height - 12 << "\" text-anchor=\"middle\" fill=\"#555\" font-size=\"11\">"
      << xml_escape(o.note) << "</text>\n";
  s << "</svg>\n";
  return s.str();
}

std::string shading_color(const std::string& shading) {
  static const std::map<std::string, std::string> c = {{"flat", "#D55E00"},          {"smooth-average", "#0072B2"},
                                                       {"smooth-area", "#009E73"},   {"smooth-angle", "#CC79A7"},
                                                       {"smooth-max", "#E69F00"},    {"smooth-sphere", "#000000"}};
  auto it = c.find(shading);
  return it == c.end() ? "#777777" : it->second;
}

std::string shading_marker(const std::string& shading) {
  static const std::map<std::string, std::string> m = {{"flat", "circle"},        {"smooth-average", "square"},
                                                       {"smooth-area", "triangle"}, {"smooth-angle", "diamond"},
                                                       {"smooth-max", "open"},      {"smooth-sphere", "circle"}};
  auto it = m.find(shading);
  return it == m.end() ? "circle" : it->second;
}

namespace {

std::vector<std::string> distinct(const std::vector<Row>& rows, std::string Row::*field) {
  std::vector<std::string> out;
  for (const Row& r : rows)
    if (std::find(out.begin(), out.end(), r.*field) == out.end()) out.push_back(r.*field);
  return out;
}

// Drawing order: the smooth weightings first (they overlap), exact normals dashed on top of them,
// then smooth-average and flat, the two the headline compares.
std::vector<std::string> draw_order(std::vector<std::string> shadings) {
  auto rank = [](const std::string& s) {
    if (s == "flat") return 5;
    if (s == "smooth-average") return 4;
    if (s == "smooth-sphere") return 3;
    return 0;
  };
  std::stable_sort(shadings.begin(), shadings.end(),
                   [&](const std::string& a, const std::string& b) { return rank(a) < rank(b); });
  return shadings;
}

Series shading_series(const std::string& sh) {
  Series s;
  s.label = sh;
  s.color = shading_color(sh), s.marker = shading_marker(sh);
  if (sh == "smooth-sphere") s.dash = "5 3", s.width = 1.4;
  if (sh != "flat" && sh != "smooth-average" && sh != "smooth-sphere") s.width = 1.4;
  return s;
}

std::vector<std::vector<LegendEntry>> legend(const std::vector<std::string>& shadings) {
  std::vector<LegendEntry> a{{"shading:", "", "", ""}};
  for (const std::string& s : shadings) {
    const Series x = shading_series(s);
    a.push_back({s, x.color, x.dash, x.marker});
  }
  return {a};
}

std::string floor_label(double f) {
  char b[96];
  std::snprintf(b, sizeof b, "8-bit rounding floor: %.2f", f);
  return b;
}

double floor_of(const std::vector<std::pair<std::string, double>>& floors, const std::string& scene) {
  for (const auto& [n, f] : floors)
    if (n == scene) return f;
  return 0;
}

}  // namespace

std::string error_vs_time_svg(const std::vector<Row>& rows, const std::vector<std::pair<std::string, double>>& floors) {
  const auto scenes = distinct(rows, &Row::scene), shadings = distinct(rows, &Row::shading),
             backends = distinct(rows, &Row::backend);
  std::vector<Panel> panels;
  for (const std::string& sc : scenes)
    for (const std::string& b : backends) {
      Panel p;
      p.title = sc + " lighting, " + b;
      p.hline = floor_of(floors, sc);
      p.hline_label = floor_label(p.hline);
      for (const std::string& sh : draw_order(shadings)) {
        Series s = shading_series(sh);
        s.label = sh + " on " + b;
        std::vector<const Row*> pts;
        for (const Row& r : rows)
          if (r.scene == sc && r.shading == sh && r.backend == b) pts.push_back(&r);
        std::sort(pts.begin(), pts.end(), [](const Row* x, const Row* y) { return x->depth < y->depth; });
        const bool labelled = sh == "flat" || sh == "smooth-average";
        s.labels_below_left = sh == "smooth-average";
        for (const Row* r : pts) {
          s.points.push_back({r->ms_per_frame, r->rmse});
          s.point_labels.push_back(labelled ? std::to_string(r->depth) : "");
        }
        p.series.push_back(s);
      }
      panels.push_back(p);
    }
  ChartOptions o;
  o.title = "Shading error against run time: icosphere depths " +
            std::to_string(rows.empty() ? 0 : rows.front().depth) + " to " +
            std::to_string(rows.empty() ? 0 : rows.back().depth);
  o.x_label = "milliseconds per frame (median)";
  o.y_label = "RMSE against the ideal (8-bit steps)";
  o.columns = int(backends.size());
  o.panel_width = backends.size() >= 3 ? 400 : 520;
  o.panel_height = backends.size() >= 3 ? 300 : 360;
  o.legend_rows = legend(shadings);
  o.note = "Error over the pixels both cover (silhouette apart). Numbers: subdivision depth (flat above, smooth-average "
           "below). Lower left is better.";
  return log_log_chart(panels, o);
}

std::string error_vs_triangles_svg(const std::vector<Row>& rows,
                                   const std::vector<std::pair<std::string, double>>& floors, const std::string& backend,
                                   const std::vector<Headline>& headlines) {
  const auto scenes = distinct(rows, &Row::scene), shadings = distinct(rows, &Row::shading);
  std::vector<Panel> panels;
  for (const std::string& sc : scenes) {
    Panel p;
    p.title = sc + " lighting, " + backend;
    p.hline = floor_of(floors, sc);
    p.hline_label = floor_label(p.hline);
    for (const std::string& sh : draw_order(shadings)) {
      Series s = shading_series(sh);
      for (const Row& r : rows)
        if (r.scene == sc && r.shading == sh && r.backend == backend) s.points.push_back({double(r.triangles), r.rmse});
      std::sort(s.points.begin(), s.points.end());
      p.series.push_back(s);
    }
    for (const Headline& h : headlines)
      if (h.scene == sc && !h.crossings.empty()) {
        char b[96];
        std::snprintf(b, sizeof b, "%s× the triangles at %g steps", ratio_text(h.main.ratio).c_str(), h.main.target_rmse);
        p.measures.push_back({h.main.smooth.triangles, h.main.flat.triangles, h.main.target_rmse, b});
      }
    panels.push_back(p);
  }
  ChartOptions o;
  o.title = "Shading error against triangles (" + backend + ")";
  o.x_label = "triangles";
  o.y_label = "RMSE against the ideal (8-bit steps)";
  o.legend_rows = legend(shadings);
  o.note = "Read across at one RMSE: how many more triangles GL_FLAT needs than GL_SMOOTH with averaged normals.";
  return log_log_chart(panels, o);
}

}  // namespace ffc::report
