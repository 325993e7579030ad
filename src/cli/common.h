// What the ffcompat subcommands share: the scene options and JSON printing.
#pragma once
#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>
#include <string>

#include "image/compare.h"
#include "scene/scene.h"

namespace ffc::cli {

// --scene, --shade, --normals, --depth, --size, --cam-angle, --cam-height, --backend. Options left
// out keep the built-in scene's defaults.
struct SceneOptions {
  std::string scene = "cube", shade, normals, size, backend = "mesa";
  int depth = -1;
  double cam_angle = 0, cam_height = 1;
  void add_to(CLI::App* app, bool with_shade_and_normals = true);
  scene::Spec spec() const;  // throws std::invalid_argument for a bad value
};

nlohmann::json to_json(const scene::Spec& s);
nlohmann::json to_json(const image::Diff& d);
void print_json(const nlohmann::json& j);

void add_render(CLI::App& app);
void add_normals(CLI::App& app);
void add_compare(CLI::App& app);
void add_shading(CLI::App& app);

}  // namespace ffc::cli
