// integrator.cpp: the integrator's module of setup (see integrator.h).
#include "setup/modules/integrator.h"

#include <fmt/format.h>

#include <algorithm>

#include "setup/case_tables.h"
#include "setup/model.h"

namespace swarf {

const std::vector<Key<IntegratorSettings>>& integrator_keys() {
  using S = IntegratorSettings;
  static const std::vector<Key<S>> keys{
      {.name = "scheme",
       .field = &S::scheme,
       .choices = {"auto", "verlet", "newmark"},
       .doc = "`\"verlet\"`: velocity Verlet, explicit, constant step. `\"newmark\"`: implicit Newmark with step "
              "size control (see [Newmark step](#newmark-step)). `\"auto\"`: `\"newmark\"` with `solver = "
              "\"newton\"`, otherwise `\"verlet\"`, also where rods can break (measured on the cut at 0.3-10 m/s, "
              "the Newmark step costs 1.3-4.2 times Verlet's time for the same forces: "
              "validation/integrators/README.md). Until 2026-12-07 `\"auto\"` chose `\"newmark\"` wherever "
              "rods could break: name `\"newmark\"` to run such an older case as it ran."},
      {.name = "dt",
       .field = &S::dt,
       .unit = "s",
       .range = or_zero(in(1e-15, 1.0, "[]", "0 derives it; else 1 fs to 1 s")),
       .rule = "newmark: within [`dt_min`, `dt_max`]",
       .doc = "verlet: the time step. newmark: the first step. 0 means `dt_safety` x the stable step."},
      {.name = "dt_safety",
       .field = &S::dt_safety,
       .unit = "1",
       .range = in(0, 1, "(]"),
       .doc = "Fraction of the stable step used when `dt` = 0; an explicit `dt` > 0 takes precedence."},
      {.name = "allow_unstable_dt",
       .field = &S::allow_unstable_dt,
       .doc = "verlet only: run even when dt exceeds the stable step estimate."},
      {.name = "end_time",
       .field = &S::end_time,
       .unit = "s",
       .range = or_zero(kTime),
       .rule = "> 0 unless `[uniaxial]` is present",
       .doc = "Simulated time. With `[uniaxial]`, 0 means the duration of the strain path.",
       .restartable = true},
      {.name = "max_step_displacement",
       .field = &S::max_step_displacement,
       .unit = "1",
       .range = in(1e-6, 10.0, "[]", "1e-6 to 10 radii"),
       .doc = "Largest move of any particle (group members included) in one step, in its radii. verlet: measured "
              "on the free components; the run stops (exit code 3) if a particle moves further, or if the state "
              "becomes non-finite. newmark: measured on the whole displacement from the start of the step, "
              "prescribed components included; the step is rejected and retried shorter."},
      {.name = "max_steps",
       .field = &S::max_steps,
       .unit = "1",
       .range = in(1, 1e15, "[]"),
       .doc = "A run whose step count, estimated before the first step as `end_time` over the step (verlet: `dt`; "
              "newmark: `dt_max`, the fewest it can take), exceeds this is refused (exit code 2) with the keys that "
              "set the step, the count and the time it would take at about 100 ns per particle-step; `swarf run "
              "--allow-long` runs it anyway. 1e8 steps is some 300 times the default cut's (a judgement: a run that "
              "long is a mistake far more often than an intent).",
       .restartable = true},
      {.name = "beta",
       .field = &S::beta,
       .unit = "1",
       .range = in(0, 0.5, "(]", "beta = 0 is the explicit scheme: use scheme = \"verlet\""),
       .doc = "Newmark beta. 0 would be the explicit scheme: use `scheme = \"verlet\"`.",
       .section = "newmark"},
      {.name = "gamma",
       .field = &S::gamma,
       .unit = "1",
       .range = in(0.5, 1, "[]"),
       .doc = "Newmark gamma.",
       .section = "newmark"},
      {.name = "tolerance",
       .field = &S::tolerance,
       .unit = "1",
       .range = in(1e-16, 0.5, "[]", "1e-16 is near the doubles' precision, 2.2e-16: below it no iteration gets there"),
       .doc = "The fixed-point iteration has converged when the sweep's relative change is at most this (see "
              "[convergence](#newmark-step)).",
       .section = "newmark"},
      {.name = "max_iterations",
       .field = &S::max_iterations,
       .unit = "1",
       .range = in(2, 10000, "[]"),
       .doc = "Sweeps allowed per step. A step that has not converged after this many is rejected.",
       .section = "newmark"},
      {.name = "dt_min",
       .field = &S::dt_min,
       .unit = "s",
       .range = or_zero(in(1e-15, 1.0, "[]", "0 derives it; else 1 fs to 1 s")),
       .rule = "not above `dt_max` when both are > 0",
       .doc = "Smallest step. 0 means 1e-3 x the stable step. A rejected step whose retry would be shorter stops "
              "the run (exit code 3).",
       .section = "newmark"},
      {.name = "dt_max",
       .field = &S::dt_max,
       .unit = "s",
       .range = or_zero(in(1e-15, 1.0, "[]", "0 derives it; else 1 fs to 1 s")),
       .doc = "Largest step. 0 means 0.4/sqrt(`beta`) x the stable step: 0.8 x at `beta` = 1/4 (see "
              "[Fixed-point limit](#newmark-step)).",
       .section = "newmark"},
      {.name = "iterations_grow",
       .field = &S::iterations_grow,
       .unit = "1",
       .range = in(1, 10000, "[]"),
       .rule = "below `iterations_shrink`",
       .doc = "A step that converged in at most this many sweeps lengthens the next step.",
       .section = "newmark"},
      {.name = "iterations_shrink",
       .field = &S::iterations_shrink,
       .unit = "1",
       .range = in(2, 10000, "[]"),
       .rule = "not above `max_iterations`",
       .doc = "A step that needed at least this many sweeps shortens the next step.",
       .section = "newmark"},
      {.name = "grow_factor",
       .field = &S::grow_factor,
       .unit = "1",
       .range = in(1, 10, "(]"),
       .doc = "Factor on the step when it grows.",
       .section = "newmark"},
      {.name = "shrink_factor",
       .field = &S::shrink_factor,
       .unit = "1",
       .range = in(0.01, 1.0, "[)"),
       .doc = "Factor on the step when it shrinks.",
       .section = "newmark"},
      {.name = "reject_factor",
       .field = &S::reject_factor,
       .unit = "1",
       .range = in(0.01, 0.99, "[]", "a judgement: 0.99 takes 69 tries to halve a step"),
       .doc = "A rejected step is retried with its size times this factor.",
       .section = "newmark"},
      {.name = "relaxation",
       .field = &S::relaxation,
       .unit = "1",
       .range = in(1e-3, 1.0, "[]"),
       .doc = "Relaxation w of the fixed-point sweeps: after a sweep that has not converged, the next one places "
              "with (1 - w) a_guess + w a_swept instead of the swept accelerations alone. 0.75 cuts the default "
              "cut's force evaluations by a third; see **Relaxation** below.",
       .section = "newmark"},
      {.name = "solver",
       .field = &S::solver,
       .choices = {"fixed_point", "newton"},
       .rule = "newton: not with `scheme = \"verlet\"`",
       .doc = "How the Newmark step is solved. `\"fixed_point\"`: sweeps of force evaluations, convergent only "
              "below the explicit stable step. `\"newton\"`: Newton-Krylov with the rods' and contacts' tangent "
              "stiffness "
              "(conjugate gradients, block-Jacobi preconditioner, matrix-free), which converges beyond it: "
              "`tolerance` then bounds the residual relative to the force level, `max_iterations`, "
              "`iterations_grow` and `iterations_shrink` count Newton iterations, and `dt_max` defaults to 10 x "
              "the stable step (at most 20 x). With `scheme = \"auto\"`, `\"newton\"` selects Newmark.",
       .section = "newmark"},
      {.name = "krylov_tolerance",
       .field = &S::krylov_tolerance,
       .unit = "1",
       .range = in(1e-16, 0.5, "[]", "1e-16 is near the doubles' precision, 2.2e-16: below it no iteration gets there"),
       .doc = "newton: each linear solve stops when its residual's 2-norm is at most this fraction of the Newton "
              "residual's (an inexact Newton step; the Newton loop measures the real residual again).",
       .section = "newmark"},
      {.name = "krylov_max_iterations",
       .field = &S::krylov_max_iterations,
       .unit = "1",
       .range = in(1, 100000, "[]"),
       .doc = "newton: conjugate-gradient iterations allowed per Newton iteration. A solve that stops here is "
              "used as it is, and the next step is shortened (`shrink_factor`).",
       .section = "newmark"},
  };
  return keys;
}

void read_integrator(const CaseInput& in, CaseSettings& cs) {
  TableReader r = in.reader(in.table("integrator"), "integrator");
  auto& g = cs.integrator;
  r.read(integrator_keys(), g);
  r.finish();  // (an unknown key, often a misspelt one, is named before the rules between keys)
  if (g.dt_min > 0 && g.dt_max > 0 && g.dt_min > g.dt_max)
    r.fail("dt_min", r.get("dt_min"), fmt::format("must not exceed dt_max = {} s", g.dt_max));
  if (g.iterations_grow >= g.iterations_shrink)
    r.fail("iterations_grow", r.get("iterations_grow"), "must be below iterations_shrink");
  if (g.iterations_shrink > g.max_iterations)
    r.fail("iterations_shrink", r.get("iterations_shrink"), "must not exceed max_iterations");
  if (g.solver == "newton" && g.scheme == "verlet")
    r.fail("solver", r.get("solver"), "solves the implicit Newmark step: not with scheme = \"verlet\"");
}

StepSettings step_settings(const CaseSettings& cs, const Derived& d) {
  const IntegratorSettings& g = cs.integrator;
  StepSettings s;
  s.scheme = d.implicit ? Scheme::Newmark : Scheme::Verlet;
  s.dt = d.dt;
  s.beta = g.beta;
  s.gamma = g.gamma;
  s.dt_min = d.dt_min;
  s.dt_max = d.dt_max;
  s.tolerance = g.tolerance;
  s.max_iterations = g.max_iterations;
  s.iterations_grow = g.iterations_grow;
  s.iterations_shrink = g.iterations_shrink;
  s.grow_factor = g.grow_factor;
  s.shrink_factor = g.shrink_factor;
  s.reject_factor = g.reject_factor;
  s.relaxation = g.relaxation;
  s.solver = g.solver == "newton" ? Solver::Newton : Solver::FixedPoint;
  s.krylov_tolerance = g.krylov_tolerance;
  s.krylov_max_iterations = g.krylov_max_iterations;
  s.max_step_displacement = g.max_step_displacement;
  build_output(cs, s);
  s.length_scale = d.nn_distance;
  s.stiffness_scale = d.rod_stiffness;
  return s;
}

std::string integrator_echo(const Model& m) {
  const Derived& d = m.derived;
  return fmt::format("  scheme {}; stable step {:.4g} s; dt = {:.4g} s ({:.3g} of it){}; end time {:.4g} s\n",
                     d.implicit ? "newmark" : "verlet", d.dt_stable, d.dt, d.dt / d.dt_stable,
                     d.implicit ? fmt::format(" first, controlled in [{:.3g}, {:.3g}] s", d.dt_min, d.dt_max) : "",
                     m.settings.integrator.end_time);
}

}  // namespace swarf
