// rods.h: the rods of the workpiece, each stored once.
//
// Per rod: its two particles, rest length, the COMMITTED plastic shift and intact flag,
// plus the trial values and the force of the last evaluation, kept as one coefficient: the
// force on end i is coef (x_j - x_i) and on end j coef (x_i - x_j), so Newton's third law
// holds exactly and the gather needs no sign. The force on a particle is gathered in a fixed
// order from a per-particle list of its rods (compressed rows built once), so that the sum
// does not depend on the number of threads.
#pragma once

#include <array>
#include <cstdint>
#include <type_traits>
#include <vector>

#include "swarf/core/vec3.h"
#include "swarf/laws/any_rod_law.h"
#include "swarf/laws/bond_formation.h"

namespace swarf {

struct Rods {
  AnyRodLaw law;                    ///< one rod family: the law (any_rod_law.h) with its parameters
  double area = 0.0;                ///< cross-section A of every rod, m^2
  BondFormation formation;          ///< when unbonded lattice particles pressed together form a rod (off by default)
  bool isochoric = false;           ///< each step's plastic increments made mean-free per particle: the lattice's
                                    ///< plastic flow keeps its volume (forces/plastic_volume.h); set with
                                    ///< formation.lattice_length
  double compaction_modulus = 0.0;  ///< K, Pa, of a neighbourhood compacted beyond compaction_onset
                                    ///< (forces/density_floor.h); 0: none
  double compaction_onset = 0.0;    ///< theta_0, 1: the volume a neighbourhood may lose before K acts

  std::vector<std::array<std::int32_t, 2>> ends;  ///< particle indices (i, j), i < j
  std::vector<double> rest_length;                ///< L0, m
  std::vector<double> shift;                      ///< committed plastic shift eps0, 1
  std::vector<std::uint8_t> intact;               ///< committed: 1 intact, 0 broken (for good unless 'formation')
  std::vector<std::uint8_t> formed;  ///< 1 for a rod between a new pair, formed during the run (bond_formation.h)

  // Results of the last evaluation (trial state, not committed).
  std::vector<double> trial_shift;         ///< 1
  std::vector<std::uint8_t> trial_broken;  ///< 1 if this evaluation broke the rod
  std::vector<double> stress;              ///< elastic-plastic stress, Pa
  std::vector<double> force_coef;          ///< (sigma + sigma_visc) A / L: force on i = coef (x_j - x_i), N/m

  /// One entry of a particle's rod list: the rod and the particle at its other end.
  struct Entry {
    std::int32_t rod;
    std::int32_t other;
  };
  // Per-particle rod lists (compressed rows), in ascending rod order.
  std::vector<std::int32_t> row_start;  ///< size particles + 1
  std::vector<Entry> entries;
  std::vector<Entry> spare_entries;  ///< update_rows' scratch (its last rows), kept so that a cut's many
                                     ///< updates reuse its memory instead of faulting in fresh pages

  std::size_t size() const { return ends.size(); }

  /// Calls f(name, array) for every per-rod array except 'ends', in one fixed order (the
  /// removal of rods and the state visit go through it, so a new field is added here once).
  template <class F>
  void for_each_field(F&& f) {
    f("rest_length", rest_length);
    f("shift", shift);
    f("intact", intact);
    f("formed", formed);
    f("trial_shift", trial_shift);
    f("trial_broken", trial_broken);
    f("stress", stress);
    f("force_coef", force_coef);
  }
  /// Calls f(mine, theirs) for each per-rod array of this and of 'other' (the same field, so the
  /// same type), in for_each_field's order: copying or moving rods' fields between two Rods.
  template <class F>
  void for_each_field_with(Rods& other, F&& f) {
    std::vector<void*> theirs;
    other.for_each_field([&](const char*, auto& v) { theirs.push_back(&v); });
    std::size_t k = 0;
    for_each_field(
        [&](const char*, auto& v) { f(v, *static_cast<std::remove_reference_t<decltype(v)>*>(theirs[k++])); });
  }

  /// Sets the committed state to virgin (no shift, all intact) and sizes the scratch arrays.
  void reset_state();
  /// Builds the per-particle rod lists for n particles.
  void build_rows(std::size_t n_particles);
  /// Number of the lattice's own rods (those not formed during the run) that are broken. A
  /// formed rod that breaks is removed (remove_broken_formed), so it is not counted.
  std::size_t broken_count() const;
  /// Number of the lattice's own rods (those not formed during the run).
  std::size_t original_count() const;
  /// Brings the rows up to date after the rods from index 'first_changed' on were appended,
  /// removed or moved, while those before it kept their index and ends. Each row is sorted, so
  /// its rods below 'first_changed' are a prefix that is copied; only the changed rods are
  /// placed. The result equals build_rows(n_particles), at a cost in the changed rods and the
  /// particles instead of all the rods (bond formation changes a few rods at the end at most
  /// steps of a cut).
  void update_rows(std::size_t first_changed, std::size_t n_particles);
  /// Removes the formed rods that are broken and returns the index of the first rod that moved
  /// (size() when none was removed). They carry no force, and a pair that forms again gets a new
  /// rod, as a virgin as a revived one would be, so nothing is lost; without this, every
  /// neighbour exchange would leave a dead rod that the kernels visit for the rest of the run.
  /// The others keep their order. Formed rods are appended, so they sit after the lattice's
  /// rods, and only that tail is searched. The rows are stale until update_rows.
  std::size_t remove_broken_formed();
  /// Appends an intact, stress-free rod of rest length 'length' (m) between i and j, marked
  /// 'formed'; the rows are stale until build_rows.
  void append_formed(std::int32_t i, std::int32_t j, double length);
};

/// Per-particle rod lists built apart from a Rods (what Rods::build_rows fills in place).
struct RodRows {
  std::vector<std::int32_t> row_start;  ///< size particles + 1
  std::vector<Rods::Entry> entries;
};

/// The per-particle rod lists of 'ends' for n particles, each in ascending rod order.
void build_rod_rows(const std::vector<std::array<std::int32_t, 2>>& ends, std::size_t n_particles, RodRows& out);

}  // namespace swarf
