// Periodic width (y): the lattice is bonded across the boundary, contacts see the nearest
// image, and a block pushed by a tool carries the load through the wrapped rods exactly as
// the closed form of a laterally confined lattice says.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <nlohmann/json.hpp>
#include <random>
#include <sstream>

#include "io/h5file.h"
#include "push_case.h"
#include "setup/model.h"
#include "swarf/contacts/contacts.h"
#include "swarf/core/errors.h"
#include "swarf/state/particles.h"
#include "swarf/state/rods.h"
#include "test_helpers.h"

namespace swarf {
namespace {

ContactParams params() {
  ContactParams prm;
  prm.youngs_modulus = 2e11;
  prm.poisson_ratio = 0.3;
  prm.skin = 1e-4;
  return prm;
}

TEST(Periodic, EveryParticleAwayFromTheXAndZFacesHasTwelveRods) {
  const auto cs = parse_case(R"([workpiece]
cells = [3, 2, 3]
radius = 1e-4
periodic_width = true
[integrator]
end_time = 1e-6
)",
                             "periodic.toml", {});
  const Model m = build_model(cs);
  ASSERT_TRUE(m.periodic.on());
  const double a = m.derived.cell_edge;
  EXPECT_NEAR(m.periodic.period, 2 * a, 1e-15);
  std::vector<int> count(m.particles.size(), 0);
  for (const auto& e : m.rods.ends) {
    ++count[e[0]];
    ++count[e[1]];
  }
  double xmax = 0, zmax = 0;
  for (const auto& x : m.particles.position) {
    xmax = std::max(xmax, x[0]);
    zmax = std::max(zmax, x[2]);
  }
  int inner = 0;
  for (std::size_t i = 0; i < m.particles.size(); ++i) {
    const Vec3& x = m.particles.position[i];
    if (x[0] < 0.25 * a || x[0] > xmax - 0.25 * a || x[2] < 0.25 * a || x[2] > zmax - 0.25 * a) continue;
    EXPECT_EQ(count[i], 12) << "particle " << i;
    ++inner;
  }
  EXPECT_GT(inner, 10);
  // Every rod (also the wrapped ones) has the nearest-neighbour length through the nearest image.
  for (std::size_t k = 0; k < m.rods.size(); ++k) {
    Vec3 d = m.particles.position[m.rods.ends[k][1]] - m.particles.position[m.rods.ends[k][0]];
    m.periodic.wrap(d);
    EXPECT_NEAR(d.norm(), 2e-4, 1e-12);
  }
}

TEST(Periodic, NeighbourSearchFindsThePairsOfBruteForceThroughTheBoundary) {
  std::mt19937 rng(7);
  const double L = 6e-3;
  std::uniform_real_distribution<double> u(0.0, 0.01), uy(0.0, L), ur(0.3e-3, 0.6e-3);
  Particles p;
  const std::size_t n = 1500;
  p.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    p.position[i] = Vec3(u(rng), uy(rng), 0.3 * u(rng));
    p.radius[i] = ur(rng);
    p.mass[i] = 1e-6;
    p.inv_mass[i] = 1e6;
  }
  // Some particles sit beyond the period (positions are never wrapped).
  for (std::size_t i = 0; i < n; i += 7) p.position[i][1] += (i % 2 ? L : -L);
  const Periodic per = Periodic::along_y(L);
  Rods rods;
  rods.build_rows(n);
  std::vector<MeshBody> meshes;
  ContactSystem cs;
  cs.setup(params(), n, &meshes, per);
  cs.update_lists(p, rods, true);
  cs.evaluate(p, 1e-7);
  std::size_t brute = 0, across = 0;
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j) {
      Vec3 d = p.position[j] - p.position[i];
      const double direct = d.norm();
      per.wrap(d);
      if (d.norm() < p.radius[i] + p.radius[j]) {
        ++brute;
        across += direct >= p.radius[i] + p.radius[j] ? 1 : 0;
      }
    }
  EXPECT_GT(across, 20u);  // the test exercises the boundary
  EXPECT_EQ(cs.touching(), brute);
  // Two spheres touching only through the boundary push each other apart along y.
  Particles q;
  q.resize(2);
  q.position[0] = Vec3(0, 0.1e-3, 0);
  q.position[1] = Vec3(0, L - 0.1e-3 - 0.1e-3, 0);  // gap through the boundary 0.3 mm < 2 R
  q.radius = {0.2e-3, 0.2e-3};
  q.mass = {1e-6, 1e-6};
  q.inv_mass = {1e6, 1e6};
  Rods none;
  none.build_rows(2);
  ContactSystem two;
  two.setup(params(), 2, &meshes, per);
  two.update_lists(q, none, true);
  two.evaluate(q, 1e-7);
  ASSERT_EQ(two.touching(), 1u);
  Vec3 f0 = Vec3::Zero(), f1 = Vec3::Zero(), t = Vec3::Zero();
  two.add_to_particle(0, 1.0, f0, t);
  two.add_to_particle(1, 1.0, f1, t);
  EXPECT_GT(f0[1], 0.0);  // particle 0 (just above y = 0) is pushed up, away from its image neighbour below
  EXPECT_EQ(f0[1], -f1[1]);
}

// The tool test of test_cut_force.cpp with a periodic width instead of guided y faces: the
// period holds the width (plane strain), a group holds z; the rods crossing a gap are
// counted from results.h5 (wrapped rods included), so the closed form is the same.
TEST(Periodic, ToolPushingAPeriodicBlockMatchesTheLatticeStiffness) {
  const double R = 1e-4, u = 1e-6, nu = 0.3, E_contact = 2e14;
  const double a = 2.0 * std::sqrt(2.0) * R, h = a / 2;
  const int nx = 4, ny = 2, nz = 3;
  const double L = ny * a;
  test::TempDir dir("periodic_push");
  const test::PushCase pc{.nx = nx,
                          .ny = ny,
                          .nz = nz,
                          .R = R,
                          .u = u,
                          .E_contact = E_contact,
                          .nu = nu,
                          .periodic = true,
                          .guide_dofs = "z",
                          .tool_y = 0.5 * L - 0.5 * h,
                          .tool_width = 1.5e-3};
  test::write_file(dir / "c.toml", test::push_case_toml(pc));
  const auto r = test::run_command(std::string(SWARF_BINARY) + " run " + (dir / "c.toml") + " --out " + (dir / "out"));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const auto sum = nlohmann::json::parse(test::read_file(dir / "out/summary.json"));
  const double kb = sum["derived"]["rod_stiffness_N_per_m"].get<double>();
  EXPECT_NEAR(sum["cutting"]["width_m"].get<double>(), L, 1e-12);  // force per width over the period
  H5File f(dir / "out/results.h5", H5File::Mode::Read);
  std::size_t rows = 0, cols = 0;
  const auto x = f.read_doubles("/particles/position", rows, cols);
  const auto disp = f.read_doubles("/particles/displacement", rows, cols);
  const auto pairs = f.read_ints("/bonds/pairs", rows, cols);
  auto x0 = [&](std::int64_t i) { return x[3 * i] - disp[3 * i]; };
  int n_cross = 0, n_face = 0;
  for (std::size_t b = 0; b < rows; ++b) {
    const double xa = std::min(x0(pairs[2 * b]), x0(pairs[2 * b + 1])),
                 xb = std::max(x0(pairs[2 * b]), x0(pairs[2 * b + 1]));
    n_cross += xa < 0.25 * h && xb > 0.75 * h ? 1 : 0;
  }
  int n_edge = 0;  // face particles on the bottom or top z layer (one z rod fewer)
  const double z_top = (2 * nz - 1) * h;
  for (std::size_t i = 0; i < x.size() / 3; ++i) {
    if (!(x0(i) < 0.25 * h)) continue;
    ++n_face;
    const double z = x[3 * i + 2] - disp[3 * i + 2];
    n_edge += z < 0.25 * h || z > z_top - 0.25 * h ? 1 : 0;
  }
  // Periodic in y: every face particle has both of its y-diagonal rods to the next layer
  // (the wrapped ones included); only the z faces take rods away.
  EXPECT_EQ(n_cross, 4 * n_face - n_edge);
  const int gaps = 2 * nx - 1;
  const double K = 4.0 / 3.0 * E_contact / (1.0 - nu * nu) * std::sqrt(R);
  const double F = test::push_force_closed_form(gaps, n_cross, kb, n_face, K, u);
  const auto row = test::last_row(test::read_file(dir / "out/series.csv"));
  std::printf("periodic: tool force %.6g N, closed form %.6g N (%+.3f %%)\n", -row.at("force_tool_x"), F,
              100.0 * (-row.at("force_tool_x") / F - 1.0));
  // Tolerance 1 %, as in test_cut_force.cpp (uneven share of the face's edge particles along z).
  EXPECT_NEAR(-row.at("force_tool_x"), F, 0.01 * F);
  EXPECT_NEAR(row.at("cutting_force_per_width"), F / L, 0.01 * F / L);
}

TEST(Periodic, NeedsCellsAndTwoCellsAcross) {
  EXPECT_THROW(parse_case("[workpiece]\nsize = [1e-3, 1e-3, 1e-3]\nradius = 1e-4\nperiodic_width = true\n"
                          "[integrator]\nend_time = 1e-6\n",
                          "p.toml", {}),
               InputError);
  try {
    parse_case("[workpiece]\ncells = [3, 1, 3]\nradius = 1e-4\nperiodic_width = true\n[integrator]\nend_time = 1e-6\n",
               "p.toml", {});
    FAIL() << "one cell across accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("cells"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace swarf
