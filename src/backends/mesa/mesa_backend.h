// Mesa's own fixed-function pipeline, offscreen, on one of two platforms (mesa_platform.h): OSMesa
// or EGL, the same llvmpipe behind both. name() is "mesa" on either; platform() says which.
#pragma once
#include <memory>
#include <string>
#include <vector>

#include "backends/backend.h"

namespace ffc::backends {

namespace mesa {
class Platform;
}

// The platforms of this build ("osmesa", "egl"), in order of preference.
std::vector<std::string> mesa_platforms();
// The platform a "mesa" backend takes now: FFCOMPAT_PLATFORM's if set, else OSMesa where built,
// else EGL (src/platform/platform_choice.h). Throws std::invalid_argument for an unknown or
// unbuilt platform.
std::string mesa_platform();
// A GL entry point of that platform's Mesa, or null; for the functions the dispatch does not
// hold (the differential tester's glLightiv and others).
void* mesa_proc_address(const std::string& platform, const char* name);

// Whether llvmpipe fuses its multiply-adds (llvm.fmuladd: window positions, depth) in this
// process: on x86 only with FMA3, which Mesa takes with AVX (util/u_cpu_detect.c) and drops under
// GALLIUM_OVERRIDE_CPU_CAPS=nosse|sse|sse2|sse3|ssse3|sse4.1; AArch64 always fuses. Soft follows
// the fused llvmpipe on every target, so where this is false depth ties and edges can differ
// (docs/deviations.md row 74, "llvmpipe-fma-rounding").
bool llvmpipe_fuses();

class MesaBackend final : public Backend {
 public:
  // Throws std::invalid_argument for a platform that is unknown or not built.
  explicit MesaBackend(std::string platform = mesa_platform());
  ~MesaBackend() override;
  MesaBackend(const MesaBackend&) = delete;
  MesaBackend& operator=(const MesaBackend&) = delete;

  std::string name() const override { return "mesa"; }
  const std::string& platform() const { return platform_; }
  void begin(int width, int height) override;
  void resume() override;
  void read_into(image::Image& out) override;

 private:
  std::string platform_;
  std::unique_ptr<mesa::Platform> context_;  // a fresh one per begin()
};

}  // namespace ffc::backends
