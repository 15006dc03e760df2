// ExactSum (core/exact_sum.h): a sum whose bits do not depend on the order of its terms.
//
// Compared with == throughout: the claims are exactness and order independence, not accuracy
// within a tolerance; the one accuracy test compares with a closed form that is a double.
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <mutex>
#include <random>
#include <vector>

#include "swarf/core/comm.h"
#include "swarf/core/exact_sum.h"
#include "swarf/core/loopback_comm.h"

namespace swarf {
namespace {

std::uint64_t bits(double x) { return std::bit_cast<std::uint64_t>(x); }

// Terms over 600 binary orders of magnitude, both signs, subnormals among them: the worst case
// for a floating-point sum's order dependence.
std::vector<double> wild_terms(std::size_t n, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> mant(1.0, 2.0);
  std::uniform_int_distribution<int> expo(-300, 300);
  std::vector<double> t(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double sign = (rng() & 1) ? -1.0 : 1.0;
    t[i] = sign * std::ldexp(mant(rng), expo(rng));
    if (i % 97 == 0) t[i] = sign * std::ldexp(mant(rng), -1060);  // (subnormal)
  }
  return t;
}

double exact(const std::vector<double>& t) {
  ExactSum s;
  for (double x : t) s.add(x);
  return s.value();
}

TEST(ExactSum, TheSumDoesNotDependOnTheOrderOfItsTerms) {
  std::vector<double> t = wild_terms(20000, 7);
  const double forward = exact(t);
  double plain_forward = 0.0, plain_backward = 0.0;
  for (double x : t) plain_forward += x;
  for (auto it = t.rbegin(); it != t.rend(); ++it) plain_backward += *it;
  // (the scene can fail: a plain sum of these terms does depend on the order)
  ASSERT_NE(bits(plain_forward), bits(plain_backward));
  std::reverse(t.begin(), t.end());
  EXPECT_EQ(bits(exact(t)), bits(forward));
  std::mt19937_64 rng(11);
  for (int trial = 0; trial < 5; ++trial) {
    std::shuffle(t.begin(), t.end(), rng);
    EXPECT_EQ(bits(exact(t)), bits(forward));
  }
  // Split into parts summed apart and merged, as threads or ranks would.
  std::shuffle(t.begin(), t.end(), rng);
  for (std::size_t parts : {2u, 3u, 7u, 64u}) {
    std::vector<ExactSum> part(parts);
    for (std::size_t i = 0; i < t.size(); ++i) part[i % parts].add(t[i]);
    ExactSum merged;
    for (std::size_t p = parts; p-- > 0;) merged.add(part[p]);
    EXPECT_EQ(bits(merged.value()), bits(forward)) << parts << " parts";
    // Through the words a Comm sends: digit-wise integer sums of canonical accumulators.
    std::vector<std::int64_t> words(ExactSum::kWords, 0);
    for (const ExactSum& s : part) {
      const std::vector<std::int64_t> d = s.digits();
      for (std::size_t k = 0; k < words.size(); ++k) words[k] += d[k];
    }
    EXPECT_EQ(bits(ExactSum::from_digits(words).value()), bits(forward)) << parts << " parts, as words";
  }
}

TEST(ExactSum, SumsThatRoundOffLosesComeOutExact) {
  // Closed forms: each result below is a double, so an exact sum rounded once must give it.
  ExactSum a;
  a.add(1e100);
  a.add(1.0);
  a.add(-1e100);
  EXPECT_EQ(a.value(), 1.0);  // (a plain sum gives 0)
  ExactSum b;
  const std::vector<double> t = wild_terms(5000, 3);
  for (double x : t) b.add(x);
  for (double x : t) b.add(-x);
  EXPECT_EQ(bits(b.value()), bits(0.0));  // every term cancelled exactly
  ExactSum c;                             // sum_{k=1}^{n} k 2^-10 = n (n + 1) / 2 * 2^-10, exact in a double
  const int n = 100000;
  for (int k = n; k >= 1; --k) c.add(std::ldexp(k, -10));
  EXPECT_EQ(c.value(), std::ldexp(static_cast<double>(n) * (n + 1) / 2, -10));
  ExactSum d;  // 2^20 smallest subnormals: 2^-1054, a normal number
  for (int k = 0; k < (1 << 20); ++k) d.add(std::ldexp(1.0, -1074));
  EXPECT_EQ(d.value(), std::ldexp(1.0, -1054));
  ExactSum e;  // a negative sum with carries through every digit below its top
  e.add(-std::ldexp(1.0, 900));
  e.add(std::ldexp(1.0, -1074));
  EXPECT_EQ(e.value(), -std::ldexp(1.0, 900));  // (faithful: -2^900 + 2^-1074 rounds to -2^900)
  e.add(std::ldexp(1.0, 900));
  EXPECT_EQ(e.value(), std::ldexp(1.0, -1074));
  ExactSum f;
  for (double x : {0.1, 0.2, 0.3, -0.6}) f.add(x);
  // 0.1 + 0.2 + 0.3 - 0.6 as doubles is exactly 2^-54 + 2^-55 + ... : compare with long double,
  // which holds this short sum exactly (64-bit mantissa; the terms span 3 binary orders).
  const long double ld = static_cast<long double>(0.1) + static_cast<long double>(0.2) + static_cast<long double>(0.3) -
                         static_cast<long double>(0.6);
  EXPECT_EQ(f.value(), static_cast<double>(ld));
}

TEST(ExactSum, NonFiniteTermsAndOverflowAreIeeeLike) {
  ExactSum a;
  a.add(1.0);
  a.add(HUGE_VAL);
  EXPECT_EQ(a.value(), HUGE_VAL);
  a.add(-HUGE_VAL);
  EXPECT_TRUE(std::isnan(a.value()));
  ExactSum b;
  b.add(std::nan(""));
  b.add(1.0);
  EXPECT_TRUE(std::isnan(b.value()));
  ExactSum c;  // finite terms whose sum overflows, and comes back in range
  c.add(DBL_MAX);
  c.add(DBL_MAX);
  EXPECT_EQ(c.value(), HUGE_VAL);
  c.add(-DBL_MAX);
  EXPECT_EQ(c.value(), DBL_MAX);
  ExactSum d;
  d.add(-DBL_MAX);
  d.add(-DBL_MAX);
  EXPECT_EQ(d.value(), -HUGE_VAL);
}

TEST(ExactSum, RanksOfACommGetTheSameBitsAsOneSum) {
  const std::vector<double> t = wild_terms(9000, 5);
  const double whole = exact(t);
  for (int n : {1, 2, 3, 4}) {
    std::vector<double> got(n, 0.0);
    run_loopback(n, [&](Comm& comm) {
      std::vector<ExactSum> mine(2);
      for (std::size_t i = comm.rank(); i < t.size(); i += comm.size()) mine[0].add(t[i]);
      mine[1].add(static_cast<double>(comm.rank() + 1));
      const std::vector<ExactSum> total = comm.sum_exact(mine);
      got[comm.rank()] = total[0].value();
      EXPECT_EQ(total[1].value(), n * (n + 1) / 2.0);
    });
    for (int r = 0; r < n; ++r) EXPECT_EQ(bits(got[r]), bits(whole)) << n << " ranks, rank " << r;
  }
}

}  // namespace
}  // namespace swarf
