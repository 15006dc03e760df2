// case_bodies.cpp: the helpers that the bodies' modules share (see case_tables.h): an array of
// tables' entries, a name that becomes CSV columns, a direction, a file relative to the case and a
// tool measured from its mesh file. The bodies' tables themselves are modules (setup/modules/:
// groups, motion, meshes, particles, flows, membrane, uniaxial).
#include <fmt/format.h>

#include <cctype>
#include <cmath>
#include <filesystem>

#include "io/mesh_file.h"
#include "io/path_kind.h"
#include "setup/case_tables.h"
#include "swarf/core/errors.h"
#include "tool_paths/tool_measure.h"

namespace swarf {
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

}  // namespace swarf
