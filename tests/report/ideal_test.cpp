// The ray-cast ideal sphere: pixels whose colour is worked out by hand, its coverage, the rounding
// floor, and the shading error measure.
#include "report/ideal.h"

#include <gtest/gtest.h>

#include <cmath>

#include "report/metrics.h"
#include "report/sweep.h"

namespace ffc::report {
namespace {

struct Hit {
  bool hit = false;
  double p[3], n[3];  // eye space
};

// By hand, in eye space: the camera at the origin looking down -z, the unit sphere's centre at
// (0,0,-4) (gluLookAt from (0,0,4) at the origin is a translation by -4 in z). A pixel centre
// (col + .5, row from the bottom + .5) on a w x w picture with fovy 45 and aspect 1 is the
// direction (ndc_x t, ndc_y t, -1), t = tan(22.5 deg) = sqrt(2) - 1.
Hit cast(int col, int row_from_top, int w) {
  const double t = std::sqrt(2.0) - 1;
  const double nx = 2 * (col + 0.5) / w - 1, ny = 2 * (w - 1 - row_from_top + 0.5) / w - 1;
  const double d[3] = {nx * t, ny * t, -1};
  // |s d - c|^2 = 1 with c = (0,0,-4): s^2 |d|^2 - 2 s (d.c) + 15 = 0, d.c = 4.
  const double dd = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
  const double disc = 16 - 15 * dd;
  Hit h;
  if (disc < 0) return h;
  const double s = (4 - std::sqrt(disc)) / dd;
  h.hit = true;
  for (int k = 0; k < 3; ++k) h.p[k] = s * d[k];
  h.n[0] = h.p[0], h.n[1] = h.p[1], h.n[2] = h.p[2] + 4;
  return h;
}

int steps(double c) { return int(std::nearbyint(std::min(1.0, std::max(0.0, c)) * 255)); }

TEST(Ideal, SeedPixelByHand) {
  const Lighting l = lighting("seed", 256);
  const Ideal ideal = ray_cast_sphere(l.scene);
  const int col = 170, row = 90;  // up and to the right of the centre, well inside the disc
  const Hit h = cast(col, row, 256);
  ASSERT_TRUE(h.hit);
  // Light 0: directional (0,0,1) in eye space, ambient .2, diffuse 1, no specular; global ambient
  // .2; material ambient = diffuse = (.8,.6,.4), as the floats GL is given.
  const double ndotl = std::max(0.0, h.n[2]);
  const double m[3] = {double(.8f), double(.6f), double(.4f)};
  const uint8_t* px = ideal.image.at(col, row);
  for (int k = 0; k < 3; ++k) {
    const double c = double(.2f) * m[k] + double(.2f) * m[k] + ndotl * m[k];
    EXPECT_NEAR(ideal.exact[size_t(row) * 256 + col][k], std::min(1.0, c), 1e-12) << "channel " << k;
    EXPECT_EQ(int(px[k]), steps(c)) << "channel " << k;
  }
  EXPECT_EQ(int(px[3]), 255);
  // The centre pixel faces the light: 1.4 x the material, red clamped.
  const uint8_t* centre = ideal.image.at(128, 128);
  EXPECT_EQ(int(centre[0]), 255);
  EXPECT_NEAR(int(centre[1]), 214, 1);  // 0.84 * 255 = 214.2
  EXPECT_NEAR(int(centre[2]), 143, 1);  // 0.56 * 255 = 142.8
}

TEST(Ideal, SpecularPixelByHand) {
  const Lighting l = lighting("specular", 256);
  const Ideal ideal = ray_cast_sphere(l.scene);
  // Light 0 at (3,4,5,1) in the world is (3,4,1) in eye space. Red ambient and diffuse, white
  // specular, shininess 10; infinite viewer: h = normalize(L + (0,0,1)).
  for (auto [col, row] : {std::pair{150, 100}, std::pair{128, 128}, std::pair{100, 170}}) {
    SCOPED_TRACE("pixel " + std::to_string(col) + "," + std::to_string(row));
    const Hit hit = cast(col, row, 256);
    ASSERT_TRUE(hit.hit);
    double L[3] = {3 - hit.p[0], 4 - hit.p[1], 1 - hit.p[2]};
    const double ll = std::sqrt(L[0] * L[0] + L[1] * L[1] + L[2] * L[2]);
    for (double& x : L) x /= ll;
    double H[3] = {L[0], L[1], L[2] + 1};
    const double hl = std::sqrt(H[0] * H[0] + H[1] * H[1] + H[2] * H[2]);
    for (double& x : H) x /= hl;
    const double ndotl = hit.n[0] * L[0] + hit.n[1] * L[1] + hit.n[2] * L[2];
    const double ndoth = std::max(0.0, hit.n[0] * H[0] + hit.n[1] * H[1] + hit.n[2] * H[2]);
    const double spec = ndotl > 0 ? std::pow(ndoth, 10) : 0;
    const double red = double(.2f) + double(.1f) + std::max(0.0, ndotl) * 1 + spec;
    const uint8_t* px = ideal.image.at(col, row);
    EXPECT_EQ(int(px[0]), steps(red));
    EXPECT_EQ(int(px[1]), steps(spec));
    EXPECT_EQ(int(px[2]), steps(spec));
    EXPECT_NEAR(ideal.exact[size_t(row) * 256 + col][1], spec, 1e-12);
  }
}

TEST(Ideal, CoversTheProjectedDisc) {
  const Ideal ideal = ray_cast_sphere(lighting("seed", 512).scene);
  // The silhouette cone's half angle is asin(1/4); on the image plane the disc's radius is
  // tan(asin(1/4)) / tan(22.5 deg) * 256 = 159.6 pixels.
  const double r = std::tan(std::asin(0.25)) / std::tan(M_PI / 8) * 256;
  EXPECT_NEAR(double(ideal.covered_count), M_PI * r * r, 0.002 * M_PI * r * r);
  EXPECT_EQ(ideal.covered[0], 0);
  EXPECT_EQ(int(ideal.image.at(0, 0)[3]), 0);
  EXPECT_EQ(int(ideal.image.at(0, 0)[0]), 0);
  EXPECT_EQ(ideal.covered[256 * 512 + 256], 1);
  // Symmetric about the vertical axis (the seed's light is on the axis of view).
  for (int row = 0; row < 512; row += 37)
    for (int col = 0; col < 256; col += 11) ASSERT_EQ(ideal.covered[size_t(row) * 512 + col], ideal.covered[size_t(row) * 512 + 511 - col]);
}

TEST(Ideal, WorldLightIsMovedIntoEyeSpace) {
  const LightingState s = lighting_state(lighting("specular").scene);
  EXPECT_EQ(s.lights[0].position, glm::dvec4(3, 4, 1, 1));
  EXPECT_TRUE(s.lights[0].enabled);
  EXPECT_TRUE(s.key.specular());
  const LightingState seed = lighting_state(lighting("seed").scene);
  EXPECT_EQ(seed.lights[0].position, glm::dvec4(0, 0, 1, 0));
  EXPECT_FALSE(seed.key.specular());
}

TEST(Ideal, RefusesWhatItDoesNotModel) {
  scene::Description d = lighting("seed", 64).scene;
  d.color_material.enabled = true;
  EXPECT_THROW(ray_cast_sphere(d), std::invalid_argument);
  d = lighting("seed", 64).scene;
  d.transforms.push_back(scene::translate(1, 0, 0));
  EXPECT_THROW(ray_cast_sphere(d), std::invalid_argument);
}

TEST(Metrics, RoundingFloorIsAboutARoundingError) {
  // Uniform rounding error: sqrt(1/12) = 0.289 steps; clamped channels (exactly 255) lower it.
  for (const char* n : {"seed", "specular"}) {
    const double f = rounding_floor(ray_cast_sphere(lighting(n, 256).scene));
    EXPECT_GT(f, 0.2) << n;
    EXPECT_LT(f, 0.2887 + 0.005) << n;
  }
}

TEST(Metrics, ShadingErrorSeparatesTheSilhouette) {
  const Ideal ideal = ray_cast_sphere(lighting("seed", 64).scene);
  image::Image pic = ideal.image;
  ShadingError e = shading_error(pic, ideal);
  EXPECT_EQ(e.rmse, 0);
  EXPECT_EQ(e.max_error, 0);
  EXPECT_EQ(e.silhouette, 0u);
  EXPECT_EQ(e.both, ideal.covered_count);
  // One channel off by 3 steps on one covered pixel; one covered pixel dropped; one extra pixel.
  pic.at(32, 32)[1] = uint8_t(pic.at(32, 32)[1] - 3);
  pic.at(33, 32)[3] = 0;
  pic.at(0, 0)[0] = 200, pic.at(0, 0)[3] = 255;
  e = shading_error(pic, ideal);
  EXPECT_EQ(e.max_error, 3);
  EXPECT_EQ(e.silhouette, 2u);
  EXPECT_EQ(e.both, ideal.covered_count - 1);
  EXPECT_NEAR(e.rmse, std::sqrt(9.0 / (3.0 * double(e.both))), 1e-12);
  EXPECT_NEAR(e.silhouette_share, 2.0 / double(ideal.covered_count + 1), 1e-12);
  const image::Image map = error_map(pic, ideal);
  EXPECT_EQ(int(map.at(0, 0)[0]), 255);  // magenta: only the picture
  EXPECT_EQ(int(map.at(0, 0)[1]), 0);
  EXPECT_EQ(int(map.at(33, 32)[1]), 255);  // cyan: only the ideal
  EXPECT_EQ(int(map.at(33, 32)[0]), 0);
  EXPECT_THROW(shading_error(image::Image(8, 8), ideal), std::invalid_argument);
}

}  // namespace
}  // namespace ffc::report
