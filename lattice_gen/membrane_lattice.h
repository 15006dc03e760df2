// membrane_lattice.h: a membrane of bonded spheres (paper section 5.3): the sites of a flat
// triangular (hexagonal close-packed) sheet, its nearest-neighbour rods, and the relations
// that turn the sheet's in-plane modulus, Poisson ratio, areal density and pre-tension into
// the rod stiffness, the particle mass, the wave speeds and the stable step.
//
// The sheet lies in the plane z = origin_z: rows along x at spacing d = 2R, row j at
// y = j sqrt(3)/2 d, odd rows shifted by d/2; every site inside the closed rectangle
// [0, length] x [0, width] (from the origin) is kept, and each pair at distance d is bonded
// once by a central spring.
//
// Relations (derived in docs/physics.md, section "Membranes"): a triangular network of central
// springs k between neighbours at distance d is isotropic in the plane with
//     lambda = mu = sqrt(3) k / 4,  E_2D = 2 k / sqrt(3),  nu = 1/3,
// whatever the spacing: a central-force triangular lattice cannot carry another Poisson ratio,
// so any other nu is refused. Each site stands for the area sqrt(3)/2 d^2, so a sheet of areal
// density rho_A gets the particle mass m = rho_A sqrt(3)/2 d^2. A pre-strain eps0 of every
// rod (rest length d / (1 + eps0), rod force f = k d eps0 / (1 + eps0)) gives the isotropic
// tension T = sqrt(3) f / d. Long waves along a rod direction (pre-stress included):
//     c_L^2 = (d^2/m)(9 k/8 + 3 f/(8 d)),  c_S^2 = (d^2/m)(3 k/8 + 9 f/(8 d)),
//     c_T^2 = (3/2) f d / m = T / rho_A     (out of plane).
// The highest in-plane mode (zone edge, M point) has omega^2 = 6 k / m; with the pre-stress,
// omega_max^2 <= 6 (k + f/d) / m (Gershgorin; the out-of-plane bound 12 f/(d m) is below it
// while eps0 < 1). The sheet has no bending stiffness: as the paper's membranes, it carries
// loads by tension (a sheet without pre-tension is floppy out of plane until it stretches).
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "lattice_gen/fcc_lattice.h"

namespace swarf {

struct MembraneSpec {
  double radius = 0.0;                    ///< R, m (site spacing d = 2R)
  double length = 0.0;                    ///< extent along x, m
  double width = 0.0;                     ///< extent along y, m
  std::array<double, 3> origin{0, 0, 0};  ///< corner of the sheet, m
  double pre_strain = 0.0;                ///< eps0 of every rod: rest length d / (1 + eps0), 1
};

/// The sheet's sites (radius R) and rods (rest length d / (1 + eps0)); cell_edge is 0 (no
/// cubic cell). Throws InputError on a bad spec (naming the value).
Lattice generate_membrane(const MembraneSpec& spec);

/// What the relations need: the sheet as a continuum and its discretisation.
struct MembraneMaterial {
  double spacing = 0.0;              ///< d = 2R, m
  double modulus_2d = 0.0;           ///< E_2D = E t, in-plane Young's modulus times thickness, N/m
  double poisson_ratio = 1.0 / 3.0;  ///< only checked: the lattice has 1/3
  double areal_density = 0.0;        ///< rho_A = rho t, kg/m^2
  double pre_tension = 0.0;          ///< isotropic tension T of the sheet as generated, N/m
};

/// The sheet's discrete parameters and the closed forms it is checked against.
struct MembraneRelations {
  double bond_stiffness = 0;     ///< k = sqrt(3)/2 E_2D, N/m
  double site_area = 0;          ///< sqrt(3)/2 d^2, m^2
  double particle_mass = 0;      ///< m = rho_A sqrt(3)/2 d^2, kg
  double pre_strain = 0;         ///< eps0 = s/(1 - s), s = T/(sqrt(3) k), 1
  double bond_force = 0;         ///< f = T d / sqrt(3), N
  double lambda = 0;             ///< in-plane Lame constant sqrt(3) k/4, N/m
  double mu = 0;                 ///< in-plane shear modulus sqrt(3) k/4, N/m
  double wave_longitudinal = 0;  ///< c_L, m/s
  double wave_shear = 0;         ///< c_S, m/s
  double wave_transverse = 0;    ///< c_T = sqrt(T/rho_A), m/s (0 without pre-tension)
  double omega_max = 0;          ///< sqrt(6 (k + f/d) / m), rad/s
  double dt_stable = 0;          ///< 2 / omega_max (undamped explicit limit), s
  double dt_cfl = 0;             ///< d / max(c_L, c_S, c_T): a wave crosses one spacing per step, s
};

/// Throws InputError (naming the quantity) on a non-positive modulus, density or spacing, a
/// Poisson ratio other than 1/3 (beyond 1e-6) or a tension the springs cannot hold.
MembraneRelations membrane_relations(const MembraneMaterial& material);

/// Rows x columns of the sheet membrane_lattice generates for a length x width rectangle at
/// radius R (site spacing 2R, rows sqrt(3) R apart): at least its site count (odd rows may lose
/// their last site), as a double so that a huge sheet is counted before anything is built. The
/// run's memory estimate and the fuzzers' size limit read it; the generator is built on it.
double membrane_site_count(double length, double width, double radius);

/// Indices of the sites with fewer than 6 rods: the sheet's edge.
std::vector<std::int32_t> membrane_edge(const Lattice& lattice);

}  // namespace swarf
