#include "backends/glsl/glsl_backend.h"

#include <stdexcept>

#include "gl/dispatch.h"
#include "raster/raster.h"
#include "state/soft_gl.h"

namespace ffc::backends {

// OSMesa and EGL share Mesa's GL dispatch (libglapi): after an OSMesa context was made current on
// this thread, EGL still counts its own as current and would not bind it again, and our calls
// would reach OSMesa's context. Releasing EGL's first makes the binding real.
void GlslBackend::bind() {
  platform::EglContext::release();
  egl_->make_current();
}

GlslBackend::~GlslBackend() {
  if (state::Context::current() == context_.get()) state::Context::make_current(nullptr);
  if (egl_ && renderer_) {
    bind();  // the renderer's objects belong to this context
    renderer_.reset();
  }
}

void GlslBackend::begin(int width, int height) {
  if (context_ && state::Context::current() == context_.get()) state::Context::make_current(nullptr);
  if (egl_ && renderer_) bind(), renderer_.reset();
  platform::EglRequest r;
  r.profile = platform::Profile::Core, r.major = 3, r.minor = 3, r.width = width, r.height = height;
  egl_ = std::make_unique<platform::EglContext>(r);
  bind();
  for (const std::string& name : gl_.load(&platform::EglContext::proc_address))
    throw std::runtime_error("glsl: the core-profile context has no " + name);
  renderer_ = std::make_unique<glsl::Renderer>(gl_);
  renderer_->set_phong(phong_);
  context_ = std::make_unique<state::Context>(width, height, state::Precision::Float);
  context_->set_draw_sink(renderer_.get());
  resume();
}

void GlslBackend::resume() {
  if (!context_) throw std::logic_error("glsl: resume() before begin()");
  bind();
  state::Context::make_current(context_.get());
  for (const std::string& name : gl::load(state::proc_address))
    throw std::runtime_error("glsl: no entry point for " + name);
}

void GlslBackend::resize(int width, int height) {
  if (!context_) throw std::logic_error("glsl: resize() before begin()");
  bind(), egl_->resize(width, height), context_->framebuffer() = raster::Framebuffer(width, height);
}

void GlslBackend::read_into(image::Image& img) {
  if (!context_) throw std::logic_error("glsl: read_into() before begin()");
  egl_->make_current();  // after resume(), as Backend says: no release needed
  img.width = egl_->width(), img.height = egl_->height();
  img.rgba.resize(size_t(img.width) * size_t(img.height) * 4);
  renderer_->read_back(img.rgba.data(), img.width, img.height);
}

}  // namespace ffc::backends

// Offers "glsl" and "glsl-phong" to backends::make(). ffcompat_glsl's users link with -u naming this symbol, so the
// linker keeps this object, and its registration, out of the static library.
extern "C" const bool ffcompat_glsl_backend_registered;
const bool ffcompat_glsl_backend_registered = ffc::backends::register_backend(
    "glsl", []() -> std::unique_ptr<ffc::backends::Backend> { return std::make_unique<ffc::backends::GlslBackend>(); });
extern "C" const bool ffcompat_glsl_phong_registered;
const bool ffcompat_glsl_phong_registered = ffc::backends::register_backend(
    "glsl-phong", []() -> std::unique_ptr<ffc::backends::Backend> { return std::make_unique<ffc::backends::GlslBackend>(true); });
