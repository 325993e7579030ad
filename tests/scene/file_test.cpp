// Scene files: the schema's values land in the Description, and every mistake is a FileError
// pointing at the file, line and column, with nothing returned.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "scene/file.h"
#include "scene_test_util.h"

namespace ffc {
namespace {

using scene::FileError;
using scene_test::write_file;

scene::Description parse(const std::string& text) { return scene::parse_scene(text, "test.toml"); }

TEST(SceneFile, ReadsEveryPartOfTheSchema) {
  const scene::Description d = parse(R"(
name = "all"
size = [320, 200]
background = [0.1, 0.2, 0.3]
shade = "flat"
lighting = false
depth_test = false
normalize = true
rescale_normal = true
cull_face = "front_and_back"
front_face = "cw"
axes = true
transforms = [{ rotate = [30, 0, 1, 0] }, { translate = [1, 2, 3] }, { scale = [2, 2, 2] }]

[camera]
projection = "frustum"
left = -2
right = 2
bottom = -1
top = 1
near = 2
far = 20
eye = [1, 2, 3]
center = [0, 1, 0]
up = [0, 0, 1]

[light_model]
ambient = [0.3, 0.3, 0.3, 1]
local_viewer = true
two_sided = true
separate_specular = true

[material]
ambient_and_diffuse = [0.5, 0.4, 0.3]
specular = [1, 1, 1]
shininess = 64
[material.back]
diffuse = [0, 1, 0]
emission = [0.1, 0, 0, 1]

[color_material]
face = "back"
mode = "specular"

[[light]]
index = 3
position = [1, 2, 3, 1]
space = "world"
diffuse = [1, 0, 0]
spot_direction = [0, -1, 0]
spot_exponent = 8
spot_cutoff = 30
constant_attenuation = 0.5
linear_attenuation = 0.25
quadratic_attenuation = 0.125

[[light]]
enabled = false

[[mesh]]
source = "icosphere:2"
normals = "average"
draw = "immediate"
color = "position"
transforms = [{ translate = [0, 1, 0] }]
[mesh.material.front]
shininess = 5

[[mesh]]
source = "cube"
color = [1, 0.5, 0]
)");
  EXPECT_EQ(d.name, "all");
  EXPECT_EQ(d.source, "test.toml");
  EXPECT_EQ(d.width, 320);
  EXPECT_EQ(d.height, 200);
  EXPECT_EQ(d.background, (scene::Color{0.1f, 0.2f, 0.3f, 1}));
  EXPECT_EQ(d.shade, scene::Shade::Flat);
  EXPECT_FALSE(d.lighting);
  EXPECT_FALSE(d.depth_test);
  EXPECT_TRUE(d.normalize && d.rescale_normal && d.cull_face && d.front_face_cw && d.axes);
  EXPECT_EQ(d.cull_mode, scene::Face::FrontAndBack);
  ASSERT_EQ(d.transforms.size(), 3u);
  EXPECT_EQ(d.transforms[0], scene::rotate(30, 0, 1, 0));
  EXPECT_EQ(d.transforms[1], scene::translate(1, 2, 3));
  EXPECT_EQ(d.transforms[2], scene::scale(2, 2, 2));
  EXPECT_EQ(d.camera.projection, scene::Camera::Projection::Frustum);
  EXPECT_EQ(d.camera.left, -2);
  EXPECT_EQ(d.camera.z_near, 2);
  EXPECT_EQ(d.camera.z_far, 20);
  EXPECT_EQ(d.camera.eye, (scene::Vec3{1, 2, 3}));
  EXPECT_EQ(d.camera.up, (scene::Vec3{0, 0, 1}));
  EXPECT_TRUE(d.light_model.local_viewer && d.light_model.two_sided && d.light_model.separate_specular);
  EXPECT_EQ(d.front.ambient, (scene::Color{0.5f, 0.4f, 0.3f, 1}));
  EXPECT_EQ(d.front.diffuse, d.front.ambient);
  EXPECT_EQ(d.front.shininess, 64);
  EXPECT_EQ(d.back.ambient, d.front.ambient);  // [material] keys are both faces'
  EXPECT_EQ(d.back.diffuse, (scene::Color{0, 1, 0, 1}));
  EXPECT_EQ(d.back.emission, (scene::Color{0.1f, 0, 0, 1}));
  EXPECT_EQ(d.front.emission, scene::Material{}.emission);
  EXPECT_TRUE(d.color_material.enabled);  // the table's presence enables it
  EXPECT_EQ(d.color_material.face, scene::Face::Back);
  EXPECT_EQ(d.color_material.mode, scene::ColorMode::Specular);
  const scene::Light& l3 = d.lights[3];
  EXPECT_TRUE(l3.enabled);
  EXPECT_EQ(l3.space, scene::Space::World);
  EXPECT_EQ(l3.position, (scene::Vec4f{1, 2, 3, 1}));
  EXPECT_EQ(l3.diffuse, (scene::Color{1, 0, 0, 1}));
  EXPECT_EQ(l3.specular, scene::default_light(3).specular);  // black: only light 0 is white
  EXPECT_EQ(l3.spot_cutoff, 30);
  EXPECT_EQ(l3.spot_exponent, 8);
  EXPECT_EQ(l3.quadratic_attenuation, 0.125f);
  // The second [[light]] has no index: its place in the list, 1.
  EXPECT_FALSE(d.lights[1].enabled);
  EXPECT_FALSE(d.lights[0].enabled);
  EXPECT_EQ(d.lights[0], scene::default_light(0));
  ASSERT_EQ(d.objects.size(), 2u);
  const scene::Object& a = d.objects[0];
  EXPECT_EQ(a.kind, scene::Object::Kind::Icosphere);
  EXPECT_EQ(a.depth, 2);
  EXPECT_EQ(a.normals, mesh::NormalSource::Average);
  EXPECT_FALSE(a.file_normals);
  EXPECT_EQ(a.draw, scene::DrawPath::Immediate);
  EXPECT_EQ(a.color.kind, scene::ColorSource::Kind::Position);
  ASSERT_TRUE(a.front && a.back);
  EXPECT_EQ(a.front->shininess, 5);  // the scene's material with this key on top
  EXPECT_EQ(a.front->ambient, d.front.ambient);
  EXPECT_EQ(*a.back, d.back);
  const scene::Object& b = d.objects[1];
  EXPECT_EQ(b.kind, scene::Object::Kind::Cube);
  EXPECT_EQ(b.normals, mesh::NormalSource::Face);
  EXPECT_EQ(b.draw, scene::DrawPath::Auto);
  EXPECT_EQ(b.color.kind, scene::ColorSource::Kind::Constant);
  EXPECT_EQ(b.color.constant, (scene::Color{1, 0.5f, 0, 1}));
  EXPECT_FALSE(b.front || b.back);
}

TEST(SceneFile, DefaultsAreGlsExceptLightingDepthTestAndCamera) {
  const scene::Description d = parse("[[mesh]]\nsource = \"cube\"\n");
  scene::Description want;
  want.name = "test";
  want.source = "test.toml";
  scene::Object cube;
  want.objects.push_back(cube);
  EXPECT_TRUE(d == want);
  EXPECT_TRUE(d.lighting && d.depth_test);
  EXPECT_EQ(d.width, 512);
  EXPECT_EQ(d.objects[0].normals, mesh::NormalSource::Face);
  EXPECT_FALSE(d.objects[0].file_normals);
  const scene::Description ico = parse("[[mesh]]\nsource = \"icosphere\"\n");
  EXPECT_EQ(ico.objects[0].depth, 3);
}

TEST(SceneFile, MeshPathsAreRelativeToTheSceneFile) {
  write_file("rel/meshes/tri.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  const auto scene = write_file("rel/s.toml", "[[mesh]]\nsource = \"meshes/tri.obj\"\n");
  const scene::Description d = scene::load_file(scene.string());
  ASSERT_EQ(d.objects.size(), 1u);
  EXPECT_EQ(d.objects[0].kind, scene::Object::Kind::File);
  EXPECT_EQ(d.objects[0].path, (scene.parent_path() / "meshes/tri.obj").string());
  ASSERT_TRUE(d.objects[0].file);
  EXPECT_EQ(d.objects[0].file->mesh.n_faces(), 1u);
}

// One mistake per file; each must be reported at its line and column with this message.
struct Bad {
  const char* name;
  std::string text;
  int line, column;
  std::string message;  // a part of the message
};

const std::string mesh = "\n[[mesh]]\nsource = \"cube\"\n";

std::string nine_lights() {
  std::string s;
  for (int i = 0; i < 9; ++i) s += "[[light]]\n";
  return s;
}

std::vector<Bad> bad_files() {
  return {
      {"toml_syntax", "shade = smooth" + mesh, 1, 9, "TOML syntax"},
      {"toml_duplicate_key", "shade = \"flat\"\nshade = \"smooth\"" + mesh, 2, 9, "TOML syntax"},
      {"unknown_top_key", "shadow = true" + mesh, 1, 1, "unknown key 'shadow' in the scene file"},
      {"unknown_material_key", "[material]\nshinyness = 5" + mesh, 2, 1, "unknown key 'shinyness' in [material]"},
      {"unknown_light_key", "[[light]]\nposition = [0, 0, 1, 0]\nspotcutoff = 20" + mesh, 3, 1,
       "unknown key 'spotcutoff' in [[light]] 0"},
      {"unknown_mesh_key", "[[mesh]]\nsource = \"cube\"\nnormal = \"face\"\n", 3, 1,
       "unknown key 'normal' in [[mesh]] 0"},
      {"unknown_camera_key", "[camera]\nfov = 45" + mesh, 2, 1, "unknown key 'fov' in [camera]"},
      {"size_not_array", "size = \"big\"" + mesh, 1, 8, "size: expected an array, got string"},
      {"size_float", "size = [512.0, 512]" + mesh, 1, 9, "size[0] (width): expected an integer"},
      {"size_zero", "size = [0, 10]" + mesh, 1, 9, "size[0] (width): 0 is outside 1..16384"},
      {"size_huge", "size = [10, 20000]" + mesh, 1, 13, "size[1] (height): 20000 is outside 1..16384"},
      {"size_three", "size = [1, 2, 3]" + mesh, 1, 8, "expected 2 elements, got 3"},
      {"shininess_high", "[material]\nshininess = 200" + mesh, 2, 13, "material.shininess: 200 is outside 0..128"},
      {"shininess_string", "[material]\nshininess = \"high\"" + mesh, 2, 13, "expected a number, got string"},
      {"shininess_nan", "[material]\nshininess = nan" + mesh, 2, 13, "is not a finite number"},
      {"spot_exponent", "[[light]]\nspot_exponent = 129" + mesh, 2, 17, "light[0].spot_exponent: 129 is outside 0..128"},
      {"spot_cutoff_95", "[[light]]\nspot_cutoff = 95" + mesh, 2, 15, "light[0].spot_cutoff: 95 is outside GL's range"},
      {"spot_cutoff_neg", "[[light]]\nspot_cutoff = -1" + mesh, 2, 15, "light[0].spot_cutoff: -1 is outside GL's range"},
      {"attenuation_neg", "[[light]]\nlinear_attenuation = -0.5" + mesh, 2, 22, "light[0].linear_attenuation: -0.5 is negative"},
      {"light_index_8", "[[light]]\nindex = 8" + mesh, 2, 9, "light[0].index: 8 is outside 0..7"},
      {"light_index_twice", "[[light]]\nindex = 2\n[[light]]\nindex = 2" + mesh, 4, 9,
       "light 2 is already described at line 2"},
      {"light_ninth", nine_lights() + mesh, 9, 1, "light[8]: GL has 8 lights"},
      {"light_not_array", "[light]\nposition = [0, 0, 1, 0]" + mesh, 1, 1, "light: expected an array of tables ([[light]])"},
      {"position_three", "[[light]]\nposition = [0, 0, 1]" + mesh, 2, 12, "expected 4 elements, got 3"},
      {"position_inf", "[[light]]\nposition = [0, inf, 1, 0]" + mesh, 2, 16, "light[0].position[1]: inf is not a finite number"},
      {"space_unknown", "[[light]]\nspace = \"camera\"" + mesh, 2, 9, "unknown light space 'camera' (eye or world)"},
      {"shade_unknown", "shade = \"phong\"" + mesh, 1, 9, "shade: unknown shade model 'phong' (flat or smooth)"},
      {"cull_unknown", "cull_face = \"sideways\"" + mesh, 1, 13, "unknown cull face 'sideways'"},
      {"front_face_unknown", "front_face = \"left\"" + mesh, 1, 14, "unknown winding 'left' (ccw or cw)"},
      {"color_material_mode", "[color_material]\nmode = \"glow\"" + mesh, 2, 8, "unknown colour material mode 'glow'"},
      {"projection_unknown", "[camera]\nprojection = \"fisheye\"" + mesh, 2, 14, "unknown projection 'fisheye'"},
      {"fovy_180", "[camera]\nfovy = 180" + mesh, 2, 8, "camera.fovy: 180 is not between 0 and 180"},
      {"near_zero", "[camera]\nnear = 0" + mesh, 2, 8, "must satisfy 0 < near < far"},
      {"ortho_fovy", "[camera]\nprojection = \"ortho\"\nfovy = 30" + mesh, 3, 8, "camera.fovy applies to the perspective projection only"},
      {"eye_is_center", "[camera]\neye = [0, 0, 0]" + mesh, 2, 7, "eye and center are the same point"},
      {"up_along_sight", "[camera]\nup = [0, 0, 2]" + mesh, 2, 6, "up is zero or along the line of sight"},
      {"background_high", "background = [0, 0, 1.5]" + mesh, 1, 21, "background[2]: 1.5 is outside 0..1"},
      {"color_five", "[material]\ndiffuse = [1, 1, 1, 1, 1]" + mesh, 2, 11, "expected 3 or 4 elements, got 5"},
      {"color_string_element", "[material]\ndiffuse = [1, \"one\", 1]" + mesh, 2, 15, "material.diffuse[1]: expected a number"},
      {"ambient_and_diffuse_twice", "[material]\nambient = [1, 0, 0]\nambient_and_diffuse = [0, 1, 0]" + mesh, 3, 23,
       "ambient_and_diffuse and ambient both given"},
      {"transform_unknown", "transforms = [{ spin = [1, 0, 0] }]" + mesh, 1, 17, "unknown key 'spin' in transforms[0]"},
      {"transform_two_keys", "transforms = [{ scale = [1, 1, 1], translate = [0, 0, 1] }]" + mesh, 1, 15,
       "expected exactly one of translate, rotate or scale"},
      {"rotate_zero_axis", "transforms = [{ rotate = [30, 0, 0, 0] }]" + mesh, 1, 26, "the axis [0, 0, 0] has no direction"},
      {"no_mesh", "shade = \"flat\"\n", 1, 1, "a scene needs at least one [[mesh]]"},
      {"mesh_without_source", "[[mesh]]\nnormals = \"face\"\n", 1, 1, "mesh[0]: source is required"},
      {"icosphere_depth_13", "[[mesh]]\nsource = \"icosphere:13\"\n", 2, 10, "icosphere depth 13 is beyond the limit of 10"},
      // Depths 11 and 12 passed the check once and then ran out of memory half a minute later.
      {"icosphere_depth_11", "[[mesh]]\nsource = \"icosphere:11\"\n", 2, 10,
       "mesh[0].source: icosphere depth 11 is beyond the limit of 10: each level quadruples the triangles and the memory"},
      {"icosphere_depth_word", "[[mesh]]\nsource = \"icosphere:three\"\n", 2, 10, "the icosphere depth must be a number 0..10"},
      {"normals_unknown", "[[mesh]]\nsource = \"cube\"\nnormals = \"vertex\"\n", 3, 11,
       "mesh[0].normals: unknown normal source 'vertex' ("},
      {"normals_file_builtin", "[[mesh]]\nsource = \"cube\"\nnormals = \"file\"\n", 3, 11, "'cube' is built in"},
      {"draw_unknown", "[[mesh]]\nsource = \"cube\"\ndraw = \"strip\"\n", 3, 8, "unknown draw path 'strip'"},
      {"color_unknown", "[[mesh]]\nsource = \"cube\"\ncolor = \"rainbow\"\n", 3, 9, "unknown colour source 'rainbow'"},
      {"mesh_material_key", "[[mesh]]\nsource = \"cube\"\nmaterial = { shiny = 1 }\n", 3, 14,
       "unknown key 'shiny' in [mesh[0].material]"},
      {"mesh_file_missing", "[[mesh]]\nsource = \"meshes/nope.obj\"\n", 2, 10, "meshes/nope.obj' does not exist"},
      {"mesh_file_corrupt", "[[mesh]]\nsource = \"corrupt.off\"\n", 2, 10, "corrupt.off' is corrupt"},
      {"mesh_file_format", "[[mesh]]\nsource = \"model.3ds\"\n", 2, 10, "unsupported format '.3ds'"},
      {"mesh_file_without_normals", "[[mesh]]\nsource = \"plain.obj\"\nnormals = \"file\"\n", 3, 11,
       "plain.obj' has none"},
  };
}

void PrintTo(const Bad& b, std::ostream* os) { *os << b.name; }

class BadSceneFile : public ::testing::TestWithParam<Bad> {};

TEST_P(BadSceneFile, IsAFileErrorAtItsLineAndColumn) {
  const Bad& b = GetParam();
  write_file("bad/corrupt.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n");
  write_file("bad/model.3ds", "not a mesh");
  write_file("bad/plain.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  const std::string path = write_file(std::string("bad/") + b.name + ".toml", b.text).string();
  scene::Description kept;
  kept.name = "kept";
  try {
    kept = scene::load_file(path);
    FAIL() << "no error for " << b.name;
  } catch (const FileError& e) {
    EXPECT_EQ(e.path(), path);
    EXPECT_EQ(e.line(), b.line) << e.what();
    EXPECT_EQ(e.column(), b.column) << e.what();
    EXPECT_NE(e.message().find(b.message), std::string::npos) << e.what();
    const std::string prefix = path + ":" + std::to_string(b.line) + ":" + std::to_string(b.column) + ": ";
    EXPECT_EQ(std::string(e.what()).rfind(prefix, 0), 0u) << e.what();
  }
  // Nothing half-applied: the variable still holds what it held.
  EXPECT_EQ(kept.name, "kept");
  EXPECT_TRUE(kept.objects.empty());
}

INSTANTIATE_TEST_SUITE_P(Table, BadSceneFile, ::testing::ValuesIn(bad_files()),
                         [](const ::testing::TestParamInfo<Bad>& i) { return std::string(i.param.name); });

TEST(SceneFile, AMissingOrUnreadableSceneFileHasNoLine) {
  try {
    scene::load_file((scene_test::temp_dir() / "absent.toml").string());
    FAIL();
  } catch (const FileError& e) {
    EXPECT_EQ(e.line(), 0);
    EXPECT_NE(std::string(e.what()).find("absent.toml: the scene file does not exist"), std::string::npos) << e.what();
  }
  EXPECT_THROW(scene::load_file(scene_test::temp_dir().string()), FileError);  // a directory
}

// What is not a regular file is refused before it is opened: a FIFO blocked the open until a
// writer came, and a link to /dev/zero read until memory ran out. Each runs in a child (a death
// test's fork) under an alarm, so a hang or a crash fails the case instead of the test binary.
void expect_refused_quickly(const std::string& path, const std::string& message) {
  EXPECT_EXIT(
      {
        alarm(10);
        try {
          scene::load_file(path);
        } catch (const FileError& e) {
          const std::string what = e.what();
          std::exit(e.line() == 0 && what.rfind(path + ": ", 0) == 0 && what.find(message) != std::string::npos ? 0 : 3);
        }
        std::exit(4);
      },
      ::testing::ExitedWithCode(0), "");
}

TEST(SceneFileDeathTest, AFifoIsRefusedNotWaitedOn) {
  const std::string fifo = (scene_test::temp_dir() / "fifo.toml").string();
  ::unlink(fifo.c_str());
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  expect_refused_quickly(fifo, "is not a regular file");
  ::unlink(fifo.c_str());
}

TEST(SceneFileDeathTest, ALinkToDevZeroIsRefusedNotReadForever) {
  const std::filesystem::path link = scene_test::temp_dir() / "zero.toml";
  std::filesystem::remove(link);
  std::filesystem::create_symlink("/dev/zero", link);
  expect_refused_quickly(link.string(), "is not a regular file");
  std::filesystem::remove(link);
}

TEST(SceneFile, AFileOverTheSizeLimitIsRefusedWithItsSize) {
  const std::filesystem::path big = scene_test::temp_dir() / "big.toml";
  {
    std::ofstream out(big, std::ios::binary);
    const std::string line = "# a comment that makes the file large, and nothing else\n";
    for (uintmax_t n = 0; n <= scene::kMaxSceneFileBytes; n += line.size()) out << line;
  }
  try {
    scene::load_file(big.string());
    FAIL();
  } catch (const FileError& e) {
    EXPECT_EQ(e.line(), 0);
    EXPECT_NE(std::string(e.what()).find("over the limit of 4194304"), std::string::npos) << e.what();
  }
  std::filesystem::remove(big);
}

TEST(SceneFile, ErrorsAreFileErrorsAndRuntimeErrors) {
  try {
    parse("[[mesh]]\nsource = 3\n");
    FAIL();
  } catch (const std::runtime_error& e) {  // FileError is one
    EXPECT_STREQ(e.what(), "test.toml:2:10: mesh[0].source: expected a string, got integer");
  }
}

TEST(SceneFile, IsSceneFileMeansEndsInToml) {
  EXPECT_TRUE(scene::is_scene_file("scenes/spotlight.toml"));
  EXPECT_TRUE(scene::is_scene_file("x.toml"));
  EXPECT_FALSE(scene::is_scene_file("cube"));
  EXPECT_FALSE(scene::is_scene_file(".toml"));
  EXPECT_FALSE(scene::is_scene_file("scene.tom"));
}

}  // namespace
}  // namespace ffc
