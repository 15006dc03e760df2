// The cutting-force bookkeeping on a case with a known answer: a tool with a flat vertical
// rake face (rake 0) pushes the x- face of a block whose far face is clamped and whose other
// particles are held in y and z. Every layer of atoms then moves rigidly along x (each
// particle has as many rods to the left as to the right, so equal gap strains balance it),
// and the lattice is a chain of identical gaps in series: the force across a gap crossed by
// N rods (direction cosine 1/sqrt(2) to x) compressed by d is F = N kb d / 2. The tool reaches
// the face through Hertz contacts, one per face particle, in series with the lattice:
//   u_tool = (gaps) 2 F / (N kb) + (F / (N_face K))^(2/3),  K = 4/3 E* sqrt(R).
// The tool's force (series force_tool_x), the clamp's reaction and the cutting force per width
// must all give this F.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>

#include "lattice_gen/fcc_lattice.h"
#include "push_case.h"
#include "test_helpers.h"

namespace swarf {
namespace {

TEST(CutForce, ToolPushingAClampedBlockMatchesTheLatticeStiffness) {
  const double R = 1e-4, u = 1e-6, nu = 0.3, E_contact = 2e14;
  const int nx = 4, ny = 3, nz = 3;
  FccSpec spec;
  spec.radius = R;
  spec.cells = {nx, ny, nz};
  const Lattice lat = generate_fcc(spec);
  const double a = lat.cell_edge, h = a / 2;
  // Rods crossing the gap between the first two layers, particles on the face, layers.
  int n_cross = 0, n_face = 0;
  double x_max = 0, y_max = 0;
  for (const auto& x : lat.position) {
    n_face += x[0] < 0.25 * h ? 1 : 0;
    x_max = std::max(x_max, x[0]);
    y_max = std::max(y_max, x[1]);
  }
  for (const auto& b : lat.rods) {
    const double x0 = std::min(lat.position[b[0]][0], lat.position[b[1]][0]);
    const double x1 = std::max(lat.position[b[0]][0], lat.position[b[1]][0]);
    n_cross += x0 < 0.25 * h && x1 > 0.75 * h ? 1 : 0;
  }
  const int gaps = static_cast<int>(std::lround(x_max / h));  // the last layer is clamped

  test::TempDir dir("cut_force");
  const test::PushCase pc{
      .nx = nx, .ny = ny, .nz = nz, .R = R, .u = u, .E_contact = E_contact, .nu = nu, .tool_y = 0.5 * y_max};
  test::write_file(dir / "c.toml", test::push_case_toml(pc));
  const auto r = test::run_command(std::string(SWARF_BINARY) + " run " + (dir / "c.toml") + " --out " + (dir / "out"));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const auto sum = nlohmann::json::parse(test::read_file(dir / "out/summary.json"));
  const double kb = sum["derived"]["rod_stiffness_N_per_m"].get<double>();
  const double width = sum["cutting"]["width_m"].get<double>();
  // The closed form above, solved for F by bisection (u_tool grows monotonically with F).
  const double K = 4.0 / 3.0 * E_contact / (1.0 - nu * nu) * std::sqrt(R);
  const double F = test::push_force_closed_form(gaps, n_cross, kb, n_face, K, u);
  const auto row = test::last_row(test::read_file(dir / "out/series.csv"));
  std::printf("tool force %.6g N, closed form %.6g N (%+.3f %%); %d gaps of %d rods, %d face particles\n",
              -row.at("force_tool_x"), F, 100.0 * (-row.at("force_tool_x") / F - 1.0), gaps, n_cross, n_face);
  // Tolerance 1 %: the closed form spreads the tool's force evenly over the face particles,
  // while the face's edge particles have fewer rods and sit a little deeper in the tool; the
  // contacts take about 2 % of the displacement here, so the uneven share is well below 1 %.
  // The 10 us hold after the push leaves the damped lattice vibrations below 0.1 %.
  EXPECT_NEAR(-row.at("force_tool_x"), F, 0.01 * F);
  EXPECT_NEAR(row.at("reaction_clamp_x"), -F, 0.01 * F);  // the clamp holds the block against the tool
  EXPECT_NEAR(row.at("cutting_force_per_width"), F / width, 0.01 * F / width);
  EXPECT_NEAR(row.at("thrust_force_per_width"), 0.0, 1e-9 * F / width);  // frictionless vertical face
  // The contacts' share is small but not negligible: check the closed form needs it.
  EXPECT_GT(std::pow(F / (n_face * K), 2.0 / 3.0), 0.01 * u);
}

}  // namespace
}  // namespace swarf
