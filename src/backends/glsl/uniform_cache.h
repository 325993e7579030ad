// The values of one program's uniforms for a draw's state, without rebuilding them (names and
// all: uniforms() allocates) when the state was seen recently. The matrices that change from
// object to object (u_mvp, u_modelview, u_normal_inverse) are copied from the state every draw;
// everything else uniforms() reads is compared byte by byte with the states of the last few
// rebuilds (SinkValues, the lights, the materials, the fragment state), and equal bytes reuse
// that rebuild's values. Unequal bytes for equal values (padding, -0) only cost a rebuild.
#pragma once
#include <cstdint>
#include <vector>

#include "backends/glsl/shader_gen.h"
#include "state/draw_sink.h"

namespace ffc::glsl {

class UniformCache {
 public:
  explicit UniformCache(const ProgramKey& k);
  // The program's uniforms (in uniforms()'s order) with their values for s.
  const std::vector<Uniform>& values(const state::SinkState& s);
  uint64_t rebuilds() const { return rebuilds_; }

  static constexpr size_t kStates = 16;  // e.g. a frame's materials on one program

 private:
  struct Entry {
    std::vector<unsigned char> inputs;
    std::vector<Uniform> values;
    uint64_t used = 0;
  };
  ProgramKey key_;
  int mvp_ = -1, modelview_ = -1, normal_inverse_ = -1;  // their places in the list, or -1
  std::vector<Entry> entries_;
  std::vector<unsigned char> scratch_;  // this draw's inputs
  uint64_t clock_ = 0, rebuilds_ = 0;
};

}  // namespace ffc::glsl
