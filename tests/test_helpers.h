// test_helpers.h: small helpers shared by the tests (temporary directories, running the CLI).
#pragma once

#include <fmt/format.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace swarf::test {

/// A fresh directory under the system temp dir, removed at the end of the test.
class TempDir {
 public:
  explicit TempDir(const std::string& tag) {
    path_ = std::filesystem::temp_directory_path() / ("swarf_test_" + tag + "_" + std::to_string(::getpid()));
    std::filesystem::remove_all(path_);
    std::filesystem::create_directories(path_);
  }
  ~TempDir() { std::filesystem::remove_all(path_); }
  std::string str() const { return path_.string(); }
  std::string operator/(const std::string& name) const { return (path_ / name).string(); }

 private:
  std::filesystem::path path_;
};

struct CommandResult {
  int exit_code = -1;
  std::string output;  ///< stdout and stderr together
};

/// Runs a shell command, capturing its output and exit code.
inline CommandResult run_command(const std::string& cmd) {
  CommandResult r;
  FILE* pipe = popen((cmd + " 2>&1").c_str(), "r");
  if (!pipe) return r;
  char buf[4096];
  while (fgets(buf, sizeof buf, pipe)) r.output += buf;
  const int st = pclose(pipe);
  r.exit_code = WIFEXITED(st) ? WEXITSTATUS(st) : -1;
  return r;
}

inline std::string read_file(const std::string& path) {
  std::ifstream in(path);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

inline void write_file(const std::string& path, const std::string& text) {
  std::ofstream out(path);
  out << text;
}

/// The linear-law steel cut that was the built-in default case until the C45 cut replaced it
/// (validation/cutting/linear_cut.toml): 4,608 particles, Newmark. The tests that need a
/// whole cut quickly (signals, full disks, locks, the golden series) run it.
inline std::string linear_cut_case() { return std::string(SWARF_SOURCE_DIR) + "/validation/cutting/linear_cut.toml"; }

/// The C45 cut without heat, the paper's rods (validation/cutting/cold_cut.toml): the default
/// case until it gained heat; the tests that need a case whose rod law is not Johnson-Cook.
inline std::string cold_cut_case() { return std::string(SWARF_SOURCE_DIR) + "/validation/cutting/cold_cut.toml"; }

/// A small granular gas: 216 spheres (R = 0.5 mm, a 6^3 array of 1.05 mm spacing) with
/// pseudo-random velocities (+-0.5 m/s, a fixed sequence) in a 7 mm box of triangle walls,
/// Hertz with friction 0.5 and restitution 0.5, gravity, explicit steps of 1 us to 3 ms.
/// Writes the particle file into 'dir' and returns the case text (which names it by its path).
inline std::string granular_gas_case(const TempDir& dir) {
  std::string particles;
  std::uint64_t state = 12345;
  auto uniform = [&] {  // a fixed linear congruential sequence in [-0.5, 0.5)
    state = state * 6364136223846793005ULL + 1442695040888963407ULL;
    return double(state >> 11) / double(1ULL << 53) - 0.5;
  };
  int id = 0;
  for (int z = 0; z < 6; ++z)
    for (int y = 0; y < 6; ++y)
      for (int x = 0; x < 6; ++x)
        particles += fmt::format("{} {} {} {} {} {} {}\n", ++id, 0.55e-3 + 1.05e-3 * x, 0.55e-3 + 1.05e-3 * y,
                                 0.55e-3 + 1.05e-3 * z, uniform(), uniform(), uniform());
  write_file(dir / "p.txt", particles);
  std::string walls;
  const char* planes[6][4] = {
      {"xmin", "[0, 0, 0]", "[0, 7e-3, 0]", "[0, 0, 7e-3]"}, {"xmax", "[7e-3, 0, 0]", "[0, 7e-3, 0]", "[0, 0, 7e-3]"},
      {"ymin", "[0, 0, 0]", "[7e-3, 0, 0]", "[0, 0, 7e-3]"}, {"ymax", "[0, 7e-3, 0]", "[7e-3, 0, 0]", "[0, 0, 7e-3]"},
      {"zmin", "[0, 0, 0]", "[7e-3, 0, 0]", "[0, 7e-3, 0]"}, {"zmax", "[0, 0, 7e-3]", "[7e-3, 0, 0]", "[0, 7e-3, 0]"}};
  for (const auto& w : planes)
    walls += fmt::format("[[mesh]]\nname = \"{}\"\norigin = {}\nedge1 = {}\nedge2 = {}\nyoungs_modulus = 1e7\n", w[0],
                         w[1], w[2], w[3]);
  return fmt::format(R"([material]
density = 2500.0
[particles]
file = "{}"
radius = 0.5e-3
[contact]
youngs_modulus = 1e7
restitution = 0.5
friction = 0.5
tangential_damping = 1.0
[environment]
gravity = [0.0, 0.0, -9.81]
[integrator]
scheme = "verlet"
dt = 1e-6
end_time = 3e-3
[output]
vtk = false
plots = false
series_interval = 5e-5
)",
                     dir / "p.txt") +
         walls;
}

}  // namespace swarf::test
