// cut_case.cpp: [cut] turned into lower-level keys (see cut_case.h). Each rule below is the
// built-in default cut's choice (docs/default-case.md says why); the notes printed with the
// keys say it again for the user.
#include "setup/cut_case.h"

#include <fmt/format.h>

#include <cmath>
#include <optional>
#include <tuple>
#include <vector>

#include "setup/case_keys.h"
#include "setup/material_presets.h"
#include "setup/toml_parse.h"
#include "swarf/core/errors.h"
#include "tool_paths/tool_measure.h"

namespace swarf {
namespace {

// The derivation as it is printed: one TOML section per table, a line per key.
struct Printout {
  std::vector<std::string> lines;

  void section(const std::string& header) { lines.push_back((lines.empty() ? "" : "\n") + header); }
  void key(const std::string& name, const std::string& value, const std::string& note) {
    lines.push_back(fmt::format("{} = {}{}", name, value, note.empty() ? "" : "  # " + note));
  }
  void given(const std::string& name, const toml::node& n) {
    const auto* f = n.as_floating_point();
    lines.push_back(
        fmt::format("# {} = {}  (given in the case)", name, f ? fmt::format("{}", f->get()) : print_toml(n)));
  }
  std::string text() const {
    std::string s;
    for (const auto& l : lines) s += l + "\n";
    return s;
  }
};

// TOML text of a value: floats always with a point or an exponent (so that they read back
// as floats) and in their shortest exact form.
std::string text_of(double v) {
  std::string s = fmt::format("{}", v);
  if (s.find_first_of(".eEni") == std::string::npos) s += ".0";
  return s;
}
template <std::size_t N>
std::string text_of(const std::array<double, N>& v) {
  std::string s = "[";
  for (std::size_t k = 0; k < N; ++k) s += (k ? ", " : "") + text_of(v[k]);
  return s + "]";
}
std::string text_of(const std::array<int, 3>& v) { return fmt::format("[{}, {}, {}]", v[0], v[1], v[2]); }
std::string text_of(const std::string& v) { return '"' + v + '"'; }
std::string text_of(bool v) { return v ? "true" : "false"; }
std::string text_of(int v) { return std::to_string(v); }

template <std::size_t N>
toml::array node_of(const std::array<double, N>& v) {
  toml::array a;
  for (double x : v) a.push_back(x);
  return a;
}
toml::array node_of(const std::array<int, 3>& v) { return toml::array{v[0], v[1], v[2]}; }
template <class T>
T node_of(const T& v) {
  return v;
}

// Puts derived values into one table of the tree where the case does not give them.
class Filler {
 public:
  Filler(toml::table& t, std::string prefix, Printout& out, std::set<std::string>& derived)
      : t_(t), prefix_(std::move(prefix)), out_(out), derived_(derived) {}

  template <class T>
  void put(const std::string& key, const T& value, const std::string& note) {
    if (const toml::node* n = t_.get(key)) {
      out_.given(key, *n);
      return;
    }
    t_.insert(key, node_of(value));
    derived_.insert(prefix_ + "." + key);
    out_.key(key, text_of(value), note);
  }

 private:
  toml::table& t_;
  std::string prefix_;
  Printout& out_;
  std::set<std::string>& derived_;
};

toml::table& table_in(toml::table& root, const char* name) {
  if (!root.contains(name)) root.insert(name, toml::table{});
  return *root.get_as<toml::table>(name);
}

toml::array& array_in(toml::table& root, const char* name) {
  if (!root.contains(name)) root.insert(name, toml::array{});
  toml::array* a = root.get_as<toml::array>(name);
  if (!a) throw InputError(fmt::format("'{}' must be an array of tables ([[{}]])", name, name));
  return *a;
}

// The entry of an array of tables with that name, or null.
toml::table* named(toml::array& arr, const std::string& name) {
  for (auto& e : arr)
    if (toml::table* t = e.as_table())
      if (const auto* n = t->get_as<std::string>("name"); n && n->get() == name) return t;
  return nullptr;
}

// Half a layer spacing above the lattice layer at or just below v: a box bound between two
// layers, so that which particles it selects does not hang on the last bit of a coordinate.
double between_layers(double v, double spacing) { return (std::floor(v / spacing + 1e-9) + 0.5) * spacing; }

constexpr double kAngleAgreement = 0.5;  // deg: a given angle and the file's measured one agree within it

constexpr int kBaseLayers = 2;             // the vice under the block: its two bottom layers
constexpr double kStartAhead = 0.25;       // the tool's tip starts h/4 before the block's first centres
constexpr double kEndClampReach = 0.5;     // the end clamp holds the last h/2 of the block ...
constexpr double kEndClampBelowTip = 0.4;  // ... from the base clamp up to 0.4 h below the tool's tip
constexpr double kFaceLength = 5.0;        // rake and flank faces 5 h long: the chip's contact is 1 to 2 h_c
constexpr double kToolOverhang = 2.0;      // the tool overhangs the width by 2 h on each side
constexpr double kRunOut = 7.6;            // default block length: the cut plus 7.6 h ahead of the tool's end
constexpr int kFrames = 10;                // ParaView frames over the run (plus the first)
constexpr int kSeriesRows = 400;           // series.csv rows over the run

}  // namespace

void expand_cut(toml::table& root, const CaseInput& in, CaseSettings& cs, std::set<std::string>& derived) {
  const toml::table* t = in.table("cut");
  if (!t) return;
  TableReader r = in.reader(t, "cut");
  CutSettings& c = cs.cut;
  c.enabled = true;
  r.read(cut_keys(), c);
  r.finish();
  const bool from_file = r.has("tool_file");
  for (const char* key : {"uncut_chip_thickness", "cutting_speed", "rake_angle", "material"})
    if (!r.has(key) && !(from_file && std::string(key) == "rake_angle"))
      r.fail(key, nullptr,
             key == std::string("rake_angle") ? "is required (or a tool_file to measure it from)" : "is required");
  if (r.has("tool_scale") && !from_file) r.fail("tool_scale", r.get("tool_scale"), "is used only with tool_file");
  for (const char* table : {"membrane", "uniaxial"})
    if (in.table(table))
      throw InputError(fmt::format("{}: [cut] makes a cutting case; it cannot go with [{}]", in.source, table));
  if (const toml::table* w = in.table("workpiece"))
    for (const char* key : {"lattice_file", "size"})
      if (w->contains(key))
        throw InputError(fmt::format(
            "{}: key 'workpiece.{}': [cut] generates the lattice by cells from the depth of cut and 'cut.layers'; "
            "give workpiece.cells and workpiece.radius to override it, or leave out [cut]",
            in.source, key));

  const double h = c.uncut_chip_thickness;  // m
  const double v = c.cutting_speed;         // m/s
  // The tool's geometry: the keys', or measured from the tool file.
  double rake = c.rake_angle, clearance = c.clearance_angle, edge_radius = c.edge_radius;  // deg, deg, m
  std::optional<ToolMeasure> measured;
  if (from_file) {
    measured = measure_tool_file(r, "tool_file", resolve(c.tool_file, in.directory), c.tool_scale);
    rake = measured->rake_angle_deg, clearance = measured->clearance_angle_deg, edge_radius = measured->edge_radius;
    for (auto [key, given, got] :
         {std::tuple{"rake_angle", c.rake_angle, rake}, std::tuple{"clearance_angle", c.clearance_angle, clearance}})
      if (r.has(key) && !(std::abs(given - got) <= kAngleAgreement))
        r.fail(key, r.get(key),
               fmt::format("is {} deg, but the tool in cut.tool_file '{}' measures {:.6g} deg (more than {} deg "
                           "apart): correct it, or leave it out to take the file's",
                           given, c.tool_file, got, kAngleAgreement));
    if (r.has("edge_radius"))
      r.fail("edge_radius", r.get("edge_radius"),
             fmt::format("is not used with tool_file: the file's edge is the edge (measured r_n = {})",
                         measured->sharp ? "0, sharp" : fmt::format("{:.4g} m", edge_radius)));
  }
  // (the keys' defaults that depend on others; cs.cut keeps what the case gave, as every table does)
  const double length = r.has("length_of_cut") ? c.length_of_cut : 10.0 * h;                          // m
  const double block_length = r.has("workpiece_length") ? c.workpiece_length : length / h + kRunOut;  // in h
  const double steady_from = r.has("steady_from") ? c.steady_from : 0.5 * length;                     // m of travel
  if (!(edge_radius < h))
    r.fail(from_file ? "tool_file" : "edge_radius", r.get(from_file ? "tool_file" : "edge_radius"),
           fmt::format("{}must be below the depth of cut h = {} m",
                       from_file ? fmt::format("the tool's edge radius (measured {:.4g} m) ", edge_radius) : "", h));
  if (!(steady_from < length))
    r.fail("steady_from", r.get("steady_from"),
           fmt::format("must be below the length of cut {} m (a tool travel, m)", length));
  const bool compliant = c.tool_stiffness > 0.0;
  if (compliant && !r.has("tool_mass"))
    r.fail("tool_stiffness", r.get("tool_stiffness"), "a compliant tool needs tool_mass (kg/m) too");
  for (const char* key : {"tool_mass", "tool_damping_ratio"})
    if (!compliant && r.has(key))
      r.fail(key, r.get(key), "is used only with tool_stiffness > 0 (N/m/m): a compliant tool");
  const MaterialPreset& preset = *find_material_preset(c.material);  // (the key's choices are the presets)
  const bool plane_strain = !(c.width > 0.0);
  const double incline = c.inclination_angle;  // deg
  if (incline != 0.0 && plane_strain)
    r.fail("inclination_angle", r.get("inclination_angle"),
           "needs a finite width (cut.width, m): an inclined edge across plane strain's periodic slab would have "
           "to cross its period");
  if (incline != 0.0 && from_file)
    r.fail("inclination_angle", r.get("inclination_angle"),
           "is not taken with cut.tool_file: the file's tool is measured in the orthogonal frame; incline the "
           "generated tool, or turn the file's tool yourself and give it as a [[mesh]] with tool_tip");

  Printout out;
  out.lines.push_back(
      fmt::format("# derived from [cut]: h = {:.4g} mm, v_c = {:.4g} m/s, {:.4g} mm of cut, rake {:.6g} deg, clearance "
                  "{:.6g} deg, edge radius {:.4g} um, {}, {}{}",
                  h * 1e3, v, length * 1e3, rake, clearance, edge_radius * 1e6, c.material,
                  plane_strain ? "plane strain" : fmt::format("width {:.4g} mm", c.width * 1e3),
                  incline != 0.0 ? fmt::format(", inclination {:.6g} deg (oblique)", incline) : ""));
  if (measured)
    out.lines.push_back(
        fmt::format("# the tool from {} (x {}), measured: {}", c.tool_file, c.tool_scale, describe(*measured)));

  // The lattice. The keys the case gives are read back through the key table (with its
  // checks), so that what follows uses them.
  out.section("[workpiece]");
  toml::table& wt = table_in(root, "workpiece");
  Filler w(wt, "workpiece", out, derived);
  w.put("radius", h / (c.layers * std::sqrt(2.0)),
        fmt::format("m: {} layers across h, R = h / (layers sqrt 2)", c.layers));
  WorkpieceSettings ws;
  in.reader(&wt, "workpiece").read(workpiece_keys(), ws);
  const double s = std::sqrt(2.0) * ws.radius;  // layer spacing along x and z, m (a = 2 s)
  const double a = 2.0 * s;
  // Whole cells along an axis; a count beyond any lattice a machine holds is refused by the
  // key that asked for it (before lround, which a count beyond a long's range would trap).
  constexpr double kMaxCells = 1e6;
  const auto cells_of = [&](double length, const char* key) {
    const double n = length / a;
    if (!(n <= kMaxCells))
      r.fail(key, r.get(key),
             fmt::format("makes {:.3g} cells of a = {:.4g} m along its axis, more than {:g}", n, a, kMaxCells));
    return std::max(2, static_cast<int>(std::lround(n)));
  };
  w.put("cells",
        std::array<int, 3>{cells_of(block_length * h, "workpiece_length"), plane_strain ? 2 : cells_of(c.width, "width"),
                           cells_of(c.workpiece_height * h, "workpiece_height")},
        fmt::format("{} h long, {}, {} h high, in cells of a = {} m", block_length,
                    plane_strain ? "2 cells wide" : "the width", c.workpiece_height, a));
  w.put("periodic_width", plane_strain, plane_strain ? "plane strain" : "free sides");
  in.reader(&wt, "workpiece").read(workpiece_keys(), ws);
  const std::array<int, 3> n = ws.cells;
  const double x_last = (2 * n[0] - 1) * s, y_last = (2 * n[1] - 1) * s, z_top = (2 * n[2] - 1) * s;  // centres, m
  const double z_tip = z_top - h;
  // An inclined edge leads with one end: the tip (the edge's middle) starts and ends that lead
  // further back, so that the leading corner enters the block where an orthogonal edge would
  // and the middle of the width cuts the length of cut.
  const double lead = 0.5 * y_last * std::tan(std::abs(incline) * M_PI / 180.0);  // m

  out.section("[material]");
  Filler m(table_in(root, "material"), "material", out, derived);
  m.put("preset", c.material, std::string(preset.description));
  m.put("calibration", std::string("tension"), "the flow curve matched in tension along [100]");

  out.section("[rod]");
  Filler rod(table_in(root, "rod"), "rod", out, derived);
  rod.put("damping_ratio", 0.1, "1, of the rod's critical damping");
  rod.put("bond_overlap", 0.0, "1: unbonded lattice neighbours that touch form a rod ...");
  rod.put("neighbour_exchange", true, "... in exchange for the most stretched rod of a particle that has 12");

  out.section("[contact]");
  Filler ct(table_in(root, "contact"), "contact", out, derived);
  ct.put("youngs_modulus", preset.youngs_modulus, "Pa: the material's");
  ct.put("friction", c.friction, "1");

  // The vice: the bottom layers, and the far end of the block below the cut line (a clamp
  // over the whole end face would push the layer ahead of the tool as a column).
  toml::array& groups = array_in(root, "group");
  const double end_x = between_layers(x_last - kEndClampReach * h, s);
  const double end_z_lo = between_layers(kBaseLayers * s, s);
  const double end_z_hi = between_layers(z_tip - kEndClampBelowTip * h, s);
  // (the end clamp's own rules only when [cut] makes it; a case's own 'end' group is its own)
  const bool derive_end = !named(groups, "end");
  if (derive_end && !(end_z_hi > end_z_lo))
    r.fail("workpiece_height", r.get("workpiece_height"),
           fmt::format("leaves no material for the end clamp between the base clamp ({} layers) and {} h below the "
                       "tool's tip: raise it",
                       kBaseLayers, kEndClampBelowTip));
  const double tool_end = -kStartAhead * h + length;  // m, the tip's x at the end of the cut
  if (derive_end && !(tool_end + lead < end_x - h))
    r.fail("workpiece_length", r.get("workpiece_length"),
           fmt::format("is too short: the tool's {} would end at x = {} m, within h of the end clamp (from x = {} m)",
                       lead > 0 ? "leading corner" : "tip", tool_end + lead, end_x));
  if (!derive_end && !(tool_end + lead < x_last))
    r.fail("workpiece_length", r.get("workpiece_length"),
           fmt::format("is too short: the tool's tip would end at x = {} m, beyond the block's last particles at "
                       "x = {} m",
                       tool_end, x_last));
  std::vector<toml::table> new_groups;
  for (const char* name : {"base", "end"}) {
    out.section("[[group]]");
    if (named(groups, name)) {
      out.lines.push_back(fmt::format("# [[group]] '{}' given in the case", name));
      continue;
    }
    toml::table g;
    Filler f(g, "group", out, derived);
    f.put("name", std::string(name), "");
    if (std::string(name) == "base") {
      f.put("side", std::string("z-"), "the vice under the block");
      f.put("layers", kBaseLayers, "");
    } else {
      f.put("box_min", std::array<double, 3>{end_x, -a, end_z_lo},
            fmt::format("m: the last {} h of the block, above the base clamp ...", kEndClampReach));
      f.put("box_max", std::array<double, 3>{x_last + a, y_last + a, end_z_hi},
            fmt::format("m: ... up to {} h below the tool's tip, so the clamp does not push on the uncut layer",
                        kEndClampBelowTip));
    }
    new_groups.push_back(std::move(g));
  }
  for (auto it = new_groups.rbegin(); it != new_groups.rend(); ++it) groups.insert(groups.begin(), std::move(*it));

  // The tool: generated, its sharp tip h below the top centres and h/4 before the block.
  out.section("[[mesh]]");
  toml::array& meshes = array_in(root, "mesh");
  toml::table* tool = named(meshes, "tool");
  if (!tool) {
    meshes.insert(meshes.begin(), toml::table{{"name", "tool"}});
    tool = meshes.front().as_table();
    derived.insert("mesh.name");
    out.key("name", text_of(std::string("tool")), "");
  } else {
    out.lines.push_back("# name = \"tool\"  (given in the case; its other keys below win over [cut])");
  }
  Filler tf(*tool, "mesh", out, derived);
  const double span = plane_strain ? 2 * n[1] * s : y_last;  // the period, or the block's width between centres
  const std::array<double, 3> tip{-kStartAhead * h - lead, 0.5 * y_last, z_tip};
  const std::string
      tip_note = lead > 0
                     ? fmt::format(
                           "m: sharp tip (the edge's middle) {} h and the inclined edge's lead {:.4g} m before the "
                           "block, h below its top centres ({} m)",
                           kStartAhead, lead, z_top)
                     : fmt::format("m: sharp tip {} h before the block, h below its top centres ({} m)", kStartAhead,
                                   z_top);
  if (measured) {
    if (!(measured->edge_length >= span))
      r.fail("tool_file", r.get("tool_file"),
             fmt::format("the tool's edge is {:.6g} m long along y, the workpiece {:.6g} m wide{}: the edge must "
                         "span it",
                         measured->edge_length, span, plane_strain ? " (the period of plane strain)" : ""));
    tf.put("file", c.tool_file, "the tool from cut.tool_file");
    tf.put("scale", c.tool_scale, "1");
    tf.put("tool_tip", tip, tip_note + ", the edge's middle on the block's");
  } else {
    tf.put("rake_angle", c.rake_angle, "deg");
    tf.put("clearance_angle", c.clearance_angle, "deg");
    tf.put("edge_radius", c.edge_radius, "m");
    const double cos_l = std::cos(incline * M_PI / 180.0);
    tf.put("width", (span + 2 * kToolOverhang * h) / cos_l,
           fmt::format("m: overhangs the workpiece by {} h on each side{}", kToolOverhang,
                       incline != 0.0 ? " (across y; the edge is 1/cos(lambda) longer)" : ""));
    if (incline != 0.0) tf.put("inclination_angle", incline, "deg: lambda_s, an oblique cut");
    tf.put("face_length", kFaceLength * h, fmt::format("m: {} h", kFaceLength));
    tf.put("origin", tip, tip_note);
  }
  if (compliant) {
    // A rigid body that does not turn, pulled along the path by its mount: the spring's
    // anchor starts at the tip (its centre of mass) and moves with the holder.
    const double b = 2 * n[1] * s;  // m: the width the forces are per (as the cut's probe measures it)
    const double k = c.tool_stiffness * b, mass = c.tool_mass * b;  // N/m, kg
    tf.put("dynamics", std::string("rigid_body"),
           fmt::format("a compliant tool: f_n = sqrt(k/m) / 2 pi = {:.4g} kHz", std::sqrt(k / mass) / (2e3 * M_PI)));
    tf.put("mass", mass, fmt::format("kg: tool_mass x the width b = {} m", b));
    tf.put("centre_of_mass", tip, "m: at the sharp tip, where the mount's spring pulls");
    const double I = mass * kFaceLength * h * kFaceLength * h / 6.0;  // kg m^2 (nominal: it does not turn)
    tf.put("inertia", std::array<double, 6>{I, I, I, 0.0, 0.0, 0.0}, "kg m^2: nominal, the tool does not turn");
    tf.put("rotation", std::string("prescribed"), "with no angular velocity: it does not turn");
    tf.put("fixed", std::string("y"), "held across the width");
    tf.put("initial_velocity", std::array<double, 3>{v, 0.0, 0.0}, "m/s: starts at the holder's speed");
    tf.put("holder_velocity", std::array<double, 3>{v, 0.0, 0.0}, "m/s: the holder moves at the cutting speed");
    tf.put("spring_stiffness", std::array<double, 3>{k, 0.0, k}, "N/m: tool_stiffness x b along x and z");
    tf.put("damping", 2.0 * c.tool_damping_ratio * std::sqrt(k * mass),
           fmt::format("N s/m: {} of critical, 2 sqrt(k m)", c.tool_damping_ratio));
  } else {
    tf.put("motion", std::string("velocity"), "");
    tf.put("velocity", std::array<double, 3>{v, 0.0, 0.0}, "m/s: the cutting speed along +x");
  }

  const double end_time = (length + lead) / v;
  out.section("[integrator]");
  Filler ig(table_in(root, "integrator"), "integrator", out, derived);
  ig.put("end_time", end_time,
         lead > 0 ? "s: the length of cut and the inclined edge's lead over the cutting speed"
                  : "s: the length of cut over the cutting speed");
  ig.put("scheme", std::string("verlet"), "explicit: docs/default-case.md says why");
  ig.put("dt_safety", 0.9, "1, of the stable step for 12 rods crowding one axis (bond formation)");

  out.section("[output]");
  Filler o(table_in(root, "output"), "output", out, derived);
  o.put("steady_from", (steady_from + lead) / v,
        fmt::format("s: forces averaged from {} m of travel on{}", steady_from,
                    lead > 0 ? " (of the edge's middle in the block)" : ""));
  o.put("frame_interval", end_time / kFrames, fmt::format("s: {} ParaView frames", kFrames + 1));
  o.put("series_interval", end_time / kSeriesRows, fmt::format("s: {} rows", kSeriesRows + 1));
  cs.cut_derived = out.text();
}

}  // namespace swarf
