// simulation.h: the time loop: step control around the integrators, the listeners, the door for
// particles, the state visit.
//
// A step is one of the integrators (integrate/integration.h: Verlet, the fixed-point Newmark
// sweeps, Newton-Krylov), free functions over the World, the systems (systems/systems.h) and the
// integrators' own state. The Simulation owns them and adds what lies around a step: the
// implicit step's save, rejection and step size control (paper section 3.4), the inflows and
// outflows after it, the listeners, the door through which particles are reordered, removed
// and appended, and the visit of the whole state (checkpoints and the state hash).
#pragma once

#include <cstdint>
#include <functional>
#include <limits>
#include <memory>
#include <vector>

#include "swarf/core/exact_sum.h"
#include "swarf/core/stage_clock.h"
#include "swarf/core/state_archive.h"
#include "swarf/integrate/integration.h"
#include "swarf/integrate/step_settings.h"
#include "swarf/state/reindex.h"
#include "swarf/state/world.h"
#include "swarf/step_listener.h"
#include "swarf/systems/energy_ledger.h"
#include "swarf/systems/systems.h"

namespace swarf {

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
  /// Replaces every particle and rod at once (a domain's migration, issue 38): 'particles'
  /// becomes the World's particles, the ends and per-rod arrays of 'rods' its rods' (the law,
  /// area and bond formation stay the World's); the rows, the groups' members (from the
  /// particles' group indices) and scratch follow, the step's state (time, counters, windows)
  /// stays. With contacts, 'contacts' holds the contacts that touch or carry a history
  /// (ContactSystem::records, indices into 'particles'): the lists are made anew around them
  /// (ContactSystem::replace). Throws InputError with contacts but no records, with bodies or
  /// flows, whose per-particle state cannot follow a wholesale change, or arrays of unequal length.
  void replace_particles(Particles particles, Rods rods, const ContactSystem::Records* contacts = nullptr);
  /// Lets 'write' overwrite the values of the particles' and rods' fields in place (the same
  /// particles and rods: a run over ranks bringing its mirror up to date, issue 38); 'write'
  /// must not resize or reorder them, nor change rod ends. The rows, the groups' members,
  /// scratch and the contacts follow as in replace_particles, with the same refusals.
  void overwrite_records(const std::function<void(Particles&, Rods&)>& write,
                         const ContactSystem::Records* contacts = nullptr);
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
  const NewtonStats& newton_stats() const { return ms_.newton_stats; }
  /// The Newton solve's CG preconditioned by p, which reads J assembled (integrate/tangent_matrix.h),
  /// in place of the matrix-free block-Jacobi; nullptr restores the block-Jacobi.
  void set_newton_preconditioner(std::shared_ptr<LinearPreconditioner> p) { ms_.newton.preconditioner = std::move(p); }
  const EnergyLedger& ledger() const { return ledger_; }
  /// The rods' ledger lines summed exactly over the rods whose first particle has counted[i]
  /// != 0 (RodSystem::count_exactly; nullptr: off): a domain's share, the same sums over the
  /// ranks for any partition. The array must be set again when the particles change.
  /// The groups' work and reactions too (GroupSystem::count_exactly).
  /// 'rod_keys': per rod, its place in the global rod order (nullptr: this World's rods are the
  /// global list), for RodSystem::count_exactly.
  /// With contacts, the contact part of each particle's force is kept (contact_power_exact).
  void count_exactly(const std::uint8_t* counted, const std::int64_t* rod_keys = nullptr) {
    sys_.rods.count_exactly(counted, rod_keys);
    sys_.groups.count_exactly(counted, m_);
    ms_.keep_contact_force = counted != nullptr;
  }
  /// The power of the contact forces and torques on the particles i with counted[i] at the end
  /// of the last step (the ledger's contact line measures it so, trapezoid over the step), each
  /// term added exactly, W: a domain's share (issue 38; needs count_exactly's mask set).
  ExactSum contact_power_exact(const std::uint8_t* counted) const;
  const RodSystem::ExactLedger& exact_ledger() const { return sys_.rods.exact_ledger(); }
  const GroupSystem::ExactShare& exact_group_share() const { return sys_.groups.exact_share(); }
  std::size_t broken_rods() const { return sys_.rods.broken(); }
  /// Rods formed (or formed again) during the run by bond formation (laws/bond_formation.h).
  std::size_t formed_rods() const { return sys_.rods.formed(); }

  /// Rotations are integrated only when on (set by a torque source, or by hand in tests).
  bool rotations() const { return ms_.rotations; }
  /// Turning rotations on makes the angular accelerations consistent with the current torques
  /// and angular velocities (Euler's equations), as the Newmark update assumes.
  void set_rotations(bool on);

  double kinetic_energy() const;     ///< translational + rotational, J
  double rotational_energy() const;  ///< rotational part of the kinetic energy, J
  /// The particles' kinetic energy (translational + rotational, the bodies' apart), J, summed
  /// exactly over the particles i with counted[i] (all when null): the same bits for any
  /// split of the particles over domains (core/exact_sum.h). kinetic_energy() is its value
  /// plus the bodies'.
  ExactSum particle_kinetic_energy(const std::uint8_t* counted = nullptr) const;
  /// Recoverable elastic energy of the intact rods, J.
  double elastic_energy() const;
  /// The same over the rods k with counted[k] (all when null), exactly (as particle_kinetic_energy).
  ExactSum rod_elastic_energy(const std::uint8_t* counted = nullptr) const {
    return sys_.rods.elastic_energy_exact(m_, counted);
  }
  /// Elastic energy stored in the contacts now (Hertz, normal part), J.
  double contact_energy() const { return sys_.contacts.enabled() ? sys_.contacts.elastic_energy() : 0.0; }
  /// Potential energy in gravity relative to the initial positions, J.
  double potential_energy() const;
  /// Force the particles exert on mesh m in the last evaluation of an accepted step, N.
  Vec3 mesh_force(std::size_t m) const { return ms_.mesh_force[m]; }
  /// The power of the contact forces at the end of the last step, W: where the ledger's
  /// contact line (a trapezoid over each step) goes on from.
  double contact_power() const { return ms_.contact_power_old; }
  /// Kinetic energy of the rigid bodies, J (part of kinetic_energy()).
  double body_kinetic_energy() const { return sys_.bodies.kinetic_energy(m_); }
  const ContactSystem& contacts() const { return sys_.contacts; }
  /// The heat: the tools' temperatures, the stored heat, the conduction's step (issue 33).
  const ThermalSystem& thermal() const { return sys_.thermal; }
  /// A domain's link to the other domains for what a step needs of them midway (issue 38;
  /// systems/step_exchange.h): the heat's conduction, bond formation. Not owned; null: a run in one process.
  void set_exchange(StepExchange* x) {
    sys_.thermal.set_exchange(x);
    sys_.rods.set_exchange(x);
  }
  /// Per-stage wall time of the steps taken while enabled (swarf bench --stages).
  StageClock& stage_clock() { return clock_; }
  const StageClock& stage_clock() const { return clock_; }
  /// Force the group's prescribed motion exerts on the rest of the body, N (minus the sum
  /// of the internal forces on its particles).
  Vec3 group_reaction(std::size_t g) const { return sys_.groups.reaction(g); }

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
  void apply_flows(double h);  // outflows then inflows after a step of h
  /// What the integrators work on in a step that starts now.
  Integration integration() { return Integration{m_, sys_, ms_, set_, clock_, stats_, ledger_, time_, implicit_}; }
  void reindex_all(const Reindex& r);  // the door's common part
  // after replace_particles, overwrite_records: rows, members, contacts, scratch
  void records_replaced(const ContactSystem::Records* contacts);
  void resize_scratch();  // per-particle, per-rod-block and per-group scratch after a change
  void check_loaded_world(const std::vector<std::int32_t>& ends);  // after a load: sizes, indices, rows
  void update_mesh_step_limit();  // after the particles change (construction, the door, a load)

  World& m_;
  StepSettings set_;
  std::vector<StepListener*> listeners_;
  bool implicit_ = false;
  double time_ = 0;
  double dt_ = 0;
  double last_dt_ = 0;
  EnergyLedger ledger_;
  StepStats stats_;
  Systems sys_;     // each system with its own state and stages (systems/systems.h)
  MotionState ms_;  // the integrators' own state (integrate/integration.h)
  StageClock clock_;
};

}  // namespace swarf
