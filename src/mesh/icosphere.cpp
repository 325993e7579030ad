#include "mesh/icosphere.h"

#include <cmath>
#include <map>
#include <stdexcept>
#include <utility>

namespace ffc::mesh {

const std::vector<Vec3>& icosahedron_positions() {
  static constexpr double X = .525731112119133606, Z = .850650808352039932;
  static const std::vector<Vec3> p = {{-X, 0, Z}, {X, 0, Z},  {-X, 0, -Z}, {X, 0, -Z},
                                      {0, Z, X},  {0, Z, -X}, {0, -Z, X},  {0, -Z, -X},
                                      {Z, X, 0},  {-Z, X, 0}, {Z, -X, 0},  {-Z, -X, 0}};
  return p;
}

const std::vector<Tri>& icosahedron_seed_triangles() {
  static const std::vector<Tri> t = {
      {1, 4, 0},  {4, 9, 0},  {4, 9, 5},  {8, 5, 4},  {1, 8, 4},  {1, 10, 8}, {10, 3, 8},
      {8, 3, 5},  {3, 2, 5},  {3, 7, 2},  {3, 10, 7}, {10, 6, 7}, {6, 11, 7}, {6, 0, 11},
      {6, 1, 0},  {10, 1, 6}, {11, 0, 9}, {2, 11, 9}, {5, 2, 9},  {11, 2, 7}};
  return t;
}

std::vector<int> inward_facing(const std::vector<Vec3>& p, const std::vector<Tri>& tris) {
  std::vector<int> out;
  for (size_t i = 0; i < tris.size(); ++i) {
    const Vec3 &a = p[tris[i][0]], &b = p[tris[i][1]], &c = p[tris[i][2]];
    const double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
    const double v[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
    const double n[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
    // The icosahedron is centred on the origin, so a face is outward iff n points away from it.
    if (n[0] * (a[0] + b[0] + c[0]) + n[1] * (a[1] + b[1] + c[1]) + n[2] * (a[2] + b[2] + c[2]) < 0)
      out.push_back(int(i));
  }
  return out;
}

std::vector<Tri> icosahedron_triangles() {
  // The seed's {4,9,5} is the one clockwise triangle: flat-shaded it would face inward and go
  // dark, culling would drop it, and OpenMesh rejects it as a complex edge. Reverse it.
  std::vector<Tri> t = icosahedron_seed_triangles();
  for (int i : inward_facing(icosahedron_positions(), t)) std::swap(t[i][1], t[i][2]);
  return t;
}

std::string icosphere_depth_error(int depth) {
  if (depth >= 0 && depth <= kMaxIcosphereDepth) return "";
  if (depth < 0) return "icosphere depth " + std::to_string(depth) + " is negative (0.." + std::to_string(kMaxIcosphereDepth) + ")";
  return "icosphere depth " + std::to_string(depth) + " is beyond the limit of " + std::to_string(kMaxIcosphereDepth) +
         ": each level quadruples the triangles and the memory (depth 10: 21 million triangles, 4.6 GB at its peak; "
         "depth 11 would need about 18 GB)";
}

Mesh make_icosphere(int depth) {
  if (const std::string e = icosphere_depth_error(depth); !e.empty()) throw std::invalid_argument(e);
  std::vector<Vec3> pos = icosahedron_positions();
  std::vector<Tri> tris = icosahedron_triangles();
  for (int level = 0; level < depth; ++level) {
    std::map<std::pair<int, int>, int> midpoint;  // shared edges get one midpoint
    auto mid = [&](int a, int b) {
      auto key = std::minmax(a, b);
      auto [it, fresh] = midpoint.try_emplace(key, int(pos.size()));
      if (fresh) {
        Vec3 m = {pos[a][0] + pos[b][0], pos[a][1] + pos[b][1], pos[a][2] + pos[b][2]};
        const double len = std::sqrt(m[0] * m[0] + m[1] * m[1] + m[2] * m[2]);
        pos.push_back({m[0] / len, m[1] / len, m[2] / len});
      }
      return it->second;
    };
    std::vector<Tri> next;
    next.reserve(tris.size() * 4);
    for (const Tri& t : tris) {
      const int v12 = mid(t[0], t[1]), v23 = mid(t[1], t[2]), v31 = mid(t[2], t[0]);
      next.push_back({t[0], v12, v31});
      next.push_back({t[1], v23, v12});
      next.push_back({t[2], v31, v23});
      next.push_back({v12, v23, v31});
    }
    tris = std::move(next);
  }
  Mesh m = build(pos, tris);
  update_normals(m);
  return m;
}

}  // namespace ffc::mesh
