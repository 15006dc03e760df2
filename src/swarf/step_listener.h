// step_listener.h: the engine's hook around each step, for observers and co-simulation.
//
// As Jolt's PhysicsStepListener and LAMMPS's fixes at end_of_step: a listener registered with
// Simulation::add_listener is called before every step (with the time the step starts from)
// and after every accepted step (the state committed: plastic shifts and breakage written,
// time advanced). A listener may change what the step reads next (a mesh's motion, a group's
// motion, external data it feeds to an outside code) in before_step; it must not resize the
// World. Listeners are called in the order they were added. Without listeners the step does
// exactly what it did before (no extra work, the same bits).
#pragma once

namespace swarf {

class Simulation;

class StepListener {
 public:
  virtual ~StepListener() = default;
  /// Before the step from sim.time().
  virtual void before_step(Simulation& /*sim*/) {}
  /// After the step was accepted and committed; sim.time() is its end.
  virtual void after_step(Simulation& /*sim*/) {}
};

}  // namespace swarf
