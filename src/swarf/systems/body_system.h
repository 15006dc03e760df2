// body_system.h: the meshes' motions: prescribed (tools on their paths) or as rigid bodies
// under the contacts, their loads and gravity (state/rigid_body.h).
//
// Stages (integrate/integration.h):
//   prescribe   the prescribed meshes at t + h (offset and the step's velocity)
//   place       Newmark: each body at x+ from the latest wrench, turned by the quaternion
//               Newmark update; Verlet: drift before the contacts, kick after them
//   gather      the bodies' wrenches from the contacts (and their part of the sweep's
//               convergence measure)
//   account     the work of the bodies' external loads
//   visit_state the meshes' placement and the bodies' state and last wrench
// A rejected Newmark try restores the bodies saved at the start of the step. The system owns
// the mesh -> body map, the start-of-step copy and the bodies' initial centres; the bodies
// and meshes themselves are the World's.
#pragma once

#include <cmath>
#include <cstdint>
#include <vector>

#include "swarf/core/vec3.h"
#include "swarf/state/world.h"
#include "swarf/systems/energy_ledger.h"
#include "swarf/systems/step_context.h"

namespace swarf {

class ContactSystem;
class StateArchive;

/// What the bodies' part of a Newmark sweep's convergence measure compares with (the
/// particles' part, from the gather).
struct SweepMeasure {
  bool implicit = false;
  double h = 0;             ///< the sweep's step, s
  double beta = 0;          ///< Newmark's beta, 1
  double force_level2 = 0;  ///< the particles' force level squared, N^2
  double step_disp2 = 0;    ///< the particles' largest squared displacement in the step, m^2
};

class BodySystem {
 public:
  /// Checks the bodies (Newton's tangent treats meshes as prescribed: refused with 'newton'),
  /// builds the mesh -> body map and places the bodies' meshes.
  void setup(World& w, bool newton);
  /// How far a mesh may move in a step, m (max_step_displacement x the smallest radius).
  void set_step_limit(double limit) { step_limit_ = limit; }
  double step_limit() const { return step_limit_; }

  /// The prescribed meshes at t + h; false if one would move further than the step limit.
  bool prescribe(const StepContext& c);
  [[noreturn]] void throw_mesh_too_far(const World& w, double t, double h, std::int64_t step,
                                       double max_step_displacement) const;

  /// Saves the bodies at the start of a Newmark step.
  void save(const World& w) { body_n_ = w.bodies; }
  /// A rejected try: the bodies as saved, their meshes placed again; t the step's start, s.
  void restore(World& w, double t);
  /// Newmark placement from the saved start and the latest wrench; false if too far.
  bool place(World& w, double t, double h, double beta, double gamma) { return advance(w, t, h, beta, gamma); }
  /// Verlet: saves the start, then the positions and orientations (beta = 0).
  bool drift(World& w, double t, double h);
  /// Verlet: the same update with the new wrench: the velocities get the kick.
  void kick(World& w, double t, double h);
  /// Every body's wrench; Newmark: returns the sweep's change measure (0 if none).
  double wrenches(World& w, const ContactSystem& contacts, const SweepMeasure& sweep);
  /// Accelerations consistent with the wrench (construction).
  void init_accelerations(World& w);
  /// Body b's mesh from its pose.
  void place_mesh(World& w, std::size_t b);

  /// The power of the loads now, as the start of the first step's trapezoid (construction).
  void init_power(const World& w) { power_old_ = load_power(w); }
  /// The work of the bodies' external loads over an accepted step.
  void account(const StepContext& c);

  /// The rigid body that moves mesh k, or -1 (a prescribed mesh).
  int mesh_body(std::size_t k) const { return mesh_body_[k]; }
  double kinetic_energy(const World& w) const;    ///< J
  double potential_energy(const World& w) const;  ///< in gravity, from the initial centres, J
  void visit_state(StateArchive& ar, World& w, EnergyLedger& ledger);

  // Domains (issue 38): the bodies and meshes are few and held whole on every rank; a body's
  // wrench is the sum of the ranks' contact parts. The contact system, not this one, needs the
  // particles near the meshes.
  static constexpr Sharing sharing = Sharing::Replicated;
  double ghost_reach(const World&) const { return 0.0; }

 private:
  bool advance(World& w, double t, double h, double beta, double gamma);  // from body_n_; false if too far
  double load_power(const World& w) const;                                // W

  double step_limit_ = HUGE_VAL;   // m
  std::vector<int> mesh_body_;     // per mesh: the rigid body that moves it, or -1
  std::vector<RigidBody> body_n_;  // the bodies at the start of the step
  double body_time_ = 0;           // the time of the bodies' placement, s (their loads' anchors move)
  std::vector<Vec3> body_x0_;      // the bodies' initial centres (potential energy), m
  double power_old_ = 0;           // power of the bodies' loads at the start of the step, W
};

}  // namespace swarf
