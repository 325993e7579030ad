#include "backends/glsl/vertex_compare.h"

#include <cmath>
#include <map>
#include <utility>

#include "backends/glsl/glsl_backend.h"

namespace ffc::glsl {

namespace {

constexpr double kSamePlace = 0.05;  // pixels: the same vertex, placed by two implementations
constexpr double kCell = 0.25;       // the position index's cell, pixels

struct OurPrimitive {
  std::vector<check::FeedbackVertex> v;
};

check::FeedbackVertex to_window(const CapturedDraw& d, const glm::vec4& clip) {
  const glm::dvec3 ndc = glm::dvec3(clip) / double(clip.w);
  const glm::dvec4 vp(d.viewport);
  check::FeedbackVertex f;
  f.position = {vp.x + (ndc.x + 1) * vp.z / 2, vp.y + (ndc.y + 1) * vp.w / 2,
                d.depth_range.x + (ndc.z + 1) * (d.depth_range.y - d.depth_range.x) / 2};
  return f;
}

// Ours as feedback would report them: each primitive's window positions and the colours of the
// face it shows, each vertex its own (Mesa's feedback does not flatten GL_FLAT's colours);
// culled ones left out.
std::vector<OurPrimitive> ours_as_feedback(const std::vector<CapturedDraw>& draws) {
  std::vector<OurPrimitive> out;
  for (const CapturedDraw& d : draws) {
    const size_t k = d.mode == GL_TRIANGLES ? 3 : d.mode == GL_LINES ? 2 : 1;
    for (size_t i = 0; i + k <= d.vertices.size(); i += k) {
      OurPrimitive p;
      bool behind = false;
      for (size_t j = 0; j < k; ++j) {
        p.v.push_back(to_window(d, d.vertices[i + j].clip));
        behind |= !(d.vertices[i + j].clip.w > 0);
      }
      bool back = false;
      if (k == 3 && !behind) {
        const glm::dvec3 &a = p.v[0].position, &b = p.v[1].position, &c = p.v[2].position;
        const double area = (b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y);
        back = area != 0 && ((area > 0) != (d.front_face == GL_CCW));
        if (d.cull && (d.cull_mode == GL_FRONT_AND_BACK || (d.cull_mode == GL_BACK) == back)) continue;
      }
      for (size_t j = 0; j < k; ++j) {
        const CapturedVertex& cv = d.vertices[i + j];
        p.v[j].color = glm::dvec4(back ? cv.back : cv.front);
      }
      out.push_back(std::move(p));
    }
  }
  return out;
}

using Cell = std::pair<long, long>;
Cell cell_of(const glm::dvec3& p) { return {std::lround(p.x / kCell), std::lround(p.y / kCell)}; }

// Our primitives by the cells of their vertices' positions.
struct Index {
  std::map<Cell, std::vector<size_t>> at;
  explicit Index(const std::vector<OurPrimitive>& ours) {
    for (size_t i = 0; i < ours.size(); ++i)
      for (const auto& v : ours[i].v) at[cell_of(v.position)].push_back(i);
  }
  template <class F>
  void near(const glm::dvec3& p, F f) const {
    const Cell c = cell_of(p);
    for (long dx = -1; dx <= 1; ++dx)
      for (long dy = -1; dy <= 1; ++dy)
        if (auto it = at.find({c.first + dx, c.second + dy}); it != at.end())
          for (size_t i : it->second) f(i);
  }
};

double distance2d(const glm::dvec3& a, const glm::dvec3& b) { return glm::length(glm::dvec2(a - b)); }
// For pairing: window depth too, scaled to weigh as pixels do (an orthographic sphere's front and
// back halves share their x and y).
double distance_paired(const glm::dvec3& a, const glm::dvec3& b) {
  return glm::length(glm::dvec3(a.x - b.x, a.y - b.y, 1e4 * (a.z - b.z)));
}

// Mesa's vertex j's partner among ours: the closest by position, then by colour (a cone's apex
// shares its position with different colours).
std::vector<size_t> pair_vertices(const check::FeedbackPrimitive& m, const OurPrimitive& o, double& worst) {
  std::vector<size_t> partner(m.vertices.size());
  std::vector<bool> used(o.v.size(), false);
  worst = 0;
  for (size_t j = 0; j < m.vertices.size(); ++j) {
    size_t best = 0;
    double bd = INFINITY, bc = INFINITY;
    for (size_t q = 0; q < o.v.size(); ++q) {
      if (used[q]) continue;
      const double d = distance_paired(m.vertices[j].position, o.v[q].position);
      const double c = glm::length(m.vertices[j].color - o.v[q].color);
      if (d < bd - 1e-9 || (d <= bd + 1e-9 && c < bc)) best = q, bd = d, bc = c;
    }
    used[best] = true, partner[j] = best, worst = std::max(worst, bd);
  }
  return partner;
}

}  // namespace

VertexComparison compare_with_mesa(int width, int height, const std::function<void()>& draw) {
  auto mesa = backends::make("mesa");
  const std::vector<check::FeedbackPrimitive> ref = check::capture(*mesa, width, height, draw);
  backends::GlslBackend g;
  g.begin(width, height);
  g.renderer()->set_capture(true);
  draw();
  const std::vector<OurPrimitive> ours = ours_as_feedback(g.renderer()->captured());
  VertexComparison r;
  r.known_mesa_deviations = g.context()->deviations();
  r.compiles = g.renderer()->stats().compiles, r.cache_hits = g.renderer()->stats().cache_hits;
  const Index index(ours);
  double sum_sq = 0;
  r.mesa_primitives = ref.size();
  for (size_t p = 0; p < ref.size(); ++p) {
    const check::FeedbackPrimitive& m = ref[p];
    size_t best = SIZE_MAX;
    double best_worst = INFINITY;
    std::vector<size_t> best_partner;
    index.near(m.vertices.front().position, [&](size_t i) {
      if (ours[i].v.size() != m.vertices.size()) return;
      double worst = 0;
      std::vector<size_t> partner = pair_vertices(m, ours[i], worst);
      if (worst < best_worst) best = i, best_worst = worst, best_partner = std::move(partner);
    });
    if (best == SIZE_MAX || best_worst > kSamePlace) {
      bool all_ours = true;  // every vertex where one of ours is
      for (const auto& v : m.vertices) {
        bool found = false;
        index.near(v.position, [&](size_t i) {
          for (const auto& o : ours[i].v) found |= distance2d(o.position, v.position) <= kSamePlace;
        });
        all_ours &= found;
      }
      ++(all_ours ? r.unpaired : r.clipped);
      continue;
    }
    ++r.compared;
    for (size_t j = 0; j < m.vertices.size(); ++j) {
      const check::FeedbackVertex& o = ours[best].v[best_partner[j]];
      ++r.vertices;
      r.max_position = std::max(r.max_position, distance2d(o.position, m.vertices[j].position));
      for (int c = 0; c < 4; ++c) {
        const double e = std::abs(o.color[c] - m.vertices[j].color[c]);
        sum_sq += e * e;
        if (e > r.max_abs) r.max_abs = e, r.worst_primitive = p, r.worst_vertex = j, r.worst_mesa = m.vertices[j], r.worst_ours = o;
      }
    }
  }
  if (r.vertices) r.rms = std::sqrt(sum_sq / (4.0 * double(r.vertices)));
  return r;
}

}  // namespace ffc::glsl
