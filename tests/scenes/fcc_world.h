// fcc_world.h: a World holding an FCC block of unit-mass particles and its rods (no law set),
// for tests that evaluate rods or their observers on positions they set themselves.
#pragma once

#include <Eigen/Dense>
#include <array>
#include <cmath>
#include <cstdint>

#include "lattice_gen/fcc_lattice.h"
#include "swarf/state/world.h"

namespace swarf::test {

/// cells[0] x cells[1] x cells[2] FCC cells of radius R (m): positions at the lattice's (initial and
/// current), unit masses, ids in index order, the lattice's rods virgin and their rows built.
inline World fcc_world(double R, std::array<int, 3> cells) {
  FccSpec spec;
  spec.radius = R;
  spec.cells = cells;
  const Lattice lat = generate_fcc(spec);
  World w;
  Particles& p = w.particles;
  const std::size_t n = lat.position.size();
  p.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    p.position[i] = p.initial_position[i] = lat.position[i];
    p.radius[i] = R;
    p.mass[i] = p.inv_mass[i] = 1.0;
    p.id[i] = static_cast<std::int64_t>(i);
  }
  p.next_id = static_cast<std::int64_t>(n);
  w.rods.ends = lat.rods;
  w.rods.rest_length = lat.rest_length;
  w.rods.reset_state();
  w.rods.build_rows(n);
  return w;
}

/// The block of fcc_world with its positions mapped by x -> c + F (x - c) about its centre c, its
/// rods of cross-section 1 mm^2 following the paper's single-slope law at k = 0 (perfectly plastic)
/// with modulus E (Pa) and yield strain eps_y (1), unbreakable.
inline World mapped_fcc_block(double R, std::array<int, 3> cells, const Eigen::Matrix3d& F, double E,
                              double yield_strain) {
  World w = fcc_world(R, cells);
  Particles& p = w.particles;
  Vec3 c = Vec3::Zero();
  for (const Vec3& x : p.initial_position) c += x;
  c /= double(p.size());
  for (std::size_t i = 0; i < p.size(); ++i) p.position[i] = c + F * (p.initial_position[i] - c);
  RodLaw law;
  law.youngs_modulus = E;
  law.yield_strain = yield_strain;
  law.hardening = 0.0;
  law.tensile_strength = HUGE_VAL;
  w.rods.law = law;
  w.rods.area = 1e-6;
  return w;
}

}  // namespace swarf::test
