// run_directory.cpp: the run directory (see run_directory.h).
#include "app/run_directory.h"

#include <fcntl.h>
#include <fmt/format.h>
#include <sys/file.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>

#include "app/paraview_script.h"
#include "app/plots.h"
#include "app/post.h"
#include "app/run.h"
#include "app/run_outputs.h"
#include "io/console.h"
#include "swarf/core/errors.h"

namespace swarf {
namespace {

constexpr const char* kLock = ".swarf-run.lock";

// Holds DIR/.swarf-run.lock for the rest of the process: two runs writing into one directory
// would leave one's summary beside the other's series. The lock ends with the process (also
// when it is killed), so a stale lock file never blocks a later run.
void lock_run_directory(const std::string& dir) {
  const std::string path = dir + "/" + kLock;
  const int fd = ::open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  if (fd < 0) throw InputError(fmt::format("--out {}: cannot create '{}': {}", dir, path, std::strerror(errno)));
  if (::flock(fd, LOCK_EX | LOCK_NB) != 0) {
    char pid[32] = {0};
    const ssize_t got = ::pread(fd, pid, sizeof pid - 1, 0);
    ::close(fd);
    throw InputError(
        fmt::format("--out {}: another swarf run{} is writing into this directory (it holds '{}'); "
                    "give another --out or wait for it to end",
                    dir, got > 0 ? fmt::format(" (process {})", std::string(pid, got)) : "", path));
  }
  const std::string me = std::to_string(::getpid());
  if (::ftruncate(fd, 0) == 0) {
    [[maybe_unused]] const ssize_t w = ::pwrite(fd, me.data(), me.size(), 0);  // (only for the refusal's message)
  }
  // fd stays open on purpose: the lock is the process's.
}

}  // namespace

std::vector<RunFile> run_directory_files() {
  std::vector<RunFile> files{{kLock, RunFile::Keep::always}};
  for (const auto& writer : {run_case_files(), RunOutputs::files(), paraview_script_files(), plot_files(), cut_files()})
    files.insert(files.end(), writer.begin(), writer.end());
  return files;
}

std::string prepare_run_directory(const RunOptions& opt) {
  namespace fs = std::filesystem;
  const bool restarting = !opt.restart.empty();
  std::string dir = opt.out_dir;
  if (dir.empty()) {
    const auto parent = fs::path(opt.restart).parent_path();
    dir = restarting ? (parent.empty() ? "." : parent.string()) : "swarf-out";
  }
  fs::create_directories(dir);
  lock_run_directory(dir);
  // Outputs of an earlier run in the same directory would mix with this one's: a file this run
  // does not write would pass for its own, and a previous summary would make an interrupted run
  // look complete. So every file a writer declares goes, the ones this run rewrites too; a
  // restart keeps what it continues.
  for (const RunFile& f : run_directory_files()) {
    if (f.keep == RunFile::Keep::always || (restarting && f.keep == RunFile::Keep::on_restart)) continue;
    const fs::path path = fs::path(dir) / f.name;
    fs::remove_all(path);
    fs::remove(path.string() + ".part");
    fs::remove(path.string() + ".part" + path.extension().string());  // (VTK's: chip_surface.vtp.part.vtp)
  }
  return dir;
}

void carry_frames(const std::filesystem::path& from_dir, const std::string& to_dir, std::size_t frames) {
  namespace fs = std::filesystem;
  if (frames == 0) return;
  const fs::path from = (from_dir.empty() ? fs::path(".") : from_dir) / "frames", to = fs::path(to_dir) / "frames";
  fs::create_directories(to);
  std::error_code ec;
  if (fs::exists(from) && !fs::equivalent(from, to, ec)) {
    for (const auto& e : fs::directory_iterator(from)) {
      const std::string stem = e.path().stem().string();  // particles_00003, rods_00003, mesh_<name>_00003
      const auto us = stem.rfind('_');
      if (us == std::string::npos || stem.size() - us != 6) continue;
      const std::string digits = stem.substr(us + 1);
      if (digits.find_first_not_of("0123456789") != std::string::npos) continue;
      if (std::stoul(digits) < frames)
        fs::copy_file(e.path(), to / e.path().filename(), fs::copy_options::overwrite_existing);
    }
  }
  std::size_t missing = 0;
  for (std::size_t k = 0; k < frames; ++k)
    if (!fs::exists(to / fmt::format("particles_{:05d}.vtu", k))) ++missing;
  if (missing > 0)
    eprint(
        "swarf: warning: {} of the {} frames written before the checkpoint are neither in {} nor in {}: "
        "particles.pvd lists them\n",
        missing, frames, to.string(), from.string());
}

}  // namespace swarf
