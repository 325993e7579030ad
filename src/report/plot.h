// Hand-written SVG: log-log line charts in panels side by side, with decade ticks, axis labels and
// a legend below; and the report's two charts built on it.
#pragma once
#include <string>
#include <utility>
#include <vector>

#include "report/sweep.h"

namespace ffc::report {

struct Series {
  std::string label;
  std::string color = "#000";
  std::string dash;    // stroke-dasharray, empty: solid
  std::string marker;  // circle, square, triangle, diamond
  std::vector<std::pair<double, double>> points;  // (x, y), both > 0
  std::vector<std::string> point_labels;          // drawn beside each point when not empty
  bool labels_below_left = false;                 // labels below left of the points (default: above right)
  double width = 1.8;                             // stroke width
};

// A horizontal double-headed measure between two x values at one y, labelled above its middle.
struct Measure {
  double x_from = 0, x_to = 0, y = 0;
  std::string label;
};

struct Panel {
  std::string title;
  std::vector<Series> series;
  double hline = 0;          // a dashed horizontal reference line at this y (0: none)...
  std::string hline_label;   // ...and its label
  std::vector<Measure> measures;
};

// One legend entry: a short line in a colour and dash, with a marker.
struct LegendEntry {
  std::string label, color, dash, marker;
};

struct ChartOptions {
  std::string title, x_label, y_label;
  int panel_width = 540, panel_height = 420;
  int columns = 0;  // panels per row; 0: all in one row
  std::vector<std::vector<LegendEntry>> legend_rows;  // one row each, under the panels
  std::string note;                                   // a line of small text at the bottom
};

// The panels share their axes (the range of every point of every panel, widened to whole or half
// decades), laid out `columns` to a row. Points that are not positive are left out.
std::string log_log_chart(const std::vector<Panel>& panels, const ChartOptions& o);

// The report's charts. RMSE against milliseconds per frame: a panel per lighting setup (rows) and
// backend (columns), one curve per shading, flat and smooth-average labelled with their depths.
// RMSE against triangles on one backend: a panel per lighting setup, with the headlines drawn as
// measures between the flat and smooth-average curves.
std::string error_vs_time_svg(const std::vector<Row>& rows, const std::vector<std::pair<std::string, double>>& floors);
struct Headline;
std::string error_vs_triangles_svg(const std::vector<Row>& rows,
                                   const std::vector<std::pair<std::string, double>>& floors,
                                   const std::string& backend = "mesa", const std::vector<Headline>& headlines = {});

// Colour and marker of a shading, as the charts draw them.
std::string shading_color(const std::string& shading);
std::string shading_marker(const std::string& shading);

// Escapes &, <, >, " for XML and HTML text.
std::string xml_escape(const std::string& s);

}  // namespace ffc::report
