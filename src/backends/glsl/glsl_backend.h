// "glsl": our state tracker (state::Context: errors, glGet, matrices, lights, materials, arrays,
// immediate mode) drawing through a core-profile EGL context (3.3) with the shaders generated
// from each draw's lighting key (renderer.h). The gl* dispatch points at our context, as for soft.
#pragma once
#include <memory>

#include "backends/backend.h"
#include "backends/glsl/gl_core.h"
#include "backends/glsl/renderer.h"
#include "platform/egl_context.h"
#include "state/context.h"

namespace ffc::backends {

class GlslBackend final : public Backend {
 public:
  // phong: lit, smooth draws evaluate the equation per fragment ("glsl-phong").
  explicit GlslBackend(bool phong = false) : phong_(phong) {}
  ~GlslBackend() override;
  std::string name() const override { return phong_ ? "glsl-phong" : "glsl"; }
  void begin(int width, int height) override;
  void resume() override;
  void read_into(image::Image& out) override;
  // A new width x height pbuffer and framebuffer, the GL state kept (libGL.so.1's window resized).
  void resize(int width, int height);

  // The sink, for the checks and `ffcompat glsl` (null before begin()).
  glsl::Renderer* renderer() { return renderer_.get(); }
  state::Context* context() { return context_.get(); }

 private:
  void bind();  // this backend's EGL context current, for certain
  bool phong_;
  std::unique_ptr<platform::EglContext> egl_;
  glsl::CoreGl gl_;
  std::unique_ptr<glsl::Renderer> renderer_;
  std::unique_ptr<state::Context> context_;
};

}  // namespace ffc::backends
