// The built-in scenes as Descriptions draw what the seed programs drew (the GL calls kept in
// seed_reference.h): the same pixels and the same lighting state, for every shade model, normal
// source and camera the command line offers; and cube.toml / icosphere.toml are those scenes.
#include <gtest/gtest.h>

#include <array>
#include <vector>

#include "backends/backend.h"
#include "scene/file.h"
#include "scene/scene.h"
#include "scene_test_util.h"
#include "seed_reference.h"

namespace ffc {
namespace {

using scene_test::identical;

image::Image render_seed(const scene::Spec& spec, backends::Backend& b) {
  b.begin(spec.width, spec.height);
  scene_test::seed::draw(spec);
  return b.read();
}

std::vector<scene::Spec> variants() {
  std::vector<scene::Spec> out;
  for (const char* name : {"cube", "icosphere"})
    for (auto shade : {scene::Shade::Flat, scene::Shade::Smooth})
      for (auto normals : {mesh::NormalSource::Face, mesh::NormalSource::Average, mesh::NormalSource::Sphere}) {
        scene::Spec s = scene::builtin(name);
        s.shade = shade;
        s.normals = normals;
        s.width = 200, s.height = 150;  // an aspect other than 1
        out.push_back(s);
        if (s.name == "cube") {
          s.cam_angle_deg = 35, s.cam_height = 2.5;
        } else {
          s.depth = 1;
        }
        out.push_back(s);
      }
  out.push_back(scene::builtin("cube"));  // the defaults, full size
  out.push_back(scene::builtin("icosphere"));
  return out;
}

std::string label(const scene::Spec& s) {
  return s.name + " " + scene::to_string(s.shade) + " " + mesh::to_string(s.normals) + " " +
         std::to_string(s.width) + "x" + std::to_string(s.height) + " depth " + std::to_string(s.depth) +
         " cam " + std::to_string(s.cam_angle_deg) + "/" + std::to_string(s.cam_height);
}

TEST(BuiltinScenes, DescriptionsDrawTheSeedProgramsPixelForPixel) {
  auto mesa = backends::make("mesa");
  for (const scene::Spec& s : variants()) {
    SCOPED_TRACE(label(s));
    const image::Image seed = render_seed(s, *mesa);
    const image::Image described = scene::render(scene::describe(s), *mesa);
    EXPECT_TRUE(identical(seed, described));
    EXPECT_GT(scene_test::lit_share(described), 0.05);  // not a blank picture that trivially agrees
  }
}

// Everything of the lighting state GL holds after a draw (not GL_LIGHTING itself: the seed's cube
// switches it off after drawing, which the picture cannot see).
std::vector<float> lighting_state() {
  std::vector<float> s;
  auto get = [&](auto fn, auto... args) {
    std::array<float, 16> v{};
    fn(args..., v.data());
    s.insert(s.end(), v.begin(), v.end());
  };
  for (int i = 0; i < 8; ++i) {
    const GLenum l = GLenum(GL_LIGHT0 + i);
    s.push_back(glIsEnabled(l));
    for (GLenum p : {GL_AMBIENT, GL_DIFFUSE, GL_SPECULAR, GL_POSITION, GL_SPOT_DIRECTION, GL_SPOT_EXPONENT,
                     GL_SPOT_CUTOFF, GL_CONSTANT_ATTENUATION, GL_LINEAR_ATTENUATION, GL_QUADRATIC_ATTENUATION})
      get(glGetLightfv, l, p);
  }
  for (GLenum face : {GL_FRONT, GL_BACK})
    for (GLenum p : {GL_AMBIENT, GL_DIFFUSE, GL_SPECULAR, GL_EMISSION, GL_SHININESS}) get(glGetMaterialfv, face, p);
  for (GLenum p : {GL_LIGHT_MODEL_AMBIENT, GL_LIGHT_MODEL_TWO_SIDE, GL_LIGHT_MODEL_LOCAL_VIEWER,
                   GL_LIGHT_MODEL_COLOR_CONTROL, GL_SHADE_MODEL, GL_CULL_FACE_MODE, GL_FRONT_FACE,
                   GL_COLOR_MATERIAL_FACE, GL_COLOR_MATERIAL_PARAMETER, GL_MODELVIEW_MATRIX, GL_PROJECTION_MATRIX})
    get(glGetFloatv, p);
  for (GLenum cap : {GL_NORMALIZE, GL_RESCALE_NORMAL, GL_DEPTH_TEST, GL_COLOR_MATERIAL, GL_CULL_FACE})
    s.push_back(glIsEnabled(cap));
  return s;
}

TEST(BuiltinScenes, DescriptionsLeaveTheSeedProgramsLightingState) {
  auto mesa = backends::make("mesa");
  for (const scene::Spec& s : variants()) {
    SCOPED_TRACE(label(s));
    mesa->begin(s.width, s.height);
    scene_test::seed::draw(s);
    const std::vector<float> seed = lighting_state();
    mesa->begin(s.width, s.height);
    scene::draw(scene::describe(s));
    const std::vector<float> described = lighting_state();
    ASSERT_EQ(described.size(), seed.size());
    for (size_t i = 0; i < seed.size(); ++i) EXPECT_EQ(described[i], seed[i]) << "state value " << i;
    EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  }
}

TEST(BuiltinScenes, DescribeNamesWhatTheSeedsSet) {
  const scene::Description cube = scene::describe(scene::builtin("cube"));
  EXPECT_TRUE(cube.axes);
  EXPECT_TRUE(cube.rescale_normal);
  EXPECT_EQ(cube.lights[0].space, scene::Space::World);
  EXPECT_EQ(cube.lights[0].position, (scene::Vec4f{3, 4, 5, 1}));
  EXPECT_EQ(cube.back, scene::Material{});  // the seed sets GL_FRONT only
  const scene::Description ico = scene::describe(scene::builtin("icosphere"));
  EXPECT_EQ(ico.lights[0].space, scene::Space::Eye);
  EXPECT_EQ(ico.lights[0].position, scene::default_light(0).position);
  ASSERT_EQ(ico.objects.size(), 1u);
  EXPECT_EQ(ico.objects[0].depth, 3);
  EXPECT_THROW(scene::describe(scene::Spec{"teapot"}), std::invalid_argument);
}

class SceneFileOfBuiltin : public ::testing::TestWithParam<const char*> {};

TEST_P(SceneFileOfBuiltin, IsTheBuiltinSceneFieldByFieldAndPixelForPixel) {
  const std::string name = GetParam();
  scene::Description file = scene::load_file((scene_test::scenes_dir() / (name + ".toml")).string());
  const scene::Description builtin = scene::describe(scene::builtin(name));
  EXPECT_FALSE(file.source.empty());
  file.source.clear();  // the one field that says where it came from
  EXPECT_TRUE(file == builtin);
  auto mesa = backends::make("mesa");
  const image::Image a = scene::render(file, *mesa), b = scene::render(builtin, *mesa);
  EXPECT_TRUE(identical(a, b));
  EXPECT_GT(scene_test::lit_share(a), 0.05);
}

INSTANTIATE_TEST_SUITE_P(Scenes, SceneFileOfBuiltin, ::testing::Values("cube", "icosphere"));

}  // namespace
}  // namespace ffc
