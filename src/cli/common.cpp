#include "cli/common.h"

#include <cmath>
#include <iostream>
#include <stdexcept>

namespace ffc::cli {

void SceneOptions::add_to(CLI::App* app, bool with_shade_and_normals) {
  app->add_option("--scene", scene, "Built-in scene: cube or icosphere")->capture_default_str();
  if (with_shade_and_normals) {
    app->add_option("--shade", shade, "glShadeModel: flat or smooth (default: smooth)");
    app->add_option("--normals", normals,
                    "Normals: face, average (OpenMesh) or sphere (default: cube face, icosphere sphere)");
  }
  app->add_option("--depth", depth, "Icosphere subdivision depth, 0..12 (default 3)")->check(CLI::Range(0, 12));
  app->add_option("--size", size, "Framebuffer WxH (default: cube 640x640, icosphere 512x512)");
  app->add_option("--cam-angle", cam_angle, "Cube camera angle around y, degrees")->capture_default_str();
  app->add_option("--cam-height", cam_height, "Cube camera height")->capture_default_str();
  app->add_option("--backend", backend, "Renderer: mesa")->capture_default_str();
}

scene::Spec SceneOptions::spec() const {
  scene::Spec s = scene::builtin(scene);
  if (!shade.empty()) s.shade = scene::parse_shade(shade);
  if (!normals.empty()) s.normals = mesh::parse_normal_source(normals);
  if (depth >= 0) s.depth = depth;
  if (!size.empty()) {
    int w = 0, h = 0;
    char x = 0, extra = 0;
    if (std::sscanf(size.c_str(), "%d%c%d%c", &w, &x, &h, &extra) != 3 || (x != 'x' && x != 'X') ||
        w < 1 || h < 1 || w > 16384 || h > 16384)
      throw std::invalid_argument("--size '" + size + "' is not WxH with sides 1..16384");
    s.width = w;
    s.height = h;
  }
  if (!std::isfinite(cam_angle) || !std::isfinite(cam_height))
    throw std::invalid_argument("--cam-angle and --cam-height must be finite");
  s.cam_angle_deg = cam_angle;
  s.cam_height = cam_height;
  return s;
}

nlohmann::json to_json(const scene::Spec& s) {
  nlohmann::json j = {{"scene", s.name},
                      {"shade", scene::to_string(s.shade)},
                      {"normals", mesh::to_string(s.normals)},
                      {"width", s.width},
                      {"height", s.height}};
  if (s.name == "icosphere") j["depth"] = s.depth;
  if (s.name == "cube") j["cam_angle"] = s.cam_angle_deg, j["cam_height"] = s.cam_height;
  return j;
}

nlohmann::json to_json(const image::Diff& d) {
  // JSON has no infinity: identical pictures report psnr as null.
  return {{"max_diff", d.max_diff},
          {"mean_diff", d.mean_diff},
          {"differing_share", d.differing_share},
          {"rmse", d.rmse},
          {"psnr", std::isfinite(d.psnr) ? nlohmann::json(d.psnr) : nlohmann::json(nullptr)}};
}

void print_json(const nlohmann::json& j) { std::cout << j.dump(2) << "\n"; }

}  // namespace ffc::cli
