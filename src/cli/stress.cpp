// ffcompat stress: the catalogue of stiff and extreme cases (src/stress), each drawn on Mesa, our
// float path and our double reference, with a verdict and a note per case.
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "cli/common.h"
#include "stress/stress.h"

namespace ffc::cli {

namespace {

nlohmann::json to_json(const stress::Result& r, bool details) {
  nlohmann::json j = {{"name", r.name},
                      {"crashed", r.crashed},
                      {"nan_pixels", r.nan_pixels},
                      {"nan_vertices", r.nan_vertices},
                      {"max_abs_vs_double", r.max_abs_vs_double},
                      {"mesa_agrees", r.mesa_agrees},
                      {"verdict", r.verdict},
                      {"note", r.note}};
  if (details)
    j["details"] = {{"group", r.group},
                    {"mesa_ran", r.mesa_ran},
                    {"mesa_crashed", r.mesa_crashed},
                    {"mesa_difference", r.mesa_difference},
                    {"mesa_nan_vertices", r.mesa_nan_vertices},
                    {"max_colour_vs_mesa", r.max_colour_vs_mesa},
                    {"max_position_px", r.max_position_px},
                    {"max_position_vs_double_px", r.max_position_vs_double_px},
                    {"max_pixel_steps", r.max_pixel_steps},
                    {"differing_pixels", r.differing_pixels},
                    {"primitives", {{"mesa", r.primitives[0]}, {"soft", r.primitives[1]}, {"soft_double", r.primitives[2]}}},
                    {"gl_errors", {{"mesa", r.gl_errors[0]}, {"soft", r.gl_errors[1]}, {"soft_double", r.gl_errors[2]}}},
                    {"check_failure", r.check_failure},
                    {"seconds", r.seconds}};
  return j;
}

// Words wrapped to `width` columns after an indent.
void print_wrapped(const std::string& text, size_t indent, size_t width) {
  size_t col = indent;
  std::printf("%*s", int(indent), "");
  size_t i = 0;
  while (i < text.size()) {
    size_t j = text.find(' ', i);
    if (j == std::string::npos) j = text.size();
    const std::string word = text.substr(i, j - i);
    if (col > indent && col + 1 + word.size() > width) {
      std::printf("\n%*s", int(indent), "");
      col = indent;
    } else if (col > indent) {
      std::printf(" ");
      ++col;
    }
    std::printf("%s", word.c_str());
    col += word.size();
    i = j + 1;
  }
  std::printf("\n");
}

// One line after the table: how many cases, how long, each verdict's count, and the worst of
// what the table's columns measure, so a person need not read seventy rows to know the outcome.
std::string summary(const std::vector<stress::Result>& results) {
  size_t ok = 0, deviation = 0, fail = 0, crashed = 0;
  uint64_t nan_pixels = 0, nan_vertices = 0;
  double seconds = 0, worst = 0;
  std::string worst_case;
  for (const auto& r : results) {
    if (r.verdict.rfind("FAIL", 0) == 0)
      ++fail;
    else if (r.verdict.rfind("mesa-deviation", 0) == 0)
      ++deviation;
    else
      ++ok;
    crashed += r.crashed;
    nan_pixels += r.nan_pixels, nan_vertices += r.nan_vertices;
    seconds += r.seconds;
    if (r.max_abs_vs_double > worst) worst = r.max_abs_vs_double, worst_case = r.name;
  }
  char b[512];
  std::snprintf(b, sizeof b,
                "stress: %zu cases in %.1f s: %zu ok, %zu mesa-deviation, %zu FAIL; %zu crashed, %llu NaN pixels, "
                "%llu NaN vertices; float vs double worst %.3g%s%s%s",
                results.size(), seconds, ok, deviation, fail, crashed, (unsigned long long)nan_pixels,
                (unsigned long long)nan_vertices, worst, worst_case.empty() ? "" : " (", worst_case.c_str(),
                worst_case.empty() ? "" : ")");
  return b;
}

}  // namespace

void add_stress(CLI::App& app) {
  auto* cmd = app.add_subcommand("stress", "Numerical stability on stiff and extreme inputs: ours against Mesa and our double reference");
  auto names = std::make_shared<std::vector<std::string>>();
  auto list = std::make_shared<bool>(false);
  auto json = std::make_shared<bool>(false);
  auto details = std::make_shared<bool>(false);
  auto notes = std::make_shared<bool>(false);
  auto slow = std::make_shared<bool>(false);
  auto no_mesa = std::make_shared<bool>(false);
  auto in_process = std::make_shared<bool>(false);
  auto out = std::make_shared<std::string>();
  cmd->add_option("--case", *names, "Run only these cases (repeatable); default: every case but the slow ones");
  cmd->add_flag("--list", *list, "List the cases (name, group, slow) and their notes, and run nothing");
  cmd->add_flag("--json", *json, "Print an array of {name, crashed, nan_pixels, nan_vertices, max_abs_vs_double, mesa_agrees, verdict, note}");
  cmd->add_flag("--details", *details, "JSON: add each case's details (Mesa's difference, pixel steps, primitive counts, timings)");
  cmd->add_flag("--notes", *notes, "Text: print each case's note under the table");
  cmd->add_flag("--slow", *slow, "Also run the cases marked slow");
  cmd->add_flag("--no-mesa", *no_mesa, "Run only our two backends");
  cmd->add_flag("--in-process", *in_process, "Do not fork a child per backend run (a crash then ends the command)");
  cmd->add_option("--out", *out, "Write each case's pictures (mesa.png, soft.png, soft-double.png) under DIR/<case>/");
  cmd->callback([=] {
    std::vector<const stress::Case*> cases;
    if (names->empty()) {
      for (const auto& c : stress::catalogue())
        if (*slow || !c.slow || *list) cases.push_back(&c);
    } else {
      for (const auto& n : *names) {
        const stress::Case* c = stress::find(n);
        if (!c) throw std::invalid_argument("unknown stress case '" + n + "' (see ffcompat stress --list)");
        cases.push_back(c);
      }
    }
    if (*list) {
      if (*json) {
        nlohmann::json j = nlohmann::json::array();
        for (const auto* c : cases)
          j.push_back({{"name", c->name}, {"group", c->group}, {"slow", c->slow}, {"note", c->note}});
        print_json(j);
      } else {
        for (const auto* c : cases) {
          std::printf("%-34s %-12s%s\n", c->name.c_str(), c->group.c_str(), c->slow ? " slow" : "");
          if (*notes) print_wrapped(c->note, 4, 100);
        }
      }
      return;
    }
    stress::Options o;
    o.mesa = !*no_mesa;
    o.isolate = !*in_process;
    nlohmann::json j = nlohmann::json::array();
    std::vector<stress::Result> results;
    bool failed = false;
    if (!*json)
      std::printf("%-34s %5s %8s %8s %10s %5s %6s  %s\n", "case", "crash", "nan_px", "nan_vtx", "f_vs_d", "mesa",
                  "time_s", "verdict");
    for (const auto* c : cases) {
      stress::Result r = stress::run(*c, o, !out->empty());
      failed |= r.verdict.rfind("FAIL", 0) == 0;
      if (!out->empty()) {
        const std::string dir = *out + "/" + r.name;
        std::filesystem::create_directories(dir);
        const std::pair<const char*, const stress::Run*> runs[] = {
            {"mesa", &r.observed.mesa}, {"soft", &r.observed.soft}, {"soft-double", &r.observed.dbl}};
        for (const auto& [name, run] : runs)
          if (run->ran && !run->crashed && run->image.width > 0)
            image::write_png(dir + "/" + name + ".png", run->image);
        r.observed = {};
      }
      if (*json) {
        j.push_back(to_json(r, *details));
      } else {
        std::printf("%-34s %5s %8llu %8llu %10.3g %5s %6.2f  %s\n", r.name.c_str(), r.crashed ? "yes" : "no",
                    (unsigned long long)r.nan_pixels, (unsigned long long)r.nan_vertices, r.max_abs_vs_double,
                    !r.mesa_ran ? "-" : r.mesa_agrees ? "yes" : "no", r.seconds, r.verdict.c_str());
        std::fflush(stdout);
      }
      results.push_back(std::move(r));
    }
    if (*json) {
      print_json(j);
    } else {
      std::printf("%s\n", summary(results).c_str());
    }
    if (!*json && *notes) {
      std::printf("\n");
      for (const auto& r : results) {
        std::printf("%s\n", r.name.c_str());
        print_wrapped(r.note, 4, 100);
        if (!r.mesa_difference.empty()) print_wrapped("Mesa: " + r.mesa_difference, 4, 100);
      }
    }
    if (failed) throw CLI::RuntimeError(2);
  });
}

}  // namespace ffc::cli
