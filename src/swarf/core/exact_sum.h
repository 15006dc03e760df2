// exact_sum.h: a sum of doubles that does not depend on the order of its terms (issue 38).
//
// Why: a run over N domains adds its sums' terms in another order than the serial run (each
// domain has part of them), and floating-point addition is not associative. Adding every term
// exactly, into a fixed-point integer wide enough for the whole double range, and rounding once
// at the end makes the result a function of the set of terms alone: the same bits for any order,
// any split over threads or ranks (the ranks add their accumulators' integers, which is exact).
// The idea is Kulisch's long accumulator; the layout with carry room is Neal's "small
// superaccumulator" (arXiv:1505.05571): 32-bit digits held in 64-bit signed integers, so that
// 2^30 additions fit before the carries must be propagated.
//
// Cost: a few integer operations per term (no branch on the data but the rare non-finite one),
// against one for a plain double addition: for sums that are read, not for inner loops that
// only need thread-count independence (parallel.h's blocks give that more cheaply).
//
// The rounding at the end is deterministic and faithful (within an ulp or two of the exact sum,
// not always the nearest double); the sum of finite terms that overflows is +-inf; a NaN term,
// or +inf and -inf together, gives NaN.
#pragma once

#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <vector>

namespace swarf {

class ExactSum {
 public:
  /// Digits of 32 bits from 2^-1074 (the smallest subnormal) up: the largest finite double's
  /// top bit is bit 2097, and a term's 53-bit mantissa shifted within its digit spans 3 digits.
  static constexpr int kDigits = 67;

  void add(double x) {
    const std::uint64_t bits = std::bit_cast<std::uint64_t>(x);
    const int e = static_cast<int>((bits >> 52) & 0x7ff);
    std::uint64_t mant = bits & ((std::uint64_t{1} << 52) - 1);
    if (e == 0x7ff) [[unlikely]] {
      special_ |= mant != 0 ? kNan : (bits >> 63) ? kNegInf : kPosInf;
      return;
    }
    // x = mant * 2^(e - 1075) for normal numbers (with the hidden bit), mant * 2^-1074 for
    // subnormals: bit position p = e - 1 above 2^-1074 (e = 0 and e = 1 both start at 0).
    int p = 0;
    if (e != 0) {
      mant |= std::uint64_t{1} << 52;
      p = e - 1;
    }
    const int k = p >> 5;
    const unsigned __int128 v = static_cast<unsigned __int128>(mant) << (p & 31);
    const auto d0 = static_cast<std::int64_t>(static_cast<std::uint64_t>(v) & 0xffffffffu);
    const auto d1 = static_cast<std::int64_t>(static_cast<std::uint64_t>(v >> 32) & 0xffffffffu);
    const auto d2 = static_cast<std::int64_t>(static_cast<std::uint64_t>(v >> 64));
    if (bits >> 63) {
      d_[k] -= d0;
      d_[k + 1] -= d1;
      d_[k + 2] -= d2;
    } else {
      d_[k] += d0;
      d_[k + 1] += d1;
      d_[k + 2] += d2;
    }
    if (++pending_ == kRoom) normalize();
  }

  /// Adds another accumulator's exact value.
  void add(const ExactSum& o) {
    ExactSum b = o;
    b.normalize();
    normalize();
    for (int k = 0; k < kDigits; ++k) d_[k] += b.d_[k];
    special_ |= o.special_;
    pending_ = 1;  // (each digit grew by less than 2^32 once)
  }

  /// The sum rounded to a double: a function of the exact sum alone.
  double value() const {
    if (special_ & kNan || (special_ & kPosInf && special_ & kNegInf)) return std::nan("");
    if (special_ & kPosInf) return HUGE_VAL;
    if (special_ & kNegInf) return -HUGE_VAL;
    ExactSum a = *this;
    a.normalize();
    // Canonical: digits 0..kDigits-2 in [0, 2^32), the top one signed. A negative sum is
    // negated first so that every digit adds with the same sign (no cancellation below).
    const bool negative = a.d_[kDigits - 1] < 0;
    if (negative) {
      for (auto& d : a.d_) d = -d;
      a.normalize();
    }
    int top = kDigits - 1;
    while (top > 0 && a.d_[top] == 0) --top;
    // Near the top of the range the digits are added scaled down by 2^-64 and the overflow is
    // decided before scaling back (an ldexp that overflows would raise FE_OVERFLOW, which the
    // runs may trap).
    const int scale = 32 * top - 1074 + 64 > 1000 ? -64 : 0;
    double r = 0.0;
    for (int k = top; k >= 0; --k)
      if (a.d_[k] != 0) r += std::ldexp(static_cast<double>(a.d_[k]), 32 * k - 1074 + scale);
    if (scale != 0) r = r >= std::ldexp(1.0, 1024 + scale) ? HUGE_VAL : std::ldexp(r, -scale);
    return negative ? -r : r;
  }

  /// The digits in canonical form (for a Comm to add over ranks: digit-wise integer sums of
  /// canonical accumulators, at most 2^30 of them, are exact) and back.
  std::vector<std::int64_t> digits() const {
    ExactSum a = *this;
    a.normalize();
    std::vector<std::int64_t> out(a.d_.begin(), a.d_.end());
    out.push_back(special_);
    return out;
  }
  static ExactSum from_digits(const std::vector<std::int64_t>& v, std::size_t offset = 0) {
    ExactSum s;
    for (int k = 0; k < kDigits; ++k) s.d_[k] = v[offset + k];
    s.special_ = static_cast<int>(v[offset + kDigits]);
    s.pending_ = kRoom - 1;  // (a sum of up to 2^30 canonical sets of digits: normalize at the next add)
    return s;
  }
  static constexpr std::size_t kWords = kDigits + 1;  ///< int64 words of digits()
  /// True if v[offset, offset + kWords) can be digits() of some sum (a checkpoint's, read back).
  static bool canonical(const std::vector<std::int64_t>& v, std::size_t offset = 0) {
    if (v.size() < offset + kWords) return false;
    for (int k = 0; k + 1 < kDigits; ++k)
      if (v[offset + k] < 0 || v[offset + k] >= (std::int64_t{1} << 32)) return false;
    const std::int64_t top = v[offset + kDigits - 1], special = v[offset + kDigits];
    return top > -(std::int64_t{1} << 32) && top < (std::int64_t{1} << 32) && special >= 0 && special <= 7;
  }

 private:
  static constexpr int kNan = 1, kPosInf = 2, kNegInf = 4;
  static constexpr std::int32_t kRoom = std::int32_t{1} << 30;

  // Carries up: every digit but the top one into [0, 2^32) (arithmetic shifts floor).
  void normalize() {
    for (int k = 0; k + 1 < kDigits; ++k) {
      const std::int64_t carry = d_[k] >> 32;
      d_[k] -= carry * (std::int64_t{1} << 32);
      d_[k + 1] += carry;
    }
    pending_ = 0;
  }

  std::array<std::int64_t, kDigits> d_{};
  std::int32_t pending_ = 0;
  int special_ = 0;
};

}  // namespace swarf
