// rigid_body.h: rigid macro particles (paper section 4.4): a closed triangle mesh whose
// translation and rotation are integrated from the contact forces and torques of the particles
// on all its triangles, summed about its centre of mass, plus external loads and gravity.
//
// The state is that of a particle with a full inertia tensor (paper eqs. 2-7): centre of
// mass, velocity and acceleration; orientation q from the body's principal frame to the
// world, angular velocity and acceleration (world frame). The step integrates it with the
// particles' schemes (velocity Verlet; Newmark with the quaternion update of
// laws/rotation.h inside the step's fixed point) and places the mesh from it
// (MeshBody::turn, offset) before each contact evaluation.
//
// Constraints, each optional: translation components held at their initial velocity
// ('fixed'; all three: a fixed point at the centre of mass); rotation free, about a fixed
// axis (a hinge: then only the turn angle about the axis is integrated, with the moment of
// inertia about it), or prescribed (held at its initial angular velocity; zero: it does not
// turn). The hinge's axis passes through the centre of mass, or through a fixed point of the
// world ('pivoted': a pendulum, an eccentric wheel): then the centre of mass turns about the
// axis with the body, the moment of inertia is that about the axis through the pivot
// (parallel axes) and the torque is taken about it; the axle's reaction does no work. External loads: a constant
// force and torque, and dampers linear in the velocity and the angular velocity (the water
// wheel's braking torque -c omega).
#pragma once

#include <cstddef>
#include <cstdint>

#include "swarf/core/quat.h"
#include "swarf/core/vec3.h"

namespace swarf {

/// Free; about a fixed axis through the centre of mass; or at the initial angular velocity.
enum class BodyRotation { Free, Hinge, Prescribed };

/// External loads on a body: F = force - spring .* (x - a(t)) - force_damping (v - holder_velocity),
/// T = torque - torque_damping omega, with the anchor a(t) = anchor + holder_velocity t: a mount
/// on a spring and damper to a holder that moves at a constant velocity (a compliant tool:
/// the holder moves at the cutting speed, the tool lags it by what the forces bend the spring).
struct BodyLoad {
  Vec3 force = Vec3::Zero();            ///< N, world frame
  Vec3 torque = Vec3::Zero();           ///< N m, world frame, about the centre of mass
  double force_damping = 0;             ///< N s/m
  double torque_damping = 0;            ///< N m s/rad
  Vec3 spring = Vec3::Zero();           ///< stiffness along each world axis, N/m
  Vec3 anchor = Vec3::Zero();           ///< the spring's rest position of the centre of mass at t = 0, m
  Vec3 holder_velocity = Vec3::Zero();  ///< m/s
  /// The load's force at the centre of mass at position x, velocity v and time t, N.
  Vec3 force_at(const Vec3& x, const Vec3& v, double t) const {
    return force - spring.cwiseProduct(x - anchor - t * holder_velocity) - force_damping * (v - holder_velocity);
  }
};

/// What one body integrates: the pose and its rates.
struct BodyState {
  Vec3 position = Vec3::Zero();          ///< centre of mass, m
  Vec3 velocity = Vec3::Zero();          ///< m/s
  Vec3 acceleration = Vec3::Zero();      ///< m/s^2
  Quat orientation{1.0, 0.0, 0.0, 0.0};  ///< principal frame -> world
  Vec3 omega = Vec3::Zero();             ///< angular velocity, world frame, rad/s
  Vec3 omega_dot = Vec3::Zero();         ///< angular acceleration, world frame, rad/s^2
  double angle = 0;                      ///< hinge: turn about the axis since the start, rad
};

struct RigidBody {
  std::size_t mesh = 0;                ///< index of its mesh in World::meshes (reference coordinates)
  double mass = 0;                     ///< kg
  Vec3 inertia = Vec3::Zero();         ///< principal moments of inertia about the centre of mass, kg m^2
  Vec3 centre_ref = Vec3::Zero();      ///< centre of mass in the mesh's reference coordinates, m
  Quat principal{1.0, 0.0, 0.0, 0.0};  ///< principal frame -> the mesh's reference frame
  std::uint8_t fixed = 0;              ///< translation components held (bit c: component c)
  BodyRotation rotation = BodyRotation::Free;
  Vec3 axis = Vec3::UnitZ();  ///< hinge axis, world frame, unit
  BodyLoad load;
  BodyState state;
  bool pivoted = false;                  ///< hinge: the axis passes through 'pivot', not the centre of mass
  Vec3 pivot = Vec3::Zero();             ///< a point of the hinge's axis, world frame, m
  Quat hinge_start{1.0, 0.0, 0.0, 0.0};  ///< hinge: the orientation at angle 0 (set by the step)
  Vec3 pivot_arm = Vec3::Zero();         ///< pivoted: centre of mass - pivot at angle 0 (set by the step), m
  // The wrench of the last evaluation, world frame (written by the step).
  Vec3 contact_force = Vec3::Zero();   ///< from the particles, N
  Vec3 contact_torque = Vec3::Zero();  ///< from the particles, about the centre of mass, N m
  Vec3 force = Vec3::Zero();           ///< total: contacts, loads and gravity, N
  Vec3 torque = Vec3::Zero();          ///< total, N m

  /// Moment of inertia about the hinge axis, kg m^2.
  double axis_inertia() const {
    const Vec3 e = to_body(state.orientation, axis);
    return e.dot(inertia.cwiseProduct(e));
  }
  /// Hinge: the angular acceleration about its axis from the latest wrench, rad/s^2. Pivoted:
  /// the torque about the axis through the pivot, over the moment of inertia about it.
  double hinge_acceleration() const {
    if (!pivoted) return torque.dot(axis) / axis_inertia();
    const Vec3 r = state.position - pivot;
    const Vec3 across = r - r.dot(axis) * axis;
    return (torque + r.cross(force)).dot(axis) / (axis_inertia() + mass * across.squaredNorm());
  }
  /// Force the constraints exert on the body, N, from the latest wrench and state: the held
  /// components' (minus the applied force along them: they do not accelerate) or, on a pivoted
  /// hinge, the axle's, m a_c - force with the centre's circular acceleration a_c = omega_dot x r
  /// + omega x (omega x r). Zero for a free centre of mass.
  Vec3 constraint_force() const {
    if (pivoted) {
      const Vec3 r = state.position - pivot;
      return mass * (state.omega_dot.cross(r) + state.omega.cross(state.omega.cross(r))) - force;
    }
    Vec3 f = Vec3::Zero();
    for (int c = 0; c < 3; ++c)
      if (fixed & (1u << c)) f[c] = -force[c];
    return f;
  }
  /// Kinetic energy, J.
  double kinetic_energy() const {
    const Vec3 wb = to_body(state.orientation, state.omega);
    return 0.5 * mass * state.velocity.squaredNorm() + 0.5 * wb.dot(inertia.cwiseProduct(wb));
  }
  /// Angular momentum about its centre of mass, world frame, N m s.
  Vec3 angular_momentum() const {
    const Vec3 wb = to_body(state.orientation, state.omega);
    return to_world(state.orientation, inertia.cwiseProduct(wb));
  }
};

}  // namespace swarf
