// ffcompat glsl: the GLSL programs the GLSL backend generates for a scene, with their uniforms'
// values after the frame: the fixed-function state of a scene written as shaders, a porting aid.
#include <cstdio>
#include <functional>
#include <stdexcept>

#include "cli/common.h"
#ifdef FFCOMPAT_WITH_GLSL
#include "backends/glsl/glsl_backend.h"
#endif

namespace ffc::cli {

void add_glsl(CLI::App& app) {
  auto* cmd = app.add_subcommand("glsl", "Print the GLSL 330 programs the glsl backend generates for a scene, and their uniforms");
  auto opts = std::make_shared<SceneOptions>();
  auto json = std::make_shared<bool>(false);
  auto frames = std::make_shared<int>(1);
  auto shading = std::make_shared<std::string>("gouraud");
  auto out = std::make_shared<std::string>();
  opts->add_to(cmd, true, false);
  cmd->add_option("--frames", *frames, "Frames drawn (the later ones find their programs in the cache)")
      ->check(CLI::Range(1, 100000))
      ->capture_default_str();
  cmd->add_option("--shading", *shading,
                  "gouraud (GL's: lit per vertex) or phong (the same equation per fragment, from the interpolated "
                  "eye-space normal and position)")
      ->check(CLI::IsMember({"gouraud", "phong"}))
      ->capture_default_str();
  cmd->add_option("--out", *out, "Also write the last frame's picture (PNG)");
  refuse_option(cmd, "--backend", "glsl always draws on the glsl backend");
  cmd->add_flag("--json", *json, "Print the programs as JSON");
  cmd->callback([=] {
#ifndef FFCOMPAT_WITH_GLSL
    throw std::invalid_argument("backend 'glsl' is not built: EGL was not found at configure time");
#else
    const scene::Description desc = opts->description();
    backends::GlslBackend b(*shading == "phong");
    image::Image picture = scene::render(desc, b);
    if (*frames > 1) {
      const std::function<void()> frame = scene::frame(desc);  // the meshes built once
      for (int f = 1; f < *frames; ++f) frame();
      picture = b.read();
    }
    if (!out->empty()) image::write_png(*out, picture);
    const glsl::Stats& st = b.renderer()->stats();
    if (*json) {
      nlohmann::json programs = nlohmann::json::array();
      for (const glsl::ProgramInfo* p : b.renderer()->programs()) {
        nlohmann::json u = nlohmann::json::object();
        for (const glsl::Uniform& x : p->uniforms)
          u[x.name] = {{"type", x.type}, {"value", std::vector<float>(x.value.begin(), x.value.begin() + x.size)}};
        char key[32];
        std::snprintf(key, sizeof key, "%08x/%03x", p->key.key.bits, p->key.key.extra);
        programs.push_back({{"key", key},
                            {"lighting", p->key.lit},
                            {"flat", p->key.flat},
                            {"draws", p->draws},
                            {"vertex_shader", p->sources.vertex},
                            {"fragment_shader", p->sources.fragment},
                            {"uniforms", u}});
      }
      print_json({{"scene", opts->json(desc)},
                  {"frames", *frames},
                  {"shading", *shading},
                  {"draws", st.draws},
                  {"compiles", st.compiles},
                  {"cache_hits", st.cache_hits},
                  {"uniform_uploads", st.uniform_uploads},
                  {"unsupported", std::vector<std::string>(b.renderer()->unsupported().begin(), b.renderer()->unsupported().end())},
                  {"programs", programs}});
      return;
    }
    std::printf("// %llu draws: %llu programs compiled, %llu cache hits, %llu uniform uploads\n",
                static_cast<unsigned long long>(st.draws), static_cast<unsigned long long>(st.compiles),
                static_cast<unsigned long long>(st.cache_hits), static_cast<unsigned long long>(st.uniform_uploads));
    for (const std::string& u : b.renderer()->unsupported()) std::printf("// not drawn: %s\n", u.c_str());
    int n = 0;
    for (const glsl::ProgramInfo* p : b.renderer()->programs()) {
      std::printf("\n// ---- program %d (%llu draws): vertex shader\n%s", n++, static_cast<unsigned long long>(p->draws),
                  p->sources.vertex.c_str());
      std::printf("// ---- fragment shader\n%s// ---- uniforms after the frame\n", p->sources.fragment.c_str());
      for (const glsl::Uniform& x : p->uniforms) {
        std::printf("%s %s =", x.type, x.name.c_str());
        for (int k = 0; k < x.size; ++k) std::printf(" %.9g", double(x.value[size_t(k)]));
        std::printf("\n");
      }
    }
#endif
  });
}

}  // namespace ffc::cli
