// motion.cpp: the motion keys' part of setup (see motion.h).
#include "setup/modules/motion.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>

#include "io/csv_cell.h"
#include "setup/case_tables.h"

namespace swarf {
namespace {

// Reads a CSV velocity table 'time,vx,vy,vz' (header line first) for motion = "velocity_table".
void read_velocity_csv(const TableReader& r, const std::string& path, MotionSettings& m) {
  std::ifstream in(path);
  if (!in) r.fail("velocity_file", r.get("velocity_file"), "file not found or unreadable: " + path);
  std::string line;
  int lineno = 0;
  while (std::getline(in, line)) {
    ++lineno;
    if (lineno == 1 || line.empty() || line == "\r") continue;  // header
    std::vector<double> x;
    std::istringstream ls(line);
    bool ok = true;
    for (std::string cell; std::getline(ls, cell, ',');) {
      double c = 0;
      ok = ok && parse_csv_number(cell, c) && std::isfinite(c);
      x.push_back(c);
    }
    if (!ok || x.size() != 4)
      r.fail("velocity_file", r.get("velocity_file"),
             fmt::format("{}:{}: expected 'time,vx,vy,vz': four finite numbers in s and m/s, got '{}'", path, lineno,
                         line));
    m.table_time.push_back(x[0]);
    m.table_velocity.push_back({x[1], x[2], x[3]});
  }
}

}  // namespace

const std::vector<Key<MotionSettings>>& motion_keys() {
  using S = MotionSettings;
  static const std::vector<Key<S>> keys{
      {.name = "motion",
       .field = &S::kind,
       .choices = {"fixed", "velocity", "ramp", "table", "velocity_table"},
       .doc = "How the prescribed components move."},
      {.name = "velocity",
       .field = &S::velocity,
       .unit = "m/s",
       .no_default = true,
       .range = kVelocity,
       .rule = "required for `\"velocity\"` and `\"ramp\"`, rejected for the other motions",
       .doc = "Constant velocity; for `\"ramp\"` the velocity reached at `ramp_time`."},
      {.name = "ramp_time",
       .field = &S::ramp_time,
       .unit = "s",
       .no_default = true,
       .range = kTime,
       .rule = "required for and only with `\"ramp\"`",
       .doc = "The velocity rises linearly from 0 to `velocity` over this time, then stays: u = v t^2/(2 T) for "
              "t < T, v (t - T/2) after."},
      {.name = "table_time",
       .field = &S::table_time,
       .unit = "s",
       .no_default = true,
       .range = in(0.0, 1e6, "[]", "0 to 1e6 s"),
       .rule = "first 0; strictly ascending; at least 2 entries; only with `\"table\"` and `\"velocity_table\"`",
       .doc = "Times of the table."},
      {.name = "table_displacement",
       .field = &S::table_displacement,
       .unit = "m",
       .no_default = true,
       .range = kCoordinate,
       .rule = "same length as `table_time`; first row [0, 0, 0]; only with `\"table\"`",
       .doc = "Displacements [x, y, z] from the start position at each `table_time` (piecewise linear; constant "
              "after the last)."},
      {.name = "table_velocity",
       .field = &S::table_velocity,
       .unit = "m/s",
       .no_default = true,
       .range = kVelocity,
       .rule = "same length as `table_time`; only with `\"velocity_table\"`",
       .doc = "Velocities at each `table_time`, piecewise linear in time; the displacement is their exact "
              "integral, and the last velocity holds after the last time."},
      {.name = "velocity_file",
       .field = &S::velocity_file,
       .no_default = true,
       .rule = "an existing CSV file, relative paths from the case file's folder; only with `\"velocity_table\"`, "
               "not with `table_time`/`table_velocity`",
       .doc = "CSV with a header line and rows `time,vx,vy,vz` (s, m/s), read as `table_time`/`table_velocity`."},
  };
  return keys;
}

// The rules of the motion keys shared by [[group]] and [[mesh]] (read by motion_keys()).
void check_motion(const TableReader& r, const std::string& directory, MotionSettings& m) {
  // Every key only where the motion uses it.
  const std::map<std::string, std::vector<std::string>> uses{
      {"velocity", {"velocity", "ramp"}},          {"ramp_time", {"ramp"}},
      {"table_time", {"table", "velocity_table"}}, {"table_displacement", {"table"}},
      {"table_velocity", {"velocity_table"}},      {"velocity_file", {"velocity_table"}}};
  for (const auto& [key, kinds] : uses)
    if (r.has(key) && std::find(kinds.begin(), kinds.end(), m.kind) == kinds.end())
      r.fail(key, r.get(key), fmt::format("is not used with motion = \"{}\"", m.kind));
  if ((m.kind == "velocity" || m.kind == "ramp") && !r.has("velocity"))
    r.fail("velocity", nullptr, fmt::format("motion = \"{}\" needs a velocity [vx, vy, vz] in m/s", m.kind));
  if (m.kind == "ramp" && !r.has("ramp_time")) r.fail("ramp_time", nullptr, "motion = \"ramp\" needs ramp_time in s");
  if (m.kind == "velocity_table") {
    if (!m.velocity_file.empty()) {
      if (r.has("table_time") || r.has("table_velocity"))
        r.fail("velocity_file", r.get("velocity_file"), "give either velocity_file or table_time/table_velocity");
      read_velocity_csv(r, resolve(m.velocity_file, directory), m);
    }
    if (m.table_time.size() < 2 || m.table_time.size() != m.table_velocity.size())
      r.fail("table_time", r.get("table_time"),
             "motion = \"velocity_table\" needs table_time (s) and table_velocity (m/s) of equal length >= 2, "
             "or velocity_file");
  }
  if (m.kind == "table") {
    if (m.table_time.size() < 2 || m.table_time.size() != m.table_displacement.size())
      r.fail("table_time", r.get("table_time"),
             "motion = \"table\" needs table_time (s) and table_displacement (m) of equal length >= 2");
    for (double u : m.table_displacement[0])
      if (u != 0.0)
        r.fail("table_displacement", r.get("table_displacement"), "must start at [0, 0, 0] m (no jump at t = 0)");
  }
  if (m.kind == "table" || m.kind == "velocity_table") {
    const char* key = r.has("table_time") ? "table_time" : "velocity_file";
    if (m.table_time[0] != 0.0) r.fail(key, r.get(key), "the table must start at 0 s");
    for (std::size_t k = 1; k < m.table_time.size(); ++k)
      if (!(m.table_time[k] > m.table_time[k - 1])) r.fail(key, r.get(key), "times must be strictly ascending");
  }
}

Motion motion_from(const MotionSettings& ms) {
  Motion m;
  auto vec = [](const std::array<double, 3>& a) { return Vec3(a[0], a[1], a[2]); };
  m.velocity = vec(ms.velocity);
  m.time = ms.table_time;
  if (ms.kind == "velocity") {
    m.kind = Motion::Kind::Velocity;
  } else if (ms.kind == "ramp") {
    m.kind = Motion::Kind::Ramp;
    m.ramp_time = ms.ramp_time;
  } else if (ms.kind == "table") {
    m.kind = Motion::Kind::Table;
    for (const auto& u : ms.table_displacement) m.displacement.push_back(vec(u));
  } else if (ms.kind == "velocity_table") {
    m.kind = Motion::Kind::VelocityTable;
    // Displacement at each table time: the exact integral of the piecewise-linear velocity.
    m.displacement.push_back(Vec3::Zero());
    for (const auto& v : ms.table_velocity) m.table_velocity.push_back(vec(v));
    for (std::size_t k = 1; k < m.time.size(); ++k)
      m.displacement.push_back(m.displacement.back() +
                               0.5 * (m.table_velocity[k - 1] + m.table_velocity[k]) * (m.time[k] - m.time[k - 1]));
  }
  return m;
}

}  // namespace swarf
