#include "mesh/normals.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace ffc::mesh {

namespace {

struct V {
  double x = 0, y = 0, z = 0;
};
inline V operator-(const V& a, const V& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline V operator*(const V& a, double s) { return {a.x * s, a.y * s, a.z * s}; }
inline V& operator+=(V& a, const V& b) {
  a.x += b.x, a.y += b.y, a.z += b.z;
  return a;
}
inline double dot(const V& a, const V& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline V cross(const V& a, const V& b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }

// |v| without overflow or underflow: scaled by the largest component first.
double norm(const V& v) {
  const double s = std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)});
  if (!(s > 0) || !std::isfinite(s)) return s;  // 0, or inf / NaN passed through
  const V u = v * (1 / s);
  return s * std::sqrt(dot(u, u));
}

Vec3 unit(const V& v) {
  const double s = std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)});
  if (!(s > 0) || !std::isfinite(s)) return {0, 0, 0};
  const V u = v * (1 / s);
  const double l = std::sqrt(dot(u, u));
  return {u.x / l, u.y / l, u.z / l};
}

}  // namespace

std::vector<Vec3> vertex_normals(const Mesh& m, NormalSource weighting) {
  std::vector<Vec3> out(m.n_vertices(), Vec3{0, 0, 0});
  if (weighting == NormalSource::Face)
    throw std::invalid_argument("face normals belong to triangle corners, not vertices");
  if (weighting == NormalSource::Sphere) {
    for (auto v : m.vertices()) {
      const auto& p = m.point(v);
      out[size_t(v.idx())] = unit({p[0], p[1], p[2]});
    }
    return out;
  }
  std::vector<V> sum(m.n_vertices());
  for (auto f : m.faces()) {
    // The corners in the face's order (next halfedge = counter-clockwise seen from the front).
    auto h = m.halfedge_handle(f);
    int idx[3];
    V p[3];
    for (int k = 0; k < 3; ++k, h = m.next_halfedge_handle(h)) {
      const auto vh = m.to_vertex_handle(h);
      idx[k] = vh.idx();
      const auto& q = m.point(vh);
      p[k] = {q[0], q[1], q[2]};
    }
    // Edge k is opposite corner k; squared lengths.
    const V e[3] = {p[2] - p[1], p[0] - p[2], p[1] - p[0]};
    const double len2[3] = {dot(e[0], e[0]), dot(e[1], e[1]), dot(e[2], e[2])};
    // One cross product per face, from the corner opposite the longest edge: (p[i+1]-p[i]) x
    // (p[i+2]-p[i]) has the face's orientation from every corner.
    const int o = len2[0] >= len2[1] ? (len2[0] >= len2[2] ? 0 : 2) : (len2[1] >= len2[2] ? 1 : 2);
    const V c = cross(p[(o + 1) % 3] - p[o], p[(o + 2) % 3] - p[o]);
    const double twice_area = norm(c);
    if (!(twice_area > 0) || !std::isfinite(twice_area)) continue;  // degenerate: no direction
    const V n = c * (1 / twice_area);
    for (int k = 0; k < 3; ++k) {
      // Corner k's edges run to the next and the previous corner: e1 = p[k+1]-p[k] (edge k+2),
      // e2 = p[k+2]-p[k] (edge k+1, reversed).
      const double l1 = len2[(k + 2) % 3], l2 = len2[(k + 1) % 3];
      V& s = sum[size_t(idx[k])];
      switch (weighting) {
        case NormalSource::Average: s += n; break;
        case NormalSource::Area: s += c; break;
        case NormalSource::Angle: {
          const V e1 = p[(k + 1) % 3] - p[k], e2 = p[(k + 2) % 3] - p[k];
          s += n * std::atan2(norm(cross(e1, e2)), dot(e1, e2));
          break;
        }
        case NormalSource::Max:
          // |c| / (l1 l2) = sin(angle) / (|e1| |e2|), divided in turn: l1 * l2 alone underflows for
          // edges below 1e-77, this only for edges below about 1e-150.
          if (l1 > 0 && l2 > 0) s += n * (twice_area / l1 / l2);
          break;
        default: break;
      }
    }
  }
  for (size_t i = 0; i < sum.size(); ++i) out[i] = unit(sum[i]);
  return out;
}

void set_vertex_normals(Mesh& m, NormalSource weighting) {
  const std::vector<Vec3> n = vertex_normals(m, weighting);
  for (auto v : m.vertices()) {
    const Vec3& x = n[size_t(v.idx())];
    m.set_normal(v, Mesh::Normal(x[0], x[1], x[2]));
  }
}

const std::vector<NormalSource>& vertex_weightings() {
  static const std::vector<NormalSource> w = {NormalSource::Average, NormalSource::Area, NormalSource::Angle,
                                              NormalSource::Max, NormalSource::Sphere};
  return w;
}

}  // namespace ffc::mesh
