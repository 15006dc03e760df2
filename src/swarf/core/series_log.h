// series_log.h: a natural logarithm the compiler can vectorise, for the Johnson-Cook rate factor.
//
// The rate factor 1 + C ln(rate / rate_ref) is evaluated for every rod on every force evaluation
// of a cut (the rods' strain rates are above the reference nearly everywhere). libm's log is an
// opaque call: it keeps the rod kernel's loop scalar, and it cost as much as the rest of the
// Johnson-Cook law (validation/cutting/README.md). This one is a few multiplies and adds with no
// table and no branch, so a '#pragma omp simd' loop runs it on a whole vector of rods.
//
// The method: x = 2^e m with m in [sqrt(1/2), sqrt(2)), and ln m = 2 atanh(s) with s = (m - 1) /
// (m + 1), |s| <= 0.1716, summed as the series 2 s (1 + s^2/3 + s^4/5 + ... + s^20/21). The first
// term left out, s^22/23, is below 3e-19 of the sum: the result is within a few rounding errors
// of the true logarithm (a test compares it with std::log: within 4 ulp, below 1e-15 relative).
// e ln 2 is added in two parts (Cody and Waite's split of ln 2) so that it is exact to 2^-80
// for any exponent.
//
// Domain: finite x >= DBL_MIN (normal numbers). The Johnson-Cook factor calls
// series_log_at_least_one, ln(max(x, 1)), for which ln 1 = 0 exactly (s = 0).
#pragma once

#include <bit>
#include <cstdint>

namespace swarf {

inline double series_log(double x) {
  const std::uint64_t bits = std::bit_cast<std::uint64_t>(x);
  // The mantissa as m in [sqrt(1/2), sqrt(2)), where the series converges fastest, and the
  // unbiased exponent, all in integer arithmetic: the mantissa bits above sqrt(2)'s get the
  // exponent of [1/2, 1) and one more power of two; the exponent is made a double by the
  // 2^52 trick (its bits as the low bits of 2^52 + e). Integer compares and selects are what
  // the compiler if-converts in a vector loop: a floating-point compare, a conditional multiply
  // or an integer-to-double conversion "could trap" under the default -ftrapping-math and keep
  // the loop scalar.
  const std::uint64_t frac = bits & 0x000fffffffffffffULL;
  const std::uint64_t high = frac > 0x6a09e667f3bcdULL ? 1 : 0;  // (sqrt(2) = 0x3ff6a09e667f3bcd)
  const double m = std::bit_cast<double>(frac | (0x3ff0000000000000ULL - (high << 52)));
  const std::uint64_t biased = (bits >> 52) + high;  // (x >= 0: no sign bit)
  const double e = std::bit_cast<double>(0x4330000000000000ULL | biased) - (4503599627370496.0 + 1023.0);
  const double s = (m - 1.0) / (m + 1.0), z = s * s;
  double p = 1.0 / 21.0;
  p = p * z + 1.0 / 19.0;
  p = p * z + 1.0 / 17.0;
  p = p * z + 1.0 / 15.0;
  p = p * z + 1.0 / 13.0;
  p = p * z + 1.0 / 11.0;
  p = p * z + 1.0 / 9.0;
  p = p * z + 1.0 / 7.0;
  p = p * z + 1.0 / 5.0;
  p = p * z + 1.0 / 3.0;
  // ln 2 = ln2_hi + ln2_lo, ln2_hi with its last 11 bits zero (e ln2_hi exact for |e| < 2^11).
  constexpr double ln2_hi = 6.93147180369123816490e-01, ln2_lo = 1.90821492927058770002e-10;
  const double ln_m = 2.0 * s + 2.0 * s * z * p;
  return e * ln2_hi + (e * ln2_lo + ln_m);
}

/// ln(max(x, 1)) for x >= 0 (0 below 1, exactly): the clamp in the integer image of x, which
/// orders non-negative doubles as their values (no floating-point compare; see above).
inline double series_log_at_least_one(double x) {
  const std::uint64_t bits = std::bit_cast<std::uint64_t>(x), one = 0x3ff0000000000000ULL;
  return series_log(std::bit_cast<double>(bits > one ? bits : one));
}

}  // namespace swarf
