// chung_ooi.cpp: benchmark tests of Chung and Ooi (2011, Granular Matter 13:643-656) run
// through swarf's case parser, model and step, compared with the analytic Hertz solution
// and, for oblique impacts, with the rigid-body impulse theory in the sliding regime.
// Writes results.md and oblique.csv into the directory given as the first argument (default:
// validation/chung_ooi of the source tree).
//
// Tests 1-3 compare with the analytic Hertz impact; tests 4-8 (oblique impacts, spin, two
// spheres of equal and different size) with the rigid-body impulse theory where the contact
// slides throughout, and show the sticking regime (governed by tangential compliance) as is.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

#include "setup/case_config.h"
#include "setup/model.h"
#include "swarf/simulation.h"

using namespace swarf;

namespace {

struct Material {
  const char* name;
  double E, nu, rho;
};

struct ImpactResult {
  double contact_time = 0, peak_force = 0, peak_overlap = 0;
  Vec3 v_after = Vec3::Zero(), w_after = Vec3::Zero();
};

std::string contact_table(const Material& m, double e, double mu) {
  return fmt::format(
      "[material]\ndensity = {}\n[contact]\nyoungs_modulus = {}\npoisson_ratio = {}\nrestitution = {}\n"
      "friction = {}\nfriction_law = \"spring\"\n",
      m.rho, m.E, m.nu, e, mu);
}

// Steps a model until the contact measured by 'overlap' (m) has opened and closed again;
// records the contact time, the peak overlap and the peak of 'force' (N).
template <class Overlap, class Force>
ImpactResult run_impact(Simulation& sim, Overlap overlap, Force force) {
  ImpactResult r;
  double t_on = -1;
  for (long k = 0; k < 100000000; ++k) {
    sim.step();
    const double d = overlap();
    if (d > 0 && t_on < 0) t_on = sim.time();
    r.peak_overlap = std::max(r.peak_overlap, d);
    r.peak_force = std::max(r.peak_force, force());
    if (d <= 0 && t_on >= 0) {
      r.contact_time = sim.time() - t_on;
      break;
    }
  }
  return r;
}

// Two identical spheres, radius R, approaching at +-v along x (test 1).
ImpactResult two_spheres(const Material& m, double R, double v, double dt) {
  const std::string text = contact_table(m, 1.0, 0.0) +
                           fmt::format(
                               "[[particle]]\nposition = [0.0, 0.0, 0.0]\nvelocity = [{v}, 0.0, 0.0]\nradius = {R}\n"
                               "[[particle]]\nposition = [{x}, 0.0, 0.0]\nvelocity = [-{v}, 0.0, 0.0]\nradius = {R}\n"
                               "[integrator]\nscheme = \"verlet\"\ndt = {dt:.17g}\nend_time = 1\n",
                               fmt::arg("v", v), fmt::arg("R", R), fmt::arg("x", 2 * R * 1.0001), fmt::arg("dt", dt));
  Model model = build_model(parse_case(text, "chung_ooi test 1", {}));
  Simulation sim(model, model.step);
  const auto& p = model.particles;
  ImpactResult r = run_impact(
      sim, [&] { return 2 * R - (p.position[1] - p.position[0]).norm(); }, [&] { return p.force[1][0]; });
  r.v_after = p.velocity[1];
  return r;
}

// A sphere onto a rigid plane z = 0 with velocity (vt, 0, -vn) and spin wy (tests 2 to 4).
ImpactResult sphere_on_plane(const Material& m, double R, double vn, double vt, double e, double mu, double dt,
                             double spin_y = 0.0) {
  const double L = 200 * R;
  const std::string text =
      contact_table(m, e, mu) +
      fmt::format(
          "[[particle]]\nposition = [0.0, 0.0, {z:.17g}]\nvelocity = [{vt:.17g}, 0.0, {vz:.17g}]\nradius = {R}\n"
          "angular_velocity = [0.0, {wy:.17g}, 0.0]\n"
          "[[mesh]]\nname = \"plane\"\norigin = [{o}, {o}, 0.0]\nedge1 = [{L}, 0.0, 0.0]\nedge2 = [0.0, {L}, 0.0]\n"
          "[integrator]\nscheme = \"verlet\"\ndt = {dt:.17g}\nend_time = 1\n",
          fmt::arg("z", R * 1.0001), fmt::arg("vt", vt), fmt::arg("vz", -vn), fmt::arg("R", R), fmt::arg("o", -L / 2),
          fmt::arg("L", L), fmt::arg("dt", dt), fmt::arg("wy", spin_y));
  Model model = build_model(parse_case(text, "chung_ooi sphere on plane", {}));
  Simulation sim(model, model.step);
  const auto& p = model.particles;
  ImpactResult r = run_impact(
      sim, [&] { return R - p.position[0][2]; }, [&] { return p.force[0][2]; });
  r.v_after = p.velocity[0];
  r.w_after = p.omega[0];
  return r;
}

// Sphere 1 (radius R1) at rest is hit by sphere 2 (radius R2) moving with (vt, 0, -vn) from
// above (tests 7 and 8). Returns sphere 2's state after the impact in v_after / w_after.
ImpactResult two_spheres_oblique(const Material& m, double R1, double R2, double vn, double vt, double e, double mu,
                                 double dt) {
  const std::string text = contact_table(m, e, mu) +
                           fmt::format(
                               "[[particle]]\nposition = [0.0, 0.0, 0.0]\nradius = {R1}\n"
                               "[[particle]]\nposition = [0.0, 0.0, {z:.17g}]\nvelocity = [{vt:.17g}, 0.0, "
                               "{vz:.17g}]\nradius = {R2}\n"
                               "[integrator]\nscheme = \"verlet\"\ndt = {dt:.17g}\nend_time = 1\n",
                               fmt::arg("R1", R1), fmt::arg("R2", R2), fmt::arg("z", (R1 + R2) * 1.0001),
                               fmt::arg("vt", vt), fmt::arg("vz", -vn), fmt::arg("dt", dt));
  Model model = build_model(parse_case(text, "chung_ooi two spheres oblique", {}));
  Simulation sim(model, model.step);
  const auto& p = model.particles;
  ImpactResult r = run_impact(
      sim, [&] { return R1 + R2 - (p.position[1] - p.position[0]).norm(); }, [&] { return p.force[1][2]; });
  r.v_after = p.velocity[1] - p.velocity[0];  // relative velocity after
  r.w_after = p.omega[1];
  return r;
}

struct Hertz {
  double contact_time, peak_force, peak_overlap;
};

// Elastic Hertz impact at relative speed v (Johnson 1985): delta_max, F_max, t_c.
Hertz hertz(double Estar, double Rstar, double mstar, double v) {
  Hertz h;
  h.peak_overlap = std::pow(15 * mstar * v * v / (16 * Estar * std::sqrt(Rstar)), 0.4);
  h.peak_force = 4.0 / 3.0 * Estar * std::sqrt(Rstar) * std::pow(h.peak_overlap, 1.5);
  h.contact_time = 2.868 * std::pow(mstar * mstar / (Estar * Estar * Rstar * v), 0.2);
  return h;
}

double pct(double got, double want) { return 100.0 * (got - want) / want; }

// The three rows (contact time, peak force, peak overlap) of tests 1 and 2; returns the
// largest absolute deviation in percent.
double hertz_rows(std::string& md, const char* name, const ImpactResult& r, const Hertz& h) {
  const double d[3] = {pct(r.contact_time, h.contact_time), pct(r.peak_force, h.peak_force),
                       pct(r.peak_overlap, h.peak_overlap)};
  md += fmt::format("| {} | contact time (us) | {:.4f} | {:.4f} | {:+.3f} |\n", name, r.contact_time * 1e6,
                    h.contact_time * 1e6, d[0]);
  md += fmt::format("| {} | peak force (kN) | {:.4f} | {:.4f} | {:+.3f} |\n", name, r.peak_force / 1e3,
                    h.peak_force / 1e3, d[1]);
  md += fmt::format("| {} | peak overlap (um) | {:.4f} | {:.4f} | {:+.3f} |\n", name, r.peak_overlap * 1e6,
                    h.peak_overlap * 1e6, d[2]);
  return std::max({std::abs(d[0]), std::abs(d[1]), std::abs(d[2])});
}

}  // namespace

int main(int argc, char** argv) {
  // Without an argument, into its own folder (validation/chung_ooi), never the working directory.
  const std::string out = argc > 1 ? argv[1] : SWARF_CHUNG_OOI_DIR;
  std::string md = "<!-- written by chung_ooi (validation/chung_ooi); do not edit -->\n";
  int failures = 0;
  auto check = [&](double dev) {
    if (std::abs(dev) > 2.0) ++failures;
    return dev;
  };

  // Test 1: two identical spheres, R = 0.01 m, 10 m/s each.
  md +=
      "## Test 1: elastic normal impact of two identical spheres (R = 0.01 m, 10 m/s each)\n\n"
      "| material | quantity | swarf | Hertz | deviation % |\n|---|---|---|---|---|\n";
  for (const Material m : {Material{"glass", 4.8e10, 0.2, 2800}, Material{"limestone", 2.0e10, 0.25, 2500}}) {
    const double R = 0.01, v = 10.0;
    const double mass = m.rho * 4.0 / 3.0 * M_PI * R * R * R;
    const Hertz h = hertz(m.E / (2 * (1 - m.nu * m.nu)), R / 2, mass / 2, 2 * v);
    check(hertz_rows(md, m.name, two_spheres(m, R, v, h.contact_time / 2000), h));
  }

  // Test 2: sphere on a rigid plane, R = 0.1 m, 0.2 m/s.
  md +=
      "\n## Test 2: elastic normal impact of a sphere on a rigid plane (R = 0.1 m, 0.2 m/s)\n\n"
      "| material | quantity | swarf | Hertz | deviation % |\n|---|---|---|---|---|\n";
  for (const Material m : {Material{"aluminium oxide", 3.8e11, 0.23, 4000}, Material{"cast iron", 1.0e11, 0.25, 7000}}) {
    const double R = 0.1, v = 0.2;
    const double mass = m.rho * 4.0 / 3.0 * M_PI * R * R * R;
    const Hertz h = hertz(m.E / (1 - m.nu * m.nu), R, mass, v);
    check(hertz_rows(md, m.name, sphere_on_plane(m, R, v, 0.0, 1.0, 0.0, h.contact_time / 2000), h));
  }

  // Test 3: restitution sweep (aluminium oxide sphere, R = 2.55 mm, 3.9 m/s onto the plane).
  md +=
      "\n## Test 3: normal impacts with different coefficients of restitution (R = 2.55 mm, 3.9 m/s)\n\n"
      "| restitution set | rebound / impact speed | deviation % |\n|---|---|---|\n";
  const Material alox{"aluminium oxide", 3.8e11, 0.23, 4000};
  for (double e : {0.1, 0.3, 0.5, 0.7, 0.9, 1.0}) {
    const double R = 2.55e-3, v = 3.9;
    const double mass = alox.rho * 4.0 / 3.0 * M_PI * R * R * R;
    const Hertz h = hertz(alox.E / (1 - alox.nu * alox.nu), R, mass, v);
    const ImpactResult r = sphere_on_plane(alox, R, v, 0.0, e, 0.0, h.contact_time / 2000);
    md += fmt::format("| {:.1f} | {:.5f} | {:+.3f} |\n", e, r.v_after[2] / v, check(pct(r.v_after[2] / v, e)));
  }

  // Test 4: oblique impacts at 3.9 m/s, mu = 0.092, e = 0.98 (Kharaz et al. aluminium oxide).
  // Rigid-body impulse theory: while the contact slides throughout, the tangential impulse is
  // mu (1 + e) m vn, so vt' = vt - mu (1 + e) vn and w' R = 5/2 mu (1 + e) vn; it slides
  // throughout when vt/vn > 7/2 mu (1 + e).
  md +=
      "\n## Test 4: oblique impacts of a sphere on a plane (3.9 m/s, mu = 0.092, e = 0.98)\n\n"
      "| incidence angle (deg) | vt'/vt swarf | theory (sliding) | w' R / vn swarf | theory (sliding) | regime |\n"
      "|---|---|---|---|---|---|\n";
  std::ofstream csv(out + "/oblique.csv");
  csv << "angle_deg,vt_ratio,vt_ratio_sliding,spin,spin_sliding,rolling_limit_vt_ratio\n";
  const double mu = 0.092, e = 0.98, v = 3.9, R = 2.55e-3;
  const double mass = alox.rho * 4.0 / 3.0 * M_PI * R * R * R;
  const Hertz h = hertz(alox.E / (1 - alox.nu * alox.nu), R, mass, v);
  for (double deg : {5.0, 10.0, 15.0, 20.0, 30.0, 40.0, 50.0, 60.0, 70.0, 80.0}) {
    const double a = deg * M_PI / 180.0, vn = v * std::cos(a), vt = v * std::sin(a);
    const ImpactResult r = sphere_on_plane(alox, R, vn, vt, e, mu, h.contact_time / 2000);
    const double ratio = r.v_after[0] / vt, spin = r.w_after[1] * R / vn;
    const double ratio_s = 1.0 - mu * (1 + e) * vn / vt, spin_s = 2.5 * mu * (1 + e);
    const bool sliding = vt / vn > 3.5 * mu * (1 + e);
    md += fmt::format("| {:.0f} | {:.4f} | {:.4f} | {:.4f} | {:.4f} | {} |\n", deg, ratio, ratio_s, spin, spin_s,
                      sliding ? "sliding" : "sticking or transition");
    if (sliding) {
      check(100.0 * (ratio - ratio_s));  // absolute deviation in percent of vt
      check(pct(spin, spin_s));
    }
    csv << fmt::format("{},{},{},{},{},{}\n", deg, ratio, ratio_s, spin, spin_s, 5.0 / 7.0);
  }
  // Rigid-body impulse theory for the sliding regime (used by tests 5 to 8): normal impulse
  // (1 + e) m* vn, tangential impulse mu times it, solid spheres I = 2/5 m R^2. The contact
  // slides throughout when the contact-point slip exceeds 7/2 mu (1 + e) vn (sphere on a
  // plane, or relative slip between two spheres).
  md +=
      "\n## Test 5: oblique impacts on a plane at constant normal velocity (aluminium alloy, R = 0.1 m, vn = 0.2 m/s, "
      "mu = 0.4, e = 0.5)\n\n| vt (m/s) | vt' swarf (m/s) | theory (sliding) | w' swarf (rad/s) | theory (sliding) | "
      "regime |\n"
      "|---|---|---|---|---|---|\n";
  const Material alu{"aluminium alloy", 7.0e10, 0.33, 2700};
  {
    const double R5 = 0.1, vn5 = 0.2, mu5 = 0.4, e5 = 0.5;
    const double m5 = alu.rho * 4.0 / 3.0 * M_PI * R5 * R5 * R5;
    const Hertz h5 = hertz(alu.E / (1 - alu.nu * alu.nu), R5, m5, vn5);
    for (double vt5 : {0.05, 0.1, 0.2, 0.3, 0.5, 1.0}) {
      const ImpactResult r = sphere_on_plane(alu, R5, vn5, vt5, e5, mu5, h5.contact_time / 2000);
      const double jt = mu5 * (1 + e5) * vn5;  // tangential impulse per unit mass
      const double vt_s = vt5 - jt, w_s = 2.5 * jt / R5;
      const bool sliding = vt5 > 3.5 * jt;
      md += fmt::format("| {:.2f} | {:.5f} | {:.5f} | {:.5f} | {:.5f} | {} |\n", vt5, r.v_after[0], vt_s, r.w_after[1],
                        w_s, sliding ? "sliding" : "sticking or transition");
      if (sliding) {
        check(pct(r.v_after[0], vt_s));
        check(pct(r.w_after[1], w_s));
      }
    }
  }
  md +=
      "\n## Test 6: normal impacts on a plane with initial spin (aluminium alloy, R = 0.1 m, vn = 0.2 m/s, mu = 0.4, "
      "e = 0.5)\n\n| w0 R (m/s) | vt' swarf (m/s) | theory (sliding) | w' R swarf (m/s) | theory (sliding) | regime |\n"
      "|---|---|---|---|---|---|\n";
  {
    const double R6 = 0.1, vn6 = 0.2, mu6 = 0.4, e6 = 0.5;
    const double m6 = alu.rho * 4.0 / 3.0 * M_PI * R6 * R6 * R6;
    const Hertz h6 = hertz(alu.E / (1 - alu.nu * alu.nu), R6, m6, vn6);
    for (double s6 : {0.05, 0.1, 0.3, 0.5, 1.0}) {
      // Spin about +y: the contact point (bottom) moves at -w0 R along x, friction pushes +x.
      const ImpactResult r = sphere_on_plane(alu, R6, vn6, 0.0, e6, mu6, h6.contact_time / 2000, s6 / R6);
      const double jt = mu6 * (1 + e6) * vn6;
      const double vt_s = jt, wr_s = s6 - 2.5 * jt;
      const bool sliding = s6 > 3.5 * jt;
      md += fmt::format("| {:.2f} | {:.5f} | {:.5f} | {:.5f} | {:.5f} | {} |\n", s6, r.v_after[0], vt_s,
                        r.w_after[1] * R6, wr_s, sliding ? "sliding" : "sticking or transition");
      if (sliding) {
        check(pct(r.v_after[0], vt_s));
        check(pct(r.w_after[1] * R6, wr_s));
      }
    }
  }
  for (int test : {7, 8}) {
    const double R1 = 0.1, R2 = test == 7 ? 0.1 : 0.05, vn = 0.2, mu7 = 0.4, e7 = 0.5;
    md += fmt::format(
        "\n## Test {}: two spheres (R = {} m and {} m, aluminium alloy), constant normal and varying "
        "tangential velocity (vn = 0.2 m/s, mu = 0.4, e = 0.5)\n\n"
        "| vt (m/s) | relative vt' swarf (m/s) | theory (sliding) | w' of the moving sphere swarf (rad/s) | "
        "theory (sliding) | regime |\n|---|---|---|---|---|---|\n",
        test, R1, R2);
    const double m1 = alu.rho * 4.0 / 3.0 * M_PI * R1 * R1 * R1, m2 = alu.rho * 4.0 / 3.0 * M_PI * R2 * R2 * R2;
    const double ms = m1 * m2 / (m1 + m2), Rs = R1 * R2 / (R1 + R2);
    const Hertz h = hertz(alu.E / (2 * (1 - alu.nu * alu.nu)), Rs, ms, vn);
    for (double vt7 : {0.05, 0.1, 0.3, 0.5, 1.0}) {
      const ImpactResult r = two_spheres_oblique(alu, R1, R2, vn, vt7, e7, mu7, h.contact_time / 2000);
      const double J = mu7 * (1 + e7) * ms * vn;  // tangential impulse, N s
      const double vt_s = vt7 - J * (1 / m1 + 1 / m2);
      const double w_s = J * R2 / (0.4 * m2 * R2 * R2);  // the moving sphere (2) spins about +y
      const bool sliding = vt7 > 3.5 * J / ms;
      md += fmt::format("| {:.2f} | {:.5f} | {:.5f} | {:.5f} | {:.5f} | {} |\n", vt7, r.v_after[0], vt_s, r.w_after[1],
                        w_s, sliding ? "sliding" : "sticking or transition");
      if (sliding) {
        check(pct(r.v_after[0], vt_s));
        check(pct(r.w_after[1], w_s));
      }
    }
  }
  md += fmt::format("\n{} comparison(s) outside 2 %.\n", failures);
  std::ofstream(out + "/results.md") << md;
  std::fputs(md.c_str(), stdout);
  return failures == 0 ? 0 : 1;
}
