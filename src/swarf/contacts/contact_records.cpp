// contact_records.cpp: the contacts as records that travel between domains and to a run's
// mirror, lists made anew around them, and a domain's exact shares (see contacts.h, issue 38).
//
// Why records need only the contacts that touch or carry a history: an evaluation is a pure
// function of the two particles' state and the committed history, a candidate that does not
// touch contributes exact zeros (its results are zero, and adding +-0 to a sum that started
// at +0 changes no bit), and a history is zeroed when its contact stops touching. Which
// candidates a list holds and when it was built therefore change no bit of any force.
#include <fmt/format.h>

#include <stdexcept>

#include "swarf/contacts/contacts.h"

namespace swarf {

ContactSystem::Records ContactSystem::records() const {
  Records out;
  for (std::size_t k = 0; k < pairs_.size(); ++k)
    if (ptouch_[k] || phist_[k] != Vec3::Zero())
      out.pairs.push_back(
          PairRecord{pairs_[k].i, pairs_[k].j, phist_[k], ptouch_[k], pres_[k], ptouch_[k] ? pe_[k] : 0.0});
  for (std::size_t k = 0; k < tris_.size(); ++k)
    if (ttouch_[k] || tris_[k].history != Vec3::Zero())
      out.triangles.push_back(TriangleRecord{tris_[k].i, tris_[k].tri, tris_[k].history, ttouch_[k], tres_[k],
                                             tpoint_[k], ttouch_[k] ? te_[k] : 0.0});
  return out;
}

void ContactSystem::replace(const Particles& p, const Rods& rods, const Records& r) {
  if (!enabled_) return;
  const std::size_t n = p.size();
  // The records as the current lists (their rows let the build carry the histories over) ...
  pairs_.clear();
  phist_.clear();
  for (const PairRecord& q : r.pairs) {
    if (q.i < 0 || q.j <= q.i || static_cast<std::size_t>(q.j) >= n)
      throw std::logic_error(fmt::format("contacts: a pair record ({}, {}) for {} particles", q.i, q.j, n));
    pairs_.push_back(Pair{q.i, q.j});
    phist_.push_back(q.history);
  }
  tris_.assign(r.triangles.size(), TriPair{});
  for (std::size_t k = 0; k < r.triangles.size(); ++k) {
    const TriangleRecord& q = r.triangles[k];
    if (q.i < 0 || static_cast<std::size_t>(q.i) >= n || q.tri < 0 ||
        static_cast<std::size_t>(q.tri) >= tri_mesh_.size())
      throw std::logic_error(fmt::format("contacts: a triangle record ({}, {}) out of range", q.i, q.tri));
    tris_[k].i = q.i;
    tris_[k].tri = q.tri;
    tris_[k].history = q.history;
  }
  finish_build(p);
  // ... then a full search, which keeps them (each is within reach) with their histories.
  build(p, rods);
  // The last evaluation's results of those that touched, where the new lists hold them.
  for (const PairRecord& q : r.pairs) {
    std::int32_t k = prow_[q.i];
    while (k < prow_[q.i + 1] && pairs_[k].j != q.j) ++k;
    if (k == prow_[q.i + 1])
      throw std::logic_error(fmt::format("contacts: the pair ({}, {}) is not in the new lists", q.i, q.j));
    if (!q.touching) continue;
    ptouch_[k] = 1;
    pres_[k] = q.result;
    pe_[k] = q.energy;
  }
  for (const TriangleRecord& q : r.triangles) {
    std::int32_t k = trow_[q.i];
    while (k < trow_[q.i + 1] && tris_[k].tri != q.tri) ++k;
    if (k == trow_[q.i + 1])
      throw std::logic_error(
          fmt::format("contacts: the contact of particle {} and triangle {} is not in the new lists", q.i, q.tri));
    if (!q.touching) continue;
    ttouch_[k] = 1;
    tres_[k] = q.result;
    tpoint_[k] = q.point;
    te_[k] = q.energy;
  }
  // (every particle's sum made from the results until the next evaluation partitions the rows)
  spanning_.assign(n, 1);
}

ExactSum ContactSystem::elastic_energy_exact(const std::uint8_t* counted) const {
  ExactSum e;
  for (std::size_t k = 0; k < pairs_.size(); ++k)
    if (ptouch_[k] && counted[pairs_[k].i]) e.add(pe_[k]);
  for (std::size_t k = 0; k < tris_.size(); ++k)
    if (ttouch_[k] && counted[tris_[k].i]) e.add(te_[k]);
  return e;
}

std::vector<ExactSum> ContactSystem::mesh_forces_exact(const std::uint8_t* counted) const {
  std::vector<ExactSum> out(3 * (meshes_ ? meshes_->size() : 0));
  for (std::size_t k = 0; k < tris_.size(); ++k)
    if (ttouch_[k] && counted[tris_[k].i]) {
      const std::size_t m = static_cast<std::size_t>(tri_mesh_[tris_[k].tri]);
      for (int c = 0; c < 3; ++c) out[3 * m + c].add(-tres_[k].force[c]);
    }
  return out;
}

}  // namespace swarf
