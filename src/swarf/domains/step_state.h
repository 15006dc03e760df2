// step_state.h: a Simulation's step state without its particles and rods, copied from one
// Simulation to another (issue 38: a run over domains that starts where a serial Simulation is,
// from a checkpoint or a gathered World, on any rank count).
//
// Simulation::visit_state names every field once; the archive made here keeps, on save, every
// field but the per-particle and per-rod arrays (and the groups' member lists), which the
// domains carry in their own records, and on load gives them back to a Simulation of another
// World: the time and counters, the ledger, the systems' own state (the plastic-strain window,
// the groups' displacements and reactions, ...). Loading leaves the arrays it did not keep as
// they are.
#pragma once

#include "swarf/core/memory_archive.h"

namespace swarf {

class Simulation;

/// An archive that keeps a step state (MemoryArchive with the particles' and rods' arrays skipped).
MemoryArchive step_state_archive();
/// 'from''s step state, kept.
MemoryArchive save_step_state(const Simulation& from);
/// 'to' takes the kept step state.
void load_step_state(MemoryArchive& a, Simulation& to);
/// 'to' takes 'from''s step state (both Simulations of one case; their Worlds may differ).
inline void copy_step_state(const Simulation& from, Simulation& to) {
  MemoryArchive a = save_step_state(from);
  load_step_state(a, to);
}

}  // namespace swarf
