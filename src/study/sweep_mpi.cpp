// sweep_mpi.cpp: the only translation unit that calls MPI (see sweep_mpi.h). Built without
// MPI (SWARF_HAVE_MPI undefined), a launch under mpirun is refused with a clear message.
#include "study/sweep_mpi.h"

#include <cstdlib>

#include "swarf/core/errors.h"

#ifdef SWARF_HAVE_MPI
#include <mpi.h>
#endif

namespace swarf {

bool MpiSession::launched() { return std::getenv("OMPI_COMM_WORLD_SIZE") || std::getenv("PMI_SIZE"); }

#ifdef SWARF_HAVE_MPI

MpiSession::MpiSession() {
  if (!launched()) return;
  int initialized = 0;
  MPI_Initialized(&initialized);
  if (!initialized) {
    // Only the main thread calls MPI; the case runners just start processes.
    int provided = 0;
    MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided);
    active_ = true;
  }
  MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
  MPI_Comm_size(MPI_COMM_WORLD, &size_);
  MPI_Comm node;
  MPI_Comm_split_type(MPI_COMM_WORLD, MPI_COMM_TYPE_SHARED, rank_, MPI_INFO_NULL, &node);
  MPI_Comm_size(node, &local_size_);
  MPI_Comm_rank(node, &local_rank_);
  MPI_Comm_free(&node);
}

MpiSession::~MpiSession() {
  if (active_) MPI_Finalize();
}

void MpiSession::barrier() const {
  if (size_ > 1) MPI_Barrier(MPI_COMM_WORLD);
}

int MpiSession::max_all(int v) const {
  int out = v;
  if (size_ > 1) MPI_Allreduce(&v, &out, 1, MPI_INT, MPI_MAX, MPI_COMM_WORLD);
  return out;
}

int MpiSession::from_root(int v) const {
  if (size_ > 1) MPI_Bcast(&v, 1, MPI_INT, 0, MPI_COMM_WORLD);
  return v;
}

void MpiSession::abort(int code) const {
  if (active_) MPI_Abort(MPI_COMM_WORLD, code);
  std::exit(code);
}

#else

MpiSession::MpiSession() {
  if (launched())
    throw InputError(
        "this swarf was built without MPI: run the study without mpirun (swarf sweep --jobs N), "
        "or rebuild with the MPI development files (libopenmpi-dev)");
}
MpiSession::~MpiSession() = default;
void MpiSession::barrier() const {}
int MpiSession::max_all(int v) const { return v; }
int MpiSession::from_root(int v) const { return v; }

void MpiSession::abort(int code) const { std::exit(code); }

#endif

}  // namespace swarf
