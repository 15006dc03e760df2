// group_system.h: groups of particles whose components follow prescribed motions (grips,
// clamps, the workpiece's base), and the reactions they exert.
//
// Stages (integrate/integration.h): prescribe puts the prescribed components at their displacement at
// t + h with the step's velocity; account takes the reactions of the converged step (minus
// the internal forces on the members) and books the work the motions did on the body, by the
// trapezoid over the step, plus the change of the members' own kinetic energy (a grip that
// starts or reverses accelerates them). The members' indices are the World's (Group::members):
// the door (simulation_door.cpp) reindexes them; the system keeps only per-group values.
#pragma once

#include <array>
#include <vector>

#include "swarf/core/exact_sum.h"
#include "swarf/core/vec3.h"
#include "swarf/state/motion.h"
#include "swarf/state/particles.h"
#include "swarf/systems/energy_ledger.h"
#include "swarf/systems/step_context.h"

namespace swarf {

class StateArchive;

class GroupSystem {
 public:
  /// Sizes the per-group values and sums the groups' masses.
  void setup(const std::vector<Group>& groups, const Particles& p);
  /// The prescribed components at t + h (positions from the initial ones, velocities over the
  /// step). Always within the step's limits (true).
  bool prescribe(const StepContext& c);
  /// The reactions of the forces now (the initial state's, at construction).
  void init_reactions(const std::vector<Group>& groups, const Particles& p) { reactions(groups, p, reaction_); }
  /// After an accepted step: the reactions and the work of the motions.
  void account(const StepContext& c);
  /// The members' masses again, after the door changed the particles.
  void resize(const World& w);
  void visit_state(StateArchive& ar, World& w, EnergyLedger& ledger);

  // Domains (issue 38): a group's members may lie on several ranks; its reaction is the sum of
  // the ranks' parts. It computes no pair force, so it needs no ghosts.
  static constexpr Sharing sharing = Sharing::Replicated;
  double ghost_reach(const World&) const { return 0.0; }

  /// Force the group's prescribed motion exerts on the rest of the body, N (minus the sum of
  /// the internal forces on its particles).
  Vec3 reaction(std::size_t g) const { return reaction_[g]; }

  /// A domain's exact share of the groups' sums (issue 38), beside the plain ones: the work of
  /// the motions booked per member particle with counted[i] != 0 (the trapezoid's two halves,
  /// the force at the step's start and at its end, each times the step's displacement, and the
  /// member's own kinetic energy change), and the reactions now over the counted members.
  /// Summed over the domains, the same bits for any partition. nullptr: off. The array must be
  /// set again when the particles change.
  struct ExactShare {
    ExactSum external_work;                         ///< J
    std::vector<std::array<ExactSum, 3>> reaction;  ///< per group, N
  };
  void count_exactly(const std::uint8_t* counted, const World& w);
  const ExactShare& exact_share() const { return exact_; }

 private:
  static void reactions(const std::vector<Group>& groups, const Particles& p, std::vector<Vec3>& out);
  void account_exactly(const StepContext& c);
  void book_old_forces(const World& w);  // the counted members' forces now, for the next account

  std::vector<Vec3> u_old_, u_new_;            // displacements at t and t + h, m
  std::vector<Vec3> reaction_, reaction_old_;  // N
  std::vector<Vec3> v_;                        // velocity of the prescribed components in the last step, m/s
  std::vector<double> mass_;                   // total mass of each group, kg
  const std::uint8_t* counted_ = nullptr;      // exact share: per particle, counted here (null: off)
  ExactShare exact_;
  struct OldForce {
    std::int32_t group;
    Vec3 force;  // N
  };
  std::vector<OldForce> old_forces_;  // exact share: the counted members' forces at the last account
};

}  // namespace swarf
