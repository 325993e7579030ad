// include/ffcompat/ffcompat.h on top of the backends.
#include "ffcompat/ffcompat.h"

#include <stdexcept>

#include "backends/backend.h"

#ifndef FFCOMPAT_VERSION
#error "FFCOMPAT_VERSION is defined by CMakeLists.txt from project(VERSION)"
#endif

namespace ffcompat {

const char* version() { return FFCOMPAT_VERSION; }

std::vector<std::string> backends() { return ffc::backends::names(); }

struct Context::Impl {
  std::unique_ptr<ffc::backends::Backend> backend;
  int width = 0, height = 0;
};

Context::Context(const std::string& backend, int width, int height) : impl_(std::make_unique<Impl>()) {
  impl_->backend = ffc::backends::make(backend);
  impl_->backend->begin(width, height);
  impl_->width = width, impl_->height = height;
}

Context::~Context() = default;
Context::Context(Context&&) noexcept = default;
Context& Context::operator=(Context&&) noexcept = default;

void Context::make_current() { impl_->backend->resume(); }

std::vector<std::uint8_t> Context::read_pixels() {
  ffc::image::Image img;
  impl_->backend->read_into(img);
  return std::move(img.rgba);
}

int Context::width() const { return impl_->width; }
int Context::height() const { return impl_->height; }
std::string Context::backend() const { return impl_->backend->name(); }

}  // namespace ffcompat
