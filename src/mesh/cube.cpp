#include "mesh/cube.h"

namespace ffc::mesh {

const std::vector<Vec3>& cube_positions() {
  static const std::vector<Vec3> p = {{-1, 1, 1},  {1, 1, 1},  {1, -1, 1},  {-1, -1, 1},
                                      {-1, 1, -1}, {1, 1, -1}, {1, -1, -1}, {-1, -1, -1}};
  return p;
}

const std::vector<Tri>& cube_triangles() {
  static const std::vector<Tri> t = {{0, 2, 1}, {0, 3, 2}, {4, 5, 6}, {4, 6, 7},
                                     {0, 1, 5}, {0, 5, 4}, {3, 6, 2}, {3, 7, 6},
                                     {1, 2, 6}, {1, 6, 5}, {0, 7, 3}, {0, 4, 7}};
  return t;
}

Mesh make_cube() {
  Mesh m = build(cube_positions(), cube_triangles());
  update_normals(m);
  return m;
}

}  // namespace ffc::mesh
