// field_history.h: the frames' per-particle fields over time in one HDF5 file, and the XDMF
// sidecar that opens them in ParaView and VisIt as one time series.
//
// The frames are written during the run as the ParaView series (frames/particles_NNNNN.vtu,
// vtk_output.h), each file atomically. At the end of a run they are read back and copied into
// the results file as groups /frames/NNNNN, inside the results file's own .part-then-rename
// (summary.h): the history holds the very doubles of the .vtu frames, and an interrupted run
// leaves no results file and no sidecar that could pass for complete (the sidecar is written
// after the results file it points into). A restart continues the frames, so its history has
// them all.
//
// Why XDMF: VTK's own HDF5 format (VTKHDF) reads time series only from VTK 9.3 on; Debian 12
// ships VTK 9.1 and ParaView 5.11. XDMF with HDF5 heavy data, in the elements of its version 2
// (which the version 3 readers read too), opens in both ParaView readers ("XDMF Reader" and
// "Xdmf3 Reader") and in VisIt.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace swarf {

class H5File;

/// One dataset of a frame's group.
struct HistoryArray {
  std::string name;            ///< "position", "id", then the point arrays' names
  std::string unit;            ///< as its 'unit' attribute ("1" for numbers without unit)
  std::size_t components = 1;  ///< columns (1: a 1-D dataset)
  bool integer = false;        ///< int64 (ids, groups), else float64
};

/// One frame as written: its group, time and datasets.
struct HistoryFrame {
  std::size_t number = 0;            ///< the frame's number k (frames/particles_k.vtu)
  double time = 0;                   ///< s
  std::size_t points = 0;            ///< particles in the frame
  std::vector<HistoryArray> arrays;  ///< position first, then every point array of the frame
};

/// The group of frame k in the results file ("/frames/00003").
std::string history_group(std::size_t k);

/// Copies the particles' frames of the ParaView series in 'dir' (frame k at times[k], s) into
/// 'f': per frame a group /frames/NNNNN with attribute time_s and datasets position (n x 3, m)
/// and every point array of the frame under its own name, with its unit; and /frame_time, the
/// frames' times (s). A frame whose file is missing (a restart into another directory whose
/// frames could not be carried) is left out; the caller compares the count. Throws OutputError
/// when a frame cannot be read.
std::vector<HistoryFrame> write_field_history(H5File& f, const std::string& dir, const std::vector<double>& times);

/// The XDMF (version 2) text of a temporal collection of Polyvertex grids, one per frame, whose data
/// items point into 'h5_file' (a path relative to the sidecar: "results.h5").
std::string field_history_xdmf(const std::vector<HistoryFrame>& frames, const std::string& h5_file);

}  // namespace swarf
