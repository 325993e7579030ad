// The seeds' cube tables (seed 001, also seed 000): OpenMesh must reproduce both.
#include "mesh/cube.h"

#include <gtest/gtest.h>

namespace ffc::mesh {
namespace {

// Seed 001, "Normals of the Cube for Flat Shading": vertex index, position, normal; 36 rows.
struct FlatRow {
  int vertex;
  Vec3 position, normal;
};
const FlatRow kFlatTable[36] = {
    {0, {-1, 1, 1}, {0, 0, 1}},    {2, {1, -1, 1}, {0, 0, 1}},    {1, {1, 1, 1}, {0, 0, 1}},
    {0, {-1, 1, 1}, {0, 0, 1}},    {3, {-1, -1, 1}, {0, 0, 1}},   {2, {1, -1, 1}, {0, 0, 1}},
    {4, {-1, 1, -1}, {0, 0, -1}},  {5, {1, 1, -1}, {0, 0, -1}},   {6, {1, -1, -1}, {0, 0, -1}},
    {4, {-1, 1, -1}, {0, 0, -1}},  {6, {1, -1, -1}, {0, 0, -1}},  {7, {-1, -1, -1}, {0, 0, -1}},
    {0, {-1, 1, 1}, {0, 1, 0}},    {1, {1, 1, 1}, {0, 1, 0}},     {5, {1, 1, -1}, {0, 1, 0}},
    {0, {-1, 1, 1}, {0, 1, 0}},    {5, {1, 1, -1}, {0, 1, 0}},    {4, {-1, 1, -1}, {0, 1, 0}},
    {3, {-1, -1, 1}, {0, -1, 0}},  {6, {1, -1, -1}, {0, -1, 0}},  {2, {1, -1, 1}, {0, -1, 0}},
    {3, {-1, -1, 1}, {0, -1, 0}},  {7, {-1, -1, -1}, {0, -1, 0}}, {6, {1, -1, -1}, {0, -1, 0}},
    {1, {1, 1, 1}, {1, 0, 0}},     {2, {1, -1, 1}, {1, 0, 0}},    {6, {1, -1, -1}, {1, 0, 0}},
    {1, {1, 1, 1}, {1, 0, 0}},     {6, {1, -1, -1}, {1, 0, 0}},   {5, {1, 1, -1}, {1, 0, 0}},
    {0, {-1, 1, 1}, {-1, 0, 0}},   {7, {-1, -1, -1}, {-1, 0, 0}}, {3, {-1, -1, 1}, {-1, 0, 0}},
    {0, {-1, 1, 1}, {-1, 0, 0}},   {4, {-1, 1, -1}, {-1, 0, 0}},  {7, {-1, -1, -1}, {-1, 0, 0}},
};

// Seed 001, "Normals of the Cube for Smooth Shading", to the digits printed there.
const Vec3 kSmoothTable[8] = {
    {-0.5773502691896258, 0.5773502691896258, 0.5773502691896258},
    {0.8164965809277261, 0.4082482904638631, 0.4082482904638631},
    {0.4082482904638631, -0.4082482904638631, 0.8164965809277261},
    {-0.4082482904638631, -0.8164965809277261, 0.4082482904638631},
    {-0.4082482904638631, 0.4082482904638631, -0.8164965809277261},
    {0.4082482904638631, 0.8164965809277261, -0.4082482904638631},
    {0.5773502691896258, -0.5773502691896258, -0.5773502691896258},
    {-0.8164965809277261, -0.4082482904638631, -0.4082482904638631},
};

TEST(Cube, HasTheSeedsVerticesAndTriangles) {
  const Mesh m = make_cube();
  EXPECT_EQ(m.n_vertices(), 8u);
  EXPECT_EQ(m.n_faces(), 12u);
  EXPECT_EQ(m.n_edges(), 18u);  // closed: V - E + F = 2
}

TEST(Cube, FaceNormalCornersReproduceTheSeedsFlatTable) {
  const Layout l = layout(make_cube(), NormalSource::Face);
  ASSERT_EQ(l.vertices.size(), 36u);
  EXPECT_TRUE(l.indices.empty());
  for (int i = 0; i < 36; ++i) {
    SCOPED_TRACE("row " + std::to_string(i));
    EXPECT_EQ(l.vertices[i].source, kFlatTable[i].vertex);
    for (int k = 0; k < 3; ++k) {
      EXPECT_EQ(l.vertices[i].position[k], kFlatTable[i].position[k]);
      EXPECT_NEAR(l.vertices[i].normal[k], kFlatTable[i].normal[k], 1e-15);
    }
  }
}

TEST(Cube, AveragedNormalsReproduceTheSeedsSmoothTable) {
  const Layout l = layout(make_cube(), NormalSource::Average);
  ASSERT_EQ(l.vertices.size(), 8u);
  ASSERT_EQ(l.indices.size(), 36u);
  for (int i = 0; i < 8; ++i) {
    SCOPED_TRACE("vertex " + std::to_string(i));
    EXPECT_EQ(l.vertices[i].position, cube_positions()[i]);
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(l.vertices[i].normal[k], kSmoothTable[i][k], 1e-12);
  }
  // The indices are the seed's 12-triangle list, in order.
  for (int t = 0; t < 12; ++t)
    for (int k = 0; k < 3; ++k) EXPECT_EQ(int(l.indices[t * 3 + k]), cube_triangles()[t][k]);
}

TEST(Cube, AveragingIsUnweightedByAngleOrArea) {
  // Vertex 1 is in {0,2,1} {0,1,5} {1,2,6} {1,6,5}: normals +z, +y, +x, +x, so (2,1,1)/sqrt(6),
  // which is why the seed's table is not symmetric.
  const Mesh m = make_cube();
  const auto n = m.normal(m.vertex_handle(1));
  EXPECT_NEAR(n[0], 2 / std::sqrt(6.0), 1e-15);
  EXPECT_NEAR(n[1], 1 / std::sqrt(6.0), 1e-15);
  EXPECT_NEAR(n[2], 1 / std::sqrt(6.0), 1e-15);
}

}  // namespace
}  // namespace ffc::mesh
