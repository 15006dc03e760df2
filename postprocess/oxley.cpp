// oxley.cpp: Oxley's predictive machining theory (see oxley.h for the equations and sources).
#include "postprocess/oxley.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <sstream>

#include "swarf/core/errors.h"

namespace swarf {
namespace {

constexpr double kSqrt3 = 1.7320508075688772;
constexpr double kPi = std::numbers::pi;
// Search ranges. phi: the shear angle. C: Oxley's strain-rate constant. delta: secondary zone
// thickness over chip thickness.
constexpr double kPhiMin = 1.0 * kPi / 180, kPhiMax = 60.0 * kPi / 180;
constexpr int kPhiGrid = 118;  // 0.5 deg steps
constexpr double kCMin = 1.0, kCMax = 20.0;
constexpr int kCGrid = 19;
constexpr double kDeltaMin = 0.005, kDeltaMax = 0.5;
constexpr int kDeltaGrid = 25;  // log-spaced
constexpr int kBisections = 40;
// Temperatures are searched in [T_0, T_0 + kMaxRise] (and below T_melt): bounded even with no
// thermal softening. Properties k(T), c(T) are floored at 10 % of their value at T_0 so that a
// linear fit extrapolated far beyond its range never turns negative.
constexpr double kMaxRise = 3000;

void require(bool ok, const char* field, double value, const char* what) {
  if (ok) return;
  std::ostringstream s;
  s << "oxley: " << field << " = " << value << ": " << what;
  throw InputError(s.str());
}

struct Model {
  OxleyCut cut;
  OxleyMaterial m;

  double conductivity(double t) const {
    const double k0 = m.conductivity + m.conductivity_slope * (cut.initial_temperature - m.property_t0);
    return std::max(m.conductivity + m.conductivity_slope * (t - m.property_t0), 0.1 * k0);
  }
  double heat_capacity(double t) const {
    const double c0 = m.heat_capacity + m.heat_capacity_slope * (cut.initial_temperature - m.property_t0);
    return std::max(m.heat_capacity + m.heat_capacity_slope * (t - m.property_t0), 0.1 * c0);
  }
  double t_max() const { return std::min(m.t_melt, cut.initial_temperature + kMaxRise); }

  /// Johnson-Cook equivalent flow stress, Pa.
  double flow_stress(double eps, double epsdot, double t) const {
    const double hard = m.jc_a + m.jc_b * std::pow(std::max(eps, 0.0), m.jc_n);
    const double rate = 1 + m.jc_c * std::log(std::max(epsdot / m.reference_strain_rate, 1.0));
    double soft = 1;
    if (std::isfinite(m.t_melt)) {
      const double ts = std::clamp((t - m.t_ref) / (m.t_melt - m.t_ref), 0.0, 1.0);
      soft = 1 - std::pow(ts, m.jc_m);
    }
    return hard * rate * soft;
  }
  /// Local strain hardening exponent d ln(sigma) / d ln(eps) at eps.
  double n_eq(double eps) const {
    const double be = m.jc_b * std::pow(eps, m.jc_n);
    return m.jc_n * be / (m.jc_a + be);
  }
  /// beta, fraction of the primary zone's heat conducted into the work (Boothroyd, as in Oxley).
  static double beta(double rt_tan_phi) {
    const double x = std::max(rt_tan_phi, 1e-12);
    const double b = x <= 10 ? 0.5 - 0.35 * std::log10(x) : 0.3 - 0.15 * std::log10(x);
    return std::clamp(b, 0.0, 1.0);
  }

  /// Bisection for the root of the decreasing g on [lo, hi]; g(lo) >= 0 assumed.
  template <class G>
  static double decreasing_root(G g, double lo, double hi) {
    if (g(hi) >= 0) return hi;
    for (int i = 0; i < kBisections; ++i) {
      const double mid = 0.5 * (lo + hi);
      (g(mid) >= 0 ? lo : hi) = mid;
    }
    return 0.5 * (lo + hi);
  }

  struct State {
    bool valid = false;
    double fc = 0, ft = 0, hc = 0, lc = 0, t_ab = 0, t_int = 0, k_ab = 0;
    double tau_int = 0, k_chip = 0, sigma_n = 0, sigma_n_b = 0;
  };

  State evaluate(double phi, double c, double delta) const {
    State s;
    const double v = cut.speed, h = cut.uncut_thickness, w = cut.width, a = cut.rake;
    const double t0 = cut.initial_temperature;
    if (std::cos(phi - a) <= 0) return s;
    const double l_ab = h / std::sin(phi);
    const double vs = v * std::cos(a) / std::cos(phi - a);
    const double vc = v * std::sin(phi) / std::cos(phi - a);
    const double eps_ab = std::cos(a) / (2 * kSqrt3 * std::sin(phi) * std::cos(phi - a));
    const double epsdot_ab = c * vs / (kSqrt3 * l_ab);
    const double neq = n_eq(eps_ab);
    const double tan_theta = 1 + 2 * (kPi / 4 - phi) - c * neq;
    if (tan_theta <= 0) return s;
    const double theta = std::atan(tan_theta);
    const double lambda = theta - phi + a;
    if (std::cos(lambda) <= 0 || lambda <= 0) return s;

    // Primary zone temperature: T = T_0 + eta dT_SZ(T), the right side falls with T.
    auto primary_rise = [&](double t) {
      const double rho_c = m.density * heat_capacity(t);
      const double rt = rho_c * v * h / conductivity(t);
      const double k_ab = flow_stress(eps_ab, epsdot_ab, t) / kSqrt3;
      const double fs = k_ab * l_ab * w;
      return (1 - beta(rt * std::tan(phi))) * m.taylor_quinney * fs * vs / (rho_c * h * v * w);
    };
    const double t_ab = decreasing_root([&](double t) { return t0 + m.eta * primary_rise(t) - t; }, t0, t_max());
    const double dt_sz = primary_rise(t_ab);
    const double k_ab = flow_stress(eps_ab, epsdot_ab, t_ab) / kSqrt3;
    if (k_ab <= 0) return s;
    const double fs = k_ab * l_ab * w;
    const double r = fs / std::cos(theta);
    const double f = r * std::sin(lambda), n = r * std::cos(lambda);
    const double hc = h * std::cos(phi - a) / std::sin(phi);
    const double lc = h * std::sin(theta) / (std::cos(lambda) * std::sin(phi)) * (1 + c * neq / (3 * tan_theta));

    // Chip: mean temperature T_C = T_0 + dT_SZ + dT_C(T_C), the properties taken at T_C
    // (bisection, bounded like T_AB); the rake face's T_int then follows from R_T at T_C.
    auto chip_rise = [&](double t) { return m.taylor_quinney * f * vc / (m.density * heat_capacity(t) * h * v * w); };
    const double t_c = decreasing_root([&](double t) { return t0 + dt_sz + chip_rise(t) - t; }, t0,
                                       t0 + dt_sz + chip_rise(t0) + 1);
    const double rt_c = m.density * heat_capacity(t_c) * v * h / conductivity(t_c);
    const double x = rt_c * hc / lc;
    const double dt_m = chip_rise(t_c) * std::pow(10.0, 0.06 - 0.195 * delta * std::sqrt(x) + 0.5 * std::log10(x));
    const double t_int = t0 + dt_sz + m.psi * dt_m;

    const double eps_m = lc / (kSqrt3 * delta * hc);
    const double eps_int = 2 * eps_ab + 0.5 * eps_m;
    const double epsdot_int = vc / (kSqrt3 * delta * hc);
    s.valid = true;
    s.fc = r * std::cos(lambda - a);
    s.ft = r * std::sin(lambda - a);
    s.hc = hc;
    s.lc = lc;
    s.t_ab = t_ab;
    s.t_int = t_int;
    s.k_ab = k_ab;
    s.tau_int = f / (lc * w);
    s.k_chip = flow_stress(eps_int, epsdot_int, t_int) / kSqrt3;
    s.sigma_n = n / (lc * w);
    s.sigma_n_b = k_ab * (1 + kPi / 2 - 2 * a - 2 * c * neq);
    return s;
  }

  /// The first sign change of g(x, ok) on a grid of `grid` steps over [lo, hi] (points where
  /// ok comes back false skipped), refined by bisection. NaN if none.
  template <class G>
  static double first_root(G g, double lo, double hi, int grid) {
    bool ok_prev = false;
    double x_prev = 0, g_prev = 0;
    for (int i = 0; i <= grid; ++i) {
      const double x = lo + (hi - lo) * i / grid;
      bool ok = false;
      const double gi = g(x, ok);
      if (ok && ok_prev && (g_prev < 0) != (gi < 0)) {
        double a = x_prev, b = x, ga = g_prev;
        for (int k = 0; k < kBisections; ++k) {
          const double mid = 0.5 * (a + b);
          bool okm = false;
          const double gm = g(mid, okm);
          if (!okm) break;
          if ((gm < 0) == (ga < 0)) {
            a = mid;
            ga = gm;
          } else {
            b = mid;
          }
        }
        return 0.5 * (a + b);
      }
      ok_prev = ok;
      x_prev = x;
      g_prev = gi;
    }
    return std::numeric_limits<double>::quiet_NaN();
  }

  /// phi where tau_int = k_chip, for given C and delta: the first root going up from kPhiMin.
  double solve_phi(double c, double delta) const {
    return first_root(
        [&](double phi, bool& ok) {
          const State s = evaluate(phi, c, delta);
          ok = s.valid;
          return s.tau_int - s.k_chip;
        },
        kPhiMin, kPhiMax, kPhiGrid);
  }

  struct Solution {
    bool found = false;
    double phi = 0, c = 0;
  };

  /// C where sigma_n = sigma_n_b (with phi solved for each C), for given delta.
  Solution solve_c(double delta) const {
    const double c = first_root(
        [&](double c, bool& ok) {
          const double phi = solve_phi(c, delta);
          ok = std::isfinite(phi);
          if (!ok) return 0.0;
          const State s = evaluate(phi, c, delta);
          ok = s.valid;
          return s.sigma_n - s.sigma_n_b;
        },
        kCMin, kCMax, kCGrid);
    if (!std::isfinite(c)) return {};
    const double phi = solve_phi(c, delta);
    if (!std::isfinite(phi)) return {};
    return {true, phi, c};
  }
};

}  // namespace

OxleyMaterial oxley_aisi1045_jaspers() {
  OxleyMaterial m;
  m.jc_a = 553.1e6;
  m.jc_b = 600.8e6;
  m.jc_n = 0.234;
  m.jc_c = 0.0134;
  m.jc_m = 1;
  m.reference_strain_rate = 1;
  m.t_ref = 293.15;
  m.t_melt = 1733;
  m.density = 7850;
  m.conductivity = 52.61;
  m.conductivity_slope = -0.0281;
  m.heat_capacity = 420;
  m.heat_capacity_slope = 0.504;
  m.property_t0 = 273.15;
  m.taylor_quinney = 1;
  m.eta = 0.9;
  m.psi = 0.7;
  return m;
}

OxleyResult oxley(const OxleyCut& cut, const OxleyMaterial& m) {
  auto positive = [](double x) { return std::isfinite(x) && x > 0; };
  require(positive(cut.speed), "speed", cut.speed, "must be a positive speed in m/s");
  require(positive(cut.uncut_thickness), "uncut_thickness", cut.uncut_thickness, "must be a positive thickness in m");
  require(positive(cut.width), "width", cut.width, "must be a positive width in m");
  require(std::isfinite(cut.rake) && std::abs(cut.rake) < kPi / 2, "rake", cut.rake, "must be in (-pi/2, pi/2) rad");
  require(positive(cut.initial_temperature), "initial_temperature", cut.initial_temperature,
          "must be a positive temperature in K");
  require(positive(m.jc_a), "jc_a", m.jc_a, "must be positive (Pa)");
  require(std::isfinite(m.jc_b) && m.jc_b >= 0, "jc_b", m.jc_b, "must be >= 0 (Pa)");
  require(std::isfinite(m.jc_n) && m.jc_n >= 0 && m.jc_n < 1, "jc_n", m.jc_n, "must be in [0, 1)");
  require(std::isfinite(m.jc_c) && m.jc_c >= 0, "jc_c", m.jc_c, "must be >= 0");
  require(positive(m.jc_m), "jc_m", m.jc_m, "must be positive");
  require(positive(m.reference_strain_rate), "reference_strain_rate", m.reference_strain_rate, "must be positive (1/s)");
  require(positive(m.t_ref), "t_ref", m.t_ref, "must be a positive temperature in K");
  require(m.t_melt > m.t_ref, "t_melt", m.t_melt, "must exceed t_ref (K; infinity allowed)");
  require(cut.initial_temperature < m.t_melt, "initial_temperature", cut.initial_temperature, "must be below t_melt");
  require(positive(m.density), "density", m.density, "must be positive (kg/m^3)");
  require(std::isfinite(m.conductivity_slope), "conductivity_slope", m.conductivity_slope, "must be finite");
  require(std::isfinite(m.heat_capacity_slope), "heat_capacity_slope", m.heat_capacity_slope, "must be finite");
  require(std::isfinite(m.property_t0), "property_t0", m.property_t0, "must be finite");
  const Model model{cut, m};
  require(std::isfinite(m.conductivity) &&
              m.conductivity + m.conductivity_slope * (cut.initial_temperature - m.property_t0) > 0,
          "conductivity", m.conductivity, "k(T_0) must be positive (W/(m K))");
  require(m.heat_capacity + m.heat_capacity_slope * (cut.initial_temperature - m.property_t0) > 0, "heat_capacity",
          m.heat_capacity, "c(T_0) must be positive (J/(kg K))");
  require(std::isfinite(m.taylor_quinney) && m.taylor_quinney > 0 && m.taylor_quinney <= 1, "taylor_quinney",
          m.taylor_quinney, "must be in (0, 1]");
  require(std::isfinite(m.eta) && m.eta > 0 && m.eta <= 1, "eta", m.eta, "must be in (0, 1]");
  require(std::isfinite(m.psi) && m.psi > 0 && m.psi <= 1, "psi", m.psi, "must be in (0, 1]");

  // delta: the least F_c over a log grid, then golden-section refinement between the grid
  // neighbours of the best point.
  OxleyResult best;
  bool any_phi = false;
  auto try_delta = [&](double delta) {
    const Model::Solution sol = model.solve_c(delta);
    if (!sol.found) {
      if (!any_phi) any_phi = std::isfinite(model.solve_phi(0.5 * (kCMin + kCMax), delta));
      return std::numeric_limits<double>::infinity();
    }
    any_phi = true;
    const Model::State s = model.evaluate(sol.phi, sol.c, delta);
    if (!s.valid) return std::numeric_limits<double>::infinity();
    if (!best.solved || s.fc < best.cutting_force) {
      best.solved = true;
      best.cutting_force = s.fc;
      best.thrust_force = s.ft;
      best.cutting_force_per_width = s.fc / cut.width;
      best.shear_angle = sol.phi;
      best.chip_thickness = s.hc;
      best.chip_ratio = cut.uncut_thickness / s.hc;
      best.primary_temperature = s.t_ab;
      best.rake_temperature = s.t_int;
      best.contact_length = s.lc;
      best.strain_rate_constant = sol.c;
      best.secondary_zone_ratio = delta;
      best.shear_flow_stress = s.k_ab;
      best.interface_shear_stress = s.tau_int;
    }
    return s.fc;
  };
  const double ratio = std::pow(kDeltaMax / kDeltaMin, 1.0 / (kDeltaGrid - 1));
  int i_best = -1;
  double fc_best = std::numeric_limits<double>::infinity();
  for (int i = 0; i < kDeltaGrid; ++i) {
    const double fc = try_delta(kDeltaMin * std::pow(ratio, i));
    if (fc < fc_best) {
      fc_best = fc;
      i_best = i;
    }
  }
  if (i_best >= 0) {
    double lo = std::log(kDeltaMin * std::pow(ratio, std::max(i_best - 1, 0)));
    double hi = std::log(kDeltaMin * std::pow(ratio, std::min(i_best + 1, kDeltaGrid - 1)));
    const double g = 0.5 * (std::sqrt(5.0) - 1);
    double x1 = hi - g * (hi - lo), x2 = lo + g * (hi - lo);
    double f1 = try_delta(std::exp(x1)), f2 = try_delta(std::exp(x2));
    for (int k = 0; k < 12; ++k) {
      if (f1 < f2) {
        hi = x2;
        x2 = x1;
        f2 = f1;
        x1 = hi - g * (hi - lo);
        f1 = try_delta(std::exp(x1));
      } else {
        lo = x1;
        x1 = x2;
        f1 = f2;
        x2 = lo + g * (hi - lo);
        f2 = try_delta(std::exp(x2));
      }
    }
  }
  if (!best.solved) {
    best.reason = any_phi ? "no strain-rate constant C in [1, 20] balances the normal stress at the "
                            "cutting edge"
                          : "no shear angle makes the tool-chip interface shear stress equal the chip's "
                            "flow stress (without enough thermal softening the rake-face layer never "
                            "gets soft enough)";
  }
  return best;
}

}  // namespace swarf
