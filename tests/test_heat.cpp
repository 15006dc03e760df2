// test_heat.cpp: the heat (issue 33; systems/thermal_system.h, laws/heat_conduction.h) against
// the scheme's own recurrence, the lattice's closed forms (steady bar, the transient series)
// and the energy balance of a plastically stretched bar.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <random>

#include "scenes/shear_layers.h"
#include "scenes/tiny_cut.h"
#include "setup/case_config.h"
#include "setup/model.h"
#include "swarf/core/errors.h"
#include "swarf/laws/heat_conduction.h"
#include "swarf/measure/particle_fields.h"
#include "swarf/simulation.h"
#include "swarf/systems/thermal_system.h"

namespace swarf {
namespace {

constexpr double kRho = 7870.0, kC = 486.0, kK = 50.7;  // C45: kg/m^3, J/(kg K), W/(m K)

// An FCC bar of steel particles (radius 14 um), periodic across y, with the two x faces in
// groups 'cold' and 'hot' (one layer each); heat with C45's properties, both groups held.
Model steel_bar(int nx, int nz, const std::string& extra = "") {
  return build_model(parse_case(fmt::format(R"([workpiece]
cells = [{}, 2, {}]
radius = 14e-6
periodic_width = true
[material]
density = {}
[rod]
youngs_modulus = 200e9
tensile_strength = 1e12
[integrator]
scheme = "newmark"
end_time = 1
[[group]]
name = "cold"
side = "x-"
layers = 1
[[group]]
name = "hot"
side = "x+"
layers = 1
[heat]
heat_capacity = {}
conductivity = {}
held_groups = ["cold", "hot"]
{}
)",
                                            nx, nz, kRho, kC, kK, extra),
                                "bar", {}));
}

double lowest(const Particles& p, int axis) {
  double v = HUGE_VAL;
  for (const Vec3& x : p.position) v = std::min(v, x[axis]);
  return v;
}
double highest(const Particles& p, int axis) {
  double v = -HUGE_VAL;
  for (const Vec3& x : p.position) v = std::max(v, x[axis]);
  return v;
}
int layers(const Particles& p, int axis, double spacing) {
  return static_cast<int>(std::lround((highest(p, axis) - lowest(p, axis)) / spacing)) + 1;
}

// The explicit limit min C_i / sum_j G_ij over the particles not held (rods only).
double explicit_limit(const World& w, const std::vector<std::uint8_t>& held) {
  const auto& p = w.particles;
  const auto& r = w.rods;
  std::vector<double> g(p.size(), 0.0);
  for (std::size_t k = 0; k < r.size(); ++k) {
    const double G = rod_conductance(w.heat.conductivity, r.rest_length[k]);
    g[r.ends[k][0]] += G;
    g[r.ends[k][1]] += G;
  }
  double lim = HUGE_VAL;
  for (std::size_t i = 0; i < p.size(); ++i)
    if (!held[i] && g[i] > 0) lim = std::min(lim, p.mass[i] * w.heat.heat_capacity / g[i]);
  return lim;
}

std::vector<std::uint8_t> held_flags(const World& w) {
  std::vector<std::uint8_t> h(w.particles.size(), 0);
  for (std::size_t i = 0; i < h.size(); ++i) {
    const int g = w.particles.group[i];
    h[i] = g >= 0 && static_cast<std::size_t>(g) < w.heat.held.size() && w.heat.held[g];
  }
  return h;
}

// One conduction is the forward Euler step of the lattice's heat equation, particle by
// particle: T_i' = T_i + h/(m_i c) sum_j G_ij (T_j - T_i), G = k d / (2 sqrt 2), the held
// particles unchanged; and it conserves sum m c T plus what the clamps took. Tolerance: the
// rounding of a dozen-term sum (1e-12 relative to the temperature).
TEST(Heat, OneConductionIsTheDiscreteRecurrence) {
  Model w = steel_bar(3, 2);
  const auto held = held_flags(w);
  auto& p = w.particles;
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(300.0, 900.0);
  for (std::size_t i = 0; i < p.size(); ++i) p.temperature[i] = u(rng);
  const std::vector<double> T0 = p.temperature;
  ThermalSystem th;
  th.setup(w);
  EXPECT_EQ(p.temperature, T0);  // (every particle had a temperature: none is replaced)
  const double h = 0.3 * explicit_limit(w, held);
  std::vector<double> expect = T0;
  const auto& r = w.rods;
  for (std::size_t k = 0; k < r.size(); ++k) {
    const auto [i, j] = r.ends[k];
    const double q = h * rod_conductance(kK, r.rest_length[k]) * (T0[j] - T0[i]);
    if (!held[i]) expect[i] += q / (p.mass[i] * kC);
    if (!held[j]) expect[j] -= q / (p.mass[j] * kC);
  }
  EnergyLedger ledger;
  ContactSystem none;
  th.heat(StepContext{w, 0.0, h, 0.25, 0.5, false, ledger}, none, {});
  EXPECT_EQ(th.conductions(), 1);
  EXPECT_DOUBLE_EQ(th.conduction_step(), h);
  double before = 0, after = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    EXPECT_NEAR(p.temperature[i], expect[i], 1e-12 * T0[i]) << i;
    if (held[i]) {
      EXPECT_EQ(p.temperature[i], T0[i]);
    }
    before += p.mass[i] * kC * T0[i];
    after += p.mass[i] * kC * p.temperature[i];
  }
  EXPECT_NEAR(after + ledger.heat_to_clamps, before, 1e-12 * before);
  EXPECT_NE(ledger.heat_to_clamps, 0.0);
}

// A conduction longer than the limit is split into sub-steps within it (stability_fraction of
// the limit), and the next interval is that much.
TEST(Heat, AConductionBeyondTheLimitIsSubStepped) {
  Model w = steel_bar(3, 2, "stability_fraction = 0.5");
  const auto held = held_flags(w);
  ThermalSystem th;
  th.setup(w);
  const double lim = explicit_limit(w, held);
  EnergyLedger ledger;
  ContactSystem none;
  th.heat(StepContext{w, 0.0, 3.2 * lim, 0.25, 0.5, false, ledger}, none, {});
  EXPECT_NEAR(th.conduction_limit(), lim, 1e-12 * lim);
  EXPECT_NEAR(th.conduction_step(), 3.2 * lim / 7.0, 1e-12 * lim);  // ceil(3.2 / 0.5) = 7 sub-steps
  // Steps shorter than the interval only gather time.
  th.heat(StepContext{w, 0.0, 0.2 * lim, 0.25, 0.5, false, ledger}, none, {});
  EXPECT_EQ(th.conductions(), 1);
  th.heat(StepContext{w, 0.0, 0.3 * lim, 0.25, 0.5, false, ledger}, none, {});
  EXPECT_EQ(th.conductions(), 2);
  // At most 1000 sub-steps in a step: beyond, the run stops with a SimulationError naming the
  // limit and the key, instead of sub-stepping without end (a diffusivity no solid has, or a
  // tiny heated tool: found by the case_model fuzzer).
  th.heat(StepContext{w, 0.0, 499.9 * lim, 0.25, 0.5, false, ledger}, none, {});
  EXPECT_NEAR(th.conduction_step(), 499.9 * lim / 1000.0, 1e-12 * lim);
  try {
    th.heat(StepContext{w, 0.0, 500.1 * lim, 0.25, 0.5, false, ledger}, none, {});
    ADD_FAILURE() << "no error";
  } catch (const SimulationError& e) {
    EXPECT_NE(std::string(e.what()).find("1001 sub-steps"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("heat.heat_capacity"), std::string::npos) << e.what();
  }
}

// Runs the bar's conduction (no mechanics) for 'time' s in steps of the conduction interval.
void conduct_for(World& w, ThermalSystem& th, EnergyLedger& ledger, double time, double step) {
  ContactSystem none;
  for (double t = 0; t < time - 0.5 * step; t += step)
    th.heat(StepContext{w, t, step, 0.25, 0.5, false, ledger}, none, {});
}

// The steady bar. Ends held at T1 and T2 (x faces); the lattice's steady state is the linear
// profile (every particle not held has neighbours symmetric in x, so a linear field has no net
// flux), and the heat through the bar is k g times its area, less the free faces' share: a
// slab of L particle layers along z has L layers of in-plane rods but L - 1 gaps of rods
// between layers, so the flux is k g W (a/2) (L - 1/2) exactly (W the period along y). Both
// to 1e-6 relative: the run is long enough (20 diffusion times) for the slowest mode to have
// decayed below that.
TEST(Heat, TheSteadyBarIsLinearWithTheLatticeConductivity) {
  Model w = steel_bar(8, 2);
  auto& p = w.particles;
  const double a = 2.0 * std::sqrt(2.0) * 14e-6;
  const double x0 = lowest(p, 0), x1 = highest(p, 0);
  const double T1 = 300.0, T2 = 500.0, g = (T2 - T1) / (x1 - x0);
  for (std::size_t i = 0; i < p.size(); ++i) p.temperature[i] = p.group[i] >= 0 ? T1 + g * (p.position[i][0] - x0) : T1;
  ThermalSystem th;
  th.setup(w);
  const double alpha = kK / (kRho * kC), Lx = x1 - x0;
  const double step = 0.5 * explicit_limit(w, held_flags(w));
  EnergyLedger ledger;
  conduct_for(w, th, ledger, 20.0 * Lx * Lx / (M_PI * M_PI * alpha), step);
  for (std::size_t i = 0; i < p.size(); ++i)
    EXPECT_NEAR(p.temperature[i], T1 + g * (p.position[i][0] - x0), 1e-6 * T2) << i;
  // The flux through the plane halfway between two layers near the middle.
  const double xm = x0 + (std::floor(0.5 * Lx / (0.5 * a)) + 0.5) * 0.5 * a;
  double flux = 0;
  for (std::size_t k = 0; k < w.rods.size(); ++k) {
    const auto [i, j] = w.rods.ends[k];
    const double xi = p.position[i][0], xj = p.position[j][0];
    if ((xi - xm) * (xj - xm) >= 0) continue;
    const double q = rod_conductance(kK, w.rods.rest_length[k]) * (p.temperature[i] - p.temperature[j]);
    flux += xi > xj ? q : -q;  // (from high x to low x: the hot end is at x1)
  }
  const int L = layers(p, 2, 0.5 * a);
  const double W = 2 * a;  // (cells[1] = 2)
  EXPECT_EQ(L, 4);
  EXPECT_NEAR(flux, kK * g * W * 0.5 * a * (L - 0.5), 1e-6 * flux);
}

// The transient bar: interior at T0, both ends held at T1 from t = 0. The closed form is the
// series T1 + (T0 - T1) sum_{n odd} 4/(n pi) sin(n pi xi) exp(-alpha_L (n pi / Lx)^2 t), with
// the slab's diffusivity alpha_L = (1 - 1/(2L)) k / (rho c) (the free faces as above; the mass
// of a particle is its cell's, rho a^3 / 4). Compared at three times from 0.2 to 2 decay times
// of the first mode, at every particle: within 0.5 % of T0 - T1. What is left: the free faces'
// layers conduct 3/4 of the inner ones along x, which bends the profile across the slab by
// a fraction of a percent, and the lattice's dispersion of the higher modes.
TEST(Heat, TheTransientBarFollowsTheSeries) {
  Model w = steel_bar(12, 2);
  auto& p = w.particles;
  const double T0 = 400.0, T1 = 300.0;
  for (std::size_t i = 0; i < p.size(); ++i) p.temperature[i] = p.group[i] >= 0 ? T1 : T0;
  ThermalSystem th;
  th.setup(w);
  const double a = 2.0 * std::sqrt(2.0) * 14e-6;
  const int L = layers(p, 2, 0.5 * a);
  const double x0 = lowest(p, 0), Lx = highest(p, 0) - x0;
  const double alpha = (1.0 - 0.5 / L) * kK / (kRho * kC);
  const double tau1 = Lx * Lx / (M_PI * M_PI * alpha);
  const double step = 0.5 * explicit_limit(w, held_flags(w));
  EnergyLedger ledger;
  double t = 0;
  for (double target : {0.2 * tau1, 0.6 * tau1, 2.0 * tau1}) {
    const int n = static_cast<int>(std::lround((target - t) / step));
    conduct_for(w, th, ledger, n * step, step);
    t += n * step;
    double worst = 0;
    for (std::size_t i = 0; i < p.size(); ++i) {
      const double xi = (p.position[i][0] - x0) / Lx;
      double s = 0;
      for (int m = 1; m < 2000; m += 2)
        s += 4.0 / (m * M_PI) * std::sin(m * M_PI * xi) * std::exp(-alpha * std::pow(m * M_PI / Lx, 2) * t);
      worst = std::max(worst, std::fabs(p.temperature[i] - (T1 + (T0 - T1) * s)));
    }
    EXPECT_LT(worst, 0.005 * (T0 - T1)) << "t = " << t / tau1 << " tau1";
  }
}

// The adiabatic shear cell. Every (001) layer of a bonded block is a group moved along x at
// gamma_dot times its height, so the lattice shears affinely (simple shear gamma in the xz
// plane, periodic across y). The rods along (1,0,+-1)/sqrt 2 stretch and shorten by about
// gamma/2, those along (0,1,+-1) by gamma^2/4 (elastic), the rest not at all. With perfectly
// plastic rods (flow stress s_y, yield strain e_y) an interior particle's four yielding rods
// give it beta/2 s_y A L0 (|e_r| - e_y) each, and with k = 1e-3 W/(m K) the conduction is
// negligible (a particle's time constant about 0.5 s against the 2 us of shear): adiabatic.
// Checked twice: (1) each interior particle's temperature rise against that discrete sum with
// the rods' exact strains, to 1e-9 (round-off of 2,000 steps' increments); (2) the continuum's
// adiabatic heating Delta T = beta tau gamma_p / (rho c), with tau the particle's virial shear
// stress measured at the end and gamma_p = gamma - 2 e_y, within 0.5 %: the finite-strain
// geometry (|e_r| differs from gamma/2 by gamma^2/8, 5e-4 relative at gamma = 0.02) and tau's
// rotation by the shear, also of order gamma.
TEST(Heat, TheAdiabaticShearCellHeatsAsBetaTauGammaOverRhoC) {
  const double R = 14e-6, E = 200e9, ey = 1e-3, sy = E * ey, beta = 0.9, k_low = 1e-3;
  const double gamma = 0.02, duration = 2e-6, rate = gamma / duration;
  const std::string head = fmt::format(R"([workpiece]
cells = [5, 2, 3]
radius = {}
periodic_width = true
[material]
density = {}
[rod]
youngs_modulus = {}
yield_strain = {}
hardening_modulus = 0.0
damping_ratio = 0.0
tensile_strength = 1e12
failure_strain = 10.0
[integrator]
scheme = "newmark"
end_time = {}
[heat]
heat_capacity = {}
conductivity = {}
taylor_quinney = {}
)",
                                       R, kRho, E, ey, duration, kC, k_low, beta);
  const Model plain = build_model(parse_case(head, "shear", {}));
  int nz = 0;
  const std::string groups = test::shear_layer_groups(plain.particles, R, rate, nz);
  Model w = build_model(parse_case(head + groups, "shear", {}));
  ASSERT_EQ(w.groups.size(), static_cast<std::size_t>(nz));
  const std::vector<Vec3> x0 = w.particles.position;
  Simulation sim(w, w.step);
  while (sim.time() < duration * (1 - 1e-12)) sim.step(duration - sim.time());
  const double g_end = rate * sim.time();  // (the shear reached, exactly gamma when the last step lands on the end)
  const auto& p = w.particles;
  const auto& r = w.rods;
  const double T0 = w.heat.initial_temperature;
  const double A = M_PI * R * R;
  // The discrete sum, with each rod's strain under the affine map x += g z.
  std::vector<double> heat(p.size(), 0.0);
  for (std::size_t b = 0; b < r.size(); ++b) {
    const auto [i, j] = r.ends[b];
    Vec3 d = x0[j] - x0[i];
    w.periodic.wrap(d);
    const double L0 = r.rest_length[b];
    const Vec3 dd(d[0] + g_end * d[2], d[1], d[2]);
    const double e = dd.norm() / L0 - 1.0;
    const double q = 0.5 * beta * sy * A * L0 * std::max(0.0, std::fabs(e) - ey);
    heat[i] += q;
    heat[j] += q;
  }
  std::vector<int> rods_of(p.size(), 0);
  for (const auto& e : r.ends) ++rods_of[e[0]], ++rods_of[e[1]];
  const ParticleFields f = particle_fields(p, r, w.periodic, nullptr);
  int interior = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (rods_of[i] != 12) continue;  // (a face particle has fewer rods)
    ++interior;
    const double dT = p.temperature[i] - T0;
    EXPECT_NEAR(dT, heat[i] / (p.mass[i] * kC), 1e-9 * dT) << i;
    const double tau = f.stress[i][5];  // xz, Pa
    EXPECT_NEAR(dT, beta * tau * (g_end - 2.0 * ey) / (kRho * kC), 5e-3 * dT) << i;
  }
  EXPECT_GT(interior, 0);
  // The heat of the whole block is beta times the plastic work the ledger booked.
  EXPECT_NEAR(sim.ledger().heat_plastic, beta * sim.ledger().plastic_work, 1e-12 * sim.ledger().heat_plastic);
}

// The heat ledger of a cut closes: a few hundred steps of a small [cut] (C45, 4 layers across
// h = 0.1 mm) with friction, the base held as a clamp and a tool with a heat capacity and a
// conductivity. heat_plastic + heat_friction = stored + to the tools + to the clamps, to 1e-9
// of the heat made (each step's sources and conduction are exact transfers; what remains is
// round-off over the steps); heat_plastic is beta times the plastic work the commit booked, to
// round-off; and each of the terms is at work (none of them is zero).
TEST(Heat, TheLedgerOfACutCloses) {
  Model w = build_model(parse_case(R"([cut]
uncut_chip_thickness = 0.1e-3
cutting_speed = 10.0
rake_angle = 10.0
material = "C45"
layers = 4
length_of_cut = 0.2e-3
[heat]
held_groups = ["base"]
tool_heat_capacity = 1e-6
tool_conductivity = 20.0
)",
                                   "cut", {}));
  ASSERT_TRUE(w.heat.enabled);
  Simulation sim(w, w.step);
  for (int n = 0; n < 800; ++n) sim.step();
  const EnergyLedger& L = sim.ledger();
  const double made = L.heat_plastic + L.heat_friction;
  const double stored = sim.thermal().stored_heat(w);
  EXPECT_GT(L.heat_plastic, 0.0);
  EXPECT_GT(L.heat_friction, 0.0);
  EXPECT_GT(L.heat_to_tools, 0.0);
  EXPECT_NEAR(L.heat_plastic, w.heat.taylor_quinney * L.plastic_work, 1e-12 * L.heat_plastic);
  EXPECT_NEAR(made, stored + L.heat_to_tools + L.heat_outflow + L.heat_to_clamps, 1e-9 * made);
  // The tool's lumped temperature holds what reached it.
  ASSERT_FALSE(sim.thermal().tool_temperature().empty());
  EXPECT_GT(sim.thermal().tool_temperature()[0], w.heat.tool_temperature);
}

// heat.tool_friction_share splits a tool contact's frictional heat: the tiny cut (rods that do
// not read the temperature, no sticking: the motion is the same whatever the heat) with a tool
// taking 0.5 (the default), 0.2 and 0 of it. The motion is the same bits in all three and the
// friction heat made the same to round-off; what the tool takes scales with the share, to
// round-off (1e-12: the same terms summed with another factor), and the particles keep the rest
// (the ledger closes).
TEST(Heat, TheToolsShareOfTheFrictionHeatIsTheSetFraction) {
  struct Out {
    double friction = 0, to_tools = 0, stored = 0, made = 0;
    std::vector<Vec3> x;
  };
  const auto run = [](double share) {
    Model w = build_model(parse_case(std::string(test::kTinyCut) + fmt::format(R"([heat]
heat_capacity = 486.0
conductivity = 50.7
tool_friction_share = {}
)",
                                                                               share),
                                     "tiny_cut", {}));
    EXPECT_EQ(w.heat.tool_friction_share, share);
    Simulation sim(w, w.step);
    for (int n = 0; n < 1500; ++n) sim.step();
    const EnergyLedger& L = sim.ledger();
    return Out{L.heat_friction, L.heat_to_tools, sim.thermal().stored_heat(w), L.heat_plastic + L.heat_friction,
               w.particles.position};
  };
  const Out half = run(0.5), fifth = run(0.2), none = run(0.0);
  ASSERT_GT(half.to_tools, 0.0) << "the tool must rub";
  EXPECT_TRUE(half.x == fifth.x && half.x == none.x) << "the heat changed the motion";
  // (the same power, split in other parts before the sums: equal to round-off)
  EXPECT_NEAR(fifth.friction, half.friction, 1e-12 * half.friction);
  EXPECT_NEAR(none.friction, half.friction, 1e-12 * half.friction);
  EXPECT_NEAR(fifth.to_tools, 0.4 * half.to_tools, 1e-12 * half.to_tools);
  EXPECT_EQ(none.to_tools, 0.0);
  for (const Out* o : {&half, &fifth, &none}) EXPECT_NEAR(o->made, o->stored + o->to_tools, 1e-9 * o->made);
  // The particles hold what the tool did not take.
  EXPECT_NEAR(none.stored - half.stored, half.to_tools, 1e-9 * half.made);
  EXPECT_THROW(build_model(parse_case(std::string(test::kTinyCut) + "[heat]\nheat_capacity = 486.0\nconductivity = "
                                                                    "50.7\ntool_friction_share = 1.5\n",
                                      "tiny_cut", {})),
               InputError);
}

}  // namespace
}  // namespace swarf
