// case_override.h: one --set override ("dotted.key=value") applied to the TOML tree before
// the tables are read, so that an overridden key is checked exactly like a key in the file.
// Internal to setup/.
#pragma once

#include <toml++/toml.h>

#include <set>
#include <string>

namespace swarf {

/// Applies "a.b.c=value" to 'root' (array indices as components: mesh.0.origin.2) and
/// records the key as the readers name it, indices dropped (group.0.x -> group.x), in
/// 'overridden'. Throws InputError for a malformed argument or a missing index.
void apply_override(toml::table& root, const std::string& arg, std::set<std::string>& overridden);

}  // namespace swarf
