// Which SIMD target the Highway kernels run on. Highway compiles each kernel for every target it
// can (AVX-512, AVX2, SSE4 on x86; NEON/SVE on ARM; EMU128, its portable scalar-like target,
// everywhere) and picks the best the CPU has at the first call (HWY_DYNAMIC_DISPATCH). This file
// is where that choice is narrowed: FFCOMPAT_SIMD=avx512|avx2|sse4|scalar in the environment (for
// comparisons and tests; FFCOMPAT_SCALAR=1 means scalar), or restrict() from a test. Every target
// gives the same bits, so the choice changes speed only.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

namespace ffc::simd {

// Applies FFCOMPAT_SIMD / FFCOMPAT_SCALAR once per process (later calls do nothing). Call before
// the first dispatched kernel; the GL context does so when it is made. Throws
// std::invalid_argument for a value that names no target.
void configure_from_environment();

// The targets this build compiled and this CPU runs, best first, by our names ("avx512", "avx2",
// "sse4", "ssse3", "neon", "sve", "scalar", or Highway's name for others).
std::vector<std::string> available();

// The target the next dispatched kernel will run on.
std::string current();

// Restricts the dispatch to `name` and worse targets (as FFCOMPAT_SIMD does); "" lifts the
// restriction. Returns false (and changes nothing) when `name` is not available here. For tests
// that run each target in turn; not thread-safe against kernels running at the same time.
bool restrict(const std::string& name);

// Whether the dispatch now picks a vector target rather than the portable one ("scalar"): where
// it does not, the rasterizer runs its scalar loops (FFCOMPAT_SCALAR=1 keeps meaning those).
extern bool g_vector_target;
inline bool vector_target() { return g_vector_target; }

// Highway's target bit for one of our names, or 0 when the name is unknown.
int64_t target_bit(const std::string& name);

}  // namespace ffc::simd
