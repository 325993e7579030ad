#include "check/vertex_check.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

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

// For each of Mesa's vertices in a primitive, the index of its partner among ours. A clipped
// polygon may start its fan at another vertex than Mesa's clipper does, so ours may be Mesa's
// list rotated (or, walked the other way, reversed): the arrangement that puts every vertex
// closest to its partner's window position wins. Pairing each vertex with its nearest one instead goes wrong where two vertices share a
// window position with different colours (a cone's apex, a quad with an edge collapsed to a
// point): both would take the same partner. Ties (equal positions) go to the arrangement whose
// colours are closest; among equals, feedback order (no rotation) comes first. For a triangle the
// rotations and reversals are every pairing there is.
std::vector<size_t> partners(const FeedbackPrimitive& mesa, const FeedbackPrimitive& ours) {
  const size_t n = mesa.vertices.size();
  std::vector<size_t> out(n);
  auto index = [n](size_t i, size_t r, bool reversed) { return reversed ? (r + n - i) % n : (i + r) % n; };
  size_t best = 0;
  bool best_reversed = false;
  double best_pos = INFINITY, best_col = INFINITY;
  for (int rev = 0; rev < 2; ++rev)
    for (size_t r = 0; r < n; ++r) {
      double pos = 0, col = 0;
      for (size_t i = 0; i < n; ++i) {
        const FeedbackVertex &m = mesa.vertices[i], &o = ours.vertices[index(i, r, rev)];
        pos = std::max(pos, glm::length(o.position - m.position));
        col += glm::length(o.color - m.color);
      }
      // Positions decide (both agree far below a pixel); colours only break ties.
      const double tie = 1e-6;
      if (pos < best_pos - tie || (pos <= best_pos + tie && col < best_col))
        best = r, best_reversed = rev, best_pos = pos, best_col = col;
    }
  for (size_t i = 0; i < n; ++i) out[i] = index(i, best, best_reversed);
  return out;
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
  for (size_t p = 0; p < ref.size(); ++p) {
    const std::vector<size_t> pf = partners(ref[p], ours_f[p]), pd = partners(ref[p], ours_d[p]);
    for (size_t v = 0; v < ref[p].vertices.size(); ++v) {
      const FeedbackVertex& m = ref[p].vertices[v];
      const FeedbackVertex &f = ours_f[p].vertices[pf[v]], &d = ours_d[p].vertices[pd[v]];
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
  }
  if (r.vertices) {
    r.rms = std::sqrt(sum_sq / (4.0 * r.vertices));
    r.rms_double = std::sqrt(sum_sq_d / (4.0 * r.vertices));
    for (int c = 0; c < 4; ++c) r.channel[c].rms = std::sqrt(ch_sq[c] / r.vertices);
  }
  return r;
}

}  // namespace ffc::check
