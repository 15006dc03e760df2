// rods.cpp: the rods' module of setup (see rods.h).
#include "setup/modules/rods.h"

#include <fmt/format.h>

#include <utility>

#include "lattice_gen/fcc_lattice.h"
#include "setup/case_tables.h"
#include "setup/derived.h"
#include "setup/rod_laws/rod_laws.h"
#include "swarf/core/errors.h"
#include "swarf/laws/bond_formation.h"
#include "swarf/state/rods.h"

namespace swarf {

// rod.law's doc line: each law's part after the other (setup/rod_laws/).
std::string_view rod_law_doc() {
  static const std::string doc = [] {
    std::string d = "The rod law.";
    for (const RodLawSetup& law : rod_law_setups()) d += " " + std::string(law.doc);
    return d;
  }();
  return doc;
}

const std::vector<Key<RodSettings>>& rod_keys() {
  using S = RodSettings;
  static const std::vector<Key<S>> head{
      {.name = "youngs_modulus",
       .field = &S::youngs_modulus,
       .unit = "Pa",
       .range = kModulus,
       .rule = "not with `material.youngs_modulus`",
       .doc = "E of the rod."},
      {.name = "area",
       .field = &S::area,
       .unit = "m^2",
       .range = in(0.0, 10.0, "[]", "0 (derived) to 10 m^2"),
       .doc = "Cross-section A. 0 means pi R^2."},
      {.name = "yield_strain",
       .field = &S::yield_strain,
       .unit = "1",
       .range = or_inf(kStrain),
       .rule = "not with `material.youngs_modulus`",
       .doc = "eps_y = sigma_02/E. `inf` means purely elastic."},
      {.name = "hardening_modulus",
       .field = &S::hardening_modulus,
       .unit = "Pa",
       .range = kModulusOrZero,
       .rule = "< `youngs_modulus`; not with `material.youngs_modulus`",
       .doc = "Slope k of the plastic branch."},
      {.name = "tensile_strength",
       .field = &S::tensile_strength,
       .unit = "Pa",
       .range = or_inf(kStress),
       .rule = "not with `material.youngs_modulus`",
       .doc = "sigma_max. `inf` means unbreakable."},
      {.name = "failure_strain",
       .field = &S::failure_strain,
       .unit = "1",
       .range = or_inf(kStrain),
       .rule = "not with `material.youngs_modulus`",
       .doc = "The rod breaks when its strain (L - L0)/L0 exceeds this in tension, whatever its stress: failure by "
              "strain, for a ductile metal whose flow curve may never reach `tensile_strength`. `inf` means "
              "never."},
      {.name = "failure_elongation",
       .field = &S::failure_elongation,
       .unit = "m",
       .range = or_inf(kLength),
       .rule = "not with `failure_strain` (it sets it: failure_elongation / L0); with `[material]` it replaces the "
               "calibrated failure strain",
       .doc = "The rod breaks when it is stretched by this length beyond its rest length in tension. A failure "
              "strain fixed in strain lets every broken rod dissipate its plastic work over a band of broken rods "
              "one or two particles thick, so the work to part the material grows with the particle size; a fixed "
              "elongation keeps that work per unit area of a parted surface the same at every resolution (the crack "
              "band regularisation of FEM, Bazant and Oh 1983). `inf` means never."},
      {.name = "flow_plastic_strain",
       .field = &S::flow_plastic_strain,
       .unit = "1",
       .no_default = true,
       .default_note = "none: the linear law",
       .range = in(0.0, 100.0, "[]", "a plastic strain, 0 to 100"),
       .rule = "2 to 8 increasing values, the first 0; with `flow_stress`; not with `yield_strain`, "
               "`hardening_modulus` or `material.youngs_modulus`",
       .doc = "A piecewise-linear hardening curve in place of the single slope k: the plastic strains of its "
              "points. The rod yields at `flow_stress[0]`; beyond the last point the last slope continues. The "
              "curve is the tension branch of a kinematic law: reversed, the rod yields at the back stress minus "
              "`flow_stress[0]` (the Bauschinger effect, as the linear law), and compression mirrors tension."},
      {.name = "flow_stress",
       .field = &S::flow_stress,
       .unit = "Pa",
       .no_default = true,
       .default_note = "none",
       .range = kStress,
       .rule = "as many as `flow_plastic_strain`, not decreasing; each below E, and rising by at most E times its "
               "plastic strain range",
       .doc = "The flow stress of the rod in tension at the points of `flow_plastic_strain`."},
      {.name = "law", .field = &S::law, .choices = rod_law_names(), .doc = rod_law_doc()},
  };
  // Then each law's own keys (setup/rod_laws/), then the keys every law shares.
  static const std::vector<Key<S>> tail{
      {.name = "damping_ratio",
       .field = &S::damping_ratio,
       .unit = "1",
       .range = in(0, 10, "[]"),
       .doc = "Viscous part, as a fraction zeta of critical damping of one rod between two particles."},
      {.name = "bond_overlap",
       .field = &S::bond_overlap,
       .unit = "1",
       .range = or_inf(in(-0.2, 1.0, "()", "a relative overlap; below 0 a gap; inf: never")),
       .rule = "needs `[contact]`",
       .doc = "Bond formation: two particles of the lattice that are not bonded (their rod broke, or they were "
              "never neighbours) and are pressed together until their relative overlap (r_i + r_j - d)/(r_i + "
              "r_j) exceeds this form a rod, stress-free at their distance, when a step has converged. This is "
              "how the lattice flows: a metal's atoms change neighbours where fixed rods would stretch and "
              "harden without bound (docs/materials.md). `inf` means never, the paper's lattice."},
      {.name = "neighbour_exchange",
       .field = &S::neighbour_exchange,
       .rule = "needs `bond_overlap`",
       .doc = "With bond formation: a particle that already has the lattice's 12 intact rods and is pressed "
              "against a new neighbour gives up its most stretched rod for the new one (no rod stretched: no new "
              "rod). Its coordination stays while its neighbours change, which is how a metal flows; the lattice "
              "then shears at a steady stress instead of hardening without bound or softening into a slip plane "
              "(validation/cutting/README.md). Without it, a particle with 12 rods forms none."},
      {.name = "isochoric_plasticity",
       .field = &S::isochoric_plasticity,
       .rule = "not with `integrator.solver = \"newton\"`; one process (not over MPI ranks)",
       .doc = "The rods' plastic flow keeps the volume, as a metal's does: after the law's return map, each step's "
              "plastic increments of a particle's rods lose their mean (half of each end's), so that pressure "
              "alone yields nothing and a shear flows as before. Without it a lattice of rods yields under a "
              "hydrostatic pressure of about 0.77 times its yield stress and compacts plastically: the plain C45 "
              "chip ends about 1.8 times as dense as the workpiece (docs/physics.md, \"Plastic flow that keeps "
              "the volume\")."},
      {.name = "compaction_modulus",
       .field = &S::compaction_modulus,
       .unit = "Pa",
       .range = kModulusOrZero,
       .rule = "not with `integrator.solver = \"newton\"`; one process (not over MPI ranks)",
       .doc = "Bulk modulus K with which a particle whose neighbourhood has lost more than `compaction_onset` of "
              "its volume pushes back (the material's: C45 about 1.6e11 Pa). The volume change is read from the "
              "distances of all its neighbours within 1.15 (r_i + r_j), bonded or not (the embedded-atom form), so "
              "what the rods lost plastically counts and no rod's breaking, forming or exchange moves it; its energy "
              "1/2 K V min(theta + onset, 0)^2 per particle is elastic. Without it a bonded pair's only resistance "
              "in compression is its rod, which yields, and the cut's chip compacts. With it the lattice must find "
              "new neighbours without compacting: give bond formation a gap (`bond_overlap` < 0, and a "
              "`contact.skin` that reaches it) (docs/physics.md, \"A floor under the volume\"). 0 means off."},
      {.name = "compaction_onset",
       .field = &S::compaction_onset,
       .unit = "1",
       .range = in(0.0, 0.5, "[)", "0 to 0.5"),
       .rule = "with `compaction_modulus`",
       .doc = "The volumetric strain theta_0 a particle's neighbourhood may lose before `compaction_modulus` acts: "
              "below it the lattice's calibrated elastic response is untouched."},
  };
  static const std::vector<Key<S>> keys = [] {
    std::vector<Key<S>> all = head;
    for (const RodLawSetup& law : rod_law_setups()) all.insert(all.end(), law.keys().begin(), law.keys().end());
    all.insert(all.end(), tail.begin(), tail.end());
    return all;
  }();
  return keys;
}

void read_rod(const CaseInput& in, CaseSettings& cs) {
  TableReader r = in.reader(in.table("rod"), "rod");
  auto& d = cs.rod;
  r.know(rod_keys());
  r.finish();  // (an unknown key, often a misspelt one, is named before the rules between keys)
  if (cs.material.macroscopic)
    for (const char* key : {"youngs_modulus", "yield_strain", "hardening_modulus", "tensile_strength", "failure_strain",
                            "flow_plastic_strain", "flow_stress"})
      if (r.has(key))
        r.fail(key, r.get(key), "the rod law comes from the [material] properties here; give one or the other");
  r.read(rod_keys(), d);
  if (!(d.hardening_modulus < d.youngs_modulus))
    r.fail("hardening_modulus", r.get("hardening_modulus"),
           fmt::format("must be below rod.youngs_modulus = {} Pa", d.youngs_modulus));
  // Each law's rules on its keys, whether rod.law names it or not (setup/rod_laws/).
  const RodLawSetup& chosen = rod_law_setup(d.law);
  for (const RodLawSetup& law : rod_law_setups()) law.rules(r, cs, &law == &chosen);
  if (r.has("failure_elongation") && r.has("failure_strain"))
    r.fail(
        "failure_elongation", r.get("failure_elongation"),
        "sets the failure strain (failure_elongation / L0): give one of rod.failure_strain and rod.failure_elongation");
  if (d.neighbour_exchange && !BondFormation{d.bond_overlap}.enabled())
    r.fail("neighbour_exchange", r.get("neighbour_exchange"),
           "exchanges neighbours through bond formation: set bond_overlap");
  if (r.has("compaction_onset") && !(d.compaction_modulus > 0.0))
    r.fail("compaction_onset", r.get("compaction_onset"), "sets where rod.compaction_modulus acts: set it too");
  if (r.has("flow_plastic_strain") || r.has("flow_stress")) {
    for (const char* key : {"yield_strain", "hardening_modulus"})
      if (r.has(key)) r.fail(key, r.get(key), "the hardening curve (flow_plastic_strain, flow_stress) replaces it");
    check_flow_curve(r, "flow_plastic_strain", "flow_stress", d.flow_plastic_strain, d.flow_stress, d.youngs_modulus,
                     "rod.youngs_modulus");
  }
}

void check_rods_across_tables(const CaseSettings& cs) {
  if (BondFormation{cs.rod.bond_overlap}.enabled() && !cs.contact.enabled)
    throw InputError(
        fmt::format("{}: key 'rod.bond_overlap' = {}: bond formation finds the pressed pairs among the "
                    "contacts: add a [contact] table",
                    cs.source, cs.rod.bond_overlap));
  if (cs.rod.compaction_modulus > 0.0 && cs.integrator.solver == "newton")
    throw InputError(
        fmt::format("{}: key 'rod.compaction_modulus' = {}: not with integrator.solver = \"newton\" "
                    "(its tangent has no term for it): use Verlet or the fixed-point Newmark step",
                    cs.source, cs.rod.compaction_modulus));
  // (Newton's tangent has no term for the correction, which couples a rod to its ends' other
  // rods: not built.)
  if (cs.rod.isochoric_plasticity && cs.integrator.solver == "newton")
    throw InputError(
        fmt::format("{}: key 'rod.isochoric_plasticity' = true: not with integrator.solver = \"newton\" "
                    "(its tangent has no term for the correction that couples a rod to its ends' other rods): "
                    "use Verlet or the fixed-point Newmark step",
                    cs.source));
}

void build_rods(const CaseSettings& cs, const Derived& d, Lattice& lat, std::size_t particles, Rods& r) {
  r.law = d.law;
  r.area = d.rod_area;
  r.formation.overlap = cs.rod.bond_overlap;
  r.formation.exchange = cs.rod.neighbour_exchange;
  r.isochoric = r.formation.lattice_length = cs.rod.isochoric_plasticity;
  r.compaction_modulus = cs.rod.compaction_modulus;
  r.compaction_onset = cs.rod.compaction_onset;
  // Moved, not copied: the lattice's arrays are not needed after this, and a copy would hold
  // the largest arrays of the build twice.
  r.ends = std::move(lat.rods);
  r.rest_length = std::move(lat.rest_length);
  r.reset_state();
  r.build_rows(particles);
}

}  // namespace swarf
