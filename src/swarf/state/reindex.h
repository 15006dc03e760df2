// reindex.h: the one door for changing particle indices (reordering and removal).
//
// A Reindex maps every current particle index to its new index, or to kRemoved. Applied to
// the particle arrays, the rods (a rod with a removed end goes with it; the others' ends are
// renumbered, i < j kept), the groups' member lists and, through Simulation, the contact
// lists with their friction histories. Rods keep their order, so each particle's forces are
// still summed in rod order. Simulation::apply_permutation / remove_particles /
// append_particles are the public door; these functions are its parts.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "swarf/state/motion.h"
#include "swarf/state/particles.h"
#include "swarf/state/rods.h"

namespace swarf {

struct Reindex {
  static constexpr std::int32_t kRemoved = -1;
  std::vector<std::int32_t> new_index;  ///< per current particle: its new index, or kRemoved
  std::size_t new_count = 0;            ///< particles after the change

  /// order[k]: the current index of the particle that goes to index k (a permutation of
  /// 0..n-1; throws std::invalid_argument otherwise).
  static Reindex permutation(const std::vector<std::int32_t>& order);
  /// Removes the particles with remove[i] != 0; the others keep their order.
  static Reindex removal(const std::vector<std::uint8_t>& remove);
};

void reindex(Particles& p, const Reindex& r);
/// Drops the rods with a removed end and renumbers the others; rebuilds the per-particle
/// rows. Returns the number of rods dropped.
std::size_t reindex(Rods& rods, const Reindex& r);
void reindex(std::vector<Group>& groups, const Reindex& r);

/// Particle i's new index in a std::vector<T> of per-particle values (the generic step).
template <class T>
void reindex_array(std::vector<T>& v, const Reindex& r) {
  std::vector<T> out(r.new_count);
  for (std::size_t i = 0; i < v.size() && i < r.new_index.size(); ++i)
    if (r.new_index[i] != Reindex::kRemoved) out[r.new_index[i]] = v[i];
  v.swap(out);
}

}  // namespace swarf
