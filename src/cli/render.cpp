// ffcompat render: one scene (built in or from a scene file) through one backend, to a PNG.
#include <iostream>
#include <memory>

#include "cli/common.h"

namespace ffc::cli {

void add_render(CLI::App& app) {
  auto* cmd = app.add_subcommand("render", "Render a scene (built in or a .toml file) to a PNG");
  auto opts = std::make_shared<SceneOptions>();
  auto out = std::make_shared<std::string>();
  auto json = std::make_shared<bool>(false);
  opts->add_to(cmd);
  cmd->add_option("--out", *out, "PNG file to write")->required();
  cmd->add_flag("--json", *json, "Print the result as JSON");
  cmd->callback([=] {
    const scene::Description desc = opts->description();
    auto backend = backends::make(opts->backend);
    image::write_png(*out, scene::render(desc, *backend));
    nlohmann::json j = opts->json(desc);
    j["backend"] = backend->name();
    add_platform(j, backend->name());
    j["out"] = *out;
    if (*json)
      print_json(j);
    else
      std::cout << "wrote " << *out << " (" << desc.name << ", " << desc.width << "x" << desc.height
                << ", GL_" << (desc.shade == scene::Shade::Flat ? "FLAT" : "SMOOTH") << ", "
                << normals_of(desc) << " normals, " << backend->name() << ")\n";
  });
}

}  // namespace ffc::cli
