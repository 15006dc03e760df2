// membrane_waves.cpp: waves in a clamped, pre-tensioned membrane excited at a point (paper
// section 5.3, figure 7's set-up without the doll), run through swarf's case parser, model and
// step. The site nearest the sheet's centre follows a raised-cosine pulse of duration tau, out
// of plane (transverse wave) or along x (in-plane longitudinal wave); the sites of its row to
// the +x side are probes. Writes, into the directory given as the first argument, one CSV per
// run (time and the probes' displacement component) and cases.csv (the closed forms and the
// set-up); analyse.py measures the speeds and draws the plots.
//
// The sheet: 120 x 120 mm, E = 5 MPa, t = 0.5 mm, rho = 1200 kg/m^3 (a rubber sheet), tension
// T = 37.5 N/m (rod pre-strain 1 %), clamped edges; two resolutions, R = 0.25 and 0.125 mm. The
// pulse's wave length c tau is 10 mm (20 and 40 spacings); the probes lie 1 to 5 wave lengths
// from the source, and the run ends before the reflection from the clamped edge (6 wave lengths
// away) reaches the farthest probe.
#include <fmt/format.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

#include "../../tests/scenes/membrane_pulse.h"
#include "setup/case_config.h"
#include "setup/model.h"
#include "swarf/simulation.h"

using namespace swarf;

namespace {

constexpr double kLength = 120e-3, kWave = 10e-3;

struct Run {
  const char* name;
  bool transverse;
  double radius;
};

std::string case_text(double radius) {
  return fmt::format(R"(
[membrane]
length = {0}
width = {0}
radius = {1}
thickness = 0.5e-3
youngs_modulus = 5e6
density = 1200.0
pre_tension = 37.5
clamp_edges = true
[integrator]
end_time = 1.0
[output]
progress = false
)",
                     kLength, radius);
}

void run(const Run& r, const std::string& dir, std::FILE* cases) {
  Model m = build_model(parse_case(case_text(r.radius), r.name, {}));
  const Derived& d = m.derived;
  const double c = r.transverse ? d.membrane_wave_transverse : d.membrane_wave_longitudinal;
  const double tau = kWave / c, amplitude = 1e-3 * kWave;
  // The source: the site nearest the centre; the probes: its row's sites towards +x.
  const int comp = r.transverse ? 2 : 0;
  const test::MembranePulse pulse = test::add_membrane_pulse(m, Vec3(0.5 * kLength, 0.5 * kLength, 0.0), comp,
                                                             amplitude, tau, 0.5 * kWave, 5.5 * kWave);
  const auto& probes = pulse.probes;
  const auto& dist = pulse.distance;

  Simulation sim(m, m.step);
  const double end = 6.5 * kWave / c;
  const int stride = std::max(1, static_cast<int>(tau / 64.0 / sim.dt()));
  std::ofstream out(fmt::format("{}/waves_{}.csv", dir, r.name));
  out << "time_s";
  for (double x : dist) out << fmt::format(",r_{:.6e}", x);
  out << "\n";
  auto row = [&] {
    out << fmt::format("{:.9e}", sim.time());
    for (auto i : probes)
      out << fmt::format(",{:.9e}", m.particles.position[i][comp] - m.particles.initial_position[i][comp]);
    out << "\n";
  };
  row();
  while (sim.time() < end) {
    sim.step();
    if (sim.steps() % stride == 0) row();
  }
  std::fprintf(cases, "%s,%d,%.9e,%zu,%zu,%.9e,%.9e,%.9e,%.9e,%.9e,%.9e,%.9e,%.9e,%.9e,%.9e\n", r.name,
               r.transverse ? 1 : 0, r.radius, m.particles.size(), probes.size(), d.nn_distance, d.particle_mass,
               d.rod_stiffness, d.membrane_pre_strain * d.rod_stiffness * d.nn_distance / (1 + d.membrane_pre_strain),
               c, tau, sim.dt(), d.dt_stable, d.membrane_dt_cfl, d.membrane_wave_shear);
  std::fflush(cases);
  std::printf("%s: %zu particles, %zu probes, c = %.5g m/s, tau = %.4g s, dt = %.4g s, %lld steps\n", r.name,
              m.particles.size(), probes.size(), c, tau, sim.dt(), static_cast<long long>(sim.steps()));
  std::fflush(stdout);
}

}  // namespace

int main(int argc, char** argv) {
  const std::string dir = argc > 1 ? argv[1] : SWARF_MEMBRANE_DIR;
  const std::vector<Run> runs{{"transverse_coarse", true, 0.25e-3},
                              {"longitudinal_coarse", false, 0.25e-3},
                              {"longitudinal_fine", false, 0.125e-3},
                              {"transverse_fine", true, 0.125e-3}};
  std::FILE* cases = std::fopen((dir + "/cases.csv").c_str(), "w");
  if (!cases) {
    std::fprintf(stderr, "cannot write %s/cases.csv\n", dir.c_str());
    return 2;
  }
  std::fprintf(cases,
               "run,transverse,radius_m,particles,probes,spacing_m,mass_kg,bond_stiffness_N_per_m,bond_force_N,"
               "closed_form_speed_m_per_s,tau_s,dt_s,dt_stable_s,dt_cfl_s,shear_speed_m_per_s\n");
  for (const auto& r : runs)
    if (argc <= 2 || r.name == std::string(argv[2])) run(r, dir, cases);
  std::fclose(cases);
  return 0;
}
