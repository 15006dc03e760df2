// step_settings.h: every number the step uses, in SI units, with its default.
//
// Owned by the engine (as Jolt's PhysicsSettings or Box2D's b2WorldDef): setup/ fills it from
// the case file's [integrator] table and the derived stable step; a program that embeds the
// engine fills it in code. The step never reads a case key or an output flag.
#pragma once

namespace swarf {

enum class Scheme {
  Verlet,   ///< explicit velocity Verlet (Newmark beta 0, gamma 1/2), fixed step
  Newmark,  ///< implicit Newmark, fixed-point sweeps, step size control, commit after convergence
};

/// How the Newmark step's equations are solved (ignored by Verlet).
enum class Solver {
  FixedPoint,  ///< sweeps {place, forces, gather}: converge only below the explicit stable step
  Newton,      ///< Newton-Krylov on the residual in the accelerations (integrate/newton.cpp); rods only
};

struct StepSettings {
  Scheme scheme = Scheme::Verlet;
  double dt = 0;  ///< s: Verlet's fixed step; Newmark's first step
  // Newmark (ignored by Verlet).
  double beta = 0.25;          ///< 1
  double gamma = 0.5;          ///< 1
  double dt_min = 0;           ///< s: a step that must shrink below this stops the run
  double dt_max = 0;           ///< s: largest step the control may take
  double tolerance = 1e-6;     ///< 1: relative force change between sweeps at convergence
  int max_iterations = 25;     ///< sweeps before a step is rejected
  int iterations_grow = 4;     ///< a step that took at most this many sweeps grows the next
  int iterations_shrink = 10;  ///< a step that took at least this many sweeps shrinks the next
  double grow_factor = 1.2;    ///< 1
  double shrink_factor = 0.7;  ///< 1
  double reject_factor = 0.5;  ///< 1: a rejected step is retried this much smaller
  double relaxation = 1.0;     ///< 1: w of the relaxed sweeps, (1 - w) a_guess + w a_swept
  Solver solver = Solver::FixedPoint;
  // Newton (Solver::Newton): 'tolerance' bounds the residual relative to the force level,
  // 'max_iterations' the Newton iterations; iterations_grow/shrink count Newton iterations.
  double krylov_tolerance = 1e-2;   ///< 1: CG stops when |r| <= this x |R| (2-norms over the free components)
  int krylov_max_iterations = 500;  ///< CG iterations per Newton iteration; a step that hits it does not grow
  // Both schemes.
  double max_step_displacement = 0.25;  ///< radii: a particle moving further in a step stops (Verlet) or rejects
                                        ///< (Newmark) it
  bool sphere_orientations = false;  ///< integrate the free spheres' orientations (nothing in the dynamics depends on them)
  int plastic_strain_window = 32;  ///< committed steps between the accumulated plastic strain's fits
                                   ///< (systems/plastic_strain_system.h); 0 = off
  // Scales of the convergence measure (Newmark): the force level of a rod strained by
  // 1e-8 is stiffness_scale * length_scale * 1e-8, the floor below which forces are noise.
  double length_scale = 0;     ///< m: nearest-neighbour distance
  double stiffness_scale = 0;  ///< N/m: axial stiffness of the stiffest rod

  bool implicit() const { return scheme == Scheme::Newmark; }
};

}  // namespace swarf
