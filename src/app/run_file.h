// run_file.h: a file that a writer of the run directory may write, as the writer declares it.
//
// Each writer (the run's own files in run.cpp, RunOutputs, the ParaView script, the plots, the
// cut's end) lists the names it may write beside the code that writes them, and
// prepare_run_directory (run_directory.h) removes every declared name before a run: a file
// an earlier run wrote and this one does not (a tool spectrum, a plot of a column this case
// lacks) would otherwise sit beside this run's outputs as if it were one of them. Names that
// are written atomically (io/atomic_file.h) have a NAME.part while they are written (a VTK
// file NAME.part.EXT, for VTK's writers choose the format by the extension); it goes with its
// name.
#pragma once

#include <string>
#include <vector>

namespace swarf {

struct RunFile {
  /// Which runs keep it when they start in its directory.
  enum class Keep {
    never,       ///< removed before every run (this run writes it anew, or not at all)
    on_restart,  ///< a restart continues it (the checkpoint, the frames, the ParaView series, the log)
    always,      ///< the run holds it while it runs (the directory's lock)
  };
  std::string name;  ///< relative to the run directory; a folder ("frames") goes with all it holds
  Keep keep = Keep::never;
};

}  // namespace swarf
