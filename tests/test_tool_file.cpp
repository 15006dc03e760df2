// test_tool_file.cpp: a cutting tool from a file (cut.tool_file, [[mesh]] tool_tip) and its
// measurement (tool_paths/tool_measure.h). The generated tool written to a file measures the
// angles it was made with and, through cut.tool_file, builds the model of the generated tool;
// a file that is not a tool is refused by name with what was measured.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "app/observers/cut_probe.h"
#include "case_errors.h"
#include "io/mesh_file.h"
#include "setup/case_config.h"
#include "setup/model.h"
#include "swarf/core/errors.h"
#include "test_helpers.h"
#include "tool_paths/tool_geometry.h"
#include "tool_paths/tool_measure.h"
#include "tool_spec.h"

namespace swarf {
namespace {

ToolSpec spec(double rake, double clearance, double radius) { return test::tool_spec(rake, clearance, radius); }

const MeshSettings& tool_of(const CaseSettings& cs) {
  for (const auto& m : cs.meshes)
    if (m.tool) return m;
  throw std::runtime_error("no tool");
}

// The (rake, clearance, edge radius) of the tests: negative, zero and positive rake, sharp and honed.
struct Angles {
  double rake, clearance, radius;
};
const Angles kTools[] = {{-5.0, 7.0, 0.0},  {0.0, 3.0, 0.0},   {6.0, 7.0, 0.0},
                         {20.0, 10.0, 0.0}, {-5.0, 7.0, 1e-4}, {6.0, 7.0, 5e-5}};

// The generated tool written as OBJ (exact decimals) and read back: the faces' normals come from
// the same vertices, so the angles agree to rounding (1e-13 deg; 1e-9 asked); a sharp tool's tip
// is its vertex, exactly at the origin, a honed tool's where the faces' planes meet (to rounding
// of the 2 mm faces, 1e-18 m); the honed edge's tangent points are vertices of the arc, so r_n
// comes out to rounding too.
TEST(ToolFile, TheGeneratedToolMeasuresItsOwnAngles) {
  test::TempDir dir("tool_measure");
  for (const Angles& a : kTools) {
    const ToolSpec s = spec(a.rake, a.clearance, a.radius);
    const std::string path = (dir / "tool.obj");
    write_obj(path, make_tool(s));
    const ToolMeasure t = measure_tool(read_mesh(path));
    SCOPED_TRACE(describe(t));
    EXPECT_NEAR(t.rake_angle_deg, a.rake, 1e-9);
    EXPECT_NEAR(t.clearance_angle_deg, a.clearance, 1e-9);
    EXPECT_EQ(t.sharp, a.radius == 0.0);
    EXPECT_NEAR(t.edge_radius, a.radius, 1e-12);
    if (a.radius == 0.0) {
      EXPECT_EQ(t.tip, Vec3(0, 0, 0));
    } else {
      EXPECT_NEAR(t.tip.norm(), 0.0, 1e-15);
    }
    EXPECT_NEAR(t.face_length, s.face_length, 1e-15);
    EXPECT_NEAR(t.flank_length, s.face_length, 1e-15);
    EXPECT_EQ(t.edge_length, s.width);
  }
}

// Binary STL holds floats: each coordinate moves by up to 6e-8 of itself (1.2e-10 m on 2 mm), the
// faces' normals by about as much in radians (3.4e-6 deg), the tip by the rounding of its vertex.
TEST(ToolFile, TheGeneratedToolAsStlMeasuresItsAnglesToFloatRounding) {
  test::TempDir dir("tool_measure_stl");
  for (const Angles& a : kTools) {
    const std::string path = (dir / "tool.stl");
    write_stl(path, make_tool(spec(a.rake, a.clearance, a.radius)));
    const ToolMeasure t = measure_tool(read_mesh(path));
    SCOPED_TRACE(describe(t));
    EXPECT_NEAR(t.rake_angle_deg, a.rake, 2e-5);
    EXPECT_NEAR(t.clearance_angle_deg, a.clearance, 2e-5);
    EXPECT_NEAR(t.edge_radius, a.radius, 1e-9);
    EXPECT_NEAR(t.tip.norm(), 0.0, 1e-9);
  }
  // A CAD file's own origin 0.2 m away: its floats hold 1.5e-8 m there, the faces' normals 1e-5 rad
  // (6e-4 deg), the tip about 1e-8 m.
  const Vec3 far(0.1, 0.05, 0.2);
  for (const Angles& a : kTools) {
    TriangleMesh m = make_tool(spec(a.rake, a.clearance, a.radius));
    for (auto& v : m.vertices) v += far;
    const std::string path = (dir / "far.stl");
    write_stl(path, m);
    const ToolMeasure t = measure_tool(read_mesh(path));
    SCOPED_TRACE(describe(t));
    EXPECT_NEAR(t.rake_angle_deg, a.rake, 2e-3);
    EXPECT_NEAR(t.clearance_angle_deg, a.clearance, 2e-3);
    EXPECT_NEAR((t.tip - far).norm(), 0.0, 1e-7);
    EXPECT_NEAR(t.edge_radius, a.radius, 1e-7);
    EXPECT_NEAR(t.face_length, 2e-3, 1e-7);
  }
}

// A [cut] with the generated tool, and the same [cut] with that tool written out as cut.tool_file:
// the same measured angles and, a sharp tool's tip being its vertex at the origin, the same
// mesh bit for bit (a honed one's to 1e-12 m: its tip is computed). The rake angle the cut's
// analysis takes is the measured one.
std::string cut_text(double rake, double clearance, double radius) {
  return fmt::format(
      "[cut]\nuncut_chip_thickness = 0.1e-3\ncutting_speed = 2.0\nrake_angle = {}\nclearance_angle = {}\n"
      "edge_radius = {}\nmaterial = \"C45\"\nlayers = 4\nlength_of_cut = 0.2e-3\n",
      rake, clearance, radius);
}

TEST(ToolFile, CutToolFileBuildsTheModelOfTheGeneratedTool) {
  test::TempDir dir("tool_file_cut");
  for (const Angles& a : kTools) {
    if (a.radius >= 0.1e-3) continue;  // (the depth of cut here)
    SCOPED_TRACE(fmt::format("rake {} clearance {} radius {}", a.rake, a.clearance, a.radius));
    const CaseSettings gen = parse_case(cut_text(a.rake, a.clearance, a.radius), "generated", {});
    const MeshSettings& g = tool_of(gen);
    ToolSpec s = spec(a.rake, a.clearance, a.radius);
    s.width = g.width, s.face_length = g.face_length;
    write_obj((dir / "tool.obj"), make_tool(s));
    const std::string text = fmt::format(
        "[cut]\nuncut_chip_thickness = 0.1e-3\ncutting_speed = 2.0\ntool_file = \"tool.obj\"\nmaterial = \"C45\"\n"
        "layers = 4\nlength_of_cut = 0.2e-3\n");
    const CaseSettings file = parse_case(text, "from file", {}, dir.str());
    const MeshSettings& f = tool_of(file);
    EXPECT_TRUE(f.tool_from_file);
    EXPECT_NEAR(f.rake_angle, a.rake, 1e-9);
    EXPECT_NEAR(f.clearance_angle, a.clearance, 1e-9);
    EXPECT_NEAR(f.edge_radius, a.radius, 1e-12);
    EXPECT_EQ(f.origin, g.origin);
    EXPECT_NE(file.cut_derived.find("measured: rake"), std::string::npos) << file.cut_derived;
    const Model mg = build_model(gen), mf = build_model(file);
    ASSERT_EQ(mg.meshes.size(), mf.meshes.size());
    const auto &vg = mg.meshes[0].mesh.vertices, &vf = mf.meshes[0].mesh.vertices;
    ASSERT_EQ(vg.size(), vf.size());
    if (a.radius == 0.0) {
      EXPECT_EQ(vg, vf);
    } else {
      for (std::size_t k = 0; k < vg.size(); ++k) EXPECT_NEAR((vg[k] - vf[k]).norm(), 0.0, 1e-12) << k;
    }
    EXPECT_EQ(mg.meshes[0].mesh.triangles, mf.meshes[0].mesh.triangles);
    EXPECT_EQ(mg.particles.position, mf.particles.position);
    // The printed derivation reads back as the same case (the file named relative to it).
    const CaseSettings again = parse_case(file.cut_derived, "printed", {}, dir.str());
    EXPECT_EQ(build_model(again).meshes[0].mesh.vertices, vf);
    // A given angle must agree with the measured one; the file wins otherwise refused.
    EXPECT_EQ(
        parse_case(text, "agreeing", {fmt::format("cut.rake_angle={}", a.rake + 0.4)}, dir.str()).meshes[0].rake_angle,
        f.rake_angle);
  }
}

// A short cut with the file tool writes the generated tool's series byte for byte: the model is
// the same bit for bit (above), the run deterministic.
TEST(ToolFile, AShortCutWithTheFileToolGivesTheGeneratedToolsSeries) {
  test::TempDir dir("tool_file_run");
  const CaseSettings gen = parse_case(cut_text(6.0, 7.0, 0.0), "generated", {});
  ToolSpec s = spec(6.0, 7.0, 0.0);
  s.width = tool_of(gen).width, s.face_length = tool_of(gen).face_length;
  write_obj((dir / "tool.obj"), make_tool(s));
  {
    std::ofstream(dir / "gen.toml") << cut_text(6.0, 7.0, 0.0);
    std::ofstream(dir / "file.toml")
        << "[cut]\nuncut_chip_thickness = 0.1e-3\ncutting_speed = 2.0\ntool_file = \"tool.obj\"\nmaterial = "
           "\"C45\"\nlayers = 4\nlength_of_cut = 0.2e-3\n";
  }
  for (const char* name : {"gen", "file"}) {
    const auto r = test::run_command(fmt::format(
        "timeout 300 {} run {}/{}.toml --out {}/{} --set output.plots=false --set integrator.end_time=2e-5 --threads 1",
        SWARF_BINARY, dir.str(), name, dir.str(), name));
    ASSERT_EQ(r.exit_code, 0) << r.output;
  }
  const auto slurp = [](const std::string& p) {
    std::ifstream in(p, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
  };
  const std::string a = slurp(dir / "gen/series.csv"), b = slurp(dir / "file/series.csv");
  ASSERT_FALSE(a.empty());
  EXPECT_TRUE(a == b) << "the series differ";
}

// The example's insert (scripts/make_example_insert.py: 6 deg, 7 deg, a 20 um hone faceted every
// 2 deg, in mm to 9 digits, 1e-8 mm on its 3 mm coordinates): its angles within 1e-6 deg, its
// edge radius within 1 nm; the cut's analysis (the cut probe's set-up) takes the measured rake
// angle and the placed tip.
TEST(ToolFile, TheExampleInsertMeasuresItsAnglesAndTheCutTakesThem) {
  const CaseSettings cs = load_case(std::string(SWARF_SOURCE_DIR) + "/examples/cut_tool_from_file.toml",
                                    {"cut.layers=4"});
  const MeshSettings& t = tool_of(cs);
  EXPECT_TRUE(t.tool_from_file);
  EXPECT_NEAR(t.rake_angle, 6.0, 1e-6);
  EXPECT_NEAR(t.clearance_angle, 7.0, 1e-6);
  EXPECT_NEAR(t.edge_radius, 20e-6, 1e-9);
  EXPECT_NEAR(t.face_length, 2e-3, 1e-9);
  const Model model = build_model(cs);
  const auto probe = CutProbe::of(model);
  ASSERT_TRUE(probe);
  EXPECT_EQ(probe->setup().rake_angle_deg, t.rake_angle);
  EXPECT_EQ(probe->setup().tool_tip, Vec3(t.tool_tip[0], t.tool_tip[1], t.tool_tip[2]));
  // The placed mesh's lowest point lies on the hone, above the sharp tip by r_n (1 / sin(wedge/2) - 1)
  // along the bisector: between the tip's height and r_n above it.
  double z_low = HUGE_VAL;
  for (const Vec3& v : model.meshes[0].mesh.vertices) z_low = std::min(z_low, v.z());
  EXPECT_GT(z_low, t.tool_tip[2]);
  EXPECT_LT(z_low, t.tool_tip[2] + 20e-6);
}

// Files that are not tools, refused by the key and the file, with what was measured.
TEST(ToolFile, BadToolFilesAreRefusedByName) {
  test::TempDir dir("tool_file_bad");
  const auto write = [&](const std::string& name, const TriangleMesh& m) { write_obj((dir / name), m); };
  TriangleMesh box = make_tool(spec(0.0, 7.0, 0.0));  // a box: the flank flat
  box.vertices.clear();
  for (int k = 0; k < 8; ++k) box.vertices.emplace_back(k & 1 ? 1e-3 : 0.0, k & 2 ? 1e-3 : 0.0, k & 4 ? 1e-3 : 0.0);
  box.triangles = {{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6}, {0, 1, 4}, {1, 5, 4},
                   {2, 6, 3}, {3, 6, 7}, {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}};
  write("box.obj", box);
  TriangleMesh plate;  // one square in x-y: no face along y
  plate.vertices = {{0, 0, 0}, {1e-3, 0, 0}, {1e-3, 1e-3, 0}, {0, 1e-3, 0}};
  plate.triangles = {{0, 1, 2}, {0, 2, 3}};
  write("plate.obj", plate);
  TriangleMesh tilted = plate;  // the plate turned by 45 deg about x: no face along y
  for (auto& v : tilted.vertices) v = Vec3(v.x(), v.y() * std::sqrt(0.5), v.y() * std::sqrt(0.5));
  write("tilted.obj", tilted);
  TriangleMesh mirrored = make_tool(spec(6.0, 7.0, 0.0));  // rake face facing -x
  for (auto& v : mirrored.vertices) v.x() = -v.x();
  for (auto& t : mirrored.triangles) std::swap(t[1], t[2]);
  write("mirrored.obj", mirrored);
  write("steep.obj", make_tool(spec(50.0, 7.0, 0.0)));
  write("narrow.obj", [] {
    ToolSpec s = spec(6.0, 7.0, 0.0);
    s.width = 1e-5;
    return make_tool(s);
  }());
  std::ofstream(dir / "text.stl") << "not a mesh\n";
  const std::string
      base = "[cut]\nuncut_chip_thickness = 0.1e-3\ncutting_speed = 2.0\nmaterial = \"C45\"\nlayers = 4\n";
  const auto error = [&](const std::string& extra) {
    try {
      build_model(parse_case(base + extra, "bad.toml", {}, dir.str()));
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  using test::expect_mentions;
  expect_mentions(error("tool_file = \"box.obj\""), {"cut.tool_file", "box.obj", "clearance 0 deg", "(0, 45)"});
  expect_mentions(error("tool_file = \"plate.obj\""), {"cut.tool_file", "plate.obj", "no cutting edge found"});
  expect_mentions(error("tool_file = \"tilted.obj\""), {"cut.tool_file", "tilted.obj", "no face is parallel to y"});
  expect_mentions(error("tool_file = \"mirrored.obj\""), {"cut.tool_file", "mirrored.obj", "no rake face"});
  expect_mentions(error("tool_file = \"steep.obj\""), {"cut.tool_file", "steep.obj", "rake 50 deg", "(-45, 45)"});
  expect_mentions(error("tool_file = \"narrow.obj\""), {"cut.tool_file", "narrow.obj", "1e-05 m long", "span"});
  expect_mentions(error("tool_file = \"text.stl\""), {"cut.tool_file", "text.stl"});
  expect_mentions(error("tool_file = \"missing.stl\""), {"cut.tool_file", "missing.stl"});
  write("tool.obj", make_tool(spec(6.0, 7.0, 0.0)));
  expect_mentions(error("tool_file = \"tool.obj\"\nrake_angle = 5.0"),
                  {"cut.rake_angle", "5 deg", "tool.obj", "measures 6 deg"});
  expect_mentions(error("tool_file = \"tool.obj\"\nclearance_angle = 8.0"),
                  {"cut.clearance_angle", "8 deg", "measures 7 deg"});
  expect_mentions(error("tool_file = \"tool.obj\"\nedge_radius = 1e-6"), {"cut.edge_radius", "tool_file"});
  expect_mentions(error("rake_angle = 6.0\ntool_scale = 1e-3"), {"cut.tool_scale", "only with tool_file"});
  expect_mentions(error("rake_angle = 6.0\n[[mesh]]\nname = \"tool\"\nfile = \"tool.obj\""),
                  {"mesh.file", "cut.tool_file = \"", "tool.obj"});
  // Without [cut]: a [[mesh]] file with tool_tip is measured the same way.
  expect_mentions(test::case_error("[[mesh]]\nfile = \"" + (dir / "box.obj") + "\"\ntool_tip = [0.0, 0.0, 0.0]\n"),
                  {"mesh.file", "box.obj", "clearance 0 deg"});
  expect_mentions(test::case_error("[[mesh]]\nbox_size = [1.0, 1.0, 1.0]\ntool_tip = [0.0, 0.0, 0.0]\n"),
                  {"mesh.tool_tip", "needs file"});
}

// The command line: a bad tool file stops 'swarf run --check' with exit code 2 and its name.
TEST(ToolFile, CheckRefusesABadToolFileWithExitCode2) {
  test::TempDir dir("tool_file_cli");
  {
    std::ofstream(dir / "plate.obj") << "v 0 0 0\nv 1 0 0\nv 1 1 0\nf 1 2 3\n";
    std::ofstream(dir / "case.toml") << "[cut]\nuncut_chip_thickness = 0.1e-3\ncutting_speed = 2.0\n"
                                        "material = \"C45\"\ntool_file = \"plate.obj\"\n";
  }
  const auto r = test::run_command(fmt::format("{} run {}/case.toml --check", SWARF_BINARY, dir.str()));
  EXPECT_EQ(r.exit_code, 2) << r.output;
  test::expect_mentions(r.output, {"cut.tool_file", "plate.obj"});
}

}  // namespace
}  // namespace swarf
