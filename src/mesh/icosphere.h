// The icosahedron of seed 004 subdivided toward the unit sphere by bisecting edges and pushing the
// midpoints onto the sphere, kept as one connected mesh: 20*4^d faces, 10*4^d+2 vertices.
#pragma once
#include <string>
#include "mesh/mesh.h"

namespace ffc::mesh {

// The seed's vdata and tindices exactly as printed, including the one clockwise triangle.
const std::vector<Vec3>& icosahedron_positions();
const std::vector<Tri>& icosahedron_seed_triangles();

// Indices of triangles whose winding is clockwise seen from outside (normal toward the centre).
std::vector<int> inward_facing(const std::vector<Vec3>& positions, const std::vector<Tri>& tris);

// The seed's triangles with every inward-facing one reversed.
std::vector<Tri> icosahedron_triangles();

// depth 0 is the icosahedron; each level splits every triangle into four in the seed's order:
// (v1,v12,v31), (v2,v23,v12), (v3,v31,v23), (v12,v23,v31). Throws std::invalid_argument for a
// depth outside 0..kMaxIcosphereDepth, with icosphere_depth_error's message.
Mesh make_icosphere(int depth);

// The deepest icosphere we build. Each level has four times the triangles and, with the OpenMesh
// mesh, its normals and the draw arrays, about four times the memory. Measured peaks of
// `ffcompat render --backend soft` (GNU time's maximum resident size): depth 8 0.34 GB, depth 9
// 1.2 GB, depth 10 (21 million triangles) 4.6 GB in 26 s; so depth 11 would need about 18 GB and
// depth 12 about 72 GB: they ran for half a minute and died of std::bad_alloc. Refusing them up front is the honest answer.
constexpr int kMaxIcosphereDepth = 10;
// "" for a depth we build; otherwise why not, naming the limit and the reason.
std::string icosphere_depth_error(int depth);

}  // namespace ffc::mesh
