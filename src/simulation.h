// simulation.h: the time loop's state and the step function with named stages.
//
// One step of velocity Verlet is, in order:
//   predict       half kick v += dt/2 a, drift x += dt v; prescribed components follow
//                 their group's motion at t + dt; a particle that moves more than
//                 max_step_displacement radii stops the run
//   rod_forces    every intact rod evaluated from its committed state: trial shift,
//                 trial break flag, force (rate term from the half-step velocities)
//   gather        per particle, the forces of its rods summed in fixed (rod) order
//   correct       second half kick v += dt/2 a
//   commit        plastic shifts and breakage of the converged evaluation written back
//                 (for Verlet every evaluation is final; the Newmark step will iterate
//                 rod_forces..correct and commit only after convergence)
//   account       work of the grips, dissipation, time and step counters
#pragma once

#include <cstdint>
#include <vector>

#include "model.h"

namespace swarf {

/// Energy bookkeeping, J. external = kinetic + elastic + plastic + viscous + fracture (+ error).
struct EnergyLedger {
  double external_work = 0;     ///< work done by the prescribed motions
  double plastic_work = 0;      ///< sum of sigma d(eps_p) A L0 over commits
  double viscous_work = 0;      ///< dissipated by the rods' viscous part
  double fracture_energy = 0;   ///< elastic energy lost with broken rods
};

class Simulation {
 public:
  explicit Simulation(Model& model);

  /// Advances one step of size dt(). Throws SimulationError when the state blows up.
  void step();

  double time() const { return time_; }
  std::int64_t steps() const { return steps_; }
  double dt() const { return dt_; }
  const EnergyLedger& ledger() const { return ledger_; }
  std::size_t broken_rods() const { return broken_; }

  double kinetic_energy() const;
  /// Recoverable elastic energy of the intact rods, J.
  double elastic_energy() const;
  /// Force the group's prescribed motion exerts on the rest of the body, N (minus the sum
  /// of the internal forces on its particles).
  Vec3 group_reaction(std::size_t g) const { return reaction_[g]; }

  Model& model() { return m_; }
  const Model& model() const { return m_; }

 private:
  void predict();
  void rod_forces();
  void gather();
  void correct();
  void commit();
  void account();

  void compute_reactions(std::vector<Vec3>& out) const;

  Model& m_;
  double time_ = 0;
  std::int64_t steps_ = 0;
  double dt_ = 0;
  std::size_t broken_ = 0;
  EnergyLedger ledger_;
  std::vector<double> block_viscous_;   // per rod block, W
  std::vector<int> block_changed_;      // per rod block: a trial shift or break to commit
  std::vector<Vec3> group_u_old_, group_u_new_;  // group displacements at t and t + dt
  std::vector<Vec3> reaction_, reaction_old_;
  std::vector<Vec3> group_v_;      // velocity of the prescribed components in the last step, m/s
  std::vector<double> group_mass_; // total mass of each group, kg
};

}  // namespace swarf
