// The triangle-list path (GL_TRIANGLES from glDrawArrays, glDrawElements or immediate mode:
// vertices lit in batches, triangles binned to the threads that own their rows) draws what the
// general path draws (vertex by vertex, triangles set up and then rasterized), bit for bit,
// whatever the state and the number of threads; and with the Highway kernels (raster/wide/), on
// every target the CPU runs, what the scalar row loop draws.
#include <gtest/gtest.h>

#include "backends/backend.h"
#include "gl/dispatch.h"
#include "image/compare.h"
#include "raster/wide/kernels.h"
#include "scene/scene.h"
#include "simd/target.h"
#include "state/context.h"

namespace ffc {
namespace {

image::Image draw(scene::Description d, scene::DrawPath path, int threads, bool triangle_lists = true, bool wide = true) {
  for (scene::Object& o : d.objects) o.draw = path;
  raster::detail::set_wide_kernels(wide);
  auto soft = backends::make("soft");
  soft->begin(d.width, d.height);
  state::Context::current()->set_threads(threads);
  state::Context::current()->set_triangle_lists(triangle_lists);
  scene::draw(d);
  image::Image img = soft->read();
  raster::detail::set_wide_kernels(true);
  return img;
}

// Pixels that are not the background.
double drawn_share(const image::Image& img) {
  size_t n = 0;
  for (size_t i = 0; i < img.rgba.size(); i += 4) n += img.rgba[i] | img.rgba[i + 1] | img.rgba[i + 2];
  return double(n) / double(img.rgba.size() / 4);
}

struct Case {
  std::string name;
  scene::Description d;
};
void PrintTo(const Case& c, std::ostream* os) { *os << c.name; }

std::vector<Case> cases() {
  auto sphere = [](int depth) {
    scene::Spec s = scene::builtin("icosphere");
    s.depth = depth;
    s.normals = mesh::NormalSource::Average;
    return scene::describe(s);
  };
  std::vector<Case> out;
  out.push_back({"smooth", sphere(4)});
  out.push_back({"smooth_depth_5", sphere(5)});  // boxes of about 4x4 pixels: the box kernel
  {
    scene::Description d = sphere(3);
    d.shade = scene::Shade::Flat;  // the provoking (third) vertex's colour
    out.push_back({"flat", d});
  }
  {
    scene::Description d = sphere(4);  // the inside shows, lit with the back material
    d.cull_face = true, d.cull_mode = scene::Face::Front, d.light_model.two_sided = true;
    d.back.diffuse = {0.1f, 0.7f, 0.2f, 1};
    out.push_back({"two_sided_front_culled", d});
  }
  {
    scene::Description d = sphere(4);
    d.lights[0].specular = {1, 1, 1, 1}, d.front.specular = {1, 1, 1, 1};
    d.light_model.separate_specular = true;
    out.push_back({"separate_specular", d});
  }
  {
    scene::Description d = sphere(3);  // primitive order decides: back faces may show
    d.depth_test = false;
    out.push_back({"no_depth_test", d});
  }
  {
    scene::Description d = sphere(4);  // the near plane cuts the front cap: clipped triangles
    d.camera.z_near = 3.4;
    out.push_back({"near_plane_clips", d});
  }
  {
    scene::Description d = sphere(5);  // bands cut short by the framebuffer's edges
    d.width = 301, d.height = 77;
    out.push_back({"odd_size", d});
  }
  {
    // Half the triangles cover no pixel centre: the grouped setup queues the others for their
    // planes (raster/wide/triangle_list_wide.cpp), among them clipped ones drawn in their order.
    scene::Description d = sphere(6);
    d.width = d.height = 160;
    d.camera.z_near = 3.4;
    out.push_back({"tiny_triangles_queued", d});
  }
  {
    scene::Description d = sphere(3);  // lit, the diffuse colour following each vertex's colour
    d.color_material.enabled = true;
    d.color_material.mode = scene::ColorMode::Diffuse;
    d.objects[0].color.kind = scene::ColorSource::Kind::Position;
    out.push_back({"colour_material", d});
  }
  {
    scene::Description d = sphere(2);  // unlit: the current colour, clamped
    d.lighting = false;
    d.objects[0].color.kind = scene::ColorSource::Kind::Normal;
    out.push_back({"unlit_colour_array", d});
  }
  return out;
}

class TriangleList : public ::testing::TestWithParam<Case> {};

TEST_P(TriangleList, DrawsWhatTheGeneralPathDraws) {
  const scene::Description& d = GetParam().d;
  const image::Image general = draw(d, scene::DrawPath::Immediate, 1, false, false);
  EXPECT_GT(drawn_share(general), 0.005) << "a picture with something in it";
  // On every Highway target this CPU runs ("scalar": the scalar loops).
  for (const std::string& target : simd::available()) {
    ASSERT_TRUE(simd::restrict(target)) << target;
    for (int threads : {1, 2, 3})
      for (auto path : {scene::DrawPath::Elements, scene::DrawPath::Arrays, scene::DrawPath::Immediate})
        EXPECT_EQ(image::compare(general, draw(d, path, threads)).max_diff, 0) << target << " " << threads << " " << scene::to_string(path);
    EXPECT_EQ(image::compare(general, draw(d, scene::DrawPath::Elements, 2, false)).max_diff, 0) << target << ": general path, kernels";
  }
  simd::restrict("");
}

INSTANTIATE_TEST_SUITE_P(States, TriangleList, ::testing::ValuesIn(cases()),
                         [](const auto& info) { return info.param.name; });

// glMaterial between glBegin and glEnd changes the material of the vertices that follow: the
// vertices kept so far are lit with the material they were sent under.
TEST(TriangleList, MaterialChangesBetweenVerticesLightTheVerticesThatFollow) {
  auto picture = [](bool triangle_lists) {
    auto soft = backends::make("soft");
    soft->begin(64, 64);
    state::Context::current()->set_triangle_lists(triangle_lists);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glBegin(GL_TRIANGLES);
    const GLfloat red[] = {1, 0, 0, 1}, green[] = {0, 1, 0, 1}, blue[] = {0, 0, 1, 1};
    glNormal3f(0, 0, 1);
    glMaterialfv(GL_FRONT, GL_DIFFUSE, red);
    glVertex2f(-0.9f, -0.9f);
    glMaterialfv(GL_FRONT, GL_DIFFUSE, green);
    glVertex2f(0.9f, -0.9f);
    glMaterialfv(GL_FRONT, GL_DIFFUSE, blue);
    glVertex2f(0, 0.9f);
    glEnd();
    return soft->read();
  };
  const image::Image general = picture(false), lists = picture(true);
  EXPECT_EQ(image::compare(general, lists).max_diff, 0);
  // A smooth mix of the three: red near the first corner, blue near the third.
  EXPECT_GT(general.at(6, 60)[0], 2 * general.at(6, 60)[2]);
  EXPECT_GT(general.at(32, 6)[2], 2 * general.at(32, 6)[0]);
}

}  // namespace
}  // namespace ffc
