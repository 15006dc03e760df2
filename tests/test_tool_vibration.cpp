// test_tool_vibration.cpp: a compliant tool's analysis (postprocess/tool_vibration.h) against
// closed forms: a sinusoid's amplitude spectrum, and a mounted mass under a step force, whose
// deflection rings at the damped frequency and settles at F / k.
#include <gtest/gtest.h>

#include <cmath>

#include "postprocess/tool_vibration.h"

namespace swarf {
namespace {

// A sinusoid of amplitude A at a frequency of the grid (whole cycles over the record) reads A
// there: the Hann window's coherent gain is divided out, and its side lobes fall off so fast
// that the image at -f0 (25 bins away here) adds below 1e-6 of A. The trapezoid weights of
// the rows make that hold to rounding for equal spacing; the tolerance 1e-6 is the image's.
TEST(ToolVibration, ASinusoidReadsItsAmplitudeAtItsFrequency) {
  const double T = 1e-4, f0 = 50e3, A = 3e-6;  // s, Hz (5 cycles), m
  std::vector<double> t, x;
  for (int i = 0; i <= 400; ++i) {
    t.push_back(i * T / 400);
    x.push_back(7e-6 + A * std::sin(2 * M_PI * f0 * t.back() + 0.3));
  }
  const std::vector<double> f{f0, 2 * f0, f0 + 0.25 / T};
  const auto a = amplitude_spectrum(t, x, f);
  EXPECT_NEAR(a[0], A, 1e-6 * A);
  EXPECT_LT(a[1], 1e-6 * A);  // another whole number of cycles: the window's zeros
  // A quarter bin off: Hann's scalloping loss, sinc-like, 0.951 of the peak for 1/4 bin
  // (|W(1/4)| / |W(0)| of the Hann window, (sin(pi/4)/(pi/4)) / (1 - 1/16)).
  const double d = 0.25, loss = std::sin(M_PI * d) / (M_PI * d) / (1 - d * d);
  EXPECT_NEAR(a[2], A * loss, 2e-3 * A);
}

// m d'' + c d' + k d = F (a step at t = 0, from rest): d(t) = F/k (1 - e^{-z w t} (cos wd t +
// z/sqrt(1 - z^2) sin wd t)). The analysis finds the peak of the deflection's spectrum within
// one grid step (1/(4 T)) of the damped frequency, the steady mean at F/k within the ringing's
// remaining average over the steady rows, and reports the mount's closed forms.
TEST(ToolVibration, AMountedMassUnderAStepForceRingsAtItsFrequencyAndSettlesAtFOverK) {
  const ToolMount mount{1e10, 2e10, 0.025, 0.0};  // N/m/m, kg/m
  ToolMount damped = mount;
  const double zeta = 0.02, k = mount.stiffness_x, m = mount.mass;
  damped.damping = 2 * zeta * std::sqrt(k * m);
  const double w = std::sqrt(k / m), wd = w * std::sqrt(1 - zeta * zeta);
  const double Fc = 3e5, Ft = 1e5;  // N/m
  ToolSeries s;
  const double T = 2e-4;  // s
  for (int i = 0; i <= 400; ++i) {
    const double t = i * T / 400, e = std::exp(-zeta * w * t);
    const double ring = 1 - e * (std::cos(wd * t) + zeta / std::sqrt(1 - zeta * zeta) * std::sin(wd * t));
    s.time.push_back(t);
    s.fc.push_back(Fc);
    s.ft.push_back(Ft);
    s.deflection_x.push_back(-Fc / k * ring);
    s.deflection_z.push_back(Ft / mount.stiffness_z * ring);
  }
  const ToolVibration tv = analyze_tool(damped, s, 1e-4);
  const auto& j = tv.summary;
  EXPECT_NEAR(j["natural_frequency_x_Hz"].get<double>(), w / (2 * M_PI), 1e-9 * w);
  EXPECT_NEAR(j["natural_frequency_z_Hz"].get<double>(), std::sqrt(2.0) * w / (2 * M_PI), 1e-9 * w);
  EXPECT_NEAR(j["damping_ratio_x"].get<double>(), zeta, 1e-12);
  EXPECT_NEAR(j["static_deflection_x_m"].get<double>(), -Fc / k, 1e-12 * Fc / k);
  EXPECT_NEAR(j["static_deflection_z_m"].get<double>(), Ft / mount.stiffness_z, 1e-12);
  // The ring has decayed to e^{-z w T/2} = 0.28 by the steady rows and averages out over their
  // ~10 cycles to within a few % of its amplitude: 2 % of F/k.
  EXPECT_NEAR(j["deflection_x_mean_m"].get<double>(), -Fc / k, 0.02 * Fc / k);
  const double grid = 0.25 / T;
  EXPECT_NEAR(j["deflection_x_peak_frequency_Hz"].get<double>(), wd / (2 * M_PI), grid);
  EXPECT_NEAR(j["deflection_z_peak_frequency_Hz"].get<double>(), wd / (2 * M_PI), grid);  // (the same ring)
  EXPECT_NEAR(j["spectrum_resolution_Hz"].get<double>(), 1 / T, 1e-9 / T);
  ASSERT_FALSE(tv.spectra.frequency.empty());
  EXPECT_NEAR(tv.spectra.frequency.back(), 0.5 * 400 / T, grid);  // up to the rows' Nyquist frequency
  // The constant forces have no spectrum beyond the mean.
  for (double a : tv.spectra.fc) EXPECT_LT(a, 1e-9 * Fc);
}

}  // namespace
}  // namespace swarf
