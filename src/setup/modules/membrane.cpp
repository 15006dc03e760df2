// membrane.cpp: the membrane's module of setup (see membrane.h).
#include "setup/modules/membrane.h"

#include <fmt/format.h>

#include <cmath>

#include "lattice_gen/membrane_lattice.h"
#include "setup/case_tables.h"
#include "setup/model.h"
#include "swarf/core/errors.h"

namespace swarf {

const std::vector<Key<MembraneSettings>>& membrane_keys() {
  using S = MembraneSettings;
  static const std::vector<Key<S>> keys{
      {.name = "length",
       .field = &S::length,
       .unit = "m",
       .no_default = true,
       .default_note = "required",
       .range = kLength,
       .doc = "Extent of the sheet along x. Every site of the triangular lattice in the closed rectangle is kept."},
      {.name = "width",
       .field = &S::width,
       .unit = "m",
       .no_default = true,
       .default_note = "required",
       .range = kLength,
       .doc = "Extent of the sheet along y (rows of sites along x, sqrt(3) R apart)."},
      {.name = "origin",
       .field = &S::origin,
       .unit = "m",
       .range = kCoordinate,
       .doc = "Corner of the sheet; it lies in the plane z = `origin[2]`."},
      {.name = "radius",
       .field = &S::radius,
       .unit = "m",
       .range = kRadius,
       .doc = "Particle radius R; the sites are 2R apart (neighbours touch), the rods' rest length is "
              "2R / (1 + pre-strain)."},
      {.name = "thickness",
       .field = &S::thickness,
       .unit = "m",
       .no_default = true,
       .default_note = "required",
       .range = kLength,
       .doc = "Thickness t of the sheet: in-plane modulus E_2D = E t, areal density rho t."},
      {.name = "youngs_modulus",
       .field = &S::youngs_modulus,
       .unit = "Pa",
       .no_default = true,
       .default_note = "required",
       .range = kModulus,
       .doc = "Young's modulus E of the sheet's material. The rods get k = sqrt(3)/2 E t (N/m) "
              "([membranes](#membrane-relations))."},
      {.name = "poisson_ratio",
       .field = &S::poisson_ratio,
       .unit = "1",
       .default_note = "1/3",
       .range = in(-1, 0.5, "()"),
       .rule = "1/3 (within 1e-6): any other value is refused",
       .doc = "Only checked: a triangular lattice of central springs has nu = 1/3 in the plane, fixed."},
      {.name = "density",
       .field = &S::density,
       .unit = "kg/m^3",
       .range = kDensity,
       .rule = "not with `areal_density`",
       .doc = "Density rho of the sheet's material: areal density rho t."},
      {.name = "areal_density",
       .field = &S::areal_density,
       .unit = "kg/m^2",
       .no_default = true,
       .default_note = "`density` x `thickness`",
       .range = in(1e-12, 1e6, "[]", "1e-12 to 1e6 kg/m^2: the densities times the lengths, within reason"),
       .rule = "not with `density`",
       .doc = "Mass per area rho_A of the sheet; each particle carries rho_A sqrt(3)/2 (2R)^2 (kg)."},
      {.name = "pre_tension",
       .field = &S::pre_tension,
       .unit = "N/m",
       .range = in(0.0, 1e12, "[]", "0 to 1e12 N/m"),
       .rule = "< 3/4 E t (a rod pre-strain below 1)",
       .doc = "Isotropic in-plane tension T of the sheet as generated: every rod starts stretched by the "
              "pre-strain that carries it. Hold the edges (`clamp_edges`) or the sheet contracts."},
      {.name = "damping_ratio",
       .field = &S::damping_ratio,
       .unit = "1",
       .range = in(0, 1, "[]"),
       .doc = "Rod dashpot as a fraction of critical damping of one rod between two particles (as "
              "`rod.damping_ratio`)."},
      {.name = "clamp_edges",
       .field = &S::clamp_edges,
       .doc = "Holds every edge site (fewer than 6 rods) fixed in x, y and z: a group named `membrane_edges`."},
  };
  return keys;
}

void read_membrane(const CaseInput& in, CaseSettings& cs) {
  const toml::table* t = in.table("membrane");
  if (!t) return;
  TableReader r = in.reader(t, "membrane");
  auto& m = cs.membrane;
  m.enabled = true;
  r.read(membrane_keys(), m);
  r.finish();  // (an unknown key, often a misspelt one, is named before the rules between keys)
  for (const char* key : {"length", "width", "thickness", "youngs_modulus"})
    if (!r.has(key)) r.fail(key, nullptr, "is required (the sheet's extent, thickness and modulus)");
  if (std::abs(m.poisson_ratio - 1.0 / 3.0) > 1e-6)
    r.fail("poisson_ratio", r.get("poisson_ratio"),
           "cannot be represented: a triangular lattice of central springs has nu = 1/3 in the plane, fixed "
           "(give 1/3 or leave the key out)");
  // T = sqrt(3) k eps0 / (1 + eps0) with k = sqrt(3)/2 E t: a rod pre-strain below 1 holds T < 3/4 E t.
  if (!(m.pre_tension < 0.75 * m.youngs_modulus * m.thickness))
    r.fail("pre_tension", r.get("pre_tension"),
           fmt::format("needs a rod pre-strain of 1 or more: must be below 3/4 E t = {:.6g} N/m",
                       0.75 * m.youngs_modulus * m.thickness));
  if (r.has("density") && r.has("areal_density"))
    r.fail("areal_density", r.get("areal_density"), "give either density (kg/m^3, times thickness) or areal_density");
  if (cs.workpiece.enabled)
    throw InputError(fmt::format("{}: a case has either a [workpiece] or a [membrane], not both", in.source));
  if (in.table("rod"))
    throw InputError(
        fmt::format("{}: [rod] does not apply to a [membrane], whose rods follow from its own modulus "
                    "and damping_ratio: remove the table",
                    in.source));
  // [material] then only gives the free particles' density.
  if (const toml::table* mt = in.table("material"))
    for (const auto& [k, v] : *mt)
      if (k.str() != "density")
        throw InputError(
            fmt::format("{}: key 'material.{}' does not apply to a [membrane] (its material is in "
                        "[membrane]; [material] gives only the free particles' density)",
                        in.source, k.str()));
}

// The membrane's sheet of sites (triangular lattice).
Lattice membrane_lattice(const CaseSettings& cs) {
  const MembraneSettings& ms = cs.membrane;
  MembraneSpec spec;
  spec.radius = ms.radius;
  spec.length = ms.length;
  spec.width = ms.width;
  spec.origin = ms.origin;
  spec.pre_strain = membrane_relations_of(cs).pre_strain;
  try {
    return generate_membrane(spec);
  } catch (const InputError& e) {
    throw InputError(fmt::format("{}: {}", cs.source, e.what()));
  }
}

std::string membrane_echo(const Model& m) {
  const Derived& d = m.derived;
  std::string out;
  out += fmt::format(
      "  membrane: E_2D = E t = {:.4g} N/m, nu = 1/3, rho_A = {:.4g} kg/m^2, pre-tension T = {:.4g} N/m (rod "
      "pre-strain {:.4g}); rod k = sqrt(3)/2 E_2D = {:.4g} N/m, damping c = {:.4g} N s/m\n",
      d.membrane_modulus_2d, d.membrane_areal_density, d.membrane_tension, d.membrane_pre_strain, d.rod_stiffness,
      d.rod_damping);
  out += fmt::format(
      "  membrane waves: c_L = {:.4g} m/s, c_S = {:.4g} m/s, c_T = sqrt(T/rho_A) = {:.4g} m/s; CFL step d/c_L = "
      "{:.4g} s, stable step sqrt(4m/(6(k+f/d))) = {:.4g} s\n",
      d.membrane_wave_longitudinal, d.membrane_wave_shear, d.membrane_wave_transverse, d.membrane_dt_cfl,
      2.0 / d.omega_max);
  return out;
}

}  // namespace swarf
