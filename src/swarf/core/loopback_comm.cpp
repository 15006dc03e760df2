// loopback_comm.cpp: the in-process group of ranks (see loopback_comm.h).
#include "swarf/core/loopback_comm.h"

#include <atomic>
#include <barrier>
#include <exception>
#include <stdexcept>
#include <string>
#include <thread>

namespace swarf {

namespace {

// What the ranks of one group share.
struct Hub {
  explicit Hub(int n) : n(n), bar(n), mail(n, std::vector<Bytes>(n)), gathered(n), calls(n, 0), errors(n) {}
  int n;
  std::barrier<> bar;
  std::vector<std::vector<Bytes>> mail;  // mail[from][to]
  std::vector<Bytes> gathered;           // all_gather: each rank's buffer
  std::vector<std::int64_t> calls;       // per rank: collectives entered (a rank that left early is caught)
  std::atomic<bool> failed{false};
  std::vector<std::exception_ptr> errors;
};

class LoopbackComm final : public Comm {
 public:
  LoopbackComm(Hub& hub, int rank) : hub_(hub), rank_(rank) {}
  int rank() const override { return rank_; }
  int size() const override { return hub_.n; }

  std::vector<Bytes> all_to_all(std::vector<Bytes> send) override {
    if (static_cast<int>(send.size()) != hub_.n)
      throw std::logic_error("all_to_all: " + std::to_string(send.size()) + " buffers for " + std::to_string(hub_.n) +
                             " ranks");
    hub_.mail[rank_] = std::move(send);
    enter();
    std::vector<Bytes> out(hub_.n);
    for (int r = 0; r < hub_.n; ++r) out[r] = std::move(hub_.mail[r][rank_]);
    wait();  // (nobody posts again before every rank has taken its mail)
    return out;
  }

  std::vector<Bytes> all_gather(Bytes mine) override {
    hub_.gathered[rank_] = std::move(mine);
    enter();
    std::vector<Bytes> out = hub_.gathered;
    wait();
    return out;
  }

  void barrier() override {
    enter();
    wait();  // (or a rank could enter the next collective before the others checked this one)
  }

 private:
  // Every rank has posted: check that they are all in the same collective.
  void enter() {
    hub_.calls[rank_] = ++calls_;
    wait();
    for (int r = 0; r < hub_.n; ++r)
      if (hub_.calls[r] != calls_)
        throw std::logic_error("loopback: rank " + std::to_string(r) + " left or is in another collective");
  }
  void wait() {
    hub_.bar.arrive_and_wait();
    if (hub_.failed) throw std::runtime_error("loopback: another rank failed");
  }

  Hub& hub_;
  int rank_;
  std::int64_t calls_ = 0;
};

}  // namespace

void run_loopback(int n, const std::function<void(Comm&)>& f) {
  if (n < 1) throw std::invalid_argument("run_loopback: " + std::to_string(n) + " ranks");
  Hub hub(n);
  std::vector<std::thread> threads;
  threads.reserve(n);
  for (int r = 0; r < n; ++r)
    threads.emplace_back([&hub, &f, r] {
      LoopbackComm comm(hub, r);
      try {
        f(comm);
      } catch (...) {
        hub.errors[r] = std::current_exception();
        hub.failed = true;
      }
      hub.bar.arrive_and_drop();  // (the others no longer wait for this rank)
    });
  for (std::thread& t : threads) t.join();
  // The first failure that is not the echo of another's.
  std::exception_ptr first;
  for (const std::exception_ptr& e : hub.errors) {
    if (!e) continue;
    try {
      std::rethrow_exception(e);
    } catch (const std::runtime_error& x) {
      if (std::string(x.what()) == "loopback: another rank failed") {
        if (!first) first = e;
        continue;
      }
      std::rethrow_exception(e);
    } catch (...) {
      std::rethrow_exception(e);
    }
  }
  if (first) std::rethrow_exception(first);
}

}  // namespace swarf
