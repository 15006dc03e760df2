// fcc_world.h: a World holding an FCC block of unit-mass particles and its rods (no law set),
// for tests that evaluate rods or their observers on positions they set themselves.
#pragma once

#include <array>
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

}  // namespace swarf::test
