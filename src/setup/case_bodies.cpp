// case_bodies.cpp: the tables that repeat or name files: [[group]] with its motion, [[mesh]],
// [[particle]] and [particles] (see case_tables.h). The key tables check each key; the
// rules here check the keys against each other and against the files they name.
#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "io/csv_cell.h"
#include "io/mesh_file.h"
#include "io/path_kind.h"
#include "setup/case_tables.h"
#include "swarf/core/errors.h"
#include "tool_paths/tool_measure.h"

namespace swarf {
namespace {

// dynamics = "rigid_body": its keys only there, and the rules between them.
void check_body(const TableReader& r, const MeshSettings& m, bool open_shape) {
  const bool body = m.dynamics == "rigid_body";
  for (const char* key : {"density", "mass", "centre_of_mass", "inertia", "initial_velocity", "angular_velocity",
                          "rotation", "hinge_axis", "hinge_point", "fixed", "force", "torque", "damping",
                          "torque_damping", "spring_stiffness", "holder_velocity"})
    if (!body && r.has(key)) r.fail(key, r.get(key), "is a rigid body's key: it needs dynamics = \"rigid_body\"");
  if (!body) return;
  const bool given = r.has("inertia");
  if (open_shape && !given)
    r.fail("dynamics", r.get("dynamics"),
           "a rigid body needs a closed mesh: file, box_size or cylinder_radius (a rectangle or a tool is open), "
           "or its mass, centre_of_mass and inertia given");
  if (given) {
    if (m.inertia.size() != 6)
      r.fail("inertia", r.get("inertia"), "give 6 numbers [Ixx, Iyy, Izz, Ixy, Iyz, Ixz] in kg m^2");
    if (!r.has("mass") || r.has("density"))
      r.fail("inertia", r.get("inertia"), "goes with mass (kg), not density: the mesh's volume is not used");
    if (!r.has("centre_of_mass")) r.fail("inertia", r.get("inertia"), "needs centre_of_mass (m) too");
  } else if (r.has("centre_of_mass")) {
    r.fail("centre_of_mass", r.get("centre_of_mass"), "is given with inertia (kg m^2)");
  }
  if (r.has("motion")) r.fail("motion", r.get("motion"), "a rigid body moves by its dynamics, not by a motion");
  if (r.has("density") == r.has("mass")) r.fail("density", r.get("density"), "give density (kg/m^3) or mass (kg)");
  if (r.has("hinge_axis") && m.rotation != "hinge")
    r.fail("hinge_axis", r.get("hinge_axis"), "is used only with rotation = \"hinge\"");
  if (r.has("hinge_point") && m.rotation != "hinge")
    r.fail("hinge_point", r.get("hinge_point"), "is used only with rotation = \"hinge\"");
  if (r.has("hinge_point") && r.has("fixed"))
    r.fail("fixed", r.get("fixed"), "does not apply with hinge_point: the axle is fixed there");
  const auto& e = m.hinge_axis;
  const double e2 = e[0] * e[0] + e[1] * e[1] + e[2] * e[2];
  check_direction(r, "hinge_axis", e);
  if (m.rotation == "hinge") {
    const auto& w = m.angular_velocity;
    const double wx = w[1] * e[2] - w[2] * e[1], wy = w[2] * e[0] - w[0] * e[2], wz = w[0] * e[1] - w[1] * e[0];
    if (!(std::sqrt(wx * wx + wy * wy + wz * wz) <=
          1e-12 * std::sqrt(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]) * std::sqrt(e2)))
      r.fail("angular_velocity", r.get("angular_velocity"), "must lie along hinge_axis with rotation = \"hinge\"");
  }
  for (double k : m.spring_stiffness)
    if (!(k >= 0.0 && std::isfinite(k)))
      r.fail("spring_stiffness", r.get("spring_stiffness"), "each stiffness must be >= 0 and finite (N/m)");
  std::string seen;
  for (char c : m.fixed)
    if ((c != 'x' && c != 'y' && c != 'z') || seen.find(c) != std::string::npos)
      r.fail("fixed", r.get("fixed"), "use the letters x, y and z, each at most once (\"xyz\", \"z\", ...)");
    else
      seen += c;
}

// A [[mesh]] file with tool_tip: a cutting tool, measured now so that the cut's analysis has
// its angles; the tool fields are set from the measurement, its tip placed at tool_tip.
void measure_file_tool(const TableReader& r, MeshSettings& m) {
  const ToolMeasure t = measure_tool_file(r, "file", m.file, m.scale);
  m.tool = true;
  m.tool_from_file = true;
  m.rake_angle = t.rake_angle_deg;
  m.clearance_angle = t.clearance_angle_deg;
  m.edge_radius = t.edge_radius;
  m.face_length = t.face_length;
  m.width = t.edge_length;
  m.origin = m.tool_tip;
  m.file_tip = {t.tip.x(), t.tip.y(), t.tip.z()};
}

void check_mesh(const TableReader& r, const std::string& directory, MeshSettings& m) {
  if (static_cast<double>(m.divisions[0]) * m.divisions[1] > 1e7)
    r.fail("divisions", r.get("divisions"), "must be two positive integers [n1, n2]");
  m.tool = r.has("rake_angle");
  m.hinge_at_point = r.has("hinge_point");
  for (const char* key : {"clearance_angle", "edge_radius", "width", "face_length"})
    if (!m.tool && r.has(key)) r.fail(key, r.get(key), "is a tool key: give rake_angle (deg) to make a tool");
  if (m.tool && (!r.has("width") || !r.has("face_length")))
    r.fail("rake_angle", r.get("rake_angle"), "a tool needs width (m) and face_length (m) too");
  check_motion(r, directory, m.motion);
  const bool rect = r.has("edge1") || r.has("edge2") || r.has("divisions");
  const bool box = r.has("box_size"), cyl = r.has("cylinder_radius");
  for (const char* key : {"cylinder_length", "cylinder_axis", "cylinder_segments"})
    if (!cyl && r.has(key)) r.fail(key, r.get(key), "is a cylinder key: give cylinder_radius (m) to make a cylinder");
  if (cyl && !r.has("cylinder_length"))
    r.fail("cylinder_radius", r.get("cylinder_radius"), "needs cylinder_length (m)");
  if (cyl) check_direction(r, "cylinder_axis", m.cylinder_axis);
  // [cut] makes the mesh named "tool" a generated tool: a [[mesh]] of that name with a file
  // gets its tool keys, and the conflict below would name keys the user never wrote.
  if (!m.file.empty()) {
    std::string from_cut;
    for (const char* key : {"rake_angle", "clearance_angle", "edge_radius", "width", "face_length", "origin"})
      if (r.from_cut(key)) from_cut += fmt::format("{}{} = {}", from_cut.empty() ? "" : ", ", key, r.value_text(key));
    if (!from_cut.empty())
      r.fail("file", r.get("file"),
             fmt::format("[cut] set the keys of its generated tool on this [[mesh]] '{}' ({}), which a mesh file "
                         "cannot take. To cut with a tool from a file, give it as cut.tool_file = \"{}\" (with "
                         "cut.tool_scale for a file not in m): [cut] measures its angles and places it. Name this "
                         "mesh otherwise to have it beside [cut]'s tool",
                         m.name, from_cut, m.file));
  }
  if ((!m.file.empty() ? 1 : 0) + (rect ? 1 : 0) + (m.tool ? 1 : 0) + (box ? 1 : 0) + (cyl ? 1 : 0) > 1)
    r.fail("file",
           r.get("file")         ? r.get("file")
           : r.get("rake_angle") ? r.get("rake_angle")
                                 : r.get("box_size"),
           "give one of: file, a rectangle (edge1, edge2, divisions), a tool (rake_angle, ...), box_size or "
           "cylinder_radius");
  if (m.file.empty() && !m.tool && !box && !cyl && !(r.has("edge1") && r.has("edge2")))
    r.fail("file", nullptr,
           "a mesh needs file = \"...stl|obj\", a rectangle (origin, edge1, edge2 in m), a tool (rake_angle, ...), "
           "box_size or cylinder_radius");
  check_body(r, m, rect || m.tool);
  if (!m.file.empty() && r.has("origin"))
    r.fail("origin", r.get("origin"),
           "places a rectangle or a generated tool; a mesh file is used where its coordinates (times scale) put it, "
           "or, as a cutting tool, with its sharp tip at tool_tip (m)");
  if (r.has("tool_tip") && m.file.empty())
    r.fail("tool_tip", r.get("tool_tip"), "places a cutting tool from a file: it needs file = \"...stl|obj\"");
  if (!m.file.empty()) {
    m.file = resolve(m.file, directory);
    if (const std::string why = file_problem(m.file, "a mesh file"); !why.empty()) r.fail("file", r.get("file"), why);
    if (r.has("tool_tip")) measure_file_tool(r, m);
  } else if (!m.tool && !box && !cyl) {  // a tool's angles and sizes are checked by its generator, which names them
    const auto& e1 = m.edge1;
    const auto& e2 = m.edge2;
    const double cx = e1[1] * e2[2] - e1[2] * e2[1], cy = e1[2] * e2[0] - e1[0] * e2[2],
                 cz = e1[0] * e2[1] - e1[1] * e2[0];
    if (!(cx * cx + cy * cy + cz * cz > 0.0)) r.fail("edge2", r.get("edge2"), "edge1 and edge2 must span a rectangle");
  }
}

}  // namespace

// Names become CSV columns (reaction_<name>_x, force_<name>_x).
void check_name(const TableReader& r, const std::string& name) {
  for (char ch : name)
    if (!(std::isalnum(static_cast<unsigned char>(ch)) || ch == '_' || ch == '-'))
      r.fail("name", r.get("name"), "use letters, digits, '_' and '-' only (it names CSV columns)");
  if (name.empty()) r.fail("name", r.get("name"), "must not be empty");
}

// The entries of an array of tables ([[group]]), or none when the key is absent.
const toml::array* entries(const CaseInput& in, const char* name) {
  const toml::node* n = in.root.get(name);
  if (!n) return nullptr;
  auto arr = n->as_array();
  if (!arr || !arr->is_array_of_tables())
    throw InputError(fmt::format("{}: '{}' must be an array of tables ([[{}]])", in.source, name, name));
  return arr;
}

// A direction (an axis, a normal): only its direction counts, but a length below 1e-6 is a
// zero written otherwise, and a denormal one normalised to inf or NaN (issue 37: an outflow
// normal of length 1e-320 ran and stopped as a blow-up).
void check_direction(const TableReader& r, const char* key, const std::array<double, 3>& v) {
  const double length = std::hypot(v[0], v[1], v[2]);  // (no underflow of the squares)
  if (!(length >= 1e-6))
    r.fail(key, r.get(key),
           fmt::format("must not be zero: a direction's length must be at least 1e-6 (it is {:.4g}; only its "
                       "direction counts)",
                       length));
}

ToolMeasure measure_tool_file(const TableReader& r, const char* key, const std::string& path, double scale) {
  if (const std::string why = file_problem(path, "a mesh file"); !why.empty()) r.fail(key, r.get(key), why);
  TriangleMesh mesh;
  try {
    mesh = read_mesh(path, scale);
  } catch (const InputError& e) {
    r.fail(key, r.get(key), e.what());
  }
  try {
    return measure_tool(mesh);
  } catch (const InputError& e) {
    r.fail(key, r.get(key),
           fmt::format("'{}' is not a cutting tool in swarf's frame (cutting along +x, the edge along y, the rake "
                       "face facing +x): {}",
                       path, e.what()));
  }
}

std::string resolve(const std::string& file, const std::string& directory) {
  std::filesystem::path p(file);
  if (p.is_relative()) p = std::filesystem::path(directory) / p;
  return p.string();
}

void read_meshes(const CaseInput& in, CaseSettings& cs) {
  const toml::array* arr = entries(in, "mesh");
  if (!arr) return;
  std::set<std::string> names;
  for (std::size_t k = 0; k < arr->size(); ++k) {
    TableReader r = in.reader((*arr)[k].as_table(), "mesh");
    MeshSettings m;
    r.read(mesh_keys(), m);
    r.read(motion_keys(), m.motion);
    r.finish();  // (an unknown key, often a misspelt one, is named before the rules between keys)
    if (!r.has("name")) m.name = fmt::format("mesh{}", k);
    check_name(r, m.name);
    if (!names.insert(m.name).second) r.fail("name", r.get("name"), "two meshes have this name");
    check_mesh(r, in.directory, m);
    cs.meshes.push_back(m);
  }
}

}  // namespace swarf
