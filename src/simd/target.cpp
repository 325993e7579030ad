#include "simd/target.h"

#include <hwy/targets.h>

#include <cstdlib>
#include <mutex>
#include <stdexcept>

namespace ffc::simd {

namespace {

struct Name {
  const char* ours;
  int64_t bit;
};
// Ours for Highway's. "scalar" is whichever of Highway's two portable targets the build has as
// its baseline (HWY_SCALAR, one lane, in Debian's build for plain x86-64; EMU128 elsewhere).
constexpr int64_t kPortable = HWY_EMU128 | HWY_SCALAR;
constexpr Name kNames[] = {{"avx512", HWY_AVX3}, {"avx2", HWY_AVX2}, {"sse4", HWY_SSE4}, {"ssse3", HWY_SSSE3}, {"neon", HWY_NEON},
                           {"sve", HWY_SVE},     {"scalar", HWY_EMU128}, {"scalar", HWY_SCALAR}};

std::string name_of(int64_t bit) {
  for (const Name& n : kNames)
    if (n.bit == bit) return n.ours;
  return hwy::TargetName(bit);
}

bool vectors_now() { return (hwy::SupportedTargets() & HWY_TARGETS & ~kPortable) != 0; }

int64_t g_applied = 0;  // the restriction in force (0: none), for restrict() to keep on failure

// Highway's bits are ordered best first (a lower bit is a better target), so "this one and
// worse" is every bit from it upwards; the portable target stays as the fallback of every
// restriction.
void apply(int64_t bit) {
  g_applied = bit;
  if (bit == 0) {
    hwy::SetSupportedTargetsForTest(0);
  } else {
    const int64_t from_here = ~(bit - 1);
    hwy::SetSupportedTargetsForTest((hwy::SupportedTargets() & from_here) | (HWY_TARGETS & kPortable));
  }
  // Dispatch tables chose at their first call; make them choose again.
  hwy::GetChosenTarget().Update(hwy::SupportedTargets());
  g_vector_target = vectors_now();
}

}  // namespace

bool g_vector_target = vectors_now();

int64_t target_bit(const std::string& name) {
  for (const Name& n : kNames)
    if (name == n.ours) return n.bit;
  return 0;
}

void configure_from_environment() {
  static std::once_flag once;
  std::call_once(once, [] {
    std::string want;
    if (const char* s = std::getenv("FFCOMPAT_SIMD"); s && *s) want = s;
    else if (const char* s = std::getenv("FFCOMPAT_SCALAR"); s && std::string(s) == "1") want = "scalar";
    if (want.empty()) return;
    if (!target_bit(want))
      throw std::invalid_argument("FFCOMPAT_SIMD=" + want + " names no target (avx512, avx2, sse4, ssse3, neon, sve, scalar)");
    // A target the CPU lacks (avx512 on a laptop) leaves the best one it has: the worse ones.
    apply(want == "scalar" ? (HWY_TARGETS & kPortable & -(HWY_TARGETS & kPortable)) : target_bit(want));
  });
}

std::vector<std::string> available() {
  std::vector<std::string> out;
  for (int64_t t : hwy::SupportedAndGeneratedTargets()) out.push_back(name_of(t));
  return out;
}

std::string current() {
  const int64_t t = hwy::SupportedTargets() & HWY_TARGETS;
  return name_of(t & -t);
}

bool restrict(const std::string& name) {
  int64_t bit = name.empty() ? 0 : target_bit(name);
  if (name == "scalar") bit = HWY_TARGETS & kPortable & -(HWY_TARGETS & kPortable);
  if (!name.empty()) {
    // Whether the CPU runs it and the build has it, with any earlier restriction lifted to ask.
    hwy::SetSupportedTargetsForTest(0);
    const bool there = bit && (hwy::SupportedTargets() & HWY_TARGETS & bit);
    if (!there) return apply(g_applied), false;  // the restriction before, as it was
  }
  apply(bit);
  return true;
}

}  // namespace ffc::simd
