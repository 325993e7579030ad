// The seeds' cube of side 2 (seed 001, "12 triangles"): 8 vertices, the index list as written.
#pragma once
#include "mesh/mesh.h"

namespace ffc::mesh {

const std::vector<Vec3>& cube_positions();
const std::vector<Tri>& cube_triangles();
Mesh make_cube();  // normals updated

}  // namespace ffc::mesh
