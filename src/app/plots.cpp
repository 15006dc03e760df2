// plots.cpp: calls the matplotlib script (see plots.h). Python plots keep the C++ side free
// of a plotting library; the script only draws columns that swarf computed.
#include "app/plots.h"

#include <fcntl.h>
#include <fmt/format.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cerrno>
#include <cstring>
#include <filesystem>

#include "app/threads.h"

extern char** environ;

namespace swarf {

ScriptRun run_postprocess_script(const std::string& name, const std::vector<std::string>& args,
                                 const std::vector<std::string>& prefix) {
  ScriptRun r;
  const std::string script = postprocess_path(name);
  if (!std::filesystem::exists(script)) {
    r.output = "script not found: " + script;
    return r;
  }
  std::vector<std::string> argv = prefix;
  argv.push_back(std::filesystem::exists("/usr/bin/python3") ? "/usr/bin/python3" : "python3");
  argv.push_back(script);
  argv.insert(argv.end(), args.begin(), args.end());
  std::vector<char*> cargv;
  for (auto& a : argv) cargv.push_back(a.data());
  cargv.push_back(nullptr);

  // The child's stdout and stderr go into one pipe; its stdin is /dev/null.
  int fd[2];
  if (::pipe(fd) != 0) {
    r.output = "cannot make a pipe for " + argv[0];
    return r;
  }
  posix_spawn_file_actions_t fa;
  posix_spawn_file_actions_init(&fa);
  posix_spawn_file_actions_addclose(&fa, fd[0]);
  posix_spawn_file_actions_addopen(&fa, 0, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_adddup2(&fa, fd[1], 1);
  posix_spawn_file_actions_adddup2(&fa, fd[1], 2);
  posix_spawn_file_actions_addclose(&fa, fd[1]);
  pid_t pid = 0;
  const CallingThreadUnpinned unpinned;  // (the plots' process gets the run's CPUs, not thread 0's one)
  const int rc = posix_spawnp(&pid, argv[0].c_str(), &fa, nullptr, cargv.data(), environ);
  posix_spawn_file_actions_destroy(&fa);
  ::close(fd[1]);
  if (rc != 0) {
    ::close(fd[0]);
    r.output = fmt::format("cannot start {}: {}", argv[0], std::strerror(rc));
    return r;
  }
  std::array<char, 4096> buf{};
  for (ssize_t n; (n = ::read(fd[0], buf.data(), buf.size())) != 0;) {
    if (n < 0) {
      if (errno == EINTR) continue;
      break;
    }
    r.output.append(buf.data(), static_cast<std::size_t>(n));
  }
  ::close(fd[0]);
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  r.ok = WIFEXITED(status) && WEXITSTATUS(status) == 0;
  return r;
}

std::vector<std::string> written_files(const std::string& output) {
  std::vector<std::string> files;
  std::size_t pos = 0;
  while (pos < output.size()) {
    const auto eol = output.find('\n', pos);
    const std::string line = output.substr(pos, eol - pos);
    if (line.rfind("wrote ", 0) == 0) files.push_back(line.substr(6));
    if (eol == std::string::npos) break;
    pos = eol + 1;
  }
  return files;
}

std::vector<RunFile> plot_files() {
  // (the script names them: a plot it adds is added here too, or a rerun keeps a stale one)
  return {{"forces.png"}, {"tool_vibration.png"}, {"stress_strain.png"}, {"energy.png"}};
}

PlotResult make_plots(const std::string& dir, const std::string& summary_path) {
  PlotResult r;
  const ScriptRun run = run_postprocess_script("plot_run.py", {dir, summary_path});
  r.files = written_files(run.output);
  r.ok = run.ok;
  if (!r.ok) r.message = "plot script failed: " + run.output.substr(0, 400);
  return r;
}

}  // namespace swarf
