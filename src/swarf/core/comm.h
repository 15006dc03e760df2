// comm.h: what the domains of one run say to each other (issue 38), free of MPI.
//
// A Comm is one rank's end of a group of ranks that call its collectives together, in the same
// order. Two primitives carry bytes: all_to_all (a buffer for every rank, one from every rank)
// and all_gather (every rank's buffer to every rank), and 'exchange' sends point to point when
// both sides know the sizes (the halo); the reductions are built on them so that
// their results do not depend on how the numbers are split over the ranks: integers are summed
// exactly, minima and maxima are exact, and sums of doubles are gathered and added in rank order.
// SerialComm is the one-rank group; LoopbackComm (loopback_comm.h) runs N ranks as threads of
// one process (the tests); MpiComm (study/mpi_comm.h) is MPI's. Not virtual in hot loops: a
// collective is called a few times per step.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <utility>
#include <vector>

#include "swarf/core/exact_sum.h"

namespace swarf {

using Bytes = std::vector<std::byte>;

class Comm {
 public:
  virtual ~Comm() = default;
  virtual int rank() const = 0;
  virtual int size() const = 0;
  /// send[r] goes to rank r (send.size() == size()); returns what every rank r sent to this one.
  virtual std::vector<Bytes> all_to_all(std::vector<Bytes> send) = 0;
  /// Every rank's 'mine', indexed by rank, on every rank.
  virtual std::vector<Bytes> all_gather(Bytes mine) = 0;
  /// On rank 0, every other rank's 'mine' in 'from[r]' (r = 1..size-1; from[0] is left empty:
  /// rank 0's own is its 'mine'); nothing on the others: what only the rank that writes needs.
  /// 'from' is reused from call to call (its buffers keep their memory: a run gathers its whole
  /// state at every output). The default goes through all_gather.
  virtual void gather_to_root(const Bytes& mine, std::vector<Bytes>& from) {
    std::vector<Bytes> all = all_gather(mine);
    if (rank() != 0) return;
    all[0].clear();
    from = std::move(all);
  }
  virtual void barrier() = 0;
  /// Point to point with sizes known on both sides: send[r] goes to rank r and recv_bytes[r]
  /// bytes come from rank r; ranks with nothing to send or receive are not contacted (the
  /// halo after each step talks to its neighbours only, not to every rank as all_to_all does).
  /// Every rank calls it together. The default goes through all_to_all.
  virtual std::vector<Bytes> exchange(std::vector<Bytes> send, const std::vector<std::size_t>& recv_bytes) {
    (void)recv_bytes;
    return all_to_all(std::move(send));
  }

  /// Element-wise sums of the ranks' integer vectors (all the same length): exact.
  std::vector<std::int64_t> sum_all(const std::vector<std::int64_t>& v) {
    std::vector<std::int64_t> out(v.size(), 0);
    for (const Bytes& b : all_gather(to_bytes(v)))
      for (std::size_t k = 0; k < out.size(); ++k) out[k] += from_bytes<std::int64_t>(b)[k];
    return out;
  }
  std::int64_t sum_all(std::int64_t v) { return sum_all(std::vector<std::int64_t>{v})[0]; }
  /// The largest (smallest) v over the ranks.
  double max_all(double v) {
    double m = v;
    for (const Bytes& b : all_gather(to_bytes(std::vector<double>{v}))) m = std::max(m, from_bytes<double>(b)[0]);
    return m;
  }
  double min_all(double v) { return -max_all(-v); }
  /// Sums of the ranks' partial vectors added in rank order: the same bits on every rank, and
  /// the same for any rank count wherever the partials themselves are.
  std::vector<double> sum_in_rank_order(const std::vector<double>& v) {
    std::vector<double> out(v.size(), 0.0);
    for (const Bytes& b : all_gather(to_bytes(v))) {
      const std::vector<double> part = from_bytes<double>(b);
      for (std::size_t k = 0; k < out.size(); ++k) out[k] += part[k];
    }
    return out;
  }

  /// The exact sums of the ranks' accumulators, element-wise: the same bits on every rank and
  /// for any split of the terms over the ranks (exact_sum.h).
  std::vector<ExactSum> sum_exact(const std::vector<ExactSum>& v) {
    std::vector<std::int64_t> words;
    words.reserve(v.size() * ExactSum::kWords);
    for (const ExactSum& s : v) {
      const std::vector<std::int64_t> d = s.digits();
      words.insert(words.end(), d.begin(), d.end());
    }
    std::vector<std::int64_t> total(words.size(), 0);
    for (const Bytes& b : all_gather(to_bytes(words))) {
      const std::vector<std::int64_t> part = from_bytes<std::int64_t>(b);
      for (std::size_t k = 0; k < total.size(); ++k)
        total[k] = (k + 1) % ExactSum::kWords == 0 ? (total[k] | part[k]) : total[k] + part[k];  // (flags: or)
    }
    std::vector<ExactSum> out;
    out.reserve(v.size());
    for (std::size_t i = 0; i < v.size(); ++i) out.push_back(ExactSum::from_digits(total, i * ExactSum::kWords));
    return out;
  }

  template <class T>
  static Bytes to_bytes(const std::vector<T>& v) {
    Bytes b(v.size() * sizeof(T));
    if (!v.empty()) std::memcpy(b.data(), v.data(), b.size());
    return b;
  }
  template <class T>
  static std::vector<T> from_bytes(const Bytes& b) {
    std::vector<T> v(b.size() / sizeof(T));
    if (!v.empty()) std::memcpy(v.data(), b.data(), v.size() * sizeof(T));
    return v;
  }
};

/// The group of one rank: every collective returns what it was given.
class SerialComm final : public Comm {
 public:
  int rank() const override { return 0; }
  int size() const override { return 1; }
  std::vector<Bytes> all_to_all(std::vector<Bytes> send) override { return send; }
  std::vector<Bytes> all_gather(Bytes mine) override {
    std::vector<Bytes> out;
    out.push_back(std::move(mine));
    return out;
  }
  void barrier() override {}
};

}  // namespace swarf
