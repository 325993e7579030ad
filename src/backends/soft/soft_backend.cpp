#include "backends/soft/soft_backend.h"

#include <cstring>
#include <stdexcept>

#include "gl/dispatch.h"
#include "state/soft_gl.h"

namespace ffc::backends {

SoftBackend::~SoftBackend() {
  if (state::Context::current() == context_.get()) state::Context::make_current(nullptr);
}

void SoftBackend::begin(int width, int height) {
  if (width <= 0 || height <= 0 || width > 16384 || height > 16384)
    throw std::runtime_error("soft: framebuffer size " + std::to_string(width) + "x" + std::to_string(height) +
                             " is outside 1..16384");
  context_ = std::make_unique<state::Context>(width, height, precision_);
  context_->set_spec(spec_);
  resume();
}

void SoftBackend::resume() {
  if (!context_) throw std::logic_error("soft: resume() before begin()");
  state::Context::make_current(context_.get());
  for (const std::string& name : gl::load(state::proc_address))
    throw std::runtime_error("soft: no entry point for " + name);
}

void SoftBackend::read_into(image::Image& img) {
  const raster::Framebuffer& fb = context_->framebuffer();
  img.width = fb.width, img.height = fb.height;
  img.rgba.resize(fb.color.size());
  context_->read_top_down(img.rgba.data());
}

}  // namespace ffc::backends
