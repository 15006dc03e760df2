// group_reactions.cpp: the groups' reaction forces (see group_reactions.h).
#include "app/observers/group_reactions.h"

#include <fmt/format.h>

#include "swarf/simulation.h"

namespace swarf {

void GroupReactions::columns(std::vector<Column>& out) const {
  for (const auto& g : groups_)
    for (char c : {'x', 'y', 'z'})
      out.push_back(
          {fmt::format("reaction_{}_{}", g.name, c), "N",
           fmt::format("{} component of the force that the prescribed motion of group '{}' exerts", c, g.name)});
}

void GroupReactions::row(const Simulation& sim, std::vector<double>& values) {
  for (std::size_t g = 0; g < groups_.size(); ++g)
    for (int c = 0; c < 3; ++c) values.push_back(sim.group_reaction(g)[c]);
}

void GroupReactions::finish(const RunEnd& end, nlohmann::json& summary) {
  for (std::size_t g = 0; g < groups_.size(); ++g) {
    const Vec3 r = end.sim.group_reaction(g);
    summary["results"]["reaction_" + groups_[g].name + "_N"] = {r[0], r[1], r[2]};
  }
}

}  // namespace swarf
