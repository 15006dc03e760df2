// integrator.h: the integrator's module of setup: [integrator]'s settings, key table, rules (the
// step control's limits, the solver with the scheme), its build (the engine's StepSettings) and its
// line of the setup printout. Listed once in each central list: parse_case (case_config.cpp), the key
// rows (case_key_text.cpp), the case echo (app/case_echo.cpp), build_model (model.cpp) and the setup
// printout (app/setup_report.cpp). The scheme and the step sizes themselves are derived
// (compute_derived, derived.cpp: they need the lattice's stiffness and masses).
#pragma once

#include <string>
#include <vector>

#include "setup/key.h"
#include "swarf/integrate/step_settings.h"

namespace swarf {

struct CaseInput;
struct CaseSettings;
struct Derived;
struct Model;

/// [integrator]
struct IntegratorSettings {
  std::string scheme = "auto";          ///< "verlet", "newmark", or "auto": newmark if rods can break, else verlet
  double dt = 0.0;                      ///< s; 0 = dt_safety * stable step (newmark: the first step)
  double dt_safety = 0.5;               ///< fraction of the stable step used when dt = 0, 1
  bool allow_unstable_dt = false;       ///< run even if dt exceeds the stable step estimate
  double end_time = 0.0;                ///< simulated time, s (the [uniaxial] path sets it when 0)
  double max_step_displacement = 0.25;  ///< stop if a particle moves more than this many radii in one step, 1
  double max_steps = 1e8;  ///< a run estimated to need more steps is refused before its first (--allow-long), 1
  // Newmark (implicit) step, solved by fixed-point iteration on the new accelerations.
  double beta = 0.25;          ///< Newmark beta, 1
  double gamma = 0.5;          ///< Newmark gamma, 1
  double tolerance = 1e-6;     ///< converged when the force change or the position correction of a sweep is below this,
                               ///< relative (Simulation::gather), 1
  int max_iterations = 25;     ///< sweeps before the step is rejected
  double dt_min = 0.0;         ///< s; 0 = 1e-3 * stable step. Below it the run stops
  double dt_max = 0.0;         ///< s; 0 = 0.8 x the stable step (the fixed-point limit for beta = 1/4 is 1x)
  int iterations_grow = 4;     ///< a step that needed at most this many sweeps grows the next one
  int iterations_shrink = 10;  ///< a step that needed at least this many sweeps shrinks the next one
  double grow_factor = 1.2;    ///< 1
  double shrink_factor = 0.7;  ///< 1
  double reject_factor = 0.5;  ///< a rejected step is retried with dt times this, 1
  double relaxation = 1.0;     ///< w in (0, 1]: each sweep places with (1 - w) a_guess + w a_swept, 1
  std::string solver = "fixed_point";  ///< "fixed_point" (sweeps) or "newton" (Newton-Krylov, rods only)
  double krylov_tolerance = 1e-2;      ///< newton: CG stops at |r| <= this x |R|, 1
  int krylov_max_iterations = 500;     ///< newton: CG iterations per Newton iteration
};

const std::vector<Key<IntegratorSettings>>& integrator_keys();

/// Reads [integrator] (absent: the defaults) and checks its rules. (integrator.end_time's rule with
/// [uniaxial] is parse_case's, once every table is read.)
void read_integrator(const CaseInput& in, CaseSettings& cs);

/// The step's settings of a case: [integrator], the derived stable step, and [output]'s orientations
/// and fields (whether the step integrates the spheres' orientations and accumulates PEEQ).
StepSettings step_settings(const CaseSettings& cs, const Derived& d);

/// The setup printout's line on the scheme, the step and the end time.
std::string integrator_echo(const Model& m);

}  // namespace swarf
