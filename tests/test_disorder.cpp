// test_disorder.cpp: the workpiece's seeded position jitter (workpiece.disorder_seed,
// position_jitter; lattice_gen/lattice_disorder.h). Seed 0 or amplitude 0 is the ordered
// lattice bit for bit; a seed moves every site by a nonzero vector within the amplitude, the
// same bits for 1 and 2 threads and in any order, other bits for another seed; the rods are
// the ordered lattice's, at rest at their jittered lengths (nothing moves); groups are
// selected on the ordered sites; bad values are refused naming the key; the seed and the
// amplitude reach the set-up printout, summary.json and results.h5.
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <omp.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <nlohmann/json.hpp>

#include "case_errors.h"
#include "io/h5file.h"
#include "lattice_gen/fcc_lattice.h"
#include "lattice_gen/lattice_disorder.h"
#include "lattice_gen/lattice_file.h"
#include "setup/case_config.h"
#include "setup/model.h"
#include "swarf/core/errors.h"
#include "swarf/simulation.h"
#include "test_helpers.h"

namespace swarf {
namespace {

constexpr double kR = 0.5e-3;  // m
constexpr double kEps = std::numeric_limits<double>::epsilon();

// A 4 x 3 x 3 block on a clamped base, with a region group whose lower bound lies 6 um (0.012 R)
// below the lattice plane x = 2h = 1.4142 mm: a selection on jittered positions would lose
// about half of that plane's sites.
const std::string kBlock = R"([workpiece]
cells = [4, 3, 3]
radius = 0.5e-3

[rod]
youngs_modulus = 200e9
yield_strain = 1e-3
damping_ratio = 0.1

[integrator]
end_time = 1e-5

[[group]]
name = "base"
side = "z-"
layers = 2

[[group]]
name = "slab"
box_min = [1.4082e-3, -1.0, 1.2e-3]
box_max = [2.2e-3, 1.0, 1.0]
)";

Model block(const std::vector<std::string>& overrides) {
  return build_model(parse_case(kBlock, "block.toml", overrides));
}

Model jittered(int seed, double amplitude, std::vector<std::string> more = {}) {
  more.push_back(fmt::format("workpiece.disorder_seed={}", seed));
  more.push_back(fmt::format("workpiece.position_jitter={}", amplitude));
  return block(more);
}

std::string error_of(const std::string& text, const std::vector<std::string>& overrides) {
  return test::case_error(text, overrides, "block.toml");
}

using test::expect_mentions;

TEST(Disorder, SeedZeroOrAmplitudeZeroIsTheOrderedLatticeBitForBit) {
  FccSpec spec;
  spec.radius = kR;
  spec.cells = {4, 3, 3};
  const Lattice ordered = generate_fcc(spec);
  for (const auto& overrides : std::vector<std::vector<std::string>>{
           {}, {"workpiece.disorder_seed=0"}, {"workpiece.disorder_seed=9", "workpiece.position_jitter=0.0"}}) {
    const Model m = block(overrides);
    ASSERT_EQ(m.particles.size(), ordered.position.size());
    for (std::size_t i = 0; i < ordered.position.size(); ++i) {
      ASSERT_EQ(m.particles.position[i], ordered.position[i]) << "particle " << i;
      ASSERT_EQ(m.sites[i], ordered.position[i]);
    }
    EXPECT_EQ(m.rods.ends, ordered.rods);
    EXPECT_EQ(m.rods.rest_length, ordered.rest_length);
    EXPECT_EQ(m.derived.position_jitter, 0.0);
  }
}

TEST(Disorder, DisplacementsAreNonzeroWithinTheAmplitudeAndUniformInTheBall) {
  const double A = 0.05;
  const Model m = jittered(7, A, {"workpiece.cells=[6,6,6]"});
  const std::size_t n = m.particles.size();  // 864
  ASSERT_EQ(m.derived.position_jitter, A);
  double r_max = 0.0, r2_sum = 0.0;
  Vec3 sum = Vec3::Zero();
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3 d = m.particles.position[i] - m.sites[i];
    const double r = d.norm();
    EXPECT_GT(r, 0.0) << "particle " << i;
    // |d| <= A R up to the rounding of site + d (|x| < 5 mm: 1e-18 m against A R = 25 um).
    EXPECT_LE(r, A * kR * (1.0 + 1e-12)) << "particle " << i;
    r_max = std::max(r_max, r);
    r2_sum += r * r;
    sum += d;
  }
  // Uniform in the ball of radius s = A R: E|d|^2 = 3/5 s^2 (the standard deviation of the
  // mean of |d|^2/s^2 over 864 draws is 0.009: 0.04 is 4.5 of them); each component has mean 0
  // and standard deviation s/sqrt(5), so the mean's is s/sqrt(5 n) (0.015 s): 0.07 s is 4.6.
  const double s = A * kR;
  EXPECT_GT(r_max, 0.95 * s) << "draws fill the ball";
  EXPECT_NEAR(r2_sum / double(n) / (s * s), 0.6, 0.04);
  for (int c = 0; c < 3; ++c) EXPECT_LT(std::abs(sum[c] / double(n)), 0.07 * s) << "component " << c;
  // The unit draws themselves, over many ids: inside the closed unit ball exactly (c . c <= 2^60
  // in integers, scaled by 2^-30 exactly; the double sum of squares rounds by an ulp or two).
  for (std::uint64_t id = 0; id < 100000; ++id) ASSERT_LE(unit_ball_jitter(7, id).squaredNorm(), 1.0 + 4 * kEps);
}

TEST(Disorder, SameSeedGivesTheSameBitsOnOneAndTwoThreadsAndInAnyOrder) {
  const int saved = omp_get_max_threads();
  omp_set_num_threads(1);
  const Model one = jittered(42, 0.1, {"workpiece.cells=[8,6,6]"});
  omp_set_num_threads(2);
  const Model two = jittered(42, 0.1, {"workpiece.cells=[8,6,6]"});
  omp_set_num_threads(saved);
  ASSERT_EQ(one.particles.size(), two.particles.size());
  for (std::size_t i = 0; i < one.particles.size(); ++i)
    ASSERT_EQ(one.particles.position[i], two.particles.position[i]) << "particle " << i;
  EXPECT_EQ(one.rods.rest_length, two.rods.rest_length);
  // A particle's move depends on (seed, id) only: drawn here backwards, one at a time, it is the
  // model's (to the rounding of site + move, a few ulps of the coordinates).
  const double s = 0.1 * kR;
  for (std::size_t k = one.particles.size(); k-- > 0;) {
    const Vec3 want = s * unit_ball_jitter(42, static_cast<std::uint64_t>(one.particles.id[k]));
    EXPECT_LE((one.particles.position[k] - one.sites[k] - want).norm(), 1e-12 * s) << "particle " << k;
  }
}

TEST(Disorder, DifferentSeedsGiveDifferentPositions) {
  const Model a = jittered(1, 0.02), b = jittered(2, 0.02);
  std::size_t same = 0;
  for (std::size_t i = 0; i < a.particles.size(); ++i) same += a.particles.position[i] == b.particles.position[i];
  EXPECT_EQ(same, 0u);
  EXPECT_NE(a.rods.rest_length, b.rods.rest_length);
}

TEST(Disorder, RodsAreTheOrderedLatticesTwelveNeighboursAtTheirJitteredLengths) {
  for (const bool periodic : {false, true}) {
    const std::vector<std::string> more{fmt::format("workpiece.periodic_width={}", periodic)};
    const Model ordered = block(more);
    const double A = 0.2;  // the largest allowed
    const Model m = jittered(5, A, more);
    ASSERT_EQ(m.periodic.on(), periodic);
    EXPECT_EQ(m.rods.ends, ordered.rods.ends) << "rods come from the ordered lattice's topology";
    // Coordination: 12 rods for every site away from the open faces (and from y's when not periodic).
    const double a = m.derived.cell_edge;
    Vec3 hi = Vec3::Zero();
    for (const auto& x : m.sites) hi = hi.cwiseMax(x);
    std::vector<int> count(m.particles.size(), 0);
    for (const auto& e : m.rods.ends) ++count[e[0]], ++count[e[1]];
    int inner = 0;
    for (std::size_t i = 0; i < m.particles.size(); ++i) {
      bool interior = true;
      for (int c = 0; c < 3; ++c)
        if (!(periodic && c == 1)) interior = interior && m.sites[i][c] > 0.25 * a && m.sites[i][c] < hi[c] - 0.25 * a;
      if (!interior) continue;
      EXPECT_EQ(count[i], 12) << "particle " << i;
      ++inner;
    }
    EXPECT_GT(inner, 3);
    // Each rest length is the distance of the moved ends through the nearest image (the same
    // expression as the kernel's, which may contract multiply-adds differently: 2 ulps), within
    // 2R (1 +- A); and the jitter does change them.
    const double d0 = 2 * kR;
    int changed = 0;
    for (std::size_t k = 0; k < m.rods.size(); ++k) {
      Vec3 dx = m.particles.position[m.rods.ends[k][1]] - m.particles.position[m.rods.ends[k][0]];
      m.periodic.wrap(dx);
      const double L = std::sqrt(dx.squaredNorm()), L0 = m.rods.rest_length[k];
      EXPECT_NEAR(L0, L, 2 * kEps * L) << "rod " << k;
      EXPECT_GE(L0, d0 * (1 - A) * (1 - 1e-12));
      EXPECT_LE(L0, d0 * (1 + A) * (1 + 1e-12));
      changed += std::abs(L0 - d0) > 1e-3 * d0;
    }
    EXPECT_GT(changed, int(m.rods.size()) / 2);
  }
}

TEST(Disorder, TheJitteredBlockStartsStressFreeAndStaysAtRest) {
  Model m = jittered(11, 0.1, {"workpiece.periodic_width=true"});
  const double E = std::get<RodLaw>(m.derived.law).youngs_modulus, A = m.derived.rod_area;
  // Had the rods kept the ordered length 2R, the jitter would strain them by up to 10 %.
  double strain_if_ordered = 0.0;
  for (double L0 : m.rods.rest_length) strain_if_ordered = std::max(strain_if_ordered, std::abs(L0 / (2 * kR) - 1));
  EXPECT_GT(strain_if_ordered, 0.05);
  Simulation sim(m, m.step);  // (evaluates the initial forces)
  // Tolerance: the kernel's length and the rest length are the same expression, rounded at
  // most an ulp apart each (multiply-add contraction may differ between the two places): a
  // strain of at most 2 eps (4.4e-16), so |stress| <= 2 eps E; checked at 4 eps E. A particle
  // has at most 12 rods: |f| <= 12 x 4 eps E A.
  double s_max = 0.0, f_max = 0.0;
  for (double s : m.rods.stress) s_max = std::max(s_max, std::abs(s));
  for (const auto& f : m.particles.force) f_max = std::max(f_max, f.norm());
  std::printf("disorder: largest initial |stress|/E %.3g (rest lengths left at 2R: %.3g), |f|/(E A) %.3g\n", s_max / E,
              strain_if_ordered, f_max / (E * A));
  EXPECT_LE(s_max, 4 * kEps * E) << "largest initial rod stress (Pa)";
  EXPECT_LE(f_max, 12 * 4 * kEps * E * A) << "largest initial particle force (N)";
  // Nothing loads the block: after 50 steps every particle is where it started, to 1e-12 R
  // (the residual forces above move a particle by about 1e-17 m in that time).
  for (int k = 0; k < 50; ++k) sim.step();
  double moved = 0.0;
  for (std::size_t i = 0; i < m.particles.size(); ++i)
    moved = std::max(moved, (m.particles.position[i] - m.particles.initial_position[i]).norm());
  EXPECT_LE(moved, 1e-12 * kR);
}

TEST(Disorder, GroupsAreSelectedOnTheOrderedSitesAndClampedParticlesAreJittered) {
  const Model ordered = block({}), m = jittered(3, 0.05);
  ASSERT_EQ(m.groups.size(), ordered.groups.size());
  for (std::size_t g = 0; g < m.groups.size(); ++g)
    EXPECT_EQ(m.groups[g].members, ordered.groups[g].members) << "group " << m.groups[g].name;
  // The slab's lower bound is 6 um above a lattice plane: the jitter (up to 25 um) moves some of
  // that plane's members below it, so the test would catch a selection on jittered positions.
  const auto& slab = m.groups[1];
  int below = 0;
  for (auto i : slab.members) below += m.particles.position[i][0] < 1.4082e-3;
  EXPECT_GT(below, 0);
  // The clamped base is jittered too (its rods start at rest like the others) and stays there.
  const auto& base = m.groups[0];
  for (auto i : base.members) EXPECT_NE(m.particles.position[i], m.sites[i]) << "particle " << i;
}

TEST(Disorder, TheStableStepAllowsForTheShortestRodTheSameForEverySeed) {
  const Model ordered = block({"rod.damping_ratio=0"});
  const Model a = jittered(1, 0.2, {"rod.damping_ratio=0"}), b = jittered(2, 0.2, {"rod.damping_ratio=0"});
  // The material is the ordered block's whatever the seed.
  EXPECT_EQ(std::get<RodLaw>(a.derived.law).youngs_modulus, std::get<RodLaw>(ordered.derived.law).youngs_modulus);
  EXPECT_EQ(a.derived.rod_stiffness, ordered.derived.rod_stiffness);
  // kb_max = E A/(2R (1 - A)), so the undamped step is sqrt(1 - A) of the ordered one.
  EXPECT_NEAR(a.derived.dt_stable / ordered.derived.dt_stable, std::sqrt(1 - 0.2), 1e-12);
  EXPECT_EQ(a.derived.dt_stable, b.derived.dt_stable);
  EXPECT_EQ(ordered.derived.rod_stiffness_max, ordered.derived.rod_stiffness);
  // ... and is a bound: no rod is stiffer than kb_max.
  const double E = std::get<RodLaw>(a.derived.law).youngs_modulus, area = a.derived.rod_area;
  for (double L0 : a.rods.rest_length) EXPECT_LE(E * area / L0, a.derived.rod_stiffness_max * (1 + 1e-12));
}

TEST(Disorder, BadValuesAreRefusedNamingTheFileKeyAndValue) {
  expect_mentions(error_of(kBlock, {"workpiece.disorder_seed=1", "workpiece.position_jitter=0.3"}),
                  {"block.toml (--set workpiece.position_jitter)", "key 'workpiece.position_jitter' = 0.3",
                   "must lie in [0, 0.2]", "0.207"});
  expect_mentions(error_of(kBlock, {"workpiece.disorder_seed=1", "workpiece.position_jitter=-0.01"}),
                  {"workpiece.position_jitter' = -0.01", "[0, 0.2]"});
  expect_mentions(error_of(kBlock, {"workpiece.disorder_seed=-1"}),
                  {"key 'workpiece.disorder_seed' = -1", "must lie in [0, 2147483647]"});
  expect_mentions(error_of(kBlock, {"workpiece.disorder_seed=4294967296"}), {"workpiece.disorder_seed", "4294967296"});
  expect_mentions(error_of(kBlock, {"workpiece.disorder_seed=1.5"}), {"workpiece.disorder_seed", "must be an integer"});
  // In the file: the line is named.
  std::string text = kBlock;
  text.replace(text.find("radius = 0.5e-3\n"), 16, "radius = 0.5e-3\ndisorder_seed = 3\nposition_jitter = 0.25\n");
  expect_mentions(error_of(text, {}), {"block.toml:5", "key 'workpiece.position_jitter' = 0.25", "[0, 0.2]"});
  // An amplitude without a seed would silently do nothing.
  expect_mentions(error_of(kBlock, {"workpiece.position_jitter=0.05"}),
                  {"key 'workpiece.position_jitter' = 0.05", "disorder_seed > 0"});
  // A lattice file is used as it is.
  test::TempDir dir("disorder_file");
  FccSpec spec;
  spec.radius = kR;
  spec.cells = {2, 2, 2};
  write_lattice(dir / "l.h5", generate_fcc(spec));
  const std::string from_file = "[workpiece]\nlattice_file = \"" + (dir / "l.h5") +
                                "\"\ndisorder_seed = 2\n[integrator]\nend_time = 1e-6\n[rod]\nyield_strain = 1e-3\n";
  expect_mentions(error_of(from_file, {}), {"block.toml:3", "key 'workpiece.disorder_seed' = 2", "lattice_file"});
  // The library call checks its amplitude too.
  Lattice lat = generate_fcc(spec);
  expect_mentions(
      [&] {
        try {
          jitter_lattice(lat, 1, 0.21, lat.position.size(), Periodic{});
        } catch (const InputError& e) {
          return std::string(e.what());
        }
        return std::string();
      }(),
      {"0.21", "[0, 0.2]"});
}

TEST(Disorder, SeedAndAmplitudeAreRecordedInThePrintoutSummaryAndResults) {
  test::TempDir dir("disorder_run");
  test::write_file(dir / "block.toml", kBlock + "[output]\nvtk = false\nplots = false\nprogress = false\n");
  auto run = [&](const std::string& name, const std::string& sets) {
    return test::run_command(fmt::format("timeout 120 {} run {} --out {} --threads 1 --set integrator.end_time=2e-7 {}",
                                         SWARF_BINARY, dir / "block.toml", dir / name, sets));
  };
  const auto r = run("seeded", "--set workpiece.disorder_seed=3");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("disorder: seed 3, sites moved uniformly within 0.02 R = 1e-05 m"), std::string::npos)
      << r.output;
  const auto sum = nlohmann::json::parse(test::read_file(dir / "seeded/summary.json"));
  EXPECT_EQ(sum["derived"]["disorder_seed"], 3);
  EXPECT_EQ(sum["derived"]["position_jitter"], 0.02);  // the default with a seed
  EXPECT_DOUBLE_EQ(sum["derived"]["position_jitter_m"].get<double>(), 0.02 * kR);
  {
    H5File f(dir / "seeded/results.h5", H5File::Mode::Read);
    EXPECT_EQ(f.read_double_attribute("disorder_seed"), 3.0);
    EXPECT_EQ(f.read_double_attribute("position_jitter"), 0.02);
  }
  const auto plain = run("plain", "");
  ASSERT_EQ(plain.exit_code, 0) << plain.output;
  EXPECT_EQ(plain.output.find("  disorder:"), std::string::npos) << plain.output;
  const auto sum0 = nlohmann::json::parse(test::read_file(dir / "plain/summary.json"));
  EXPECT_EQ(sum0["derived"]["disorder_seed"], 0);
  EXPECT_EQ(sum0["derived"]["position_jitter"], 0.0);
  H5File f(dir / "plain/results.h5", H5File::Mode::Read);
  EXPECT_EQ(f.read_double_attribute("disorder_seed"), 0.0);
  EXPECT_EQ(f.read_double_attribute("position_jitter"), 0.0);
}

}  // namespace
}  // namespace swarf
