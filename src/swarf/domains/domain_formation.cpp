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
// With key kCountReport, a RodReport is the particle's count of intact rods (in 'other').
constexpr std::int64_t kCountReport = -1;
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
         return owned_[i] && lattice_local_[i] && lattice_local_[j];
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
  // 2. For each particle of the pairs, by its owner: its count of intact rods and, if it may
  // reach the coordination within this step's pairs (so that the rule may ask for its most
  // stretched rod), its intact rods that are stretched (the rule gives no other). A particle's count grows by at most
  // one per pair of it before its last, so one with count + pairs - 1 below the coordination never gives a rod (most of
  // a cut's: only their counts travel).
  std::vector<std::int64_t> involved;
  for (const PairReport& q : pairs) involved.push_back(q.a), involved.push_back(q.b);
  std::sort(involved.begin(), involved.end());
  std::vector<int> pairs_of;  // per involved particle: its number of pairs
  {
    std::size_t out = 0;
    for (std::size_t k = 0; k < involved.size(); ++k)
      if (k > 0 && involved[k] == involved[out - 1]) {
        ++pairs_of.back();
      } else {
        involved[out++] = involved[k];
        pairs_of.push_back(1);
      }
    involved.resize(out);
  }
  const auto slot = [&](std::int64_t id) {
    return static_cast<std::size_t>(std::lower_bound(involved.begin(), involved.end(), id) - involved.begin());
  };
  std::vector<RodReport> reports_mine;
  for (std::size_t n = 0; n < involved.size(); ++n) {
    const std::int64_t id = involved[n];
    const std::int32_t i = local_index(id);
    if (i < 0 || !owned_[i]) continue;
    int intact = 0;
    for (std::int32_t x = r.row_start[i]; x < r.row_start[i + 1]; ++x) intact += r.intact[r.entries[x].rod];
    reports_mine.push_back(RodReport{id, kCountReport, intact, 0, 0.0, 0.0});
    if (!rule.exchange || may_form(rule, intact + pairs_of[n] - 1)) continue;
    for (std::int32_t x = r.row_start[i]; x < r.row_start[i + 1]; ++x) {
      const std::int32_t k = r.entries[x].rod;
      if (!r.intact[k]) continue;
      Vec3 d = p.position[r.entries[x].other] - p.position[i];
      w.periodic.wrap(d);
      const double strain = d.norm() * (1.0 / r.rest_length[k]) - 1.0;
      if (!(strain > 0.0)) continue;  // (the rule gives only a stretched rod: the others need not travel)
      reports_mine.push_back(RodReport{id, rod_key_[k], p.id[r.entries[x].other], r.formed[k], strain,
                                       elastic_energy_density(r.law, r.stress[k]) * r.area * r.rest_length[k]});
    }
  }
  // By particle, its count first, then its rods in key order.
  std::vector<RodReport> reports = gathered(comm_, reports_mine);
  std::sort(reports.begin(), reports.end(), [](const RodReport& x, const RodReport& y) {
    return std::pair{x.id, x.key} < std::pair{y.id, y.key};
  });
  std::vector<std::size_t> first_report(involved.size() + 1, reports.size());
  for (std::size_t n = 0; n < involved.size(); ++n) {
    const auto it = std::lower_bound(reports.begin(), reports.end(), involved[n],
                                     [](const RodReport& x, std::int64_t id) { return x.id < id; });
    if (it == reports.end() || it->id != involved[n] || it->key != kCountReport)
      throw std::logic_error(fmt::format("DomainRun::form_rods: no rank reported particle {}", involved[n]));
    first_report[n] = static_cast<std::size_t>(it - reports.begin());
  }
  // 3. The serial rule (RodSystem::form), replayed on the same data by every domain. A
  // particle's count is taken at its first pair, as the serial rule counts it then: its intact
  // rods less those its neighbours gave away in the pairs before ('pending').
  std::vector<std::int64_t> exchanged_keys;  // (a few per step)
  const auto was_exchanged = [&](std::int64_t key) {
    return std::find(exchanged_keys.begin(), exchanged_keys.end(), key) != exchanged_keys.end();
  };
  std::vector<const RodReport*> exchanged;
  std::vector<const PairReport*> formed;
  std::vector<int> count(involved.size(), -1), pending(involved.size(), 0);
  std::int64_t broken_change = 0;
  const auto most_stretched = [&](std::size_t n) -> const RodReport* {
    const RodReport* best = nullptr;
    double worst = 0.0;
    for (std::size_t x = first_report[n] + 1; x < first_report[n + 1]; ++x)
      if (const RodReport& q = reports[x]; !was_exchanged(q.key) && q.strain > worst) {
        worst = q.strain;
        best = &q;
      }
    return best;
  };
  for (const PairReport& q : pairs) {
    const std::size_t e[2] = {slot(q.a), slot(q.b)};
    for (const std::size_t n : e)
      if (count[n] < 0) count[n] = static_cast<int>(reports[first_report[n]].other) - pending[n];
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
      exchanged_keys.push_back(give[s]->key);
      exchanged.push_back(give[s]);
      broken_change += !give[s]->formed;
      if (const std::size_t o = slot(give[s]->other); o < involved.size() && involved[o] == give[s]->other) {
        if (count[o] >= 0)
          --count[o];
        else
          ++pending[o];
      }
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
  const std::size_t m_before = r.size();
  for (const PairReport* q : formed) {
    const std::int32_t i = local_index(q->a), j = local_index(q->b);
    if (i >= 0 && j >= 0) gone_pairs.push_back({i, j});
    if (q->key >= 0) {
      broken_change -= !q->formed;
      if (const std::int64_t k = local_rod(q->key); k >= 0) {
        r.rest_length[k] = q->length;
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
  // the owner of its first end; the keys after them close up. The formed rods are the tail of
  // the local list, as in the serial one (their keys follow the lattice's, and the local rods are
  // in key order), so only the tail is searched and compacted.
  if (r.formed.size() != r.size()) throw std::logic_error("DomainRun::form_rods: the rods carry no 'formed' flags");
  std::size_t tail = r.size();
  while (tail > 0 && r.formed[tail - 1]) --tail;
  std::vector<std::int64_t> gone_mine;
  for (std::size_t k = tail; k < r.size(); ++k)
    if (!r.intact[k] && owned_[r.ends[k][0]]) gone_mine.push_back(rod_key_[k]);
  std::vector<std::int64_t> gone = gathered(comm_, gone_mine);
  std::sort(gone.begin(), gone.end());
  std::size_t first_changed = m_before;  // (the rows change from the first rod appended or moved on)
  if (!gone.empty()) {
    const std::size_t first = std::lower_bound(rod_key_.begin(), rod_key_.end(), gone.front()) - rod_key_.begin();
    first_changed = std::min(first_changed, first);
    const std::size_t m = r.size();
    std::vector<std::uint8_t> keep(m - first);
    for (std::size_t k = first; k < m; ++k)
      keep[k - first] = !std::binary_search(gone.begin(), gone.end(), rod_key_[k]);
    const auto compact = [&](auto& v) {
      std::size_t out = first;
      for (std::size_t k = first; k < m; ++k)
        if (keep[k - first]) v[out++] = v[k];
      v.resize(out);
    };
    compact(r.ends);
    r.for_each_field([&](const char*, auto& v) { compact(v); });
    compact(rod_key_);
    for (std::size_t k = first; k < rod_key_.size(); ++k)
      rod_key_[k] -= std::lower_bound(gone.begin(), gone.end(), rod_key_[k]) - gone.begin();
    global_rods_ -= static_cast<std::int64_t>(gone.size());
  }
  rs.formation_applied(w, formed.size(), broken_change, first_changed);
  rs.count_exactly(owned_.data(), rod_key_.data());  // (the keys may have moved)
  contacts.remove_pairs(p, gone_pairs);
  touched = gone_pairs;
  touched.insert(touched.end(), new_pairs.begin(), new_pairs.end());
  contacts.add_pairs(p, std::move(new_pairs));
  return touched;
}

}  // namespace swarf
