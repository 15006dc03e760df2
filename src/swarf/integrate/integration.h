// integration.h: what the integrators work on, and the stages they are made of.
//
// Both schemes are Newmark's family, x+ = x + dt v + dt^2 ((1/2 - beta) a + beta a+),
// v+ = v + dt ((1 - gamma) a + gamma a+), and share the stages (stages.cpp, gather.cpp):
//   prescribe     group and mesh motions at t + dt (displacements and step velocities); rigid
//                 bodies are placed with the particles (systems/body_system.cpp)
//   rod_forces    every intact rod evaluated from its COMMITTED state: trial shift, trial
//                 break flag, force coefficient
//   contact_forces  Verlet lists updated if needed; every contact evaluated from its
//                 committed friction history (contacts/contacts.h)
//   gather        per particle, its rods' forces summed in fixed (rod) order; a = f/m
//   commit        the heat of the step, plastic shifts and breakage of the final evaluation
//                 written back, the broken pairs into the contacts, bond formation
//   account       work of the grips, dissipation, the contacts' work
// The integrators are free functions over an Integration (the World, the systems, the
// integrators' own state, the settings and the step's counters), one file each:
//   verlet.cpp    explicit velocity Verlet (beta 0, gamma 1/2, one evaluation per step)
//   newmark.cpp   implicit Newmark solved by fixed-point sweeps (paper section 3.4)
//   newton.cpp    the same step solved by Newton-Krylov (newton_newmark.h)
// The step control around the implicit tries (save, restore, the step size) is Simulation's.
#pragma once

#include <cstdint>
#include <vector>

#include "swarf/core/stage_clock.h"
#include "swarf/integrate/newton_newmark.h"
#include "swarf/integrate/step_settings.h"
#include "swarf/laws/rotation.h"
#include "swarf/state/world.h"
#include "swarf/systems/energy_ledger.h"
#include "swarf/systems/step_context.h"
#include "swarf/systems/systems.h"

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

/// The integrators' own state: the start of the step (the Newmark predictor and the rejection),
/// the particles free to rotate, the contacts' force and power between stages, and the step's
/// displacement measures. Per-particle arrays follow the door through Simulation::resize_scratch.
struct MotionState {
  bool rotations = false;                    ///< rotations integrated (a torque source, or by hand)
  std::vector<std::uint8_t> free_to_rotate;  ///< 1 for particles without intact rods
  std::vector<std::int32_t> free_list;       ///< those particles, in order
  std::vector<Vec3> x_n, v_n, a_n, f_n;      ///< start-of-step state (Newmark)
  std::vector<RotState> rot_n;               ///< start-of-step rotations (Newmark)
  std::vector<Vec3> a_guess;                 ///< accelerations a sweep placed with (integrator.relaxation < 1)
  std::vector<Vec3> contact_force;           ///< contact part of each particle's force, N
  /// Keep contact_force in the explicit step too (whose kick sums the power without it): a
  /// domain counts the contacts' power per owned particle (Simulation::contact_power_exact).
  bool keep_contact_force = false;
  std::vector<Vec3> mesh_force;     ///< force on each mesh after the last accepted step, N
  double contact_power_old = 0;     ///< power of the contact forces at the start of the step, W
  double kick_power = 0;            ///< power of the contact forces on the particles after the kick, W
  std::vector<double> block_power;  ///< its parts per block of particles, W
  /// The gather's threads' blocks: thread t takes blocks [gather_split[t], gather_split[t+1]),
  /// balanced by their measured times (gather.cpp; the results do not depend on it).
  std::vector<std::size_t> gather_split;
  std::vector<double> gather_seconds;  ///< each thread's time in the gathers since the ranges moved, s
  int gather_timed = 0;                ///< those gathers
  double sweep_force_level2 = 0;       ///< the particles' force level of the last sweep squared, N^2
  double sweep_dt = 0;                 ///< step size of the current sweep, s
  double step_disp2 = 0;               ///< largest squared displacement of the step so far, m^2
  double moved2 = -1.0;          ///< largest squared displacement since the contact lists' build, m^2 (< 0: unknown)
  bool rebuild_lists = false;    ///< rebuild the contact lists at the next evaluation (after an append)
  bool mesh_rejected = false;    ///< the last implicit try was rejected because a mesh moved too far
  RodSystem::WorkList rod_work;  ///< commit's scratch: the rods that flowed (the heat's and PEEQ's sources)
  NewtonWork newton;             ///< the Newton solve's work arrays
  NewtonStats newton_stats;      ///< and its counters
};

/// What an integrator works on in one step: built by the Simulation for every step.
struct Integration {
  World& world;
  Systems& sys;
  MotionState& ms;
  const StepSettings& set;
  StageClock& clock;
  StepStats& stats;
  EnergyLedger& ledger;
  double t = 0;           ///< time at the start of the step, s
  bool implicit = false;  ///< the Newmark step (its sweeps) rather than Verlet's

  /// The systems' view of the step (systems/step_context.h).
  StepContext context(double h) const { return StepContext{world, t, h, set.beta, set.gamma, implicit, ledger}; }
};

namespace integrate {

// The integrators (one file each). A try returns false when the step must be retried shorter
// (not converged, diverging, a particle or mesh moving too far); the caller restores the state.
/// One explicit step of h: throws SimulationError when a particle or mesh moves too far.
void verlet_step(Integration& it, double h);
/// The fixed-point Newmark sweeps of one step of h; true if converged (state advanced, not committed).
bool newmark_try(Integration& it, double h);
/// The same step solved by Newton-Krylov (newton.cpp); true if converged.
bool newton_try(Integration& it, double h);

// The stages (stages.cpp, gather.cpp).
bool prescribe(Integration& it, double h);   ///< false if a mesh would move too far in the step
bool kick_drift(Integration& it, double h);  ///< explicit predictor; false if a particle moved too far
bool place(Integration& it,
           double h);  ///< Newmark positions, velocities, rotations from the latest a; false if too far
void rotate_one(Integration& it, std::size_t i, double h, double beta, double gamma);
/// The rods' trial evaluation; 'lagged_rate': a rate-scaled law's rate factor from the step's
/// start (x_n, v_n), as the Newton solve evaluates (newton.cpp).
void rod_forces(Integration& it, bool lagged_rate = false);
void contact_forces(Integration& it, double h, bool final = false);
double gather(Integration& it);               ///< the sweep's relative force change (free components; implicit only)
void gather_kick(Integration& it, double h);  ///< explicit: gather, then the corrector v += h/2 a and the rotation
void commit(Integration& it, double h);       ///< the heat (before the rods' commit reads its trial), then the commits
void account(Integration& it, double h);      ///< the energies of the accepted step (not the time)
/// Power of the contact forces on the particles and the meshes, W; the particles' part from the
/// fused gather and kick if 'from_kick'.
double contact_power(const Integration& it, bool from_kick = false);
void save_state(Integration& it);     ///< the start of an implicit step
void restore_state(Integration& it);  ///< back to it, bit for bit, after a rejected try
/// The particles free to rotate: all of them, or only those of 'pairs' (whose rods changed).
void update_free_to_rotate(const World& w, MotionState& ms);
void update_free_to_rotate(const World& w, MotionState& ms, const std::vector<std::array<std::int32_t, 2>>& pairs);

}  // namespace integrate
}  // namespace swarf
