// ffcompat shading: one scene four ways (GL_FLAT and GL_SMOOTH, each with face and with averaged
// normals), a contact sheet and the differences. The main job of scripts/run.
#include <cstdio>
#include <filesystem>
#include <map>
#include <memory>

#include "cli/common.h"

namespace ffc::cli {

void add_shading(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "shading", "Render a scene flat and smooth, with face and averaged normals, and compare them");
  auto opts = std::make_shared<SceneOptions>();
  auto out = std::make_shared<std::string>();
  auto json = std::make_shared<bool>(false);
  opts->add_to(cmd, false);
  cmd->add_option("--out", *out, "Directory for the pictures")->required();
  cmd->add_flag("--json", *json, "Print the comparison as JSON");
  cmd->callback([=] {
    namespace fs = std::filesystem;
    fs::create_directories(*out);
    auto backend = backends::make(opts->backend);
    const std::pair<scene::Shade, mesh::NormalSource> ways[] = {
        {scene::Shade::Flat, mesh::NormalSource::Face},
        {scene::Shade::Smooth, mesh::NormalSource::Face},
        {scene::Shade::Flat, mesh::NormalSource::Average},
        {scene::Shade::Smooth, mesh::NormalSource::Average}};
    std::map<std::string, image::Image> pics;
    nlohmann::json j = {{"backend", backend->name()}, {"images", nlohmann::json::object()}};
    const scene::Description desc = opts->description();
    for (auto [shade, normals] : ways) {
      scene::Description d = desc;
      d.shade = shade;
      for (auto& o : d.objects) o.normals = normals, o.file_normals = false;
      const std::string key = std::string(scene::to_string(shade)) + "_" + mesh::to_string(normals);
      pics[key] = scene::render(d, *backend);
      const std::string path = (fs::path(*out) / (key + ".png")).string();
      image::write_png(path, pics[key]);
      j["images"][key] = path;
    }
    j["scene"] = opts->json(desc);
    j["scene"].erase("shade");
    j["scene"].erase("normals");
    // flat vs smooth for each normal source, then face vs averaged normals under GL_SMOOTH.
    const std::pair<std::string, std::string> pairs[] = {{"flat_face", "smooth_face"},
                                                         {"flat_average", "smooth_average"},
                                                         {"smooth_face", "smooth_average"}};
    std::map<std::string, image::Image> heat;
    j["comparisons"] = nlohmann::json::array();
    if (!*json)
      std::printf("%-14s vs %-14s  %8s  %9s  %9s  %9s\n", "a", "b", "max_diff", "mean_diff", "differing",
                  "psnr_db");
    for (const auto& [a, b] : pairs) {
      const image::Diff d = image::compare(pics[a], pics[b]);
      const std::string name = "diff_" + a + "_vs_" + b;
      heat[name] = image::heat_map(pics[a], pics[b]);
      const std::string path = (fs::path(*out) / (name + ".png")).string();
      image::write_png(path, heat[name]);
      nlohmann::json row = to_json(d);
      row["a"] = a, row["b"] = b, row["diff"] = path;
      j["comparisons"].push_back(row);
      if (!*json)
        std::printf("%-14s vs %-14s  %8d  %9.3f  %8.2f%%  %9.2f\n", a.c_str(), b.c_str(), d.max_diff,
                    d.mean_diff, 100 * d.differing_share, d.psnr);
    }
    // Sheet: rows face / average normals; columns GL_FLAT | GL_SMOOTH | their difference.
    const image::Image sheet = image::grid(
        {{&pics["flat_face"], &pics["smooth_face"], &heat["diff_flat_face_vs_smooth_face"]},
         {&pics["flat_average"], &pics["smooth_average"], &heat["diff_flat_average_vs_smooth_average"]}});
    const std::string sheet_path = (fs::path(*out) / "sheet.png").string();
    image::write_png(sheet_path, sheet);
    j["sheet"] = sheet_path;
    if (*json)
      print_json(j);
    else
      std::printf("sheet: %s (rows: face, average normals; columns: GL_FLAT, GL_SMOOTH, difference)\n",
                  sheet_path.c_str());
  });
}

}  // namespace ffc::cli
