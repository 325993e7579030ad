// One drawing on Mesa's fixed function and on the GLSL backend, and what the backend said it did
// not draw: the pictures the GLSL feature tests compare.
#pragma once
#include <GL/gl.h>

#include <functional>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "backends/glsl/glsl_backend.h"
#include "gl/dispatch.h"
#include "image/image.h"

namespace ffc::test {

struct Pictures {
  image::Image mesa, glsl;
  std::vector<std::string> unsupported;  // what the GLSL backend said it did not draw
};

inline Pictures draw_both(int w, int h, const std::function<void()>& draw) {
  auto mesa = backends::make("mesa");
  backends::GlslBackend ours;
  mesa->begin(w, h), ours.begin(w, h);
  ours.resume(), draw();
  Pictures p;
  p.glsl = ours.read();
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  p.unsupported.assign(ours.renderer()->unsupported().begin(), ours.renderer()->unsupported().end());
  mesa->resume(), draw();
  p.mesa = mesa->read();
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  return p;
}

}  // namespace ffc::test
