// ffcompat normals: the normals a scene is drawn with, per vertex (per corner for face normals).
#include <cstdio>
#include <memory>

#include "cli/common.h"

namespace ffc::cli {

void add_normals(CLI::App& app) {
  auto* cmd = app.add_subcommand("normals", "Print the per-vertex (or per-corner) normals table");
  auto opts = std::make_shared<SceneOptions>();
  auto json = std::make_shared<bool>(false);
  cmd->add_option("--scene", opts->scene, "Scene: cube, icosphere, or a TOML scene file (*.toml)")->capture_default_str();
  add_depth_option(cmd, opts->depth, "Icosphere subdivision depth (default 3)");
  cmd->add_option("--normals", opts->normals, "face, average, area, angle, max, sphere or file (default: the scene's)");
  cmd->add_flag("--json", *json, "Print an array of {vertex, position, normal} rows");
  cmd->callback([=] {
    const scene::Description desc = opts->description();
    const bool several = desc.objects.size() > 1;  // then each row says which mesh
    nlohmann::json rows = nlohmann::json::array();
    if (!*json) std::printf("%-6s  %-28s  %s\n", "vertex", "position", "normal");
    for (size_t i = 0; i < desc.objects.size(); ++i) {
      const mesh::Layout l = scene::layout(desc.objects[i]);
      if (several && !*json) std::printf("# mesh %zu: %s\n", i, scene::to_string(desc.objects[i]).c_str());
      for (const auto& v : l.vertices) {
        if (*json) {
          rows.push_back({{"vertex", v.source}, {"position", v.position}, {"normal", v.normal}});
          if (several) rows.back()["mesh"] = i;
          continue;
        }
        char pos[96];
        std::snprintf(pos, sizeof pos, "(%.6g, %.6g, %.6g)", v.position[0], v.position[1], v.position[2]);
        std::printf("%-6d  %-28s  (%.16g, %.16g, %.16g)\n", v.source, pos, v.normal[0] + 0.0, v.normal[1] + 0.0, v.normal[2] + 0.0);  // no "-0"
      }
    }
    if (*json) print_json(rows);
  });
}

}  // namespace ffc::cli
