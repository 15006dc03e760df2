// rods.h: the rods' module of setup: [rod]'s settings, key table, rules and build into the
// World's Rods. The rod laws' own parts are in setup/rod_laws/ (one file each), which this module
// reads through their list. Listed once in each central list: parse_case (case_config.cpp), the
// key rows (case_key_text.cpp), the case echo (app/case_echo.cpp) and build_model (model.cpp).
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "setup/key.h"

namespace swarf {

struct CaseInput;
struct CaseSettings;
struct Derived;
struct Lattice;
struct Rods;

/// [rod]: the rod law (paper eqs. 23-31) between bonded neighbours.
struct RodSettings {
  double youngs_modulus = 200e9;            ///< E of the rod, Pa
  double area = 0.0;                        ///< cross-section A, m^2; 0 = pi R^2
  double yield_strain = kInf;               ///< eps_y = sigma_02/E, 1; inf = elastic
  double hardening_modulus = 0.0;           ///< slope k of the plastic branch, Pa, 0 <= k < E
  double tensile_strength = kInf;           ///< sigma_max, Pa; inf = unbreakable
  double failure_strain = kInf;             ///< rod strain in tension at which a rod breaks, 1; inf = never
  double failure_elongation = kInf;         ///< stretch L - L0 at which a rod breaks, m; inf = never
  std::vector<double> flow_plastic_strain;  ///< hardening curve: plastic strains of its points, 1 (first 0)
  std::vector<double> flow_stress;          ///< flow stress at those points, Pa (first: the yield stress)
  std::string law = "bilinear";             ///< "bilinear" (the paper's) or "johnson_cook" (rate and temperature; alias
                                            ///< "johnson_cook_rate")
  double rate_sensitivity = 0.0;            ///< johnson_cook: C of R = 1 + C ln(max(|rate|/rate_ref, 1)), 1
  double reference_rate = 1.0;              ///< johnson_cook: rate_ref, 1/s (a rod strain rate)
  double thermal_softening_exponent = 1.0;  ///< johnson_cook: m of Theta = 1 - T*^m, 1
  double melt_temperature = kInf;           ///< johnson_cook: T_melt, K; inf = no softening
  double reference_temperature = 293.15;    ///< johnson_cook: T_ref, K
  double damping_ratio = 0.0;  ///< viscous part as a fraction of critical damping of one rod between two particles, 1
  double bond_overlap = kInf;  ///< relative overlap at which unbonded lattice particles form a rod, 1; inf = never
  bool neighbour_exchange = false;    ///< a particle with 12 rods gives up its most stretched one for a new neighbour
  double compaction_modulus = 0.0;    ///< bulk modulus of a neighbourhood compacted beyond the onset, Pa; 0 = off
  double compaction_onset = 0.01;     ///< volumetric strain a neighbourhood may lose before it acts, 1
  bool isochoric_plasticity = false;  ///< each step's plastic increments of a particle's rods lose their mean
                                      ///< (forces/plastic_volume.h)
};

/// [rod]'s keys: the shared ones, then each law's own (rod_laws.h), then the rest, in the docs' order.
const std::vector<Key<RodSettings>>& rod_keys();

/// Reads [rod] (absent: the defaults) and checks its rules, after [material].
void read_rod(const CaseInput& in, CaseSettings& cs);

/// The rods' rules on other tables, once every table is read: bond formation needs [contact].
void check_rods_across_tables(const CaseSettings& cs);

/// The World's rods: the derived law and area, bond formation, and the lattice's rods and rest
/// lengths (moved out of 'lattice'), for 'particles' particles.
void build_rods(const CaseSettings& cs, const Derived& d, Lattice& lattice, std::size_t particles, Rods& rods);

}  // namespace swarf
