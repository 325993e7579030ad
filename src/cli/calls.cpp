// ffcompat calls: each gl* function that libGL.so.1 exports (every GLAPI prototype of <GL/gl.h>)
// and whether the soft backend implements it. A call soft does not implement records
// GL_INVALID_OPERATION at run time and names itself once on stderr (src/classic/gl/table.cpp).
#include <cstdio>
#include <iostream>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "backends/backend.h"
#include "cli/common.h"
#include "state/soft_gl.h"

namespace ffc::cli {

namespace {

struct Call {
  const char* name;
  std::string version, section;  // as gl.h files it
  bool implemented;
};

std::vector<Call> calls() {
  std::vector<Call> out;
  // The group string is "version; section".
  auto add = [&](const char* name, const std::string& group) {
    const size_t semi = group.find("; ");
    out.push_back({name, group.substr(0, semi), group.substr(semi + 2), state::proc_address(name) != nullptr});
  };
#define FFC_CLASSIC_GL(R, N, P, A, G) add(#N, G);
#include "classic/gl/gl_exports.inc"
#undef FFC_CLASSIC_GL
  return out;
}

// The part of docs/classic.md that lists the calls: per section of gl.h, what soft implements and
// what it does not.
void print_markdown(const std::vector<Call>& list, const std::string& backend, size_t implemented) {
  std::printf("%zu of the %zu functions of `<GL/gl.h>` are implemented by %s (`ffcompat calls --markdown`).\n\n",
              implemented, list.size(), backend.c_str());
  std::printf("| gl.h section | version | implemented | not implemented |\n|---|---|---|---|\n");
  std::vector<std::string> order;
  std::map<std::string, std::pair<std::string, std::string>> cells;  // section -> (yes, no)
  for (const Call& c : list) {
    const std::string key = c.section + "|" + c.version;
    if (!cells.count(key)) order.push_back(key);
    std::string& cell = c.implemented ? cells[key].first : cells[key].second;
    cell += (cell.empty() ? "" : " ") + std::string(c.name);
  }
  for (const std::string& key : order) {
    const size_t bar = key.find('|');
    const std::string section = key.substr(0, bar), version = key.substr(bar + 1);
    std::printf("| %s | %s | %s | %s |\n", section.c_str(), version == section ? "extension" : version.c_str(),
                cells[key].first.empty() ? "-" : cells[key].first.c_str(),
                cells[key].second.empty() ? "-" : cells[key].second.c_str());
  }
}

}  // namespace

void add_calls(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "calls", "List each gl* function of libGL.so.1 (every one of <GL/gl.h>) and whether soft implements it");
  auto backend = std::make_shared<std::string>("soft");
  auto json = std::make_shared<bool>(false);
  auto markdown = std::make_shared<bool>(false);
  auto missing = std::make_shared<bool>(false);
  cmd->add_option("--backend", *backend, "A soft backend (soft, soft-double, soft-spec, soft-double-spec)")
      ->capture_default_str();
  cmd->add_flag("--json", *json, "Print {backend, total, implemented, calls: [{name, implemented, version, section}]}");
  cmd->add_flag("--markdown", *markdown, "Print the table of docs/classic.md");
  cmd->add_flag("--missing", *missing, "List only the functions the backend does not implement");
  cmd->callback([=] {
    bool known = false;
    for (const std::string& n : backends::names()) known |= n == *backend && n != "mesa";
    if (*backend == "mesa")
      throw std::invalid_argument(
          "calls lists what the soft backends implement; mesa (OSMesa) is Mesa's whole GL and answers every "
          "function of gl.h");
    if (!known) throw std::invalid_argument("unknown backend '" + *backend + "' (soft, soft-double, soft-spec or soft-double-spec)");
    // Every soft variant is the same state tracker: one table (state::proc_address) for all.
    const std::vector<Call> list = calls();
    size_t implemented = 0;
    for (const Call& c : list) implemented += c.implemented;
    if (*markdown) return print_markdown(list, *backend, implemented);
    if (*json) {
      nlohmann::json rows = nlohmann::json::array();
      for (const Call& c : list)
        if (!*missing || !c.implemented)
          rows.push_back({{"name", c.name}, {"implemented", c.implemented}, {"version", c.version}, {"section", c.section}});
      print_json({{"backend", *backend}, {"total", list.size()}, {"implemented", implemented}, {"calls", rows}});
      return;
    }
    for (const Call& c : list)
      if (!*missing || !c.implemented)  // an extension's section is its name: said once
        std::printf("%-32s %-3s  %s%s%s\n", c.name, c.implemented ? "yes" : "no", c.version.c_str(),
                    c.section == c.version ? "" : ", ", c.section == c.version ? "" : c.section.c_str());
    std::printf("# %s implements %zu of the %zu functions of <GL/gl.h>; each other one records GL_INVALID_OPERATION "
                "and names itself once on stderr\n",
                backend->c_str(), implemented, list.size());
  });
}

}  // namespace ffc::cli
