// zoltan_rcb.cpp: Zoltan's RCB made into the ranks' boxes (see zoltan_rcb.h).
//
// Each rank hands Zoltan its owned particles (positions and weights, 1 + intact rods: exact as
// floats) and keeps nothing of Zoltan's import and export lists: the boxes of the cut tree
// (Zoltan_RCB_Box, which needs KEEP_CUTS) are the partition, and the domains move the particles
// themselves (domain_run.cpp), so that every rank decides ownership by the same half-open boxes.
// AVERAGE_CUTS puts a cut midway between the particles on either side: on a lattice a cut never
// falls on a plane of particles. A periodic y is left out of the coordinates, so it is never cut.
#include "study/zoltan_rcb.h"

#include <cfloat>
#include <cmath>
#include <stdexcept>

#include "swarf/core/errors.h"

#if defined(SWARF_HAVE_ZOLTAN) && defined(SWARF_HAVE_MPI)
#include <mpi.h>
#include <zoltan.h>
#define SWARF_ZOLTAN 1
#endif

namespace swarf {

#ifdef SWARF_ZOLTAN

namespace {

struct Points {
  const std::vector<Vec3>* x;
  const std::vector<std::int64_t>* w;
  bool cut_y;
};

int num_obj(void* data, int* ierr) {
  *ierr = ZOLTAN_OK;
  return static_cast<int>(static_cast<Points*>(data)->x->size());
}

void obj_list(void* data, int, int, ZOLTAN_ID_PTR gids, ZOLTAN_ID_PTR lids, int wdim, float* wgts, int* ierr) {
  const Points& p = *static_cast<Points*>(data);
  for (std::size_t i = 0; i < p.x->size(); ++i) {
    gids[i] = static_cast<ZOLTAN_ID_TYPE>(i);  // (ids only name objects within a call: no lists come back)
    lids[i] = static_cast<ZOLTAN_ID_TYPE>(i);
    if (wdim > 0) wgts[i] = static_cast<float>((*p.w)[i]);
  }
  *ierr = ZOLTAN_OK;
}

int num_geom(void* data, int* ierr) {
  *ierr = ZOLTAN_OK;
  return static_cast<Points*>(data)->cut_y ? 3 : 2;
}

void geom_multi(void* data, int, int, int n, ZOLTAN_ID_PTR, ZOLTAN_ID_PTR lids, int dim, double* out, int* ierr) {
  const Points& p = *static_cast<Points*>(data);
  for (int k = 0; k < n; ++k) {
    const Vec3& x = (*p.x)[lids[k]];
    double* o = out + static_cast<std::size_t>(k) * dim;
    o[0] = x[0];
    if (dim == 3) {
      o[1] = x[1];
      o[2] = x[2];
    } else {
      o[1] = x[2];
    }
  }
  *ierr = ZOLTAN_OK;
}

// Zoltan's outer faces are +-DBL_MAX; the boxes' are +-inf.
double open(double v) { return v <= -DBL_MAX ? -HUGE_VAL : (v >= DBL_MAX ? HUGE_VAL : v); }

}  // namespace

bool ZoltanRcb::available() { return true; }

ZoltanRcb::ZoltanRcb() {
  int initialized = 0;
  MPI_Initialized(&initialized);
  if (!initialized) throw std::logic_error("ZoltanRcb: MPI is not initialised (start an MpiSession first)");
  static const bool once = [] {
    float version = 0.0f;
    return Zoltan_Initialize(0, nullptr, &version) == ZOLTAN_OK;
  }();
  if (!once) throw std::runtime_error("Zoltan_Initialize failed");
}

std::vector<DomainBox> ZoltanRcb::partition(const std::vector<Vec3>& x, const std::vector<std::int64_t>& w, bool cut_y) {
  int size = 1;
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  if (size == 1) return {DomainBox{}};  // (Partition makes it all of space)
  Points pts{&x, &w, cut_y};
  Zoltan_Struct* zz = Zoltan_Create(MPI_COMM_WORLD);
  Zoltan_Set_Param(zz, "DEBUG_LEVEL", "0");
  Zoltan_Set_Param(zz, "LB_METHOD", "RCB");
  Zoltan_Set_Param(zz, "NUM_GID_ENTRIES", "1");
  Zoltan_Set_Param(zz, "NUM_LID_ENTRIES", "1");
  Zoltan_Set_Param(zz, "OBJ_WEIGHT_DIM", "1");
  Zoltan_Set_Param(zz, "RETURN_LISTS", "NONE");
  Zoltan_Set_Param(zz, "KEEP_CUTS", "1");
  Zoltan_Set_Param(zz, "AVERAGE_CUTS", "1");
  Zoltan_Set_Num_Obj_Fn(zz, num_obj, &pts);
  Zoltan_Set_Obj_List_Fn(zz, obj_list, &pts);
  Zoltan_Set_Num_Geom_Fn(zz, num_geom, &pts);
  Zoltan_Set_Geom_Multi_Fn(zz, geom_multi, &pts);
  int changes = 0, ngid = 0, nlid = 0, nimp = 0, nexp = 0;
  ZOLTAN_ID_PTR igid = nullptr, ilid = nullptr, egid = nullptr, elid = nullptr;
  int *iproc = nullptr, *ipart = nullptr, *eproc = nullptr, *epart = nullptr;
  const int rc = Zoltan_LB_Partition(zz, &changes, &ngid, &nlid, &nimp, &igid, &ilid, &iproc, &ipart, &nexp, &egid,
                                     &elid, &eproc, &epart);
  Zoltan_LB_Free_Part(&igid, &ilid, &iproc, &ipart);
  Zoltan_LB_Free_Part(&egid, &elid, &eproc, &epart);
  std::vector<DomainBox> boxes(size);
  int bad = rc != ZOLTAN_OK;
  for (int part = 0; part < size && !bad; ++part) {
    int ndim = 0;
    double lo[3], hi[3];
    bad = Zoltan_RCB_Box(zz, part, &ndim, &lo[0], &lo[1], &lo[2], &hi[0], &hi[1], &hi[2]) != ZOLTAN_OK;
    DomainBox& b = boxes[part];
    b.lo = Vec3(open(lo[0]), cut_y ? open(lo[1]) : -HUGE_VAL, open(cut_y ? lo[2] : lo[1]));
    b.hi = Vec3(open(hi[0]), cut_y ? open(hi[1]) : HUGE_VAL, open(cut_y ? hi[2] : hi[1]));
  }
  Zoltan_Destroy(&zz);
  if (bad)
    throw std::runtime_error("Zoltan's recursive coordinate bisection failed (Zoltan error " + std::to_string(rc) + ")");
  return boxes;
}

#else

bool ZoltanRcb::available() { return false; }

ZoltanRcb::ZoltanRcb() {
  throw InputError(
      "this swarf was built without Zoltan (Debian's libtrilinos-zoltan-dev) or MPI: "
      "--partition rcb is not available; use --partition slabs");
}

std::vector<DomainBox> ZoltanRcb::partition(const std::vector<Vec3>&, const std::vector<std::int64_t>&, bool) {
  return {};
}

#endif

}  // namespace swarf
