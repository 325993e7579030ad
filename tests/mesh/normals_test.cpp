// The vertex-normal weightings against closed forms.
#include "mesh/normals.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "mesh/cube.h"
#include "mesh/icosphere.h"

namespace ffc::mesh {
namespace {

Vec3 unit(Vec3 v) {
  const double l = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
  return {v[0] / l, v[1] / l, v[2] / l};
}

double degrees_between(const Vec3& a, const Vec3& b) {
  const double c[3] = {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
  return std::atan2(std::sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]), a[0] * b[0] + a[1] * b[1] + a[2] * b[2]) *
         180 / M_PI;
}

void expect_near(const Vec3& got, const Vec3& want, double tol) {
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(got[size_t(k)], want[size_t(k)], tol) << "component " << k;
}

TEST(NormalSource, NewNamesRoundTrip) {
  for (auto n : {NormalSource::Face, NormalSource::Average, NormalSource::Sphere, NormalSource::Area,
                 NormalSource::Angle, NormalSource::Max})
    EXPECT_EQ(parse_normal_source(to_string(n)), n);
  EXPECT_THROW(parse_normal_source("weighted"), std::invalid_argument);
}

TEST(VertexNormals, FaceIsNotAVertexWeighting) {
  EXPECT_THROW(vertex_normals(make_cube(), NormalSource::Face), std::invalid_argument);
}

// The corner of a box with edges a, b, c along the axes: three right triangles at the origin,
// facing +z, +x, +y. By hand:
//   area:    (0,0,ab) + (bc,0,0) + (0,ca,0)                  -> (bc, ca, ab)
//   angle:   90 degrees each                                  -> (1, 1, 1)
//   average: one triangle each                                -> (1, 1, 1)
//   max:     (0,0,ab)/(a^2 b^2) + ... = (1/bc, 1/ca, 1/ab)    -> (a, b, c): the direction from
//            the centre (a,b,c)/2 of the sphere through the four points, as Max's weights promise
TEST(VertexNormals, BoxCornerWithKnownIncidentFaces) {
  const double a = 1, b = 2, c = 3;
  const Mesh m = build({{0, 0, 0}, {a, 0, 0}, {0, b, 0}, {0, 0, c}}, {{0, 1, 2}, {0, 2, 3}, {0, 3, 1}});
  auto at0 = [&](NormalSource s) { return vertex_normals(m, s)[0]; };
  expect_near(at0(NormalSource::Area), unit({b * c, c * a, a * b}), 1e-15);
  expect_near(at0(NormalSource::Angle), unit({1, 1, 1}), 1e-15);
  expect_near(at0(NormalSource::Average), unit({1, 1, 1}), 1e-15);
  expect_near(at0(NormalSource::Max), unit({a, b, c}), 1e-15);
  // OpenMesh's own average agrees.
  Mesh om = m;
  update_normals(om);
  const auto n = om.normal(om.vertex_handle(0));
  expect_near({n[0], n[1], n[2]}, unit({1, 1, 1}), 1e-15);
}

// The seeds' cube: side 2, two right isosceles triangles per face. At a corner each face has one
// triangle (90 degrees at the corner) or two (45 degrees each), all of area 2.
//   area = average: the faces weighted by their triangle counts (the seeds' smooth table);
//   angle: 90 degrees per face -> the diagonal (+-1,+-1,+-1)/sqrt(3);
//   max:   one triangle: (4n)/(4*4) = n/4; two: 2 * (4n)/(4*8) = n/4 -> the diagonal too.
TEST(VertexNormals, CubeCornersClosedForms) {
  Mesh m = make_cube();  // vertex normals: OpenMesh's average
  const auto area = vertex_normals(m, NormalSource::Area), angle = vertex_normals(m, NormalSource::Angle),
             maxw = vertex_normals(m, NormalSource::Max), avg = vertex_normals(m, NormalSource::Average);
  for (auto v : m.vertices()) {
    SCOPED_TRACE("vertex " + std::to_string(v.idx()));
    const auto p = m.point(v);
    const Vec3 diagonal = unit({p[0], p[1], p[2]});
    const auto om = m.normal(v);
    const Vec3 openmesh{om[0], om[1], om[2]};
    const size_t i = size_t(v.idx());
    expect_near(avg[i], openmesh, 1e-15);
    expect_near(area[i], openmesh, 1e-15);
    expect_near(angle[i], diagonal, 1e-15);
    expect_near(maxw[i], diagonal, 1e-15);
    // The triangle counts per face at this corner, worked out from the index list: the normal is
    // (k_x sx, k_y sy, k_z sz) normalised, k the number of triangles of that face at the corner.
    int k[3] = {0, 0, 0};
    for (const Tri& t : cube_triangles()) {
      if (t[0] != v.idx() && t[1] != v.idx() && t[2] != v.idx()) continue;
      const Vec3 &A = cube_positions()[size_t(t[0])], &B = cube_positions()[size_t(t[1])],
                 &C = cube_positions()[size_t(t[2])];
      for (int axis = 0; axis < 3; ++axis)
        if (A[size_t(axis)] == B[size_t(axis)] && B[size_t(axis)] == C[size_t(axis)]) ++k[axis];
    }
    expect_near(area[i], unit({k[0] * p[0], k[1] * p[1], k[2] * p[2]}), 1e-15);
    EXPECT_EQ(k[0] + k[1] + k[2], int(m.valence(v)));
  }
  // The cube is not symmetric enough for the area weighting: some corners lean.
  double worst = 0;
  for (auto v : m.vertices()) {
    const auto p = m.point(v);
    worst = std::max(worst, degrees_between(area[size_t(v.idx())], unit({p[0], p[1], p[2]})));
  }
  EXPECT_NEAR(worst, std::acos((2 + 1 + 1) / std::sqrt(6.0) / std::sqrt(3.0)) * 180 / M_PI, 1e-9);  // 19.47 deg
}

// Depth 0 and 1: every vertex's one-ring has a rotational symmetry about the vertex's axis (5-fold
// at the 12 original vertices, 2-fold at the edge midpoints), so every weighting gives the exact
// normal.
TEST(VertexNormals, IcosphereDepth0And1AllWeightingsExact) {
  for (int depth : {0, 1}) {
    const Mesh m = make_icosphere(depth);
    const auto exact = vertex_normals(m, NormalSource::Sphere);
    for (NormalSource s : vertex_weightings()) {
      SCOPED_TRACE(std::string(to_string(s)) + " depth " + std::to_string(depth));
      const auto n = vertex_normals(m, s);
      for (size_t i = 0; i < n.size(); ++i) ASSERT_LT(degrees_between(n[i], exact[i]), 1e-12);
    }
  }
}

// Max's weights are exact for a vertex whose neighbours lie on a sphere through it: every
// icosphere vertex, at every depth; the other weightings are off by a fraction of a degree.
TEST(VertexNormals, MaxIsExactOnTheIcosphereTheOthersAreNot) {
  for (int depth = 2; depth <= 5; ++depth) {
    SCOPED_TRACE("depth " + std::to_string(depth));
    const Mesh m = make_icosphere(depth);
    const auto exact = vertex_normals(m, NormalSource::Sphere);
    auto worst = [&](NormalSource s) {
      const auto n = vertex_normals(m, s);
      double w = 0;
      for (size_t i = 0; i < n.size(); ++i) w = std::max(w, degrees_between(n[i], exact[i]));
      return w;
    };
    EXPECT_LT(worst(NormalSource::Max), 1e-10);
    EXPECT_GT(worst(NormalSource::Area), 1e-3);
    EXPECT_GT(worst(NormalSource::Angle), 1e-3);
    EXPECT_GT(worst(NormalSource::Average), 1e-3);
  }
  // The README's figure for the average at depth 2: 0.760 degrees.
  const Mesh m = make_icosphere(2);
  const auto exact = vertex_normals(m, NormalSource::Sphere), avg = vertex_normals(m, NormalSource::Average);
  double w = 0;
  for (size_t i = 0; i < avg.size(); ++i) w = std::max(w, degrees_between(avg[i], exact[i]));
  EXPECT_NEAR(w, 0.760, 5e-4);
}

// An irregular fan on the unit sphere: a vertex at the north pole and six neighbours at random
// longitudes and latitudes. Max is exact; the others lean, each its own way.
TEST(VertexNormals, IrregularFanOnASphere) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> jitter(-0.35, 0.35), colat(0.2, 0.9);
  std::vector<Vec3> p = {{0, 0, 1}};
  for (int i = 0; i < 6; ++i) {
    const double phi = (i + 0.5 + jitter(rng)) * M_PI / 3, th = colat(rng);
    p.push_back({std::sin(th) * std::cos(phi), std::sin(th) * std::sin(phi), std::cos(th)});
  }
  std::vector<Tri> t;
  for (int i = 0; i < 6; ++i) t.push_back({0, 1 + i, 1 + (i + 1) % 6});
  const Mesh m = build(p, t);
  const Vec3 up{0, 0, 1};
  const Vec3 area = vertex_normals(m, NormalSource::Area)[0], angle = vertex_normals(m, NormalSource::Angle)[0],
             avg = vertex_normals(m, NormalSource::Average)[0], maxw = vertex_normals(m, NormalSource::Max)[0];
  EXPECT_LT(degrees_between(maxw, up), 1e-12);
  EXPECT_GT(degrees_between(area, up), 0.1);
  EXPECT_GT(degrees_between(angle, up), 0.1);
  EXPECT_GT(degrees_between(avg, up), 0.1);
  EXPECT_GT(degrees_between(area, angle), 0.01);
  EXPECT_GT(degrees_between(angle, avg), 0.01);
}

// Splitting an incident triangle through the vertex (a vertex added on its far edge) leaves a
// coplanar fan: area and angle weightings do not see the split (the areas and the angle add up);
// the unweighted average counts the face twice and leans toward it.
TEST(VertexNormals, SplittingAFaceMovesOnlyTheAverage) {
  const std::vector<Vec3> p = {{0, 0, 0}, {1, 0, 0}, {0, 2, 0}, {0, 0, 3}, {0.5, 1, 0}};
  const Mesh whole = build(p, {{0, 1, 2}, {0, 2, 3}, {0, 3, 1}});
  const Mesh split = build(p, {{0, 1, 4}, {0, 4, 2}, {0, 2, 3}, {0, 3, 1}});
  for (NormalSource s : {NormalSource::Area, NormalSource::Angle})
    expect_near(vertex_normals(split, s)[0], vertex_normals(whole, s)[0], 1e-15);
  EXPECT_GT(degrees_between(vertex_normals(split, NormalSource::Average)[0],
                            vertex_normals(whole, NormalSource::Average)[0]),
            1.0);
  expect_near(vertex_normals(split, NormalSource::Average)[0], unit({1, 1, 2}), 1e-15);
}

TEST(VertexNormals, DegenerateAndTinyTriangles) {
  // A zero-area sliver next to a proper triangle: skipped, not a NaN.
  const Mesh m = build({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {2, 0, 0}}, {{0, 1, 2}, {0, 3, 1}});
  for (NormalSource s : vertex_weightings()) {
    if (s == NormalSource::Sphere) continue;
    const auto n = vertex_normals(m, s);
    SCOPED_TRACE(to_string(s));
    expect_near(n[0], {0, 0, 1}, 1e-15);
    expect_near(n[3], {0, 0, 0}, 0);  // only the sliver: no direction
  }
  // Tiny edges (1e-120): Max's 1/|e|^4 would overflow a naive product; the result is still exact.
  const double e = 1e-120;
  const Mesh tiny = build({{0, 0, 0}, {e, 0, 0}, {0, 2 * e, 0}, {0, 0, 3 * e}}, {{0, 1, 2}, {0, 2, 3}, {0, 3, 1}});
  expect_near(vertex_normals(tiny, NormalSource::Max)[0], unit({1, 2, 3}), 1e-15);
  expect_near(vertex_normals(tiny, NormalSource::Area)[0], unit({6, 3, 2}), 1e-15);
}

TEST(VertexNormals, LayoutSendsTheWeightedNormals) {
  const Mesh m = make_icosphere(2);
  for (NormalSource s : {NormalSource::Area, NormalSource::Angle, NormalSource::Max}) {
    const Layout l = layout(m, s);
    const auto n = vertex_normals(m, s);
    ASSERT_EQ(l.vertices.size(), m.n_vertices());
    EXPECT_EQ(l.indices.size(), 3 * m.n_faces());
    for (const auto& v : l.vertices) ASSERT_EQ(v.normal, n[size_t(v.source)]);
  }
  Mesh w = m;
  set_vertex_normals(w, NormalSource::Angle);
  const Layout l = layout(w, NormalSource::Average);  // Average sends the mesh's vertex normals
  const auto n = vertex_normals(m, NormalSource::Angle);
  for (const auto& v : l.vertices) ASSERT_EQ(v.normal, n[size_t(v.source)]);
}

}  // namespace
}  // namespace ffc::mesh
