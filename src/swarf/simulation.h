// simulation.h: the time loop's state and the step function with named stages.
//
// Both schemes are Newmark's family, x+ = x + dt v + dt^2 ((1/2 - beta) a + beta a+),
// v+ = v + dt ((1 - gamma) a + gamma a+), and share the stages:
//   prescribe     group and mesh motions at t + dt (displacements and step velocities); rigid
//                 bodies are placed with the particles (systems/body_system.cpp)
//   rod_forces    every intact rod evaluated from its COMMITTED state: trial shift, trial
//                 break flag, force coefficient
//   contact_forces  Verlet lists updated if needed; every contact evaluated from its
//                 committed friction history (contacts.h)
//   gather        per particle, its rods' forces summed in fixed (rod) order; a = f/m
//   commit        plastic shifts and breakage of the final evaluation written back
//   account       work of the grips, dissipation, time and counters
// Explicit (velocity Verlet = beta 0, gamma 1/2, one evaluation per step):
//   prescribe, kick_drift (v += dt/2 a, x += dt v), rod_forces, contact_forces (final: the
//   friction histories are committed in place), gather fused with the kick (v += dt/2 a and
//   the rotation update, particle by particle), commit, account
// Implicit Newmark (beta 1/4, gamma 1/2 by default), solved by fixed-point iteration:
//   save, prescribe, then repeat { place (x, v and the rotations from the latest a+), rod_forces,
//   contact_forces, gather } until the sweep's change is below the tolerance (see gather); then place once more with
//   the final a+, commit, account. A step that does not converge (or diverges, or moves a particle too far) is
//   rejected: everything is restored from the saved state, bit for bit, and retried with a smaller step. The number of
//   sweeps drives the next step size (paper section 3.4).
// Or, with StepSettings::solver = Solver::Newton, by Newton-Krylov on the same step's residual (try_newton,
// simulation_newton.cpp): the same prescribe, place, rod_forces and contact_forces stages, a CG solve with
// the rods' and contacts' tangent between evaluations, the same commit; converges beyond the explicit stable step.
#pragma once

#include <cstdint>
#include <limits>
#include <tuple>
#include <vector>

#include "swarf/contacts/contacts.h"
#include "swarf/core/stage_clock.h"
#include "swarf/core/state_archive.h"
#include "swarf/integrate/newton_newmark.h"
#include "swarf/laws/rotation.h"
#include "swarf/state/reindex.h"
#include "swarf/state/world.h"
#include "swarf/step_listener.h"
#include "swarf/step_settings.h"
#include "swarf/systems/body_system.h"
#include "swarf/systems/energy_ledger.h"
#include "swarf/systems/flow_system.h"
#include "swarf/systems/group_system.h"
#include "swarf/systems/plastic_strain_system.h"
#include "swarf/systems/rod_system.h"
#include "swarf/systems/step_context.h"
#include "swarf/systems/thermal_system.h"

namespace swarf {

/// Counters of the step control.
struct StepStats {
  std::int64_t accepted = 0;           ///< steps taken
  std::int64_t rejected = 0;           ///< steps rejected and retried
  std::int64_t iterations = 0;         ///< fixed-point sweeps of accepted steps
  std::int64_t force_evaluations = 0;  ///< all rod-force evaluations, rejected steps included
  int max_iterations = 0;              ///< most sweeps an accepted step needed
  int last_iterations = 0;             ///< sweeps of the last accepted step
};

class Simulation {
 public:
  /// Steps 'world' (held by reference: the caller owns it) with 'settings' (copied).
  Simulation(World& world, const StepSettings& settings);

  /// Advances one step (Newmark: of at most max_dt, e.g. the time left to the end).
  /// Throws SimulationError when the state blows up or the step falls below dt_min.
  void step(double max_dt = std::numeric_limits<double>::infinity());

  /// Registers a listener called around every step (not owned; remove it before it dies).
  void add_listener(StepListener* l) { listeners_.push_back(l); }
  void remove_listener(StepListener* l) { std::erase(listeners_, l); }

  // The one door for changing the particles between steps: every per-particle array, rod
  // end, group member list and contact (with its friction history) follows. Ids
  // (Particles::id) stay with their particles.
  /// Reorders the particles: order[k] is the current index of the particle placed at k.
  void apply_permutation(const std::vector<std::int32_t>& order);
  /// Inflow and outflow regions (particle_flows.h) act after every accepted step, before the
  /// listeners' after_step: the outflows remove the particles whose centres lie in them, then
  /// the inflows create theirs. The energy they carry is in EnergyLedger::flow_energy.
  /// Removes the particles with remove[i] != 0, their rods and their contacts; the others
  /// keep their order. Returns the number of rods removed with them.
  std::size_t remove_particles(const std::vector<std::uint8_t>& remove);
  /// Appends 'extra' (its arrays sized alike, as Particles::resize makes them; its ids are
  /// ignored: new ones are given). The new particles have no rods; the contact lists are
  /// rebuilt at the next evaluation so that they take part.
  void append_particles(const Particles& extra);
  /// Places rigid body b at 'position' (centre of mass, m) and 'orientation' (principal frame
  /// -> world, normalised here) between steps, its mesh with it. A hinge's orientation follows its
  /// angle, so it is refused for a hinged body unless unchanged. Throws InputError on a
  /// non-finite value.
  void set_body_pose(std::size_t b, const Vec3& position, const Quat& orientation);

  double time() const { return time_; }
  std::int64_t steps() const { return stats_.accepted; }
  /// The step size the next step will try (explicit: the fixed step), s.
  double dt() const { return dt_; }
  /// The size of the last accepted step, s.
  double last_dt() const { return last_dt_; }
  bool implicit() const { return implicit_; }
  const StepStats& stats() const { return stats_; }
  /// Counters of the Newton solver (zero with the fixed-point one).
  const NewtonStats& newton_stats() const { return newton_stats_; }
  const EnergyLedger& ledger() const { return ledger_; }
  std::size_t broken_rods() const { return rods_.broken(); }
  /// Rods formed (or formed again) during the run by bond formation (laws/bond_formation.h).
  std::size_t formed_rods() const { return rods_.formed(); }

  /// Rotations are integrated only when on (set by a torque source, or by hand in tests).
  bool rotations() const { return rotations_; }
  /// Turning rotations on makes the angular accelerations consistent with the current torques
  /// and angular velocities (Euler's equations), as the Newmark update assumes.
  void set_rotations(bool on);

  double kinetic_energy() const;     ///< translational + rotational, J
  double rotational_energy() const;  ///< rotational part of the kinetic energy, J
  /// Recoverable elastic energy of the intact rods, J.
  double elastic_energy() const;
  /// Elastic energy stored in the contacts now (Hertz, normal part), J.
  double contact_energy() const { return contacts_.enabled() ? contacts_.elastic_energy() : 0.0; }
  /// Potential energy in gravity relative to the initial positions, J.
  double potential_energy() const;
  /// Force the particles exert on mesh m in the last evaluation of an accepted step, N.
  Vec3 mesh_force(std::size_t m) const { return mesh_force_[m]; }
  /// Kinetic energy of the rigid bodies, J (part of kinetic_energy()).
  double body_kinetic_energy() const { return bodies_.kinetic_energy(m_); }
  const ContactSystem& contacts() const { return contacts_; }
  /// The heat: the tools' temperatures, the stored heat, the conduction's step (issue 33).
  const ThermalSystem& thermal() const { return thermal_; }
  /// Per-stage wall time of the steps taken while enabled (swarf bench --stages).
  StageClock& stage_clock() { return clock_; }
  const StageClock& stage_clock() const { return clock_; }
  /// Force the group's prescribed motion exerts on the rest of the body, N (minus the sum
  /// of the internal forces on its particles).
  Vec3 group_reaction(std::size_t g) const { return groups_.reaction(g); }

  World& world() { return m_; }
  const World& world() const { return m_; }
  const StepSettings& settings() const { return set_; }

  /// Every field of the state the next step reads, each named once (state_archive.h): one
  /// function saves, loads and hashes it. Load into a Simulation constructed from the same
  /// World as the one saved.
  void visit_state(StateArchive& ar);
  /// How far beyond a domain's region a rank would need copies of particles for every force the
  /// step computes (rods, contacts, inflows): the largest of the systems' reaches, m (issue 38).
  double ghost_reach() const;
  /// 64-bit hash of that state (bit-exact: any difference in any field changes it).
  std::uint64_t state_hash() const;

 private:
  void step_scheme(double max_dt);
  void step_explicit();
  bool try_newmark(double h);  // true if converged (state advanced, not yet committed)
  // The Newton-Krylov solve of the same step (simulation_newton.cpp).
  bool try_newton(double h);
  double newton_residual(double h);  // forces at the placed state, R = M a - F; returns |R| / force level
  void newton_tangent(double h);     // per-rod blocks of J and the particles' block-Jacobi inverses
  int newton_krylov();               // CG on J d = -R; iterations, or -1 if J is not positive definite
  template <bool Wrap, bool Contacts>
  double newton_residual_impl();
  void newton_product(const std::vector<Vec3>& x, std::vector<Vec3>& out, double& dot);  // out = J x, dot = x.Jx

  // Stages.
  bool prescribe(double h);   // false if a mesh would move too far in the step
  bool kick_drift(double h);  // explicit predictor; false if a particle moved too far
  bool place(double h);       // Newmark positions, velocities and rotations from the latest a; false if too far
  void rotate_one(std::size_t i, double h, double beta, double gamma);
  void rod_forces();
  void contact_forces(double h, bool final = false);
  double gather();             // returns the sweep's relative force change (free components; implicit only)
  void gather_kick(double h);  // explicit: gather, then the corrector v += h/2 a and the rotation
  enum class GatherMode { Plain, Measure, Kick };
  template <GatherMode Mode, bool Wrap>
  double gather_impl(double h);
  void commit(double h);  // the heat of the step (before the rods' commit reads its trial), then the commits
  /// After the rod kernel: rods on the meshes' parting lines (laws/parting_rule.h) break in
  /// this trial (force zero, broken at commit like a rod that failed by its law).
  /// Commit, last part: rods between pressed unbonded lattice particles (bond_formation.h).
  void account(double h);

  void apply_flows(double h);  // outflows then inflows after a step of h

  void update_free_to_rotate();
  void update_free_to_rotate(const std::vector<std::array<std::int32_t, 2>>& pairs);  // only these particles
  void rebuild_free_list();                                                           // from the flags
  void reindex_all(const Reindex& r);                                                 // the door's common part
  void resize_scratch();
  void check_loaded_world(const std::vector<std::int32_t>& ends);  // after a load: sizes, indices, rows // per-particle,
                                                                   // per-rod-block and per-group scratch after a change
  void save_state();
  void restore_state();
  [[noreturn]] void throw_too_far(double h) const;

  World& m_;
  StepSettings set_;
  std::vector<StepListener*> listeners_;
  void update_mesh_step_limit();  // after the particles change (construction, the door, a load)
  bool mesh_rejected_ = false;    // the last Newmark try was rejected because a mesh moved too far
  bool implicit_ = false;
  bool rotations_ = false;
  double time_ = 0;
  double dt_ = 0;
  double last_dt_ = 0;
  EnergyLedger ledger_;
  StepStats stats_;
  // The systems, each with its own state and stages (systems/). A stage that several systems
  // have calls them in this fixed order, one call each, found at compile time (no virtual call,
  // no empty stage): prescribe (the meshes, then the groups), account (the bodies' loads, the
  // rods' viscous work, the groups' reactions), resize after the door, visit_state. A new
  // system is a member and an entry in systems(). The contacts are called by name: the rods'
  // commit and bond formation hand them pairs, and the integrators time them apart.
  BodySystem bodies_;
  RodSystem rods_;
  GroupSystem groups_;
  FlowSystem flows_;
  ThermalSystem thermal_;
  PlasticStrainSystem plastic_;
  RodSystem::WorkList rod_work_;  // commit's scratch: the rods that flowed in the step (the heat's and PEEQ's sources)
  auto systems() { return std::tie(bodies_, rods_, groups_, flows_, thermal_, plastic_); }
  template <class F>
  void for_each_system(F&& f) {
    std::apply([&](auto&... s) { (f(s), ...); }, systems());
  }
  StepContext context(double h) { return StepContext{m_, time_, h, set_.beta, set_.gamma, implicit_, ledger_}; }
  std::vector<Vec3> mesh_force_;     // force on each mesh after the last accepted step, N
  double sweep_force_level2_ = 0;    // the particles' force level of the last sweep squared, N^2
  std::vector<Vec3> contact_force_;  // contact part of each particle's force, N
  double contact_power_old_ = 0;     // power of the contact forces at the start of the step, W
  double kick_power_ = 0;            // power of the contact forces on the particles after the kick, W
  std::vector<double> block_power_;  // its parts per block of particles, W
  /// Power of the contact forces on the particles and the meshes, W; the particles' part
  /// from the fused gather and kick if 'from_kick'.
  double contact_power(bool from_kick = false) const;
  /// The particles' part of the sweep's convergence measure, for the bodies' part.
  SweepMeasure sweep_measure() const { return {implicit_, sweep_dt_, set_.beta, sweep_force_level2_, step_disp2_}; }
  // Start-of-step state for Newmark (predictor and rejection).
  std::vector<Vec3> x_n_, v_n_, a_n_, f_n_;
  std::vector<Vec3> a_guess_;  // accelerations a sweep placed with (integrator.relaxation < 1)
  std::vector<RotState> rot_n_;
  NewtonWork nk_;
  NewtonStats newton_stats_;
  ContactSystem contacts_;
  StageClock clock_;
  std::vector<std::uint8_t> free_to_rotate_;  // 1 for particles without intact rods
  std::vector<std::int32_t> free_list_;       // those particles, in order
  bool rebuild_lists_ = false;  // rebuild the contact lists at the next evaluation (set by append_particles)
  double sweep_dt_ = 0;         // step size of the current sweep, s
  double step_disp2_ = 0;       // largest squared displacement of the step so far, m^2
  double moved2_ = -1.0;        // largest squared displacement since the contact lists' build, m^2 (< 0: unknown)
};

}  // namespace swarf
