// ffcompat check: our pipeline against Mesa's. --level vertex compares lit colours vertex by
// vertex through feedback mode (the GLSL backend's through transform feedback); --level pixel
// compares the pictures. --backend names ours: soft, or glsl (a build with EGL).
#include <cstdio>
#include <filesystem>
#include <memory>

#include "check/vertex_check.h"
#include "cli/common.h"
#include "raster/raster.h"
#ifdef FFCOMPAT_WITH_MESA
#include "backends/mesa/mesa_backend.h"
#endif

namespace ffc::cli {

// --backend glsl --level vertex (check_glsl.cpp): the generated shaders' colours against Mesa's
// feedback. Throws CLI::RuntimeError(2) when the check fails.
void check_glsl_vertices(const scene::Description& desc, const nlohmann::json& scene, double tolerance, bool json);
// "largest at primitive P vertex V ...": where ours is furthest from Mesa (check_glsl.cpp).
void print_largest(size_t primitive, size_t vertex, const check::FeedbackVertex& mesa, const check::FeedbackVertex& ours);

void add_check(CLI::App& app) {
  auto* cmd = app.add_subcommand("check", "Check our pipeline against Mesa's, vertex by vertex or pixel by pixel");
  auto opts = std::make_shared<SceneOptions>();
  auto level = std::make_shared<std::string>("vertex");
  auto tolerance = std::make_shared<double>(1e-5);
  auto json = std::make_shared<bool>(false);
  auto max_steps = std::make_shared<int>(1);
  auto out = std::make_shared<std::string>("check-failures");
  opts->add_to(cmd, true, false);
  auto backend = std::make_shared<std::string>("soft");
  cmd->add_option("--backend", *backend,
                  "ours to check against mesa: soft (float and double) or glsl (the generated shaders; transform "
                  "feedback at --level vertex)")
      ->check(CLI::IsMember({"soft", "glsl"}))
      ->capture_default_str();
  cmd->add_option("--level", *level, "vertex or pixel")->check(CLI::IsMember({"vertex", "pixel"}))->capture_default_str();
  const CLI::Option* tolerance_opt =
      cmd->add_option("--tolerance", *tolerance, "vertex: largest colour difference that passes")->capture_default_str();
  const CLI::Option* max_diff_opt =
      cmd->add_option("--max-diff", *max_steps, "pixel: largest difference in 8-bit steps that passes")->capture_default_str();
  const CLI::Option* out_opt =
      cmd->add_option("--out", *out, "pixel: where a failure writes mesa.png, soft.png and diff.png")->capture_default_str();
  cmd->add_flag("--json", *json, "Print the report as JSON");
  cmd->callback([=] {
    // Each level has its own options: one given to the other level would be silently ignored.
    if (*level == "vertex" && (max_diff_opt->count() || out_opt->count()))
      throw std::invalid_argument("--max-diff and --out apply to --level pixel; --level vertex takes --tolerance");
    if (*level == "pixel" && tolerance_opt->count())
      throw std::invalid_argument("--tolerance applies to --level vertex; --level pixel takes --max-diff");
    const scene::Description desc = opts->description();
    if (*level == "vertex" && *backend == "glsl") return check_glsl_vertices(desc, opts->json(desc), *tolerance, *json);
    if (*level == "pixel") {
      auto mesa = backends::make("mesa"), soft = backends::make(*backend);
      const image::Image a = scene::render(desc, *mesa), b = scene::render(desc, *soft);
      const image::Diff d = image::compare(a, b);
      const bool pass = d.max_diff <= *max_steps;
      nlohmann::json j = to_json(d);
      j["level"] = "pixel", j["backend"] = *backend, j["scene"] = opts->json(desc), j["max_allowed"] = *max_steps, j["pass"] = pass;
      add_platform(j, "mesa");
      std::vector<std::string> named;
#ifdef FFCOMPAT_WITH_MESA
      // Soft rounded llvmpipe's multiply-adds otherwise than the llvmpipe beside it (the two
      // chosen apart: FFCOMPAT_LLVMPIPE_FMA). Named, not passed: the difference is real.
      if (!pass && raster::llvmpipe_fma() != backends::llvmpipe_fuses()) named.push_back("llvmpipe-fma-rounding");
#endif
      j["known_mesa_deviations"] = named;
      if (!pass) {  // the evidence, for a person to look at
        namespace fs = std::filesystem;
        fs::create_directories(*out);
        image::write_png((fs::path(*out) / "mesa.png").string(), a);
        image::write_png((fs::path(*out) / (*backend + ".png")).string(), b);
        image::write_png((fs::path(*out) / "diff.png").string(), image::heat_map(a, b));
        j["written"] = *out;
      }
      if (*json) {
        print_json(j);
      } else {
        std::printf("%s against mesa: max_diff %d steps, differing %.4f%%, rmse %.4f, psnr %.2f dB\n%s (max %d)%s\n", backend->c_str(), d.max_diff,
                    100 * d.differing_share, d.rmse, d.psnr, pass ? "PASS" : "FAIL", *max_steps,
                    pass ? "" : ("; pictures in " + *out).c_str());
        for (const std::string& n : named)
          std::printf("known Mesa deviation: %s (llvmpipe here %s its multiply-adds and soft %s, FFCOMPAT_LLVMPIPE_FMA: "
                      "depth ties and edges may differ, docs/deviations.md row 74)\n",
                      n.c_str(), backends::llvmpipe_fuses() ? "fuses" : "does not fuse", raster::llvmpipe_fma() ? "does" : "does not");
      }
      if (!pass) throw CLI::RuntimeError(2);
      return;
    }
    const check::VertexReport r = check::compare_vertices(desc.width, desc.height, [&] { scene::draw(desc); });
    const bool pass = r.max_abs <= *tolerance || !r.known_mesa_deviations.empty();
    if (*json) {
      nlohmann::json ch = nlohmann::json::array();
      for (const auto& c : r.channel) ch.push_back({{"max_abs", c.max_abs}, {"rms", c.rms}});
      nlohmann::json j = {{"level", "vertex"},
                          {"scene", opts->json(desc)},
                          {"vertices", r.vertices},
                          {"max_abs", r.max_abs},
                          {"rms", r.rms},
                          {"max_abs_double", r.max_abs_double},
                          {"rms_double", r.rms_double},
                          {"max_abs_float_vs_double", r.max_abs_float_vs_double},
                          {"channels", ch},
                          {"max_position_px", r.max_position},
                          {"worst", {{"primitive", r.worst_primitive}, {"vertex", r.worst_vertex},
                                     {"mesa", {r.worst_mesa.color.r, r.worst_mesa.color.g, r.worst_mesa.color.b, r.worst_mesa.color.a}},
                                     {"ours", {r.worst_ours.color.r, r.worst_ours.color.g, r.worst_ours.color.b, r.worst_ours.color.a}}}},
                          {"known_mesa_deviations", r.known_mesa_deviations},
                          {"tolerance", *tolerance},
                          {"pass", pass}};
      add_platform(j, "mesa");
      print_json(j);
    } else {
      std::printf("vertices %zu\n%-8s %12s %12s\n", r.vertices, "channel", "max_abs", "rms");
      const char* names[] = {"red", "green", "blue", "alpha"};
      for (int c = 0; c < 4; ++c) std::printf("%-8s %12.3g %12.3g\n", names[c], r.channel[c].max_abs, r.channel[c].rms);
      std::printf("float  vs Mesa: max %.3g, rms %.3g\ndouble vs Mesa: max %.3g, rms %.3g\n"
                  "window positions agree within %.3g px\n",
                  r.max_abs, r.rms, r.max_abs_double, r.rms_double, r.max_position);
      if (r.max_abs > 0) print_largest(r.worst_primitive, r.worst_vertex, r.worst_mesa, r.worst_ours);
      for (const auto& d : r.known_mesa_deviations) std::printf("known Mesa deviation: %s\n", d.c_str());
      std::printf("%s (tolerance %g)\n", pass ? "PASS" : "FAIL", *tolerance);
    }
    if (!pass) throw CLI::RuntimeError(2);
  });
}

}  // namespace ffc::cli
