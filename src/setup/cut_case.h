// cut_case.h: [cut], an orthogonal cut described in cutting terms, turned into the case's
// lower-level tables.
//
// A machining engineer gives the uncut chip thickness, the cutting speed, the length of cut,
// the tool's angles and edge radius, the material and the resolution; the rest of a cutting
// case (lattice, vice, tool placement and path, end time, steady window, output intervals)
// follows from them by the rules of the built-in default cut (docs/default-case.md), so that
// the default written as a [cut] builds the same model (test_cut_table.cpp). The derived keys
// are inserted into the TOML tree before it is read, where the case does not give them: a key
// the case gives wins, and the derivation uses the given value from then on (a given radius
// moves the clamps and the tool with it). Doing it on the tree, not on the settings, keeps one
// reader with one set of checks, and lets swarf print the derivation as a case file.
#pragma once

#include <toml++/toml.h>

#include <set>
#include <string>

#include "setup/case_config.h"
#include "setup/case_tables.h"

namespace swarf {

/// Reads [cut] (when the tree has one) into cs.cut, inserts the keys it derives that the tree
/// does not give, and writes the derivation to cs.cut_derived as TOML with a note per key.
/// 'derived' receives the inserted keys ("workpiece.radius", "group.box_min", ...), so that a
/// message about one blames [cut]. Throws InputError for bad [cut] keys and for tables that
/// cannot go with it.
void expand_cut(toml::table& root, const CaseInput& in, CaseSettings& cs, std::set<std::string>& derived);

}  // namespace swarf
