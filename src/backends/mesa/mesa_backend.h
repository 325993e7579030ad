// Mesa's own fixed-function pipeline, offscreen. The platform part (context creation and the
// proc-address loader) is all that touches OSMesa, which Mesa 25.1 removed: an EGL pbuffer
// version of this one class is the whole port.
#pragma once
#include <cstdint>
#include <vector>

#include "backends/backend.h"

namespace ffc::backends {

class MesaBackend final : public Backend {
 public:
  MesaBackend() = default;
  ~MesaBackend() override;
  MesaBackend(const MesaBackend&) = delete;
  MesaBackend& operator=(const MesaBackend&) = delete;

  std::string name() const override { return "mesa"; }
  void begin(int width, int height) override;
  void resume() override;
  void read_into(image::Image& out) override;

 private:
  void* context_ = nullptr;  // OSMesaContext
  int width_ = 0, height_ = 0;
  std::vector<uint8_t> buffer_;  // OSMesa renders here, bottom row first
};

}  // namespace ffc::backends
