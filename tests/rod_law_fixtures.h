// rod_law_fixtures.h: what the rate and Johnson-Cook law tests share (test_rate_rod_law.cpp,
// test_johnson_cook_rod_law.cpp): the two base laws they scale, the single slope and a hardening
// curve with the same yield stress (numbers chosen so that the closed forms are easy to write by
// hand), and one rod pulled at a constant rate through a case file and the Simulation.
#pragma once

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <functional>
#include <string>

#include "lattice_gen/lattice_file.h"
#include "setup/case_config.h"
#include "setup/model.h"
#include "swarf/laws/rod_law.h"
#include "swarf/simulation.h"

namespace swarf::test {

constexpr double kE = 200e9, kEpsY = 1e-3, kK = 20e9;  // Pa, 1, Pa: s_y = 200 MPa, H = E k/(E - k)

/// The paper's single slope: E 200 GPa, s_y 200 MPa, k 20 GPa, unbreakable.
inline RodLaw linear_law() {
  RodLaw law;
  law.youngs_modulus = kE;
  law.yield_strain = kEpsY;
  law.hardening = kK;
  law.tensile_strength = HUGE_VAL;
  return law;
}

/// A hardening curve: flow stress 200, 400, 500 MPa at plastic strain 0, 0.01, 0.11; slope 1 GPa beyond.
inline RodLaw curve_law() {
  RodLaw law = linear_law();
  law.hardening = 0.0;
  law.flow.points = 3;
  law.flow.plastic_strain = {0.0, 0.01, 0.11};
  law.flow.stress = {200e6, 400e6, 500e6};
  return law;
}

/// One rod (rest length 1 mm, E 200 GPa, eps_y 1e-3, perfectly plastic) between two particles
/// held by grips, the left fixed and the right moving at v along x: the strain is v t / L0 and the
/// rate v / L0 at every step.
struct PulledRod {
  static constexpr double kRadius = 0.5e-3, kL0 = 2 * kRadius;
  double v = 0.05;  ///< m/s: 50/s
  std::string lattice;

  explicit PulledRod(const std::filesystem::path& dir) : lattice((dir / "rod.h5").string()) {
    Lattice lat;
    lat.position = {Vec3(0, 0, 0), Vec3(kL0, 0, 0)};
    lat.radius = {kRadius, kRadius};
    lat.rods = {{0, 1}};
    lat.rest_length = {kL0};
    write_lattice(lattice, lat);
  }
  double rate() const { return v / kL0; }
  /// The case, with more [rod] and [integrator] lines.
  std::string case_text(const std::string& rod_lines, const std::string& integrator_lines = "") const {
    return fmt::format(
        "[workpiece]\nlattice_file = \"{}\"\n[rod]\nyoungs_modulus = 200e9\nyield_strain = 1e-3\n{}"
        "[integrator]\nend_time = 1\n{}"
        "[[group]]\nname = \"left\"\nside = \"x-\"\n"
        "[[group]]\nname = \"right\"\nside = \"x+\"\nmotion = \"velocity\"\nvelocity = [{}, 0.0, 0.0]\n",
        lattice, rod_lines, integrator_lines, v);
  }
  struct Result {
    double stress = 0;     ///< at the end, Pa
    double deviation = 0;  ///< largest |sigma - min(E eps, S s_y)| / (S s_y) over the steps, 1
    int steps = 0, flowing = 0;
    std::string law;  ///< describe(law).name
  };
  /// Runs the case until the strain is 3 S eps_y ('setup' may change the model first), comparing
  /// the stress with the closed form min(E eps, S s_y) at every step.
  Result run(const std::string& toml, double S, const std::function<void(Model&)>& setup = {}) const {
    Model m = build_model(parse_case(toml, "pulled_rod", {}));
    if (setup) setup(m);
    Simulation sim(m, m.step);
    Result r;
    r.law = describe(m.rods.law).name;
    const double sy = kE * kEpsY;
    while (sim.time() * rate() < 3 * S * kEpsY) {
      sim.step();
      ++r.steps;
      const double eps = (m.particles.position[1].x() - m.particles.position[0].x() - kL0) / kL0;
      r.deviation = std::max(r.deviation, std::abs(m.rods.stress[0] - std::min(kE * eps, S * sy)) / (S * sy));
      r.flowing += m.rods.shift[0] != 0.0;
    }
    r.stress = m.rods.stress[0];
    return r;
  }
};

}  // namespace swarf::test
