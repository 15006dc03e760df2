// case_override.cpp: --set overrides on the TOML tree (see case_override.h).
#include "setup/case_override.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <vector>

#include "setup/toml_parse.h"
#include "swarf/core/errors.h"

namespace swarf {

void apply_override(toml::table& root, const std::string& arg, std::set<std::string>& overridden) {
  const auto eq = arg.find('=');
  if (eq == std::string::npos || eq == 0)
    throw InputError(fmt::format("--set '{}': expected key=value (for example integrator.dt=2e-9)", arg));
  const std::string key = arg.substr(0, eq), text = arg.substr(eq + 1);
  // A bare word is taken as a string: --set integrator.scheme=verlet
  const toml::table parsed = parse_toml_value(text).value_or(toml::table{{"v", text}});
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
      throw InputError(
          fmt::format("--set '{}': '{}' is not an index of the array '{}' ({} entries)", arg, part, where, a.size()));
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

}  // namespace swarf
