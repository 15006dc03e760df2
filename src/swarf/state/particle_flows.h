// particle_flows.h: particles created and removed during a run (paper section 5.1's stream of
// particles onto the water wheel): inflow regions that create free spheres at a rate, outflow
// regions that remove whatever enters them. The step applies both after each accepted step,
// through the engine's one door for changing the particles (Simulation::append_particles and
// remove_particles), so rods, groups, contacts and their histories follow.
//
// Creation is serial and drawn from a counter-based generator (splitmix64 of the seed and the
// number of draws so far), so it is the same whatever the thread count and continues
// identically after a restart (the counter and the fractional particle owed are state).
#pragma once

#include <cstdint>
#include <numbers>

#include "swarf/core/vec3.h"

namespace swarf {

/// A box in which free spheres appear at a rate, each at a uniformly drawn centre and radius,
/// moving at a given velocity, placed only where it overlaps no particle by more than
/// 'overlap'; a particle that finds no free place in 'attempts' draws is missed (counted).
struct Inflow {
  Vec3 box_min = Vec3::Zero(), box_max = Vec3::Zero();  ///< m: where the new centres lie
  double rate = 0;                                      ///< particles per second
  double radius_min = 0, radius_max = 0;                ///< m: radii uniform in [min, max]
  double density = 0;                                   ///< kg/m^3 of the solid sphere
  Vec3 velocity = Vec3::Zero();                         ///< m/s
  std::uint64_t seed = 1;                               ///< the generator's seed
  double overlap = 0;  ///< largest (r_i + r_j - d) / (r_i + r_j) allowed with any particle, 1
  int attempts = 20;   ///< draws of a place per particle before it is missed
  // State (checkpointed):
  double owed = 0;           ///< particles due and not yet created (a fraction below 1 between steps)
  std::uint64_t draws = 0;   ///< random numbers drawn so far
  std::int64_t created = 0;  ///< particles created
  std::int64_t missed = 0;   ///< particles due that found no free place
};

/// Whether x lies in the box [lo, hi] (faces included), m.
inline bool in_box(const Vec3& x, const Vec3& lo, const Vec3& hi) {
  return (x.array() >= lo.array()).all() && (x.array() <= hi.array()).all();
}
/// The mean mass of an inflow's particles, kg: 4/3 pi density E[R^3] with R uniform in
/// [radius_min, radius_max], E[R^3] = (b^4 - a^4) / (4 (b - a)) (a^3 when a = b).
inline double inflow_mean_mass(const Inflow& f) {
  const double a = f.radius_min, b = f.radius_max;
  const double r3 = b > a ? (b * b * b * b - a * a * a * a) / (4.0 * (b - a)) : a * a * a;
  return 4.0 / 3.0 * std::numbers::pi * f.density * r3;
}
/// A region whose contents are removed: every particle whose centre lies in it after a step.
/// A box, or (when plane_normal is not zero) the half-space beyond a plane, where
/// (x - plane_point) . plane_normal > 0: a floor or a wall the stream leaves through, however far
/// it flies.
struct Outflow {
  Vec3 box_min = Vec3::Zero(), box_max = Vec3::Zero();  ///< m
  Vec3 plane_point = Vec3::Zero();                      ///< m: a point of the plane
  Vec3 plane_normal = Vec3::Zero();                     ///< 1: points to the side removed (any length)
  std::int64_t removed = 0;                             ///< particles removed (state)
  bool is_plane() const { return plane_normal != Vec3::Zero(); }
  bool contains(const Vec3& x) const {
    return is_plane() ? (x - plane_point).dot(plane_normal) > 0.0 : in_box(x, box_min, box_max);
  }
};

/// The counter-based generator: a uniform number in [0, 1) from (seed, counter).
inline double flow_uniform(std::uint64_t seed, std::uint64_t counter) {
  std::uint64_t z = seed * 0x9e3779b97f4a7c15ull + counter + 0x632be59bd9b4e019ull;
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
  z ^= z >> 31;
  return double(z >> 11) * 0x1.0p-53;
}

}  // namespace swarf
