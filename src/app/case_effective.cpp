// case_effective.cpp: the case with its defaults (see case_effective.h). The values come from
// the settings structs through the same key table that filled them, so no key can be left out
// or named differently from the case file.
#include "app/case_effective.h"

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

// Adds each key of 'keys' with its value in 's' to 'j'.
template <class S>
void add_keys(nlohmann::json& j, const std::vector<Key<S>>& keys, const S& s) {
  static const S fresh{};
  for (const auto& k : keys)
    std::visit(
        [&](auto member) {
          if (k.no_default && s.*member == fresh.*member) return;  // (not given: nothing ran with it)
          j[std::string(k.name)] = value(s.*member);
        },
        k.field);
}

template <class S>
nlohmann::json table(const std::vector<Key<S>>& keys, const S& s) {
  nlohmann::json j = nlohmann::json::object();
  add_keys(j, keys, s);
  return j;
}

}  // namespace

nlohmann::json case_effective_json(const CaseSettings& cs) {
  nlohmann::json j = nlohmann::json::object();
  if (cs.cut.enabled) j["cut"] = table(cut_keys(), cs.cut);
  if (cs.workpiece.enabled) {
    j["workpiece"] = table(workpiece_keys(), cs.workpiece);
    j["material"] = table(material_keys(), cs.material);
    j["rod"] = table(rod_keys(), cs.rod);
  } else if (!cs.particles.empty() || !cs.particles_file.file.empty()) {
    // (without a workpiece [material] gives only the free particles' density: case_config.cpp)
    j["material"] = {{"density", value(cs.material.density)}};
  }
  if (cs.membrane.enabled) j["membrane"] = table(membrane_keys(), cs.membrane);
  j["integrator"] = table(integrator_keys(), cs.integrator);
  for (const auto& g : cs.groups) {
    nlohmann::json t = table(group_keys(), g);
    add_keys(t, motion_keys(), g.motion);
    j["group"].push_back(t);
  }
  if (cs.uniaxial.enabled) j["uniaxial"] = table(uniaxial_keys(), cs.uniaxial);
  if (cs.contact.enabled) j["contact"] = table(contact_keys(), cs.contact);
  j["environment"] = table(environment_keys(), cs);
  for (const auto& m : cs.meshes) {
    nlohmann::json t = table(mesh_keys(), m);
    add_keys(t, motion_keys(), m.motion);
    j["mesh"].push_back(t);
  }
  for (const auto& p : cs.particles) j["particle"].push_back(table(particle_keys(), p));
  if (!cs.particles_file.file.empty()) j["particles"] = table(particles_file_keys(), cs.particles_file);
  for (const auto& f : cs.inflows) j["inflow"].push_back(table(inflow_keys(), f));
  for (const auto& o : cs.outflows) j["outflow"].push_back(table(outflow_keys(), o));
  j["output"] = table(output_keys(), cs.output);
  return j;
}

}  // namespace swarf
