// Vertex normals from the positions alone, with the usual weightings of the incident triangles'
// normals, in double:
//
//   average  sum of the unit face normals (OpenMesh's update_vertex_normals)
//   area     sum of the unnormalised cross products (e1 x e2): each face weighted by twice its area
//   angle    sum of the unit face normals times the corner angle at the vertex (Thürmer & Wüthrich)
//   max      sum of (e1 x e2) / (|e1|^2 |e2|^2), e1 and e2 the corner's edges (Max, "Weights for
//            computing vertex normals from facet normals", JGT 1999): exact for a vertex whose
//            neighbours lie on a sphere through it
//
// and sphere: the exact normal of a mesh inscribed in the unit sphere centred on the origin (the
// position, normalised). Each result is normalised; a vertex with no usable incident face (none,
// or only degenerate ones) or whose sum vanishes gets (0, 0, 0), as OpenMesh does.
//
// Robustness: one cross product per face (of the two edges at the corner opposite the longest
// edge, so the two shorter edges), corner angles by atan2(|e1 x e2|, e1 . e2) (accurate near 0 and
// 180 degrees, unlike acos), zero-area faces and zero-length edges skipped, and the sums normalised
// after scaling by their largest component (no overflow for Max's 1/|e|^4 on tiny edges).
#pragma once
#include <vector>

#include "mesh/mesh.h"

namespace ffc::mesh {

// One unit normal per vertex (index = vertex index) for Average, Area, Angle, Max or Sphere.
// Throws std::invalid_argument for Face (face normals belong to corners, not vertices).
std::vector<Vec3> vertex_normals(const Mesh& m, NormalSource weighting);

// The same, written into the mesh's vertex normals (what layout() reads for Average, and what a
// scene object with file normals draws).
void set_vertex_normals(Mesh& m, NormalSource weighting);

// The weightings that give one normal per vertex, in the order reports list them.
const std::vector<NormalSource>& vertex_weightings();  // average, area, angle, max, sphere

}  // namespace ffc::mesh
