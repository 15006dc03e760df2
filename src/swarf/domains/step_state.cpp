// step_state.cpp: a Simulation's step state without its particles and rods (see step_state.h).
#include "swarf/domains/step_state.h"

#include <string_view>

#include "swarf/simulation.h"

namespace swarf {

namespace {
// The per-particle and per-rod arrays, the member lists and the contact lists: carried by the
// domains' records.
bool carried_elsewhere(std::string_view n) {
  const auto starts = [&](std::string_view p) { return n.substr(0, p.size()) == p; };
  if (starts("particles/") && n != "particles/next_id") return true;
  if (starts("rods/")) return true;
  if (starts("contacts/")) return true;  // (the lists: by particle index, made anew from the contacts' records)
  if (starts("groups/") && n.size() > 8 && n.substr(n.size() - 8) == "/members") return true;
  return n == "contact_force";
}
}  // namespace

MemoryArchive step_state_archive() { return MemoryArchive(carried_elsewhere); }

MemoryArchive save_step_state(const Simulation& from) {
  MemoryArchive a = step_state_archive();
  const_cast<Simulation&>(from).visit_state(a);  // (a save: it only reads)
  return a;
}

void load_step_state(MemoryArchive& a, Simulation& to) {
  a.set_loading(true);
  to.visit_state(a);
}

}  // namespace swarf
