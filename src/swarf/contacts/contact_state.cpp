// contact_state.cpp: the contact system's part of the state visit (see state_archive.h and
// Simulation::visit_state): its lists with their friction histories and build references,
// checked on a load.
#include <fmt/format.h>

#include <algorithm>
#include <string>
#include <vector>

#include "swarf/contacts/contacts.h"
#include "swarf/core/bounds.h"
#include "swarf/core/errors.h"
#include "swarf/core/state_archive.h"

namespace swarf {

void ContactSystem::visit_state(StateArchive& ar, const Particles& p) {
  const bool load = ar.loading();
  if (!ar.keeps("contacts/pairs")) return;  // (a domain's step state: the contacts travel as records)
  // Lists as flat index arrays (i, j) and (i, triangle), their histories beside them.
  std::vector<std::int32_t> pairs(2 * pairs_.size()), tris(2 * tris_.size());
  std::vector<Vec3> th(tris_.size());
  for (std::size_t k = 0; k < pairs_.size(); ++k) {
    pairs[2 * k] = pairs_[k].i;
    pairs[2 * k + 1] = pairs_[k].j;
  }
  for (std::size_t k = 0; k < tris_.size(); ++k) {
    tris[2 * k] = tris_[k].i;
    tris[2 * k + 1] = tris_[k].tri;
    th[k] = tris_[k].history;
  }
  ar.array("contacts/pairs", pairs, StateArchive::kAnySize);
  const std::size_t np = pairs.size() / 2;
  ar.array("contacts/pair_history", phist_, load ? np : StateArchive::kAnySize);
  ar.array("contacts/triangle_contacts", tris, StateArchive::kAnySize);
  const std::size_t nt = tris.size() / 2;
  ar.array("contacts/triangle_history", th, load ? nt : StateArchive::kAnySize);
  ar.array("contacts/x_build", x_build_, load ? p.size() : StateArchive::kAnySize);
  ar.array("contacts/mesh_build", mesh_build_, load ? meshes_->size() : StateArchive::kAnySize);
  ar.scalar("contacts/builds", builds_);
  if (std::any_of(meshes_->begin(), meshes_->end(), [](const MeshBody& mb) { return mb.turns; }))
    ar.array("contacts/mesh_build_turn", mesh_build_turn_, load ? meshes_->size() : StateArchive::kAnySize);
  if (!load) return;
  // The build positions lie where positions may (the particles' check below): beyond, their
  // distance to the particles overflowed in the skin check (1e289 m, the checkpoint fuzzer).
  for (const auto* build : {&x_build_, &mesh_build_})
    for (std::size_t i = 0; i < build->size(); ++i)
      if (!((*build)[i].cwiseAbs().maxCoeff() <= kMaxMeshCoordinate))
        throw InputError(fmt::format("state field 'contacts/{}': entry {} lies beyond {:g} m",
                                     build == &x_build_ ? "x_build" : "mesh_build", i, kMaxMeshCoordinate));
  if (pairs.size() % 2 != 0 || tris.size() % 2 != 0)
    throw InputError("state field 'contacts/pairs' or 'contacts/triangle_contacts' is not a list of index pairs");
  pairs_.resize(np);
  for (std::size_t k = 0; k < np; ++k) {
    pairs_[k] = Pair{pairs[2 * k], pairs[2 * k + 1]};
    const Pair& q = pairs_[k];
    if (q.i < 0 || q.j <= q.i || std::size_t(q.j) >= p.size())
      throw InputError(fmt::format("state field 'contacts/pairs': contact pair ({}, {}) out of range", q.i, q.j));
  }
  tris_.assign(nt, TriPair{});
  for (std::size_t k = 0; k < nt; ++k) {
    tris_[k].i = tris[2 * k];
    tris_[k].tri = tris[2 * k + 1];
    tris_[k].history = th[k];
    if (tris_[k].i < 0 || std::size_t(tris_[k].i) >= p.size() || tris_[k].tri < 0 ||
        std::size_t(tris_[k].tri) >= tri_mesh_.size())
      throw InputError(fmt::format("state field 'contacts/triangle_contacts': triangle contact {} out of range", k));
  }
  finish_build(p);
}

}  // namespace swarf
