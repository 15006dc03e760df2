// py_simulation.h: what the Python module's Simulation holds: a case built into a Model (the
// World the step works on), the Simulation stepping it, and the Python step listeners.
//
// The Model lives on the heap and never moves: the Simulation holds it by reference and the
// NumPy views of the module point into its arrays.
#pragma once
#include <pybind11/pybind11.h>

#include <memory>
#include <string>
#include <vector>

#include "io/checkpoint.h"
#include "setup/model.h"
#include "swarf/simulation.h"

namespace swarf::python {

namespace py = pybind11;

/// A Python callable (or two) called around every accepted step with the Python Simulation.
class PyListener final : public StepListener {
 public:
  PyListener(py::object before, py::object after, py::handle owner)
      : before_(std::move(before)), after_(std::move(after)), owner_(owner) {}
  void before_step(Simulation&) override { call(before_); }
  void after_step(Simulation&) override { call(after_); }

 private:
  // The step runs without the GIL (it may take a while, on several threads); the call takes it.
  void call(const py::object& f) {
    if (f.is_none()) return;
    py::gil_scoped_acquire gil;
    f(owner_);
  }
  py::object before_, after_;
  py::handle owner_;  // (borrowed: the Python Simulation owns this listener)
};

class PySimulation {
 public:
  /// From a case file (path), from TOML text, or the built-in default case (both empty),
  /// with --set style overrides. Throws InputError.
  PySimulation(const std::string& path, const std::string& text, const std::vector<std::string>& overrides);
  /// From a checkpoint written by 'swarf run' or write_checkpoint: its own case, its state.
  static std::unique_ptr<PySimulation> from_checkpoint(const std::string& path,
                                                       const std::vector<std::string>& overrides);

  Model& model() { return *model_; }
  Simulation& sim() { return *sim_; }
  const CheckpointCase& stored_case() const { return stored_; }

  /// One step of at most max_dt, without the GIL.
  void step(double max_dt);
  /// Steps until 'until' (the case's integrator.end_time when not finite) as 'swarf run' does,
  /// so that the same case gives the same bits; Python signals (Ctrl-C) are looked at after
  /// every step.
  void run(double until);
  /// Registers callables before(sim) and after(sim) (either may be None); returns a handle
  /// for remove_listener.
  int add_listener(py::object before, py::object after, py::handle self);
  void remove_listener(int handle);
  /// Writes a checkpoint of the state (the case and the step's state; no run record).
  void write_checkpoint(const std::string& path) const;

 private:
  PySimulation() = default;
  void finish_setup();
  std::unique_ptr<Model> model_;
  std::unique_ptr<Simulation> sim_;
  CheckpointCase stored_;
  std::vector<std::pair<int, std::unique_ptr<PyListener>>> listeners_;
  int next_handle_ = 1;
};

}  // namespace swarf::python
