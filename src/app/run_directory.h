// run_directory.h: the directory a run writes into, made ready for it, and the frames a
// restart into another directory brings along.
#pragma once

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include "app/run_file.h"

namespace swarf {

struct RunOptions;

/// Every file a run may write in its directory, as its writers declare them (run_file.h).
std::vector<RunFile> run_directory_files();

/// --out, else the checkpoint's directory on a restart, else "swarf-out"; created, locked,
/// and cleared of every declared file (a restart keeps those it continues: the checkpoint,
/// the ParaView series and its frames, the log).
std::string prepare_run_directory(const RunOptions& opt);

/// A restart into another directory: the frames the checkpoint's run wrote before it (numbers
/// below 'frames') are copied from its frames/ into the new one, so that particles.pvd, which
/// lists them, is complete there. Frames that cannot be found are named in a warning.
void carry_frames(const std::filesystem::path& from_dir, const std::string& to_dir, std::size_t frames);

}  // namespace swarf
