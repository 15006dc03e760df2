// plots.cpp: calls the matplotlib script (see plots.h). Python plots keep the C++ side free
// of a plotting library; the script only draws columns that swarf computed.
#include "plots.h"

#include <array>
#include <cstdio>
#include <filesystem>
#include <fmt/format.h>
#include <sys/wait.h>

namespace swarf {

static std::string quote(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

PlotResult make_plots(const std::string& dir, const std::string& summary_path) {
  PlotResult r;
  std::string script = std::string(SWARF_POSTPROCESS_DIR) + "/plot_run.py";
  if (const char* env = std::getenv("SWARF_POSTPROCESS_DIR")) script = std::string(env) + "/plot_run.py";
  if (!std::filesystem::exists(script)) {
    r.message = "plot script not found: " + script;
    return r;
  }
  const char* py = std::filesystem::exists("/usr/bin/python3") ? "/usr/bin/python3" : "python3";
  const std::string cmd = fmt::format("{} {} {} {} 2>&1", py, quote(script), quote(dir), quote(summary_path));
  FILE* pipe = popen(cmd.c_str(), "r");
  if (!pipe) {
    r.message = "cannot start " + std::string(py);
    return r;
  }
  std::string out;
  std::array<char, 512> buf{};
  while (fgets(buf.data(), buf.size(), pipe)) out += buf.data();
  const int status = pclose(pipe);
  std::size_t pos = 0;
  while (pos < out.size()) {
    const auto eol = out.find('\n', pos);
    const std::string line = out.substr(pos, eol - pos);
    if (line.rfind("wrote ", 0) == 0) r.files.push_back(line.substr(6));
    if (eol == std::string::npos) break;
    pos = eol + 1;
  }
  r.ok = WIFEXITED(status) && WEXITSTATUS(status) == 0;
  if (!r.ok) r.message = "plot script failed: " + out.substr(0, 400);
  return r;
}

}  // namespace swarf
