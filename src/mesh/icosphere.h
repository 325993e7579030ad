// The icosahedron of seed 004 subdivided toward the unit sphere by bisecting edges and pushing the
// midpoints onto the sphere, kept as one connected mesh: 20*4^d faces, 10*4^d+2 vertices.
#pragma once
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
// (v1,v12,v31), (v2,v23,v12), (v3,v31,v23), (v12,v23,v31). Throws for depth < 0 or > 12.
Mesh make_icosphere(int depth);

}  // namespace ffc::mesh
