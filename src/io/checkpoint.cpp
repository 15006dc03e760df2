// checkpoint.cpp: writing and reading restart files (see checkpoint.h). The step's state is
// Simulation::visit_state (swarf/state_visit.cpp) walked by the HDF5 archives below under
// /sim/; the run loop's record (visit_record) and the caller's visit follow under /run/.
#include "io/checkpoint.h"

#include <fmt/format.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <filesystem>

#include "io/atomic_file.h"
#include "io/h5file.h"
#include "io/path_kind.h"
#include "swarf/core/bounds.h"
#include "swarf/core/errors.h"
#include "swarf/core/nan_safe.h"
#include "swarf/core/state_archive.h"
#include "swarf/simulation.h"
#include "swarf/version.h"

namespace swarf {
namespace {

// Checkpoint layout version. 3: the run's part as named fields too (/run/loop/ and one group
// per observer; 2 packed the loop's and the probes' scalars into /run/scalars by position).
// 2: the state as the named fields of Simulation::visit_state (1 packed the step's scalars by
// position).
constexpr double kFormat = 3.0;

// The largest magnitude of any number of the step's state (/sim/; SI units: positions,
// velocities, accelerations, rates, forces, torques, inverse masses and inertias, rod and
// contact state, times): far beyond what a run reaches (1/inertia of the smallest particle
// allowed, kMinRadius, is about 1e41 1/(kg m^2)), and low enough that a step's products of two
// such numbers and their squares stay finite. A checkpoint's angular acceleration of -1e300
// overflowed the first rotation update (the checkpoint fuzzer).
constexpr double kMaxStateValue = 1e50;

void put(H5File& f, const std::string& name, const std::vector<Vec3>& v) {
  f.write(name, v.empty() ? nullptr : v[0].data(), v.size(), 3);
}
std::string join_lines(const std::vector<std::string>& v) {
  std::string s;
  for (const auto& x : v) s += x + "\n";
  return s;
}
std::vector<std::string> split_lines(const std::string& s) {
  std::vector<std::string> out;
  std::size_t pos = 0;
  while (pos < s.size()) {
    const auto eol = s.find('\n', pos);
    out.push_back(s.substr(pos, eol - pos));
    if (eol == std::string::npos) break;
    pos = eol + 1;
  }
  return out;
}

}  // namespace

namespace {

// A state visit written to and read from datasets under a root ("/sim/", "/run/"; see
// state_archive.h). Arrays keep their element shape (Vec3: N x 3, quaternions: N x 4);
// scalars are 1-element datasets.
class H5StateWriter final : public StateArchive {
 public:
  H5StateWriter(H5File& f, std::string root) : f_(f), root_(std::move(root)) {}
  bool loading() const override { return false; }
  void array(std::string_view name, std::vector<double>& v, std::size_t) override {
    f_.write(key(name), v.data(), v.size(), 1);
  }
  void array(std::string_view name, std::vector<Vec3>& v, std::size_t) override { put(f_, key(name), v); }
  void array(std::string_view name, std::vector<Quat>& v, std::size_t) override {
    f_.write(key(name), v.empty() ? nullptr : v[0].data(), v.size(), 4);
  }
  void array(std::string_view name, std::vector<std::uint8_t>& v, std::size_t) override {
    f_.write(key(name), v.data(), v.size());
  }
  void array(std::string_view name, std::vector<std::int32_t>& v, std::size_t) override {
    f_.write(key(name), v.data(), v.size(), 1);
  }
  void array(std::string_view name, std::vector<std::int64_t>& v, std::size_t) override {
    f_.write(key(name), v.data(), v.size(), 1);
  }
  void scalar(std::string_view name, double& v) override { f_.write(key(name), &v, 1, 1); }
  void scalar(std::string_view name, std::int64_t& v) override { f_.write(key(name), &v, 1, 1); }
  void int32_pairs(std::string_view name, const std::vector<std::array<std::int32_t, 2>>& v) override {
    f_.write(key(name), v.empty() ? nullptr : v[0].data(), 2 * v.size(), 1);  // (the flat array's dataset)
  }

 private:
  std::string key(std::string_view name) const { return root_ + std::string(name); }
  H5File& f_;
  std::string root_;
};

class H5StateReader final : public StateArchive {
 public:
  /// 'finite': every number read must be finite (the step's state: a NaN or an infinity there
  /// is a corrupt file, and the first step would trap or run on garbage).
  H5StateReader(const H5File& f, std::string root, bool finite) : f_(f), root_(std::move(root)), finite_(finite) {}
  bool loading() const override { return true; }
  bool has(std::string_view name) const override { return f_.has(key(name)); }
  void array(std::string_view name, std::vector<double>& v, std::size_t expected) override {
    v = doubles(name, expected, 1);
  }
  void array(std::string_view name, std::vector<Vec3>& v, std::size_t expected) override {
    const auto d = doubles(name, expected, 3);
    v.resize(d.size() / 3);
    for (std::size_t i = 0; i < v.size(); ++i) v[i] = Vec3(d[3 * i], d[3 * i + 1], d[3 * i + 2]);
  }
  void array(std::string_view name, std::vector<Quat>& v, std::size_t expected) override {
    const auto d = doubles(name, expected, 4);
    v.resize(d.size() / 4);
    for (std::size_t i = 0; i < v.size(); ++i) v[i] = Quat(d[4 * i], d[4 * i + 1], d[4 * i + 2], d[4 * i + 3]);
  }
  void array(std::string_view name, std::vector<std::uint8_t>& v, std::size_t expected) override {
    const auto d = ints(name, expected);
    v.assign(d.begin(), d.end());
  }
  void array(std::string_view name, std::vector<std::int32_t>& v, std::size_t expected) override {
    const auto d = ints(name, expected);
    v.assign(d.begin(), d.end());
  }
  void array(std::string_view name, std::vector<std::int64_t>& v, std::size_t expected) override {
    v = ints(name, expected);
  }
  void scalar(std::string_view name, double& v) override { v = doubles(name, 1, 1)[0]; }
  void scalar(std::string_view name, std::int64_t& v) override { v = ints(name, 1)[0]; }

 private:
  std::string key(std::string_view name) const { return root_ + std::string(name); }
  std::vector<double> doubles(std::string_view name, std::size_t expected, std::size_t cols) const {
    std::size_t r = 0, c = 0;
    auto v = f_.read_doubles(key(name), r, c);
    if (v.empty()) r = 0, c = cols;  // (an empty dataset reads as 0 x 1)
    if (c != cols || (expected != kAnySize && r != expected))
      throw InputError(fmt::format(
          "checkpoint '{}': dataset '{}' has shape {} x {}, expected {} x {} "
          "(the checkpoint belongs to another case or version)",
          f_.path(), key(name), r, c, expected == kAnySize ? std::string("N") : std::to_string(expected), cols));
    // The step's state (/sim/): finite, and within kMaxStateValue (finite values such as
    // 1e300 overflowed the first step's products and squares); the run's part may hold infinities.
    if (finite_)
      for (std::size_t k = 0; k < v.size(); ++k)
        if (!finite_bits(v[k]) || !(std::abs(v[k]) <= kMaxStateValue))
          throw InputError(fmt::format(
              "checkpoint '{}': dataset '{}' entry {} = {} is not a finite number within +-{:g} (a corrupt file)",
              f_.path(), key(name), k, nan_safe(v[k]), kMaxStateValue));
    return v;
  }
  std::vector<std::int64_t> ints(std::string_view name, std::size_t expected) const {
    std::size_t r = 0, c = 0;
    auto v = f_.read_ints(key(name), r, c);
    if (v.empty()) r = 0, c = 1;
    if (c != 1 || (expected != kAnySize && r != expected))
      throw InputError(
          fmt::format("checkpoint '{}': dataset '{}' has {} entries, expected {} "
                      "(the checkpoint belongs to another case or version)",
                      f_.path(), key(name), r, expected));
    return v;
  }
  const H5File& f_;
  std::string root_;
  bool finite_;
};

// The loop's record, each field named once for save and load.
void visit_record(StateArchive& ar, RunRecord& rec) {
  ar.scalar("loop/series_columns", rec.columns);
  ar.array("loop/series_rows", rec.rows, StateArchive::kAnySize);  // row-major, columns a row
  ar.scalar("loop/next_row_s", rec.next_row);
  ar.scalar("loop/next_frame_s", rec.next_frame);
  ar.array("loop/frame_times_s", rec.frame_times, StateArchive::kAnySize);
  ar.scalar("loop/wall_s", rec.wall_s);
  ar.scalar("loop/output_wall_s", rec.output_s);
}

// Runs a visit of a load, naming the checkpoint in an error that does not name it already
// (the archive's own errors begin "checkpoint '...'", the caller's may begin "--restart ...").
template <class Visit>
void loading(const std::string& path, Visit&& visit) {
  try {
    visit();
  } catch (const InputError& e) {
    const std::string what = e.what();
    if (what.rfind("checkpoint", 0) == 0 || what.rfind("--restart", 0) == 0) throw;
    throw InputError(fmt::format("checkpoint '{}': {}", path, what));
  }
}

}  // namespace

void write_checkpoint(const std::string& path, const Simulation& sim, const RunRecord& rec, const CheckpointCase& c,
                      const RunStateVisit& run_state) {
  const std::string tmp = path + ".part";
  {
    H5File f(tmp, H5File::Mode::Create);
    f.write_attribute("format", kFormat);
    f.write_attribute("generator", std::string("swarf ") + SWARF_VERSION);
    f.write_attribute("case_toml", c.toml);
    f.write_attribute("case_source", c.source);
    f.write_attribute("case_directory", std::filesystem::absolute(c.directory).string());
    f.write_attribute("case_overrides", join_lines(c.overrides));
    f.write_attribute("time_s", sim.time());
    f.write_attribute("steps", double(sim.steps()));
    H5StateWriter sim_part(f, "/sim/");
    const_cast<Simulation&>(sim).visit_state(sim_part);  // (a writer only reads the state)
    H5StateWriter run_part(f, "/run/");
    visit_record(run_part, const_cast<RunRecord&>(rec));  // (likewise)
    if (run_state) run_state(run_part);
    f.close();  // (flushed, or an error: a failed checkpoint never replaces the last good one)
  }
  commit_file(tmp, path);
}

CheckpointCase read_checkpoint_case(const std::string& path) {
  if (const PathKind k = path_kind(path); k.kind != PathKind::File)
    throw InputError(fmt::format("--restart: checkpoint '{}' {}", path,
                                 k.kind == PathKind::Missing     ? "does not exist"
                                 : k.kind == PathKind::Directory ? "is a directory (give DIR/checkpoint.h5)"
                                                                 : "cannot be used: " + k.error));
  H5File f(path, H5File::Mode::Read);
  if (!f.has_attribute("format") || !f.has_attribute("case_toml"))
    throw InputError(fmt::format("--restart: '{}' is not a swarf checkpoint", path));
  if (f.read_double_attribute("format") != kFormat)
    throw InputError(fmt::format("--restart: checkpoint '{}' has layout {} (this swarf reads {})", path,
                                 f.read_double_attribute("format"), kFormat));
  CheckpointCase c;
  c.toml = f.read_string_attribute("case_toml");
  c.source = f.read_string_attribute("case_source");
  c.directory = f.read_string_attribute("case_directory");
  c.overrides = split_lines(f.read_string_attribute("case_overrides"));
  c.time = f.read_double_attribute("time_s");
  c.steps = f.read_double_attribute("steps");
  return c;
}

void read_checkpoint(const std::string& path, Simulation& sim, RunRecord& rec, const RunStateVisit& run_state) {
  H5File f(path, H5File::Mode::Read);
  H5StateReader sim_part(f, "/sim/", true), run_part(f, "/run/", false);
  loading(path, [&] { sim.visit_state(sim_part); });
  loading(path, [&] { visit_record(run_part, rec); });
  if (rec.columns == 0 || rec.rows.size() % rec.columns != 0)
    throw InputError(fmt::format("checkpoint '{}': series rows do not match {} columns", path, rec.columns));
  // The output schedule goes on from these: the run loop steps each past the time by its
  // interval, which from -1e300 never ended. (The next frame is inf without frames.)
  const bool no_frames = std::bit_cast<std::uint64_t>(rec.next_frame) == std::bit_cast<std::uint64_t>(HUGE_VAL);
  if (!(finite_bits(rec.next_row) && rec.next_row >= 0.0) ||
      !(no_frames || (finite_bits(rec.next_frame) && rec.next_frame >= 0.0)))
    throw InputError(fmt::format("checkpoint '{}': next output times {} s (row), {} s (frame) are not times >= 0", path,
                                 nan_safe(rec.next_row), nan_safe(rec.next_frame)));
  if (run_state) loading(path, [&] { run_state(run_part); });
}

}  // namespace swarf
