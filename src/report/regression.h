// The regression section of the report: every shipped scene (scenes/*.toml) and the built-in
// scenes, our pipeline against Mesa vertex by vertex (check::compare_vertices) and pixel by pixel
// (image::compare of the Mesa and soft pictures), with the thresholds of tests/check.
#pragma once
#include <string>
#include <vector>

#include "image/image.h"
#include "scene/description.h"

namespace ffc::report {

struct SceneCheck {
  std::string name, source;  // source: "built-in" or the scene file
  std::string error;         // set when the scene could not be read or drawn; nothing else is
  int width = 0, height = 0;
  size_t vertices = 0;
  double vertex_max_abs = 0, vertex_rms = 0, vertex_max_abs_double = 0, max_position = 0;
  std::vector<std::string> known_mesa_deviations;
  bool vertex_pass = false;
  int pixel_max_diff = 0;
  double pixel_differing_share = 0, pixel_rmse = 0;
  bool pixel_pass = false;
  image::Image mesa, soft;  // the pictures
  bool pass() const { return error.empty() && vertex_pass && pixel_pass; }
};

struct RegressionOptions {
  double vertex_tolerance = 1e-5;  // largest colour difference per channel
  int pixel_max_diff = 1;          // 8-bit steps
};

// The built-in scenes as scene::describe gives them, then the scene files of `scenes_dir` in name
// order (none if the folder is empty or missing). A file that does not load becomes a check with
// its error set.
std::vector<SceneCheck> check_scenes(const std::string& scenes_dir, const RegressionOptions& o = {});

SceneCheck check_scene(const scene::Description& d, const std::string& source, const RegressionOptions& o = {});

// Where the shipped scenes are: `given` if not empty; else ./scenes, else a scenes/ folder beside
// the running executable or above it (the source tree of a build folder). Empty if none is found.
std::string find_scenes_dir(const std::string& given = "");

}  // namespace ffc::report
