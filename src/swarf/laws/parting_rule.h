// parting_rule.h: the geometric separation criterion of a cutting edge (a parting line).
//
// Early finite-element cutting models separated the chip from the workpiece along a line
// given in advance: the nodes on the cutting plane part when the tool's edge comes within a
// critical distance (Strenkowski and Carroll, J. Eng. Ind. 107, 1985; Komvopoulos and
// Erpenbeck, J. Eng. Ind. 113, 1991). In a lattice whose rods fail by strain, the cutting
// plane is a lattice plane, and cracks run along it far ahead of the tool
// (validation/cutting/README.md): the layer slides off as a slab instead of forming a chip. The
// rule here parts, at the commit of a step, the rods that cross the horizontal plane through
// the edge's lowest point once the edge is within 'lead' of them along the cutting direction x,
// so that the chip separates at the edge and must form by plastic flow; the rods elsewhere
// keep their own failure law. It is an assumption about where the material separates, stated
// as such: the forces then measure the chip's formation, not the lattice's cleavage.
#pragma once

#include <cmath>

#include "swarf/core/vec3.h"

namespace swarf {

struct PartingRule {
  /// Distance ahead of the edge (along +x) within which a rod crossing the cutting plane
  /// parts, m. inf (or NaN): no parting line.
  double lead = HUGE_VAL;
  /// How far behind the edge a crossing rod still parts, m (a rod the edge has passed that the
  /// lead did not reach, e.g. at the start).
  double behind = 0.0;

  bool enabled() const { return std::isfinite(lead); }
};

/// True if the rod between xi and xj (m) crosses the horizontal plane through 'edge' (the
/// edge's lowest point, m) and its midpoint lies from 'behind' behind to 'lead' ahead of it.
inline bool parts(const PartingRule& rule, const Vec3& xi, const Vec3& xj, const Vec3& edge) {
  const bool crosses = (xi[2] > edge[2]) != (xj[2] > edge[2]);
  if (!crosses) return false;
  const double ahead = 0.5 * (xi[0] + xj[0]) - edge[0];
  return ahead <= rule.lead && ahead >= -rule.behind;
}

}  // namespace swarf
