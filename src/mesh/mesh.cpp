#include "mesh/mesh.h"

#include <stdexcept>

namespace ffc::mesh {

NormalSource parse_normal_source(const std::string& s) {
  if (s == "face") return NormalSource::Face;
  if (s == "average") return NormalSource::Average;
  if (s == "sphere") return NormalSource::Sphere;
  throw std::invalid_argument("unknown normal source '" + s + "' (face, average or sphere)");
}

const char* to_string(NormalSource n) {
  switch (n) {
    case NormalSource::Face: return "face";
    case NormalSource::Average: return "average";
    case NormalSource::Sphere: return "sphere";
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

void update_normals(Mesh& m) {
  m.update_face_normals();
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
  l.vertices.reserve(m.n_vertices());
  for (auto v : m.vertices())
    l.vertices.push_back({v.idx(), vec(m.point(v)),
                          vec(source == NormalSource::Average ? m.normal(v) : m.point(v).normalized())});
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
