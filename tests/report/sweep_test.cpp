// The sweep: its frames draw what scene::render draws, the error of exact normals falls with
// depth, and the headline interpolation on synthetic curves.
#include "report/sweep.h"

#include <gtest/gtest.h>

#include <cmath>

#include "image/compare.h"
#include "report/headline.h"
#include "scene/scene.h"

namespace ffc::report {
namespace {

TEST(Lighting, SeedIsTheBuiltInIcosphereSceneWithoutItsObject) {
  scene::Description builtin = scene::describe(scene::builtin("icosphere"));
  const Lighting l = lighting("seed", 512);
  EXPECT_TRUE(l.scene.objects.empty());
  EXPECT_EQ(l.scene.lights, builtin.lights);
  EXPECT_EQ(l.scene.front, builtin.front);
  EXPECT_EQ(l.scene.camera, builtin.camera);
  EXPECT_THROW(lighting("sunset"), std::invalid_argument);
  EXPECT_THROW(shading("smooth-cotangent"), std::invalid_argument);
  EXPECT_EQ(shadings().size(), 6u);
}

// The sweep times frames drawn from arrays built once; they must be the pictures scene::render
// draws from the full Description.
TEST(Frame, SamePixelsAsSceneRender) {
  DepthMesh dm(2);
  for (const char* b : {"mesa", "soft", "soft-double"}) {
    auto backend = backends::make(b);
    for (const char* ln : {"seed", "specular"}) {
      const Lighting l = lighting(ln, 128);
      for (const Shading& s : shadings()) {
        SCOPED_TRACE(std::string(b) + " " + ln + " " + s.name);
        const image::Image want = scene::render(describe(l, 2, s), *backend);
        backend->begin(128, 128);
        const image::Image first = frame(l, s, dm.arrays(s), *backend);
        const image::Image again = frame(l, s, dm.arrays(s), *backend);  // a second frame on the same context
        EXPECT_EQ(image::compare(want, first).max_diff, 0);
        EXPECT_EQ(image::compare(want, again).max_diff, 0);
      }
    }
  }
}

TEST(Frame, WeightedNormalsReachTheRenderer) {
  // Depth 2 is where the weightings start to differ: area, angle and max pictures are not the
  // average's; max is the exact sphere's normals (Max's weights are exact on a sphere).
  DepthMesh dm(2);
  auto mesa = backends::make("mesa");
  const Lighting l = lighting("specular", 128);
  auto pic = [&](const char* name) {
    mesa->begin(128, 128);
    return frame(l, shading(name), dm.arrays(shading(name)), *mesa);
  };
  const image::Image avg = pic("smooth-average"), area = pic("smooth-area"), angle = pic("smooth-angle"),
                     maxw = pic("smooth-max"), sphere = pic("smooth-sphere");
  EXPECT_GT(image::compare(avg, area).max_diff, 0);
  EXPECT_GT(image::compare(avg, angle).max_diff, 0);
  EXPECT_GT(image::compare(avg, maxw).max_diff, 0);
  EXPECT_LE(image::compare(maxw, sphere).max_diff, 1);
}

TEST(Sweep, ExactNormalErrorFallsWithDepth) {
  SweepOptions o;
  o.min_depth = 0, o.max_depth = 6;
  o.shadings = {"smooth-sphere", "flat"};
  o.backends = {"mesa"};
  o.size = 256;
  o.frames = o.frames_deep = 1;
  o.keep_depths = {};
  const SweepResult r = run_sweep(o);
  ASSERT_EQ(r.rows.size(), 7u * 2 * 2);
  for (const char* ln : {"seed", "specular"})
    for (const char* sh : {"smooth-sphere", "flat"}) {
      SCOPED_TRACE(std::string(ln) + " " + sh);
      const auto c = curve(r.rows, ln, sh, "mesa");
      ASSERT_EQ(c.size(), 7u);
      for (size_t i = 1; i < c.size(); ++i) EXPECT_LT(c[i].rmse, c[i - 1].rmse) << "depth " << i;
      EXPECT_EQ(c[1].triangles, 80);
    }
  // Smooth with exact normals beats flat from depth 2 on (at depth 1, 80 triangles, the interpolated
  // colours across big triangles are no better than flat ones under the specular setup).
  for (const char* ln : {"seed", "specular"}) {
    const auto flat = curve(r.rows, ln, "flat", "mesa"), smooth = curve(r.rows, ln, "smooth-sphere", "mesa");
    for (size_t i = 2; i < flat.size(); ++i) EXPECT_LT(smooth[i].rmse, flat[i].rmse) << ln << " depth " << i;
  }
  // The silhouette shrinks as the inscribed polygon approaches the circle, to no pixel at all.
  size_t prev = SIZE_MAX;
  for (const Row& row : r.rows)
    if (row.scene == "seed" && row.shading == "flat") {
      if (prev > 0)
        EXPECT_LT(row.silhouette_pixels, prev) << "depth " << row.depth;
      else
        EXPECT_EQ(row.silhouette_pixels, 0u) << "depth " << row.depth;
      prev = row.silhouette_pixels;
    }
  EXPECT_EQ(prev, 0u);
}

TEST(Headline, InterpolatesPowerLawsExactly) {
  // flat: e = 100 T^-1/2, smooth: e = 1000 T^-1, at the icosphere's counts 20 * 4^d.
  std::vector<CurvePoint> flat, smooth;
  for (int d = 0; d <= 8; ++d) {
    const double t = 20 * std::pow(4.0, d);
    flat.push_back({t, 100 / std::sqrt(t)});
    smooth.push_back({t, 1000 / t});
  }
  // e = 2: flat needs (100/2)^2 = 2500 triangles, smooth 1000/2 = 500.
  Reach f = triangles_to_reach(flat, 2), s = triangles_to_reach(smooth, 2);
  EXPECT_TRUE(f.reached && !f.extrapolated && !f.at_start);
  EXPECT_NEAR(f.triangles, 2500, 1e-9 * 2500);
  EXPECT_NEAR(s.triangles, 500, 1e-9 * 500);
  // Beyond the curve: extrapolated along the last segment's power law; above its start: the start.
  f = triangles_to_reach(flat, 0.01);
  EXPECT_TRUE(f.extrapolated && !f.reached);
  EXPECT_NEAR(f.triangles, 1e8, 1e-6 * 1e8);
  f = triangles_to_reach(flat, 50);
  EXPECT_TRUE(f.at_start);
  EXPECT_EQ(f.triangles, 20);
  // A curve that stops falling is not extrapolated.
  EXPECT_TRUE(std::isnan(triangles_to_reach({{20, 5}, {80, 4}, {320, 4}}, 1).triangles));
  // Unsorted input is sorted first.
  EXPECT_NEAR(triangles_to_reach({{320, 1000.0 / 320}, {20, 50}, {80, 12.5}}, 10).triangles, 100, 1e-9);

  // The same curves as sweep rows: the headline takes the lowest target both reach.
  std::vector<Row> rows;
  for (int d = 0; d <= 8; ++d)
    for (const char* sh : {"flat", "smooth-average"}) {
      Row r;
      r.depth = d, r.scene = "seed", r.backend = "mesa", r.shading = sh;
      r.triangles = size_t(20 * std::pow(4.0, d));
      r.rmse = std::string(sh) == "flat" ? flat[size_t(d)].rmse : smooth[size_t(d)].rmse;
      rows.push_back(r);
    }
  const auto h = headlines(rows, "mesa");
  ASSERT_EQ(h.size(), 1u);
  EXPECT_TRUE(h[0].found);
  // flat reaches 100/sqrt(1310720) = 0.087 at depth 8: every target down to 0.5 is within reach.
  EXPECT_EQ(h[0].main.target_rmse, 0.5);
  EXPECT_NEAR(h[0].main.flat.triangles, 40000, 1e-9 * 40000);
  EXPECT_NEAR(h[0].main.smooth.triangles, 2000, 1e-9 * 2000);
  EXPECT_NEAR(h[0].main.ratio, 20, 1e-9);
  // At 16 steps: flat (100/16)^2 = 39 triangles, smooth 1000/16 = 62.5: flat is ahead while coarse.
  EXPECT_EQ(h[0].crossings.front().target_rmse, 16);
  EXPECT_NEAR(h[0].crossings.front().flat.triangles, 39.0625, 1e-9);
}

}  // namespace
}  // namespace ffc::report
