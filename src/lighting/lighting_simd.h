// The float lighting kernel many vertices at a time (Highway: compiled for every SIMD target,
// chosen at run time, src/simd/target.h). It gives the bits of the scalar float kernel
// (lighting.cpp's light_impl) on every target: each lane performs the scalar code's operations in
// its order, with no fused multiply-add, and pow is simd/pow.h's exp2(log2) in double, written once
// for the scalar kernel and the vectors. The double reference stays scalar.
#pragma once
#include <cstddef>

#include "lighting/lighting.h"

namespace ffc::lighting {

// Columns of `count` vertices (structure of arrays). Every column must be readable, and every
// output column writable, up to `count` rounded up to a multiple of kSoaPad (the widest vector:
// the lanes past `count` are computed and ignored).
inline constexpr size_t kSoaPad = 64;
// The floats a vector holds on the dispatched target (a divisor of kSoaPad): columns of fewer
// vertices need padding only up to a multiple of it.
size_t soa_lanes();
struct SoaIn {
  const float* p[4];  // eye-space position x, y, z, w
  const float* n[3];  // eye-space normal, normalized or rescaled as the state asks
  const float* c[4];  // the current colour, read when colour material is on
};
struct SoaOut {
  float* col[2][2][4];  // [primary, secondary][front, back][r, g, b, a], clamped to [0, 1]
  // Whether only the columns the key makes are written: the back ones only with two-sided
  // lighting (else the back colours are the front ones) and the secondary ones only with a
  // separate specular colour (else they are 0). A third of the stores where the key has neither.
  bool keyed = false;
};

// Lights the columns with the constants of `c` on the dispatched target; what the key leaves out
// (lights, specular, two sides) is compiled out per shape as in the scalar kernels.
void light_soa(const Prepared<float>& c, const SoaIn& in, size_t count, const SoaOut& out);

// The same as a Kernel<float> (AoS in and out, any count): the vertices transposed into columns
// and back. Same bits as specialised<float>(key) and generic<float>().
Kernel<float> vectorised(const Key& key);

}  // namespace ffc::lighting
