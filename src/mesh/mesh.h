// Triangle meshes in double precision on OpenMesh, and the draw-ready arrays built from them.
#pragma once
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace ffc::mesh {

// Double points and normals: the seeds' smooth-normal table is checked to 1e-12.
struct Traits : OpenMesh::DefaultTraits {
  using Point = OpenMesh::Vec3d;
  using Normal = OpenMesh::Vec3d;
  VertexAttributes(OpenMesh::Attributes::Normal);
  FaceAttributes(OpenMesh::Attributes::Normal);
};
using Mesh = OpenMesh::TriMesh_ArrayKernelT<Traits>;

using Vec3 = std::array<double, 3>;
using Tri = std::array<int, 3>;

// Face: per triangle corner; Average: OpenMesh's unweighted average of the incident face normals;
// Sphere: exact for the icosphere (the position, normalised); Area, Angle, Max: the weighted
// averages of mesh/normals.h.
enum class NormalSource { Face, Average, Sphere, Area, Angle, Max };
NormalSource parse_normal_source(const std::string& s);  // throws std::invalid_argument
const char* to_string(NormalSource n);

// Builds an OpenMesh mesh from an indexed triangle list, in order (face i is triangles[i]).
// Throws std::invalid_argument if OpenMesh refuses a face (a non-manifold or mis-wound one).
Mesh build(const std::vector<Vec3>& positions, const std::vector<Tri>& triangles);

// Face normals, then vertex normals as OpenMesh's unweighted average of incident face normals.
void update_normals(Mesh& m);

// The vertices a draw call sends, in double. Face normals need unshared corners (one vertex per
// triangle corner, in triangle order, drawn with glDrawArrays); the other sources share the mesh's
// vertices (drawn with glDrawElements over `indices`). Average reads the mesh's vertex normals;
// Area, Angle and Max are computed from the positions (mesh/normals.h).
struct Layout {
  struct Vertex {
    int source;  // the mesh vertex it came from
    Vec3 position, normal;
  };
  std::vector<Vertex> vertices;
  std::vector<uint32_t> indices;  // empty for unshared corners
};
Layout layout(const Mesh& m, NormalSource normals);

// The same in the float client arrays that glVertexPointer / glNormalPointer read.
struct DrawArrays {
  std::vector<float> positions;   // xyz per vertex
  std::vector<float> normals;     // xyz per vertex
  std::vector<uint32_t> indices;  // empty for unshared corners
  bool indexed() const { return !indices.empty(); }
  size_t vertex_count() const { return positions.size() / 3; }
};
DrawArrays draw_arrays(const Layout& l);
inline DrawArrays draw_arrays(const Mesh& m, NormalSource n) { return draw_arrays(layout(m, n)); }

}  // namespace ffc::mesh
