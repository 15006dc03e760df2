// observer_set.cpp: the run's observers in turn (see observer_set.h).
#include "app/observers/observer_set.h"

#include <fmt/format.h>

#include <stdexcept>

#include "app/observers/prefixed_archive.h"
#include "swarf/simulation.h"

namespace swarf {

ObserverSet::ObserverSet(Simulation& sim, std::vector<std::unique_ptr<Observer>> observers)
    : sim_(sim), observers_(std::move(observers)) {
  // Names are checkpoint groups beside the loop's own (/run/loop/): two alike would read each
  // other's state back.
  for (std::size_t a = 0; a < observers_.size(); ++a) {
    if (observers_[a]->name() == "loop") throw std::logic_error("an observer named 'loop' (the run loop's group)");
    for (std::size_t b = 0; b < a; ++b)
      if (observers_[a]->name() == observers_[b]->name())
        throw std::logic_error(fmt::format("two observers named '{}'", observers_[a]->name()));
  }
  for (auto& o : observers_)
    if (StepListener* l = o->step_listener()) sim_.add_listener(l);
}

ObserverSet::~ObserverSet() {
  for (auto& o : observers_)
    if (StepListener* l = o->step_listener()) sim_.remove_listener(l);
}

std::vector<StepListener*> ObserverSet::step_listeners() const {
  std::vector<StepListener*> out;
  for (const auto& o : observers_)
    if (StepListener* l = o->step_listener()) out.push_back(l);
  return out;
}

std::vector<Column> ObserverSet::column_specs() const {
  std::vector<Column> cols{{"time", "s", "simulated time"}};
  for (const auto& o : observers_) o->columns(cols);
  return cols;
}

std::vector<std::string> ObserverSet::columns() const {
  std::vector<std::string> names;
  for (const auto& c : column_specs()) names.push_back(c.name);
  return names;
}

void ObserverSet::begin() {
  for (auto& o : observers_) o->begin(sim_);
}

std::vector<double> ObserverSet::row() {
  std::vector<double> values{sim_.time()};
  for (auto& o : observers_) o->row(sim_, values);
  return values;
}

void ObserverSet::visit_state(StateArchive& ar) {
  for (auto& o : observers_) {
    PrefixedArchive part(ar, std::string(o->name()) + "/");
    o->visit_state(part);
  }
}

void ObserverSet::write_results(H5File& f) const {
  for (const auto& o : observers_) o->write_results(f);
}

void ObserverSet::finish(const RunEnd& end, nlohmann::json& summary) {
  for (auto& o : observers_) o->finish(end, summary);
}

bool ObserverSet::has(std::string_view name) const {
  for (const auto& o : observers_)
    if (o->name() == name) return true;
  return false;
}

}  // namespace swarf
