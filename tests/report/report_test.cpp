// `ffcompat report --quick`: the CSV's columns and rows, a well-formed SVG, an HTML page whose
// pictures exist; through the library and through the command line.
#include "../temp_dir.h"
#include "report/report.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>

#include "report/plot.h"

namespace ffc::report {
namespace {

namespace fs = std::filesystem;

fs::path temp_dir(const std::string& name) {  // this run's own (tests/temp_dir.h)
  const fs::path p = test::temp_path(name);
  fs::create_directories(p);
  return p;
}

std::string slurp(const fs::path& p) {
  std::ifstream f(p, std::ios::binary);
  std::stringstream s;
  s << f.rdbuf();
  return s.str();
}

std::vector<std::string> split(const std::string& line, char sep = ',') {
  std::vector<std::string> out;
  std::stringstream in(line);
  for (std::string item; std::getline(in, item, sep);) out.push_back(item);
  return out;
}

// Well-formed XML, enough for our SVG: every tag closed in order, one root element, attribute
// values quoted, text free of bare '<' and '&' other than entities. Returns the root's name.
std::string check_xml(const std::string& x, int* elements) {
  std::vector<std::string> stack;
  size_t i = 0;
  std::string root;
  *elements = 0;
  while (i < x.size()) {
    if (x[i] != '<') {
      if (x[i] == '&') {
        const size_t semi = x.find(';', i);
        EXPECT_NE(semi, std::string::npos);
        const std::string ent = x.substr(i, semi - i + 1);
        EXPECT_TRUE(ent == "&amp;" || ent == "&lt;" || ent == "&gt;" || ent == "&quot;") << ent;
      }
      ++i;
      continue;
    }
    const size_t end = x.find('>', i);
    if (end == std::string::npos) {
      ADD_FAILURE() << "unterminated tag at " << i;
      return "";
    }
    const std::string tag = x.substr(i + 1, end - i - 1);
    i = end + 1;
    if (tag.rfind("?xml", 0) == 0) continue;
    if (tag[0] == '/') {
      const std::string name = tag.substr(1);
      if (stack.empty() || stack.back() != name) {
        ADD_FAILURE() << "</" << name << "> closes " << (stack.empty() ? "nothing" : stack.back());
        return "";
      }
      stack.pop_back();
      continue;
    }
    const std::string name = tag.substr(0, tag.find_first_of(" \n/"));
    if (stack.empty()) {
      if (!root.empty()) ADD_FAILURE() << "second root element " << name;
      root = name;
    }
    ++*elements;
    size_t quotes = 0;
    for (char c : tag) quotes += c == '"';
    EXPECT_EQ(quotes % 2, 0u) << tag;
    if (tag.back() != '/') stack.push_back(name);
  }
  EXPECT_TRUE(stack.empty()) << "unclosed <" << (stack.empty() ? "" : stack.back()) << ">";
  return root;
}

void expect_report_files(const fs::path& out, size_t rows_expected) {
  // CSV: the columns, then one row per depth, shading, scene and backend.
  std::ifstream csv(out / "results.csv");
  ASSERT_TRUE(csv) << "no results.csv";
  std::string header;
  std::getline(csv, header);
  const auto cols = split(header);
  for (const char* want : {"depth", "shading", "scene", "backend", "triangles", "rmse", "max_error", "ms_per_frame",
                           "silhouette_pixels", "normals_ms"})
    EXPECT_NE(std::find(cols.begin(), cols.end(), want), cols.end()) << want;
  size_t n = 0;
  std::set<std::string> shadings, scenes, backends;
  std::set<int> depths;
  const auto col = [&](const char* name) { return size_t(std::find(cols.begin(), cols.end(), name) - cols.begin()); };
  for (std::string line; std::getline(csv, line);) {
    if (line.empty()) continue;
    const auto f = split(line);
    ASSERT_EQ(f.size(), cols.size()) << line;
    shadings.insert(f[col("shading")]), scenes.insert(f[col("scene")]), backends.insert(f[col("backend")]);
    depths.insert(std::stoi(f[col("depth")]));
    EXPECT_GE(std::stod(f[col("rmse")]), 0);
    EXPECT_GT(std::stod(f[col("ms_per_frame")]), 0);
    EXPECT_EQ(std::stoul(f[col("triangles")]), 20ul << (2 * std::stoi(f[col("depth")])));
    ++n;
  }
  EXPECT_EQ(n, rows_expected);
  EXPECT_EQ(depths, (std::set<int>{0, 1, 2, 3, 4}));
  EXPECT_EQ(scenes, (std::set<std::string>{"seed", "specular"}));
  EXPECT_EQ(backends, (std::set<std::string>{"mesa", "soft"}));
  EXPECT_EQ(shadings.size(), 6u);

  // The SVG: well formed, an <svg> root, one polyline per curve (lighting x shading x backend).
  int elements = 0;
  const std::string svg = slurp(out / "error_vs_time.svg");
  EXPECT_EQ(check_xml(svg, &elements), "svg");
  EXPECT_GT(elements, 100);
  size_t polylines = 0;
  for (size_t p = svg.find("<polyline"); p != std::string::npos; p = svg.find("<polyline", p + 1)) ++polylines;
  EXPECT_EQ(polylines, 2u * 6 * 2);
  EXPECT_NE(svg.find("milliseconds per frame"), std::string::npos);
  EXPECT_NE(svg.find("RMSE"), std::string::npos);
  EXPECT_EQ(check_xml(slurp(out / "error_vs_triangles.svg"), &elements), "svg");

  // The page: every picture and chart it shows exists.
  const std::string html = slurp(out / "index.html");
  ASSERT_FALSE(html.empty());
  const std::regex src("(src|href)=\"([^\"#:]+\\.(png|svg|csv))\"");
  size_t pngs = 0;
  for (auto it = std::sregex_iterator(html.begin(), html.end(), src); it != std::sregex_iterator(); ++it) {
    const std::string path = (*it)[2];
    EXPECT_TRUE(fs::exists(out / path)) << path;
    pngs += (*it)[3] == "png";
  }
  EXPECT_GE(pngs, 2u * 2 * 5);  // two depths per lighting setup: ideal, flat, error, smooth, error
  EXPECT_NE(html.find("error_vs_time.svg"), std::string::npos);
  EXPECT_NE(html.find("Regression against Mesa"), std::string::npos);
}

TEST(Report, QuickRunWritesTheFiles) {
  const fs::path out = temp_dir("library");
  ReportOptions o = default_options(true);
  o.out = out.string();
  size_t calls = 0, last_total = 0;
  const Report r = run(o, [&](size_t, size_t total, const std::string&) { ++calls, last_total = total; });
  EXPECT_EQ(r.sweep.rows.size(), 5u * 2 * 6 * 2);
  EXPECT_GT(calls, r.sweep.rows.size());
  expect_report_files(out, 5 * 2 * 6 * 2);
  ASSERT_EQ(r.headlines.size(), 2u);
  // Built-in scenes first, then the shipped scene files (if found).
  ASSERT_GE(r.checks.size(), 2u);
  EXPECT_EQ(r.checks[0].name, "cube");
  EXPECT_TRUE(r.checks[0].pass());
  EXPECT_TRUE(r.checks[1].pass());
  // The page names no folder of the machine that made it: neither where the scenes were read
  // (found from the executable's path: absolute) nor where the report was written.
  const std::string html = slurp(out / "index.html");
  ASSERT_FALSE(r.scenes_dir.empty());
  EXPECT_EQ(html.find(r.scenes_dir + "/"), std::string::npos) << r.scenes_dir;
  EXPECT_EQ(html.find(out.string()), std::string::npos);
  EXPECT_NE(html.find("scenes/*.toml"), std::string::npos);
  EXPECT_NE(html.find("<td class=\"l\">scenes/cube.toml</td>"), std::string::npos);
  const std::string text = summary_text(r);
  EXPECT_NE(text.find("headline"), std::string::npos);
  EXPECT_NE(text.find("index.html"), std::string::npos);
}

TEST(Report, CsvRoundsTrip) {
  Row r;
  r.depth = 3, r.triangles = 1280, r.vertices = 642, r.shading = "smooth-area", r.shade_model = "smooth";
  r.normals = "area", r.scene = "seed", r.backend = "soft", r.rmse = 1.25, r.max_error = 7, r.ms_per_frame = 0.5;
  const auto lines = split(to_csv({r}), '\n');
  ASSERT_EQ(lines.size(), 2u);
  EXPECT_EQ(split(lines[0]).size(), csv_columns().size());
  EXPECT_EQ(split(lines[1]).size(), csv_columns().size());
  EXPECT_EQ(split(lines[1])[0], "3");
  EXPECT_EQ(split(lines[1])[3], "smooth-area");
}

TEST(Report, ChartEscapesAndSkipsNonPositivePoints) {
  Panel p;
  p.title = "a < b & c";
  Series s;
  s.label = "x";
  s.points = {{1, 1}, {10, 0}, {100, 0.1}};
  p.series.push_back(s);
  ChartOptions o;
  o.title = "t";
  const std::string svg = log_log_chart({p}, o);
  int elements = 0;
  EXPECT_EQ(check_xml(svg, &elements), "svg");
  EXPECT_NE(svg.find("a &lt; b &amp; c"), std::string::npos);
}

// The command line itself, when the ffcompat executable sits in the build folder above this test.
TEST(ReportCli, QuickJsonSummary) {
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec).parent_path().parent_path() / "ffcompat";
  if (ec || !fs::exists(exe)) GTEST_SKIP() << "no ffcompat executable at " << exe;
  const fs::path out = temp_dir("cli");
  const std::string cmd = exe.string() + " report --quick --json --no-regression --out '" + out.string() + "' 2>/dev/null";
  FILE* p = popen(cmd.c_str(), "r");
  ASSERT_NE(p, nullptr);
  std::string json;
  char buf[4096];
  for (size_t n; (n = fread(buf, 1, sizeof buf, p)) > 0;) json.append(buf, n);
  ASSERT_EQ(pclose(p), 0) << json;
  EXPECT_NE(json.find("\"rows\": 120"), std::string::npos) << json;
  EXPECT_NE(json.find("\"headline\""), std::string::npos);
  EXPECT_NE(json.find("\"seed\""), std::string::npos);
  EXPECT_NE(json.find("\"specular\""), std::string::npos);
  EXPECT_NE(json.find("flat_triangles"), std::string::npos);
  EXPECT_NE(json.find("results.csv"), std::string::npos);
  expect_report_files(out, 120);
}

}  // namespace
}  // namespace ffc::report
