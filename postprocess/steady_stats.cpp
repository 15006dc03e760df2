// steady_stats.cpp: steady-part statistics of a series (see steady_stats.h).
#include "postprocess/steady_stats.h"

#include <algorithm>
#include <boost/math/distributions/students_t.hpp>
#include <numeric>

#include "postprocess/chip.h"

namespace swarf {
namespace {

// f(first, last) of each of B batches of m = floor(n/B) consecutive samples, the last B m of x;
// empty if m < 2.
template <class F>
std::vector<double> per_batch(const std::vector<double>& x, std::size_t batches, F&& f) {
  const std::size_t m = batches > 0 ? x.size() / batches : 0;
  if (m < 2) return {};
  const auto first = x.end() - std::ptrdiff_t(batches * m);
  std::vector<double> out(batches);
  for (std::size_t b = 0; b < batches; ++b)
    out[b] = f(first + std::ptrdiff_t(b * m), first + std::ptrdiff_t((b + 1) * m));
  return out;
}

}  // namespace

std::vector<double> batch_means(const std::vector<double>& x, std::size_t batches) {
  return per_batch(x, batches,
                   [](auto first, auto last) { return std::accumulate(first, last, 0.0) / double(last - first); });
}

std::vector<double> batch_medians(const std::vector<double>& x, std::size_t batches) {
  return per_batch(x, batches, [](auto first, auto last) { return quantile(std::vector<double>(first, last), 0.5); });
}

double student_t_975(std::size_t dof) {
  if (dof == 0) return NAN;
  return boost::math::quantile(boost::math::students_t_distribution<double>(double(dof)), 0.975);
}

double batch_ci95(const std::vector<double>& b) {
  const std::size_t nb = b.size();
  if (nb < 2) return NAN;
  double mean = 0;
  for (double v : b) mean += v;
  mean /= double(nb);
  double ss = 0;
  for (double v : b) ss += (v - mean) * (v - mean);
  return student_t_975(nb - 1) * std::sqrt(ss / double(nb - 1) / double(nb));
}

double batch_ci95_linear(const std::vector<double>& bx, const std::vector<double>& by, double gx, double gy) {
  if (bx.size() != by.size() || !std::isfinite(gx) || !std::isfinite(gy)) return NAN;
  std::vector<double> g(bx.size());
  for (std::size_t k = 0; k < bx.size(); ++k) g[k] = gx * bx[k] + gy * by[k];
  return batch_ci95(g);
}

double integrated_autocorrelation_time(const std::vector<double>& x) {
  const std::size_t n = x.size();
  if (n < kSteadyMinSamples) return NAN;
  double mean = 0;
  for (double v : x) mean += v;
  mean /= double(n);
  std::vector<double> d(n);
  for (std::size_t t = 0; t < n; ++t) d[t] = x[t] - mean;
  auto autocov = [&](std::size_t k) {
    double s = 0;
    for (std::size_t t = 0; t + k < n; ++t) s += d[t] * d[t + k];
    return s / double(n);
  };
  const double c0 = autocov(0);
  if (!(c0 > 0)) return NAN;
  // Pair sums G_j = c_{2j} + c_{2j+1}: positive and non-increasing for a reversible chain; the
  // estimator stops at the first that is not positive and clips each to the one before.
  double sum = 0, previous = HUGE_VAL;
  for (std::size_t j = 0; 2 * j + 1 < n; ++j) {
    const double g = autocov(2 * j) + autocov(2 * j + 1);
    if (!(g > 0)) break;
    previous = std::min(previous, g);
    sum += previous;
  }
  return (2.0 * sum - c0) / c0;
}

SteadyStats steady_stats(const std::vector<double>& x) {
  SteadyStats s;
  const std::size_t n = x.size();
  s.samples = n;
  if (n == 0) return s;
  double sum = 0;
  for (double v : x) sum += v;
  s.mean = sum / double(n);
  if (n >= 2) {
    double var = 0;
    for (double v : x) var += (v - s.mean) * (v - s.mean);
    s.std = std::sqrt(var / double(n - 1));
  }
  if (n < kSteadyMinSamples) return s;
  const std::vector<double> b = batch_means(x);
  s.batches = b.size();
  s.batch_size = n / kSteadyBatches;
  s.ci95 = batch_ci95(b);
  s.autocorrelation_time = integrated_autocorrelation_time(x);
  s.effective_samples = double(n) / s.autocorrelation_time;
  return s;
}

}  // namespace swarf
