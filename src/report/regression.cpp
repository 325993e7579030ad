#include "report/regression.h"

#include <algorithm>
#include <filesystem>
#include <system_error>

#include "backends/backend.h"
#include "check/vertex_check.h"
#include "image/compare.h"
#include "scene/file.h"
#include "scene/scene.h"

namespace ffc::report {

namespace fs = std::filesystem;

SceneCheck check_scene(const scene::Description& d, const std::string& source, const RegressionOptions& o) {
  SceneCheck c;
  c.name = d.name;
  c.source = source;
  c.width = d.width, c.height = d.height;
  try {
    const check::VertexReport r = check::compare_vertices(d.width, d.height, [&] { scene::draw(d); });
    c.vertices = r.vertices;
    c.vertex_max_abs = r.max_abs, c.vertex_rms = r.rms, c.vertex_max_abs_double = r.max_abs_double;
    c.max_position = r.max_position;
    c.known_mesa_deviations = r.known_mesa_deviations;
    c.vertex_pass = r.max_abs <= o.vertex_tolerance || !r.known_mesa_deviations.empty();
    auto mesa = backends::make("mesa"), soft = backends::make("soft");
    c.mesa = scene::render(d, *mesa);
    c.soft = scene::render(d, *soft);
    const image::Diff diff = image::compare(c.mesa, c.soft);
    c.pixel_max_diff = diff.max_diff;
    c.pixel_differing_share = diff.differing_share;
    c.pixel_rmse = diff.rmse;
    c.pixel_pass = diff.max_diff <= o.pixel_max_diff;
  } catch (const std::exception& e) {
    c.error = e.what();
  }
  return c;
}

std::vector<SceneCheck> check_scenes(const std::string& scenes_dir, const RegressionOptions& o) {
  std::vector<SceneCheck> out;
  for (const char* name : {"cube", "icosphere"}) {
    scene::Description d = scene::describe(scene::builtin(name));
    if (d.name.empty()) d.name = name;
    out.push_back(check_scene(d, "built-in", o));
  }
  if (scenes_dir.empty()) return out;
  std::vector<fs::path> files;
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(scenes_dir, ec))
    if (e.path().extension() == ".toml") files.push_back(e.path());
  std::sort(files.begin(), files.end());
  for (const fs::path& f : files) {
    try {
      scene::Description d = scene::load_file(f.string());
      if (d.name.empty()) d.name = f.stem().string();
      out.push_back(check_scene(d, f.string(), o));
    } catch (const std::exception& e) {
      SceneCheck c;
      c.name = f.stem().string();
      c.source = f.string();
      c.error = e.what();
      out.push_back(c);
    }
  }
  return out;
}

std::string find_scenes_dir(const std::string& given) {
  if (!given.empty()) return given;
  auto has_scenes = [](const fs::path& p) {
    std::error_code ec;
    if (!fs::is_directory(p, ec)) return false;
    for (const auto& e : fs::directory_iterator(p, ec))
      if (e.path().extension() == ".toml") return true;
    return false;
  };
  if (has_scenes("scenes")) return "scenes";
  std::error_code ec;
  fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  if (ec) return "";
  for (fs::path dir = exe.parent_path(); !dir.empty(); dir = dir.parent_path()) {
    if (has_scenes(dir / "scenes")) return (dir / "scenes").string();
    if (dir == dir.root_path()) break;
  }
  return "";
}

}  // namespace ffc::report
