// contact_tangent.cpp: the contacts' part of the Newmark step's Jacobian for the Newton solver
// (see contacts.h, tangent(); the rods' part is forces/rod_tangent.h).
//
// For a sphere-sphere contact with unit normal n (i to j), overlap delta and normal force
// fn = K delta^(3/2) + D delta^(1/4) (-vn) (hertz.h), the force on i is -fn n - ft_j. Its
// derivatives with respect to the relative motion of j, with x = ... + beta h^2 a and
// v = ... + gamma h a, give the block S = beta h^2 K + gamma h C:
//   normal:     beta h^2 (3/2 K delta^(1/2)) n n^T + gamma h D delta^(1/4) n n^T
//   tangential: gamma h t (I - n n^T), t from friction_tangent (friction.h)
// so that (J d)_i = m_i d_i - sum over i's contacts of S (d_other - d_i), as for a rod. A
// sphere-triangle contact couples the sphere only to the prescribed mesh: S d_i, weighted by
// the overlap-area fraction as its force is.
//
// Left out, and why: the geometric part -(fn / dist) (I - n n^T) (the normal turning with the
// motion: negative, it would make J indefinite for a pressed pair, and it is delta / (3/2 dist)
// of the normal stiffness, below 1e-2 for the overlaps of a cut); the damping's and the
// weight's dependence on delta (singular as delta -> 0 for the damping); the rotations' part
// (only particles without rods turn, through the step's fixed point on their torques). Newton
// converges with this approximate tangent, at a linear rate where these terms matter, and its
// residual is always the real one, so a converged step is an equilibrium of the real laws.
#include <algorithm>
#include <cmath>

#include "swarf/contacts/contacts.h"
#include "swarf/geometry/overlap_area.h"
#include "swarf/laws/friction.h"
#include "swarf/state/particles.h"

namespace swarf {

void ContactSystem::tangent(const Particles& p, double h, double kx, double kv) {
  const std::size_t np = pairs_.size(), nt = tris_.size();
  ptan_axis_.resize(np);
  ptan_axial_.resize(np);
  ptan_lateral_.resize(np);
  ttan_axis_.resize(nt);
  ttan_axial_.resize(nt);
  ttan_lateral_.resize(nt);
  if (!enabled_) return;
  const FrictionRule rule{prm_.law, prm_.friction, prm_.regularization_speed, h};
  const double eta_ratio = prm_.tangential_damping;
  const Vec3* x = p.position.data();
  const Vec3* v = p.velocity.data();
  const Vec3* w = p.omega.data();
  const double* radius = p.radius.data();
  const double* temperature = p.temperature.empty() ? nullptr : p.temperature.data();
  const Periodic periodic = periodic_;
  const std::vector<MeshBody>& meshes = *meshes_;
#pragma omp parallel
  {
#pragma omp for schedule(static) nowait
    for (std::size_t k = 0; k < np; ++k) {
      ptan_axial_[k] = ptan_lateral_[k] = 0.0;
      ptan_axis_[k] = Vec3::Zero();
      if (!ptouch_[k]) continue;
      const std::int32_t i = pairs_[k].i, j = pairs_[k].j;
      Vec3 d = x[j] - x[i];
      periodic.wrap(d);
      const double ri = radius[i], rj = radius[j], dist = d.norm(), delta = ri + rj - dist;
      if (!(delta > 0.0)) continue;
      const Vec3 n = (1.0 / dist) * d;
      const double root = std::sqrt(delta), root4 = std::sqrt(root);
      const PairConstants& q = uniform_ ? uniform_constants_ : pconst_[k];
      const Vec3 vrel = v[j] + w[j].cross(-rj * n) - v[i] - w[i].cross(ri * n);
      const double vn = vrel.dot(n);
      const double fn = HertzLaw{q.K, q.D}.force(delta, root, root4, -vn);
      if (!(fn > 0.0)) continue;  // (separating faster than the overlap pushes: no force)
      const double normal = kx * 1.5 * q.K * root + kv * q.D * root4;
      const double t = kv *
                       friction_tangent(rule, n, vrel - vn * n, fn, q.kt0 * root, eta_ratio * q.D * root4, phist_[k]);
      ptan_axis_[k] = n;
      ptan_lateral_[k] = t;
      ptan_axial_[k] = normal - t;
    }
#pragma omp for schedule(static)
    for (std::size_t k = 0; k < nt; ++k) {
      ttan_axial_[k] = ttan_lateral_[k] = 0.0;
      ttan_axis_[k] = Vec3::Zero();
      if (!ttouch_[k]) continue;
      const TriPair& q = tris_[k];
      const std::int32_t i = q.i, tri_index = q.tri;
      const MeshBody& mb = meshes[tri_mesh_[tri_index]];
      const auto& tri = mb.mesh.triangles[tri_local_[tri_index]];
      const double R = radius[i];
      const SphereTriangleHit hit = sphere_triangle(x[i], R, mb.mesh.vertices[tri[0]] + mb.offset,
                                                    mb.mesh.vertices[tri[1]] + mb.offset,
                                                    mb.mesh.vertices[tri[2]] + mb.offset, tri_frame_[tri_index]);
      if (!hit.touching) continue;
      const Vec3 n = hit.normal;
      const Vec3 vrel = v[i] + w[i].cross(-R * n) - mb.velocity;
      const double vn = vrel.dot(n);
      const double root = std::sqrt(hit.overlap), root4 = std::sqrt(root);
      const double fn = hit.weight * HertzLaw{q.K, q.D}.force(hit.overlap, root, root4, -vn);
      if (!(fn > 0.0)) continue;
      const double normal = hit.weight * (kx * 1.5 * q.K * root + kv * q.D * root4);
      const Vec3 vt = vrel - vn * n;
      // The cap's fall with the slip (the flow zone, sticking.h) is left out of the tangent, as its
      // turn with the slip's direction is: Newton's residual test corrects an approximate tangent.
      const double slip = prm_.sticking.flow_zone > 0.0 ? vt.norm() : 0.0;
      const double stick = hit.weight * sticking_cap(prm_.sticking, R, temperature ? temperature[i] : 0.0, slip);
      // (the tool's mu at the sliding speed, speed_friction.h; its slope d mu / d v_s is left out
      // like the cap's turn)
      const double t = kv * friction_tangent(at_sliding_speed(rule, prm_.tool_friction, vt), n, vt, fn,
                                             hit.weight * q.kt0 * root, hit.weight * eta_ratio * q.D * root4, q.history,
                                             stick);
      ttan_axis_[k] = n;
      ttan_lateral_[k] = t;
      ttan_axial_[k] = normal - t;
    }
  }
}

ContactSystem::TangentRows ContactSystem::tangent_rows() const {
  return TangentRows{pairs_.data(),        prow_.data(),       jrow_.data(),        jent_.data(),
                     trow_.data(),         ptan_axis_.data(),  ttan_axis_.data(),   ptan_axial_.data(),
                     ptan_lateral_.data(), ttan_axial_.data(), ttan_lateral_.data()};
}

}  // namespace swarf
