// membrane_pulse.h: the wave scene the membrane test and validation/membrane share: the site of
// a [membrane] nearest a point follows a raised-cosine pulse (1 - cos(2 pi t / tau)) / 2 of one
// displacement component, then is held at rest; the sites of its row on the +x side (a bond
// direction) within a range of distances are the probes. The time of a probe's peak is found
// to a fraction of the sampling interval by a parabola through the samples around it.
#pragma once

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "setup/model.h"

namespace swarf::test {

struct MembranePulse {
  std::size_t source = 0;
  std::vector<std::size_t> probes;  ///< particle indices, by increasing distance
  std::vector<double> distance;     ///< m from the source
};

/// Adds the pulse as a group named "source" (component 'comp': 0 = x, 2 = z) at the site nearest
/// 'centre'; probes between r_min and r_max (m).
inline MembranePulse add_membrane_pulse(Model& m, const Vec3& centre, int comp, double amplitude, double tau,
                                        double r_min, double r_max) {
  MembranePulse s;
  for (std::size_t i = 0; i < m.particles.size(); ++i)
    if ((m.particles.position[i] - centre).norm() < (m.particles.position[s.source] - centre).norm()) s.source = i;
  const Vec3 x0 = m.particles.position[s.source];
  for (std::size_t i = 0; i < m.particles.size(); ++i) {
    const Vec3 u = m.particles.position[i] - x0;
    if (std::abs(u[1]) < 1e-3 * m.derived.nn_distance && u[0] > r_min && u[0] < r_max) {
      s.probes.push_back(i);
      s.distance.push_back(u[0]);
    }
  }
  Motion pulse;
  pulse.kind = Motion::Kind::Table;
  for (int k = 0; k <= 128; ++k) {  // piecewise linear through 129 points of the pulse
    const double t = tau * k / 128.0;
    Vec3 u = Vec3::Zero();
    u[comp] = amplitude * 0.5 * (1.0 - std::cos(2.0 * M_PI * t / tau));
    pulse.time.push_back(t);
    pulse.displacement.push_back(u);
  }
  const auto dofs = static_cast<std::uint8_t>(1u << comp);
  m.particles.group[s.source] = static_cast<std::int32_t>(m.groups.size());
  m.particles.prescribed[s.source] = dofs;
  m.groups.push_back(Group{"source", dofs, pulse, {static_cast<std::int32_t>(s.source)}});
  return s;
}

/// The time of the largest of 'u' (sampled at 't'), refined by a parabola through its neighbours.
inline double peak_time(const std::vector<double>& t, const std::vector<double>& u) {
  std::size_t k = std::max_element(u.begin(), u.end()) - u.begin();
  k = std::clamp<std::size_t>(k, 1, u.size() - 2);
  const double den = u[k - 1] - 2 * u[k] + u[k + 1];
  const double s = den != 0 ? 0.5 * (u[k - 1] - u[k + 1]) / den : 0.0;
  return t[k] + s * (t[k + 1] - t[k]);
}

/// The speed 1 / slope of the least-squares line through (distance, peak time), m/s.
inline double fitted_speed(const std::vector<double>& r, const std::vector<double>& t_peak) {
  Eigen::MatrixXd a(r.size(), 2);
  Eigen::VectorXd b(r.size());
  for (std::size_t i = 0; i < r.size(); ++i) {
    a(i, 0) = 1.0;
    a(i, 1) = r[i];
    b(i) = t_peak[i];
  }
  const Eigen::Vector2d x = a.colPivHouseholderQr().solve(b);
  return 1.0 / x(1);
}

}  // namespace swarf::test
