// hypre_amg.cpp: BoomerAMG behind LinearPreconditioner (see hypre_amg.h).
#include "study/hypre_amg.h"

#include <chrono>
#include <cstdlib>
#include <numeric>
#include <vector>

#include "swarf/core/errors.h"

#ifdef SWARF_HAVE_HYPRE
#include <HYPRE.h>
#include <HYPRE_parcsr_ls.h>
#include <mpi.h>
#endif

namespace swarf {

#ifdef SWARF_HAVE_HYPRE
namespace {

using Clock = std::chrono::steady_clock;

// hypre's calls need MPI; a plain (not mpirun-launched) process initialises it here, once, and
// finalises it at exit.
void ensure_mpi() {
  int on = 0;
  MPI_Initialized(&on);
  if (on) return;
  int provided = 0;
  MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided);
  std::atexit([] {
    int done = 0;
    MPI_Finalized(&done);
    if (!done) MPI_Finalize();
  });
}

void check(HYPRE_Int err, const char* what) {
  if (err != 0) {
    HYPRE_ClearAllErrors();
    throw SimulationError(std::string("hypre: ") + what + " failed (error " + std::to_string(err) + ")");
  }
}

}  // namespace

struct HypreAmg::Impl {
  HypreAmgSettings set;
  HYPRE_IJMatrix A = nullptr;
  HYPRE_IJVector b = nullptr, x = nullptr;
  HYPRE_Solver amg = nullptr;
  HYPRE_Int rows = 0;
  std::vector<HYPRE_Int> index;
  std::vector<double> zero;
  int calls = 0, setups = 0;
  double setup_s = 0, apply_s = 0;

  void release() {
    if (amg) HYPRE_BoomerAMGDestroy(amg);
    if (A) HYPRE_IJMatrixDestroy(A);
    if (b) HYPRE_IJVectorDestroy(b);
    if (x) HYPRE_IJVectorDestroy(x);
    amg = nullptr;
    A = nullptr;
    b = x = nullptr;
  }

  HYPRE_IJVector vector() const {
    HYPRE_IJVector v = nullptr;
    check(HYPRE_IJVectorCreate(MPI_COMM_SELF, 0, rows - 1, &v), "IJVectorCreate");
    check(HYPRE_IJVectorSetObjectType(v, HYPRE_PARCSR), "IJVectorSetObjectType");
    check(HYPRE_IJVectorInitialize(v), "IJVectorInitialize");
    check(HYPRE_IJVectorSetValues(v, rows, index.data(), zero.data()), "IJVectorSetValues");
    check(HYPRE_IJVectorAssemble(v), "IJVectorAssemble");
    return v;
  }

  void build(const TangentMatrix& J) {
    release();
    rows = static_cast<HYPRE_Int>(J.rows());
    index.resize(rows);
    std::iota(index.begin(), index.end(), 0);
    zero.assign(rows, 0.0);
    check(HYPRE_IJMatrixCreate(MPI_COMM_SELF, 0, rows - 1, 0, rows - 1, &A), "IJMatrixCreate");
    check(HYPRE_IJMatrixSetObjectType(A, HYPRE_PARCSR), "IJMatrixSetObjectType");
    std::vector<HYPRE_Int> ncols(rows), cols(J.column.begin(), J.column.end());
    for (HYPRE_Int r = 0; r < rows; ++r) ncols[r] = static_cast<HYPRE_Int>(J.row_start[r + 1] - J.row_start[r]);
    check(HYPRE_IJMatrixSetRowSizes(A, ncols.data()), "IJMatrixSetRowSizes");
    check(HYPRE_IJMatrixInitialize(A), "IJMatrixInitialize");
    check(HYPRE_IJMatrixSetValues(A, rows, ncols.data(), index.data(), cols.data(), J.value.data()),
          "IJMatrixSetValues");
    check(HYPRE_IJMatrixAssemble(A), "IJMatrixAssemble");
    b = vector();
    x = vector();
    HYPRE_ParCSRMatrix pA;
    HYPRE_ParVector pb, px;
    HYPRE_IJMatrixGetObject(A, reinterpret_cast<void**>(&pA));
    HYPRE_IJVectorGetObject(b, reinterpret_cast<void**>(&pb));
    HYPRE_IJVectorGetObject(x, reinterpret_cast<void**>(&px));
    check(HYPRE_BoomerAMGCreate(&amg), "BoomerAMGCreate");
    HYPRE_BoomerAMGSetPrintLevel(amg, 0);
    HYPRE_BoomerAMGSetMaxIter(amg, 1);  // one V-cycle per application: a preconditioner
    HYPRE_BoomerAMGSetTol(amg, 0.0);
    HYPRE_BoomerAMGSetCoarsenType(amg, 10);  // HMIS
    HYPRE_BoomerAMGSetInterpType(amg, 6);    // extended+i
    HYPRE_BoomerAMGSetPMaxElmts(amg, 4);
    HYPRE_BoomerAMGSetStrongThreshold(amg, set.strong_threshold);
    HYPRE_BoomerAMGSetRelaxType(amg, 6);  // symmetric Gauss-Seidel (one process): CG needs symmetry
    HYPRE_BoomerAMGSetNumSweeps(amg, 1);
    HYPRE_BoomerAMGSetNumFunctions(amg, 3);  // x, y, z of each particle, interleaved
    if (set.nodal) HYPRE_BoomerAMGSetNodal(amg, 4);
    check(HYPRE_BoomerAMGSetup(amg, pA, pb, px), "BoomerAMGSetup");
  }
};

HypreAmg::HypreAmg(const HypreAmgSettings& s) : impl_(std::make_unique<Impl>()) {
  if (s.refresh < 1) throw InputError("--amg-refresh: " + std::to_string(s.refresh) + " must be at least 1");
  ensure_mpi();
  HYPRE_Init();
  impl_->set = s;
}

HypreAmg::~HypreAmg() { impl_->release(); }

bool HypreAmg::available() { return true; }

bool HypreAmg::wants_tangent(std::size_t rows) {
  Impl& m = *impl_;
  // A new hierarchy at every refresh-th tangent, and whenever the particles' number changed.
  if (!m.amg || static_cast<HYPRE_Int>(rows) != m.rows) m.calls = 0;
  return m.calls++ % m.set.refresh == 0;
}

void HypreAmg::setup(const TangentMatrix& J) {
  Impl& m = *impl_;
  const auto t0 = Clock::now();
  m.build(J);
  ++m.setups;
  m.setup_s += std::chrono::duration<double>(Clock::now() - t0).count();
}

void HypreAmg::apply(const double* r, double* z) {
  Impl& m = *impl_;
  const auto t0 = Clock::now();
  check(HYPRE_IJVectorSetValues(m.b, m.rows, m.index.data(), r), "IJVectorSetValues");
  check(HYPRE_IJVectorSetValues(m.x, m.rows, m.index.data(), m.zero.data()), "IJVectorSetValues");
  HYPRE_ParCSRMatrix pA;
  HYPRE_ParVector pb, px;
  HYPRE_IJMatrixGetObject(m.A, reinterpret_cast<void**>(&pA));
  HYPRE_IJVectorGetObject(m.b, reinterpret_cast<void**>(&pb));
  HYPRE_IJVectorGetObject(m.x, reinterpret_cast<void**>(&px));
  check(HYPRE_BoomerAMGSolve(m.amg, pA, pb, px), "BoomerAMGSolve");
  check(HYPRE_IJVectorGetValues(m.x, m.rows, m.index.data(), z), "IJVectorGetValues");
  m.apply_s += std::chrono::duration<double>(Clock::now() - t0).count();
}

int HypreAmg::setups() const { return impl_->setups; }
double HypreAmg::setup_seconds() const { return impl_->setup_s; }
double HypreAmg::apply_seconds() const { return impl_->apply_s; }

#else

struct HypreAmg::Impl {};

HypreAmg::HypreAmg(const HypreAmgSettings&) {
  throw InputError(
      "--preconditioner amg: this swarf was built without hypre (install libhypre-dev: scripts/install-deps.sh)");
}
HypreAmg::~HypreAmg() = default;
bool HypreAmg::available() { return false; }
bool HypreAmg::wants_tangent(std::size_t) { return false; }
void HypreAmg::setup(const TangentMatrix&) {}
void HypreAmg::apply(const double*, double*) {}
int HypreAmg::setups() const { return 0; }
double HypreAmg::setup_seconds() const { return 0; }
double HypreAmg::apply_seconds() const { return 0; }

#endif

}  // namespace swarf
