// `ffcompat report`: the sweep (report/sweep.h), the headline (report/headline.h), the regression
// checks (report/regression.h), written to a folder:
//   results.csv             one row per depth, shading, scene (lighting setup) and backend
//   error_vs_time.svg       RMSE against milliseconds per frame, log-log, per lighting setup
//   error_vs_triangles.svg  RMSE against triangles on Mesa: where the headline is read
//   index.html              the pictures side by side, the tables, the regression results
//   images/                 the PNGs the page shows
#pragma once
#include <string>
#include <vector>

#include "report/headline.h"
#include "report/regression.h"
#include "report/sweep.h"

namespace ffc::report {

struct ReportOptions {
  std::string out = "report";
  bool quick = false;
  SweepOptions sweep;
  bool regression = true;
  std::string scenes_dir;  // empty: find_scenes_dir()
};

// The full sweep: depths 0..8, both lighting setups, every shading, mesa, soft and soft-double (and
// glsl-phong, per fragment, for the smooth shadings, where the program has it),
// 512x512, 5 timed frames (3 from depth 7; fast pictures more, up to 25, until 60 ms are timed),
// pictures kept at depths 1, 3, 5. Quick: depths 0..4,
// mesa and soft, 256x256, one timed frame, pictures at depths 1 and 3.
ReportOptions default_options(bool quick);

struct Files {
  std::string csv, svg, svg_triangles, html, images;
};

struct Report {
  ReportOptions options;
  SweepResult sweep;
  std::vector<Headline> headlines;
  std::vector<SceneCheck> checks;
  std::string scenes_dir;  // where the shipped scenes were read from ("" if none were found)
  Files files;
  double regression_seconds = 0, seconds = 0;
};

// Runs everything and writes the files. Throws std::runtime_error when a file cannot be written.
Report run(const ReportOptions& o, const Progress& progress = nullptr);

// The CSV: a header line, then one line per row.
const std::vector<std::string>& csv_columns();
std::string to_csv(const std::vector<Row>& rows);

// The page (image paths relative to the output folder, as run() writes them).
std::string html_page(const Report& r);

// The text summary printed at the end: the headline numbers, a few rows, where the files are.
std::string summary_text(const Report& r);

// "330k", "1.3M", "1280": a triangle count for people.
std::string short_count(double n);

}  // namespace ffc::report
