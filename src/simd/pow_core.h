// simd/pow.h's algorithm (read its comment): the constants and pow_double, with no include guard
// and no namespace of its own, because Highway code must compile it once per SIMD target inside
// that target's namespace (a template defined outside would be compiled for the baseline target
// and could not inline Highway's operations); pow.h includes it once in ffc::simd for the scalar
// kernel. Needs <cstdint> and <limits> included before.
namespace pow_constants {
inline constexpr double kSqrt2 = 1.4142135623730951;
inline constexpr double kLog2e = 1.4426950408889634;  // 1 / ln 2
inline constexpr double kLn2 = 0.6931471805599453;
inline constexpr double kTwo52 = 4503599627370496.0;  // 2^52: bits 0x4330...
// 1.5 * 2^52 + 1023: t plus this rounds t to an integer n in the low bits, biased for exp2's
// exponent field (the sum lies in [2^52, 2^53), where the spacing of doubles is 1).
inline constexpr double kRoundBias = 6755399441055744.0 + 1023.0;
// The least double that rounds to +inf as a float is 0x1.ffffffp127 (the midpoint between FLT_MAX
// and 2^128; ties go to the even 2^128): y is +inf as a float where y > the double just below it.
inline constexpr double kBelowFloatOverflow = 0x1.fffffefffffffp127;  // 0x1.ffffffp127 less 1 ulp
inline constexpr double kClamp = 1020;  // |e log2 x| beyond this is 0 or inf in float anyway
inline constexpr uint64_t kMantissa = 0x000FFFFFFFFFFFFFull, kOne = 0x3FF0000000000000ull,
                          kTwo52Bits = 0x4330000000000000ull;
}  // namespace pow_constants

// The power for each lane of x (double lanes holding floats, x >= 0 or NaN) and one exponent e
// (a float's value). Ops supplies V (a double or a vector of them), M (its comparison result)
// and: set(c), add, sub, mul, div, lt, gt, eq, select(m, a, b), and on the bit
// patterns as 64-bit unsigned integers: and_bits(v, k), or_bits(v, k), shr52(v), shl52(v).
// *over: the lanes whose float is +inf (the caller sets them after rounding to float, since
// Highway's portable targets saturate a double beyond FLT_MAX to FLT_MAX instead).
// Inlined into its caller: the constants are then loaded once per loop, not per call.
template <class Ops>
[[gnu::always_inline]] inline typename Ops::V pow_double(const Ops& o, typename Ops::V x, double e, typename Ops::M* over) {
  using namespace pow_constants;
  using V = typename Ops::V;
  if (e == 0) {  // pow(x, 0) = 1, a NaN x too
    *over = o.lt(o.set(1.0), o.set(0.0));
    return o.set(1.0);
  }
  const V one = o.set(1.0), zero = o.set(0.0), inf = o.set(std::numeric_limits<double>::infinity());
  // x = m 2^k with m in [sqrt(1/2), sqrt(2)): the biased exponent field read as an integer
  // (OR-ed under 2^52's bits, then 2^52 taken away), the mantissa under 1.0's exponent.
  V k = o.sub(o.sub(o.or_bits(o.shr52(x), kTwo52Bits), o.set(kTwo52)), o.set(1023.0));
  V m = o.or_bits(o.and_bits(x, kMantissa), kOne);
  const auto big = o.gt(m, o.set(kSqrt2));
  m = o.select(big, o.mul(m, o.set(0.5)), m);
  k = o.select(big, o.add(k, one), k);
  // ln m = 2 atanh(s), s = (m - 1) / (m + 1), |s| <= 0.1716: its series to s^13 (the next term
  // is below 1.3e-12 relative).
  // The polynomials by Estrin's scheme (pairs, then pairs of pairs): a third of Horner's chain of
  // dependent operations, which kept the vectors waiting.
  const V s = o.div(o.sub(m, one), o.add(m, one));
  const V z = o.mul(s, s), z2 = o.mul(z, z), z4 = o.mul(z2, z2);
  const auto pair = [&](V x, double c0, double c1) { return o.add(o.set(c0), o.mul(x, o.set(c1))); };
  const V poly = o.add(o.add(pair(z, 2.0, 2.0 / 3), o.mul(z2, pair(z, 2.0 / 5, 2.0 / 7))),
                       o.mul(z4, o.add(pair(z, 2.0 / 9, 2.0 / 11), o.mul(z2, o.set(2.0 / 13)))));
  const V log2x = o.add(k, o.mul(o.mul(s, poly), o.set(kLog2e)));
  V t = o.mul(o.set(e), log2x);
  t = o.select(o.lt(t, o.set(-kClamp)), o.set(-kClamp), t);
  t = o.select(o.gt(t, o.set(kClamp)), o.set(kClamp), t);
  // 2^t = 2^n 2^f: n the nearest integer, f = t - n in [-1/2, 1/2] (exact), 2^f = exp(f ln 2) by
  // its Taylor series to degree 10 (the next term is below 2.2e-13), 2^n built in the exponent.
  const V biased = o.add(t, o.set(kRoundBias));
  const V n = o.sub(biased, o.set(kRoundBias));
  const V g = o.mul(o.sub(t, n), o.set(kLn2));
  const V g2 = o.mul(g, g), g4 = o.mul(g2, g2), g8 = o.mul(g4, g4);
  const V low = o.add(o.add(pair(g, 1.0, 1.0), o.mul(g2, pair(g, 0.5, 1.0 / 6))),
                      o.mul(g4, o.add(pair(g, 1.0 / 24, 1.0 / 120), o.mul(g2, pair(g, 1.0 / 720, 1.0 / 5040)))));
  const V p = o.add(low, o.mul(g8, o.add(pair(g, 1.0 / 40320, 1.0 / 362880), o.mul(g2, o.set(1.0 / 3628800)))));
  V y = o.mul(p, o.shl52(biased));
  // The special values (e is one number for every lane: the branches are on it, not per lane).
  const auto x0 = o.eq(x, zero), xinf = o.eq(x, inf);
  if (e > 0) y = o.select(x0, zero, o.select(xinf, inf, y));
  else if (e < 0) y = o.select(x0, inf, o.select(xinf, zero, y));
  else y = o.set(std::numeric_limits<double>::quiet_NaN());  // a NaN exponent
  y = o.select(o.eq(x, x), y, x);  // a NaN base stays NaN
  y = o.select(o.eq(x, one), one, y);
  *over = o.gt(y, o.set(kBelowFloatOverflow));
  return y;
}

