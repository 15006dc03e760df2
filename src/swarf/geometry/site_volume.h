// site_volume.h: the volume a particle stands for in the FCC packing of spheres in contact.
#pragma once

#include <cmath>

namespace swarf {

/// The volume V = 4 sqrt(2) R^3 (a^3/4 with the cell a = 2 sqrt(2) R) a particle of radius R (m)
/// stands for, m^3: the per-particle stress's reference volume, the plastic work's and the
/// density floor's.
inline double particle_volume(double radius) { return 4.0 * std::sqrt(2.0) * radius * radius * radius; }

}  // namespace swarf
