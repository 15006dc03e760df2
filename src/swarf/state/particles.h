// particles.h: particle state as a structure of arrays.
//
// One array per field, indexed by the particle's position in the arrays (its index); the
// particle's identity is 'id', which stays with it when particles are reordered, removed or
// appended (Simulation::apply_permutation, remove_particles, append_particles: the one door
// that every per-particle array, rod end, group and contact follows). The rod kernel gathers positions and
// velocities of two particles, so each field keeps its three components together (Vec3).
// Components that a grip prescribes are flagged per particle in 'prescribed' (bit c set =
// component c follows the motion of group 'group'); the integrator leaves them alone.
#pragma once

#include <cstdint>
#include <vector>

#include "swarf/core/quat.h"
#include "swarf/core/vec3.h"

namespace swarf {

/// Which optional groups of per-particle arrays a Particles holds. A run whose particles never
/// turn (no contacts, bodies, flows or orientation output) holds no rotation arrays (136 B per
/// particle), one without the accumulated plastic strain none of its arrays (72 B), one without
/// heat no temperature (8 B); the Simulation decides (Simulation::Simulation,
/// PlasticStrainSystem::setup, ThermalSystem::setup). Every Particles that takes another's
/// records (domains/records.h) takes its layout first.
struct ParticleLayout {
  bool rotation = true;        ///< orientation, omega, omega_dot, inertia, inv_inertia, torque
  bool plastic_strain = true;  ///< peeq, peeq_rate, window_normal, window_shear, plastic_work
  bool temperature = true;     ///< temperature
};

struct Particles {
  std::vector<Vec3> position;            ///< m
  std::vector<Vec3> velocity;            ///< m/s
  std::vector<Vec3> acceleration;        ///< m/s^2 (of the last force evaluation)
  std::vector<Vec3> force;               ///< N, total force of the last evaluation
  std::vector<Vec3> initial_position;    ///< m, reference for displacement output
  std::vector<double> mass;              ///< kg
  std::vector<double> inv_mass;          ///< 1/kg
  std::vector<double> radius;            ///< m
  std::vector<std::uint8_t> prescribed;  ///< bitmask of prescribed components (1=x, 2=y, 4=z)
  std::vector<std::int32_t> group;       ///< index of the particle's group, -1 if none
  std::vector<double> temperature;       ///< K; 0 = not given one yet (ThermalSystem sets it); held only with heat
  // Accumulated plastic strain (systems/plastic_strain_system.h): PEEQ, its rate over the last
  // window and the window's sum of the rods' plastic increments, g (x) de_p (g the normal-strain
  // row of the rod's direction: xx, yy, zz parts in 'normal', 2xy, 2yz, 2xz in 'shear').
  // (held only with layout.plastic_strain; otherwise empty)
  std::vector<double> peeq;          ///< equivalent plastic strain, integral of its rate, 1
  std::vector<double> peeq_rate;     ///< equivalent plastic strain rate over the last window, 1/s
  std::vector<Vec3> window_normal;   ///< the window's sum n_a^2 de_p (a = x, y, z), 1
  std::vector<Vec3> window_shear;    ///< the window's sum 2 n_a n_b de_p (xy, yz, xz), 1
  std::vector<double> plastic_work;  ///< accumulated plastic work, half of each of its rods' commits, J
  // Rotation (integrated only when Simulation::rotations() is on: rods act at the centres,
  // so torques come from contacts; the machinery is here for them). Held only with
  // layout.rotation; otherwise empty.
  std::vector<Quat> orientation;    ///< unit quaternion, body to world
  std::vector<Vec3> omega;          ///< world-frame angular velocity, rad/s
  std::vector<Vec3> omega_dot;      ///< world-frame angular acceleration, rad/s^2
  std::vector<Vec3> inertia;        ///< principal moments of inertia, kg m^2 (2/5 m R^2 for a sphere)
  std::vector<double> inv_inertia;  ///< 1/I for isotropic inertia (spheres), 1/(kg m^2); 0 otherwise
  std::vector<Vec3> torque;         ///< world-frame torque of the last evaluation, N m
  std::vector<std::int64_t> id;     ///< stable identity (0, 1, ... in creation order; never reused)
  std::int64_t next_id = 0;         ///< the id the next new particle gets
  ParticleLayout layout;            ///< the optional groups held

  /// Holds the groups 'l' names and frees the others. A group taken up anew gets the values a
  /// new particle gets (resize), except the inertia: that of a solid sphere, 2/5 m R^2, which is
  /// what every particle a layout can drop the rotation of has (setup/model.cpp).
  void set_layout(ParticleLayout l) {
    const std::size_t n = size();
    const ParticleLayout was = layout;
    if (was.rotation && !l.rotation) release(orientation, omega, omega_dot, inertia, inv_inertia, torque);
    if (was.plastic_strain && !l.plastic_strain) release(peeq, peeq_rate, window_normal, window_shear, plastic_work);
    if (was.temperature && !l.temperature) release(temperature);
    layout = l;
    resize(n);
    if (!was.rotation && l.rotation)
      for (std::size_t i = 0; i < n; ++i) set_sphere_inertia(i);
  }

  /// Particle i's inertia as a solid sphere's, 2/5 m R^2, from its mass and radius.
  void set_sphere_inertia(std::size_t i) {
    inertia[i] = Vec3::Constant(0.4 * mass[i] * radius[i] * radius[i]);
    inv_inertia[i] = inertia[i][0] > 0.0 ? 1.0 / inertia[i][0] : 0.0;
  }

  std::size_t size() const { return position.size(); }

  /// Calls f(name, array) for every per-particle array, in one fixed order: what reordering,
  /// removal, appending and the state visit go through, so that a new field is added here once.
  template <class F>
  void for_each_field(F&& f) {
    f("position", position);
    f("velocity", velocity);
    f("acceleration", acceleration);
    f("force", force);
    f("initial_position", initial_position);
    f("mass", mass);
    f("inv_mass", inv_mass);
    f("radius", radius);
    f("prescribed", prescribed);
    f("group", group);
    if (layout.temperature) f("temperature", temperature);
    if (layout.plastic_strain) {
      f("peeq", peeq);
      f("peeq_rate", peeq_rate);
      f("window_normal", window_normal);
      f("window_shear", window_shear);
      f("plastic_work", plastic_work);
    }
    if (layout.rotation) {
      f("orientation", orientation);
      f("omega", omega);
      f("omega_dot", omega_dot);
      f("inertia", inertia);
      f("inv_inertia", inv_inertia);
      f("torque", torque);
    }
    f("id", id);
  }

  /// Resizes every field to n particles (new entries zero, group -1).
  void resize(std::size_t n) {
    position.resize(n, Vec3::Zero());
    velocity.resize(n, Vec3::Zero());
    acceleration.resize(n, Vec3::Zero());
    force.resize(n, Vec3::Zero());
    initial_position.resize(n, Vec3::Zero());
    mass.resize(n, 0.0);
    inv_mass.resize(n, 0.0);
    radius.resize(n, 0.0);
    prescribed.resize(n, 0);
    group.resize(n, -1);
    if (layout.temperature) temperature.resize(n, 0.0);
    if (layout.plastic_strain) {
      peeq.resize(n, 0.0);
      peeq_rate.resize(n, 0.0);
      window_normal.resize(n, Vec3::Zero());
      window_shear.resize(n, Vec3::Zero());
      plastic_work.resize(n, 0.0);
    }
    if (layout.rotation) {
      orientation.resize(n, Quat(1.0, 0.0, 0.0, 0.0));
      omega.resize(n, Vec3::Zero());
      omega_dot.resize(n, Vec3::Zero());
      inertia.resize(n, Vec3::Zero());
      inv_inertia.resize(n, 0.0);
      torque.resize(n, Vec3::Zero());
    }
    if (id.size() < n) id.reserve(n);  // (not one by one: that could leave twice the room)
    while (id.size() < n) id.push_back(next_id++);
    id.resize(n);
  }

 private:
  template <class... V>
  static void release(V&... v) {
    ((v = {}), ...);  // (clear() would keep the memory)
  }
};

}  // namespace swarf
