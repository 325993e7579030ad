// ffcompat check --backend glsl --level vertex: the GLSL backend's generated vertex shaders,
// recorded with transform feedback, against Mesa's fixed-function feedback (glsl/vertex_compare.h).
#include <cstdio>
#include <stdexcept>

#include "check/feedback.h"
#include "cli/common.h"
#ifdef FFCOMPAT_WITH_GLSL
#include "backends/glsl/vertex_compare.h"
#endif

namespace ffc::cli {

void print_largest(size_t primitive, size_t vertex, const check::FeedbackVertex& m, const check::FeedbackVertex& o) {
  std::printf("largest at primitive %zu vertex %zu, window (%.2f, %.2f): Mesa (%.6f %.6f %.6f %.6f), ours "
              "(%.6f %.6f %.6f %.6f)\n",
              primitive, vertex, m.position.x, m.position.y, m.color.r, m.color.g, m.color.b, m.color.a, o.color.r,
              o.color.g, o.color.b, o.color.a);
}

void check_glsl_vertices(const scene::Description& desc, const nlohmann::json& scene, double tolerance, bool json) {
#ifndef FFCOMPAT_WITH_GLSL
  (void)desc, (void)scene, (void)tolerance, (void)json;
  throw std::invalid_argument("backend 'glsl' is not built: EGL was not found at configure time");
#else
  const glsl::VertexComparison r = glsl::compare_with_mesa(desc.width, desc.height, [&] { scene::draw(desc); });
  // Every primitive Mesa reports is either compared or holds a clip-made vertex; none compared is
  // no check at all.
  const bool within = r.max_abs <= tolerance || !r.known_mesa_deviations.empty();
  const bool pass = r.unpaired == 0 && r.compared > 0 && within;
  const std::vector<std::string> known(r.known_mesa_deviations.begin(), r.known_mesa_deviations.end());
  if (json) {
    const auto& m = r.worst_mesa.color;
    const auto& o = r.worst_ours.color;
    print_json({{"level", "vertex"},
                {"backend", "glsl"},
                {"scene", scene},
                {"mesa_primitives", r.mesa_primitives},
                {"compared", r.compared},
                {"clipped", r.clipped},
                {"unpaired", r.unpaired},
                {"vertices", r.vertices},
                {"max_abs", r.max_abs},
                {"rms", r.rms},
                {"max_position_px", r.max_position},
                {"worst", {{"primitive", r.worst_primitive}, {"vertex", r.worst_vertex},
                           {"mesa", {m.r, m.g, m.b, m.a}}, {"ours", {o.r, o.g, o.b, o.a}}}},
                {"programs", {{"compiles", r.compiles}, {"cache_hits", r.cache_hits}}},
                {"known_mesa_deviations", known},
                {"tolerance", tolerance},
                {"pass", pass}});
  } else {
    std::printf("glsl (transform feedback) against mesa (feedback)\n"
                "primitives %zu: compared %zu, with a clip-made vertex %zu, unpaired %zu\n"
                "vertices %zu: colour max %.3g, rms %.3g; window positions within %.3g px\n"
                "programs compiled %llu, cache hits %llu\n",
                r.mesa_primitives, r.compared, r.clipped, r.unpaired, r.vertices, r.max_abs, r.rms, r.max_position,
                static_cast<unsigned long long>(r.compiles), static_cast<unsigned long long>(r.cache_hits));
    if (r.max_abs > 0) print_largest(r.worst_primitive, r.worst_vertex, r.worst_mesa, r.worst_ours);
    for (const auto& d : known) std::printf("known Mesa deviation: %s\n", d.c_str());
    std::printf("%s (tolerance %g)\n", pass ? "PASS" : "FAIL", tolerance);
  }
  if (!pass) throw CLI::RuntimeError(2);
#endif
}

}  // namespace ffc::cli
