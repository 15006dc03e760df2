// bond_formation.h: new rods between unbonded lattice particles pressed together.
//
// A lattice whose rods never change cannot flow: simple shear beyond gamma of about 1 stretches
// rods that carried nothing at small strain and brings unbonded neighbours into contact, so its
// shear stress climbs without bound (validation/material/README.md), where a metal's flow stress
// saturates because atoms change neighbours. The movable cellular automata of Psakhie et al.
// (Theor. Appl. Fract. Mech. 37, 2001) model this by pairs that switch between linked and
// unlinked; here a pair of lattice particles (both built with rods) that is not bonded and is
// pressed together beyond a relative overlap gets a rod, stress-free at the pair's distance
// when the step that pressed it converged. A rod that broke before between the same two
// particles is the one that forms again (each pair has at most one rod).
//
// Forming alone adds rods: a particle that keeps its 12 and gains more hardens the lattice
// without bound. Neighbour exchange keeps the coordination: a particle at 12 gives up its most
// stretched rod for the new one. With it, a DEM simple-shear test flows at a steady stress
// (validation/cutting/README.md); without rod failure by strain it is what lets the lattice flow.
// A negative overlap is a gap: pairs of the contact lists closer than (r_i + r_j)(1 + |overlap|).
//
// The rule is decided at commit, like breakage, so an implicit step's iterations never see it.
// It adds no energy: the new rod is stress-free; the Hertz energy the pair's contact held stays
// in the contacts' ledger (what they took up), as it does when a contact separates. With
// 'lattice_length' (rod.isochoric_plasticity) the new rod takes the lattice's length r_i + r_j
// instead: a pair pressed into contact is closer than the lattice spacing, and a rod born at
// that distance keeps it (each exchange gives up the most stretched rod and takes a pressed one:
// the lattice compacts through its exchanges, validation/cutting/compaction/). It is then born
// pressed, and the caller books its elastic energy.
#pragma once

#include <cmath>

namespace swarf {

struct BondFormation {
  /// Relative overlap (r_i + r_j - d) / (r_i + r_j) beyond which an unbonded pair bonds, 1,
  /// in (-0.2, 1) (below 0: a gap, within the contact skin). inf (or NaN): never, the paper's
  /// lattice, whose rods only break.
  double overlap = HUGE_VAL;
  /// Most intact rods a particle may have for it to form one more: the FCC lattice's 12. More
  /// would stiffen the particle beyond what the stable step was computed for (12 rods).
  int coordination = 12;
  /// Neighbour exchange: a particle at the coordination that is pressed against a new
  /// neighbour gives up its most stretched rod for the new one, so that its coordination stays
  /// while its neighbours change. Off: it forms no rod.
  bool exchange = false;
  /// A new rod's rest length: the lattice's r_i + r_j (true) or the pair's distance (false).
  bool lattice_length = false;

  bool enabled() const { return overlap < 1.0; }
};

/// The rest length of a rod formed between particles of radii ri, rj (m) 'distance' (m) apart.
inline double formed_rest_length(const BondFormation& rule, double distance, double ri, double rj) {
  return rule.lattice_length ? ri + rj : distance;
}

/// True if a particle with 'intact' intact rods may form another.
inline bool may_form(const BondFormation& rule, int intact) { return intact < rule.coordination; }

/// True if two unbonded lattice particles of radii ri, rj (m) whose centres are 'distance' (m)
/// apart form a rod.
inline bool forms_rod(const BondFormation& rule, double distance, double ri, double rj) {
  return rule.enabled() && distance < (ri + rj) * (1.0 - rule.overlap);
}

}  // namespace swarf
