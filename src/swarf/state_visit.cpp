// state_visit.cpp: every field of the step's state, named once (see state_archive.h): the
// World's variable part, then each system's own visit (systems/systems.h), the step's counters
// and the contacts' lists (contacts/contact_state.cpp), in this one order for a checkpoint, its
// load and the state hash.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "swarf/core/bounds.h"
#include "swarf/core/errors.h"
#include "swarf/core/nan_safe.h"
#include "swarf/neighbors/neighbor_pairs.h"
#include "swarf/simulation.h"

namespace swarf {

void Simulation::visit_state(StateArchive& ar) {
  const bool load = ar.loading();
  auto& p = m_.particles;
  auto& r = m_.rods;
  const std::size_t n = p.size(), m = r.size(), ng = m_.groups.size(), nm = m_.meshes.size();
  // (after a load of particles and rods, n and m below are the loaded sizes)
  // The particles and rods whole, static fields too: the door (simulation.h) may have
  // removed, appended or reordered them since the World was built, so a load takes the
  // World's variable part from the archive and checks it (sizes, indices) below.
  const std::size_t any = StateArchive::kAnySize;
  // A checkpoint of a run that held no accumulated plastic strain (ParticleLayout), which this run
  // holds because a restart may add an output field that needs it: it would start at 0 mid-run,
  // so such a restart is refused. (No other optional group can differ on a restart: the keys that
  // decide them may not change.)
  if (load && p.layout.plastic_strain && !ar.has("particles/peeq"))
    throw InputError(
        "the checkpoint holds no accumulated plastic strain (the run that wrote it had no output field that needs "
        "it): output.fields may not add 'peeq', 'peeq_rate' or 'plastic_work' on this restart");
  if (load && p.layout.plastic_strain && !ar.has("particles/plastic_work"))
    throw InputError(
        "the checkpoint holds the accumulated plastic strain but not the particles' plastic work (written by a swarf "
        "before 2026-12-08): restart it with the swarf that wrote it, or run the case again");
  p.for_each_field([&](const char* name, auto& v) { ar.array(std::string("particles/") + name, v, load ? any : n); });
  ar.scalar("particles/next_id", p.next_id);
  // A load reads the flat array and checks it below; it starts as the World's ends, which an
  // archive that keeps no rods (a domain's step state) leaves as they are. A save or a hash reads
  // the ends in place (the copy was the end of a run's peak: StateArchive::int32_pairs).
  std::vector<std::int32_t> ends;
  if (load) {
    ends.resize(2 * m);
    for (std::size_t k = 0; k < m; ++k) {
      ends[2 * k] = r.ends[k][0];
      ends[2 * k + 1] = r.ends[k][1];
    }
    ar.array("rods/ends", ends, any);
  } else {
    ar.int32_pairs("rods/ends", r.ends);
  }
  r.for_each_field([&](const char* name, auto& v) { ar.array(std::string("rods/") + name, v, load ? any : m); });
  for (std::size_t g = 0; g < ng; ++g) ar.array("groups/" + std::to_string(g) + "/members", m_.groups[g].members, any);
  if (load) check_loaded_world(ends);
  sys_.for_each([&](auto& s) { s.visit_state(ar, m_, ledger_); });
  const std::size_t n_now = p.size();
  ar.array("mesh_force", ms_.mesh_force, StateArchive::kAnySize);
  ar.array("contact_force", ms_.contact_force, sys_.contacts.enabled() ? n_now : 0);
  ar.scalar("time", time_);
  ar.scalar("dt", dt_);
  ar.scalar("last_dt", last_dt_);
  ar.scalar("rotations", ms_.rotations);
  ar.scalar("rebuild_lists", ms_.rebuild_lists);
  ar.scalar("contact_power_old", ms_.contact_power_old);
  ar.scalar("ledger/external_work", ledger_.external_work);
  ar.scalar("ledger/plastic_work", ledger_.plastic_work);
  ar.scalar("ledger/viscous_work", ledger_.viscous_work);
  ar.scalar("ledger/fracture_energy", ledger_.fracture_energy);
  ar.scalar("ledger/contact_work", ledger_.contact_work);
  ar.scalar("stats/accepted", stats_.accepted);
  ar.scalar("stats/rejected", stats_.rejected);
  ar.scalar("stats/iterations", stats_.iterations);
  ar.scalar("stats/force_evaluations", stats_.force_evaluations);
  ar.scalar("stats/max_iterations", stats_.max_iterations);
  ar.scalar("stats/last_iterations", stats_.last_iterations);
  if (sys_.contacts.enabled()) sys_.contacts.visit_state(ar, p);
  if (load) {
    // (finite first: an ordered comparison with a NaN raises FE_INVALID, a trap in the test build)
    if (!(std::isfinite(time_) && time_ >= 0.0) || !(std::isfinite(dt_) && dt_ > 0.0) || !std::isfinite(last_dt_))
      throw InputError(
          fmt::format("state fields 'time' = {} s, 'dt' = {} s, 'last_dt' = {} s: not finite times "
                      "(time >= 0, dt > 0)",
                      time_, dt_, last_dt_));
    // The step the run goes on with: within the step control's range (Newmark), or the
    // constant step (Verlet). A checkpoint's dt of 1e289 s overflowed the first placement
    // (the checkpoint fuzzer).
    if (implicit_ ? !(dt_ >= set_.dt_min && dt_ <= set_.dt_max) : dt_ != set_.dt)
      throw InputError(
          implicit_ ? fmt::format("state field 'dt' = {} s lies outside the case's [dt_min, dt_max] = [{}, {}] s", dt_,
                                  set_.dt_min, set_.dt_max)
                    : fmt::format("state field 'dt' = {} s is not the case's constant step {} s", dt_, set_.dt));
    if (ms_.mesh_force.size() != nm && !ms_.mesh_force.empty())
      throw InputError(fmt::format("state field 'mesh_force' has {} entries, expected {}", ms_.mesh_force.size(), nm));
    resize_scratch();
  }
}

void Simulation::check_loaded_world(const std::vector<std::int32_t>& ends) {
  auto& p = m_.particles;
  auto& r = m_.rods;
  const std::size_t n = p.size();
  bool same = true;
  p.for_each_field([&](const char*, auto& v) { same = same && v.size() == n; });
  if (!same) throw InputError("state fields 'particles/*' differ in length");
  if (ends.size() % 2 != 0) throw InputError("state field 'rods/ends' is not a list of index pairs");
  const std::size_t m = ends.size() / 2;
  r.ends.resize(m);
  for (std::size_t k = 0; k < m; ++k) {
    r.ends[k] = {ends[2 * k], ends[2 * k + 1]};
    if (r.ends[k][0] < 0 || r.ends[k][1] <= r.ends[k][0] || std::size_t(r.ends[k][1]) >= n)
      throw InputError(fmt::format("state field 'rods/ends': rod {} joins particles ({}, {}) of {}", k, r.ends[k][0],
                                   r.ends[k][1], n));
  }
  same = true;
  r.for_each_field([&](const char*, auto& v) { same = same && v.size() == m; });
  if (!same) throw InputError("state fields 'rods/*' differ in length from 'rods/ends'");
  for (std::size_t g = 0; g < m_.groups.size(); ++g)
    for (auto i : m_.groups[g].members)
      if (i < 0 || std::size_t(i) >= n)
        throw InputError(fmt::format("state field 'groups/{}/members': particle {} of {}", g, i, n));
  // Far-flung or coincident particles: the contact grid's counts and the contact normal
  // (0/0) cannot be formed (the checkpoint and lattice-file fuzzers).
  for (std::size_t i = 0; i < n; ++i)
    if (!(p.position[i].cwiseAbs().maxCoeff() <= kMaxMeshCoordinate))
      throw InputError(
          fmt::format("state field 'particles/position': particle {} lies beyond {:g} m", i, kMaxMeshCoordinate));
  const double near = n > 0 ? 1e-6 * *std::min_element(p.radius.begin(), p.radius.end()) : 0.0;
  if (const auto c = find_coincident(p.position, near); c[0] >= 0)
    throw InputError(fmt::format(
        "state field 'particles/position': particles {} and {} lie within {:g} m of each other (a millionth of "
        "the smallest radius)",
        c[0], c[1], near));
  r.build_rows(n);
}

std::uint64_t Simulation::state_hash() const {
  HashArchive h;
  // The visit reads the state when the archive is not loading; it is one function for all
  // three uses, so it takes the state as non-const.
  const_cast<Simulation*>(this)->visit_state(h);
  return h.value();
}

}  // namespace swarf
