// case_echo.cpp: the case echoes of summary.json (see case_echo.h). Both walk the tables in
// the same order, with the key table's entries naming the settings' members; they differ in
// which keys they take.
#include "app/case_echo.h"

#include <functional>

#include "app/summary.h"
#include "setup/case_keys.h"

namespace swarf {
namespace {

nlohmann::json value(double v) { return number(v); }
nlohmann::json value(int v) { return v; }
nlohmann::json value(bool v) { return v; }
nlohmann::json value(const std::string& v) { return v; }
template <class T, std::size_t N>
nlohmann::json value(const std::array<T, N>& v) {
  nlohmann::json j = nlohmann::json::array();
  for (const auto& x : v) j.push_back(value(x));
  return j;
}
template <class T>
nlohmann::json value(const std::vector<T>& v) {
  nlohmann::json j = nlohmann::json::array();
  for (const auto& x : v) j.push_back(value(x));
  return j;
}

// Which tables and keys an echo takes: 'table' and 'key' are paths as in CaseSettings::given
// ("mesh.0", "mesh.0.origin").
struct Selection {
  std::function<bool(const std::string& table)> table;
  std::function<bool(const std::string& key, bool no_default_unset)> key;
};

// The struct's default member initialisers, made once.
template <class S>
const S& defaults() {
  static const S d{};
  return d;
}

// Adds each selected key of 'keys' with its value in 's' to 'j'.
template <class S>
void add_keys(nlohmann::json& j, const std::vector<Key<S>>& keys, const S& s, const Selection& sel,
              const std::string& path) {
  for (const auto& k : keys)
    std::visit(
        [&](auto member) {
          // (a key whose default only means "not given", left at it: nothing ran with it)
          const bool unset = k.no_default && s.*member == defaults<S>().*member;
          if (sel.key(path + "." + std::string(k.name), unset)) j[std::string(k.name)] = value(s.*member);
        },
        k.field);
}

template <class S>
void add_table(nlohmann::json& j, const char* name, const std::vector<Key<S>>& keys, const S& s, const Selection& sel) {
  if (!sel.table(name)) return;
  nlohmann::json t = nlohmann::json::object();
  add_keys(t, keys, s, sel, name);
  j[name] = t;
}

// An array of tables ([[group]], ...): one entry per settings struct the case has; 'motion'
// names the member that the motion keys of a [[group]] or [[mesh]] fill.
template <class S>
void add_array(nlohmann::json& j, const char* name, const std::vector<S>& entries, const std::vector<Key<S>>& keys,
               const Selection& sel, MotionSettings S::*motion = nullptr) {
  for (std::size_t i = 0; i < entries.size(); ++i) {
    const std::string path = std::string(name) + "." + std::to_string(i);
    if (!sel.table(path)) continue;
    nlohmann::json t = nlohmann::json::object();
    add_keys(t, keys, entries[i], sel, path);
    if (motion) add_keys(t, motion_keys(), entries[i].*motion, sel, path);
    j[name].push_back(t);
  }
}

nlohmann::json echo(const CaseSettings& cs, const Selection& sel) {
  nlohmann::json j = nlohmann::json::object();
  add_table(j, "cut", cut_keys(), cs.cut, sel);
  add_table(j, "workpiece", workpiece_keys(), cs.workpiece, sel);
  add_table(j, "membrane", membrane_keys(), cs.membrane, sel);
  add_table(j, "material", material_keys(), cs.material, sel);
  add_table(j, "rod", rod_keys(), cs.rod, sel);
  add_table(j, "integrator", integrator_keys(), cs.integrator, sel);
  add_array(j, "group", cs.groups, group_keys(), sel, &GroupSettings::motion);
  add_table(j, "uniaxial", uniaxial_keys(), cs.uniaxial, sel);
  add_table(j, "contact", contact_keys(), cs.contact, sel);
  add_table(j, "heat", heat_keys(), cs.heat, sel);
  add_table(j, "environment", environment_keys(), cs, sel);
  add_array(j, "mesh", cs.meshes, mesh_keys(), sel, &MeshSettings::motion);
  add_array(j, "particle", cs.particles, particle_keys(), sel);
  add_table(j, "particles", particles_file_keys(), cs.particles_file, sel);
  add_array(j, "inflow", cs.inflows, inflow_keys(), sel);
  add_array(j, "outflow", cs.outflows, outflow_keys(), sel);
  add_table(j, "output", output_keys(), cs.output, sel);
  return j;
}

}  // namespace

nlohmann::json case_json(const CaseSettings& cs) {
  const auto given = [&](const std::string& path) { return cs.given.count(path) > 0; };
  return echo(cs, {given, [&](const std::string& key, bool) { return given(key); }});
}

nlohmann::json case_effective_json(const CaseSettings& cs) {
  // The tables in use: those whose settings say so, the arrays' every entry, and the two
  // every run reads.
  const bool free_particles = !cs.particles.empty() || !cs.particles_file.file.empty();
  const auto in_use = [&](const std::string& table) {
    if (table == "cut") return cs.cut.enabled;
    if (table == "workpiece" || table == "rod") return cs.workpiece.enabled;
    if (table == "material") return cs.workpiece.enabled || free_particles;
    if (table == "membrane") return cs.membrane.enabled;
    if (table == "uniaxial") return cs.uniaxial.enabled;
    if (table == "contact") return cs.contact.enabled;
    if (table == "heat") return cs.heat.present;
    if (table == "particles") return !cs.particles_file.file.empty();
    return true;  // integrator, environment, output, and each entry of an array of tables
  };
  const auto key = [&](const std::string& key, bool unset) {
    // Without a workpiece [material] gives only the free particles' density (case_config.cpp).
    if (!cs.workpiece.enabled && key.rfind("material.", 0) == 0) return key == "material.density";
    return !unset;
  };
  return echo(cs, {in_use, key});
}

}  // namespace swarf
