#include "backends/glsl/uniform_cache.h"

#include <algorithm>
#include <cstring>
#include <glm/gtc/type_ptr.hpp>

namespace ffc::glsl {

namespace {

// The bytes uniforms() depends on, the per-object matrices zeroed (they are copied directly).
void inputs_of(const state::SinkState& s, std::vector<unsigned char>& out) {
  constexpr size_t kValues = sizeof(state::SinkValues), kLights = 8 * sizeof(lighting::LightParams),
                   kMaterials = 2 * sizeof(lighting::MaterialParams), kFragment = sizeof(state::FragmentState);
  out.assign(kValues + kLights + kMaterials + kFragment, 0);  // no allocation once sized
  unsigned char* at = out.data();
  std::memcpy(at, static_cast<const state::SinkValues*>(&s), kValues);
  auto zero = [&](const void* field, size_t n) {
    std::memset(at + (static_cast<const unsigned char*>(field) - reinterpret_cast<const unsigned char*>(&s)), 0, n);
  };
  zero(&s.mvp, sizeof s.mvp), zero(&s.modelview, sizeof s.modelview), zero(&s.normal_inverse, sizeof s.normal_inverse);
  at += kValues;
  if (s.lights) std::memcpy(at, s.lights, kLights);
  at += kLights;
  if (s.materials) std::memcpy(at, s.materials, kMaterials);
  at += kMaterials;
  if (s.fragment) std::memcpy(at, s.fragment, kFragment);
}

void put(Uniform& u, const float* v) { std::copy(v, v + u.size, u.value.begin()); }

}  // namespace

UniformCache::UniformCache(const ProgramKey& k) : key_(k) {
  const std::vector<Uniform> list = uniforms(k, nullptr);
  for (size_t i = 0; i < list.size(); ++i) {
    if (list[i].name == "u_mvp") mvp_ = int(i);
    if (list[i].name == "u_modelview") modelview_ = int(i);
    if (list[i].name == "u_normal_inverse") normal_inverse_ = int(i);
  }
  entries_.reserve(kStates);
}

const std::vector<Uniform>& UniformCache::values(const state::SinkState& s) {
  inputs_of(s, scratch_);
  ++clock_;
  Entry* e = nullptr;
  for (Entry& c : entries_)
    if (c.inputs == scratch_) e = &c;
  if (!e) {
    ++rebuilds_;
    if (entries_.size() < kStates) {
      e = &entries_.emplace_back();
    } else {
      e = &*std::min_element(entries_.begin(), entries_.end(), [](const Entry& a, const Entry& b) { return a.used < b.used; });
    }
    e->inputs = scratch_;
    e->values = uniforms(key_, &s);
  }
  e->used = clock_;
  // As uniforms() computes them: the float matrices as they are, the normal matrix made float.
  if (mvp_ >= 0) put(e->values[size_t(mvp_)], glm::value_ptr(s.mvp));
  if (modelview_ >= 0) put(e->values[size_t(modelview_)], glm::value_ptr(s.modelview));
  if (normal_inverse_ >= 0) {
    const glm::mat3 inv(s.normal_inverse);
    put(e->values[size_t(normal_inverse_)], glm::value_ptr(inv));
  }
  return e->values;
}

}  // namespace ffc::glsl
