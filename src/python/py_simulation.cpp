// py_simulation.cpp: see py_simulation.h.
#include "python/py_simulation.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "swarf/core/errors.h"

namespace swarf::python {

PySimulation::PySimulation(const std::string& path, const std::string& text, const std::vector<std::string>& overrides) {
  if (!path.empty() && !text.empty())
    throw InputError(fmt::format("Simulation: give a case file ('{}') or a case text, not both", path));
  const CaseSettings cs = !path.empty()   ? load_case(path, overrides)
                          : !text.empty() ? parse_case(text, "<case text>", overrides)
                                          : parse_case(kDefaultCaseToml, "<built-in default case>", overrides);
  stored_.toml = cs.text;
  stored_.source = cs.source;
  stored_.directory = cs.directory;
  stored_.overrides = cs.overrides;
  model_ = std::make_unique<Model>(build_model(cs));
  finish_setup();
}

std::unique_ptr<PySimulation> PySimulation::from_checkpoint(const std::string& path,
                                                            const std::vector<std::string>& overrides) {
  std::unique_ptr<PySimulation> p(new PySimulation());
  p->stored_ = read_checkpoint_case(path);
  p->stored_.overrides.insert(p->stored_.overrides.end(), overrides.begin(), overrides.end());
  const CaseSettings cs = parse_case(p->stored_.toml, p->stored_.source, p->stored_.overrides, p->stored_.directory);
  p->model_ = std::make_unique<Model>(build_model(cs));
  p->finish_setup();
  RunRecord rec;
  read_checkpoint(path, *p->sim_, rec, {});  // (the run's own state, the observers', is the program's)
  return p;
}

void PySimulation::finish_setup() { sim_ = std::make_unique<Simulation>(*model_, model_->step); }

void PySimulation::step(double max_dt) {
  py::gil_scoped_release free;
  sim_->step(max_dt);
}

void PySimulation::run(double until) {
  const double end = std::isfinite(until) ? until : model_->settings.integrator.end_time;  // s
  // The loop of 'swarf run' (app/run.cpp): steps of at most the time left, and a last step
  // that lands within round-off of the end is the last.
  const double t_end = end * (1.0 - 1e-12);
  while (sim_->time() < t_end) {
    step(end - sim_->time());
    if (PyErr_CheckSignals() != 0) throw py::error_already_set();
  }
}

int PySimulation::add_listener(py::object before, py::object after, py::handle self) {
  if (!before.is_none() && !PyCallable_Check(before.ptr()))
    throw py::type_error("add_listener: 'before' is not callable");
  if (!after.is_none() && !PyCallable_Check(after.ptr())) throw py::type_error("add_listener: 'after' is not callable");
  auto l = std::make_unique<PyListener>(std::move(before), std::move(after), self);
  sim_->add_listener(l.get());
  listeners_.emplace_back(next_handle_, std::move(l));
  return next_handle_++;
}

void PySimulation::remove_listener(int handle) {
  const auto it = std::find_if(listeners_.begin(), listeners_.end(), [&](const auto& e) { return e.first == handle; });
  if (it == listeners_.end()) throw py::key_error(fmt::format("remove_listener: no listener {}", handle));
  sim_->remove_listener(it->second.get());
  listeners_.erase(it);
}

void PySimulation::write_checkpoint(const std::string& path) const {
  RunRecord rec;
  rec.columns = 1;  // (no series: the Python program keeps its own)
  CheckpointCase c = stored_;
  c.time = sim_->time();
  c.steps = static_cast<double>(sim_->steps());
  swarf::write_checkpoint(path, *sim_, rec, c, {});
}

}  // namespace swarf::python
