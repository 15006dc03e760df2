// checkpoint.cpp: writing and reading restart files (see checkpoint.h). The member functions
// Simulation::save/load and ContactSystem::save/load live here so that everything a
// checkpoint holds is listed in one file.
#include "checkpoint.h"

#include <filesystem>
#include <fmt/format.h>

#include "errors.h"
#include "h5file.h"
#include "simulation.h"

namespace swarf {
namespace {

constexpr double kFormat = 1.0;  // checkpoint layout version

void put(H5File& f, const std::string& name, const std::vector<Vec3>& v) {
  f.write(name, v.empty() ? nullptr : v[0].data(), v.size(), 3);
}
void put(H5File& f, const std::string& name, const std::vector<double>& v) {
  f.write(name, v.data(), v.size(), 1);
}
void put(H5File& f, const std::string& name, const std::vector<std::uint8_t>& v) { f.write(name, v.data(), v.size()); }

std::vector<double> get(const H5File& f, const std::string& name, std::size_t rows, std::size_t cols) {
  std::size_t r = 0, c = 0;
  auto v = f.read_doubles(name, r, c);
  if (r != rows || c != cols)
    throw InputError(fmt::format("checkpoint '{}': dataset '{}' has shape {} x {}, expected {} x {} "
                                 "(the checkpoint belongs to another case or version)",
                                 f.path(), name, r, c, rows, cols));
  return v;
}
std::vector<double> get_any(const H5File& f, const std::string& name) {
  std::size_t r = 0, c = 0;
  return f.read_doubles(name, r, c);
}
void get(const H5File& f, const std::string& name, std::vector<Vec3>& out) {
  const auto v = get(f, name, out.size(), 3);
  for (std::size_t i = 0; i < out.size(); ++i) out[i] = Vec3(v[3 * i], v[3 * i + 1], v[3 * i + 2]);
}
void get(const H5File& f, const std::string& name, std::vector<double>& out) { out = get(f, name, out.size(), 1); }
void get(const H5File& f, const std::string& name, std::vector<std::uint8_t>& out) {
  std::size_t r = 0, c = 0;
  const auto v = f.read_ints(name, r, c);
  if (r != out.size() || c != 1)
    throw InputError(fmt::format("checkpoint '{}': dataset '{}' has {} entries, expected {}", f.path(), name, r,
                                 out.size()));
  for (std::size_t i = 0; i < r; ++i) out[i] = static_cast<std::uint8_t>(v[i]);
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

void ContactSystem::save(H5File& f, const std::string& prefix) const {
  std::vector<std::int64_t> pairs(2 * pairs_.size()), tris(2 * tris_.size());
  std::vector<Vec3> th(tris_.size());
  for (std::size_t k = 0; k < pairs_.size(); ++k) {
    pairs[2 * k] = pairs_[k].i;
    pairs[2 * k + 1] = pairs_[k].j;
  }
  for (std::size_t k = 0; k < tris_.size(); ++k) {
    tris[2 * k] = tris_[k].i;
    tris[2 * k + 1] = tris_[k].tri;
    th[k] = tris_[k].history;
  }
  f.write(prefix + "/pairs", pairs.data(), pairs_.size(), 2);
  put(f, prefix + "/pair_history", phist_);
  f.write(prefix + "/triangle_contacts", tris.data(), tris_.size(), 2);
  put(f, prefix + "/triangle_history", th);
  put(f, prefix + "/x_build", x_build_);
  put(f, prefix + "/mesh_build", mesh_build_);
  const std::vector<double> builds{double(builds_)};
  put(f, prefix + "/builds", builds);
}

void ContactSystem::load(const H5File& f, const std::string& prefix, const Particles& p) {
  std::size_t r = 0, c = 0;
  const auto pairs = f.read_ints(prefix + "/pairs", r, c);
  const std::size_t np = pairs.empty() ? 0 : r;
  pairs_.resize(np);
  for (std::size_t k = 0; k < np; ++k)
    pairs_[k] = Pair{static_cast<std::int32_t>(pairs[2 * k]), static_cast<std::int32_t>(pairs[2 * k + 1])};
  phist_.assign(np, Vec3::Zero());
  get(f, prefix + "/pair_history", phist_);
  const auto tris = f.read_ints(prefix + "/triangle_contacts", r, c);
  const std::size_t nt = tris.empty() ? 0 : r;
  std::vector<Vec3> th(nt, Vec3::Zero());
  get(f, prefix + "/triangle_history", th);
  tris_.assign(nt, TriPair{});
  for (std::size_t k = 0; k < nt; ++k) {
    tris_[k].i = static_cast<std::int32_t>(tris[2 * k]);
    tris_[k].tri = static_cast<std::int32_t>(tris[2 * k + 1]);
    tris_[k].history = th[k];
    if (tris_[k].i < 0 || std::size_t(tris_[k].i) >= p.size() || tris_[k].tri < 0 ||
        std::size_t(tris_[k].tri) >= tri_mesh_.size())
      throw InputError(fmt::format("checkpoint '{}': triangle contact {} out of range", f.path(), k));
  }
  for (const auto& q : pairs_)
    if (q.i < 0 || q.j <= q.i || std::size_t(q.j) >= p.size())
      throw InputError(fmt::format("checkpoint '{}': contact pair ({}, {}) out of range", f.path(), q.i, q.j));
  x_build_.assign(p.size(), Vec3::Zero());
  get(f, prefix + "/x_build", x_build_);
  mesh_build_.assign(meshes_->size(), Vec3::Zero());
  get(f, prefix + "/mesh_build", mesh_build_);
  builds_ = static_cast<std::size_t>(get(f, prefix + "/builds", 1, 1)[0]);
  finish_build(p);
}

void Simulation::save(H5File& f) const {
  const auto& p = m_.particles;
  const auto& r = m_.rods;
  put(f, "/sim/particles/position", p.position);
  put(f, "/sim/particles/velocity", p.velocity);
  put(f, "/sim/particles/acceleration", p.acceleration);
  put(f, "/sim/particles/force", p.force);
  std::vector<double> q(4 * p.size());
  for (std::size_t i = 0; i < p.size(); ++i)
    for (int c = 0; c < 4; ++c) q[4 * i + c] = p.orientation[i][c];
  f.write("/sim/particles/orientation", q.data(), p.size(), 4);
  put(f, "/sim/particles/omega", p.omega);
  put(f, "/sim/particles/omega_dot", p.omega_dot);
  put(f, "/sim/particles/torque", p.torque);
  put(f, "/sim/rods/shift", r.shift);
  put(f, "/sim/rods/intact", r.intact);
  put(f, "/sim/rods/trial_shift", r.trial_shift);
  put(f, "/sim/rods/trial_broken", r.trial_broken);
  put(f, "/sim/rods/stress", r.stress);
  put(f, "/sim/rods/force_coef", r.force_coef);
  std::vector<Vec3> offset, velocity;
  for (const auto& mb : m_.meshes) {
    offset.push_back(mb.offset);
    velocity.push_back(mb.velocity);
  }
  put(f, "/sim/meshes/offset", offset);
  put(f, "/sim/meshes/velocity", velocity);
  put(f, "/sim/groups/u_old", group_u_old_);
  put(f, "/sim/groups/u_new", group_u_new_);
  put(f, "/sim/groups/reaction", reaction_);
  put(f, "/sim/groups/reaction_old", reaction_old_);
  put(f, "/sim/groups/velocity", group_v_);
  put(f, "/sim/mesh_force", mesh_force_);
  put(f, "/sim/contact_force", contact_force_);
  const std::vector<double> s{time_,
                              dt_,
                              last_dt_,
                              double(broken_),
                              rotations_ ? 1.0 : 0.0,
                              rebuild_lists_ ? 1.0 : 0.0,
                              contact_power_old_,
                              ledger_.external_work,
                              ledger_.plastic_work,
                              ledger_.viscous_work,
                              ledger_.fracture_energy,
                              ledger_.contact_work,
                              double(stats_.accepted),
                              double(stats_.rejected),
                              double(stats_.iterations),
                              double(stats_.force_evaluations),
                              double(stats_.max_iterations),
                              double(stats_.last_iterations)};
  put(f, "/sim/scalars", s);
  if (contacts_.enabled()) contacts_.save(f, "/sim/contacts");
}

void Simulation::load(const H5File& f) {
  auto& p = m_.particles;
  auto& r = m_.rods;
  get(f, "/sim/particles/position", p.position);
  get(f, "/sim/particles/velocity", p.velocity);
  get(f, "/sim/particles/acceleration", p.acceleration);
  get(f, "/sim/particles/force", p.force);
  const auto q = get(f, "/sim/particles/orientation", p.size(), 4);
  for (std::size_t i = 0; i < p.size(); ++i)
    for (int c = 0; c < 4; ++c) p.orientation[i][c] = q[4 * i + c];
  get(f, "/sim/particles/omega", p.omega);
  get(f, "/sim/particles/omega_dot", p.omega_dot);
  get(f, "/sim/particles/torque", p.torque);
  get(f, "/sim/rods/shift", r.shift);
  get(f, "/sim/rods/intact", r.intact);
  get(f, "/sim/rods/trial_shift", r.trial_shift);
  get(f, "/sim/rods/trial_broken", r.trial_broken);
  get(f, "/sim/rods/stress", r.stress);
  get(f, "/sim/rods/force_coef", r.force_coef);
  std::vector<Vec3> offset(m_.meshes.size()), velocity(m_.meshes.size());
  get(f, "/sim/meshes/offset", offset);
  get(f, "/sim/meshes/velocity", velocity);
  for (std::size_t k = 0; k < m_.meshes.size(); ++k) {
    m_.meshes[k].offset = offset[k];
    m_.meshes[k].velocity = velocity[k];
  }
  get(f, "/sim/groups/u_old", group_u_old_);
  get(f, "/sim/groups/u_new", group_u_new_);
  get(f, "/sim/groups/reaction", reaction_);
  reaction_old_.assign(reaction_.size(), Vec3::Zero());
  get(f, "/sim/groups/reaction_old", reaction_old_);
  get(f, "/sim/groups/velocity", group_v_);
  mesh_force_.assign(m_.meshes.size(), Vec3::Zero());
  get(f, "/sim/mesh_force", mesh_force_);
  get(f, "/sim/contact_force", contact_force_);
  const auto s = get(f, "/sim/scalars", 18, 1);
  time_ = s[0];
  dt_ = s[1];
  last_dt_ = s[2];
  broken_ = static_cast<std::size_t>(s[3]);
  rotations_ = s[4] != 0.0;
  rebuild_lists_ = s[5] != 0.0;
  contact_power_old_ = s[6];
  ledger_ = EnergyLedger{s[7], s[8], s[9], s[10], s[11]};
  stats_.accepted = static_cast<std::int64_t>(s[12]);
  stats_.rejected = static_cast<std::int64_t>(s[13]);
  stats_.iterations = static_cast<std::int64_t>(s[14]);
  stats_.force_evaluations = static_cast<std::int64_t>(s[15]);
  stats_.max_iterations = static_cast<int>(s[16]);
  stats_.last_iterations = static_cast<int>(s[17]);
  if (rotations_) update_free_to_rotate();
  if (contacts_.enabled()) contacts_.load(f, "/sim/contacts", p);
}

void write_checkpoint(const std::string& path, const Simulation& sim, const RunRecord& rec, const CheckpointCase& c) {
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
    sim.save(f);
    f.write("/run/rows", rec.rows.data(), rec.columns ? rec.rows.size() / rec.columns : 0,
            std::max<std::size_t>(rec.columns, 1));
    const std::vector<double> s{double(rec.columns), rec.e0,         rec.next_row,   rec.next_frame,
                                rec.predicted,       rec.bar_shift,  rec.bar_broken, rec.max_stress,
                                rec.max_mismatch,    rec.wall_s,     rec.output_s,   double(sim.steps())};
    put(f, "/run/scalars", s);
    put(f, "/run/s_strain", rec.s_strain);
    put(f, "/run/s_stress", rec.s_stress);
    put(f, "/run/s_segment", rec.s_segment);
    put(f, "/run/frame_times", rec.frame_times);
  }  // closed (flushed) before the rename
  std::filesystem::rename(tmp, path);
}

CheckpointCase read_checkpoint_case(const std::string& path) {
  if (!std::filesystem::exists(path)) throw InputError(fmt::format("--restart: checkpoint '{}' does not exist", path));
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

void read_checkpoint(const std::string& path, Simulation& sim, RunRecord& rec) {
  H5File f(path, H5File::Mode::Read);
  sim.load(f);
  const auto s = get(f, "/run/scalars", 12, 1);
  rec.columns = static_cast<std::size_t>(s[0]);
  rec.e0 = s[1];
  rec.next_row = s[2];
  rec.next_frame = s[3];
  rec.predicted = s[4];
  rec.bar_shift = s[5];
  rec.bar_broken = s[6];
  rec.max_stress = s[7];
  rec.max_mismatch = s[8];
  rec.wall_s = s[9];
  rec.output_s = s[10];
  rec.last_checkpoint_step = static_cast<std::int64_t>(s[11]);
  rec.rows = get_any(f, "/run/rows");
  if (rec.columns == 0 || rec.rows.size() % rec.columns != 0)
    throw InputError(fmt::format("checkpoint '{}': series rows do not match {} columns", path, rec.columns));
  rec.s_strain = get_any(f, "/run/s_strain");
  rec.s_stress = get_any(f, "/run/s_stress");
  rec.s_segment = get_any(f, "/run/s_segment");
  rec.frame_times = get_any(f, "/run/frame_times");
}

}  // namespace swarf
