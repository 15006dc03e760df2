// domain_formation.cpp: bond formation over the domains (laws/bond_formation.h; issue 38).
//
// Why it is decided for the whole run: the serial rule runs through the pressed pairs in list
// order, and a pair's outcome depends on the ones before it (a particle's count of intact rods,
// its most stretched rod, both change as earlier pairs exchange rods), so no domain can decide
// its pairs alone. Every domain reports the pressed pairs whose first particle it owns and, for
// each particle of those pairs that it owns, its intact rods (key, other end, strain, the energy
// a break would free); all domains then replay the serial loop on the same data in the serial
// order (the pairs sorted by their ids) and apply its outcome to their own rods: the exchanged
// rods break, a pair's broken rod forms again or a new rod is appended with the next key of the
// run, and the broken formed rods are removed, every key renumbered as Rods::remove_broken_formed
// compacts the serial list. The rods of every domain then are the serial run's, in its order.
#include <fmt/format.h>

#include <algorithm>
#include <map>
#include <set>
#include <stdexcept>

#include "swarf/domains/domain_run.h"
#include "swarf/laws/any_rod_law.h"
#include "swarf/laws/bond_formation.h"

namespace swarf {

namespace {

struct PairReport {           // a pressed pair, by its first particle's owner
  std::int64_t a = 0, b = 0;  // ids, a < b
  std::int64_t key = -1;      // the pair's broken rod's key, -1: none
  std::int64_t formed = 0;    // that rod was formed (not one of the lattice's)
  double length = 0.0;        // m, the centres' distance now
};
struct RodReport {         // an intact rod of a particle of the pressed pairs, by the particle's owner
  std::int64_t id = 0;     // the particle
  std::int64_t key = 0;    // the rod
  std::int64_t other = 0;  // its other end's id
  std::int64_t formed = 0;
  double strain = 0.0;  // 1, the rod's strain now (as the serial rule measures it)
  double energy = 0.0;  // J, the elastic energy its break frees
};

template <class T>
std::vector<T> gathered(Comm& comm, const std::vector<T>& mine) {
  std::vector<T> all;
  for (const Bytes& b : comm.all_gather(Comm::to_bytes(mine))) {
    const std::vector<T> part = Comm::from_bytes<T>(b);
    all.insert(all.end(), part.begin(), part.end());
  }
  return all;
}

}  // namespace

std::vector<std::array<std::int32_t, 2>> DomainRun::form_rods(RodSystem& rs, World& w, ContactSystem& contacts) {
  Particles& p = w.particles;
  Rods& r = w.rods;
  const BondFormation rule = r.formation;
  const auto lattice = [&](std::int64_t id) { return std::binary_search(lattice_ids_.begin(), lattice_ids_.end(), id); };
  const auto local_index = [&](std::int64_t id) -> std::int32_t {
    const auto it = std::lower_bound(p.id.begin(), p.id.end(), id);
    return it != p.id.end() && *it == id ? static_cast<std::int32_t>(it - p.id.begin()) : -1;
  };
  const auto local_rod = [&](std::int64_t key) -> std::int64_t {
    const auto it = std::lower_bound(rod_key_.begin(), rod_key_.end(), key);
    return it != rod_key_.end() && *it == key ? it - rod_key_.begin() : -1;
  };
  // 1. The pressed pairs whose first particle this domain owns.
  std::vector<PairReport> mine;
  for (const auto& e : contacts.pressed_pairs(p, rule.overlap, [&](std::int32_t i, std::int32_t j) {
         return owned_[i] && lattice(p.id[i]) && lattice(p.id[j]);
       })) {
    PairReport q;
    q.a = p.id[e[0]];
    q.b = p.id[e[1]];
    for (std::int32_t x = r.row_start[e[0]]; x < r.row_start[e[0] + 1]; ++x)
      if (r.entries[x].other == e[1]) {
        q.key = rod_key_[r.entries[x].rod];
        q.formed = r.formed[r.entries[x].rod];
      }
    Vec3 d = p.position[e[1]] - p.position[e[0]];
    w.periodic.wrap(d);
    q.length = d.norm();
    mine.push_back(q);
  }
  std::vector<PairReport> pairs = gathered(comm_, mine);
  if (pairs.empty()) return {};
  std::sort(pairs.begin(), pairs.end(), [](const PairReport& x, const PairReport& y) {
    return std::pair{x.a, x.b} < std::pair{y.a, y.b};  // (the serial list's order)
  });
  // 2. The intact rods of the pairs' particles, each particle's by its owner, in key order.
  std::vector<std::int64_t> involved;
  for (const PairReport& q : pairs) involved.push_back(q.a), involved.push_back(q.b);
  std::sort(involved.begin(), involved.end());
  involved.erase(std::unique(involved.begin(), involved.end()), involved.end());
  std::vector<RodReport> rods_mine;
  for (const std::int64_t id : involved) {
    const std::int32_t i = local_index(id);
    if (i < 0 || !owned_[i]) continue;
    for (std::int32_t x = r.row_start[i]; x < r.row_start[i + 1]; ++x) {
      const std::int32_t k = r.entries[x].rod;
      if (!r.intact[k]) continue;
      Vec3 d = p.position[r.entries[x].other] - p.position[i];
      w.periodic.wrap(d);
      rods_mine.push_back(RodReport{id, rod_key_[k], p.id[r.entries[x].other], r.formed[k],
                                    d.norm() * r.inv_rest_length[k] - 1.0,
                                    elastic_energy_density(r.law, r.stress[k]) * r.area * r.rest_length[k]});
    }
  }
  std::map<std::int64_t, std::vector<RodReport>> rods_of;
  for (const RodReport& q : gathered(comm_, rods_mine)) rods_of[q.id].push_back(q);
  for (auto& [id, list] : rods_of)
    std::sort(list.begin(), list.end(), [](const RodReport& x, const RodReport& y) { return x.key < y.key; });
  // 3. The serial rule (RodSystem::form), replayed on the same data by every domain.
  std::set<std::int64_t> exchanged_keys;
  std::vector<const RodReport*> exchanged;
  std::vector<const PairReport*> formed;
  std::map<std::int64_t, int> count;
  std::int64_t broken_change = 0;
  const auto rods = [&](std::int64_t id) -> const std::vector<RodReport>& {
    static const std::vector<RodReport> none;
    const auto it = rods_of.find(id);
    return it == rods_of.end() ? none : it->second;
  };
  const auto most_stretched = [&](std::int64_t id) -> const RodReport* {
    const RodReport* best = nullptr;
    double worst = 0.0;
    for (const RodReport& q : rods(id))
      if (!exchanged_keys.count(q.key) && q.strain > worst) {
        worst = q.strain;
        best = &q;
      }
    return best;
  };
  for (const PairReport& q : pairs) {
    const std::int64_t e[2] = {q.a, q.b};
    for (const std::int64_t id : e)
      if (!count.count(id)) {
        int c = 0;
        for (const RodReport& x : rods(id)) c += !exchanged_keys.count(x.key);
        count[id] = c;
      }
    const RodReport* give[2] = {nullptr, nullptr};
    bool ok = true;
    for (int s = 0; s < 2 && ok; ++s) {
      if (may_form(rule, count[e[s]])) continue;
      give[s] = rule.exchange ? most_stretched(e[s]) : nullptr;
      ok = give[s] && (!give[1 - s] || give[s]->key != give[1 - s]->key);
    }
    if (!ok) continue;
    for (int s = 0; s < 2; ++s) {
      if (!give[s]) {
        ++count[e[s]];
        continue;
      }
      exchanged_keys.insert(give[s]->key);
      exchanged.push_back(give[s]);
      broken_change += !give[s]->formed;
      if (const auto it = count.find(give[s]->other); it != count.end()) --it->second;
    }
    formed.push_back(&q);
  }
  if (formed.empty()) return {};
  // 4. Applied here. The exchanged rods break (their energy booked once, on rank 0).
  std::vector<std::array<std::int32_t, 2>> touched, gone_pairs, new_pairs;
  for (const RodReport* q : exchanged) {
    if (comm_.rank() == 0) base_[2].add(q->energy);
    if (const std::int64_t k = local_rod(q->key); k >= 0) {
      r.intact[k] = 0;
      r.stress[k] = r.force_coef[k] = 0.0;
      new_pairs.push_back(r.ends[k]);
    }
  }
  // The pairs' rods: a broken one forms again, else a new one with the run's next key.
  std::int64_t appended = 0;
  for (const PairReport* q : formed) {
    const std::int32_t i = local_index(q->a), j = local_index(q->b);
    if (i >= 0 && j >= 0) gone_pairs.push_back({i, j});
    if (q->key >= 0) {
      broken_change -= !q->formed;
      if (const std::int64_t k = local_rod(q->key); k >= 0) {
        r.rest_length[k] = q->length;
        r.inv_rest_length[k] = 1.0 / q->length;
        r.shift[k] = r.trial_shift[k] = 0.0;
        r.stress[k] = r.force_coef[k] = 0.0;
        r.trial_broken[k] = 0;
        r.intact[k] = 1;
      }
      continue;
    }
    const std::int64_t key = global_rods_ + appended++;
    if (i >= 0 && j >= 0 && (owned_[i] || owned_[j])) {
      r.append_formed(i, j, q->length);
      rod_key_.push_back(key);
    }
  }
  global_rods_ += appended;
  // The broken formed rods leave the run's list (Rods::remove_broken_formed), each reported by
  // the owner of its first end; the keys after them close up.
  std::vector<std::int64_t> gone_mine;
  for (std::size_t k = 0; k < r.size(); ++k)
    if (r.formed[k] && !r.intact[k] && owned_[r.ends[k][0]]) gone_mine.push_back(rod_key_[k]);
  std::vector<std::int64_t> gone = gathered(comm_, gone_mine);
  std::sort(gone.begin(), gone.end());
  if (!gone.empty()) {
    std::vector<std::uint8_t> keep(r.size());
    for (std::size_t k = 0; k < r.size(); ++k) keep[k] = !std::binary_search(gone.begin(), gone.end(), rod_key_[k]);
    const auto compact = [&](auto& v) {
      std::size_t out = 0;
      for (std::size_t k = 0; k < keep.size(); ++k)
        if (keep[k]) v[out++] = v[k];
      v.resize(out);
    };
    compact(r.ends);
    r.for_each_field([&](const char*, auto& v) { compact(v); });
    compact(rod_key_);
    for (std::int64_t& key : rod_key_) key -= std::lower_bound(gone.begin(), gone.end(), key) - gone.begin();
    global_rods_ -= static_cast<std::int64_t>(gone.size());
  }
  rs.formation_applied(w, formed.size(), broken_change);
  rs.count_exactly(owned_.data(), rod_key_.data());  // (the keys may have moved)
  contacts.remove_pairs(p, gone_pairs);
  touched = gone_pairs;
  touched.insert(touched.end(), new_pairs.begin(), new_pairs.end());
  contacts.add_pairs(p, std::move(new_pairs));
  return touched;
}

}  // namespace swarf
