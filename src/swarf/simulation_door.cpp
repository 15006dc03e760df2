// simulation_door.cpp: reordering, removing and appending particles between steps (see
// simulation.h and state/reindex.h).
#include <fmt/format.h>

#include <cmath>
#include <stdexcept>
#include <utility>

#include "swarf/core/bounds.h"
#include "swarf/core/errors.h"
#include "swarf/core/parallel.h"
#include "swarf/simulation.h"

namespace swarf {

void Simulation::resize_scratch() {
  const std::size_t n = m_.particles.size();
  sys_.for_each([&](auto& s) {
    if constexpr (requires { s.resize(m_); }) s.resize(m_);
  });
  if (sys_.contacts.enabled()) ms_.contact_force.resize(n, Vec3::Zero());
  if (ms_.rotations) integrate::update_free_to_rotate(m_, ms_);
  ms_.moved2 = -1.0;
  update_mesh_step_limit();
}

void Simulation::reindex_all(const Reindex& r) {
  reindex(m_.particles, r);
  reindex(m_.rods, r);
  reindex(m_.groups, r);
  if (sys_.contacts.enabled()) {
    reindex_array(ms_.contact_force, r);
    sys_.contacts.reindex(r.new_index, r.new_count, m_.particles);
  }
  resize_scratch();
}

void Simulation::apply_permutation(const std::vector<std::int32_t>& order) {
  if (order.size() != m_.particles.size())
    throw InputError("apply_permutation: the order has " + std::to_string(order.size()) + " entries for " +
                     std::to_string(m_.particles.size()) + " particles");
  try {
    reindex_all(Reindex::permutation(order));
  } catch (const std::invalid_argument& e) {
    throw InputError(std::string("apply_permutation: ") + e.what());
  }
}

std::size_t Simulation::remove_particles(const std::vector<std::uint8_t>& remove) {
  if (remove.size() != m_.particles.size())
    throw InputError("remove_particles: the mask has " + std::to_string(remove.size()) + " entries for " +
                     std::to_string(m_.particles.size()) + " particles");
  const std::size_t rods_before = m_.rods.size();
  reindex_all(Reindex::removal(remove));
  return rods_before - m_.rods.size();
}

void Simulation::append_particles(const Particles& extra) {
  Particles add = extra;  // (a copy: its fields are moved into the World's arrays)
  const std::size_t k = add.position.size();
  bool consistent = true;
  add.for_each_field(
      [&](const char* name, auto& v) { consistent = consistent && (v.size() == k || std::string(name) == "id"); });
  if (!consistent)
    throw InputError("append_particles: the new particles' arrays differ in length (size them with Particles::resize)");
  auto& p = m_.particles;
  add.set_layout(p.layout);  // (the groups the World holds, so that the fields pair up)
  add.id.resize(k);
  for (std::size_t q = 0; q < k; ++q) add.id[q] = p.next_id++;
  // Both for_each_field walks visit the same fields in the same order: pair them by index.
  std::vector<void*> targets;
  p.for_each_field([&](const char*, auto& v) { targets.push_back(&v); });
  std::size_t f = 0;
  add.for_each_field([&](const char*, auto& v) {
    auto& dst = *static_cast<std::remove_reference_t<decltype(v)>*>(targets[f++]);
    dst.insert(dst.end(), v.begin(), v.end());
  });
  m_.rods.build_rows(p.size());
  // The contact lists keep their pairs (the old particles keep their indices) and grow their
  // rows to the new count, so that the rebuild at the next evaluation carries the committed
  // friction histories over (it does when the rows match the particles) and a checkpoint
  // written before it holds lists of the particles' size.
  if (sys_.contacts.enabled()) {
    std::vector<std::int32_t> same(p.size() - k);
    for (std::size_t i = 0; i < same.size(); ++i) same[i] = static_cast<std::int32_t>(i);
    sys_.contacts.reindex(same, p.size(), p);
  }
  ms_.rebuild_lists = true;  // (the lists' build reference no longer matches the particles)
  resize_scratch();
}

namespace {
// The door's refusals for a wholesale change of the particles (replace_particles, overwrite_records).
void check_wholesale(const World& w, bool contacts, const ContactSystem::Records* records, const char* door) {
  if (!w.bodies.empty() || !w.inflows.empty() || !w.outflows.empty())
    throw InputError(fmt::format("{}: not with rigid bodies or particle flows", door));
  if (contacts && !records) throw InputError(fmt::format("{}: the contacts' records are missing", door));
}
}  // namespace

void Simulation::replace_particles(Particles particles, Rods rods, const ContactSystem::Records* contacts) {
  check_wholesale(m_, sys_.contacts.enabled(), contacts, "replace_particles");
  const std::size_t n = particles.position.size(), m = rods.ends.size();
  bool consistent = true;
  particles.for_each_field([&](const char*, auto& v) { consistent = consistent && v.size() == n; });
  rods.for_each_field([&](const char*, auto& v) { consistent = consistent && v.size() == m; });
  for (const auto& e : rods.ends)
    consistent = consistent && e[0] >= 0 && e[0] < e[1] && static_cast<std::size_t>(e[1]) < n;
  for (const std::int32_t g : particles.group)
    consistent = consistent && g >= -1 && g < static_cast<std::int32_t>(m_.groups.size());
  if (!consistent)
    throw InputError(
        "replace_particles: arrays of unequal length, rod ends out of range or not ascending, or a group index "
        "out of range");
  const ParticleLayout layout = m_.particles.layout;
  m_.particles = std::move(particles);
  m_.particles.set_layout(layout);  // (the groups this run holds)
  m_.rods.ends = std::move(rods.ends);
  m_.rods.for_each_field_with(rods, [](auto& mine, auto& theirs) { mine = std::move(theirs); });
  records_replaced(contacts);
}

void Simulation::overwrite_records(const std::function<void(Particles&, Rods&)>& write,
                                   const ContactSystem::Records* contacts) {
  check_wholesale(m_, sys_.contacts.enabled(), contacts, "overwrite_records");
  const std::size_t n = m_.particles.size(), m = m_.rods.size();
  write(m_.particles, m_.rods);
  if (m_.particles.size() != n || m_.rods.size() != m)
    throw std::logic_error("overwrite_records: the particles or rods were resized");
  records_replaced(contacts);
}

void Simulation::records_replaced(const ContactSystem::Records* contacts) {
  const std::size_t n = m_.particles.size();
  m_.rods.build_rows(n);
  for (Group& g : m_.groups) g.members.clear();  // (the members from the particles' group indices, ascending)
  for (std::size_t i = 0; i < n; ++i)
    if (m_.particles.group[i] >= 0) m_.groups[m_.particles.group[i]].members.push_back(static_cast<std::int32_t>(i));
  if (sys_.contacts.enabled()) {
    sys_.contacts.replace(m_.particles, m_.rods, *contacts);
    ms_.contact_force.assign(n, Vec3::Zero());  // (the next evaluation's gather fills it)
  }
  resize_scratch();
}

void Simulation::set_body_pose(std::size_t b, const Vec3& position, const Quat& orientation) {
  if (b >= m_.bodies.size()) throw InputError(fmt::format("set_body_pose: body {} of {}", b, m_.bodies.size()));
  RigidBody& rb = m_.bodies[b];
  const std::string& name = m_.meshes[rb.mesh].name;
  const double norm = orientation.norm();
  if (!all_finite(position) || !(norm > 0.0) || !std::isfinite(norm))
    throw InputError(fmt::format(
        "set_body_pose: body '{}': position ({}, {}, {}) m and orientation ({}, {}, {}, {}) "
        "must be finite, the orientation non-zero",
        name, position[0], position[1], position[2], orientation[0], orientation[1], orientation[2], orientation[3]));
  const Quat q = orientation / norm;
  if (rb.rotation == BodyRotation::Hinge && q != rb.state.orientation)
    throw InputError(
        fmt::format("set_body_pose: body '{}' turns on a hinge: its orientation follows the hinge's "
                    "angle and cannot be set",
                    name));
  if (rb.rotation == BodyRotation::Hinge && rb.pivoted && position != rb.state.position)
    throw InputError(
        fmt::format("set_body_pose: body '{}' turns about a pivot: its centre follows the hinge's "
                    "angle and cannot be set",
                    name));
  rb.state.position = position;
  rb.state.orientation = q;
  sys_.bodies.place_mesh(m_, b);  // (the contact lists see the jump: they measure the meshes' moves from their build)
}

}  // namespace swarf
