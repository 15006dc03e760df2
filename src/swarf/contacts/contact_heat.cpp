// contact_heat.cpp: the contacts' part of the heat: frictional power and conduction through
// the contact circles (see ContactSystem::heat in contacts.h; laws/heat_conduction.h).
#include <algorithm>
#include <cmath>

#include "swarf/contacts/contacts.h"
#include "swarf/laws/heat_conduction.h"

namespace swarf {

void ContactSystem::heat(const Particles& p, const HeatInput& in, HeatOutput& out) const {
  if (!enabled_) return;
  const std::size_t np = pairs_.size(), nt = tris_.size(), n = p.size();
  if (prow_.size() != n + 1) return;  // (no lists built yet: no contact)
  // Per contact first (each writes its own slots), then per particle in a fixed order.
  std::vector<double> pf(np, 0.0), pg(np, 0.0), tf(nt, 0.0), tg(nt, 0.0);
  const Vec3* x = p.position.data();
  const Vec3* v = p.velocity.data();
  const Vec3* w = p.omega.data();
  const double* radius = p.radius.data();
  const double* T = in.temperature;
  const double k = in.conductivity;
  const std::vector<MeshBody>& meshes = *meshes_;
#pragma omp parallel
  {
#pragma omp for schedule(dynamic, 256) nowait
    for (std::size_t q = 0; q < np; ++q) {
      if (!ptouch_[q]) continue;
      const std::int32_t i = pairs_[q].i, j = pairs_[q].j;
      Vec3 d = x[j] - x[i];
      periodic_.wrap(d);
      const double dist = d.norm(), ri = radius[i], rj = radius[j];
      if (!(dist > 0.0)) continue;
      const Vec3 nrm = (1.0 / dist) * d;
      if (in.friction) {
        // The friction force on j is minus the tangential part of the result on i.
        const Vec3 F = pres_[q].force;
        const Vec3 ft_j = -(F - F.dot(nrm) * nrm);
        const Vec3 vrel = v[j] + w[j].cross(-rj * nrm) - v[i] - w[i].cross(ri * nrm);
        const Vec3 vt = vrel - vrel.dot(nrm) * nrm;
        pf[q] = std::max(0.0, -ft_j.dot(vt));
      }
      const double delta = ri + rj - dist;
      if (T && delta > 0.0) pg[q] = contact_conductance(std::sqrt(ri * rj / (ri + rj) * delta), k, k);
    }
#pragma omp for schedule(dynamic, 16)
    for (std::size_t q = 0; q < nt; ++q) {
      if (!ttouch_[q]) continue;
      const std::int32_t i = tris_[q].i, t = tris_[q].tri;
      const MeshBody& mb = meshes[tri_mesh_[t]];
      const double R = radius[i];
      if (in.friction) {
        // The evaluation that made the force kept where it acts on the wall, x - R n: the
        // normal follows from it, without finding the hit again (this runs every step).
        const Vec3 at = tpoint_[q];
        const Vec3 nrm = (1.0 / R) * (x[i] - at);  // from the wall towards the sphere
        const Vec3 F = tres_[q].force;             // on the sphere: fn n + ft
        const Vec3 ft = F - F.dot(nrm) * nrm;
        const Vec3 vrel = v[i] + w[i].cross(-R * nrm) - mb.velocity_at(at);
        const Vec3 vt = vrel - vrel.dot(nrm) * nrm;
        tf[q] = std::max(0.0, -ft.dot(vt));
      }
      if (T) {  // (the conduction, every 10^4 steps or so: the contact circle of the positions now)
        const SphereTriangleHit hit = triangle_hit(mb, tri_local_[t], tri_frame_[t], x[i], R);
        if (hit.touching) tg[q] = hit.weight * contact_conductance(std::sqrt(R * hit.overlap), k, in.mesh_conductivity);
      }
    }
  }
  const double* Tm = in.mesh_temperature;
  const double to_mesh = in.mesh_share, to_particle = 1.0 - in.mesh_share;  // (0.5 and 0.5 exactly by default)
#pragma omp parallel for schedule(dynamic, 256)
  for (std::size_t i = 0; i < n; ++i) {
    double f = 0.0, flux = 0.0, g = 0.0;
    const double Ti = T ? T[i] : 0.0;
    for (std::int32_t e = jrow_[i]; e < jrow_[i + 1]; ++e) {  // pairs where i is second (pair order)
      const std::int32_t q = jent_[e];
      f += 0.5 * pf[q];
      if (T) {
        flux += pg[q] * (T[pairs_[q].i] - Ti);
        g += pg[q];
      }
    }
    for (std::int32_t q = prow_[i]; q < prow_[i + 1]; ++q) {
      f += 0.5 * pf[q];
      if (T) {
        flux += pg[q] * (T[pairs_[q].j] - Ti);
        g += pg[q];
      }
    }
    for (std::int32_t q = trow_[i]; q < trow_[i + 1]; ++q) {
      f += to_particle * tf[q];
      if (T) {
        flux += tg[q] * (Tm[tri_mesh_[tris_[q].tri]] - Ti);
        g += tg[q];
      }
    }
    out.friction[i] += f;
    if (T) {
      out.flux[i] += flux;
      out.conductance[i] += g;
    }
  }
  if (in.counted) {
    out.mesh_friction_exact.assign(meshes.size(), ExactSum{});
    out.mesh_flux_exact.assign(meshes.size(), ExactSum{});
  }
  for (std::size_t q = 0; q < nt; ++q) {  // (list order: the meshes' sums do not depend on the threads)
    if (!ttouch_[q]) continue;
    const std::int32_t m = tri_mesh_[tris_[q].tri];
    out.mesh_friction[m] += to_mesh * tf[q];
    const bool counted = in.counted && in.counted[tris_[q].i];
    if (counted && in.friction) out.mesh_friction_exact[m].add(in.scale * (to_mesh * tf[q]));
    if (T) {
      out.mesh_flux[m] += tg[q] * (T[tris_[q].i] - Tm[m]);
      out.mesh_conductance[m] += tg[q];
      if (counted) out.mesh_flux_exact[m].add(in.scale * (tg[q] * (T[tris_[q].i] - Tm[m])));
    }
  }
}

}  // namespace swarf
