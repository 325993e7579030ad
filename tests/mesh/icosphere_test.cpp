#include "mesh/icosphere.h"

#include <gtest/gtest.h>

#include <cmath>

namespace ffc::mesh {
namespace {

double degrees_between(const OpenMesh::Vec3d& a, const OpenMesh::Vec3d& b) {
  return std::atan2((a % b).norm(), a | b) * 180 / M_PI;
}

TEST(Icosahedron, SeedHasExactlyOneClockwiseTriangle_4_9_5) {
  const auto inward = inward_facing(icosahedron_positions(), icosahedron_seed_triangles());
  ASSERT_EQ(inward.size(), 1u);
  EXPECT_EQ(icosahedron_seed_triangles()[inward[0]], (Tri{4, 9, 5}));
}

TEST(Icosahedron, OpenMeshRefusesTheSeedListAsWritten) {
  EXPECT_THROW(build(icosahedron_positions(), icosahedron_seed_triangles()), std::invalid_argument);
}

TEST(Icosahedron, FixedListIsAllCounterClockwiseAndOtherwiseUnchanged) {
  const auto fixed = icosahedron_triangles();
  EXPECT_TRUE(inward_facing(icosahedron_positions(), fixed).empty());
  const auto& seed = icosahedron_seed_triangles();
  int changed = 0;
  for (size_t i = 0; i < seed.size(); ++i) changed += fixed[i] != seed[i];
  EXPECT_EQ(changed, 1);
  EXPECT_EQ(fixed[2], (Tri{4, 5, 9}));
}

TEST(Icosahedron, VerticesAreOnTheUnitSphere) {
  for (const Vec3& p : icosahedron_positions())
    EXPECT_NEAR(std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]), 1.0, 1e-15);
}

TEST(Icosphere, CountsPerDepth) {
  for (int d = 0; d <= 6; ++d) {
    SCOPED_TRACE("depth " + std::to_string(d));
    const Mesh m = make_icosphere(d);
    const size_t p = size_t(1) << (2 * d);  // 4^d
    EXPECT_EQ(m.n_faces(), 20 * p);
    EXPECT_EQ(m.n_vertices(), 10 * p + 2);
    EXPECT_EQ(m.n_edges(), 30 * p);
    for (auto v : m.vertices()) ASSERT_NEAR(m.point(v).norm(), 1.0, 1e-14);
    for (auto f : m.faces())  // every face normal points outward
      ASSERT_GT(m.normal(f) | m.point(*m.cfv_begin(f)), 0.0);
  }
}

TEST(Icosphere, FirstSubdivisionFollowsTheSeedsOrder) {
  // subdivide(v1,v2,v3) emits (v1,v12,v31), (v2,v23,v12), (v3,v31,v23), (v12,v23,v31).
  const Mesh m = make_icosphere(1);
  auto corner = [&](int face, int k) {
    auto it = m.cfv_begin(m.face_handle(face));
    for (int i = 0; i < k; ++i) ++it;
    return m.point(*it);
  };
  const auto& p = icosahedron_positions();
  const OpenMesh::Vec3d v1(p[1][0], p[1][1], p[1][2]), v2(p[4][0], p[4][1], p[4][2]),
      v3(p[0][0], p[0][1], p[0][2]);  // the seed's first triangle {1,4,0}
  const OpenMesh::Vec3d v12 = (v1 + v2).normalized(), v31 = (v3 + v1).normalized();
  EXPECT_NEAR((corner(0, 0) - v1).norm(), 0, 1e-15);
  EXPECT_NEAR((corner(0, 1) - v12).norm(), 0, 1e-15);
  EXPECT_NEAR((corner(0, 2) - v31).norm(), 0, 1e-15);
  EXPECT_NEAR((corner(1, 0) - v2).norm(), 0, 1e-15);
}

TEST(Icosphere, AveragedNormalsApproachTheSphereAsDepthGrows) {
  // Largest angle between OpenMesh's averaged normal and the exact normal (the position).
  // Depths 0 and 1 are symmetric about every vertex; from depth 2 on, the error halves per level.
  const double expected[] = {0, 0, 0.7599, 0.4738, 0.2485, 0.1257, 0.0630};
  for (int d = 0; d <= 6; ++d) {
    SCOPED_TRACE("depth " + std::to_string(d));
    const Mesh m = make_icosphere(d);
    double worst = 0;
    for (auto v : m.vertices()) worst = std::max(worst, degrees_between(m.normal(v), m.point(v)));
    if (d < 2)
      EXPECT_LT(worst, 1e-12);
    else
      EXPECT_NEAR(worst, expected[d], 1e-3);
  }
}

TEST(Icosphere, RejectsDepthOutOfRange) {
  EXPECT_THROW(make_icosphere(-1), std::invalid_argument);
  EXPECT_THROW(make_icosphere(13), std::invalid_argument);
}

TEST(Layout, SphereNormalsAreThePositionsAndShareVertices) {
  const Layout l = layout(make_icosphere(2), NormalSource::Sphere);
  ASSERT_EQ(l.vertices.size(), 162u);
  ASSERT_EQ(l.indices.size(), 320u * 3);
  for (const auto& v : l.vertices)
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(v.normal[k], v.position[k], 1e-15);
}

TEST(Layout, NormalSourceNamesRoundTrip) {
  for (auto n : {NormalSource::Face, NormalSource::Average, NormalSource::Sphere})
    EXPECT_EQ(parse_normal_source(to_string(n)), n);
  EXPECT_THROW(parse_normal_source("smooth"), std::invalid_argument);
}

}  // namespace
}  // namespace ffc::mesh
