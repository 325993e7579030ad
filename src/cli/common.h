// What the ffcompat subcommands share: the scene options and JSON printing.
#pragma once
#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "image/compare.h"
#include "scene/file.h"
#include "scene/scene.h"

namespace ffc::cli {

// --scene, --shade, --normals, --depth, --size, --cam-angle, --cam-height, --backend.
// --scene is a built-in scene (cube, icosphere) or a TOML scene file (a path ending in .toml).
// Options left out keep the built-in scene's defaults or the file's values; given, they override:
// --shade the shade model, --normals every mesh's normals, --depth every icosphere's depth, --size
// the framebuffer. --cam-angle and --cam-height move the built-in cube's camera only.
struct SceneOptions {
  std::string scene = "cube", shade, normals, size, backend = "mesa", draw;
  int depth = -1;
  double cam_angle = 0, cam_height = 1;
  const CLI::Option* cam_angle_option = nullptr;   // set by add_to: whether the camera was moved
  const CLI::Option* cam_height_option = nullptr;
  // with_backend: --backend picks the renderer (render, shading); a command that always uses its
  // own renderers (check, bench) leaves it out and refuses it with refuse_option.
  void add_to(CLI::App* app, bool with_shade_and_normals = true, bool with_backend = true);
  bool is_file() const { return scene::is_scene_file(scene); }
  // A built-in scene with the options applied. Throws std::invalid_argument for a bad value or a
  // scene file (use description()).
  scene::Spec spec() const;
  // The scene to draw, built in or read from its file, with the options applied. Throws
  // std::invalid_argument for a bad value, scene::FileError for a bad scene file.
  scene::Description description() const;
  // to_json(d), plus the built-in cube's camera options.
  nlohmann::json json(const scene::Description& d) const;
};

// "face", "average", ... when every mesh has the same normal source, otherwise "mixed".
std::string normals_of(const scene::Description& d);

nlohmann::json to_json(const scene::Spec& s);
// {scene, shade, normals, width, height}, depth when a mesh is an icosphere, file when read from one.
nlohmann::json to_json(const scene::Description& d);
nlohmann::json to_json(const image::Diff& d);
void print_json(const nlohmann::json& j);
// C++ heap allocations made so far by this process (alloc_count.cpp).
uint64_t allocations();

// Adds the --depth option (0..mesh::kMaxIcosphereDepth; beyond, the error says why).
void add_depth_option(CLI::App* app, int& depth, const std::string& help);

// An option the command does not take although a user may reach for it (another command's, or a
// near miss): accepted by the parser only to be refused with `why`, which names what applies.
// Hidden from --help.
void refuse_option(CLI::App* app, const std::string& name, const std::string& why);

// --platform osmesa|egl, the Mesa backend's platform (src/platform/platform_choice.h), on every
// command that takes --backend or --backends and on those that always draw on Mesa (fuzz,
// stress). It sets FFCOMPAT_PLATFORM, so a program `ffcompat run` starts takes it too. A platform
// this build lacks is refused as the option is parsed.
void add_platform_options(CLI::App& app);
// The platform a "mesa" backend takes now ("osmesa" or "egl"); null in a build without Mesa.
nlohmann::json mesa_platform_json();
// Adds "platform" to a command's JSON when `backend` is Mesa.
void add_platform(nlohmann::json& j, const std::string& backend);

// The backends by name, for --backend's choices and help.
extern const std::vector<std::string> kBackendNames;

void add_render(CLI::App& app);
void add_normals(CLI::App& app);
void add_compare(CLI::App& app);
void add_shading(CLI::App& app);

}  // namespace ffc::cli
