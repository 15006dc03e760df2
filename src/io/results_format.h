// results_format.h: the layout version of DIR/results.h5 (root attribute 'format').
//
// Readers of older files go through this number, not through guesses from the data:
//   1 (no attribute): runs before 2026-12-01: /cutting/setup has 9 values (no face length),
//     series.csv may lack the chip_thickness column;
//   2: /cutting/setup has 10 values, /particles/id holds the particles' stable ids;
//   3: every dataset has 'unit' and 'description' attributes; the cut's set-up is one named
//      dataset per value under /cutting (width, steady_from, tool_tip, ...); /groups/name holds
//      the group names; /series/<column> the time history; the root has the provenance.
//   4: /bonds/formed marks the rods formed during the run, so that the broken-rod fraction can
//      be taken over the lattice's own rods (before it, 'swarf post' divided by all rods).
//   5: /frames/NNNNN hold the ParaView frames' per-particle fields over time (attribute time_s,
//      datasets position, id and every point array of frames/particles_NNNNN.vtu, each with its
//      unit), /frame_time their times; results.xdmf beside it opens them as one time series.
#pragma once

#include "io/h5file.h"

namespace swarf {

inline constexpr double kResultsFormat = 5.0;

/// The layout of an open results.h5: its 'format' attribute, 1 when it has none.
inline int results_format(const H5File& f) {
  return f.has_attribute("format") ? static_cast<int>(f.read_double_attribute("format")) : 1;
}

}  // namespace swarf
