// flows.cpp: the particle flows' module of setup (see flows.h).
#include "setup/modules/flows.h"

#include <fmt/format.h>

#include "setup/case_tables.h"
#include "swarf/state/world.h"

namespace swarf {
namespace {

// An inflow's or outflow's box: both corners given, the upper one above the lower.
void check_box(const TableReader& r, const std::array<double, 3>& lo, const std::array<double, 3>& hi) {
  for (const char* key : {"box_min", "box_max"})
    if (!r.has(key)) r.fail(key, nullptr, "is required");
  for (int c = 0; c < 3; ++c)
    if (!(hi[c] >= lo[c])) r.fail("box_max", r.get("box_max"), "must be >= box_min in x, y and z (m)");
}

Vec3 to_vec(const std::array<double, 3>& a) { return Vec3(a[0], a[1], a[2]); }

}  // namespace

const std::vector<Key<InflowSettings>>& inflow_keys() {
  using S = InflowSettings;
  static const std::vector<Key<S>> keys{
      {.name = "box_min",
       .field = &S::box_min,
       .unit = "m",
       .no_default = true,
       .default_note = "required",
       .range = kCoordinate,
       .doc = "Lower corner of the box in which the new particles' centres are drawn (uniformly)."},
      {.name = "box_max",
       .field = &S::box_max,
       .unit = "m",
       .no_default = true,
       .default_note = "required",
       .range = kCoordinate,
       .rule = "> box_min in x, y and z (a box with volume)",
       .doc = "Upper corner of that box."},
      {.name = "rate",
       .field = &S::rate,
       .unit = "1/s",
       .no_default = true,
       .default_note = "required unless mass_rate is given",
       .range = in(0.0, 1e12, "[]", "0 to 1e12 particles per second"),
       .doc = "Particles created per second. Each step owes rate x dt more; the fraction left over carries to "
              "the next step, so created + missed = floor(rate t)."},
      {.name = "mass_rate",
       .field = &S::mass_rate,
       .unit = "kg/s",
       .no_default = true,
       .default_note = "none (give rate)",
       .range = in(0.0, 1e6, "[]", "0 to 1e6 kg/s"),
       .rule = "instead of rate",
       .doc = "Mass created per second instead of a particle rate: rate = mass_rate / the mean mass of a particle, "
              "4/3 pi density E[R^3] with the radii uniform in [radius_min, radius_max] (E[R^3] = (radius_max^4 - "
              "radius_min^4) / (4 (radius_max - radius_min))). Missed particles (inflow_missed) are mass not "
              "delivered."},
      {.name = "radius_min",
       .field = &S::radius_min,
       .unit = "m",
       .no_default = true,
       .default_note = "required",
       .range = kRadius,
       .doc = "Smallest radius; the radii are drawn uniformly in [radius_min, radius_max]. The stable step takes "
              "it into account as it does the smallest initial particle."},
      {.name = "radius_max",
       .field = &S::radius_max,
       .unit = "m",
       .no_default = true,
       .default_note = "radius_min",
       .range = kRadius,
       .rule = ">= radius_min",
       .doc = "Largest radius."},
      {.name = "velocity",
       .field = &S::velocity,
       .unit = "m/s",
       .range = kVelocity,
       .doc = "Velocity of every new particle."},
      {.name = "seed",
       .field = &S::seed,
       .unit = "1",
       .range = in(0, 2147483647, "[]"),
       .doc = "Seed of the placement's random numbers: the same seed, the same particles at the same places, on "
              "any number of threads and across a restart."},
      {.name = "overlap",
       .field = &S::overlap,
       .unit = "1",
       .range = in(0.0, 1.0, "[)"),
       .doc = "Largest relative overlap (r_i + r_j - d) / (r_i + r_j) of a new particle with any particle "
              "(those created in the same step too). 0: never overlapping. Meshes are not checked: keep the box "
              "clear of them."},
      {.name = "attempts",
       .field = &S::attempts,
       .unit = "1",
       .range = in(1, 100000, "[]"),
       .doc = "Places drawn for a due particle before it is counted as missed (`inflow_missed` in series.csv): "
              "a crowded box misses particles instead of overlapping them."},
  };
  return keys;
}

const std::vector<Key<OutflowSettings>>& outflow_keys() {
  using S = OutflowSettings;
  static const std::vector<Key<S>> keys{
      {.name = "box_min",
       .field = &S::box_min,
       .unit = "m",
       .no_default = true,
       .default_note = "required unless a plane is given",
       .range = kCoordinate,
       .doc = "Lower corner of the box; every particle whose centre lies in it after a step is removed, with its "
              "rods and contacts."},
      {.name = "box_max",
       .field = &S::box_max,
       .unit = "m",
       .no_default = true,
       .default_note = "required unless a plane is given",
       .range = kCoordinate,
       .rule = ">= box_min",
       .doc = "Upper corner of the box."},
      {.name = "plane_point",
       .field = &S::plane_point,
       .unit = "m",
       .no_default = true,
       .default_note = "none (a box)",
       .range = kCoordinate,
       .rule = "with plane_normal, instead of box_min and box_max",
       .doc = "A point of a plane: instead of a box, the outflow is the half-space beyond it, and every particle "
              "whose centre has crossed it after a step is removed (a floor or a wall the stream leaves through, "
              "however far it flies)."},
      {.name = "plane_normal",
       .field = &S::plane_normal,
       .unit = "1",
       .no_default = true,
       .default_note = "none (a box)",
       .range = kDirection,
       .rule = "length >= 1e-6; with plane_point",
       .doc = "Direction out of the domain (any length): the particles with (x - plane_point) . plane_normal > 0 "
              "are removed. [0, 0, -1] with a plane_point on the floor takes what falls below it."},
  };
  return keys;
}

void read_flows(const CaseInput& in, CaseSettings& cs) {
  if (const toml::array* arr = entries(in, "inflow"))
    for (std::size_t k = 0; k < arr->size(); ++k) {
      TableReader r = in.reader((*arr)[k].as_table(), "inflow");
      InflowSettings f;
      r.read(inflow_keys(), f);
      r.finish();
      if (!r.has("radius_min")) r.fail("radius_min", nullptr, "is required");
      if (r.has("rate") == r.has("mass_rate"))
        r.fail("rate", r.get("rate"),
               r.has("rate") ? "and mass_rate both given: give one (particles per second, or kg/s)"
                             : "is required (particles per second), or mass_rate (kg/s)");
      if (!r.has("radius_max")) f.radius_max = f.radius_min;
      if (!(f.radius_max >= f.radius_min)) r.fail("radius_max", r.get("radius_max"), "must be >= radius_min (m)");
      check_box(r, f.box_min, f.box_max);
      // (a box of zero volume puts every new particle on a plane or a line, where they overlap
      // as soon as there are a few: the draws miss, silently)
      for (int c = 0; c < 3; ++c)
        if (!(f.box_max[c] > f.box_min[c]))
          r.fail("box_max", r.get("box_max"),
                 fmt::format("must lie above box_min in x, y and z: the box has no volume ({} m across along {})",
                             f.box_max[c] - f.box_min[c], "xyz"[c]));
      cs.inflows.push_back(f);
    }
  if (const toml::array* arr = entries(in, "outflow"))
    for (std::size_t k = 0; k < arr->size(); ++k) {
      TableReader r = in.reader((*arr)[k].as_table(), "outflow");
      OutflowSettings o;
      r.read(outflow_keys(), o);
      r.finish();
      if (r.has("plane_point") || r.has("plane_normal")) {
        for (const char* key : {"box_min", "box_max"})
          if (r.has(key)) r.fail(key, r.get(key), "goes with a box, not with a plane (plane_point, plane_normal)");
        for (const char* key : {"plane_point", "plane_normal"})
          if (!r.has(key)) r.fail(key, nullptr, "is required for a plane");
        check_direction(r, "plane_normal", o.plane_normal);
      } else {
        check_box(r, o.box_min, o.box_max);
      }
      cs.outflows.push_back(o);
    }
}

void build_flows(const CaseSettings& cs, World& world) {
  for (const auto& f : cs.inflows) {
    Inflow in;
    in.box_min = to_vec(f.box_min);
    in.box_max = to_vec(f.box_max);
    in.radius_min = f.radius_min;
    in.radius_max = f.radius_max;
    in.density = cs.material.density;  // (as [[particle]]s: solid spheres of the material)
    in.rate = f.mass_rate > 0.0 ? f.mass_rate / inflow_mean_mass(in) : f.rate;
    in.velocity = to_vec(f.velocity);
    in.seed = static_cast<std::uint64_t>(f.seed);
    in.overlap = f.overlap;
    in.attempts = f.attempts;
    world.inflows.push_back(in);
  }
  for (const auto& o : cs.outflows) {
    Outflow out{to_vec(o.box_min), to_vec(o.box_max)};
    out.plane_point = to_vec(o.plane_point);
    out.plane_normal = to_vec(o.plane_normal).normalized();  // (zero stays zero: a box)
    world.outflows.push_back(out);
  }
}

}  // namespace swarf
