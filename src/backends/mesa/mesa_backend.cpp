#include "backends/mesa/mesa_backend.h"

#include <cstdlib>
#include <cstring>
#include <stdexcept>

#include "backends/mesa/mesa_platform.h"
#include "gl/dispatch.h"
#include "platform/platform_choice.h"
#include "raster/raster.h"

namespace ffc::backends {

namespace {

#ifdef FFCOMPAT_MESA_OSMESA
constexpr bool kOsMesa = true;
#else
constexpr bool kOsMesa = false;
#endif
#ifdef FFCOMPAT_MESA_EGL
constexpr bool kEgl = true;
#else
constexpr bool kEgl = false;
#endif

mesa::Loader loader_of(const std::string& platform) {
#ifdef FFCOMPAT_MESA_OSMESA
  if (platform == "osmesa") return mesa::osmesa_proc_address;
#endif
#ifdef FFCOMPAT_MESA_EGL
  if (platform == "egl") return mesa::egl_proc_address;
#endif
  return nullptr;
}

std::unique_ptr<mesa::Platform> make_platform(const std::string& platform, int width, int height) {
#ifdef FFCOMPAT_MESA_OSMESA
  if (platform == "osmesa") return mesa::make_osmesa(width, height);
#endif
#ifdef FFCOMPAT_MESA_EGL
  if (platform == "egl") return mesa::make_egl(width, height);
#endif
  (void)width, (void)height;
  throw std::logic_error("mesa: platform '" + platform + "' is not built");
}

}  // namespace

std::vector<std::string> mesa_platforms() {
  std::vector<std::string> out;
  if (kOsMesa) out.push_back("osmesa");
  if (kEgl) out.push_back("egl");
  return out;
}

std::string mesa_platform() { return platform::mesa_platform_from_environment(kOsMesa, kEgl); }

void* mesa_proc_address(const std::string& platform, const char* name) {
  const mesa::Loader load = loader_of(platform);
  return load ? load(name) : nullptr;
}

bool llvmpipe_fuses() {
#if defined(__x86_64__) || defined(__i386__)
  if (const char* caps = std::getenv("GALLIUM_OVERRIDE_CPU_CAPS"))
    for (const char* without : {"nosse", "sse", "sse2", "sse3", "ssse3", "sse4.1"})
      if (std::strcmp(caps, without) == 0) return false;
  return __builtin_cpu_supports("avx") && __builtin_cpu_supports("fma");
#else
  return true;
#endif
}

// Soft rounds its copies of llvmpipe's multiply-adds as the llvmpipe beside it does (fused where
// it fuses), unless FFCOMPAT_LLVMPIPE_FMA chose: compared with Mesa, like with like.
static void follow_llvmpipe() {
  if (!raster::configure_llvmpipe_fma_from_environment()) raster::set_llvmpipe_fma(llvmpipe_fuses());
}

MesaBackend::MesaBackend(std::string platform) : platform_(std::move(platform)) {
  platform::choose_mesa_platform(kOsMesa, kEgl, platform_.c_str());  // throws for a bad one
  follow_llvmpipe();
}

MesaBackend::~MesaBackend() = default;

void MesaBackend::begin(int width, int height) {
  if (width <= 0 || height <= 0 || width > 16384 || height > 16384)
    throw std::runtime_error("mesa: framebuffer size " + std::to_string(width) + "x" + std::to_string(height) +
                             " is outside 1..16384");
  follow_llvmpipe();  // GALLIUM_OVERRIDE_CPU_CAPS may have changed since (bench --mesa-isa same)
  // A fresh context per begin(): every picture starts from GL's default state. The old one goes
  // first, its drawing finished.
  context_.reset();
  context_ = make_platform(platform_, width, height);
  const auto missing = gl::load(loader_of(platform_));
  if (!missing.empty()) throw std::runtime_error("mesa (" + platform_ + "): Mesa does not provide " + missing.front());
  glViewport(0, 0, width, height);
}

void MesaBackend::resume() {
  if (!context_) throw std::logic_error("mesa: resume() before begin()");
  context_->make_current();
  gl::load(loader_of(platform_));
}

void MesaBackend::read_into(image::Image& img) {
  if (!context_) throw std::logic_error("mesa: read before begin()");
  context_->read(img);
}

}  // namespace ffc::backends

// Offers "mesa" to backends::make(). ffcompat_mesa's users link with -u naming this symbol (its
// INTERFACE_LINK_OPTIONS, and ffcompat.pc), so the linker keeps this object out of the static
// library, and its registration with it.
extern "C" const bool ffcompat_mesa_backend_registered;
const bool ffcompat_mesa_backend_registered = ffc::backends::register_backend(
    "mesa", []() -> std::unique_ptr<ffc::backends::Backend> { return std::make_unique<ffc::backends::MesaBackend>(); });
