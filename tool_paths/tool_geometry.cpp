// tool_geometry.cpp: tool profile and extrusion (see tool_geometry.h).
#include "tool_paths/tool_geometry.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "swarf/core/errors.h"

namespace swarf {

std::vector<Eigen::Vector2d> tool_profile(const ToolSpec& s) {
  using V2 = Eigen::Vector2d;
  const double deg = M_PI / 180.0;
  const double a = s.rake_angle_deg * deg, g = s.clearance_angle_deg * deg;
  const double wedge = M_PI / 2 - a - g;
  if (!(s.rake_angle_deg > -60 && s.rake_angle_deg < 60))
    throw InputError(fmt::format("tool: rake angle {} deg must lie in (-60, 60)", s.rake_angle_deg));
  if (!(s.clearance_angle_deg > 0 && s.clearance_angle_deg < 45))
    throw InputError(fmt::format("tool: clearance angle {} deg must lie in (0, 45)", s.clearance_angle_deg));
  if (!(wedge > 5 * deg))
    throw InputError(fmt::format("tool: rake {} deg + clearance {} deg leave a wedge of {:.3g} deg (needs > 5)",
                                 s.rake_angle_deg, s.clearance_angle_deg, wedge / deg));
  if (!(s.face_length > 0) || !std::isfinite(s.face_length))
    throw InputError(fmt::format("tool: face length {} m must be positive", s.face_length));
  if (!(s.edge_radius >= 0) || !std::isfinite(s.edge_radius))
    throw InputError(fmt::format("tool: edge radius {} m must be >= 0", s.edge_radius));
  const V2 dr(-std::sin(a), std::cos(a));  // along the rake face, away from the edge
  const V2 df(-std::cos(g), std::sin(g));  // along the flank face, away from the edge
  std::vector<V2> poly;
  if (s.edge_radius == 0.0) {
    poly.push_back(V2::Zero());
  } else {
    const V2 bis = (dr + df).normalized();  // into the wedge
    const V2 c = s.edge_radius / std::sin(0.5 * wedge) * bis;
    const V2 tf = c.dot(df) * df, tr = c.dot(dr) * dr;  // tangent points
    if (!(c.dot(df) < 0.5 * s.face_length))
      throw InputError(
          fmt::format("tool: edge radius {} m is too large for the face length {} m", s.edge_radius, s.face_length));
    // Arc from the flank tangent point to the rake tangent point, the way that passes the
    // tip (the arc point farthest out along -bis).
    auto wrap = [](double x) { return x - 2 * M_PI * std::floor(x / (2 * M_PI)); };  // into [0, 2 pi)
    const double a0 = std::atan2(tf[1] - c[1], tf[0] - c[0]);
    const double a1 = std::atan2(tr[1] - c[1], tr[0] - c[0]);
    const double amid = std::atan2(-bis[1], -bis[0]);
    const double ccw = wrap(a1 - a0);
    const double turn = wrap(amid - a0) < ccw ? ccw : ccw - 2 * M_PI;
    const int n = std::max(2, static_cast<int>(std::ceil(std::abs(turn) / (s.max_arc_step_deg * deg))));
    for (int k = 0; k <= n; ++k) {
      const double t = a0 + turn * double(k) / n;
      poly.push_back(c + s.edge_radius * V2(std::cos(t), std::sin(t)));
    }
  }
  poly.push_back(s.face_length * dr);
  poly.push_back(s.face_length * df);
  // Counterclockwise in (x, z).
  double area2 = 0;
  for (std::size_t k = 0; k < poly.size(); ++k) {
    const V2& p = poly[k];
    const V2& q = poly[(k + 1) % poly.size()];
    area2 += p[0] * q[1] - p[1] * q[0];
  }
  if (area2 < 0) std::reverse(poly.begin(), poly.end());
  return poly;
}

TriangleMesh make_tool(const ToolSpec& s) {
  if (!(s.width > 0) || !std::isfinite(s.width))
    throw InputError(fmt::format("tool: width {} m must be positive", s.width));
  const auto poly = tool_profile(s);
  const int n = static_cast<int>(poly.size());
  TriangleMesh m;
  m.name = "tool";
  for (int side = 0; side < 2; ++side) {
    const double y = side == 0 ? -0.5 * s.width : 0.5 * s.width;
    for (const auto& p : poly) m.vertices.emplace_back(p[0], y, p[1]);
  }
  // A polygon counterclockwise in (x, z) has the normal x^ x z^ = -y^: the cap at y = -W/2
  // keeps the order (outward -y), the cap at +W/2 reverses it. The profile is convex: fans.
  for (int k = 1; k + 1 < n; ++k) {
    m.triangles.push_back({0, k, k + 1});
    m.triangles.push_back({n, n + k + 1, n + k});
  }
  // Side walls: edge (k, k+1) of the profile swept from -W/2 to +W/2, outward.
  for (int k = 0; k < n; ++k) {
    const int a = k, b = (k + 1) % n;
    m.triangles.push_back({a, n + a, n + b});
    m.triangles.push_back({a, n + b, b});
  }
  if (!(std::abs(s.inclination_angle_deg) < kMaxInclinationDeg))
    throw InputError(fmt::format("tool: inclination angle {} deg must lie in (-{}, {})", s.inclination_angle_deg,
                                 kMaxInclinationDeg, kMaxInclinationDeg));
  if (s.inclination_angle_deg != 0.0) {
    const double l = s.inclination_angle_deg * M_PI / 180.0, c = std::cos(l), sn = std::sin(l);
    for (Vec3& v : m.vertices) v = Vec3(c * v[0] - sn * v[1], sn * v[0] + c * v[1], v[2]);
  }
  m.validate("generated tool");
  return m;
}

}  // namespace swarf
