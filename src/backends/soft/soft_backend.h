// Our own renderer: the state tracker, vertex lighting and rasterizer of ffcompat, bound to the
// same dispatch as Mesa. Float is the fast path; double is the reference.
#pragma once
#include <memory>

#include "backends/backend.h"
#include "state/context.h"

namespace ffc::backends {

class SoftBackend final : public Backend {
 public:
  explicit SoftBackend(state::Precision p = state::Precision::Float) : precision_(p) {}
  ~SoftBackend() override;
  std::string name() const override { return precision_ == state::Precision::Float ? "soft" : "soft-double"; }
  void begin(int width, int height) override;
  void resume() override;
  void read_into(image::Image& out) override;

 private:
  state::Precision precision_;
  std::unique_ptr<state::Context> context_;
};

}  // namespace ffc::backends
