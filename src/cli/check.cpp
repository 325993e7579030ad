// ffcompat check: our pipeline against Mesa's. --level vertex compares lit colours vertex by
// vertex through feedback mode.
#include <cstdio>
#include <memory>

#include "check/vertex_check.h"
#include "cli/common.h"

namespace ffc::cli {

void add_check(CLI::App& app) {
  auto* cmd = app.add_subcommand("check", "Check our pipeline against Mesa's, vertex by vertex");
  auto opts = std::make_shared<SceneOptions>();
  auto level = std::make_shared<std::string>("vertex");
  auto tolerance = std::make_shared<double>(1e-5);
  auto json = std::make_shared<bool>(false);
  opts->add_to(cmd);
  cmd->add_option("--level", *level, "vertex")->check(CLI::IsMember({"vertex"}))->capture_default_str();
  cmd->add_option("--tolerance", *tolerance, "Largest colour difference that passes")->capture_default_str();
  cmd->add_flag("--json", *json, "Print the report as JSON");
  cmd->callback([=] {
    const scene::Spec spec = opts->spec();
    const check::VertexReport r = check::compare_vertices(spec.width, spec.height, [&] { scene::draw(spec); });
    const bool pass = r.max_abs <= *tolerance || !r.known_mesa_deviations.empty();
    if (*json) {
      nlohmann::json ch = nlohmann::json::array();
      for (const auto& c : r.channel) ch.push_back({{"max_abs", c.max_abs}, {"rms", c.rms}});
      nlohmann::json j = {{"level", "vertex"},
                          {"scene", to_json(spec)},
                          {"vertices", r.vertices},
                          {"max_abs", r.max_abs},
                          {"rms", r.rms},
                          {"max_abs_double", r.max_abs_double},
                          {"rms_double", r.rms_double},
                          {"max_abs_float_vs_double", r.max_abs_float_vs_double},
                          {"channels", ch},
                          {"max_position_px", r.max_position},
                          {"known_mesa_deviations", r.known_mesa_deviations},
                          {"tolerance", *tolerance},
                          {"pass", pass}};
      print_json(j);
    } else {
      std::printf("vertices %zu\n%-8s %12s %12s\n", r.vertices, "channel", "max_abs", "rms");
      const char* names[] = {"red", "green", "blue", "alpha"};
      for (int c = 0; c < 4; ++c) std::printf("%-8s %12.3g %12.3g\n", names[c], r.channel[c].max_abs, r.channel[c].rms);
      std::printf("float  vs Mesa: max %.3g, rms %.3g\ndouble vs Mesa: max %.3g, rms %.3g\n"
                  "window positions agree within %.3g px\n",
                  r.max_abs, r.rms, r.max_abs_double, r.rms_double, r.max_position);
      for (const auto& d : r.known_mesa_deviations) std::printf("known Mesa deviation: %s\n", d.c_str());
      std::printf("%s (tolerance %g)\n", pass ? "PASS" : "FAIL", *tolerance);
    }
    if (!pass) throw CLI::RuntimeError(2);
  });
}

}  // namespace ffc::cli
