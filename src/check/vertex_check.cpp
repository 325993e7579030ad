#include "check/vertex_check.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "backends/soft/soft_backend.h"

namespace ffc::check {

namespace {

void require_same_shape(const std::vector<FeedbackPrimitive>& a, const std::vector<FeedbackPrimitive>& b,
                        const char* what) {
  if (a.size() != b.size())
    throw std::runtime_error(std::string("vertex check: Mesa reports ") + std::to_string(a.size()) +
                             " primitives, " + what + " " + std::to_string(b.size()));
  for (size_t i = 0; i < a.size(); ++i)
    if (a[i].token != b[i].token || a[i].vertices.size() != b[i].vertices.size())
      throw std::runtime_error(std::string("vertex check: primitive ") + std::to_string(i) +
                               " differs in kind or size between Mesa and " + what);
}

const FeedbackVertex& nearest(const FeedbackPrimitive& p, const FeedbackVertex& to) {
  size_t best = 0;
  double best_d = INFINITY;
  for (size_t i = 0; i < p.vertices.size(); ++i) {
    const double d = glm::length(p.vertices[i].position - to.position);
    if (d < best_d) best = i, best_d = d;
  }
  return p.vertices[best];
}

}  // namespace

VertexReport compare_vertices(int width, int height, const std::function<void()>& draw) {
  auto mesa = backends::make("mesa");
  const auto ref = capture(*mesa, width, height, draw);
  backends::SoftBackend soft_f(state::Precision::Float), soft_d(state::Precision::Double);
  const auto ours_f = capture(soft_f, width, height, draw);
  const auto deviations = state::Context::current()->deviations();
  const auto ours_d = capture(soft_d, width, height, draw);
  require_same_shape(ref, ours_f, "ours (float)");
  require_same_shape(ref, ours_d, "ours (double)");

  VertexReport r;
  r.known_mesa_deviations.assign(deviations.begin(), deviations.end());
  double sum_sq = 0, sum_sq_d = 0, ch_sq[4] = {0, 0, 0, 0};
  for (size_t p = 0; p < ref.size(); ++p)
    for (size_t v = 0; v < ref[p].vertices.size(); ++v) {
      // Within a primitive, pair by window position: a clipped polygon may start its fan at
      // another vertex than Mesa's clipper does, and that is not a lighting difference.
      const FeedbackVertex& m = ref[p].vertices[v];
      const FeedbackVertex &f = nearest(ours_f[p], m), &d = nearest(ours_d[p], m);
      ++r.vertices;
      r.max_position = std::max(r.max_position, glm::length(glm::dvec2(m.position - f.position)));
      for (int c = 0; c < 4; ++c) {
        const double ef = std::abs(f.color[c] - m.color[c]), ed = std::abs(d.color[c] - m.color[c]);
        r.channel[c].max_abs = std::max(r.channel[c].max_abs, ef);
        ch_sq[c] += ef * ef;
        sum_sq += ef * ef, sum_sq_d += ed * ed;
        if (ef > r.max_abs) r.worst_primitive = p, r.worst_vertex = v, r.worst_mesa = m, r.worst_ours = f;
        r.max_abs = std::max(r.max_abs, ef);
        r.max_abs_double = std::max(r.max_abs_double, ed);
        r.max_abs_float_vs_double = std::max(r.max_abs_float_vs_double, std::abs(f.color[c] - d.color[c]));
      }
    }
  if (r.vertices) {
    r.rms = std::sqrt(sum_sq / (4.0 * r.vertices));
    r.rms_double = std::sqrt(sum_sq_d / (4.0 * r.vertices));
    for (int c = 0; c < 4; ++c) r.channel[c].rms = std::sqrt(ch_sq[c] / r.vertices);
  }
  return r;
}

}  // namespace ffc::check
