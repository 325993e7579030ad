// The stress catalogue's viewports cases (stress/cases.cpp says what the catalogue is).
#include "stress/case_kit.h"

namespace ffc::stress::kit {

void add_viewports(std::vector<Case>& out) {
  auto add = [&](Case c) { out.push_back(std::move(c)); };
  {
    Case c;
    c.group = "viewport";
    c.name = "viewport_1x1";
    c.draw = [] {
      scenes::standard();
      glViewport(20, 30, 1, 1);
      glTranslatef(0, 0, -4);
      scenes::draw(scenes::sphere(3));
    };
    c.note = "glViewport(20, 30, 1, 1): the whole sphere maps into one pixel (2.11.1). Window positions "
             "are within [20, 21] x [30, 31]; only triangles covering the pixel's centre draw it.";
    add(c);
  }
  {
    Case c;
    c.group = "viewport";
    c.name = "framebuffer_1x1";
    c.width = c.height = 1;
    c.draw = [] {
      scenes::standard();
      glTranslatef(0, 0, -4);
      scenes::draw(scenes::sphere(3));
    };
    c.note = "A 1x1 framebuffer (and viewport): as viewport_1x1, with the pixel at the origin.";
    add(c);
  }
  {
    Case c;
    c.group = "viewport";
    c.name = "viewport_8192";
    c.draw = [] {
      scenes::standard();
      glViewport(-4064, -4064, 8192, 8192);
      glTranslatef(0, 0, -4);
      scenes::draw(scenes::sphere(4));
    };
    c.note = "glViewport(-4064, -4064, 8192, 8192) on a 64x64 framebuffer: window coordinates up to "
             "+-4096, of which the framebuffer shows the middle 64x64 pixels (the sphere's centre, 1/128 "
             "of it across). 8192 is within GL_MAX_VIEWPORT_DIMS (16384 on llvmpipe).";
    add(c);
  }
  {
    Case c;
    c.group = "viewport";
    c.name = "viewport_beyond_max";
    c.draw = [] {
      scenes::standard();
      glViewport(-50000, -50000, 100000, 100000);
      glTranslatef(0, 0, -4);
      scenes::draw(scenes::sphere(3));
    };
    c.note = "glViewport(-50000, -50000, 100000, 100000): 'the viewport's width and height are clamped to "
             "implementation-dependent maximums' (2.11.1, GL_MAX_VIEWPORT_DIMS: 16384 in llvmpipe and "
             "ours), the origin is not: the framebuffer sees a corner of the clamped viewport, far off "
             "the sphere.";
    add(c);
  }
  {
    Case c;
    c.group = "viewport";
    c.name = "framebuffer_8192";
    c.slow = true;
    c.width = c.height = 8192;
    c.draw = [] {
      scenes::standard();
      glTranslatef(0, 0, -3);
      scenes::draw(scenes::grid(2), 0.9);
    };
    c.note = "An 8192x8192 framebuffer (256 MB of colour) with trivial geometry: 8 lit triangles. Slow "
             "and large: skipped by the CI test.";
    add(c);
  }
}

}  // namespace ffc::stress::kit
