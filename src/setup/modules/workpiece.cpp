// workpiece.cpp: the workpiece's module of setup (see workpiece.h).
#include "setup/modules/workpiece.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "io/path_kind.h"
#include "lattice_gen/fcc_lattice.h"
#include "lattice_gen/lattice_file.h"
#include "setup/case_tables.h"
#include "setup/model.h"

namespace swarf {
namespace {

// Bonds the two y faces across the periodic boundary: the layer at y = 0 and the one at
// y = period - a/2 are nearest neighbours through the periodic image.
void bond_across_periodic_width(const CaseSettings& cs, const FccSpec& spec, Lattice& lat, Periodic& periodic) {
  const double a = lat.cell_edge, L = cs.workpiece.cells[1] * a, d0 = 2.0 * spec.radius;
  periodic = Periodic::along_y(L);
  std::vector<std::int32_t> low, high;
  for (std::size_t i = 0; i < lat.position.size(); ++i) {
    if (lat.position[i][1] < 0.25 * a) low.push_back(static_cast<std::int32_t>(i));
    if (lat.position[i][1] > L - 0.75 * a) high.push_back(static_cast<std::int32_t>(i));
  }
  const double tol = spec.bond_tolerance;
  for (auto i : low)
    for (auto j : high) {
      Vec3 dx = lat.position[j] - lat.position[i];
      periodic.wrap(dx);
      const double len = dx.norm();
      if (len < d0 * (1.0 - tol) || len > d0 * (1.0 + tol)) continue;
      lat.rods.push_back({std::min(i, j), std::max(i, j)});
      lat.rest_length.push_back(len);
    }
  // Keep the rods sorted as the generator gives them (the gather order follows the rods).
  std::vector<std::size_t> order(lat.rods.size());
  for (std::size_t k = 0; k < order.size(); ++k) order[k] = k;
  std::sort(order.begin(), order.end(), [&](std::size_t x, std::size_t y) { return lat.rods[x] < lat.rods[y]; });
  std::vector<std::array<std::int32_t, 2>> sorted(order.size());
  std::vector<double> rest(order.size());
  for (std::size_t k = 0; k < order.size(); ++k) {
    sorted[k] = lat.rods[order[k]];
    rest[k] = lat.rest_length[order[k]];
  }
  lat.rods.swap(sorted);
  lat.rest_length.swap(rest);
}

}  // namespace

const std::vector<Key<WorkpieceSettings>>& workpiece_keys() {
  using S = WorkpieceSettings;
  static const std::vector<Key<S>> keys{
      {.name = "cells",
       .field = &S::cells,
       .unit = "1",
       .no_default = true,
       .range = in(1, 100000, "[]"),
       .rule = "not with `size` or `lattice_file`",
       .doc = "Conventional FCC cells NX, NY, NZ. The lattice has 4 NX NY NZ sites."},
      {.name = "size",
       .field = &S::size,
       .unit = "m",
       .no_default = true,
       .range = kLength,
       .rule = "each > 0; not with `cells` or `lattice_file`",
       .doc = "Box LX, LY, LZ. Every lattice site in the closed box [0, L] is included."},
      {.name = "lattice_file",
       .field = &S::lattice_file,
       .default_note = "generate",
       .rule = "existing file; not with `cells`/`size`",
       .doc = "HDF5 lattice, for example from `swarf lattice` (layout in "
              "[outputs.md](outputs.md#swarf-lattice-hdf5-file))."},
      {.name = "radius",
       .field = &S::radius,
       .unit = "m",
       .range = kRadius,
       .rule = "not with `lattice_file`",
       .doc = "Particle radius R. The nearest-neighbour distance and rod length are 2R."},
      {.name = "bond_tolerance",
       .field = &S::bond_tolerance,
       .unit = "1",
       .range = in(0, 0.2, "[)"),
       .rule = "not with `lattice_file`",
       .doc = "Relative tolerance on the rod length 2R when bonding generated sites."},
      {.name = "periodic_width",
       .field = &S::periodic_width,
       .rule = "only with `cells`, and `cells[1]` >= 2",
       .doc = "Periodic boundaries across the width (y): plane strain, the usual idealisation of orthogonal "
              "cutting. The period is `cells[1]` x a (m); the faces y = 0 and y = period - a/2 are bonded through "
              "the boundary, and rods and contacts take the nearest image along y. Positions are not wrapped (a "
              "particle that drifts across keeps its coordinate; ParaView draws the wrapped rods as lines across "
              "the block). Forces per width are divided by the period. Meshes do not wrap: a tool must span the "
              "period with a margin, as with free side faces. `side = \"y-\"`/`\"y+\"` groups still select the "
              "outer layers."},
      {.name = "lattice_rotation",
       .field = &S::lattice_rotation,
       .unit = "deg",
       .range = in(-90, 90, "[]"),
       .rule = "not with `lattice_file`",
       .doc = "Turns the generated lattice about y by this angle before it is cut to the box (the same box as "
              "unturned: `cells` x a, or `size`): the cube axes then lie at this angle to x and z. In a cut along "
              "x, the unturned lattice has close-packed and cube planes along the cutting plane, and rods that "
              "fail by strain open cracks along them ahead of the tool (validation/cutting/README.md); a turn "
              "moves them off it. y stays a cube axis, so `periodic_width` still fits. The faces are then rough "
              "at the scale of a particle. 0 = cube axes along x, y, z."},
      {.name = "disorder_seed",
       .field = &S::disorder_seed,
       .unit = "1",
       .default_note = "the ordered lattice",
       .range = in(0, 2147483647, "[]"),
       .rule = "> 0 not with `lattice_file`",
       .doc = "Seed of a random jitter of the generated lattice's positions ([disorder](#disorder)); 0 = none, "
              "the ordered lattice bit for bit. The same seed gives the same positions on any thread count; step "
              "it (a study's `seed_key`) to repeat a case with other disorder and measure the run-to-run spread."},
      {.name = "position_jitter",
       .field = &S::position_jitter,
       .unit = "1",
       .default_note = "used when `disorder_seed` > 0",
       .range = in(0, 0.2, "[]",
                   "beyond (sqrt(2) - 1)/2 = 0.207 R a rod could end up longer than an unbonded second neighbour; "
                   "see docs/case-reference.md#disorder"),
       .rule = "> 0 needs `disorder_seed` > 0",
       .doc = "Largest displacement of the jitter, in radii: each site moves by a vector drawn uniformly from the "
              "ball of radius `position_jitter` x R (m). Rods keep the ordered lattice's 12 neighbours and start "
              "at rest. At most 0.2, so every rod stays shorter than every unbonded pair."},
  };
  return keys;
}

void read_workpiece(const CaseInput& in, CaseSettings& cs) {
  const toml::table* t = in.table("workpiece");
  if (!t) return;
  TableReader r = in.reader(t, "workpiece");
  auto& w = cs.workpiece;
  w.enabled = true;
  r.read(workpiece_keys(), w);
  r.finish();  // (an unknown key, often a misspelt one, is named before the rules between keys)
  const bool has_cells = r.has("cells"), has_size = r.has("size");
  if (w.periodic_width && !has_cells)
    r.fail("periodic_width", r.get("periodic_width"),
           "a periodic width needs the lattice generated by cells = [NX, NY, NZ] (the period is NY cells)");
  if (w.periodic_width && has_cells && w.cells[1] < 2)
    r.fail("cells", r.get("cells"), "a periodic width needs at least 2 cells across y (NY >= 2)");
  if (!w.lattice_file.empty() && r.has("lattice_rotation"))
    r.fail("lattice_rotation", r.get("lattice_rotation"),
           "turns a generated lattice; lattice_file's positions are used as they are");
  if (!w.lattice_file.empty() && (r.has("radius") || r.has("bond_tolerance"))) {
    const char* key = r.has("radius") ? "radius" : "bond_tolerance";
    r.fail(key, r.get(key), "radii and rods come from lattice_file; remove this key");
  }
  if (!w.lattice_file.empty() && w.disorder_seed > 0)
    r.fail("disorder_seed", r.get("disorder_seed"),
           "the jitter moves a generated lattice; lattice_file's positions and rest lengths are used as they are");
  if (w.disorder_seed == 0 && w.position_jitter > 0.0 && r.has("position_jitter"))
    r.fail("position_jitter", r.get("position_jitter"),
           "has no effect without workpiece.disorder_seed > 0 (0 = the ordered lattice): give a seed, or set "
           "position_jitter = 0");
  if (!w.lattice_file.empty() && (has_cells || has_size))
    r.fail("lattice_file", r.get("lattice_file"), "give either lattice_file or cells/size, not both");
  if (has_cells && has_size) r.fail("size", r.get("size"), "give either cells or size, not both");
  if (has_size)
    for (double s : w.size)
      if (!(s > 0.0) || !std::isfinite(s)) r.fail("size", r.get("size"), "must be three positive lengths in m");
  if (w.lattice_file.empty() && !has_cells && !has_size)
    r.fail("cells", nullptr, "the workpiece needs cells = [NX, NY, NZ], size = [LX, LY, LZ] (m) or lattice_file");
  if (!w.lattice_file.empty()) {
    w.lattice_file = resolve(w.lattice_file, in.directory);
    if (const std::string why = file_problem(w.lattice_file, "a lattice file"); !why.empty())
      r.fail("lattice_file", r.get("lattice_file"), why);
  }
}

Lattice workpiece_lattice(const CaseSettings& cs, Periodic& periodic) {
  Lattice lat;
  if (!cs.workpiece.enabled) return lat;
  if (!cs.workpiece.lattice_file.empty()) return read_lattice(cs.workpiece.lattice_file);
  FccSpec spec;
  spec.radius = cs.workpiece.radius;
  spec.cells = cs.workpiece.cells;
  spec.size = cs.workpiece.size;
  spec.bond_tolerance = cs.workpiece.bond_tolerance;
  spec.rotation_y = cs.workpiece.lattice_rotation * std::numbers::pi / 180.0;
  lat = generate_fcc(spec);
  if (cs.workpiece.periodic_width) bond_across_periodic_width(cs, spec, lat, periodic);
  return lat;
}

std::string workpiece_echo(const Model& m) {
  const Derived& d = m.derived;
  std::string out;
  if (d.position_jitter > 0.0) {
    const auto [lo, hi] = std::minmax_element(m.rods.rest_length.begin(), m.rods.rest_length.end());
    out += fmt::format("  disorder: seed {}, sites moved uniformly within {:.3g} R = {:.4g} m", d.disorder_seed,
                       d.position_jitter, d.position_jitter * d.radius);
    if (lo != m.rods.rest_length.end())
      out += fmt::format("; rods at rest, {:.6g} to {:.6g} m; stable step for kb_max = {:.4g} N/m", *lo, *hi,
                         d.rod_stiffness_max);
    out += fmt::format("\n");
  } else if (d.disorder_seed > 0) {
    out += fmt::format("  disorder: seed {} with position_jitter = 0: the ordered lattice\n", d.disorder_seed);
  }
  if (m.periodic.on())
    out += fmt::format("  periodic width: period {:.4g} m along y (rods and contacts through the nearest image)\n",
                       m.periodic.period);
  return out;
}

}  // namespace swarf
