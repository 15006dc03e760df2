// steady_stats.h: statistics of the steady part of a series sampled at equal intervals (the
// series.csv rows of a cut): mean, standard deviation, and the 95 % confidence interval of the
// mean that accounts for the series' autocorrelation.
//
// The interval is that of non-overlapping batch means (Schmeiser 1982, "Batch size effects in
// the analysis of simulation output", Oper. Res. 30:556): the last B m samples (m = floor(n/B);
// the first n mod B < B, the ones nearest the transient, are left out of the batches, not of the
// mean) are cut into B = 10 batches of m consecutive samples; when m is long against the
// correlation time the batch means are nearly independent and normal, so
//     half-width = t_{0.975, B-1} s_b / sqrt(B),   s_b the sample deviation of the batch means.
// Why a fixed B = 10 and not sqrt(n) batches: the cut's steady parts are short (about 150 rows)
// and correlated over several rows; the batch-means variance is low by about tau/(2m) (tau the
// integrated autocorrelation time in samples; exact for AR(1): (tau^2 - 1)/(2 tau m)), so long
// batches matter more than many batches. Schmeiser found that 10 to 30 batches lose little
// against the best count for any correlation, and that fewer batches are the safer side; 10
// batches pay with the t quantile of 9 degrees of freedom (2.262 against 1.96 for a known
// variance), which is the honest price of estimating the variance from 10 numbers.
//
// The cross-check is the integrated autocorrelation time tau = 1 + 2 sum_k rho_k (samples),
// by Geyer's initial monotone sequence estimator (Geyer 1992, "Practical Markov chain Monte
// Carlo", Stat. Sci. 7:473, sec. 3.3), and the effective sample size n / tau. It does not enter
// the interval; it says whether the batches are long enough: with m < 5 tau the batch-means
// variance may be low by more than 10 % (the interval by 5 %), and batches_short() says so.
//
// Fewer than 20 samples (2 per batch): no interval and no tau (NaN), never a made-up number.
#pragma once

#include <cmath>
#include <cstddef>
#include <vector>

namespace swarf {

constexpr std::size_t kSteadyBatches = 10;     ///< batches of the batch-means interval
constexpr std::size_t kSteadyMinSamples = 20;  ///< fewer samples: no interval (2 per batch)
constexpr double kSteadyBatchesPerTau = 5.0;   ///< batch length below this many tau: batches_short()

struct SteadyStats {
  std::size_t samples = 0;            ///< n
  double mean = NAN;                  ///< over all n samples (NaN without samples)
  double std = NAN;                   ///< sample standard deviation (n - 1; NaN below 2 samples)
  double ci95 = NAN;                  ///< 95 % half-width of the mean by batch means (NaN: unavailable)
  std::size_t batches = 0;            ///< B (0: no interval)
  std::size_t batch_size = 0;         ///< m, samples per batch
  double autocorrelation_time = NAN;  ///< integrated, tau = 1 + 2 sum rho_k, in samples (Geyer)
  double effective_samples = NAN;     ///< n / tau

  bool has_interval() const { return std::isfinite(ci95); }
  /// The batches are shorter than kSteadyBatchesPerTau autocorrelation times: the interval may be
  /// too narrow (by more than about 5 %).
  bool batches_short() const {
    return has_interval() && std::isfinite(autocorrelation_time) &&
           double(batch_size) < kSteadyBatchesPerTau * autocorrelation_time;
  }
};

/// Mean, deviation, batch-means interval and autocorrelation time of x (equal intervals).
SteadyStats steady_stats(const std::vector<double>& x);

/// The means of B batches of m = floor(n/B) consecutive samples, the last B m samples of x (the
/// first n mod B are left out). Empty if m < 2 (n < 2B).
std::vector<double> batch_means(const std::vector<double>& x, std::size_t batches = kSteadyBatches);
/// The medians of the same batches (for the batch-median interval of a median).
std::vector<double> batch_medians(const std::vector<double>& x, std::size_t batches = kSteadyBatches);

/// 95 % half-width of the mean of the quantity whose batch values are given:
/// t_{0.975, B-1} s_b / sqrt(B). NaN for fewer than 2 batches.
double batch_ci95(const std::vector<double>& batch_values);

/// 95 % half-width of a smooth function g of two means, linearised about the means (delta
/// method over the batches): the batch values of g are gx bx_k + gy by_k, with gx, gy the partial
/// derivatives of g at the means and bx, by the two series' batch means over the same rows.
double batch_ci95_linear(const std::vector<double>& bx, const std::vector<double>& by, double gx, double gy);

/// Integrated autocorrelation time (samples) by Geyer's initial monotone sequence estimator:
/// with the autocovariances c_k (1/n normalisation, about the sample mean), the pair sums
/// G_j = c_{2j} + c_{2j+1} are summed while positive and taken non-increasing, and
/// tau = (2 sum_j G_j - c_0) / c_0. NaN for fewer than kSteadyMinSamples samples or no variance.
double integrated_autocorrelation_time(const std::vector<double>& x);

/// The 0.975 quantile of Student's t distribution with dof degrees of freedom (dof >= 1; NaN
/// for 0), from Boost.Math.
double student_t_975(std::size_t dof);

}  // namespace swarf
