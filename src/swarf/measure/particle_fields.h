// particle_fields.h: the per-particle fields an FEM user looks for, computed from the state:
// the stress tensor (the virial of the particle's rods and contacts over its volume), its von
// Mises and hydrostatic parts, and an equivalent plastic strain from its rods.
//
// Stress. Particle i's stress is the Love-Weber sum over the forces acting on it,
//     sigma_i = 1/V_i sum_c sym((x_c - x_i) (x) f_c),
// with f_c the force on i at the point x_c: a rod's force at the rod's midpoint (x_c - x_i =
// d/2, d = x_j - x_i), a sphere-sphere contact's at R_i n, a sphere-triangle contact's at
// -R_i n (n from the wall to the sphere). Positive in tension. V_i = 4 sqrt(2) R_i^3 is the
// volume per particle of the FCC lattice of spheres of radius R_i in contact (a^3/4, a = 2
// sqrt(2) R), the reference volume: the result is the Kirchhoff stress (Cauchy times the
// volume ratio), equal to the Cauchy stress within the volume change. Under a homogeneous
// deformation an interior particle's stress is exactly the Cauchy-Born crystal's times det F
// (lattice_gen/cauchy_born.h); at free surfaces and in fragments the particle's volume is not
// filled and the value is that of the particle's neighbourhood, as in any virial stress.
//
// Plastic strain. Each intact rod holds a plastic strain eps_p, its law's plastic_strain() of
// its state (the paper's law: (E - k)/E eps0; laws/rod_law.h), along its direction n. The
// particle's plastic strain tensor is the one whose
// normal strains n.E.n fit its intact rods' eps_p best in least squares (exact when the rods
// span the 6 independent directions of a symmetric tensor, as an interior FCC particle's do;
// otherwise the part the rods determine well: see particle_fields.cpp), and the field is its
// von Mises equivalent sqrt(2/3 e:e), e the deviator. It is the plastic strain the particle's CURRENT rods hold: rods
// that broke or were given up in a neighbour exchange take theirs with them, so in a flowing chip it is below the
// accumulated plastic strain of a continuum (docs/outputs.md).
#pragma once

#include <array>
#include <vector>

#include "swarf/core/periodic.h"
#include "swarf/core/sym_tensor.h"
#include "swarf/geometry/site_volume.h"
#include "swarf/state/particles.h"
#include "swarf/state/rods.h"

namespace swarf {

class ContactSystem;

/// (The von Mises and hydrostatic parts are read off the stress where they are written, von_mises()
/// and hydrostatic(): held for every particle they were 16 B each of a run's last write.)
struct ParticleFields {
  std::vector<SymTensor> stress;       ///< Pa, positive in tension
  std::vector<double> plastic_strain;  ///< von Mises equivalent of the fitted plastic strain tensor, 1
};

/// The fields for the state now. The rods' forces are those of the last evaluation
/// (Rods::force_coef: elastic-plastic and viscous); 'contacts' may be null (no contacts), else
/// its last evaluation's results are used. 'periodic': the nearest image for the rods. The
/// rods' per-particle lists (Rods::build_rows) are used when they match the rods' count, else
/// built here.
ParticleFields particle_fields(const Particles& p, const Rods& r, const Periodic& periodic,
                               const ContactSystem* contacts);

/// von Mises stress sqrt(3/2 s:s) of a symmetric tensor (s its deviator), in its unit.
double von_mises(const SymTensor& t);
/// tr(t)/3, in its unit (for a stress positive in tension: minus the pressure).
inline double hydrostatic(const SymTensor& t) { return (t[0] + t[1] + t[2]) / 3.0; }

}  // namespace swarf
