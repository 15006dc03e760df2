// mass_properties.cpp: Eberly's polyhedral mass properties (see mass_properties.h).
#include "swarf/geometry/mass_properties.h"

#include <fmt/format.h>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>

#include "swarf/core/errors.h"

namespace swarf {

namespace {
// The per-triangle subexpressions of Eberly's algorithm for one coordinate.
void subexpressions(double w0, double w1, double w2, double& f1, double& f2, double& f3, double& g0, double& g1,
                    double& g2) {
  const double t0 = w0 + w1;
  f1 = t0 + w2;
  const double t1 = w0 * w0;
  const double t2 = t1 + w1 * t0;
  f2 = t2 + w2 * f1;
  f3 = w0 * t1 + w1 * t2 + w2 * f2;
  g0 = f2 + w0 * (f1 + w0);
  g1 = f2 + w1 * (f1 + w1);
  g2 = f2 + w2 * (f1 + w2);
}
}  // namespace

void principal_frame(const Eigen::Matrix3d& inertia, Vec3& moments, Quat& axes) {
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es(inertia);
  moments = es.eigenvalues();
  Eigen::Matrix3d V = es.eigenvectors();
  if (V.determinant() < 0.0) V.col(2) = -V.col(2);  // a rotation, not a reflection
  const Eigen::Quaterniond q(V);
  axes = Quat(q.w(), q.x(), q.y(), q.z());
}

MassProperties mass_properties(const TriangleMesh& m, double density) {
  // Integrals about a point inside the mesh's box: coordinates of the size of the mesh, not of
  // its distance from the origin, keep the rounding of the x^2 terms small.
  Vec3 lo = m.vertices.empty() ? Vec3::Zero() : m.vertices[0], hi = lo;
  for (const Vec3& v : m.vertices) {
    lo = lo.cwiseMin(v);
    hi = hi.cwiseMax(v);
  }
  const Vec3 o = 0.5 * (lo + hi);
  double in[10] = {0, 0, 0, 0, 0, 0, 0, 0, 0, 0};  // 1, x, y, z, x^2, y^2, z^2, xy, yz, zx
  for (const auto& t : m.triangles) {
    const Vec3 p0 = m.vertices[t[0]] - o, p1 = m.vertices[t[1]] - o, p2 = m.vertices[t[2]] - o;
    const Vec3 d = (p1 - p0).cross(p2 - p0);
    double f1[3], f2[3], f3[3], g0[3], g1[3], g2[3];
    for (int c = 0; c < 3; ++c) subexpressions(p0[c], p1[c], p2[c], f1[c], f2[c], f3[c], g0[c], g1[c], g2[c]);
    in[0] += d[0] * f1[0];
    for (int c = 0; c < 3; ++c) {
      in[1 + c] += d[c] * f2[c];
      in[4 + c] += d[c] * f3[c];
    }
    in[7] += d[0] * (p0[1] * g0[0] + p1[1] * g1[0] + p2[1] * g2[0]);
    in[8] += d[1] * (p0[2] * g0[1] + p1[2] * g1[1] + p2[2] * g2[1]);
    in[9] += d[2] * (p0[0] * g0[2] + p1[0] * g1[2] + p2[0] * g2[2]);
  }
  const double scale[10] = {1.0 / 6,  1.0 / 24, 1.0 / 24,  1.0 / 24,  1.0 / 60,
                            1.0 / 60, 1.0 / 60, 1.0 / 120, 1.0 / 120, 1.0 / 120};
  for (int k = 0; k < 10; ++k) in[k] *= scale[k] * density;
  MassProperties out;
  out.mass = in[0];
  out.volume = in[0] / density;
  if (!(in[0] != 0.0)) return out;
  const Vec3 c(in[1] / in[0], in[2] / in[0], in[3] / in[0]);  // relative to o
  const double M = in[0];
  Eigen::Matrix3d I;
  I(0, 0) = in[5] + in[6] - M * (c[1] * c[1] + c[2] * c[2]);
  I(1, 1) = in[4] + in[6] - M * (c[2] * c[2] + c[0] * c[0]);
  I(2, 2) = in[4] + in[5] - M * (c[0] * c[0] + c[1] * c[1]);
  I(0, 1) = I(1, 0) = -(in[7] - M * c[0] * c[1]);
  I(1, 2) = I(2, 1) = -(in[8] - M * c[1] * c[2]);
  I(0, 2) = I(2, 0) = -(in[9] - M * c[2] * c[0]);
  out.centre = c + o;
  out.inertia = I;
  principal_frame(I, out.principal_moments, out.principal_axes);
  return out;
}

RigidBody rigid_body_of(std::size_t mesh_index, const TriangleMesh& m, double density) {
  const MassProperties mp = mass_properties(m, density);
  if (!(mp.volume > 0.0) || !(mp.principal_moments.minCoeff() > 0.0))
    throw InputError(
        fmt::format("mesh '{}' encloses a volume of {:.4g} m^3: a rigid body's mesh must be closed "
                    "with its triangles counterclockwise seen from outside",
                    m.name, mp.volume));
  RigidBody rb;
  rb.mesh = mesh_index;
  rb.mass = mp.mass;
  rb.inertia = mp.principal_moments;
  rb.centre_ref = mp.centre;
  rb.principal = mp.principal_axes;
  rb.state.position = mp.centre;
  rb.state.orientation = mp.principal_axes;  // (the mesh as its coordinates place it)
  return rb;
}

RigidBody rigid_body_given(std::size_t mesh_index, double mass, const Vec3& centre, const Eigen::Matrix3d& inertia) {
  if (!(mass > 0.0 && std::isfinite(mass))) throw InputError(fmt::format("mass {} kg must be positive", mass));
  Vec3 moments;
  Quat axes;
  principal_frame(0.5 * (inertia + inertia.transpose()), moments, axes);
  // (I1 + I2 >= I3 for any distribution of mass; equality for a flat one: a relative slack)
  if (!(moments[0] > 0.0) || !(moments[0] + moments[1] >= moments[2] * (1.0 - 1e-12)))
    throw InputError(
        fmt::format("principal moments ({:.6g}, {:.6g}, {:.6g}) kg m^2 are not those of a body: each "
                    "must be positive and at most the sum of the other two",
                    moments[0], moments[1], moments[2]));
  RigidBody rb;
  rb.mesh = mesh_index;
  rb.mass = mass;
  rb.inertia = moments;
  rb.centre_ref = centre;
  rb.principal = axes;
  rb.state.position = centre;
  rb.state.orientation = axes;
  return rb;
}

}  // namespace swarf
