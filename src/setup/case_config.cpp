// case_config.cpp: reading and checking case files (see case_config.h).
#include "setup/case_config.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <fmt/format.h>
#include <fstream>
#include <functional>
#include <map>
#include <set>
#include <sstream>
#include <toml++/toml.h>

#include "swarf/core/errors.h"

namespace swarf {
namespace {

std::string repr(const toml::node& n) {
  std::ostringstream os;
  if (auto s = n.as_string()) {
    os << '"' << s->get() << '"';
  } else if (auto f = n.as_floating_point()) {
    os << fmt::format("{}", f->get());
  } else {
    n.visit([&](auto&& v) { os << v; });
  }
  std::string out = os.str();
  if (out.size() > 80) out = out.substr(0, 77) + "...";
  return out;
}

// Reads the keys of one table, remembers which were used and rejects the rest.
class Reader {
 public:
  Reader(const toml::table* t, std::string prefix, const std::string& source,
         const std::set<std::string>& overridden)
      : t_(t), prefix_(std::move(prefix)), source_(source), overridden_(overridden) {}

  bool present() const { return t_ != nullptr; }

  [[noreturn]] void fail(const std::string& key, const toml::node* n, const std::string& problem) const {
    const std::string full = prefix_.empty() ? key : prefix_ + "." + key;
    std::string where = source_;
    if (overridden_.count(full)) {
      where += " (--set " + full + ")";
    } else if (n && n->source().begin.line > 0) {
      where += ":" + std::to_string(n->source().begin.line);
    }
    if (n) throw InputError(fmt::format("{}: key '{}' = {}: {}", where, full, repr(*n), problem));
    throw InputError(fmt::format("{}: key '{}': {}", where, full, problem));
  }

  bool has(const std::string& key) const { return t_ && t_->contains(key); }

  const toml::node* get(const std::string& key) {
    if (!t_) return nullptr;
    used_.insert(key);
    return t_->get(key);
  }

  double number(const std::string& key, double def, const std::function<const char*(double)>& check = {}) {
    const toml::node* n = get(key);
    if (!n) return def;
    double v;
    if (auto f = n->as_floating_point()) v = f->get();
    else if (auto i = n->as_integer()) v = static_cast<double>(i->get());
    else fail(key, n, "must be a number");
    if (std::isnan(v)) fail(key, n, "must not be nan");
    if (check) {
      if (const char* problem = check(v)) fail(key, n, problem);
    }
    return v;
  }

  int integer(const std::string& key, int def, int lo, int hi) {
    const toml::node* n = get(key);
    if (!n) return def;
    auto i = n->as_integer();
    if (!i) fail(key, n, "must be an integer");
    if (i->get() < lo || i->get() > hi) fail(key, n, fmt::format("must lie in [{}, {}]", lo, hi));
    return static_cast<int>(i->get());
  }

  bool boolean(const std::string& key, bool def) {
    const toml::node* n = get(key);
    if (!n) return def;
    auto b = n->as_boolean();
    if (!b) fail(key, n, "must be true or false");
    return b->get();
  }

  std::string string(const std::string& key, const std::string& def, const std::vector<std::string>& allowed = {}) {
    const toml::node* n = get(key);
    if (!n) return def;
    auto s = n->as_string();
    if (!s) fail(key, n, "must be a string");
    if (!allowed.empty()) {
      bool ok = false;
      for (const auto& a : allowed) ok = ok || a == s->get();
      if (!ok) {
        std::string list;
        for (const auto& a : allowed) list += (list.empty() ? "\"" : ", \"") + a + "\"";
        fail(key, n, "must be one of " + list);
      }
    }
    return s->get();
  }

  std::vector<double> numbers(const std::string& key, const std::vector<double>& def) {
    const toml::node* n = get(key);
    if (!n) return def;
    auto a = n->as_array();
    if (!a) fail(key, n, "must be an array of numbers");
    std::vector<double> out;
    for (const auto& e : *a) {
      if (auto f = e.as_floating_point()) out.push_back(f->get());
      else if (auto i = e.as_integer()) out.push_back(static_cast<double>(i->get()));
      else fail(key, n, "must be an array of numbers");
      if (!std::isfinite(out.back())) fail(key, n, "entries must be finite");
    }
    return out;
  }

  std::array<double, 3> vec3(const std::string& key, const std::array<double, 3>& def) {
    const toml::node* n = get(key);
    if (!n) return def;
    auto v = numbers(key, {});
    if (v.size() != 3) fail(key, n, "must be an array of three numbers");
    return {v[0], v[1], v[2]};
  }

  std::array<int, 3> ivec3(const std::string& key, const std::array<int, 3>& def) {
    const toml::node* n = get(key);
    if (!n) return def;
    auto a = n->as_array();
    if (!a || a->size() != 3) fail(key, n, "must be an array of three integers");
    std::array<int, 3> out{};
    for (int c = 0; c < 3; ++c) {
      auto i = (*a)[c].as_integer();
      if (!i || i->get() <= 0 || i->get() > 100000) fail(key, n, "must be three positive integers");
      out[c] = static_cast<int>(i->get());
    }
    return out;
  }

  // Rejects every key that no reader asked for.
  void finish() const {
    if (!t_) return;
    for (const auto& [k, v] : *t_) {
      const std::string key(k.str());
      if (!used_.count(key)) {
        const std::string full = prefix_.empty() ? key : prefix_ + "." + key;
        std::string where = source_;
        if (overridden_.count(full)) where += " (--set " + full + ")";
        else if (v.source().begin.line > 0) where += ":" + std::to_string(v.source().begin.line);
        throw InputError(fmt::format("{}: unknown key '{}' (see docs/case-reference.md)", where, full));
      }
    }
  }

 private:
  const toml::table* t_;
  std::string prefix_;
  const std::string& source_;
  const std::set<std::string>& overridden_;
  std::set<std::string> used_;
};

const char* positive(double v) { return v > 0.0 && std::isfinite(v) ? nullptr : "must be positive and finite"; }
const char* positive_or_inf(double v) { return v > 0.0 ? nullptr : "must be positive (inf allowed)"; }
const char* non_negative(double v) { return v >= 0.0 && std::isfinite(v) ? nullptr : "must be >= 0 and finite"; }

using Vec3Array = std::array<double, 3>;

// Applies one "a.b.c=value" override to the tree.
void apply_override(toml::table& root, const std::string& arg, std::set<std::string>& overridden) {
  const auto eq = arg.find('=');
  if (eq == std::string::npos || eq == 0)
    throw InputError(fmt::format("--set '{}': expected key=value (for example integrator.dt=2e-9)", arg));
  const std::string key = arg.substr(0, eq), text = arg.substr(eq + 1);
  toml::table parsed;
  try {
    parsed = toml::parse("v = " + text);
  } catch (const toml::parse_error&) {
    // A bare word is taken as a string: --set integrator.scheme=verlet
    parsed.insert_or_assign("v", text);
  }
  std::vector<std::string> parts;
  {
    std::size_t start = 0;
    while (true) {
      auto dot = key.find('.', start);
      parts.push_back(key.substr(start, dot - start));
      if (dot == std::string::npos) break;
      start = dot + 1;
    }
  }
  // Index parsing for array components (mesh.0.origin.2: the origin's z).
  auto index_of = [&](const toml::array& a, const std::string& part, const std::string& where) {
    char* end = nullptr;
    const long idx = std::strtol(part.c_str(), &end, 10);
    if (part.empty() || *end || idx < 0 || static_cast<std::size_t>(idx) >= a.size())
      throw InputError(fmt::format("--set '{}': '{}' is not an index of the array '{}' ({} entries)", arg, part, where,
                                   a.size()));
    return static_cast<std::size_t>(idx);
  };
  toml::node* cur = &root;
  std::string path;
  for (std::size_t p = 0; p + 1 < parts.size(); ++p) {
    const std::string& part = parts[p];
    const std::string parent = path;
    path += (path.empty() ? "" : ".") + part;
    if (part.empty()) throw InputError(fmt::format("--set '{}': empty key component", arg));
    if (auto t = cur->as_table()) {
      if (!t->contains(part)) t->insert(part, toml::table{});
      cur = t->get(part);
    } else if (auto a = cur->as_array()) {
      cur = a->get(index_of(*a, part, parent));
    } else {
      throw InputError(fmt::format("--set '{}': '{}' is not a table", arg, path));
    }
  }
  if (auto a = cur->as_array()) {  // one entry of an array: the last part is its index
    const std::size_t idx = index_of(*a, parts.back(), path);
    a->replace(a->cbegin() + static_cast<std::ptrdiff_t>(idx), *parsed.get("v"));
  } else if (auto t = cur->as_table()) {
    t->insert_or_assign(parts.back(), *parsed.get("v"));
  } else {
    throw InputError(fmt::format("--set '{}': the parent of '{}' is not a table", arg, parts.back()));
  }
  // Record the key as the reader will name it (array indices dropped: group.0.x -> group.x).
  std::string named;
  for (const auto& part : parts) {
    if (!part.empty() && std::all_of(part.begin(), part.end(), ::isdigit)) continue;
    named += (named.empty() ? "" : ".") + part;
  }
  overridden.insert(named);
}

std::string resolve(const std::string& file, const std::string& directory) {
  std::filesystem::path p(file);
  if (p.is_relative()) p = std::filesystem::path(directory) / p;
  return p.string();
}

// Reads an array of [x, y, z] triples (unit for messages).
std::vector<std::array<double, 3>> read_triples(Reader& r, const std::string& key, const char* unit) {
  std::vector<std::array<double, 3>> out;
  const toml::node* td = r.get(key);
  if (!td) return out;
  auto a = td->as_array();
  if (!a) r.fail(key, td, fmt::format("must be an array of [x, y, z] in {}", unit));
  for (const auto& row : *a) {
    auto ra = row.as_array();
    if (!ra || ra->size() != 3) r.fail(key, td, fmt::format("every entry must be [x, y, z] in {}", unit));
    std::array<double, 3> v{};
    for (int c = 0; c < 3; ++c) {
      if (auto f = (*ra)[c].as_floating_point()) v[c] = f->get();
      else if (auto i = (*ra)[c].as_integer()) v[c] = static_cast<double>(i->get());
      else r.fail(key, td, "entries must be numbers");
      if (!std::isfinite(v[c])) r.fail(key, td, "entries must be finite");
    }
    out.push_back(v);
  }
  return out;
}

// Reads a CSV velocity table 'time,vx,vy,vz' (header line first) for motion = "velocity_table".
void read_velocity_csv(Reader& r, const std::string& path, MotionSettings& m) {
  std::ifstream in(path);
  if (!in) r.fail("velocity_file", r.get("velocity_file"), "file not found or unreadable: " + path);
  std::string line;
  int lineno = 0;
  while (std::getline(in, line)) {
    ++lineno;
    if (lineno == 1 || line.empty()) continue;  // header
    std::replace(line.begin(), line.end(), ',', ' ');
    std::istringstream ls(line);
    double t, vx, vy, vz;
    if (!(ls >> t >> vx >> vy >> vz) || !std::isfinite(t + vx + vy + vz))
      r.fail("velocity_file", r.get("velocity_file"),
             fmt::format("{}:{}: expected 'time,vx,vy,vz' in s and m/s", path, lineno));
    m.table_time.push_back(t);
    m.table_velocity.push_back({vx, vy, vz});
  }
}

// The motion keys shared by [[group]] and [[mesh]], with their checks.
void read_motion(Reader& r, const std::string& directory, MotionSettings& m) {
  m.kind = r.string("motion", "fixed", {"fixed", "velocity", "ramp", "table", "velocity_table"});
  m.velocity = r.vec3("velocity", m.velocity);
  m.ramp_time = r.number("ramp_time", m.ramp_time, positive);
  m.table_time = r.numbers("table_time", {});
  m.table_displacement = read_triples(r, "table_displacement", "m");
  m.table_velocity = read_triples(r, "table_velocity", "m/s");
  m.velocity_file = r.string("velocity_file", "");
  // Every key only where the motion uses it.
  const std::map<std::string, std::vector<std::string>> uses{
      {"velocity", {"velocity", "ramp"}},     {"ramp_time", {"ramp"}},
      {"table_time", {"table", "velocity_table"}}, {"table_displacement", {"table"}},
      {"table_velocity", {"velocity_table"}}, {"velocity_file", {"velocity_table"}}};
  for (const auto& [key, kinds] : uses)
    if (r.has(key) && std::find(kinds.begin(), kinds.end(), m.kind) == kinds.end())
      r.fail(key, r.get(key), fmt::format("is not used with motion = \"{}\"", m.kind));
  if ((m.kind == "velocity" || m.kind == "ramp") && !r.has("velocity"))
    r.fail("velocity", nullptr, fmt::format("motion = \"{}\" needs a velocity [vx, vy, vz] in m/s", m.kind));
  if (m.kind == "ramp" && !r.has("ramp_time"))
    r.fail("ramp_time", nullptr, "motion = \"ramp\" needs ramp_time in s");
  if (m.kind == "velocity_table") {
    if (!m.velocity_file.empty()) {
      if (r.has("table_time") || r.has("table_velocity"))
        r.fail("velocity_file", r.get("velocity_file"), "give either velocity_file or table_time/table_velocity");
      read_velocity_csv(r, resolve(m.velocity_file, directory), m);
    }
    if (m.table_time.size() < 2 || m.table_time.size() != m.table_velocity.size())
      r.fail("table_time", r.get("table_time"),
             "motion = \"velocity_table\" needs table_time (s) and table_velocity (m/s) of equal length >= 2, "
             "or velocity_file");
  }
  if (m.kind == "table") {
    if (m.table_time.size() < 2 || m.table_time.size() != m.table_displacement.size())
      r.fail("table_time", r.get("table_time"),
             "motion = \"table\" needs table_time (s) and table_displacement (m) of equal length >= 2");
    for (double u : m.table_displacement[0])
      if (u != 0.0)
        r.fail("table_displacement", r.get("table_displacement"), "must start at [0, 0, 0] m (no jump at t = 0)");
  }
  if (m.kind == "table" || m.kind == "velocity_table") {
    const char* key = r.has("table_time") ? "table_time" : "velocity_file";
    if (m.table_time[0] != 0.0) r.fail(key, r.get(key), "the table must start at 0 s");
    for (std::size_t k = 1; k < m.table_time.size(); ++k)
      if (!(m.table_time[k] > m.table_time[k - 1])) r.fail(key, r.get(key), "times must be strictly ascending");
  }
}

void check_name(Reader& r, const std::string& name) {
  for (char ch : name)
    if (!(std::isalnum(static_cast<unsigned char>(ch)) || ch == '_' || ch == '-'))
      r.fail("name", r.get("name"), "use letters, digits, '_' and '-' only (it names CSV columns)");
  if (name.empty()) r.fail("name", r.get("name"), "must not be empty");
}

void read_groups(const toml::table& root, const std::string& source, const std::string& directory,
                 const std::set<std::string>& ov,
                 CaseSettings& cs) {
  const toml::node* n = root.get("group");
  if (!n) return;
  auto arr = n->as_array();
  if (!arr || !arr->is_array_of_tables())
    throw InputError(fmt::format("{}: 'group' must be an array of tables ([[group]])", source));
  std::set<std::string> names;
  for (std::size_t g = 0; g < arr->size(); ++g) {
    Reader r((*arr)[g].as_table(), "group", source, ov);
    GroupSettings gs;
    gs.name = r.string("name", fmt::format("group{}", g));
    if (!names.insert(gs.name).second) r.fail("name", r.get("name"), "two groups have this name");
    gs.side = r.string("side", "", {"x-", "x+", "y-", "y+", "z-", "z+"});
    gs.layers = r.integer("layers", 1, 1, 1000);
    gs.box_min = r.vec3("box_min", gs.box_min);
    gs.box_max = r.vec3("box_max", gs.box_max);
    gs.dofs = r.string("dofs", "xyz", {"x", "y", "z", "xy", "xz", "yz", "xyz"});
    read_motion(r, directory, gs.motion);
    const bool has_box = r.has("box_min") || r.has("box_max");
    if (!gs.side.empty() && has_box) {
      const char* key = r.has("box_min") ? "box_min" : "box_max";
      r.fail(key, r.get(key), "give either side (with layers) or box_min/box_max, not both");
    }
    if (gs.side.empty() && r.has("layers")) r.fail("layers", r.get("layers"), "layers needs side");
    if (gs.side.empty() && !has_box) r.fail("side", nullptr, "a group needs side = \"x-\" ... or box_min/box_max (m)");
    for (int c = 0; c < 3; ++c)
      if (gs.box_min[c] > gs.box_max[c]) r.fail("box_min", r.get("box_min"), "must not exceed box_max");
    check_name(r, gs.name);
    r.finish();
    cs.groups.push_back(gs);
  }
}

void read_contacts_and_bodies(const toml::table& root, const std::string& source, const std::string& directory,
                              const std::set<std::string>& ov, CaseSettings& cs) {
  if (const toml::table* t = root.get_as<toml::table>("contact")) {
    Reader r(t, "contact", source, ov);
    auto& c = cs.contact;
    c.enabled = true;
    c.youngs_modulus = r.number("youngs_modulus", c.youngs_modulus, positive);
    c.poisson_ratio = r.number("poisson_ratio", c.poisson_ratio,
                               [](double v) { return v > -1 && v < 0.5 ? nullptr : "must lie in (-1, 0.5)"; });
    c.restitution = r.number("restitution", c.restitution,
                             [](double v) { return v >= 0.01 && v <= 1 ? nullptr : "must lie in [0.01, 1]"; });
    c.friction = r.number("friction", c.friction, non_negative);
    c.friction_law = r.string("friction_law", c.friction_law, {"spring", "regularized", "none"});
    c.regularization_speed = r.number("regularization_speed", c.regularization_speed, positive);
    c.tangential_damping = r.number("tangential_damping", c.tangential_damping,
                                    [](double v) { return v >= 0 && v <= 10 ? nullptr : "must lie in [0, 10]"; });
    c.skin = r.number("skin", c.skin, [](double v) { return v > 0 && v <= 2 ? nullptr : "must lie in (0, 2]"; });
    r.finish();
  }
  if (const toml::table* t = root.get_as<toml::table>("environment")) {
    Reader r(t, "environment", source, ov);
    cs.gravity = r.vec3("gravity", cs.gravity);
    r.finish();
  }
  if (const toml::node* n = root.get("mesh")) {
    auto arr = n->as_array();
    if (!arr || !arr->is_array_of_tables())
      throw InputError(fmt::format("{}: 'mesh' must be an array of tables ([[mesh]])", source));
    std::set<std::string> names;
    for (std::size_t k = 0; k < arr->size(); ++k) {
      Reader r((*arr)[k].as_table(), "mesh", source, ov);
      MeshSettings m;
      m.name = r.string("name", fmt::format("mesh{}", k));
      check_name(r, m.name);
      if (!names.insert(m.name).second) r.fail("name", r.get("name"), "two meshes have this name");
      m.file = r.string("file", "");
      m.scale = r.number("scale", m.scale, positive);
      m.origin = r.vec3("origin", m.origin);
      m.edge1 = r.vec3("edge1", m.edge1);
      m.edge2 = r.vec3("edge2", m.edge2);
      if (const toml::node* dn = r.get("divisions")) {
        auto v = r.numbers("divisions", {});
        if (v.size() != 2 || v[0] < 1 || v[1] < 1 || v[0] != std::floor(v[0]) || v[1] != std::floor(v[1]) ||
            v[0] * v[1] > 1e7)
          r.fail("divisions", dn, "must be two positive integers [n1, n2]");
        m.divisions = {static_cast<int>(v[0]), static_cast<int>(v[1])};
      }
      m.tool = r.has("rake_angle");
      m.rake_angle = r.number("rake_angle", m.rake_angle);
      m.clearance_angle = r.number("clearance_angle", m.clearance_angle);
      m.edge_radius = r.number("edge_radius", m.edge_radius, non_negative);
      m.width = r.number("width", m.width, non_negative);
      m.face_length = r.number("face_length", m.face_length, non_negative);
      for (const char* key : {"clearance_angle", "edge_radius", "width", "face_length"})
        if (!m.tool && r.has(key)) r.fail(key, r.get(key), "is a tool key: give rake_angle (deg) to make a tool");
      if (m.tool && (!r.has("width") || !r.has("face_length")))
        r.fail("rake_angle", r.get("rake_angle"), "a tool needs width (m) and face_length (m) too");
      read_motion(r, directory, m.motion);
      m.youngs_modulus = r.number("youngs_modulus", m.youngs_modulus, positive_or_inf);
      m.poisson_ratio = r.number("poisson_ratio", m.poisson_ratio,
                                 [](double v) { return v > -1 && v < 0.5 ? nullptr : "must lie in (-1, 0.5)"; });
      const bool rect = r.has("edge1") || r.has("edge2") || r.has("divisions");
      if ((!m.file.empty() ? 1 : 0) + (rect ? 1 : 0) + (m.tool ? 1 : 0) > 1)
        r.fail("file", r.get("file") ? r.get("file") : r.get("rake_angle"),
               "give one of: file, a rectangle (edge1, edge2, divisions) or a tool (rake_angle, ...)");
      if (m.file.empty() && !m.tool && !(r.has("edge1") && r.has("edge2")))
        r.fail("file", nullptr,
               "a mesh needs file = \"...stl|obj\", a rectangle (origin, edge1, edge2 in m) or a tool (rake_angle, ...)");
      if (!m.file.empty()) {
        m.file = resolve(m.file, directory);
        if (!std::filesystem::exists(m.file)) r.fail("file", r.get("file"), "file not found: " + m.file);
      } else if (m.tool) {
        // checked by the generator (names the angle or size)
      } else {
        const Vec3Array e1 = m.edge1, e2 = m.edge2;
        const double cx = e1[1] * e2[2] - e1[2] * e2[1], cy = e1[2] * e2[0] - e1[0] * e2[2],
                     cz = e1[0] * e2[1] - e1[1] * e2[0];
        if (!(cx * cx + cy * cy + cz * cz > 0.0)) r.fail("edge2", r.get("edge2"), "edge1 and edge2 must span a rectangle");
      }
      r.finish();
      cs.meshes.push_back(m);
    }
  }
  if (const toml::node* n = root.get("particle")) {
    auto arr = n->as_array();
    if (!arr || !arr->is_array_of_tables())
      throw InputError(fmt::format("{}: 'particle' must be an array of tables ([[particle]])", source));
    for (std::size_t k = 0; k < arr->size(); ++k) {
      Reader r((*arr)[k].as_table(), "particle", source, ov);
      ParticleSettings p;
      p.position = r.vec3("position", p.position);
      p.velocity = r.vec3("velocity", p.velocity);
      p.angular_velocity = r.vec3("angular_velocity", p.angular_velocity);
      p.radius = r.number("radius", 0.0, positive);
      if (!r.has("radius")) r.fail("radius", nullptr, "every particle needs a radius in m");
      if (!r.has("position")) r.fail("position", nullptr, "every particle needs a position [x, y, z] in m");
      r.finish();
      cs.particles.push_back(p);
    }
  }
  if (const toml::table* t = root.get_as<toml::table>("particles")) {
    Reader r(t, "particles", source, ov);
    cs.particles_file.file = resolve(r.string("file", ""), directory);
    cs.particles_file.radius = r.number("radius", 0.0, positive);
    if (!r.has("file")) r.fail("file", nullptr, "[particles] needs file = \"...\" (columns id x y z vx vy vz)");
    if (!r.has("radius")) r.fail("radius", nullptr, "[particles] needs radius in m");
    if (!std::filesystem::exists(cs.particles_file.file))
      r.fail("file", r.get("file"), "file not found: " + cs.particles_file.file);
    r.finish();
  }
  if ((!cs.meshes.empty() || !cs.particles.empty() || !cs.particles_file.file.empty()) && !cs.contact.enabled)
    throw InputError(fmt::format("{}: meshes and free particles interact only through contacts: add a [contact] "
                                 "table (youngs_modulus, poisson_ratio, restitution, friction)", source));
}

}  // namespace

CaseSettings parse_case(const std::string& text, const std::string& source, const std::vector<std::string>& overrides,
                        const std::string& directory) {
  toml::table root;
  try {
    root = toml::parse(text, source);
  } catch (const toml::parse_error& e) {
    throw InputError(fmt::format("{}:{}:{}: TOML syntax error: {}", source, e.source().begin.line,
                                 e.source().begin.column, e.description()));
  }
  std::set<std::string> ov;
  for (const auto& o : overrides) apply_override(root, o, ov);

  CaseSettings cs;
  cs.text = text;
  cs.source = source;
  cs.directory = directory;
  cs.overrides = overrides;
  {
    std::ostringstream os;
    os << root;
    cs.effective_toml = os.str();
  }
  // Top level: only known tables.
  const std::set<std::string> tables{"workpiece", "material", "rod",      "integrator", "group",       "uniaxial",
                                     "contact",   "mesh",     "particle", "particles",  "environment", "output"};
  const std::set<std::string> arrays_of_tables{"group", "mesh", "particle"};
  for (const auto& [k, v] : root) {
    const std::string key(k.str());
    if (!tables.count(key)) {
      std::string where = source;
      if (ov.count(key) || !v.source().begin.line) where += " (--set)";
      else where += ":" + std::to_string(v.source().begin.line);
      throw InputError(fmt::format("{}: unknown table or key '{}' (known: workpiece, material, rod, integrator, "
                                   "group, uniaxial, contact, mesh, particle, particles, environment, output)",
                                   where, key));
    }
    if (!arrays_of_tables.count(key) && !v.is_table())
      throw InputError(fmt::format("{}: '{}' must be a table ([{}])", source, key, key));
  }
  auto table = [&](const char* name) -> const toml::table* { return root.get_as<toml::table>(name); };

  if (table("workpiece")) {
    Reader r(table("workpiece"), "workpiece", source, ov);
    auto& w = cs.workpiece;
    w.enabled = true;
    w.lattice_file = r.string("lattice_file", "");
    w.cells = r.ivec3("cells", w.cells);
    w.size = r.vec3("size", w.size);
    w.radius = r.number("radius", w.radius, positive);
    w.bond_tolerance = r.number("bond_tolerance", w.bond_tolerance,
                                [](double v) { return v >= 0 && v < 0.2 ? nullptr : "must lie in [0, 0.2)"; });
    w.periodic_width = r.boolean("periodic_width", w.periodic_width);
    const bool has_cells = r.get("cells") != nullptr, has_size = r.get("size") != nullptr;
    if (w.periodic_width && !has_cells)
      r.fail("periodic_width", r.get("periodic_width"),
             "a periodic width needs the lattice generated by cells = [NX, NY, NZ] (the period is NY cells)");
    if (w.periodic_width && has_cells && w.cells[1] < 2)
      r.fail("cells", r.get("cells"), "a periodic width needs at least 2 cells across y (NY >= 2)");
    if (!w.lattice_file.empty() && (r.has("radius") || r.has("bond_tolerance")))
      r.fail(r.has("radius") ? "radius" : "bond_tolerance", r.get(r.has("radius") ? "radius" : "bond_tolerance"),
             "radii and bonds come from lattice_file; remove this key");
    if (!w.lattice_file.empty() && (has_cells || has_size))
      r.fail("lattice_file", r.get("lattice_file"), "give either lattice_file or cells/size, not both");
    if (has_cells && has_size) r.fail("size", r.get("size"), "give either cells or size, not both");
    if (has_size)
      for (double s : w.size)
        if (!(s > 0.0) || !std::isfinite(s)) r.fail("size", r.get("size"), "must be three positive lengths in m");
    if (w.lattice_file.empty() && !has_cells && !has_size)
      r.fail("cells", nullptr, "the workpiece needs cells = [NX, NY, NZ], size = [LX, LY, LZ] (m) or lattice_file");
    if (!w.lattice_file.empty()) {
      std::filesystem::path p(w.lattice_file);
      if (p.is_relative()) p = std::filesystem::path(directory) / p;
      if (!std::filesystem::exists(p)) r.fail("lattice_file", r.get("lattice_file"), "file not found: " + p.string());
      w.lattice_file = p.string();
    }
    r.finish();
  }
  {
    Reader r(table("material"), "material", source, ov);
    cs.material.density = r.number("density", cs.material.density, positive);
    cs.material.mass_basis = r.string("mass_basis", cs.material.mass_basis, {"cell", "sphere"});
    auto& mt = cs.material;
    mt.macroscopic = r.has("youngs_modulus");
    mt.youngs_modulus = r.number("youngs_modulus", mt.youngs_modulus, positive);
    mt.yield_stress = r.number("yield_stress", mt.yield_stress, positive_or_inf);
    mt.hardening_modulus = r.number("hardening_modulus", mt.hardening_modulus, non_negative);
    mt.tensile_strength = r.number("tensile_strength", mt.tensile_strength, positive_or_inf);
    mt.poisson_ratio = r.number("poisson_ratio", mt.poisson_ratio,
                                [](double v) { return v > -1 && v < 0.5 ? nullptr : "must lie in (-1, 0.5)"; });
    if (!mt.macroscopic)
      for (const char* key : {"yield_stress", "hardening_modulus", "tensile_strength", "poisson_ratio"})
        if (r.has(key)) r.fail(key, r.get(key), "macroscopic properties need material.youngs_modulus (Pa) too");
    if (mt.macroscopic && !(mt.hardening_modulus < mt.youngs_modulus))
      r.fail("hardening_modulus", r.get("hardening_modulus"),
             fmt::format("must be below material.youngs_modulus = {} Pa", mt.youngs_modulus));
    r.finish();
  }
  {
    Reader r(table("rod"), "rod", source, ov);
    auto& d = cs.rod;
    if (cs.material.macroscopic)
      for (const char* key : {"youngs_modulus", "yield_strain", "hardening_modulus", "tensile_strength"})
        if (r.has(key))
          r.fail(key, r.get(key), "the rod law comes from the [material] properties here; give one or the other");
    d.youngs_modulus = r.number("youngs_modulus", d.youngs_modulus, positive);
    d.area = r.number("area", d.area, non_negative);
    d.yield_strain = r.number("yield_strain", d.yield_strain, positive_or_inf);
    d.hardening_modulus = r.number("hardening_modulus", d.hardening_modulus, non_negative);
    if (!(d.hardening_modulus < d.youngs_modulus))
      r.fail("hardening_modulus", r.get("hardening_modulus"),
             fmt::format("must be below rod.youngs_modulus = {} Pa", d.youngs_modulus));
    d.tensile_strength = r.number("tensile_strength", d.tensile_strength, positive_or_inf);
    d.damping_ratio = r.number("damping_ratio", d.damping_ratio,
                               [](double v) { return v >= 0 && v <= 10 ? nullptr : "must lie in [0, 10]"; });
    r.finish();
  }
  {
    Reader r(table("integrator"), "integrator", source, ov);
    auto& g = cs.integrator;
    g.scheme = r.string("scheme", g.scheme, {"auto", "verlet", "newmark"});
    g.dt = r.number("dt", g.dt, non_negative);
    g.dt_safety = r.number("dt_safety", g.dt_safety,
                           [](double v) { return v > 0 && v <= 1 ? nullptr : "must lie in (0, 1]"; });
    g.allow_unstable_dt = r.boolean("allow_unstable_dt", g.allow_unstable_dt);
    g.end_time = r.number("end_time", g.end_time, non_negative);
    g.max_step_displacement = r.number("max_step_displacement", g.max_step_displacement, positive);
    g.beta = r.number("beta", g.beta, [](double v) { return v > 0 && v <= 0.5 ? nullptr : "must lie in (0, 0.5] (beta = 0 is the explicit scheme: use scheme = \"verlet\")"; });
    g.gamma = r.number("gamma", g.gamma, [](double v) { return v >= 0.5 && v <= 1 ? nullptr : "must lie in [0.5, 1]"; });
    g.tolerance = r.number("tolerance", g.tolerance,
                           [](double v) { return v > 0 && v < 1 ? nullptr : "must lie in (0, 1)"; });
    g.max_iterations = r.integer("max_iterations", g.max_iterations, 2, 10000);
    g.dt_min = r.number("dt_min", g.dt_min, non_negative);
    g.dt_max = r.number("dt_max", g.dt_max, non_negative);
    if (g.dt_min > 0 && g.dt_max > 0 && g.dt_min > g.dt_max)
      r.fail("dt_min", r.get("dt_min"), fmt::format("must not exceed dt_max = {} s", g.dt_max));
    g.iterations_grow = r.integer("iterations_grow", g.iterations_grow, 1, 10000);
    g.iterations_shrink = r.integer("iterations_shrink", g.iterations_shrink, 2, 10000);
    if (g.iterations_grow >= g.iterations_shrink)
      r.fail("iterations_grow", r.get("iterations_grow"), "must be below iterations_shrink");
    if (g.iterations_shrink > g.max_iterations)
      r.fail("iterations_shrink", r.get("iterations_shrink"), "must not exceed max_iterations");
    auto factor_above_1 = [](double v) { return v > 1 && v <= 10 ? nullptr : "must lie in (1, 10]"; };
    auto factor_below_1 = [](double v) { return v > 0 && v < 1 ? nullptr : "must lie in (0, 1)"; };
    g.grow_factor = r.number("grow_factor", g.grow_factor, factor_above_1);
    g.shrink_factor = r.number("shrink_factor", g.shrink_factor, factor_below_1);
    g.reject_factor = r.number("reject_factor", g.reject_factor, factor_below_1);
    g.relaxation = r.number("relaxation", g.relaxation, [](double v) { return v > 0 && v <= 1 ? nullptr : "must lie in (0, 1]"; });
    r.finish();
  }
  read_groups(root, source, directory, ov, cs);
  if (const toml::table* ut = table("uniaxial")) {
    Reader r(ut, "uniaxial", source, ov);
    auto& u = cs.uniaxial;
    u.enabled = true;
    u.axis = r.string("axis", u.axis, {"x", "y", "z"});
    u.grip_layers = r.integer("grip_layers", u.grip_layers, 1, 1000);
    u.grip_dofs = r.string("grip_dofs", u.grip_dofs, {"axis", "xyz"});
    u.strain_path = r.numbers("strain_path", u.strain_path);
    if (u.strain_path.size() < 2 || u.strain_path[0] != 0.0)
      r.fail("strain_path", r.get("strain_path"), "needs at least two turning points, the first 0");
    for (double s : u.strain_path)
      if (std::abs(s) >= 0.5) r.fail("strain_path", r.get("strain_path"), "strains must lie in (-0.5, 0.5)");
    for (std::size_t k = 1; k < u.strain_path.size(); ++k)
      if (u.strain_path[k] == u.strain_path[k - 1])
        r.fail("strain_path", r.get("strain_path"), "consecutive turning points must differ");
    u.strain_rate = r.number("strain_rate", u.strain_rate, positive);
    r.finish();
    for (const auto& g : cs.groups)
      if (g.name == "grip_min" || g.name == "grip_max")
        throw InputError(fmt::format("{}: group name '{}' is reserved for the [uniaxial] grips", source, g.name));
  }
  read_contacts_and_bodies(root, source, directory, ov, cs);
  if (cs.uniaxial.enabled && !cs.workpiece.enabled)
    throw InputError(fmt::format("{}: [uniaxial] needs a [workpiece] (the bar)", source));
  if (!cs.workpiece.enabled && cs.particles.empty() && cs.particles_file.file.empty())
    throw InputError(fmt::format("{}: no particles: give a [workpiece], [[particle]] tables or [particles] file", source));
  {
    Reader r(table("output"), "output", source, ov);
    auto& o = cs.output;
    o.frame_interval = r.number("frame_interval", o.frame_interval, non_negative);
    o.series_interval = r.number("series_interval", o.series_interval, non_negative);
    o.vtk = r.boolean("vtk", o.vtk);
    o.rods_in_vtk = r.boolean("rods_in_vtk", o.rods_in_vtk);
    o.plots = r.boolean("plots", o.plots);
    o.progress = r.boolean("progress", o.progress);
    o.steady_from = r.number("steady_from", o.steady_from, non_negative);
    o.checkpoint_every = r.integer("checkpoint_every", static_cast<int>(o.checkpoint_every), 0, 1000000000);
    o.orientations = r.boolean("orientations", o.orientations);
    r.finish();
  }
  if (!cs.uniaxial.enabled && !(cs.integrator.end_time > 0.0))
    throw InputError(fmt::format("{}: key 'integrator.end_time' must be set (s) when there is no [uniaxial] path",
                                 source));
  return cs;
}

CaseSettings load_case(const std::string& path, const std::vector<std::string>& overrides) {
  std::ifstream in(path);
  if (!in) throw InputError(fmt::format("case file '{}' cannot be read (missing or no permission)", path));
  std::stringstream ss;
  ss << in.rdbuf();
  auto dir = std::filesystem::path(path).parent_path();
  return parse_case(ss.str(), path, overrides, dir.empty() ? "." : dir.string());
}

}  // namespace swarf
