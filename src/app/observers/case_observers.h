// case_observers.h: which observers a case gets, in the order of their series columns.
#pragma once

#include <memory>
#include <vector>

#include "app/observers/observer.h"

namespace swarf {

struct Model;

/// The uniaxial probe (with [uniaxial]), the step counters, the energy balance, the rod
/// counts, the group reactions, the mesh forces and the cut probe (with a tool mesh and a
/// workpiece); they hold 'model' by reference. 'energy_check': a lost energy balance stops
/// the run (EnergyBalance).
std::vector<std::unique_ptr<Observer>> observers_for(const Model& model, bool energy_check = true);

}  // namespace swarf
