// ffcompat render: one built-in scene through one backend, to a PNG.
#include <iostream>
#include <memory>

#include "cli/common.h"

namespace ffc::cli {

void add_render(CLI::App& app) {
  auto* cmd = app.add_subcommand("render", "Render a built-in scene to a PNG");
  auto opts = std::make_shared<SceneOptions>();
  auto out = std::make_shared<std::string>();
  auto json = std::make_shared<bool>(false);
  opts->add_to(cmd);
  cmd->add_option("--out", *out, "PNG file to write")->required();
  cmd->add_flag("--json", *json, "Print the result as JSON");
  cmd->callback([=] {
    const scene::Spec spec = opts->spec();
    auto backend = backends::make(opts->backend);
    image::write_png(*out, scene::render(spec, *backend));
    nlohmann::json j = to_json(spec);
    j["backend"] = backend->name();
    j["out"] = *out;
    if (*json)
      print_json(j);
    else
      std::cout << "wrote " << *out << " (" << spec.name << ", " << spec.width << "x" << spec.height
                << ", GL_" << (spec.shade == scene::Shade::Flat ? "FLAT" : "SMOOTH") << ", "
                << mesh::to_string(spec.normals) << " normals, " << backend->name() << ")\n";
  });
}

}  // namespace ffc::cli
