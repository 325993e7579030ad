// What draw() does with a Description, checked in Mesa's pixels: draw paths, per-mesh materials,
// colour material, light spaces, transform order, culling, background; and that meshes are built
// before any GL call.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <set>

#include "backends/backend.h"
#include "check/feedback.h"
#include "gl/dispatch.h"
#include "scene/file.h"
#include "scene/scene.h"
#include "scene_test_util.h"

namespace ffc {
namespace {

using scene_test::identical;

class Draw : public ::testing::Test {
 protected:
  std::unique_ptr<backends::Backend> mesa = backends::make("mesa");
  image::Image render(const std::string& toml) { return scene::render(scene::parse_scene(toml, "t.toml"), *mesa); }
  static std::array<int, 3> px(const image::Image& img, int x, int y) {
    const uint8_t* p = img.at(x, y);
    return {p[0], p[1], p[2]};
  }
  static void expect_near(std::array<int, 3> got, std::array<int, 3> want, int tolerance) {
    for (size_t c = 0; c < 3; ++c) EXPECT_NEAR(got[c], want[c], tolerance) << "channel " << c;
  }
};

TEST_F(Draw, ArraysElementsAndImmediateModeGiveTheSamePicture) {
  const auto bowl = (scene_test::scenes_dir() / "meshes/hemisphere.obj").string();
  scene::Description d = scene::parse_scene(R"(
size = [160, 120]
[light_model]
two_sided = true
[color_material]
[[light]]
position = [1, 2, 3, 0]
[[mesh]]
source = "cube"
normals = "face"
color = "position"
transforms = [{ translate = [-1.5, 0, 0] }, { scale = [0.5, 0.5, 0.5] }]
[[mesh]]
source = "icosphere:2"
normals = "sphere"
color = "normal"
transforms = [{ scale = [0.6, 0.6, 0.6] }]
[[mesh]]
source = ")" + bowl + R"("
normals = "file"
color = [0.9, 0.5, 0.1]
transforms = [{ translate = [1.5, 0.3, 0] }, { rotate = [-40, 1, 0, 0] }, { scale = [0.6, 0.6, 0.6] }]
)",
                                            "t.toml");
  const image::Image reference = scene::render(d, *mesa);  // auto: arrays for face normals, else elements
  EXPECT_GT(scene_test::lit_share(reference), 0.1);
  for (auto path : {scene::DrawPath::Arrays, scene::DrawPath::Elements, scene::DrawPath::Immediate}) {
    SCOPED_TRACE(scene::to_string(path));
    for (auto& o : d.objects) o.draw = path;
    EXPECT_TRUE(identical(scene::render(d, *mesa), reference));
    EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  }
}

// Three cubes seen head-on by light 0 (directional, from the viewer): the face toward the camera
// has n.L = 1, so its colour is 0.2 * ambient + diffuse of its material, clamped.
constexpr const char* three_cubes = R"(
size = [300, 100]
[camera]
projection = "ortho"
left = -4.5
right = 4.5
bottom = -1.5
top = 1.5
[[light]]
[material]
ambient_and_diffuse = [0, 1, 0]
[[mesh]]
source = "cube"
transforms = [{ translate = [-3, 0, 0] }]
material = { ambient_and_diffuse = [1, 0, 0] }
[[mesh]]
source = "cube"
[[mesh]]
source = "cube"
transforms = [{ translate = [3, 0, 0] }]
material = { ambient_and_diffuse = [0, 0, 1] }
)";

TEST_F(Draw, AMeshsMaterialIsItsOwnAndTheNextMeshGetsTheScenesBack) {
  const image::Image img = render(three_cubes);
  EXPECT_EQ(px(img, 50, 50), (std::array<int, 3>{255, 0, 0}));
  EXPECT_EQ(px(img, 150, 50), (std::array<int, 3>{0, 255, 0}));  // the scene's material again
  EXPECT_EQ(px(img, 250, 50), (std::array<int, 3>{0, 0, 255}));
  EXPECT_EQ(px(img, 100, 50), (std::array<int, 3>{0, 0, 0}));  // between the cubes
}

TEST_F(Draw, MaterialKeysApplyToBothFacesAndFaceTablesToOne) {
  // Looking straight down into the bowl with two-sided lighting and a light from the viewer: the
  // inside is back faces, lit with the back material and the normal reversed (n.L = 1 at the
  // bottom; the pixel centre is not quite the pole, hence a step of tolerance).
  const std::string scene = R"(
size = [64, 64]
[camera]
eye = [0, 5, 0]
center = [0, 0, 0]
up = [0, 0, -1]
[light_model]
two_sided = true
[[light]]
[[mesh]]
source = ")" + (scene_test::scenes_dir() / "meshes/hemisphere.obj").string() + R"("
normals = "file"
)";
  // Both faces red: 0.2 * 0.2 ambient + 1 diffuse, clamped.
  expect_near(px(render(scene + "[material]\ndiffuse = [1, 0, 0]\n"), 32, 32), {255, 10, 10}, 1);
  // Front only: the inside keeps the default back material, 0.04 + 0.8 grey.
  expect_near(px(render(scene + "[material.front]\ndiffuse = [1, 0, 0]\n"), 32, 32), {214, 214, 214}, 1);
  // Back only.
  expect_near(px(render(scene + "[material.back]\ndiffuse = [0, 0, 1]\n"), 32, 32), {10, 10, 255}, 1);
}

TEST_F(Draw, ColorMaterialMakesTheDiffuseAndAmbientFollowGlColor) {
  const std::string scene = R"(
size = [64, 64]
[camera]
projection = "ortho"
[[light]]
[[mesh]]
source = "cube"
color = [1, 0, 0]
)";
  // Default material: 0.2 * 0.2 + 0.8 = 0.84 of white; glColor ignored.
  EXPECT_EQ(px(render(scene), 32, 32), (std::array<int, 3>{214, 214, 214}));
  // GL_COLOR_MATERIAL, ambient and diffuse: 0.2 * 1 + 1 of red.
  EXPECT_EQ(px(render(scene + "[color_material]\n"), 32, 32), (std::array<int, 3>{255, 0, 0}));
  // Tracking the diffuse only: the ambient stays 0.2 grey, 0.04 of white.
  EXPECT_EQ(px(render(scene + "[color_material]\nmode = \"diffuse\"\n"), 32, 32), (std::array<int, 3>{255, 10, 10}));
  // Tracking the back faces only: the front is the default material.
  EXPECT_EQ(px(render(scene + "[color_material]\nface = \"back\"\n"), 32, 32), (std::array<int, 3>{214, 214, 214}));
}

TEST_F(Draw, EyeSpaceLightsMoveWithTheCameraWorldSpaceLightsDoNot) {
  // The camera looks at the cube's +x face from +x. Light (0,0,1,0) in eye space shines from the
  // camera: n.L = 1, 0.04 + 0.8 of white. In world space it shines along -z: n.L = 0, only 0.04.
  const std::string scene = R"(
size = [64, 64]
[camera]
projection = "ortho"
eye = [5, 0, 0]
[[light]]
position = [0, 0, 1, 0]
space = "%s"
[[mesh]]
source = "cube"
)";
  auto with = [&](const char* space) {
    std::string s = scene;
    s.replace(s.find("%s"), 2, space);
    return render(s);
  };
  EXPECT_EQ(px(with("eye"), 32, 32), (std::array<int, 3>{214, 214, 214}));
  EXPECT_EQ(px(with("world"), 32, 32), (std::array<int, 3>{10, 10, 10}));
}

TEST_F(Draw, SceneTransformsComeBeforeEachMeshsOwn) {
  // translate 2 then scale 0.5: the cube spans x 1.5..2.5 (the other order would give 0.5..1.5).
  // GL_NORMALIZE undoes the scale's effect on the normals (without it they would be twice unit
  // length and the face saturate).
  const image::Image img = render(R"(
size = [200, 50]
normalize = true
transforms = [{ translate = [2, 0, 0] }]
[camera]
projection = "ortho"
left = -4
right = 4
bottom = -1
top = 1
[[light]]
[[mesh]]
source = "cube"
transforms = [{ scale = [0.5, 0.5, 0.5] }]
)");
  EXPECT_EQ(px(img, 150, 25)[0], 214);  // x = 2
  EXPECT_EQ(px(img, 125, 25)[0], 0);    // x = 1
}

TEST_F(Draw, BackgroundAndCulling) {
  const std::string scene = R"(
size = [64, 64]
background = [0.2, 0.4, 0.6, 1]
[[light]]
[[mesh]]
source = "icosphere:1"
)";
  const image::Image plain = render(scene);
  EXPECT_EQ(px(plain, 0, 0), (std::array<int, 3>{51, 102, 153}));
  EXPECT_NE(px(plain, 32, 32), px(plain, 0, 0));
  // Back faces culled: nothing changes for a closed mesh seen from outside.
  EXPECT_TRUE(identical(render("cull_face = \"back\"\n" + scene), plain));
  // Both culled: only the background is left.
  const image::Image none = render("cull_face = \"front_and_back\"\n" + scene);
  EXPECT_EQ(px(none, 32, 32), px(none, 0, 0));
  // With clockwise front faces the outside is culled as back faces: the inside shows, lit as if it
  // faced away (one-sided lighting uses the front material and the normal as sent).
  EXPECT_FALSE(identical(render("cull_face = \"back\"\nfront_face = \"cw\"\n" + scene), plain));
}

// Counts begin() calls: a Description whose mesh cannot be built must fail before any.
class CountingBackend : public backends::Backend {
 public:
  std::unique_ptr<backends::Backend> mesa = backends::make("mesa");
  int begins = 0;
  std::string name() const override { return "counting"; }
  void begin(int w, int h) override { ++begins, mesa->begin(w, h); }
  void resume() override { mesa->resume(); }
  void read_into(image::Image& out) override { mesa->read_into(out); }
};

TEST(DrawOrder, MeshesAreBuiltBeforeTheFirstGlCall) {
  scene::Description d;
  d.lights[0].enabled = true;
  scene::Object o;
  o.kind = scene::Object::Kind::File;
  o.path = (scene_test::temp_dir() / "gone.obj").string();
  d.objects.push_back(o);
  CountingBackend b;
  try {
    scene::render(d, b);
    FAIL();
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("gone.obj' does not exist"), std::string::npos) << e.what();
  }
  EXPECT_EQ(b.begins, 0);
  // A file mesh not loaded yet is read when drawn.
  d.objects[0].path = (scene_test::scenes_dir() / "meshes/hemisphere.obj").string();
  EXPECT_GT(scene_test::lit_share(scene::render(d, b)), 0.01);
  EXPECT_EQ(b.begins, 1);
  // File normals asked of a mesh without them: an error, before GL.
  d.objects[0].path = (scene_test::scenes_dir() / "meshes/plane.off").string();
  d.objects[0].file_normals = true;
  EXPECT_THROW(scene::render(d, b), std::runtime_error);
  EXPECT_EQ(b.begins, 1);
}

TEST(DrawOrder, VertexColoursFollowTheirSource) {
  scene::Object o;
  o.kind = scene::Object::Kind::Cube;
  o.normals = mesh::NormalSource::Face;
  const mesh::Layout l = scene::layout(o);
  EXPECT_TRUE(scene::vertex_colors(o, l).empty());  // None
  o.color.kind = scene::ColorSource::Kind::Normal;
  const auto n = scene::vertex_colors(o, l);
  ASSERT_EQ(n.size(), l.vertices.size());
  for (size_t i = 0; i < n.size(); ++i)
    for (int k = 0; k < 3; ++k) EXPECT_FLOAT_EQ(n[i][k], float((l.vertices[i].normal[k] + 1) / 2));
  o.color.kind = scene::ColorSource::Kind::Position;  // the cube spans -1..1: (p + 1) / 2
  const auto p = scene::vertex_colors(o, l);
  for (size_t i = 0; i < p.size(); ++i)
    for (int k = 0; k < 3; ++k) EXPECT_FLOAT_EQ(p[i][k], float((l.vertices[i].position[k] + 1) / 2));
}

// Per-corner OBJ normals reach GL: a hard-edged cube (every face's corners name its own normal),
// drawn unlit with each vertex coloured by its normal, feeds back one colour per triangle, the
// colour of an axis direction. With one normal per vertex (the last face's, as OpenMesh keeps
// them) the corners of most triangles had the colours of other faces.
TEST(DrawOrder, ObjPerCornerNormalsAreTheFedBackOnes) {
  const auto obj = scene_test::write_file("m/hard_cube_draw.obj",
      "v -1 -1 -1\nv 1 -1 -1\nv 1 1 -1\nv -1 1 -1\nv -1 -1 1\nv 1 -1 1\nv 1 1 1\nv -1 1 1\n"
      "vn 0 0 -1\nvn 0 0 1\nvn 0 -1 0\nvn 0 1 0\nvn -1 0 0\nvn 1 0 0\n"
      "f 1//1 4//1 3//1 2//1\nf 5//2 6//2 7//2 8//2\nf 1//3 2//3 6//3 5//3\n"
      "f 4//4 8//4 7//4 3//4\nf 1//5 5//5 8//5 4//5\nf 2//6 3//6 7//6 6//6\n");
  const scene::Description d = scene::parse_scene(R"(
size = [64, 64]
lighting = false
depth_test = false
[[mesh]]
source = ")" + obj.string() + R"("
normals = "file"
color = "normal"
transforms = [{ scale = [0.5, 0.5, 0.5] }]
)", "t.toml");
  for (auto path : {scene::DrawPath::Arrays, scene::DrawPath::Elements, scene::DrawPath::Immediate}) {
    SCOPED_TRACE(scene::to_string(path));
    scene::Description dp = d;
    dp.objects[0].draw = path;
    auto mesa = backends::make("mesa");
    const auto prims = check::capture(*mesa, dp.width, dp.height, [&] { scene::draw(dp); });
    ASSERT_EQ(prims.size(), 12u);  // no culling, nothing clipped: every triangle fed back
    std::set<std::array<long, 3>> normals;
    for (const auto& p : prims) {
      ASSERT_EQ(p.vertices.size(), 3u);
      for (const auto& v : p.vertices) {
        EXPECT_EQ(v.color, p.vertices[0].color) << "a triangle's corners carry one face normal";
        std::array<long, 3> n;
        for (int k = 0; k < 3; ++k) n[size_t(k)] = std::lround(2 * v.color[k] - 1);
        EXPECT_EQ(std::abs(n[0]) + std::abs(n[1]) + std::abs(n[2]), 1) << "an axis direction";
        normals.insert(n);
      }
    }
    EXPECT_EQ(normals.size(), 6u);  // the file's six normals, each on its own face
  }
}

}  // namespace
}  // namespace ffc
