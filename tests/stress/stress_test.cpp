// ffcompat stress: every case of the catalogue runs (Mesa included, each backend in a forked
// child), ours never crashes, never writes a pixel from a non-finite colour and keeps its float
// path finite; the verdicts of the hand-checked cases are the ones derived by hand; the harness
// itself notices a crash and a non-finite fragment; face normals survive extreme coordinates.
#include <gtest/gtest.h>

#include <csignal>
#include <cmath>
#include <limits>
#include <set>

#include "gl/dispatch.h"
#include "mesh/icosphere.h"
#include "mesh/mesh.h"
#include "raster/raster.h"
#include "pool/workers.h"
#include "stress/stress.h"
#include "counted_raster.h"

namespace ffc {
namespace {

bool starts_with(const std::string& s, const std::string& prefix) { return s.rfind(prefix, 0) == 0; }

// ---------------------------------------------------------------- the catalogue

TEST(Catalogue, HasTheCasesTheIssueAsksFor) {
  const auto& cases = stress::catalogue();
  EXPECT_GE(cases.size(), 25u);
  std::set<std::string> names;
  for (const auto& c : cases) {
    EXPECT_TRUE(names.insert(c.name).second) << "duplicate name " << c.name;
    EXPECT_FALSE(c.note.empty()) << c.name;
    EXPECT_FALSE(c.group.empty()) << c.name;
    EXPECT_TRUE(c.draw) << c.name;
    if (c.mesa != stress::MesaExpectation::Agree) {
      EXPECT_FALSE(c.mesa_reason.empty()) << c.name;
    }
  }
  for (const char* n : {"scale_1e-6_normalize", "scale_1e-6_rescale", "scale_1e6_rescale", "scale_1e-30_normalize",
                        "scale_0_z_normalize", "modelview_singular_rank2", "modelview_near_singular",
                        "normal_length_1e-3_plain", "normal_length_1e3_plain", "normal_zero_normalize", "shininess_0",
                        "shininess_128", "spot_exponent_128", "spot_cutoff_0", "spot_cutoff_90_boundary",
                        "spot_cutoff_180_exponent_128", "spot_direction_zero", "attenuation_zero",
                        "attenuation_huge_quadratic", "light_at_vertex", "light_w_tiny", "light_w_negative",
                        "vertex_w_tiny", "vertex_w_negative", "local_viewer_eye_on_surface", "colours_out_of_range",
                        "mesh_slivers", "mesh_needles", "mesh_near_duplicates", "mesh_coords_1e20", "mesh_coords_1e-20",
                        "icosphere_patch_depth10", "icosphere_float_collision", "mesh_degenerate_triangles",
                        "viewport_1x1", "viewport_8192", "nan_vertex_position", "inf_vertex_position", "odd_strides",
                        "normals_byte", "normals_short", "normals_int"})
    EXPECT_TRUE(stress::find(n)) << n;
  EXPECT_EQ(stress::find("no_such_case"), nullptr);
}

// ---------------------------------------------------------------- every case, guarded

std::vector<std::string> ci_cases() {
  std::vector<std::string> out;
  for (const auto& c : stress::catalogue())
    if (!c.slow) out.push_back(c.name);
  return out;
}

class EveryCase : public ::testing::TestWithParam<std::string> {};

TEST_P(EveryCase, OursNeverCrashesNorWritesNaN) {
  const stress::Result r = stress::run(*stress::find(GetParam()));
  EXPECT_FALSE(r.crashed) << r.verdict;
  EXPECT_EQ(r.nan_pixels, 0u) << "fragments written from non-finite colours";
  EXPECT_EQ(r.nan_vertices, 0u) << "non-finite vertices in our feedback (the float path must stay finite)";
  EXPECT_TRUE(std::isfinite(r.max_abs_vs_double));
  EXPECT_TRUE(r.mesa_ran && !r.mesa_crashed) << r.mesa_difference;
  EXPECT_FALSE(starts_with(r.verdict, "FAIL")) << r.verdict << "\n" << r.mesa_difference;
  EXPECT_TRUE(r.check_failure.empty()) << r.check_failure;
}

INSTANTIATE_TEST_SUITE_P(Stress, EveryCase, ::testing::ValuesIn(ci_cases()),
                         [](const auto& info) {
                           std::string n = info.param;
                           for (char& ch : n)
                             if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
                           return n;
                         });

// ---------------------------------------------------------------- verdicts derived by hand

stress::Result run_kept(const std::string& name) { return stress::run(*stress::find(name), {}, true); }

TEST(HandChecked, ZeroNormalUnderNormalizeLeavesAmbientAndEmission) {
  // e + a_cm a_cs + a_cm a_cl = (0.1, 0.05, 0) + 0.2 * 0.2 + 0.2 * 0.1 = (0.16, 0.11, 0.06), alpha 1,
  // at every vertex, on all three backends (Mesa's normalize turns 0 into NaN, which its lighting
  // drops at max(n.L, 0)).
  for (const char* name : {"normal_zero_normalize", "normal_zero_plain", "normal_zero_rescale"}) {
    const stress::Result r = run_kept(name);
    EXPECT_EQ(r.verdict, "ok") << name;
    for (const stress::Run* run : {&r.observed.mesa, &r.observed.soft, &r.observed.dbl}) {
      ASSERT_FALSE(run->feedback.empty()) << name;
      for (const auto& p : run->feedback)
        for (const auto& v : p.vertices) {
          EXPECT_NEAR(v.color.r, 0.16, 1e-5) << name;
          EXPECT_NEAR(v.color.g, 0.11, 1e-5) << name;
          EXPECT_NEAR(v.color.b, 0.06, 1e-5) << name;
          EXPECT_NEAR(v.color.a, 1.0, 1e-6) << name;
        }
    }
  }
}

TEST(HandChecked, RescaleUnderUniformScaleEqualsNormalize) {
  // Under glScalef(1e-6) the rescale factor is exactly 1e6: GL_RESCALE_NORMAL gives the unit
  // normals GL_NORMALIZE does, vertex for vertex.
  const stress::Result a = run_kept("scale_1e-6_rescale"), b = run_kept("scale_1e-6_normalize");
  EXPECT_EQ(a.verdict, "ok");
  EXPECT_EQ(b.verdict, "ok");
  for (auto pick : {&stress::Observed::soft, &stress::Observed::dbl, &stress::Observed::mesa}) {
    const auto &fa = (a.observed.*pick).feedback, &fb = (b.observed.*pick).feedback;
    ASSERT_EQ(fa.size(), fb.size());
    ASSERT_FALSE(fa.empty());
    double worst = 0;
    for (size_t p = 0; p < fa.size(); ++p)
      for (size_t v = 0; v < fa[p].vertices.size(); ++v)
        for (int k = 0; k < 4; ++k)
          worst = std::max(worst, std::abs(fa[p].vertices[v].color[k] - fb[p].vertices[v].color[k]));
    EXPECT_LT(worst, 1e-5);
  }
}

TEST(HandChecked, SpotCutoffZeroLightsOnlyTheAxis) {
  // Only the grid's centre vertex (window (32, 32)) is exactly on the axis: it is lit, every other
  // vertex has the global ambient only (0.04). Mesa's strict test lights nothing.
  const stress::Result r = run_kept("spot_cutoff_0");
  EXPECT_TRUE(r.check_failure.empty()) << r.check_failure;
  EXPECT_TRUE(starts_with(r.verdict, "mesa-deviation: Mesa's spot test is strict")) << r.verdict;
  for (const auto& p : r.observed.mesa.feedback)
    for (const auto& v : p.vertices) EXPECT_NEAR(v.color.r, 0.04, 1e-6);
  int axis = 0;
  for (const auto& p : r.observed.dbl.feedback)
    for (const auto& v : p.vertices)
      if (std::abs(v.position.x - 32) < 1e-3 && std::abs(v.position.y - 32) < 1e-3) {
        ++axis;
        EXPECT_GT(v.color.r, 0.9);  // 0.04 + 0.02 + 0.8 (n.L = 1) + specular, clamped
      }
  EXPECT_GT(axis, 0);
}

TEST(HandChecked, SpotCutoff90LightsItsBoundary) {
  const stress::Result r = run_kept("spot_cutoff_90_boundary");
  EXPECT_TRUE(r.check_failure.empty()) << r.check_failure;
  EXPECT_TRUE(starts_with(r.verdict, "mesa-deviation")) << r.verdict;
}

TEST(HandChecked, Verdicts) {
  // Derived from the spec and Mesa's source (see each case's note).
  const std::pair<const char*, const char*> expected[] = {
      {"scale_1e6_rescale", "ok"},
      {"scale_1e7_rescale", "mesa-deviation: Mesa skips GL_RESCALE_NORMAL"},
      {"scale_0_z_normalize", "ok"},  // singular: both take the identity
      {"modelview_singular_rank2", "ok"},
      {"modelview_near_singular", "ok: differs from Mesa where the spec leaves it undefined"},
      {"scale_1e-30_normalize", "ok: differs from Mesa where the spec leaves it undefined"},
      {"vertex_w_tiny", "ok"},  // ours lights at x, y, z as Mesa does (soft-spec divides by w)
      {"vertex_w_negative", "ok"},
      {"normals_byte", "ok"},  // ours converts as Mesa's draws do (GL 4.2's rule)
      {"normals_short", "ok"},
      {"nan_vertex_position", "ok"},
      {"nan_normal", "ok"},
      {"attenuation_zero_dark_channel", "ok"},
      {"light_w_tiny", "ok; float path off the double reference"},
  };
  for (const auto& [name, verdict] : expected) {
    const stress::Result r = stress::run(*stress::find(name));
    if (std::string(verdict) == "ok")
      EXPECT_EQ(r.verdict, "ok") << name << ": " << r.mesa_difference;
    else
      EXPECT_TRUE(starts_with(r.verdict, verdict)) << name << ": " << r.verdict;
  }
}

TEST(HandChecked, WNegativeDrawsNothing) {
  const stress::Result r = run_kept("vertex_w_negative");
  EXPECT_TRUE(r.observed.soft.feedback.empty());
  EXPECT_TRUE(r.observed.mesa.feedback.empty());
  for (uint8_t b : r.observed.soft.image.rgba) ASSERT_EQ(b, 0);
}

// ---------------------------------------------------------------- the harness itself

TEST(Harness, ACrashInOursIsReportedAndTheSuiteGoesOn) {
  stress::Case c;
  c.name = "synthetic_crash";
  c.group = "harness";
  c.note = "raises SIGSEGV while drawing";
  c.draw = [] { std::raise(SIGSEGV); };
  const stress::Result r = stress::run(c, {false, true, 30});
  EXPECT_TRUE(r.crashed);
  EXPECT_TRUE(starts_with(r.verdict, "FAIL: soft died on signal")) << r.verdict;
}

TEST(Harness, AMesaCrashIsContained) {
  // A draw that dies on Mesa only (its GL_VENDOR is not ours): Mesa's child dies, ours are judged.
  stress::Case c = *stress::find("viewport_1x1");
  c.name = "synthetic_mesa_crash";
  const auto draw = c.draw;
  c.draw = [draw] {
    const GLubyte* vendor = glGetString(GL_VENDOR);
    if (!vendor || std::string(reinterpret_cast<const char*>(vendor)) != "ffcompat") std::raise(SIGSEGV);
    draw();
  };
  const stress::Result r = stress::run(c);
  EXPECT_FALSE(r.crashed);
  EXPECT_TRUE(r.mesa_crashed);
  EXPECT_TRUE(starts_with(r.verdict, "mesa-deviation: Mesa died on signal")) << r.verdict;
  EXPECT_GT(r.primitives[1], 0u);
}

TEST(Harness, AThrowIsACrash) {
  stress::Case c;
  c.name = "synthetic_throw";
  c.group = "harness";
  c.note = "throws";
  c.draw = [] { throw std::runtime_error("boom"); };
  for (bool isolate : {true, false}) {
    const stress::Result r = stress::run(c, {false, isolate, 30});
    EXPECT_TRUE(r.crashed);
    EXPECT_NE(r.verdict.find("threw: boom"), std::string::npos) << r.verdict;
  }
}

TEST(Harness, InProcessAndIsolatedRunsAgree) {
  const stress::Case& c = *stress::find("colours_out_of_range");
  const stress::Result a = stress::run(c, {false, true, 60}, true), b = stress::run(c, {false, false, 60}, true);
  EXPECT_EQ(a.verdict, b.verdict);
  EXPECT_EQ(a.observed.soft.image.rgba, b.observed.soft.image.rgba);
  EXPECT_EQ(a.observed.dbl.feedback.size(), b.observed.dbl.feedback.size());
}

TEST(Harness, TheRasterCountsFragmentsFromNonFiniteColours) {
  // A zero count means something only if a NaN would be counted.
  raster::Framebuffer fb(16, 16);
  raster::Counters counts;
  const raster::State s = test::counted_state(counts);
  raster::WindowVertex a{}, b{}, c{};
  a.pos = {1, 1, 0.5}, b.pos = {15, 2, 0.5}, c.pos = {4, 14, 0.5};
  for (auto* v : {&a, &b, &c}) v->inv_w = 1, v->color = {0.5, 0.5, 0.5, 1};
  raster::Triangle t;
  ASSERT_TRUE(raster::setup(a, b, c, s, t));
  t.c0[1] = std::numeric_limits<float>::quiet_NaN();
  const std::vector<raster::Triangle> one = {t};
  pool::Workers workers(1);
  const std::vector<raster::Triangle>* list = &one;
  raster::draw_triangles(fb, &list, 1, s, workers);
  EXPECT_GT(counts.nonfinite_fragments.load(), 20u);

  counts.nonfinite_fragments = 0;
  a.color.g = std::numeric_limits<double>::infinity();
  a.fx = 1, a.y_down = 15, b.fx = 15, b.y_down = 14;  // the position line setup reads (rows counted down)
  raster::draw_line(fb, a, b, s);
  EXPECT_GT(counts.nonfinite_fragments.load(), 5u);

  // setup refuses planes that are not finite (here a colour of 1e39: beyond float).
  a.color.g = 1e39;
  EXPECT_FALSE(raster::setup(a, b, c, s, t));
}

TEST(Harness, ClippedPolygonsSplitAsMesaFeedsThemBack) {
  check::FeedbackPrimitive pent{GL_POLYGON_TOKEN, {}};
  for (int i = 0; i < 5; ++i) pent.vertices.push_back({{double(i), 0, 0}, {0, 0, 0, 1}});
  const auto out = stress::split_polygons({pent, {GL_LINE_TOKEN, {pent.vertices[0], pent.vertices[1]}}});
  ASSERT_EQ(out.size(), 4u);
  for (int i = 0; i < 3; ++i) {
    ASSERT_EQ(out[i].vertices.size(), 3u);
    EXPECT_EQ(out[i].vertices[0].position.x, i + 1);
    EXPECT_EQ(out[i].vertices[1].position.x, i + 2);
    EXPECT_EQ(out[i].vertices[2].position.x, 0);
  }
  EXPECT_EQ(out[3].token, unsigned(GL_LINE_TOKEN));
}

// ---------------------------------------------------------------- face normals at extreme scales

TEST(FaceNormals, UnitFrom1e300DownTo1eMinus300) {
  for (double s : {1.0, 1e20, 1e-20, 1e80, 1e-80, 1e160, 1e-160, 1e300, 1e-300}) {
    mesh::Mesh m = mesh::build({{0, 0, 0}, {s, 0, 0}, {0, s, 0.5 * s}}, {{0, 1, 2}});
    mesh::update_normals(m);
    const auto n = m.normal(*m.faces().begin());
    EXPECT_DOUBLE_EQ(n[0], 0) << s;
    EXPECT_NEAR(n[1], -1 / std::sqrt(5.0), 1e-15) << s;
    EXPECT_NEAR(n[2], 2 / std::sqrt(5.0), 1e-15) << s;
  }
}

TEST(FaceNormals, SameBitsAsOpenMeshWhereItDoesNotOverflow) {
  mesh::Mesh m = mesh::make_icosphere(3);
  for (auto f : m.faces()) {
    const auto ours = m.normal(f), openmesh = m.calc_face_normal(f);
    for (int k = 0; k < 3; ++k) ASSERT_EQ(ours[k], openmesh[k]);
  }
}

TEST(FaceNormals, SliverAndDegenerate) {
  // A sliver 1e-12 wide still has its exact normal; a triangle of zero area gets (0, 0, 0).
  mesh::Mesh m = mesh::build({{0, 0, 0}, {1, 0, 0}, {0.5, 1e-12, 0}, {2, 0, 0}}, {{0, 1, 2}, {1, 3, 2}});
  mesh::update_normals(m);
  auto f = m.faces().begin();
  EXPECT_NEAR(m.normal(*f)[2], 1.0, 1e-15);
  mesh::Mesh z = mesh::build({{0, 0, 0}, {1, 0, 0}, {2, 0, 0}}, {{0, 1, 2}});
  mesh::update_normals(z);
  const auto n = z.normal(*z.faces().begin());
  EXPECT_EQ(n[0], 0);
  EXPECT_EQ(n[1], 0);
  EXPECT_EQ(n[2], 0);
}

}  // namespace
}  // namespace ffc
