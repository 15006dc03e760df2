// test_tool.cpp: the generated cutting tool: closed and outward oriented, its faces at the
// rake and clearance angles, its edge arc of the given radius and tangent to both faces.
#include <gtest/gtest.h>

#include <cmath>
#include <map>

#include "io/mesh_file.h"
#include "io/vtk_output.h"
#include "setup/case_config.h"
#include "setup/model.h"
#include "swarf/core/errors.h"
#include "test_helpers.h"
#include "tool_paths/tool_geometry.h"
#include "tool_spec.h"

namespace swarf {
namespace {

constexpr double kDeg = M_PI / 180.0;

ToolSpec spec(double rake, double clearance, double radius) { return test::tool_spec(rake, clearance, radius); }

TEST(Tool, MeshIsClosedAndOutwardOriented) {
  for (double r : {0.0, 5e-5}) {
    const TriangleMesh m = make_tool(spec(10, 7, r));
    // Watertight and consistently oriented: every directed edge once, its reverse once.
    std::map<std::pair<int, int>, int> edges;
    for (const auto& t : m.triangles)
      for (int k = 0; k < 3; ++k) ++edges[{t[k], t[(k + 1) % 3]}];
    for (const auto& [e, count] : edges) {
      EXPECT_EQ(count, 1);
      EXPECT_EQ(edges.count({e.second, e.first}), 1u) << "edge " << e.first << "-" << e.second << " is open";
    }
    // Outward normals give a positive volume equal to the profile area times the width.
    double vol = 0;
    for (const auto& t : m.triangles) vol += m.vertices[t[0]].dot(m.vertices[t[1]].cross(m.vertices[t[2]])) / 6.0;
    const auto prof = tool_profile(spec(10, 7, r));
    double area = 0;
    for (std::size_t k = 0; k < prof.size(); ++k) {
      const auto& p = prof[k];
      const auto& q = prof[(k + 1) % prof.size()];
      area += 0.5 * (p[0] * q[1] - p[1] * q[0]);
    }
    EXPECT_GT(area, 0.0);
    EXPECT_NEAR(vol, area * 4e-3, 1e-12 * area * 4e-3) << "radius " << r;
  }
}

// The outward normal of the wall triangles whose normal has the largest +x (rake face) and
// the largest -z (flank face) components.
TEST(Tool, FacesAtTheRakeAndClearanceAngles) {
  for (double rake : {-10.0, 0.0, 15.0})
    for (double clearance : {3.0, 7.0}) {
      const TriangleMesh m = make_tool(spec(rake, clearance, 0.0));
      Vec3 rake_n(0, 0, 0), flank_n(0, 0, 0);
      for (const auto& t : m.triangles) {
        const Vec3 n = (m.vertices[t[1]] - m.vertices[t[0]]).cross(m.vertices[t[2]] - m.vertices[t[0]]).normalized();
        if (std::abs(n[1]) > 0.5) continue;  // a side cap
        if (n[0] > rake_n[0]) rake_n = n;
        if (n[2] < flank_n[2]) flank_n = n;
      }
      // Outward normals: rake face (cos a, 0, sin a); flank face (-sin g, 0, -cos g).
      EXPECT_NEAR(std::atan2(rake_n[2], rake_n[0]) / kDeg, rake, 1e-9);
      EXPECT_NEAR(std::atan2(-flank_n[0], -flank_n[2]) / kDeg, clearance, 1e-9);
    }
}

// An inclined tool (oblique cutting) is the orthogonal one turned about z by lambda: its rake
// face's outward normal is Rz(lambda) (cos a, 0, sin a), its side caps face +-Rz(lambda) y, the
// sharp edge (the vertices at the origin's height) runs along Rz(lambda) y, and its volume is the
// same (a rotation); to rounding (1e-12).
TEST(Tool, InclinationTurnsTheToolAboutTheVertical) {
  for (double lambda : {-30.0, 15.0, 40.0}) {
    ToolSpec s = spec(8, 6, 0.0);
    const TriangleMesh straight = make_tool(s);
    s.inclination_angle_deg = lambda;
    const TriangleMesh m = make_tool(s);
    const double l = lambda * kDeg, a = 8 * kDeg;
    const Vec3 edge(-std::sin(l), std::cos(l), 0.0);
    const Vec3 rake_want(std::cos(a) * std::cos(l), std::cos(a) * std::sin(l), std::sin(a));
    double best = -1;
    int caps = 0;
    Vec3 rake_n = Vec3::Zero();
    for (const auto& t : m.triangles) {
      const Vec3 n = (m.vertices[t[1]] - m.vertices[t[0]]).cross(m.vertices[t[2]] - m.vertices[t[0]]).normalized();
      if (std::abs(std::abs(n.dot(edge)) - 1.0) < 1e-12) {
        ++caps;
        continue;
      }
      if (n.dot(rake_want) > best) best = n.dot(rake_want), rake_n = n;
    }
    EXPECT_EQ(caps, 2 * (static_cast<int>(tool_profile(spec(8, 6, 0.0)).size()) - 2)) << lambda;
    EXPECT_NEAR((rake_n - rake_want).norm(), 0.0, 1e-12) << lambda;
    for (const Vec3& v : m.vertices)
      if (std::abs(v[2]) < 1e-15) EXPECT_NEAR(std::abs(v.normalized().dot(edge)), 1.0, 1e-12) << lambda;
    double v0 = 0, v1 = 0;
    for (const auto& t : straight.triangles)
      v0 += straight.vertices[t[0]].dot(straight.vertices[t[1]].cross(straight.vertices[t[2]])) / 6.0;
    for (const auto& t : m.triangles) v1 += m.vertices[t[0]].dot(m.vertices[t[1]].cross(m.vertices[t[2]])) / 6.0;
    EXPECT_NEAR(v1, v0, 1e-12 * v0) << lambda;
  }
  ToolSpec s = spec(8, 6, 0.0);
  s.inclination_angle_deg = 60.0;
  EXPECT_THROW(make_tool(s), InputError);
}

TEST(Tool, EdgeArcHasTheRadiusAndIsTangent) {
  const double r = 8e-5, rake = 12, clearance = 6;
  const auto prof = tool_profile(spec(rake, clearance, r));
  const double a = rake * kDeg, g = clearance * kDeg, wedge = M_PI / 2 - a - g;
  const Eigen::Vector2d dr(-std::sin(a), std::cos(a)), df(-std::cos(g), std::sin(g));
  const Eigen::Vector2d c = r / std::sin(0.5 * wedge) * (dr + df).normalized();
  int on_arc = 0;
  for (const auto& p : prof)
    if (std::abs((p - c).norm() - r) < 1e-12) ++on_arc;
  // The arc spans 180 deg - wedge in steps of at most 5 deg.
  EXPECT_GE(on_arc, static_cast<int>(std::ceil((M_PI - wedge) / (5 * kDeg)) + 1));
  // Tangency: the centre is r from both face lines.
  EXPECT_NEAR(std::abs(c[0] * dr[1] - c[1] * dr[0]), r, 1e-15);
  EXPECT_NEAR(std::abs(c[0] * df[1] - c[1] * df[0]), r, 1e-15);
  // The arc passes at distance r (1/sin(wedge/2) - 1) from the sharp tip.
  double nearest = 1;
  for (const auto& p : prof) nearest = std::min(nearest, p.norm());
  EXPECT_NEAR(nearest, r * (1 / std::sin(0.5 * wedge) - 1), 1e-3 * r);
}

TEST(Tool, BadSpecsAreRejected) {
  EXPECT_THROW(make_tool(spec(50, 45, 0)), InputError);      // no wedge left
  EXPECT_THROW(make_tool(spec(10, -1, 0)), InputError);      // negative clearance
  EXPECT_THROW(make_tool(spec(10, 7, -1e-5)), InputError);   // negative radius
  EXPECT_THROW(make_tool(spec(10, 7, 1.5e-3)), InputError);  // radius too large for the faces
}

TEST(Tool, CliWritesStlAndVtp) {
  test::TempDir dir("tool");
  const auto r = test::run_command(std::string(SWARF_BINARY) +
                                   " tool --rake-angle 10 --clearance-angle 7 --edge-radius 2e-5 --width 5e-3 "
                                   "--face-length 2e-3 --out " +
                                   (dir / "t.stl") + " --vtp " + (dir / "t.vtp"));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const TriangleMesh m = read_mesh(dir / "t.stl");
  EXPECT_GT(m.triangles.size(), 40u);
  EXPECT_TRUE(std::filesystem::exists(dir / "t.vtp"));
  const auto bad = test::run_command(std::string(SWARF_BINARY) +
                                     " tool --rake-angle 80 --width 5e-3 --face-length 2e-3 --out " + (dir / "x.stl"));
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_NE(bad.output.find("rake"), std::string::npos) << bad.output;
}

}  // namespace
}  // namespace swarf

namespace swarf {
namespace {

TEST(Tool, AsAMeshInACase) {
  const std::string base = R"([workpiece]
cells = [4, 2, 2]
radius = 1e-4
[contact]
[integrator]
end_time = 1e-6
[[mesh]]
name = "tool"
)";
  const Model m = build_model(parse_case(base + "rake_angle = 10.0\nwidth = 1e-3\nface_length = 1e-3\n"
                                                "origin = [-1e-4, 2e-4, 1e-3]\n",
                                         "cut", {}));
  ASSERT_EQ(m.meshes.size(), 1u);
  // The sharp tip sits at the origin given: the lowest vertex of the flank/rake wedge.
  double zmin = 1;
  for (const auto& v : m.meshes[0].mesh.vertices) zmin = std::min(zmin, v[2]);
  EXPECT_NEAR(zmin, 1e-3, 1e-15);
  try {
    build_model(
        parse_case(base + "clearance_angle = 5.0\nedge1 = [1.0, 0.0, 0.0]\nedge2 = [0.0, 1.0, 0.0]\n", "cut", {}));
    ADD_FAILURE() << "a tool key without rake_angle was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("mesh.clearance_angle"), std::string::npos) << e.what();
  }
  try {
    build_model(parse_case(base + "rake_angle = 70.0\nwidth = 1e-3\nface_length = 1e-3\n", "cut", {}));
    ADD_FAILURE() << "an impossible tool was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("tool"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace swarf
