// meshes.cpp: the meshes' module of setup (see meshes.h).
#include "setup/modules/meshes.h"

#include <fmt/format.h>

#include <cmath>
#include <set>

#include "io/mesh_file.h"
#include "io/path_kind.h"
#include "setup/case_tables.h"
#include "setup/model.h"
#include "swarf/core/errors.h"
#include "swarf/geometry/mass_properties.h"
#include "swarf/geometry/shapes.h"
#include "tool_paths/tool_geometry.h"
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
  for (const char* key : {"clearance_angle", "edge_radius", "width", "face_length", "inclination_angle"})
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

TriangleMesh rectangle_mesh(const MeshSettings& ms) {
  TriangleMesh m;
  m.name = ms.name;
  const Vec3 o(ms.origin[0], ms.origin[1], ms.origin[2]), e1(ms.edge1[0], ms.edge1[1], ms.edge1[2]),
      e2(ms.edge2[0], ms.edge2[1], ms.edge2[2]);
  const int n1 = ms.divisions[0], n2 = ms.divisions[1];
  for (int b = 0; b <= n2; ++b)
    for (int a = 0; a <= n1; ++a) m.vertices.push_back(o + (double(a) / n1) * e1 + (double(b) / n2) * e2);
  auto id = [&](int a, int b) { return b * (n1 + 1) + a; };
  for (int b = 0; b < n2; ++b)
    for (int a = 0; a < n1; ++a) {
      m.triangles.push_back({id(a, b), id(a + 1, b), id(a + 1, b + 1)});
      m.triangles.push_back({id(a, b), id(a + 1, b + 1), id(a, b + 1)});
    }
  return m;
}

Vec3 to_vec(const std::array<double, 3>& a) { return Vec3(a[0], a[1], a[2]); }

// The mass properties of a [[mesh]] with dynamics = "rigid_body" from its closed mesh, filled
// uniformly at 'density' or so that it has 'mass'.
RigidBody rigid_body_from_mesh(const CaseSettings& cs, const MeshSettings& ms, std::size_t index,
                               const TriangleMesh& mesh) {
  const auto where = [&] { return fmt::format("{}: [[mesh]] '{}'", cs.source, ms.name); };
  double density = ms.density;
  if (!(density > 0.0)) {  // from 'mass'
    const double volume = mass_properties(mesh, 1.0).volume;
    if (!(volume > 0.0))
      throw InputError(
          fmt::format("{}: mass = {} kg: the mesh encloses no positive volume ({:.4g} m^3); it must be "
                      "closed with its triangles counterclockwise seen from outside",
                      where(), ms.mass, volume));
    density = ms.mass / volume;
  }
  try {
    return rigid_body_of(index, mesh, density);
  } catch (const InputError& e) {
    throw InputError(fmt::format("{}: {}", where(), e.what()));
  }
}

// A [[mesh]] with dynamics = "rigid_body": mass properties given or from its closed mesh, then
// the keys' initial state, constraints and loads.
RigidBody rigid_body(const CaseSettings& cs, const Derived& d, const MeshSettings& ms, std::size_t index,
                     const TriangleMesh& mesh) {
  const auto where = [&] { return fmt::format("{}: [[mesh]] '{}'", cs.source, ms.name); };
  RigidBody rb;
  if (!ms.inertia.empty()) {  // given: the mesh only carries the contacts
    const auto& t = ms.inertia;
    Eigen::Matrix3d I;
    I << t[0], t[3], t[5], t[3], t[1], t[4], t[5], t[4], t[2];
    try {
      rb = rigid_body_given(index, ms.mass, to_vec(ms.centre_of_mass), I);
    } catch (const InputError& e) {
      throw InputError(fmt::format("{}: key 'inertia': {}", where(), e.what()));
    }
  } else {
    rb = rigid_body_from_mesh(cs, ms, index, mesh);
  }
  // Inertia and mass consistent (issue 37): each principal moment's radius of gyration
  // sqrt(I / m) a physical length, 1 nm to 1 km as any length of a case. A moment of 1e-300
  // kg m^2 with a mass of 1 kg was accepted, and its rotation's step would be 1e-150 s.
  for (int c = 0; c < 3; ++c) {
    const double gyration = std::sqrt(rb.inertia[c] / rb.mass);  // m
    if (!(gyration >= kLength.lo && gyration <= kLength.hi))
      throw InputError(fmt::format(
          "{}: key '{}': principal moments ({:.6g}, {:.6g}, {:.6g}) kg m^2 with mass {:.6g} kg give a radius of "
          "gyration sqrt(I/m) of {:.4g} m, outside {:g} m to {:g} m: the inertia and the mass do not belong to one "
          "body",
          where(), ms.inertia.empty() ? (ms.density > 0.0 ? "density" : "mass") : "inertia", rb.inertia[0],
          rb.inertia[1], rb.inertia[2], rb.mass, gyration, kLength.lo, kLength.hi));
  }
  rb.state.velocity = to_vec(ms.initial_velocity);
  rb.state.omega = to_vec(ms.angular_velocity);
  rb.rotation = ms.rotation == "hinge"        ? BodyRotation::Hinge
                : ms.rotation == "prescribed" ? BodyRotation::Prescribed
                                              : BodyRotation::Free;
  rb.axis = to_vec(ms.hinge_axis).normalized();
  rb.pivoted = ms.hinge_at_point;
  rb.pivot = to_vec(ms.hinge_point);
  for (char c : ms.fixed) rb.fixed |= static_cast<std::uint8_t>(1u << (c - 'x'));
  rb.load.force = to_vec(ms.force);
  rb.load.torque = to_vec(ms.torque);
  rb.load.force_damping = ms.damping;
  rb.load.spring = to_vec(ms.spring_stiffness);
  rb.load.anchor = rb.state.position;  // (the initial centre of mass)
  rb.load.holder_velocity = to_vec(ms.holder_velocity);
  rb.load.torque_damping = ms.torque_damping;
  // The mount is integrated with the particles' step, which knows nothing of it: its period
  // and its damper's time m/c must span enough steps to be stable and resolved (30 steps a
  // period puts Verlet's period error below 0.2 %), or the case is refused, not run wrong.
  const double h = d.implicit ? d.dt_max : d.dt;  // s: the largest step taken
  for (int c = 0; c < 3; ++c) {
    const double omega = std::sqrt(rb.load.spring[c] / rb.mass);  // rad/s
    if (omega * h > 2.0 * M_PI / 30.0)
      throw InputError(fmt::format(
          "{}: key 'spring_stiffness' = {} N/m along {}: the mount's period 2 pi sqrt(m/k) = {:.4g} s (mass {:.4g} kg) "
          "spans fewer than 30 steps of {:.4g} s: lower the stiffness or raise the mass",
          where(), rb.load.spring[c], char('x' + c), 2.0 * M_PI / omega, rb.mass, h));
  }
  if (rb.load.force_damping * h / rb.mass > 0.2)
    throw InputError(
        fmt::format("{}: key 'damping' = {} N s/m: the damper's time m/c = {:.4g} s spans fewer than 5 steps of "
                    "{:.4g} s: lower it or raise the mass",
                    where(), rb.load.force_damping, rb.mass / rb.load.force_damping, h));
  return rb;
}

}  // namespace

const std::vector<Key<MeshSettings>>& mesh_keys() {
  using S = MeshSettings;
  static const std::vector<Key<S>> keys{
      {.name = "name",
       .field = &S::name,
       .no_default = true,
       .default_note = "`mesh<index>`",
       .rule = "non-empty; letters, digits, `_` and `-` only; unique among meshes",
       .doc = "Name used in outputs."},
      {.name = "file",
       .field = &S::file,
       .default_note = "rectangle",
       .rule = "an existing `.stl` or `.obj` file (extension in any case); not with `edge1`, `edge2`, "
               "`divisions` or `rake_angle`",
       .doc = "Mesh file, see [Mesh files](#mesh-files)."},
      {.name = "scale",
       .field = &S::scale,
       .unit = "1",
       .range = kScale,
       .doc = "Factor on the file's coordinates, for example 1e-3 for a file in mm. It has no effect on a "
              "rectangle."},
      {.name = "origin",
       .field = &S::origin,
       .unit = "m",
       .range = kCoordinate,
       .rule = "not with `file`",
       .doc = "Corner of the rectangle, or the sharp tip of a generated tool."},
      {.name = "edge1",
       .field = &S::edge1,
       .unit = "m",
       .no_default = true,
       .range = kCoordinate,
       .rule = "both edges required for a rectangle; edge1 x edge2 non-zero; not with `file`",
       .doc = "First edge of the rectangle (a parallelogram in general) from `origin`."},
      {.name = "edge2",
       .field = &S::edge2,
       .unit = "m",
       .no_default = true,
       .range = kCoordinate,
       .rule = "as `edge1`",
       .doc = "Second edge of the rectangle from `origin`."},
      {.name = "divisions",
       .field = &S::divisions,
       .unit = "1",
       .range = in(1, 1e7, "[]"),
       .rule = "product <= 1e7; not with `file`",
       .doc = "Cells n1, n2 along `edge1` and `edge2`. Each cell is cut into 2 triangles, so the rectangle has "
              "2 n1 n2 triangles."},
      {.name = "rake_angle",
       .field = &S::rake_angle,
       .unit = "deg",
       .no_default = true,
       .rule = "(-60, 60), checked when the tool is built; not with `file` or a rectangle",
       .doc = "Makes the mesh a generated cutting tool (`tool_paths/tool_geometry.h`): the rake face leaves the "
              "edge upwards, tilted back from +z by this angle."},
      {.name = "clearance_angle",
       .field = &S::clearance_angle,
       .unit = "deg",
       .rule = "(0, 45), checked when the tool is built; only with `rake_angle`",
       .doc = "The flank face leaves the edge backwards, tilted up from -x by this angle. The wedge 90 - rake - "
              "clearance must exceed 5 deg."},
      {.name = "edge_radius",
       .field = &S::edge_radius,
       .unit = "m",
       .range = kLengthOrZero,
       .rule = "only with `rake_angle`",
       .doc = "Cutting-edge radius (an arc tangent to both faces, steps of at most 5 deg); 0 = sharp."},
      {.name = "width",
       .field = &S::width,
       .unit = "m",
       .no_default = true,
       .range = kLengthOrZero,
       .rule = "> 0 when the tool is built; required with `rake_angle`",
       .doc = "Extent of the tool along y, centred on `origin`'s y."},
      {.name = "face_length",
       .field = &S::face_length,
       .unit = "m",
       .no_default = true,
       .range = kLengthOrZero,
       .rule = "> 0 when the tool is built; required with `rake_angle`",
       .doc = "Length of the rake and flank faces from the sharp tip."},
      {.name = "inclination_angle",
       .field = &S::inclination_angle,
       .unit = "deg",
       .range = in(-kMaxInclinationDeg, kMaxInclinationDeg, "()"),
       .rule = "only with `rake_angle`",
       .doc = "lambda_s (ISO 3002): turns the generated tool about the vertical through `origin`, so that its "
              "edge runs along (-sin lambda, cos lambda, 0) while it still moves along x: an oblique cut. "
              "`rake_angle` and `clearance_angle` are then the normal angles (in the section normal to the "
              "edge), and `width` the edge's length."},
      {.name = "tool_tip",
       .field = &S::tool_tip,
       .unit = "m",
       .no_default = true,
       .default_note = "the file is not a tool",
       .range = kCoordinate,
       .rule = "only with `file`; the file must measure as a tool",
       .doc = "Makes the mesh `file` a cutting tool, as `cut.tool_file` does ([A tool from a "
              "file](#a-tool-from-a-file)): "
              "its rake and clearance angles, sharp tip and edge are measured, and it is moved so that its sharp "
              "tip sits here. The cut's analysis takes the measured rake angle."},
      {.name = "youngs_modulus",
       .field = &S::youngs_modulus,
       .unit = "Pa",
       .range = or_inf(kModulus),
       .doc = "E_w of the mesh. `inf` means rigid."},
      {.name = "poisson_ratio",
       .field = &S::poisson_ratio,
       .unit = "1",
       .range = in(-1, 0.5, "()"),
       .doc = "nu_w of the mesh. No effect when `youngs_modulus` is `inf`."},
      {.name = "parting_lead",
       .field = &S::parting_lead,
       .unit = "m",
       .range = or_inf(kLength),
       .doc = "A parting line at the mesh's lowest point (a tool's cutting edge): rods that cross the horizontal "
              "plane through that point break when it comes within this distance of their midpoint along x, the "
              "cutting direction (and up to the same distance after it has passed them). The geometric "
              "separation criterion of early finite-element cutting models: the chip separates at the edge and "
              "must form by plastic flow, instead of the lattice cleaving along the cutting plane ahead of the "
              "tool (docs/materials.md). A fraction of the particle spacing to a few of them; `inf` means none, "
              "and separation is left to the rods' failure."},
      {.name = "box_size",
       .field = &S::box_size,
       .unit = "m",
       .no_default = true,
       .range = kLength,
       .rule = "not with `file`, a rectangle, a tool or a cylinder",
       .doc = "Makes the mesh a closed box with these edges along x, y, z, centred on `origin` (12 triangles).",
       .section = "shapes"},
      {.name = "cylinder_radius",
       .field = &S::cylinder_radius,
       .unit = "m",
       .no_default = true,
       .range = kLength,
       .rule = "needs `cylinder_length`; not with `file`, a rectangle, a tool or `box_size`",
       .doc = "Makes the mesh a closed cylinder of this radius centred on `origin`: a prism with "
              "`cylinder_segments` flat sides inscribed in the round face, ends as fans (4 segments triangles).",
       .section = "shapes"},
      {.name = "cylinder_length",
       .field = &S::cylinder_length,
       .unit = "m",
       .no_default = true,
       .range = kLength,
       .rule = "only with `cylinder_radius`",
       .doc = "Length of the cylinder along its axis.",
       .section = "shapes"},
      {.name = "cylinder_axis",
       .field = &S::cylinder_axis,
       .unit = "1",
       .range = kDirection,
       .rule = "length >= 1e-6; only with `cylinder_radius`",
       .doc = "Direction of the cylinder's axis (normalised).",
       .section = "shapes"},
      {.name = "cylinder_segments",
       .field = &S::cylinder_segments,
       .unit = "1",
       .range = in(3, 100000, "[]"),
       .rule = "only with `cylinder_radius`",
       .doc = "Flat sides of the faceted cylinder. Its volume is short of the round one's by 1 - sin(t)/t, t = 2 "
              "pi / segments (0.6 % at 32).",
       .section = "shapes"},
      {.name = "dynamics",
       .field = &S::dynamics,
       .choices = {"prescribed", "rigid_body"},
       .rule = "`rigid_body` needs a closed mesh (a file, `box_size` or `cylinder_radius`), no `motion`, and "
               "`density` or `mass`",
       .doc = "`prescribed`: the mesh follows its `motion`. `rigid_body`: a rigid macro particle, moved by the "
              "contact forces and torques on its triangles, its loads and gravity (see "
              "[Rigid bodies](#rigid-bodies)).",
       .section = "rigid_body"},
      {.name = "density",
       .field = &S::density,
       .unit = "kg/m^3",
       .no_default = true,
       .range = kDensity,
       .rule = "give `density` or `mass`, not both; only with `dynamics = \"rigid_body\"`",
       .doc = "Density of the body: mass, centre of mass and principal inertia follow from the closed mesh.",
       .section = "rigid_body"},
      {.name = "mass",
       .field = &S::mass,
       .unit = "kg",
       .no_default = true,
       .range = kMass,
       .rule = "as `density`",
       .doc = "Mass of the body instead of its density (uniform: density = mass / the mesh's volume; with "
              "`inertia`, the mass as given).",
       .section = "rigid_body"},
      {.name = "centre_of_mass",
       .field = &S::centre_of_mass,
       .unit = "m",
       .default_note = "from the mesh",
       .range = kCoordinate,
       .rule = "with `inertia`",
       .doc = "Centre of mass in the mesh's coordinates (as its file or shape places it), given with `inertia`.",
       .section = "rigid_body"},
      {.name = "inertia",
       .field = &S::inertia,
       .unit = "kg m^2",
       .default_note = "from the mesh",
       .range = in(-1e9, 1e9, "[]", "within 1e9 kg m^2"),
       .rule = "6 numbers; needs `mass` and `centre_of_mass`, not `density`; principal moments positive, each at "
               "most the sum of the other two",
       .doc = "Inertia tensor about `centre_of_mass`, mesh coordinates: [Ixx, Iyy, Izz, Ixy, Iyz, Ixz] (the "
              "products of inertia as tensor entries, Ixy = -integral of x y dm). With it the mass properties are "
              "not computed from the mesh, which may then be open (a tool's faces) or stand for a body whose mass "
              "is not spread uniformly in it.",
       .section = "rigid_body"},
      {.name = "initial_velocity",
       .field = &S::initial_velocity,
       .unit = "m/s",
       .range = kVelocity,
       .rule = "only with `dynamics = \"rigid_body\"`",
       .doc = "Velocity of the centre of mass at the start (a component named in `fixed` keeps its value).",
       .section = "rigid_body"},
      {.name = "angular_velocity",
       .field = &S::angular_velocity,
       .unit = "rad/s",
       .range = kAngularVelocity,
       .rule = "along `hinge_axis` with `rotation = \"hinge\"`; only with `dynamics = \"rigid_body\"`",
       .doc = "Angular velocity at the start, world frame.",
       .section = "rigid_body"},
      {.name = "rotation",
       .field = &S::rotation,
       .choices = {"free", "hinge", "prescribed"},
       .rule = "only with `dynamics = \"rigid_body\"`",
       .doc = "`free`: Euler's equations with the full inertia. `hinge`: turns only about `hinge_axis` through "
              "the centre of mass, or through `hinge_point`. `prescribed`: keeps `angular_velocity` (zero: does "
              "not turn).",
       .section = "rigid_body"},
      {.name = "hinge_axis",
       .field = &S::hinge_axis,
       .unit = "1",
       .range = kDirection,
       .rule = "length >= 1e-6; only with `rotation = \"hinge\"`",
       .doc = "Direction of the hinge's axis, world frame (normalised). The axis passes through the centre of "
              "mass (add `fixed = \"xyz\"` for a fixed axle there), or through `hinge_point`.",
       .section = "rigid_body"},
      {.name = "hinge_point",
       .field = &S::hinge_point,
       .unit = "m",
       .default_note = "the centre of mass",
       .range = kCoordinate,
       .rule = "only with `rotation = \"hinge\"`; not with `fixed`",
       .doc = "A point of the hinge's axis, world frame, where the axle is fixed: the body turns about it and "
              "its centre of mass moves on a circle about the axis (a pendulum, an eccentric wheel). The moment "
              "of inertia and the torque are taken about the axis through this point; `initial_velocity` is "
              "replaced by angular_velocity x (centre of mass - hinge_point).",
       .section = "rigid_body"},
      {.name = "fixed",
       .field = &S::fixed,
       .default_note = "none",
       .rule = "letters of `xyz`, each once; only with `dynamics = \"rigid_body\"`",
       .doc = "Translation components of the centre of mass held at their initial velocity. `\"xyz\"` is a "
              "fixed point (with `rotation = \"free\"`) or a fixed axle (with a hinge).",
       .section = "rigid_body"},
      {.name = "force",
       .field = &S::force,
       .unit = "N",
       .range = kForce,
       .rule = "only with `dynamics = \"rigid_body\"`",
       .doc = "Constant external force at the centre of mass, world frame.",
       .section = "rigid_body"},
      {.name = "torque",
       .field = &S::torque,
       .unit = "N m",
       .range = kForce,
       .rule = "only with `dynamics = \"rigid_body\"`",
       .doc = "Constant external torque, world frame.",
       .section = "rigid_body"},
      {.name = "damping",
       .field = &S::damping,
       .unit = "N s/m",
       .range = in(0.0, 1e12, "[]", "0 to 1e12 N s/m"),
       .rule = "m / damping at least 5 steps; only with `dynamics = \"rigid_body\"`",
       .doc = "External force -damping (v - holder_velocity) on the centre of mass (a mount's damper; without a "
              "holder, a drag -damping v). Damping ratio zeta = damping / (2 sqrt(k m)) along an axis of "
              "stiffness k.",
       .section = "rigid_body"},
      {.name = "spring_stiffness",
       .field = &S::spring_stiffness,
       .unit = "N/m",
       .range = kStiffness,
       .rule = "each >= 0 and finite; the period 2 pi sqrt(m/k) at least 30 steps (of dt, or of dt_max with "
               "Newmark); only with `dynamics = \"rigid_body\"`",
       .doc = "Stiffness of a mount along x, y and z: the force -k_c (x_c - a_c(t)) on the centre of mass, where "
              "the anchor a(t) starts at the initial centre of mass and moves at `holder_velocity` (a compliant "
              "tool on its holder: natural frequency sqrt(k/m) / (2 pi), static deflection F/k).",
       .section = "rigid_body"},
      {.name = "holder_velocity",
       .field = &S::holder_velocity,
       .unit = "m/s",
       .range = kVelocity,
       .rule = "only with `dynamics = \"rigid_body\"`",
       .doc = "Velocity of the mount's anchor (the tool holder), world frame: the spring and damper pull the body "
              "along. Give the body the same `initial_velocity` to start it at the holder's speed.",
       .section = "rigid_body"},
      {.name = "torque_damping",
       .field = &S::torque_damping,
       .unit = "N m s/rad",
       .range = in(0.0, 1e12, "[]", "0 to 1e12 N m s/rad"),
       .rule = "only with `dynamics = \"rigid_body\"`",
       .doc = "External torque -torque_damping omega (a water wheel's load: with a constant torque T alone it "
              "runs up to omega = T / torque_damping).",
       .section = "rigid_body"},
  };
  return keys;
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

void build_meshes(const CaseSettings& cs, Model& model) {
  for (const auto& ms : cs.meshes) {
    MeshBody mb;
    mb.name = ms.name;
    if (!ms.file.empty()) {
      mb.mesh = read_mesh(ms.file, ms.scale);
      mb.mesh.name = ms.name;
      if (ms.tool_from_file) {  // its measured sharp tip to tool_tip (as a generated tool's to its origin)
        const Vec3 shift = to_vec(ms.tool_tip) - to_vec(ms.file_tip);
        for (auto& v : mb.mesh.vertices) v += shift;
      }
    } else if (ms.tool) {
      ToolSpec ts;
      ts.rake_angle_deg = ms.rake_angle;
      ts.clearance_angle_deg = ms.clearance_angle;
      ts.edge_radius = ms.edge_radius;
      ts.width = ms.width;
      ts.face_length = ms.face_length;
      ts.inclination_angle_deg = ms.inclination_angle;
      try {
        mb.mesh = make_tool(ts);
      } catch (const InputError& e) {
        throw InputError(fmt::format("{}: [[mesh]] '{}': {}", cs.source, ms.name, e.what()));
      }
      mb.mesh.name = ms.name;
      const Vec3 o(ms.origin[0], ms.origin[1], ms.origin[2]);
      for (auto& v : mb.mesh.vertices) v += o;
    } else if (ms.box_size[0] > 0.0) {
      mb.mesh = box_mesh(to_vec(ms.origin), to_vec(ms.box_size));
      mb.mesh.name = ms.name;
    } else if (ms.cylinder_radius > 0.0) {
      mb.mesh = cylinder_mesh(to_vec(ms.origin), to_vec(ms.cylinder_axis), ms.cylinder_radius, ms.cylinder_length,
                              ms.cylinder_segments);
      mb.mesh.name = ms.name;
    } else {
      mb.mesh = rectangle_mesh(ms);
      mb.mesh.validate(cs.source + " [[mesh]] " + ms.name);
    }
    if (ms.dynamics == "rigid_body")
      model.bodies.push_back(rigid_body(cs, model.derived, ms, model.meshes.size(), mb.mesh));
    mb.youngs_modulus = ms.youngs_modulus;
    mb.poisson_ratio = ms.poisson_ratio;
    mb.parting.lead = ms.parting_lead;
    mb.parting.behind = std::isfinite(ms.parting_lead) ? ms.parting_lead : 0.0;
    model.meshes.push_back(std::move(mb));
    model.mesh_motion.push_back(motion_from(ms.motion));
  }
}

std::string meshes_echo(const Model& m) {
  std::string out;
  for (const RigidBody& rb : m.bodies) {
    const Vec3& c = rb.state.position;
    out += fmt::format(
        "  rigid body '{}': mass {:.4g} kg, centre of mass ({:.4g}, {:.4g}, {:.4g}) m, principal inertia ({:.4g}, "
        "{:.4g}, {:.4g}) kg m^2{}\n",
        m.meshes[rb.mesh].name, rb.mass, c[0], c[1], c[2], rb.inertia[0], rb.inertia[1], rb.inertia[2],
        rb.rotation == BodyRotation::Hinge ? fmt::format(", {:.4g} kg m^2 about the hinge", rb.axis_inertia()) : "");
  }
  for (const MeshSettings& ms : m.settings.meshes)  // (the angles the cut's analysis takes)
    if (ms.tool_from_file)
      out += fmt::format(
          "  tool '{}' from {}: measured rake {:.6g} deg, clearance {:.6g} deg, edge radius {:.4g} m, rake face {:.4g} "
          "m; its sharp tip placed at ({:.6g}, {:.6g}, {:.6g}) m\n",
          ms.name, ms.file, ms.rake_angle, ms.clearance_angle, ms.edge_radius, ms.face_length, ms.tool_tip[0],
          ms.tool_tip[1], ms.tool_tip[2]);
  return out;
}

}  // namespace swarf
