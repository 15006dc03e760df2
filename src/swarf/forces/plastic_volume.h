// plastic_volume.h: the rods' plastic flow made to keep the volume, as a metal's does
// (rod.isochoric_plasticity).
//
// A rod yields by its axial stress, so a lattice of rods yields under pressure alone: in
// hydrostatic compression every rod shortens by the same strain and, beyond the rod's yield
// strain, they all flow. An FCC lattice calibrated in shear does so at a pressure of about 0.77
// times the yield stress, and loses volume plastically. A metal does not: its flow does not
// depend on the pressure and keeps the volume (von Mises; Bridgman's experiments), the plastic
// strain tensor has no trace. In a cut the material ahead of the tool and in the chip is under a
// pressure of the order of the flow stress, and the plain rod lattice compacts there: the default
// C45 chip ends about 1.8 times as dense as the workpiece (validation/cutting/compaction/).
//
// The rule here: after the law's return map has given every rod its trial shift, the increments
// of each particle's rods are made free of a mean. With m_p the mean of (trial shift - shift) over
// particle p's intact rods (a plastic volume change of p's neighbourhood: for an FCC particle's 12
// rods, sum_k n_k n_k^T = 4 I, so the mean of n.de_p.n is tr(de_p) / 3), rod k between i and j
// takes (m_i + m_j) / 2 off its increment, and its stress and force follow its shift (the law's
// shift_modulus). Pressure then yields nothing: every rod proposes the same increment and keeps
// none. A shear's increments have no mean (to first order in the strain) and are kept. The stress of a corrected rod
// may lie a little off the law's band; the next evaluation's return map starts from it. The energy stays exact (the
// stress is still the law's function of strain and shift, the plastic work sigma times the committed increment); the
// work pressure did on the removed mean is no longer dissipated. (A corrected rod's own plastic work may come out
// negative, its neighbours' the more positive; the heat's sources take the rods' works as they are.) Each particle's
// mean runs over its row of the rod lists in rod order, each rod's correction is its own: the same bits for any thread
// count. Rods broken in this trial take no part.
#pragma once

#include <vector>

#include "swarf/core/periodic.h"
#include "swarf/core/vec3.h"
#include "swarf/state/rods.h"

namespace swarf {

/// Passes of the correction per evaluation (plastic_volume.cpp says what each removes).
inline constexpr int kPlasticVolumePasses = 4;

/// Per-particle and per-set scratch, kept between steps (no allocation per step): marks and
/// means are 0 between calls.
struct PlasticVolumeScratch {
  std::vector<std::uint8_t> mark;  ///< 1: at a rod that yielded; 2: a neighbour of one
  std::vector<double> mean;        ///< the particle's mean increment in the current pass, 1
  std::vector<std::int32_t> set;   ///< the marked particles, in index order
};

/// Makes the trial's plastic increments mean-free per particle (above) where rods yielded (the
/// blocks 'block_changed' marks: per block of kBlock rods, set where a correction changed a rod)
/// and one ring of neighbours around, for the particles at x; stress, force coefficient and
/// trial shift of the rods it corrects change.
void keep_plastic_volume(Rods& rods, const Vec3* x, std::size_t particles, Periodic periodic, PlasticVolumeScratch& w,
                         int* block_changed);

}  // namespace swarf
