// heat_conduction.h: the conductances of the lattice's rods and of touching contacts, and the
// explicit conduction step's limit (docs/physics.md, "Heat").
//
// A rod between neighbours at distance d on the FCC lattice carries G (T_j - T_i). With a
// gradient g along x every rod carries G g d_x, and the flux through a unit plane normal to x
// is n (1/2) sum_j G g (d_j.x)^2 over a particle's 12 neighbours (n the particles per volume;
// each rod counted once). On FCC sum_j (d_j.x)^2 = 12 d^2 / 3 = 4 d^2 and n = sqrt(2) / d^3,
// so the lattice's conductivity is k = 2 sqrt(2) G / d, i.e.
//     G = k d / (2 sqrt 2) = k a / 4,   a = sqrt(2) d the cube edge,
// the same for any direction (the sum is isotropic on a cubic lattice). The heat capacity per
// particle is m c, which is rho c per lattice cell when the mass is the cell's
// (material.mass_basis = "cell", the default).
//
// A touching contact conducts through its contact circle of radius a: two half-spaces joined
// by a circle have the constriction conductance 4 a / (1/k_1 + 1/k_2) (2 k a for equal
// materials; Batchelor and O'Brien 1977 for touching spheres), with a = sqrt(R* delta) from
// Hertz. A sphere on a tool's triangle is weighted by the share of the sphere's cut circle
// inside the triangle, as its force is (overlap_area.h).
//
// The explicit (forward Euler) step T_i += dt/C_i sum_j G_ij (T_j - T_i) is a convex
// combination of the old temperatures (no new extremum: the discrete maximum principle) when
// dt <= C_i / sum_j G_ij for every particle; that is the limit the thermal system keeps.
#pragma once

#include <cmath>

namespace swarf {

/// Conductance of a rod of rest length d (m) in a workpiece of conductivity k (W/(m K)), W/K.
inline double rod_conductance(double conductivity, double rest_length) {
  return conductivity * rest_length / (2.0 * std::sqrt(2.0));
}

/// Conductance of a contact circle of radius a (m) between conductivities k1 and k2
/// (W/(m K)), W/K: 4 a / (1/k1 + 1/k2); zero if either is zero (an insulator).
inline double contact_conductance(double radius, double k1, double k2) {
  return k1 > 0.0 && k2 > 0.0 ? 4.0 * radius * k1 * k2 / (k1 + k2) : 0.0;
}

}  // namespace swarf
