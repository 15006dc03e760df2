// mesh_file.cpp: STL and OBJ reading, STL writing (see mesh_file.h).
#include "io/mesh_file.h"

#include <fmt/format.h>

#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <sstream>
#include <string_view>

#include "io/atomic_file.h"
#include "io/path_kind.h"
#include "swarf/core/bounds.h"
#include "swarf/core/errors.h"

namespace swarf {
namespace {

std::string lower_ext(const std::string& path) {
  std::string e = std::filesystem::path(path).extension().string();
  for (auto& ch : e) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
  return e;
}

// Vertices of STL facets are not shared in the file; weld exact duplicates so the mesh has
// connectivity (needed for watertightness checks and smaller outputs).
int weld(std::map<std::array<double, 3>, int>& index, TriangleMesh& m, const Vec3& p) {
  const std::array<double, 3> key{p[0], p[1], p[2]};
  auto it = index.find(key);
  if (it != index.end()) return it->second;
  const int id = static_cast<int>(m.vertices.size());
  m.vertices.push_back(p);
  index.emplace(key, id);
  return id;
}

// A whole token as a finite number: "3abc", "nan", "inf" and "1e999" are not numbers.
std::optional<double> finite_number(std::string_view t) {
  double v = 0;
  const auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), v);
  if (ec != std::errc() || end != t.data() + t.size() || !std::isfinite(v)) return std::nullopt;
  return v;
}

// A whole token as an integer that fits in 64 bits: "3.7", "3abc" and 99999999999999999999 are not.
std::optional<long long> whole_number(std::string_view t) {
  long long v = 0;
  const auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), v);
  if (ec != std::errc() || end != t.data() + t.size()) return std::nullopt;
  return v;
}

// A vertex of the file in m, or why not: a coordinate that is not finite, or beyond
// kMaxMeshCoordinate once scaled (tested before the product, which could overflow).
std::optional<std::string> bad_vertex(const Vec3& raw, double scale) {
  for (int c = 0; c < 3; ++c) {
    if (!finite_bits(raw[c])) return "is not finite";
    if (std::abs(raw[c]) > kMaxMeshCoordinate / scale)
      return fmt::format("lies beyond {:g} m once scaled by {} (a unit or scale mistake?)", kMaxMeshCoordinate, scale);
  }
  return std::nullopt;
}

TriangleMesh read_stl(const std::string& path, double scale) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(fmt::format("mesh file '{}' cannot be read", path));
  std::string data((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  TriangleMesh m;
  m.name = std::filesystem::path(path).stem().string();
  std::map<std::array<double, 3>, int> index;
  // Binary: 80-byte header, uint32 count, 50 bytes per facet. An ASCII file starts with
  // "solid" but a binary one may too, so the size decides.
  bool binary = false;
  if (data.size() >= 84) {
    std::uint32_t n = 0;
    std::memcpy(&n, data.data() + 80, 4);
    binary = data.size() == 84 + 50 * static_cast<std::size_t>(n);
  }
  if (binary) {
    std::uint32_t n = 0;
    std::memcpy(&n, data.data() + 80, 4);
    for (std::uint32_t t = 0; t < n; ++t) {
      const char* f = data.data() + 84 + 50 * static_cast<std::size_t>(t);
      std::array<int, 3> tri{};
      for (int k = 0; k < 3; ++k) {
        float xyz[3];
        std::memcpy(xyz, f + 12 + 12 * k, 12);
        // (as floats: converting a signalling NaN to double raises FE_INVALID)
        if (!finite_bits(xyz[0]) || !finite_bits(xyz[1]) || !finite_bits(xyz[2]))
          throw InputError(fmt::format("mesh file '{}': facet {} vertex {} is not finite", path, t, k));
        const Vec3 raw(xyz[0], xyz[1], xyz[2]);
        // (a NaN would be welded onto whatever vertex the map's ordering finds for it)
        if (const auto why = bad_vertex(raw, scale))
          throw InputError(fmt::format("mesh file '{}': facet {} vertex {} {}", path, t, k, *why));
        tri[k] = weld(index, m, raw * scale);
      }
      m.triangles.push_back(tri);
    }
    return m;
  }
  if (data.rfind("solid", 0) != 0)
    throw InputError(fmt::format("mesh file '{}' is neither ASCII STL (no 'solid') nor binary STL (size)", path));
  std::istringstream ss(data);
  std::string word;
  std::vector<int> facet;
  int line_facet = 0;
  bool open_facet = false, ended = false;
  while (ss >> word) {
    if (word == "facet") {
      open_facet = true;
    } else if (word == "vertex") {
      Vec3 p;
      for (int c = 0; c < 3; ++c) {
        std::string t;
        const auto v = (ss >> t) ? finite_number(t) : std::nullopt;
        if (!v)
          throw InputError(fmt::format("mesh file '{}': facet {}: vertex coordinate '{}' is not a finite number", path,
                                       line_facet, t));
        p[c] = *v;
      }
      if (const auto why = bad_vertex(p, scale))
        throw InputError(fmt::format("mesh file '{}': facet {}: vertex {}", path, line_facet, *why));
      facet.push_back(weld(index, m, p * scale));
    } else if (word == "endsolid") {
      ended = true;
      break;
    } else if (word == "endfacet") {
      open_facet = false;
      if (facet.size() != 3)
        throw InputError(fmt::format("mesh file '{}': facet {} has {} vertices, not 3", path, line_facet, facet.size()));
      m.triangles.push_back({facet[0], facet[1], facet[2]});
      facet.clear();
      ++line_facet;
    }
  }
  // A file cut short (a copy interrupted, a full disk) must not lose its last facets unseen.
  if (open_facet || !facet.empty() || !ended)
    throw InputError(fmt::format("mesh file '{}' ends inside facet {} or without 'endsolid': truncated ASCII STL?",
                                 path, line_facet));
  return m;
}

TriangleMesh read_obj(const std::string& path, double scale) {
  std::ifstream in(path);
  if (!in) throw InputError(fmt::format("mesh file '{}' cannot be read", path));
  TriangleMesh m;
  m.name = std::filesystem::path(path).stem().string();
  std::string line;
  int lineno = 0;
  while (std::getline(in, line)) {
    ++lineno;
    std::istringstream ls(line);
    std::string tag;
    if (!(ls >> tag)) continue;
    if (tag == "v") {
      Vec3 p;
      for (int c = 0; c < 3; ++c) {
        std::string t;
        const auto v = (ls >> t) ? finite_number(t) : std::nullopt;
        if (!v)
          throw InputError(
              fmt::format("{}:{}: vertex coordinate '{}' is not a finite number in '{}'", path, lineno, t, line));
        p[c] = *v;
      }
      if (const auto why = bad_vertex(p, scale))
        throw InputError(fmt::format("{}:{}: vertex {} in '{}'", path, lineno, *why, line));
      m.vertices.emplace_back(p * scale);
    } else if (tag == "f") {
      std::vector<int> poly;
      std::string item;
      const long long nv = static_cast<long long>(m.vertices.size());
      while (ls >> item) {
        const auto idx = whole_number(std::string_view(item).substr(0, item.find('/')));
        // OBJ indices are 1-based and refer to vertices listed before; negative ones count
        // back from the last vertex.
        if (!idx || *idx == 0 || *idx > nv || *idx < -nv)
          throw InputError(
              fmt::format("{}:{}: face index '{}' is not an integer in [1, {}] or [-{}, -1] (the "
                          "vertices listed so far)",
                          path, lineno, item, nv, nv));
        poly.push_back(static_cast<int>(*idx > 0 ? *idx - 1 : nv + *idx));
      }
      if (poly.size() < 3) throw InputError(fmt::format("{}:{}: a face needs 3 vertices", path, lineno));
      for (std::size_t k = 1; k + 1 < poly.size(); ++k) m.triangles.push_back({poly[0], poly[k], poly[k + 1]});
    }
  }
  return m;
}

}  // namespace

TriangleMesh read_mesh(const std::string& path, double scale) {
  if (const PathKind k = path_kind(path); k.kind != PathKind::File)
    throw InputError(fmt::format("mesh file '{}' {}", path,
                                 k.kind == PathKind::Missing     ? "does not exist"
                                 : k.kind == PathKind::Directory ? "is a directory"
                                                                 : "cannot be used: " + k.error));
  const std::string ext = lower_ext(path);
  TriangleMesh m;
  if (ext == ".stl")
    m = read_stl(path, scale);
  else if (ext == ".obj")
    m = read_obj(path, scale);
  else
    throw InputError(fmt::format("mesh file '{}': unknown format '{}' (use .stl or .obj)", path, ext));
  m.validate(path);
  return m;
}

void write_stl(const std::string& path, const TriangleMesh& m) {
  const std::string tmp = path + ".part";
  {
    std::ofstream out(tmp, std::ios::binary);
    if (!out) throw InputError("cannot write '" + tmp + "'");
    char header[80] = {};
    std::snprintf(header, sizeof header, "swarf mesh %s", m.name.c_str());
    out.write(header, 80);
    const std::uint32_t n = static_cast<std::uint32_t>(m.triangles.size());
    out.write(reinterpret_cast<const char*>(&n), 4);
    for (const auto& t : m.triangles) {
      const Vec3 a = m.vertices[t[0]], b = m.vertices[t[1]], c = m.vertices[t[2]];
      const Vec3 nrm = (b - a).cross(c - a).normalized();
      float buf[12] = {float(nrm[0]), float(nrm[1]), float(nrm[2]), float(a[0]), float(a[1]), float(a[2]),
                       float(b[0]),   float(b[1]),   float(b[2]),   float(c[0]), float(c[1]), float(c[2])};
      out.write(reinterpret_cast<const char*>(buf), 48);
      const std::uint16_t attr = 0;
      out.write(reinterpret_cast<const char*>(&attr), 2);
    }
    out.close();  // (the last buffer is written here: a full disk shows now)
    if (!out) throw OutputError("write to '" + tmp + "' failed (disk full?)");
  }
  commit_file(tmp, path);
}

void write_obj(const std::string& path, const TriangleMesh& m) {
  const std::string tmp = path + ".part";
  {
    std::ofstream out(tmp);
    if (!out) throw InputError("cannot write '" + tmp + "'");
    out << fmt::format("# swarf mesh {}\n", m.name);
    for (const Vec3& v : m.vertices) out << fmt::format("v {} {} {}\n", v[0], v[1], v[2]);
    for (const auto& t : m.triangles) out << fmt::format("f {} {} {}\n", t[0] + 1, t[1] + 1, t[2] + 1);
    out.close();
    if (!out) throw OutputError("write to '" + tmp + "' failed (disk full?)");
  }
  commit_file(tmp, path);
}

}  // namespace swarf
