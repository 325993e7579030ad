// Our own renderer: the state tracker, vertex lighting and rasterizer of ffcompat, bound to the
// same dispatch as Mesa. Float is the fast path; double is the reference.
#pragma once
#include <memory>

#include "backends/backend.h"
#include "state/context.h"

namespace ffc::backends {

class SoftBackend final : public Backend {
 public:
  // spec: GL 2.1 to the letter where Mesa departs from it (docs/deviations.md).
  explicit SoftBackend(state::Precision p = state::Precision::Float, bool spec = false) : precision_(p), spec_(spec) {}
  ~SoftBackend() override;
  std::string name() const override {
    return std::string(precision_ == state::Precision::Float ? "soft" : "soft-double") + (spec_ ? "-spec" : "");
  }
  void begin(int width, int height) override;
  void resume() override;
  void read_into(image::Image& out) override;

 private:
  state::Precision precision_;
  bool spec_;
  std::unique_ptr<state::Context> context_;
};

}  // namespace ffc::backends
