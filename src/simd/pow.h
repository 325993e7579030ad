// pow(x, e) for the lighting's float powers (the specular (n.h)^s and the spot's cos^e), as
// exp2(e * log2(x)) evaluated in double with fixed polynomials, written once here for both the
// scalar float kernel (lighting.cpp, Ops = ScalarPowOps below) and the Highway kernel
// (lighting_simd.cpp, Ops on vectors of doubles). Only IEEE operations that round exactly on
// every target are used (+, -, *, /, comparisons, selects and bit shifts), in one order and with
// no fused multiply-add (the project compiles with -ffp-contract=off), so every SIMD target gives
// the scalar function's bits: glibc's powf has no vector form and libm's bits differ by libm.
//
// Accuracy: the float inputs are exact in double; log2 and exp2 below are good to about 1e-12
// relative, so the double result is within about 1e-10 relative of the true power for exponents up
// to 128 and the float result is the correctly rounded one but for rare halfway cases, where it is
// 1 ulp away (tests/lighting/pow_test.cpp holds it to 1 ulp of double pow, 1e-6 relative).
//
// Special values as C's pow for x >= 0 (the lighting's bases are max(0, .)): pow(x, 0) = 1 for
// every x (GL's rule for shininess 0, which the project follows: docs/deviations.md row 10),
// pow(1, e) = 1, pow(0, e > 0) = 0, pow(0, e < 0) = inf, pow(inf, e > 0) = inf, a NaN otherwise NaN.
#pragma once
#include <cstdint>
#include <cstring>
#include <limits>

namespace ffc::simd {

#include "simd/pow_core.h"  // IWYU pragma: export

// The scalar operations for pow_double: one double.
struct ScalarPowOps {
  using V = double;
  using M = bool;
  static double set(double c) { return c; }
  static double add(double a, double b) { return a + b; }
  static double sub(double a, double b) { return a - b; }
  static double mul(double a, double b) { return a * b; }
  static double div(double a, double b) { return a / b; }
  static bool lt(double a, double b) { return a < b; }
  static bool gt(double a, double b) { return a > b; }
  static bool eq(double a, double b) { return a == b; }
  static double select(bool m, double a, double b) { return m ? a : b; }
  static uint64_t bits(double v) {
    uint64_t u;
    std::memcpy(&u, &v, sizeof u);
    return u;
  }
  static double from(uint64_t u) {
    double v;
    std::memcpy(&v, &u, sizeof v);
    return v;
  }
  static double and_bits(double v, uint64_t k) { return from(bits(v) & k); }
  static double or_bits(double v, uint64_t k) { return from(bits(v) | k); }
  static double shr52(double v) { return from(bits(v) >> 52); }
  static double shl52(double v) { return from(bits(v) << 52); }
};

// pow(x, e) for one float, x >= 0 or NaN: the scalar kernel's power, the bits every SIMD target
// gives (lighting_simd.cpp).
inline float pow_float(float x, float e) {
  bool over;
  const double y = pow_double(ScalarPowOps{}, double(x), double(e), &over);
  return over ? std::numeric_limits<float>::infinity() : float(y);
}

}  // namespace ffc::simd
