// contact_params.h: the parameters of the contact laws (Hertz, damping, friction) and of the
// contact search, derived once from [contact] and the meshes.
//
// Plain data that the World holds (world.h), apart from the contact system that uses them, so
// that the World does not pull in the whole contact machinery for its parameters.
#pragma once

#include "swarf/laws/friction.h"
#include "swarf/laws/speed_friction.h"
#include "swarf/laws/sticking.h"

namespace swarf {

/// Material and law parameters, derived once from [contact] and the meshes.
struct ContactParams {
  double youngs_modulus = 0, poisson_ratio = 0;  ///< particles, Pa and 1
  double alpha = 0;                              ///< damping coefficient from the restitution (hertz.h), 1
  double friction = 0;                           ///< mu, 1
  FrictionLaw law = FrictionLaw::None;
  double regularization_speed = 1e-3;  ///< m/s
  double tangential_damping = 0;       ///< tangential dashpot as a multiple of the normal one, 1
  double skin = 0;                     ///< Verlet skin, m
  StickingRule sticking;               ///< the tool-chip friction's sticking cap (off: shear_strength 0)
  SpeedFriction tool_friction;         ///< the tool contacts' mu against the sliding speed (off: points 0)
};

}  // namespace swarf
