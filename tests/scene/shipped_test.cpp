// The example scenes in scenes/: each parses, renders a lit picture through Mesa with no GL error,
// stays small, and shows what it is there to show (colours worked out by hand where the lighting
// equation is simple enough to).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <set>

#include "backends/backend.h"
#include "gl/dispatch.h"
#include "image/compare.h"
#include "scene/file.h"
#include "scene/scene.h"
#include "scene_test_util.h"

namespace ffc {
namespace {

using glm::dvec3;

std::string scene_path(const std::string& name) { return (scene_test::scenes_dir() / (name + ".toml")).string(); }

int unorm8(double c) { return int(std::lround(std::clamp(c, 0.0, 1.0) * 255)); }

void expect_pixel(const image::Image& img, int x, int y, std::array<int, 3> want, int tolerance) {
  const uint8_t* p = img.at(x, y);
  SCOPED_TRACE("pixel (" + std::to_string(x) + "," + std::to_string(y) + ")");
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(int(p[c]), want[size_t(c)], tolerance) << "channel " << c;
}

TEST(ShippedScenes, AreTheSevenExamples) {
  std::set<std::string> names;
  for (const auto& e : std::filesystem::directory_iterator(scene_test::scenes_dir()))
    if (e.path().extension() == ".toml") names.insert(e.path().stem().string());
  EXPECT_EQ(names, (std::set<std::string>{"color_material", "cube", "eight_lights", "icosphere", "material_grid",
                                          "spotlight", "two_sided"}));
}

class ShippedScene : public ::testing::TestWithParam<const char*> {};

TEST_P(ShippedScene, ParsesAndRendersALitPictureWithoutGlErrors) {
  const scene::Description d = scene::load_file(scene_path(GetParam()));
  auto mesa = backends::make("mesa");
  const image::Image img = scene::render(d, *mesa);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  EXPECT_EQ(img.width, d.width);
  EXPECT_EQ(img.height, d.height);
  EXPECT_GT(scene_test::lit_share(img, 40), 0.08);
  // Small: sides up to 512 (the cube reproduces the built-in scene's 640), meshes below 4000 triangles.
  EXPECT_LE(std::max(d.width, d.height), std::string(GetParam()) == "cube" ? 640 : 512);
  for (const auto& o : d.objects) EXPECT_LT(scene::build_mesh(o).n_faces(), 4000u) << scene::to_string(o);
}

INSTANTIATE_TEST_SUITE_P(Scenes, ShippedScene,
                         ::testing::Values("color_material", "cube", "eight_lights", "icosphere", "material_grid",
                                           "spotlight", "two_sided"));

// The Red Book's material.c at the sphere centres, where the normal is (0,0,1) and n.L = 2/sqrt(13)
// for the light at (0,3,2,0); global ambient 0.4; diffuse (0.1, 0.5, 0.8).
TEST(ShippedScenes, MaterialGridRowsAddAmbientAndTheLastColumnEmission) {
  const scene::Description d = scene::load_file(scene_path("material_grid"));
  ASSERT_EQ(d.objects.size(), 12u);
  auto mesa = backends::make("mesa");
  const image::Image img = scene::render(d, *mesa);
  const double ndotl = 2 / std::sqrt(13.0);
  auto at = [&](double x, double y) {  // the ortho camera maps [-6,6] x [-4.5,4.5] onto 512 x 384
    return std::pair<int, int>{int((x + 6) / 12 * 512), int((4.5 - y) / 9 * 384)};
  };
  auto want = [&](std::array<double, 3> ambient, std::array<double, 3> emission) {
    const double diffuse[3] = {0.1, 0.5, 0.8};
    std::array<int, 3> c{};
    for (int k = 0; k < 3; ++k) c[size_t(k)] = unorm8(emission[size_t(k)] + 0.4 * ambient[size_t(k)] + diffuse[k] * ndotl);
    return c;
  };
  const std::array<double, 3> none{0, 0, 0}, grey{0.7, 0.7, 0.7}, yellow{0.8, 0.8, 0.2}, glow{0.3, 0.2, 0.2};
  for (auto [row_y, ambient] : {std::pair{3.0, none}, {0.0, grey}, {-3.0, yellow}}) {
    const auto [x0, y0] = at(-3.75, row_y);
    expect_pixel(img, x0, y0, want(ambient, none), 3);
    const auto [x3, y3] = at(3.75, row_y);
    expect_pixel(img, x3, y3, want(ambient, glow), 3);
  }
  // The specular columns: the highlight (toward the half vector, above the centre) saturates.
  const auto [xs, ys] = at(-1.25, 3 + 0.3);
  EXPECT_GT(img.at(xs, ys)[0], 200);
}

// The spotlight, by hand at a floor vertex inside the cone and at one outside it.
TEST(ShippedScenes, SpotlightConeExponentAndAttenuationAsTheEquationSays) {
  const scene::Description d = scene::load_file(scene_path("spotlight"));
  const scene::Light& l = d.lights[0];
  ASSERT_TRUE(l.enabled);
  ASSERT_EQ(l.spot_cutoff, 25);
  auto mesa = backends::make("mesa");
  const image::Image img = scene::render(d, *mesa);
  const scene::Camera& c = d.camera;
  const glm::dmat4 mvp = glm::perspectiveRH_NO(glm::radians(c.fovy_deg), double(d.width) / d.height, c.z_near, c.z_far) *
                         glm::lookAtRH(dvec3(c.eye[0], c.eye[1], c.eye[2]), dvec3(c.center[0], c.center[1], c.center[2]),
                                       dvec3(c.up[0], c.up[1], c.up[2]));
  auto project = [&](dvec3 p) {
    const glm::dvec4 q = mvp * glm::dvec4(p, 1);
    return std::pair<int, int>{int(std::floor((q.x / q.w * 0.5 + 0.5) * d.width)),
                               d.height - 1 - int(std::floor((q.y / q.w * 0.5 + 0.5) * d.height))};
  };
  // Floor: normal +y, ambient and diffuse 0.8; the light has no ambient; global ambient 0.12.
  auto lit = [&](dvec3 p) {
    const dvec3 lp(l.position[0], l.position[1], l.position[2]);
    const dvec3 to_light = lp - p;
    const double dist = glm::length(to_light);
    const dvec3 L = to_light / dist;
    const double att = 1 / (l.constant_attenuation + l.linear_attenuation * dist + l.quadratic_attenuation * dist * dist);
    const dvec3 s = glm::normalize(dvec3(l.spot_direction[0], l.spot_direction[1], l.spot_direction[2]));
    const double cos_angle = glm::dot(-L, s);
    const double spot = cos_angle >= std::cos(glm::radians(double(l.spot_cutoff))) ? std::pow(cos_angle, l.spot_exponent) : 0;
    const dvec3 n(0, 1, 0);
    // Eye space differs from the world by a rotation here, which leaves dot products alone; the
    // viewer is at infinity, so the half vector uses the camera's backward axis.
    const dvec3 back = glm::normalize(dvec3(c.eye[0] - c.center[0], c.eye[1] - c.center[1], c.eye[2] - c.center[2]));
    const double spec = std::pow(std::max(glm::dot(n, glm::normalize(L + back)), 0.0), 30);
    std::array<int, 3> out{};
    for (int k = 0; k < 3; ++k)
      out[size_t(k)] = unorm8(0.12 * 0.8 + att * spot * (std::max(glm::dot(n, L), 0.0) * 0.8 * l.diffuse[size_t(k)] +
                                                           spec * 0.3 * l.specular[size_t(k)]));
    return out;
  };
  const dvec3 inside(0, 0, 0.6), outside(-1.8, 0, 1.6);  // grid vertices (the grid's step is 0.1)
  const auto want_in = lit(inside), want_out = lit(outside);
  EXPECT_GT(want_in[0], 90);
  EXPECT_EQ(want_out, (std::array<int, 3>{24, 24, 24}));  // the global ambient alone
  const auto [xi, yi] = project(inside);
  expect_pixel(img, xi, yi, want_in, 2);
  const auto [xo, yo] = project(outside);
  expect_pixel(img, xo, yo, want_out, 1);
}

TEST(ShippedScenes, TwoSidedBowlShowsTheBackMaterialInside) {
  scene::Description d = scene::load_file(scene_path("two_sided"));
  ASSERT_TRUE(d.light_model.two_sided);
  ASSERT_EQ(d.objects.size(), 1u);
  EXPECT_TRUE(d.objects[0].file_normals);
  auto mesa = backends::make("mesa");
  const image::Image two = scene::render(d, *mesa);
  const uint8_t* inside = two.at(256, 230);
  const uint8_t* outside = two.at(256, 380);
  EXPECT_GT(int(inside[0]), int(inside[2]) + 80);   // gold: the back material
  EXPECT_GT(int(outside[2]), int(outside[0]) + 80);  // blue: the front material
  // One-sided: the inside takes the front material with the normal pointing away from the light.
  d.light_model.two_sided = false;
  const image::Image one = scene::render(d, *mesa);
  EXPECT_GT(int(one.at(256, 230)[2]), int(one.at(256, 230)[0]));
  EXPECT_LT(int(one.at(256, 230)[1]), int(inside[1]) - 80);
  EXPECT_EQ(std::vector<uint8_t>(outside, outside + 4), std::vector<uint8_t>(one.at(256, 380), one.at(256, 380) + 4));
}

TEST(ShippedScenes, EightLightsEachLightsThePicture) {
  scene::Description d = scene::load_file(scene_path("eight_lights"));
  std::set<std::array<float, 4>> colours;
  for (const auto& l : d.lights) {
    EXPECT_TRUE(l.enabled);
    colours.insert(l.diffuse);
  }
  EXPECT_EQ(colours.size(), 8u);
  auto mesa = backends::make("mesa");
  const image::Image all = scene::render(d, *mesa);
  for (int i = 0; i < 8; ++i) {
    SCOPED_TRACE("light " + std::to_string(i));
    scene::Description without = d;
    without.lights[size_t(i)].enabled = false;
    EXPECT_GT(image::compare(all, scene::render(without, *mesa)).max_diff, 40);
  }
}

TEST(ShippedScenes, ColorMaterialTakesThePerVertexColours) {
  scene::Description d = scene::load_file(scene_path("color_material"));
  ASSERT_TRUE(d.color_material.enabled);
  EXPECT_EQ(d.objects[0].color.kind, scene::ColorSource::Kind::Normal);
  EXPECT_EQ(d.objects[1].color.kind, scene::ColorSource::Kind::Position);
  auto mesa = backends::make("mesa");
  const image::Image with = scene::render(d, *mesa);
  d.color_material.enabled = false;
  const image::Image without = scene::render(d, *mesa);
  EXPECT_GT(image::compare(with, without).differing_share, 0.3);
  // Without colour material the sphere is the material's grey: equal channels at its centre.
  const uint8_t* grey = without.at(140, 180);
  EXPECT_EQ(grey[0], grey[1]);
  EXPECT_EQ(grey[1], grey[2]);
  const uint8_t* coloured = with.at(140, 180);
  EXPECT_GT(std::max({coloured[0], coloured[1], coloured[2]}) - std::min({coloured[0], coloured[1], coloured[2]}), 30);
}

}  // namespace
}  // namespace ffc
