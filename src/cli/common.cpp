#include "cli/common.h"

#include <cmath>
#include <iostream>
#include <memory>
#include <stdexcept>

#include "backends/backend.h"
#include "mesh/icosphere.h"
#include "platform/platform_choice.h"
#ifdef FFCOMPAT_WITH_MESA
#include "backends/mesa/mesa_backend.h"
#endif

namespace ffc::cli {

const std::vector<std::string> kBackendNames = {"mesa", "soft", "soft-double", "soft-spec", "soft-double-spec"};

void add_depth_option(CLI::App* app, int& depth, const std::string& help) {
  app->add_option("--depth", depth, help)->check(CLI::Validator(
      [](std::string& v) {
        int d = 0;
        try {
          size_t used = 0;
          d = std::stoi(v, &used);
          if (used != v.size()) return "'" + v + "' is not a whole number";
        } catch (const std::exception&) {
          return "'" + v + "' is not a whole number";
        }
        return mesh::icosphere_depth_error(d);
      },
      "0.." + std::to_string(mesh::kMaxIcosphereDepth)));
}

namespace {

// Whether each platform is built (for a build without Mesa: neither).
bool platform_built(const char* name) {
#ifdef FFCOMPAT_WITH_MESA
  for (const std::string& p : backends::mesa_platforms())
    if (p == name) return true;
#endif
  (void)name;
  return false;
}

}  // namespace

void add_platform_options(CLI::App& app) {
  for (CLI::App* cmd : app.get_subcommands([](CLI::App*) { return true; })) {
    const std::string& n = cmd->get_name();
    if (!cmd->get_option_no_throw("--backend") && !cmd->get_option_no_throw("--backends") && n != "fuzz" &&
        n != "stress")
      continue;
    cmd->add_option_function<std::string>(
           "--platform", [](const std::string& v) { setenv(platform::kPlatformVariable, v.c_str(), 1); },
           "Mesa's platform: osmesa or egl (default: osmesa where built, else egl; or FFCOMPAT_PLATFORM)")
        ->check(CLI::Validator(
            [](std::string& v) -> std::string {
              try {
                platform::choose_mesa_platform(platform_built("osmesa"), platform_built("egl"), v.c_str());
              } catch (const std::invalid_argument& e) {
                return e.what();
              }
              return "";
            },
            "osmesa|egl"));
  }
}

nlohmann::json mesa_platform_json() {
#ifdef FFCOMPAT_WITH_MESA
  return backends::mesa_platform();
#else
  return nullptr;
#endif
}

void add_platform(nlohmann::json& j, const std::string& backend) {
  if (backend == "mesa") j["platform"] = mesa_platform_json();
}

void refuse_option(CLI::App* app, const std::string& name, const std::string& why) {
  auto never_read = std::make_shared<std::string>();  // the check below refuses every value
  app->add_option(name, *never_read)
      ->check(CLI::Validator([why, never_read](std::string&) { return why; }, ""))
      ->group("");
}

void SceneOptions::add_to(CLI::App* app, bool with_shade_and_normals, bool with_backend) {
  app->add_option("--scene", scene, "Scene: cube, icosphere, or a TOML scene file (*.toml)")->capture_default_str();
  if (with_shade_and_normals) {
    app->add_option("--shade", shade, "glShadeModel: flat or smooth (default: smooth, or the file's)");
    app->add_option("--normals", normals,
                    "Normals: face, average (OpenMesh's), area, angle, max (Max 1999) or sphere, or file for a "
                    "mesh file's own "
                    "(default: cube face, icosphere sphere, or the file's)");
  }
  add_depth_option(app, depth,
                   "Icosphere subdivision depth, 0.." + std::to_string(mesh::kMaxIcosphereDepth) + " (default 3, or the file's)");
  app->add_option("--size", size, "Framebuffer WxH (default: cube 640x640, icosphere 512x512, or the file's)");
  app->add_option("--draw", draw,
                  "How every mesh is sent: arrays (glDrawArrays), elements (glDrawElements), immediate "
                  "(glBegin/glVertex, as seed 004) or auto (default: arrays for face normals, elements otherwise)");
  cam_angle_option = app->add_option("--cam-angle", cam_angle, "Cube camera angle around y, degrees (built-in cube only)")->capture_default_str();
  cam_height_option = app->add_option("--cam-height", cam_height, "Cube camera height (built-in cube only)")->capture_default_str();
  if (with_backend)
    app->add_option("--backend", backend,
                    "Renderer: mesa (Mesa's fixed-function pipeline, OSMesa or EGL: --platform), soft (ours, float), "
                    "soft-double (ours, double), glsl (our state drawn by generated GLSL on a core-profile context), "
                    "glsl-phong (the same, lit per fragment)")
        ->check(CLI::IsMember(backends::names()))
        ->capture_default_str();
}

static void parse_size(const std::string& size, int& width, int& height) {
  int w = 0, h = 0;
  char x = 0, extra = 0;
  if (std::sscanf(size.c_str(), "%d%c%d%c", &w, &x, &h, &extra) != 3 || (x != 'x' && x != 'X') || w < 1 ||
      h < 1 || w > 16384 || h > 16384)
    throw std::invalid_argument("--size '" + size + "' is not WxH with sides 1..16384");
  width = w;
  height = h;
}

scene::Spec SceneOptions::spec() const {
  if (is_file()) throw std::invalid_argument("--scene '" + scene + "' is a scene file, not a built-in scene");
  if (scene != "cube" && scene != "icosphere")
    throw std::invalid_argument("unknown scene '" + scene + "' (cube, icosphere, or a .toml scene file)");
  if (scene != "cube" && ((cam_angle_option && cam_angle_option->count()) || (cam_height_option && cam_height_option->count())))
    throw std::invalid_argument("--cam-angle and --cam-height move the built-in cube's camera; the built-in " + scene +
                                "'s camera is fixed (a scene file can place its own [camera])");
  scene::Spec s = scene::builtin(scene);
  if (!shade.empty()) s.shade = scene::parse_shade(shade);
  if (!normals.empty()) s.normals = mesh::parse_normal_source(normals);
  if (depth >= 0) s.depth = depth;
  if (!size.empty()) parse_size(size, s.width, s.height);
  if (!std::isfinite(cam_angle) || !std::isfinite(cam_height))
    throw std::invalid_argument("--cam-angle and --cam-height must be finite");
  s.cam_angle_deg = cam_angle;
  s.cam_height = cam_height;
  return s;
}

scene::Description SceneOptions::description() const {
  const bool given = !draw.empty();
  const scene::DrawPath path = given ? scene::parse_draw_path(draw) : scene::DrawPath{};  // throws for a bad name
  auto with_path = [&](scene::Description d) {
    if (given)
      for (scene::Object& o : d.objects) o.draw = path;
    return d;
  };
  if (!is_file()) return with_path(scene::describe(spec()));
  if ((cam_angle_option && cam_angle_option->count()) || (cam_height_option && cam_height_option->count()))
    throw std::invalid_argument("--cam-angle and --cam-height move the built-in cube's camera; a scene file has its own [camera]");
  // Check the options before reading the file, so a bad option is reported as such.
  std::optional<scene::Shade> shade_override;
  int width = 0, height = 0;
  if (!shade.empty()) shade_override = scene::parse_shade(shade);
  if (!normals.empty()) {
    scene::Object probe;
    scene::set_normals(probe, normals);  // throws for an unknown name
  }
  if (!size.empty()) parse_size(size, width, height);

  scene::Description d = scene::load_file(scene);
  if (shade_override) d.shade = *shade_override;
  for (size_t i = 0; i < d.objects.size(); ++i) {
    scene::Object& o = d.objects[i];
    if (!normals.empty()) {
      scene::set_normals(o, normals);
      if (o.file_normals && !(o.file && o.file->has_normals))
        throw std::invalid_argument("--normals file: mesh " + std::to_string(i) + " (" + scene::to_string(o) +
                                    ") has no normals of its own");
    }
    if (depth >= 0 && o.kind == scene::Object::Kind::Icosphere) o.depth = depth;
  }
  if (!size.empty()) d.width = width, d.height = height;
  return with_path(d);
}

nlohmann::json SceneOptions::json(const scene::Description& d) const {
  nlohmann::json j = to_json(d);
  if (!is_file() && scene == "cube") j["cam_angle"] = cam_angle, j["cam_height"] = cam_height;
  if (!draw.empty()) j["draw"] = draw;
  return j;
}

std::string normals_of(const scene::Description& d) {
  if (d.objects.empty()) return "none";
  for (const auto& o : d.objects)
    if (scene::normals_name(o) != scene::normals_name(d.objects.front())) return "mixed";
  return scene::normals_name(d.objects.front());
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

nlohmann::json to_json(const scene::Description& d) {
  nlohmann::json j = {{"scene", d.name},
                      {"shade", scene::to_string(d.shade)},
                      {"normals", normals_of(d)},
                      {"width", d.width},
                      {"height", d.height}};
  for (const auto& o : d.objects)
    if (o.kind == scene::Object::Kind::Icosphere) {
      j["depth"] = o.depth;
      break;
    }
  if (!d.source.empty()) j["file"] = d.source;
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
