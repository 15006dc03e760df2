// contact_virial.cpp: the contacts' moments for the per-particle stress (see
// ContactSystem::add_virial). Read at output times only; the triangle contacts' normals are
// found again from the geometry, as the evaluation found them, rather than stored per step.
#include "swarf/contacts/contacts.h"
#include "swarf/core/sym_tensor.h"

namespace swarf {

void ContactSystem::add_virial(const Particles& p, std::vector<SymTensor>& w) const {
  if (!enabled_) return;
  for (std::size_t k = 0; k < pairs_.size() && k < pres_.size(); ++k) {
    const Vec3& f = pres_[k].force;  // on i; -f on j
    if (f.isZero(0.0)) continue;
    const std::int32_t i = pairs_[k].i, j = pairs_[k].j;
    Vec3 d = p.position[j] - p.position[i];
    periodic_.wrap(d);
    const double dist = d.norm();
    if (dist <= 0) continue;
    const Vec3 n = d / dist;
    add_moment(w[i], p.radius[i] * n, f);
    add_moment(w[j], -p.radius[j] * n, -f);
  }
  for (std::size_t k = 0; k < tris_.size() && k < tres_.size(); ++k) {
    const Vec3& f = tres_[k].force;
    if (f.isZero(0.0)) continue;
    const TriPair& q = tris_[k];
    const MeshBody& mb = (*meshes_)[tri_mesh_[q.tri]];
    const auto& tri = mb.mesh.triangles[tri_local_[q.tri]];
    const Vec3& c = p.position[q.i];
    const double R = p.radius[q.i];
    const SphereTriangleHit hit = mb.turns
                                      ? sphere_triangle(c, R, mb.placed[tri[0]], mb.placed[tri[1]], mb.placed[tri[2]])
                                      : sphere_triangle(c, R, mb.mesh.vertices[tri[0]] + mb.offset,
                                                        mb.mesh.vertices[tri[1]] + mb.offset,
                                                        mb.mesh.vertices[tri[2]] + mb.offset, tri_frame_[q.tri]);
    add_moment(w[q.i], -p.radius[q.i] * hit.normal, f);
  }
}

}  // namespace swarf
