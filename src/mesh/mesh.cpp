#include "mesh/mesh.h"

#include "mesh/normals.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace ffc::mesh {

NormalSource parse_normal_source(const std::string& s) {
  if (s == "face") return NormalSource::Face;
  if (s == "average") return NormalSource::Average;
  if (s == "sphere") return NormalSource::Sphere;
  if (s == "area") return NormalSource::Area;
  if (s == "angle") return NormalSource::Angle;
  if (s == "max") return NormalSource::Max;
  throw std::invalid_argument("unknown normal source '" + s + "' (face, average, sphere, area, angle or max)");
}

const char* to_string(NormalSource n) {
  switch (n) {
    case NormalSource::Face: return "face";
    case NormalSource::Average: return "average";
    case NormalSource::Sphere: return "sphere";
    case NormalSource::Area: return "area";
    case NormalSource::Angle: return "angle";
    case NormalSource::Max: return "max";
  }
  return "?";
}

Mesh build(const std::vector<Vec3>& positions, const std::vector<Tri>& triangles) {
  Mesh m;
  std::vector<Mesh::VertexHandle> vh;
  vh.reserve(positions.size());
  for (const Vec3& p : positions) vh.push_back(m.add_vertex(Mesh::Point(p[0], p[1], p[2])));
  for (size_t i = 0; i < triangles.size(); ++i) {
    const Tri& t = triangles[i];
    for (int k : t)
      if (k < 0 || size_t(k) >= positions.size())
        throw std::invalid_argument("triangle " + std::to_string(i) + " has vertex index " +
                                    std::to_string(k) + " out of range");
    // OpenMesh prints "complex edge" and returns an invalid handle for a face it cannot add.
    if (!m.add_face(vh[t[0]], vh[t[1]], vh[t[2]]).is_valid())
      throw std::invalid_argument("OpenMesh refused triangle " + std::to_string(i) + " {" +
                                  std::to_string(t[0]) + "," + std::to_string(t[1]) + "," +
                                  std::to_string(t[2]) + "}: complex edge (mis-wound or non-manifold)");
  }
  return m;
}

namespace {

// v scaled by a power of two (exact) so that its largest component is in [0.5, 1); 0 stays 0.
OpenMesh::Vec3d scaled(const OpenMesh::Vec3d& v) {
  const double big = std::max({std::abs(v[0]), std::abs(v[1]), std::abs(v[2])});
  if (!(big > 0) || !std::isfinite(big)) return v;
  int e;
  std::frexp(big, &e);
  return OpenMesh::Vec3d(std::ldexp(v[0], -e), std::ldexp(v[1], -e), std::ldexp(v[2], -e));
}

// OpenMesh's face normal, (p2 - p1) x (p0 - p1) times 1/|.|, with the edges and then the cross
// product scaled by powers of two first. Scaling by 2^k is exact, so wherever OpenMesh's own
// computation neither overflows nor underflows the bits are the same; beyond (coordinates above
// ~1e77, where its squared norm overflows to a zero normal, or below ~1e-77, where the squares
// underflow) this one stays unit. Degenerate or non-finite triangles get (0, 0, 0).
OpenMesh::Vec3d face_normal(const OpenMesh::Vec3d& p0, const OpenMesh::Vec3d& p1, const OpenMesh::Vec3d& p2) {
  const OpenMesh::Vec3d a = p2 - p1, b = p0 - p1;
  // One scale for both edges (the larger one's), so their cross product keeps its direction.
  const double big = std::max({std::abs(a[0]), std::abs(a[1]), std::abs(a[2]), std::abs(b[0]), std::abs(b[1]),
                               std::abs(b[2])});
  if (!(big > 0) || !std::isfinite(big)) return OpenMesh::Vec3d(0, 0, 0);
  int e;
  std::frexp(big, &e);
  const OpenMesh::Vec3d as(std::ldexp(a[0], -e), std::ldexp(a[1], -e), std::ldexp(a[2], -e));
  const OpenMesh::Vec3d bs(std::ldexp(b[0], -e), std::ldexp(b[1], -e), std::ldexp(b[2], -e));
  OpenMesh::Vec3d n = scaled(OpenMesh::cross(as, bs));
  const double length = n.norm();
  if (!(length > 0) || !std::isfinite(length)) return OpenMesh::Vec3d(0, 0, 0);
  return n *= (1.0 / length);
}

}  // namespace

void update_normals(Mesh& m) {
  for (auto f : m.faces()) {
    auto v = m.fv_iter(f);
    const OpenMesh::Vec3d p0 = m.point(*v), p1 = m.point(*++v), p2 = m.point(*++v);
    m.set_normal(f, face_normal(p0, p1, p2));
  }
  m.update_vertex_normals();
}

Layout layout(const Mesh& m, NormalSource source) {
  Layout l;
  auto vec = [](const OpenMesh::Vec3d& x) { return Vec3{x[0], x[1], x[2]}; };
  if (source == NormalSource::Face) {
    l.vertices.reserve(m.n_faces() * 3);
    for (auto f : m.faces())
      for (auto v : m.fv_range(f)) l.vertices.push_back({v.idx(), vec(m.point(v)), vec(m.normal(f))});
    return l;
  }
  const bool weighted = source == NormalSource::Area || source == NormalSource::Angle || source == NormalSource::Max;
  const std::vector<Vec3> normals = weighted ? vertex_normals(m, source) : std::vector<Vec3>();
  l.vertices.reserve(m.n_vertices());
  for (auto v : m.vertices())
    l.vertices.push_back({v.idx(), vec(m.point(v)),
                          weighted ? normals[size_t(v.idx())]
                                   : vec(source == NormalSource::Average ? m.normal(v) : m.point(v).normalized())});
  l.indices.reserve(m.n_faces() * 3);
  for (auto f : m.faces())
    for (auto v : m.fv_range(f)) l.indices.push_back(uint32_t(v.idx()));
  return l;
}

DrawArrays draw_arrays(const Layout& l) {
  DrawArrays d;
  d.positions.reserve(l.vertices.size() * 3);
  d.normals.reserve(l.vertices.size() * 3);
  for (const auto& v : l.vertices)
    for (int k = 0; k < 3; ++k) {
      d.positions.push_back(float(v.position[k]));
      d.normals.push_back(float(v.normal[k]));
    }
  d.indices = l.indices;
  return d;
}

}  // namespace ffc::mesh
