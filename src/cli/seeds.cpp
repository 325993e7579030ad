// ffcompat seeds: seed 000's fixed-function cube (the scene "cube" on Mesa) beside seed 001's
// GLSL Gouraud and Phong cubes from the same camera, and why they differ, one difference at a
// time. A chain of pictures walks from the one to the other, each link changing one thing:
//   ff            seed 000 on Mesa: light (3,4,5), shininess 10, light-model ambient 0.2
//   ff_setup      ... with seed 001's light (3,2,4), shininess 32 and no light-model ambient
//   ff_local      ... and GL_LIGHT_MODEL_LOCAL_VIEWER (the view vector to the eye, as seed 001's)
//   glsl_ff       seed 001's shaders doing what GL does: eye space, half vector, N.L test,
//                 vertex colours clamped (should match ff_local to a step)
//   glsl_world    ... lit in world space, as the handout
//   glsl_unclamped... vertex colours interpolated unclamped, as the handout
//   glsl_reflect  ... reflection vector instead of the half vector
//   gouraud       ... without the N.L test: seed 001's step 3
//   phong         per fragment: seed 001's step 4
// The green channel of every picture is the specular term alone (the material is red, the light
// white), so each picture's highlight is measured by it: its peak and how many pixels it covers.
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <map>
#include <memory>

#include "backends/backend.h"
#include "cli/common.h"
#include "image/label.h"
#include "scene/scene.h"

#ifdef FFCOMPAT_WITH_SEED001
#include "seed001_reference.h"
#include "seed001_renderer.h"
#endif

namespace ffc::cli {

#ifdef FFCOMPAT_WITH_SEED001
namespace {

struct Link {
  const char* name;
  const char* change;  // what differs from the picture before it
};

const Link kChain[] = {
    {"ff", "seed 000's fixed-function cube on Mesa"},
    {"ff_setup", "seed 001's light (3,2,4), shininess 32, no light-model ambient (0.3 -> 0.1 red)"},
    {"ff_local", "local viewer: view vector to the eye instead of GL's fixed (0,0,1) in eye space"},
    {"glsl_ff", "GLSL 330 core doing GL's equation (eye space, half vector, N.L test, clamped vertex colours)"},
    {"glsl_world", "lit in world space instead of eye space"},
    {"glsl_unclamped", "vertex colours interpolated unclamped (GL clamps each to [0,1] first)"},
    {"glsl_reflect", "reflection vector pow(V.R, s) instead of the half vector pow(N.H, s)"},
    {"gouraud", "no N.L test on the specular: seed 001's step 3"},
    {"phong", "lit per fragment from interpolated normals and positions: seed 001's step 4"},
};

// The GLSL links as switches on seed 001's step 3.
seed001::Lighting glsl_lighting(const std::string& name) {
  seed001::Lighting l = seed001::step_lighting(name == "phong" ? 4 : 3);
  if (name == "gouraud" || name == "phong") return l;
  l.nl_guard = true;
  if (name == "glsl_reflect") return l;
  l.half_vector = true;
  if (name == "glsl_unclamped") return l;
  l.clamp_vertex_colour = true;
  if (name == "glsl_world") return l;
  l.eye_space = true;  // glsl_ff
  return l;
}

struct Highlight {
  int peak = 0;     // largest green value
  int pixels = 0;   // pixels with green >= 1
};
Highlight highlight(const image::Image& img) {
  Highlight h;
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x) {
      const int g = img.at(x, y)[1];
      h.peak = std::max(h.peak, g);
      h.pixels += g >= 1;
    }
  return h;
}

struct Camera {
  std::string prefix, label;
  double angle_deg, height;
};

// Seed 001's averaged-normal steps (5 Gouraud, 6 Phong) with and without GL's N.L test, from the
// camera where the sweep found the test matters most: pictures, heat maps and a sheet.
nlohmann::ordered_json guard_pictures(seed001::Headless& glsl, const seed001::GuardSweep& g, const std::string& dir) {
  namespace fs = std::filesystem;
  seed001::View v;
  v.fovy_radians = false;
  v.cam_ang = g.cam_angle_deg * M_PI / 180, v.cam_height = g.cam_height;
  nlohmann::ordered_json j = nlohmann::json::array();
  std::vector<image::Image> keep;
  keep.reserve(6);
  image::Sheet sheet;
  sheet.title = "seed 001, averaged normals, camera " + std::to_string(int(g.cam_angle_deg)) + " deg, height " +
                std::to_string(g.cam_height).substr(0, 4) + ": without and with GL's N.L test on the specular";
  sheet.columns = {"as the handout", "with the N.L test", "difference"};
  sheet.heat_legend = true;
  for (const int step : {5, 6}) {
    seed001::Lighting l = seed001::step_lighting(step);
    keep.push_back(glsl.render(l, v));
    l.nl_guard = true;
    keep.push_back(glsl.render(l, v));
    const image::Image& a = keep[keep.size() - 2];
    const image::Image& b = keep.back();
    keep.push_back(image::heat_map(a, b));
    const std::string name = "guard_step" + std::to_string(step);
    image::write_png((fs::path(dir) / (name + ".png")).string(), a);
    image::write_png((fs::path(dir) / (name + "_nl_test.png")).string(), b);
    image::write_png((fs::path(dir) / (name + "_diff.png")).string(), keep.back());
    nlohmann::ordered_json row = {{"step", step}, {"file", (fs::path(dir) / (name + ".png")).string()},
                                  {"specular_peak", {highlight(a).peak, highlight(b).peak}},
                                  {"highlight_pixels", {highlight(a).pixels, highlight(b).pixels}}};
    row.update(to_json(image::compare(a, b)));
    j.push_back(row);
    sheet.rows.push_back(step == 5 ? "step 5 Gouraud" : "step 6 Phong");
    sheet.cells.push_back({&a, &b, &keep.back()});
  }
  image::write_png((fs::path(dir) / "guard.png").string(), image::labelled_grid(sheet));
  return j;
}

}  // namespace
#endif

void add_seeds(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "seeds", "Seed 000's fixed-function cube beside seed 001's GLSL Gouraud and Phong cubes, and why they differ");
  auto out = std::make_shared<std::string>();
  auto json = std::make_shared<bool>(false);
  auto size = std::make_shared<int>(640);
  auto angle = std::make_shared<double>(0);
  auto height = std::make_shared<double>(1);
  cmd->add_option("--out", *out, "Directory for the pictures, heat maps and sheets")->required();
  cmd->add_flag("--json", *json, "Print the pictures' figures and the differences as JSON");
  cmd->add_option("--size", *size, "Picture size (square)")->check(CLI::Range(16, 2048))->capture_default_str();
  [[maybe_unused]] auto* angle_opt = cmd->add_option("--cam-angle", *angle, "Camera angle around y in degrees (the seeds' keys 1/3)")
                        ->capture_default_str();
  [[maybe_unused]] auto* height_opt = cmd->add_option("--cam-height", *height, "Camera height (the seeds' keys 2/W)")->capture_default_str();
  cmd->callback([=] {
#ifndef FFCOMPAT_WITH_SEED001
    throw std::runtime_error("seeds: built without EGL (FFCOMPAT_WITH_EGL=OFF): no core-profile context for seed 001");
#else
    namespace fs = std::filesystem;
    const auto names = backends::names();
    if (std::find(names.begin(), names.end(), "mesa") == names.end())
      throw std::runtime_error("seeds: this build has no 'mesa' backend to draw seed 000's fixed-function cube");
    fs::create_directories(*out);
    // The seeds' camera looks at the front face head-on, and seed 001's highlight (where V = R)
    // falls outside every face it sees. Unless told otherwise, two more: from above and aside (as
    // `ffcompat shading`), where three faces show; and 30 degrees left, 0.5 down (keys 1 1 1 and
    // W x 15), where the light's mirror image lies inside the front face, at (0.39, 0.81, 1).
    std::vector<Camera> cameras = {{"", "seeds' camera", *angle, *height}};
    if (!angle_opt->count() && !height_opt->count()) {
      cameras.push_back({"three_faces_", "three faces\n35 deg, 2.5 up", 35, 2.5});
      cameras.push_back({"highlight_", "highlight inside\n-30 deg, 0.5 down", -30, -0.5});
    }

    std::map<std::string, image::Image> pics;
    auto mesa = backends::make("mesa");
    for (const Camera& c : cameras) {
      scene::Spec spec = scene::builtin("cube");
      spec.width = spec.height = *size;
      spec.cam_angle_deg = c.angle_deg, spec.cam_height = c.height;
      scene::Description d = scene::describe(spec);
      d.axes = false;  // seed 000's axes end on the faces; left out so only the lighting differs
      d.background = {0, 0, 0, 1};  // opaque black, as seed 001's glClearColor: the sheets show it so
      pics[c.prefix + "ff"] = scene::render(d, *mesa);
      d.lights[0].position = {3, 2, 4, 1};
      d.front.shininess = 32;
      d.light_model.ambient = {0, 0, 0, 1};
      pics[c.prefix + "ff_setup"] = scene::render(d, *mesa);
      d.light_model.local_viewer = true;
      pics[c.prefix + "ff_local"] = scene::render(d, *mesa);
    }
    mesa.reset();  // Mesa's fixed function done before the core-profile context
    seed001::Headless glsl(*size, *size);
    for (const Camera& c : cameras) {
      seed001::View v;
      v.fovy_radians = false;  // seed 000's gluPerspective(45, ...): the same camera for all
      v.cam_ang = c.angle_deg * M_PI / 180, v.cam_height = c.height;
      for (const Link& link : kChain)
        if (std::string(link.name).rfind("ff", 0) != 0)
          pics[c.prefix + link.name] = glsl.render(glsl_lighting(link.name), v);
    }

    nlohmann::ordered_json j = {{"renderer", glsl.gl_renderer()}, {"size", *size}, {"cameras", nlohmann::json::array()}};
    std::map<std::string, image::Image> heat;
    for (const Camera& c : cameras) {
      nlohmann::ordered_json cj = {{"label", c.label}, {"cam_angle_deg", c.angle_deg}, {"cam_height", c.height},
                                   {"pictures", nlohmann::json::array()}, {"differences", nlohmann::json::array()}};
      if (!*json) {
        std::string label = c.label;
        std::replace(label.begin(), label.end(), '\n', ' ');
        std::printf("-- camera %g deg, height %g (%s)\n", c.angle_deg, c.height, label.c_str());
      }
      for (const Link& link : kChain) {
        const std::string key = c.prefix + link.name, path = (fs::path(*out) / (key + ".png")).string();
        image::write_png(path, pics[key]);
        const Highlight h = highlight(pics[key]);
        cj["pictures"].push_back({{"name", link.name}, {"file", path}, {"specular_peak", h.peak},
                                  {"highlight_pixels", h.pixels}});
      }
      // Each link against the one before, and the three pictures the comparison is about.
      std::vector<std::tuple<std::string, std::string, std::string>> pairs;
      for (size_t i = 1; i < std::size(kChain); ++i) pairs.emplace_back(kChain[i - 1].name, kChain[i].name, kChain[i].change);
      pairs.emplace_back("ff", "gouraud", "seed 000 against seed 001's Gouraud cube (step 3)");
      pairs.emplace_back("ff", "phong", "seed 000 against seed 001's Phong cube (step 4)");
      if (!*json)
        std::printf("  %-14s -> %-14s %5s %8s %9s %6s %7s  %s\n", "from", "to", "max", "mean", "differing", "peak",
                    "hl_px", "what changed");
      for (const auto& [a, b, what] : pairs) {
        const image::Image& pa = pics[c.prefix + a];
        const image::Image& pb = pics[c.prefix + b];
        const image::Diff d = image::compare(pa, pb);
        const std::string name = c.prefix + "diff_" + a + "_vs_" + b;
        heat[name] = image::heat_map(pa, pb);
        const std::string path = (fs::path(*out) / (name + ".png")).string();
        image::write_png(path, heat[name]);
        const Highlight ha = highlight(pa), hb = highlight(pb);
        nlohmann::ordered_json row = {{"from", a}, {"to", b}, {"what", what}};
        row.update(to_json(d));
        row["heat_map"] = path;
        row["specular_peak"] = {ha.peak, hb.peak};
        row["highlight_pixels"] = {ha.pixels, hb.pixels};
        cj["differences"].push_back(row);
        if (!*json)
          std::printf("  %-14s -> %-14s %5d %8.3f %8.2f%% %3d>%-3d %7d>%-7d %s\n", a.c_str(), b.c_str(), d.max_diff,
                      d.mean_diff, 100 * d.differing_share, ha.peak, hb.peak, ha.pixels, hb.pixels, what.c_str());
      }
      j["cameras"].push_back(cj);
    }

    // The N.L test over every camera the seeds' keys reach, on the CPU: where it would matter.
    nlohmann::ordered_json guard = nlohmann::json::object();
    for (const int step : {3, 5}) {
      const seed001::GuardSweep g = seed001::sweep_nl_guard(seed001::step_lighting(step));
      guard[step == 3 ? "face_normals" : "averaged_normals"] = {
          {"cameras", g.cameras},         {"cameras_affected", g.cameras_affected},
          {"max_steps", g.max_steps},     {"at_cam_angle_deg", g.cam_angle_deg},
          {"at_cam_height", g.cam_height}, {"at_point", {g.point.x, g.point.y, g.point.z}}};
      if (!*json)
        std::printf("N.L test, %s normals: over %d cameras (10 deg, heights -3..3), specular on faces turned away "
                    "reaches %.2f steps (camera %g deg, height %g, point (%.2f, %.2f, %.2f)); %d cameras get >= 0.5\n",
                    step == 3 ? "face" : "averaged", g.cameras, g.max_steps, g.cam_angle_deg, g.cam_height, g.point.x,
                    g.point.y, g.point.z, g.cameras_affected);
    }
    const seed001::GuardSweep worst = seed001::sweep_nl_guard(seed001::step_lighting(5));
    guard["averaged_normals"]["pictures"] = guard_pictures(glsl, worst, *out);
    guard["sheet"] = (fs::path(*out) / "guard.png").string();
    if (!*json)
      for (const auto& row : guard["averaged_normals"]["pictures"])
        std::printf("  step %d from there, without -> with the N.L test: max %d steps on %.2f%% of the pixels, "
                    "highlight %d -> %d pixels (%s)\n",
                    row["step"].get<int>(), row["max_diff"].get<int>(), 100 * row["differing_share"].get<double>(),
                    row["highlight_pixels"][0].get<int>(), row["highlight_pixels"][1].get<int>(),
                    guard["sheet"].get<std::string>().c_str());
    j["nl_guard_sweep"] = guard;

    // Sheets: the three pictures and their differences per camera; the chain for each camera.
    image::Sheet main;
    main.title = "seed 000 (fixed function, Mesa) vs seed 001 (GLSL 330, " + glsl.gl_renderer() + ")";
    main.columns = {"seed 000 fixed function", "seed 001 Gouraud", "seed 001 Phong", "ff vs Gouraud", "ff vs Phong"};
    main.heat_legend = true;
    for (const Camera& c : cameras) {
      main.rows.push_back(c.label);
      main.cells.push_back({&pics[c.prefix + "ff"], &pics[c.prefix + "gouraud"], &pics[c.prefix + "phong"],
                            &heat[c.prefix + "diff_ff_vs_gouraud"], &heat[c.prefix + "diff_ff_vs_phong"]});
    }
    const std::string sheet = (fs::path(*out) / "sheet.png").string();
    image::write_png(sheet, image::labelled_grid(main));
    j["sheet"] = sheet;
    image::Sheet chain;
    chain.title = "from seed 000 to seed 001, one change a column (heat map: against the column before)";
    chain.heat_legend = true;
    for (const Link& link : kChain) chain.columns.push_back(link.name);
    for (const Camera& c : cameras) {
      chain.rows.push_back(c.label);
      chain.rows.push_back("difference");
      std::vector<const image::Image*> row, diffs = {nullptr};
      for (size_t i = 0; i < std::size(kChain); ++i) {
        row.push_back(&pics[c.prefix + kChain[i].name]);
        if (i) diffs.push_back(&heat[c.prefix + "diff_" + kChain[i - 1].name + "_vs_" + kChain[i].name]);
      }
      chain.cells.push_back(row);
      chain.cells.push_back(diffs);
    }
    const std::string chain_path = (fs::path(*out) / "chain.png").string();
    image::write_png(chain_path, image::labelled_grid(chain));
    j["chain_sheet"] = chain_path;
    if (*json)
      print_json(j);
    else
      std::printf("sheets: %s (the three cubes), %s (the chain)\n", sheet.c_str(), chain_path.c_str());
#endif
  });
}

}  // namespace ffc::cli
