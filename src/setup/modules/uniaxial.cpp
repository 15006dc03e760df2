// uniaxial.cpp: the uniaxial test's module of setup (see uniaxial.h).
#include "setup/modules/uniaxial.h"

#include <fmt/format.h>

#include <cmath>

#include "setup/case_tables.h"
#include "setup/model.h"
#include "swarf/core/errors.h"

namespace swarf {

const std::vector<Key<UniaxialSettings>>& uniaxial_keys() {
  using S = UniaxialSettings;
  static const std::vector<Key<S>> keys{
      {.name = "axis",
       .field = &S::axis,
       .choices = {"x", "y", "z"},
       .doc = "Bar axis. The grips are the sides `<axis>-` and `<axis>+`."},
      {.name = "grip_layers",
       .field = &S::grip_layers,
       .unit = "1",
       .range = in(1, 1000, "[]"),
       .rule = "the gauge length must stay > h/2",
       .doc = "Lattice layers held by each grip. Selection is the same as for `side`."},
      {.name = "grip_dofs",
       .field = &S::grip_dofs,
       .choices = {"axis", "xyz"},
       .doc = "`\"axis\"`: the grips hold only the axial component, so the bar contracts freely. `\"xyz\"`: "
              "clamped ends."},
      {.name = "strain_path",
       .field = &S::strain_path,
       .unit = "1",
       .default_note = "invalid, so effectively required",
       .range = in(-0.5, 0.5, "()"),
       .rule = "at least 2 entries, first 0, no two consecutive equal",
       .doc = "Turning points of the nominal strain."},
      {.name = "strain_rate",
       .field = &S::strain_rate,
       .unit = "1/s",
       .range = kStrainRate,
       .doc = "Absolute rate of change of the nominal strain."},
  };
  return keys;
}

void read_uniaxial(const CaseInput& in, CaseSettings& cs) {
  const toml::table* t = in.table("uniaxial");
  if (!t) return;
  TableReader r = in.reader(t, "uniaxial");
  auto& u = cs.uniaxial;
  u.enabled = true;
  r.read(uniaxial_keys(), u);
  r.finish();  // (an unknown key, often a misspelt one, is named before the rules between keys)
  if (u.strain_path.size() < 2 || u.strain_path[0] != 0.0)
    r.fail("strain_path", r.get("strain_path"), "needs at least two turning points, the first 0");
  for (double s : u.strain_path)
    if (std::abs(s) >= 0.5) r.fail("strain_path", r.get("strain_path"), "strains must lie in (-0.5, 0.5)");
  for (std::size_t k = 1; k < u.strain_path.size(); ++k)
    if (u.strain_path[k] == u.strain_path[k - 1])
      r.fail("strain_path", r.get("strain_path"), "consecutive turning points must differ");
  for (const auto& g : cs.groups)
    if (g.name == "grip_min" || g.name == "grip_max")
      throw InputError(fmt::format("{}: group name '{}' is reserved for the [uniaxial] grips", in.source, g.name));
}

void build_uniaxial(const CaseSettings& cs, const std::vector<Vec3>& sites, double h, Model& model) {
  const auto& r = model.rods;
  const auto& u = cs.uniaxial;
  auto& info = model.uniaxial;
  info.enabled = true;
  info.axis = u.axis[0] - 'x';
  const int ax = info.axis;
  Vec3 lo = sites[0], hi = sites[0];
  for (const auto& x : sites) {
    lo = lo.cwiseMin(x);
    hi = hi.cwiseMax(x);
  }
  info.gauge_length = (hi[ax] - lo[ax]) - 2.0 * (u.grip_layers - 1) * h;
  if (!(info.gauge_length > 0.5 * h))
    throw InputError(fmt::format("{}: key 'uniaxial.grip_layers' = {}: the grips leave no free bar between them",
                                 cs.source, u.grip_layers));
  info.cross_section = 1.0;
  for (int c = 0; c < 3; ++c)
    if (c != ax) info.cross_section *= (hi[c] - lo[c]) + h;
  // Grip motion: each grip moves half the separation change, along the strain path.
  Motion mmin, mmax;
  mmin.kind = mmax.kind = Motion::Kind::Table;
  double t = 0.0;
  for (std::size_t k = 0; k < u.strain_path.size(); ++k) {
    if (k > 0) t += std::abs(u.strain_path[k] - u.strain_path[k - 1]) / u.strain_rate;
    const double half = 0.5 * u.strain_path[k] * info.gauge_length;
    Vec3 e = Vec3::Zero();
    e[ax] = half;
    mmin.time.push_back(t);
    mmax.time.push_back(t);
    mmin.displacement.push_back(-e);
    mmax.displacement.push_back(e);
  }
  const std::uint8_t dofs = u.grip_dofs == "xyz" ? 7 : static_cast<std::uint8_t>(1u << ax);
  const std::string smin = std::string(1, u.axis[0]) + "-", smax = std::string(1, u.axis[0]) + "+";
  info.grip_min = static_cast<int>(model.groups.size());
  add_group(model, cs.source, "grip_min", select_side(sites, smin, u.grip_layers, h), dofs, mmin);
  info.grip_max = static_cast<int>(model.groups.size());
  add_group(model, cs.source, "grip_max", select_side(sites, smax, u.grip_layers, h), dofs, mmax);
  if (!(model.settings.integrator.end_time > 0.0)) model.settings.integrator.end_time = t;
  const double mid = 0.5 * (lo[ax] + hi[ax]) + 0.25 * h;  // between two layers
  for (std::size_t b = 0; b < r.size(); ++b) {
    const double xi = sites[r.ends[b][0]][ax], xj = sites[r.ends[b][1]][ax];
    if ((xi < mid) != (xj < mid)) info.midplane_rods.emplace_back(static_cast<std::int32_t>(b), xi < mid ? 1 : -1);
  }
}

std::string uniaxial_echo(const Model& m) {
  const Derived& d = m.derived;
  if (!m.uniaxial.enabled) return {};
  return fmt::format(
      "  uniaxial bar: gauge length {:.4g} m, cross-section {:.4g} m^2, predicted yield {:.4g} Pa at strain {:.4g}\n",
      m.uniaxial.gauge_length, m.uniaxial.cross_section, d.bar_yield_stress, d.bar_yield_strain);
}

}  // namespace swarf
