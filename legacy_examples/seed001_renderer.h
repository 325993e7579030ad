// Seed 001's cube on a core-profile OpenGL 3.3 context: the handout's vertex arrays in buffers,
// one program per lighting (compiled on first use, kept), the draw. Headless, the same on an EGL
// pbuffer, read back as an image.
#pragma once
#include <map>
#include <memory>
#include <string>

#include "image/image.h"
#include "seed001_gl.h"
#include "seed001_scene.h"

namespace ffc::platform {
class EglContext;
}

namespace seed001 {

class Renderer {
 public:
  // Needs the context current; `gl` loaded from it and outliving the renderer.
  explicit Renderer(const Gl33& gl);
  ~Renderer();
  Renderer(const Renderer&) = delete;
  Renderer& operator=(const Renderer&) = delete;

  // Clears colour and depth (black), then draws the cube with the lighting from the view, into
  // the viewport the caller set. Throws std::runtime_error with the compiler's log when a shader
  // does not compile or link, or naming the GL error a draw raised.
  void draw(const Lighting& l, const View& v);
  int programs_compiled() const { return int(programs_.size()); }

 private:
  unsigned program(const Lighting& l, const View& v);
  const Gl33& gl_;
  GLuint vao_[2] = {}, vbo_[2] = {}, ebo_ = 0;  // [0] face normals, [1] averaged normals
  std::map<std::string, GLuint> programs_;     // by vertex + fragment text
};

// An EGL core 3.3 context with a width x height pbuffer and a renderer on it.
class Headless {
 public:
  // Throws std::runtime_error when EGL gives no core 3.3 context (the reason in the message).
  Headless(int width, int height);
  ~Headless();
  // Draws and reads back: top row first, RGBA8.
  ffc::image::Image render(const Lighting& l, const View& v);
  std::string gl_renderer() const;  // GL_RENDERER: "llvmpipe (LLVM ...)"
  int programs_compiled() const { return renderer_->programs_compiled(); }

 private:
  std::unique_ptr<ffc::platform::EglContext> context_;
  Gl33 gl_;
  std::unique_ptr<Renderer> renderer_;
  int width_, height_;
};

}  // namespace seed001
