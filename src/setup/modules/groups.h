// groups.h: the groups' module of setup: [[group]]'s settings, key table, rules and build into the
// World's groups (by a side of the block or a region, on the ordered sites), and its lines of the
// setup printout. Listed once in each central list: parse_case (case_config.cpp), the key rows
// (case_key_text.cpp), the case echo (app/case_echo.cpp), build_model (model.cpp) and the setup
// printout (app/setup_report.cpp). Its motion keys are motion.h's; [uniaxial]'s grips and the
// membrane's clamped edge are groups too (add_group).
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "setup/key.h"
#include "setup/modules/motion.h"
#include "swarf/core/vec3.h"

namespace swarf {

struct CaseInput;
struct CaseSettings;
struct Model;

/// [[group]]: particles selected by a side of the box or a region, fixed or moved.
struct GroupSettings {
  std::string name;
  std::string side;  ///< "x-", "x+", "y-", "y+", "z-", "z+" (lattice layers at that face), or empty
  int layers = 1;    ///< number of lattice layers taken at 'side'
  std::array<double, 3> box_min{-kInf, -kInf, -kInf};  ///< region selection, m (used when side is empty)
  std::array<double, 3> box_max{kInf, kInf, kInf};     ///< m
  std::string dofs = "xyz";                            ///< prescribed components ("x", "xz", "xyz", ...)
  MotionSettings motion;
};

const std::vector<Key<GroupSettings>>& group_keys();

/// Reads the [[group]] tables (with their motion keys) and checks their rules.
void read_groups(const CaseInput& in, CaseSettings& cs);

/// Selects the particles of 'layers' lattice layers at a face ("x-", "z+", ...).
std::vector<std::int32_t> select_side(const std::vector<Vec3>& position, const std::string& side, int layers,
                                      double layer_spacing);

/// Adds a group of 'members' to the model; an empty group or one that overlaps another is an
/// InputError naming 'source'.
void add_group(Model& model, const std::string& source, const std::string& name, std::vector<std::int32_t> members,
               std::uint8_t dofs, Motion motion);

/// The [[group]] tables' groups, selected on the ordered 'sites' with layers 'h' apart.
void build_groups(const CaseSettings& cs, const std::vector<Vec3>& sites, double h, Model& model);

/// The setup printout's lines on the groups (each with its number of particles).
std::string groups_echo(const Model& m);

}  // namespace swarf
