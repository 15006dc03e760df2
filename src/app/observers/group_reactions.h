// group_reactions.h: the force each group's prescribed motion exerts on the rest of the body
// (N, x y z), per row and at the end in summary.json "results" (reaction_<group>_N).
#pragma once

#include "app/observers/observer.h"

namespace swarf {

struct Group;

class GroupReactions final : public Observer {
 public:
  /// The groups of the World the simulation steps (names only: held by reference).
  explicit GroupReactions(const std::vector<Group>& groups) : groups_(groups) {}
  std::string_view name() const override { return "reactions"; }
  void columns(std::vector<Column>& out) const override;
  void row(const Simulation& sim, std::vector<double>& values) override;
  void finish(const RunEnd& end, nlohmann::json& summary) override;

 private:
  const std::vector<Group>& groups_;
};

}  // namespace swarf
