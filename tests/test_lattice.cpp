// test_lattice.cpp: FCC lattice counts, bond lengths and coordination, the HDF5 round trip,
// and the pair search against brute force.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <random>
#include <set>

#include "lattice_gen/fcc_lattice.h"
#include "lattice_gen/lattice_file.h"
#include "swarf/neighbors/neighbor_pairs.h"
#include "test_helpers.h"

namespace swarf {
namespace {

// Bonds of an NX x NY x NZ cell block (half-open index box 2N per axis): for each of the six
// directions (1,+-1,0), (1,0,+-1), (0,1,+-1) the bonded sites fill a box one shorter along
// the two axes involved, half of whose points have an even index sum.
long expected_rods(long nx, long ny, long nz) {
  return 2 * ((2 * nx - 1) * (2 * ny - 1) * nz + (2 * nx - 1) * (2 * nz - 1) * ny + (2 * ny - 1) * (2 * nz - 1) * nx);
}

TEST(Lattice, CountsByCells) {
  for (auto c : {std::array<int, 3>{1, 1, 1}, {3, 2, 4}, {5, 5, 5}, {17, 17, 17}}) {
    FccSpec spec;
    spec.radius = 0.5e-3;
    spec.cells = c;
    const Lattice lat = generate_fcc(spec);
    EXPECT_EQ(long(lat.position.size()), 4L * c[0] * c[1] * c[2]);
    EXPECT_EQ(long(lat.rods.size()), expected_rods(c[0], c[1], c[2]));
  }
}

TEST(Lattice, W1SceneMatchesPeers) {
  // validation/bench/peers/README.md: 19,652 particles and 111,078 rods.
  FccSpec spec;
  spec.radius = 0.5e-3;
  spec.cells = {17, 17, 17};
  const Lattice lat = generate_fcc(spec);
  EXPECT_EQ(lat.position.size(), 19652u);
  EXPECT_EQ(lat.rods.size(), 111078u);
}

TEST(Lattice, BondLengthsCoordinationAndUniqueness) {
  FccSpec spec;
  spec.radius = 0.25e-3;
  spec.cells = {4, 5, 6};
  const Lattice lat = generate_fcc(spec);
  const double d = 2 * spec.radius;
  std::vector<int> coordination(lat.position.size(), 0);
  std::set<std::pair<int, int>> seen;
  for (std::size_t b = 0; b < lat.rods.size(); ++b) {
    const auto [i, j] = lat.rods[b];
    EXPECT_LT(i, j);
    EXPECT_TRUE(seen.insert({i, j}).second) << "bond (" << i << "," << j << ") twice";
    // Lattice sites are multiples of a/2; the length is 2R to rounding (1e-12 relative).
    EXPECT_NEAR(lat.rest_length[b], d, 1e-12 * d);
    ++coordination[i];
    ++coordination[j];
  }
  // Interior sites (at least one half-cell from every face) have exactly 12 rods.
  const double h = d / std::sqrt(2.0);
  Eigen::Vector3d hi(4 * 2 * h - h, 5 * 2 * h - h, 6 * 2 * h - h);
  int interior = 0;
  for (std::size_t i = 0; i < lat.position.size(); ++i) {
    const auto& p = lat.position[i];
    bool inside = true;
    for (int c = 0; c < 3; ++c) inside = inside && p[c] > 0.5 * h && p[c] < hi[c] - 0.5 * h;
    if (inside) {
      ++interior;
      EXPECT_EQ(coordination[i], 12) << "interior site " << i;
    }
    EXPECT_LE(coordination[i], 12);
  }
  EXPECT_GT(interior, 50);
  // None missing: brute force over all pairs.
  long brute = 0;
  for (std::size_t i = 0; i < lat.position.size(); ++i)
    for (std::size_t j = i + 1; j < lat.position.size(); ++j)
      if (std::abs((lat.position[i] - lat.position[j]).norm() - d) < 1e-6 * d) ++brute;
  EXPECT_EQ(brute, long(lat.rods.size()));
}

TEST(Lattice, BySizeFillsTheClosedBox) {
  // A box of exactly 2 x 1 x 1 cells by size includes the far faces: sites p with
  // 0 <= p_c <= 2 N_c and an even sum, i.e. (5*3*3 + 1)/2 = 23 sites.
  FccSpec spec;
  spec.radius = 0.5e-3;
  const double a = 2 * spec.radius * std::sqrt(2.0);
  spec.size = {2 * a, a, a};
  const Lattice lat = generate_fcc(spec);
  EXPECT_EQ(lat.position.size(), 23u);
  for (const auto& p : lat.position)
    for (int c = 0; c < 3; ++c) EXPECT_LE(p[c], spec.size[c] * (1 + 1e-12));
}

TEST(Lattice, RejectsBadSpecs) {
  FccSpec spec;
  spec.radius = -1e-3;
  spec.cells = {2, 2, 2};
  EXPECT_THROW(generate_fcc(spec), std::exception);
  spec.radius = 1e-3;
  spec.cells = {2, 0, 2};
  EXPECT_THROW(generate_fcc(spec), std::exception);
}

TEST(Lattice, Hdf5RoundTrip) {
  test::TempDir dir("lattice_h5");
  FccSpec spec;
  spec.radius = 0.5e-3;
  spec.cells = {3, 2, 2};
  const Lattice lat = generate_fcc(spec);
  write_lattice(dir / "l.h5", lat);
  const Lattice back = read_lattice(dir / "l.h5");
  ASSERT_EQ(back.position.size(), lat.position.size());
  ASSERT_EQ(back.rods.size(), lat.rods.size());
  for (std::size_t i = 0; i < lat.position.size(); ++i) EXPECT_EQ(back.position[i], lat.position[i]);
  for (std::size_t b = 0; b < lat.rods.size(); ++b) {
    EXPECT_EQ(back.rods[b], lat.rods[b]);
    EXPECT_EQ(back.rest_length[b], lat.rest_length[b]);
  }
  EXPECT_EQ(back.cell_edge, lat.cell_edge);
  EXPECT_FALSE(std::filesystem::exists(dir / "l.h5.part"));
}

TEST(Lattice, CliWritesFileAndCounts) {
  test::TempDir dir("lattice_cli");
  const auto r = test::run_command(std::string(SWARF_BINARY) + " lattice --cells 2,3,4 --radius 1e-3 --out " +
                                   (dir / "w.h5"));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("96 particles"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find(std::to_string(expected_rods(2, 3, 4)) + " rods"), std::string::npos) << r.output;
  const Lattice lat = read_lattice(dir / "w.h5");
  EXPECT_EQ(lat.position.size(), 96u);
  const auto bad = test::run_command(std::string(SWARF_BINARY) + " lattice --cells 2,3,4 --radius -1 --out " +
                                     (dir / "x.h5"));
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_NE(bad.output.find("radius"), std::string::npos) << bad.output;
}

TEST(PairSearch, MatchesBruteForceOnRandomPoints) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<Vec3> pts(600);
  for (auto& p : pts) p = Vec3(u(rng), u(rng), 0.3 * u(rng));
  const double lo = 0.05, hi = 0.09;
  const auto pairs = find_pairs_in_range(pts, lo, hi);
  std::vector<std::array<std::int32_t, 2>> brute;
  for (std::size_t i = 0; i < pts.size(); ++i)
    for (std::size_t j = i + 1; j < pts.size(); ++j) {
      const double d2 = (pts[i] - pts[j]).squaredNorm();
      if (d2 >= lo * lo && d2 <= hi * hi) brute.push_back({std::int32_t(i), std::int32_t(j)});
    }
  EXPECT_EQ(pairs, brute);  // same pairs in the same (sorted) order
}

}  // namespace
}  // namespace swarf
