// ffcompat shading: one scene four ways (GL_FLAT and GL_SMOOTH, each with face and with averaged
// normals), a labelled contact sheet and the differences. The main job of scripts/run.
//
// The built-in cube is also drawn from a second camera: the seed's own looks at one face head-on
// (a red square that shows little), so the sheet adds a view from above and to the side where
// three faces show, with GL_FLAT's split of each face into two triangles and the averaged
// normals bending the light around the corners.
#include <cstdio>
#include <filesystem>
#include <map>
#include <memory>

#include "cli/common.h"
#include "image/label.h"

namespace ffc::cli {

namespace {

// The second camera of the built-in cube: 35 degrees around y, 2.5 up (as tests/scene's
// builtin_test), from where the top, front and right faces show.
constexpr double kThreeFacesAngle = 35, kThreeFacesHeight = 2.5;

struct View {
  std::string prefix;  // "" for the scene's own camera, "three_faces_" for the cube's second
  std::string label;   // row label on the sheet
  scene::Description desc;
};

// flat vs smooth for each normal source, then face vs averaged normals under GL_SMOOTH.
const std::pair<std::string, std::string> kPairs[] = {
    {"flat_face", "smooth_face"}, {"flat_average", "smooth_average"}, {"smooth_face", "smooth_average"}};

}  // namespace

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
    const scene::Description desc = opts->description();
    std::vector<View> views = {{"", "", desc}};
    const bool moved = (opts->cam_angle_option && opts->cam_angle_option->count()) ||
                       (opts->cam_height_option && opts->cam_height_option->count());
    if (!opts->is_file() && opts->scene == "cube" && !moved) {
      SceneOptions three = *opts;
      three.cam_angle = kThreeFacesAngle, three.cam_height = kThreeFacesHeight;
      views.front().label = "seed's camera";  // named only beside a second view
      views.push_back({"three_faces_", "three faces\n(35 deg, 2.5 up)", three.description()});
    }

    std::map<std::string, image::Image> pics, heat;
    nlohmann::json j = {{"backend", backend->name()}};
    if (!*json)
      std::printf("%-14s vs %-14s  %8s  %9s  %9s  %9s\n", "a", "b", "max_diff", "mean_diff", "differing",
                  "psnr_db");
    for (const View& v : views) {
      nlohmann::json vj = {{"images", nlohmann::json::object()}, {"comparisons", nlohmann::json::array()}};
      for (auto [shade, normals] : ways) {
        scene::Description d = v.desc;
        d.shade = shade;
        for (auto& o : d.objects) o.normals = normals, o.file_normals = false;
        const std::string key = v.prefix + scene::to_string(shade) + "_" + mesh::to_string(normals);
        pics[key] = scene::render(d, *backend);
        const std::string path = (fs::path(*out) / (key + ".png")).string();
        image::write_png(path, pics[key]);
        vj["images"][key.substr(v.prefix.size())] = path;
      }
      if (!v.prefix.empty() && !*json) std::printf("-- three faces: camera %g degrees around y, %g up\n", kThreeFacesAngle, kThreeFacesHeight);
      for (const auto& [a, b] : kPairs) {
        const std::string pa = v.prefix + a, pb = v.prefix + b;
        const image::Diff d = image::compare(pics[pa], pics[pb]);
        const std::string name = "diff_" + pa + "_vs_" + b;
        heat[name] = image::heat_map(pics[pa], pics[pb]);
        const std::string path = (fs::path(*out) / (name + ".png")).string();
        image::write_png(path, heat[name]);
        nlohmann::json row = to_json(d);
        row["a"] = a, row["b"] = b, row["diff"] = path;
        vj["comparisons"].push_back(row);
        if (!*json)
          std::printf("%-14s vs %-14s  %8d  %9.3f  %8.2f%%  %9.2f\n", a.c_str(), b.c_str(), d.max_diff,
                      d.mean_diff, 100 * d.differing_share, d.psnr);
      }
      if (v.prefix.empty()) {
        j["images"] = vj["images"], j["comparisons"] = vj["comparisons"];
      } else {
        vj["cam_angle"] = kThreeFacesAngle, vj["cam_height"] = kThreeFacesHeight;
        j["three_faces"] = vj;
      }
    }
    j["scene"] = opts->json(desc);
    j["scene"].erase("shade");
    j["scene"].erase("normals");

    // Sheet: per view, a row with face normals and one with averaged normals; columns GL_FLAT,
    // GL_SMOOTH and the heat map of their difference, with the heat map's legend underneath.
    image::Sheet sheet;
    sheet.title = "ffcompat shading: " + desc.name + " on " + backend->name();
    sheet.columns = {"GL_FLAT", "GL_SMOOTH", "difference"};
    sheet.heat_legend = true;
    for (const View& v : views)
      for (const char* n : {"face", "average"}) {
        const std::string p = v.prefix;
        sheet.rows.push_back((v.label.empty() ? "" : v.label + "\n") + n + " normals");
        sheet.cells.push_back({&pics[p + "flat_" + n], &pics[p + "smooth_" + n],
                               &heat["diff_" + p + "flat_" + n + "_vs_smooth_" + n]});
      }
    const std::string sheet_path = (fs::path(*out) / "sheet.png").string();
    image::write_png(sheet_path, image::labelled_grid(sheet));
    j["sheet"] = sheet_path;
    if (*json)
      print_json(j);
    else
      std::printf("sheet: %s (rows: %sface, average normals; columns: GL_FLAT, GL_SMOOTH, difference; labelled)\n",
                  sheet_path.c_str(), views.size() > 1 ? "seed's camera and three faces, each " : "");
  });
}

}  // namespace ffc::cli
