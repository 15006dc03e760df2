// plots.cpp: calls the matplotlib script (see plots.h). Python plots keep the C++ side free
// of a plotting library; the script only draws columns that swarf computed.
#include "app/plots.h"

#include <fmt/format.h>
#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <cstdlib>
#include <filesystem>

namespace swarf {

namespace {

std::string quote(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

}  // namespace

ScriptRun run_postprocess_script(const std::string& name, const std::vector<std::string>& args,
                                 const std::string& prefix) {
  ScriptRun r;
  const std::string script = postprocess_path(name);
  if (!std::filesystem::exists(script)) {
    r.output = "script not found: " + script;
    return r;
  }
  const char* py = std::filesystem::exists("/usr/bin/python3") ? "/usr/bin/python3" : "python3";
  std::string cmd = prefix;
  cmd += py;
  cmd += ' ';
  cmd += quote(script);
  for (const auto& a : args) {
    cmd += ' ';
    cmd += quote(a);
  }
  FILE* pipe = popen((cmd + " 2>&1").c_str(), "r");
  if (!pipe) {
    r.output = std::string("cannot start ") + py;
    return r;
  }
  std::array<char, 512> buf{};
  while (fgets(buf.data(), buf.size(), pipe)) r.output += buf.data();
  const int status = pclose(pipe);
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

PlotResult make_plots(const std::string& dir, const std::string& summary_path) {
  PlotResult r;
  const ScriptRun run = run_postprocess_script("plot_run.py", {dir, summary_path});
  r.files = written_files(run.output);
  r.ok = run.ok;
  if (!r.ok) r.message = "plot script failed: " + run.output.substr(0, 400);
  return r;
}

}  // namespace swarf
