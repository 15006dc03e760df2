// mass_properties.h: volume, centre of mass and inertia of a closed triangle mesh of uniform
// density, by the divergence theorem (Mirtich 1996; Eberly, "Polyhedral Mass Properties
// (Revisited)", 2002): each volume integral of 1, x, x^2, xy is a sum over the triangles of
// closed-form surface integrals, exact for the polyhedron (only rounding). The mesh must be
// closed and oriented outwards (counterclockwise seen from outside); a mesh oriented inwards
// gives a negative volume, which the caller refuses.
#pragma once

#include <Eigen/Core>

#include "swarf/core/quat.h"
#include "swarf/core/vec3.h"
#include "swarf/state/mesh.h"
#include "swarf/state/rigid_body.h"

namespace swarf {

struct MassProperties {
  double volume = 0;                                  ///< m^3 (negative: the triangles face inwards)
  double mass = 0;                                    ///< kg
  Vec3 centre = Vec3::Zero();                         ///< centre of mass, m
  Eigen::Matrix3d inertia = Eigen::Matrix3d::Zero();  ///< inertia tensor about the centre, kg m^2
  Vec3 principal_moments = Vec3::Zero();              ///< eigenvalues of 'inertia', ascending, kg m^2
  Quat principal_axes{1.0, 0.0, 0.0, 0.0};            ///< principal frame -> mesh frame (right-handed)
};

/// The mass properties of the closed mesh 'm' filled with 'density' (kg/m^3).
MassProperties mass_properties(const TriangleMesh& m, double density);

/// A rigid body of mesh 'mesh_index' (its mesh 'm', closed) at 'density' (kg/m^3), at rest
/// where the mesh's reference coordinates put it. Throws InputError (naming the mesh) if the
/// mesh encloses no positive volume (open, or its triangles face inwards).
RigidBody rigid_body_of(std::size_t mesh_index, const TriangleMesh& m, double density);

/// A rigid body of mesh 'mesh_index' with given mass (kg), centre of mass (m) and inertia
/// tensor about it (kg m^2), both in the mesh's reference coordinates, at rest where those put
/// it: for a body whose mass is not spread uniformly in its mesh, or whose mesh is open (a
/// tool's faces). Throws InputError if the mass is not positive or the tensor is not that of
/// a mass distribution (principal moments positive, each at most the sum of the other two).
RigidBody rigid_body_given(std::size_t mesh_index, double mass, const Vec3& centre, const Eigen::Matrix3d& inertia);

/// The principal moments (ascending) and axes of a symmetric inertia tensor.
void principal_frame(const Eigen::Matrix3d& inertia, Vec3& moments, Quat& axes);

}  // namespace swarf
