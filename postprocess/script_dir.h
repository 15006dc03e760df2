// script_dir.h: where the post-processing scripts (the *.py beside this file) are found, for
// the build tree's program and for an installed one alike.
#pragma once

#include <string>

namespace swarf {

/// The folder of the post-processing scripts: $SWARF_POSTPROCESS_DIR if set; else, for an
/// installed swarf, PREFIX/share/swarf/postprocess beside the program's PREFIX/bin (found from
/// /proc/self/exe, so a moved prefix works too); else the source tree's postprocess/ (the
/// build tree's program).
std::string postprocess_dir();

/// postprocess_dir()/NAME.
std::string postprocess_path(const std::string& name);

}  // namespace swarf
