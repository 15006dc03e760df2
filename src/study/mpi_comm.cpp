// mpi_comm.cpp: the domains' collectives over MPI (see mpi_comm.h): counts first, then the bytes.
#include "study/mpi_comm.h"

#include <stdexcept>
#include <string>

#ifdef SWARF_HAVE_MPI
#include <mpi.h>
#endif

namespace swarf {

#ifdef SWARF_HAVE_MPI

namespace {
// Displacements of buffers of 'counts' laid end to end, and their total.
int displacements(const std::vector<int>& counts, std::vector<int>& displ) {
  displ.assign(counts.size(), 0);
  long long total = 0;
  for (std::size_t r = 0; r < counts.size(); ++r) {
    displ[r] = static_cast<int>(total);
    total += counts[r];
  }
  if (total > 2147483647LL) throw std::runtime_error("MpiComm: more than 2 GB in one exchange");
  return static_cast<int>(total);
}
}  // namespace

MpiComm::MpiComm() {
  int initialized = 0;
  MPI_Initialized(&initialized);
  if (!initialized) throw std::logic_error("MpiComm: MPI is not initialised (start an MpiSession first)");
  MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
  MPI_Comm_size(MPI_COMM_WORLD, &size_);
}

std::vector<Bytes> MpiComm::all_to_all(std::vector<Bytes> send) {
  if (static_cast<int>(send.size()) != size_)
    throw std::logic_error("all_to_all: " + std::to_string(send.size()) + " buffers for " + std::to_string(size_) +
                           " ranks");
  std::vector<int> scount(size_), rcount(size_), sdispl, rdispl;
  for (int r = 0; r < size_; ++r) scount[r] = static_cast<int>(send[r].size());
  MPI_Alltoall(scount.data(), 1, MPI_INT, rcount.data(), 1, MPI_INT, MPI_COMM_WORLD);
  Bytes sbuf(displacements(scount, sdispl)), rbuf(displacements(rcount, rdispl));
  for (int r = 0; r < size_; ++r) std::copy(send[r].begin(), send[r].end(), sbuf.begin() + sdispl[r]);
  MPI_Alltoallv(sbuf.data(), scount.data(), sdispl.data(), MPI_BYTE, rbuf.data(), rcount.data(), rdispl.data(),
                MPI_BYTE, MPI_COMM_WORLD);
  std::vector<Bytes> out(size_);
  for (int r = 0; r < size_; ++r) out[r].assign(rbuf.begin() + rdispl[r], rbuf.begin() + rdispl[r] + rcount[r]);
  return out;
}

std::vector<Bytes> MpiComm::all_gather(Bytes mine) {
  int count = static_cast<int>(mine.size());
  std::vector<int> counts(size_), displ;
  MPI_Allgather(&count, 1, MPI_INT, counts.data(), 1, MPI_INT, MPI_COMM_WORLD);
  Bytes all(displacements(counts, displ));
  MPI_Allgatherv(mine.data(), count, MPI_BYTE, all.data(), counts.data(), displ.data(), MPI_BYTE, MPI_COMM_WORLD);
  std::vector<Bytes> out(size_);
  for (int r = 0; r < size_; ++r) out[r].assign(all.begin() + displ[r], all.begin() + displ[r] + counts[r]);
  return out;
}

void MpiComm::gather_to_root(const Bytes& mine, std::vector<Bytes>& from) {
  // Point to point into each rank's own buffer (a Gatherv would need one buffer and a copy out).
  constexpr int kTag = 39;
  if (mine.size() > 2147483647u) throw std::runtime_error("MpiComm: more than 2 GB from one rank");
  int count = static_cast<int>(mine.size());
  std::vector<int> counts(rank_ == 0 ? size_ : 0);
  MPI_Gather(&count, 1, MPI_INT, counts.data(), 1, MPI_INT, 0, MPI_COMM_WORLD);
  if (rank_ != 0) {
    MPI_Send(mine.data(), count, MPI_BYTE, 0, kTag, MPI_COMM_WORLD);
    return;
  }
  from.resize(size_);
  from[0].clear();
  std::vector<MPI_Request> requests;
  for (int r = 1; r < size_; ++r) {
    from[r].resize(static_cast<std::size_t>(counts[r]));  // (no new memory when it is as large as last time)
    requests.emplace_back();
    MPI_Irecv(from[r].data(), counts[r], MPI_BYTE, r, kTag, MPI_COMM_WORLD, &requests.back());
  }
  MPI_Waitall(static_cast<int>(requests.size()), requests.data(), MPI_STATUSES_IGNORE);
}

void MpiComm::barrier() { MPI_Barrier(MPI_COMM_WORLD); }

std::vector<Bytes> MpiComm::exchange(std::vector<Bytes> send, const std::vector<std::size_t>& recv_bytes) {
  if (static_cast<int>(send.size()) != size_ || static_cast<int>(recv_bytes.size()) != size_)
    throw std::logic_error("exchange: buffers for " + std::to_string(send.size()) + " and " +
                           std::to_string(recv_bytes.size()) + " ranks, not " + std::to_string(size_));
  constexpr int kTag = 38;  // (the halo's; no other point-to-point traffic on MPI_COMM_WORLD)
  std::vector<Bytes> out(size_);
  std::vector<MPI_Request> requests;
  for (int r = 0; r < size_; ++r) {
    if (r == rank_) {
      out[r] = std::move(send[r]);
      continue;
    }
    if (recv_bytes[r] == 0) continue;
    if (recv_bytes[r] > 2147483647u) throw std::runtime_error("MpiComm: more than 2 GB from one rank");
    out[r].resize(recv_bytes[r]);
    requests.emplace_back();
    MPI_Irecv(out[r].data(), static_cast<int>(recv_bytes[r]), MPI_BYTE, r, kTag, MPI_COMM_WORLD, &requests.back());
  }
  for (int r = 0; r < size_; ++r) {
    if (r == rank_ || send[r].empty()) continue;
    if (send[r].size() > 2147483647u) throw std::runtime_error("MpiComm: more than 2 GB to one rank");
    requests.emplace_back();
    MPI_Isend(send[r].data(), static_cast<int>(send[r].size()), MPI_BYTE, r, kTag, MPI_COMM_WORLD, &requests.back());
  }
  MPI_Waitall(static_cast<int>(requests.size()), requests.data(), MPI_STATUSES_IGNORE);
  return out;
}

#else

MpiComm::MpiComm() = default;
std::vector<Bytes> MpiComm::all_to_all(std::vector<Bytes> send) { return send; }
std::vector<Bytes> MpiComm::all_gather(Bytes mine) {
  std::vector<Bytes> out;
  out.push_back(std::move(mine));
  return out;
}
void MpiComm::gather_to_root(const Bytes&, std::vector<Bytes>& from) { from.assign(1, Bytes{}); }
void MpiComm::barrier() {}
std::vector<Bytes> MpiComm::exchange(std::vector<Bytes> send, const std::vector<std::size_t>&) { return send; }

#endif

}  // namespace swarf
