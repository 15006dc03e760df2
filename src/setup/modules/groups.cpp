// groups.cpp: the groups' module of setup (see groups.h).
#include "setup/modules/groups.h"

#include <fmt/format.h>

#include <cmath>

#include "setup/case_tables.h"
#include "setup/model.h"
#include "swarf/core/errors.h"

namespace swarf {
namespace {

// The prescribed components' mask of 'dofs' ("x", "xz", "xyz": bits 0, 1, 2).
std::uint8_t dof_mask(const std::string& dofs) {
  std::uint8_t m = 0;
  for (char ch : dofs) m |= static_cast<std::uint8_t>(1u << (ch - 'x'));
  return m;
}

}  // namespace

const std::vector<Key<GroupSettings>>& group_keys() {
  using S = GroupSettings;
  static const std::vector<Key<S>> keys{
      {.name = "name",
       .field = &S::name,
       .no_default = true,
       .default_note = "`group<index>`",
       .rule = "non-empty; letters, digits, `_` and `-` only; unique among groups. `grip_min` and `grip_max` are "
               "reserved when `[uniaxial]` is present.",
       .doc = "Name used in outputs (`reaction_<name>_x`, ...)."},
      {.name = "side",
       .field = &S::side,
       .default_note = "select by box",
       .choices = {"x-", "x+", "y-", "y+", "z-", "z+"},
       .rule = "not with `box_min`/`box_max`",
       .doc = "Select by side: lattice layers at that face."},
      {.name = "layers",
       .field = &S::layers,
       .unit = "1",
       .range = in(1, 1000, "[]"),
       .rule = "only with `side`",
       .doc = "Number of lattice layers taken at `side`."},
      {.name = "box_min",
       .field = &S::box_min,
       .unit = "m",
       .range = kCoordinate,
       .rule = "each <= the `box_max` entry; not with `side`",
       .doc = "Lower corner of the selection box."},
      {.name = "box_max",
       .field = &S::box_max,
       .unit = "m",
       .range = kCoordinate,
       .rule = "not with `side`",
       .doc = "Upper corner of the selection box."},
      {.name = "dofs",
       .field = &S::dofs,
       .choices = {"x", "y", "z", "xy", "xz", "yz", "xyz"},
       .doc = "Prescribed components. The others stay free."},
  };
  return keys;
}

void read_groups(const CaseInput& in, CaseSettings& cs) {
  const toml::array* arr = entries(in, "group");
  if (!arr) return;
  std::set<std::string> names;
  for (std::size_t g = 0; g < arr->size(); ++g) {
    TableReader r = in.reader((*arr)[g].as_table(), "group");
    GroupSettings gs;
    r.read(group_keys(), gs);
    r.read(motion_keys(), gs.motion);
    r.finish();  // (an unknown key, often a misspelt one, is named before the rules between keys)
    if (!r.has("name")) gs.name = fmt::format("group{}", g);
    if (!names.insert(gs.name).second) r.fail("name", r.get("name"), "two groups have this name");
    check_motion(r, in.directory, gs.motion);
    const bool has_box = r.has("box_min") || r.has("box_max");
    if (!gs.side.empty() && has_box) {
      const char* key = r.has("box_min") ? "box_min" : "box_max";
      r.fail(key, r.get(key), "give either side (with layers) or box_min/box_max, not both");
    }
    if (gs.side.empty() && r.has("layers")) r.fail("layers", r.get("layers"), "layers needs side");
    if (gs.side.empty() && !has_box) r.fail("side", nullptr, "a group needs side = \"x-\" ... or box_min/box_max (m)");
    for (int c = 0; c < 3; ++c)
      if (gs.box_min[c] > gs.box_max[c]) r.fail("box_min", r.get("box_min"), "must not exceed box_max");
    check_name(r, gs.name);
    cs.groups.push_back(gs);
  }
}

std::vector<std::int32_t> select_side(const std::vector<Vec3>& position, const std::string& side, int layers,
                                      double layer_spacing) {
  const int c = side[0] - 'x';
  const bool upper = side[1] == '+';
  double ext = position[0][c];
  for (const auto& p : position) ext = upper ? std::max(ext, p[c]) : std::min(ext, p[c]);
  const double reach = (layers - 0.5) * layer_spacing;
  std::vector<std::int32_t> out;
  for (std::size_t i = 0; i < position.size(); ++i)
    if (std::abs(position[i][c] - ext) < reach) out.push_back(static_cast<std::int32_t>(i));
  return out;
}

void add_group(Model& model, const std::string& source, const std::string& name, std::vector<std::int32_t> members,
               std::uint8_t dofs, Motion motion) {
  auto& p = model.particles;
  if (members.empty()) throw InputError(fmt::format("{}: group '{}' selects no particle", source, name));
  for (auto i : members) {
    if (p.group[i] >= 0)
      throw InputError(fmt::format("{}: particle {} belongs to groups '{}' and '{}'; groups must not overlap", source,
                                   i, model.groups[p.group[i]].name, name));
    p.group[i] = static_cast<std::int32_t>(model.groups.size());
    p.prescribed[i] = dofs;
  }
  model.groups.push_back(Group{name, dofs, std::move(motion), std::move(members)});
}

void build_groups(const CaseSettings& cs, const std::vector<Vec3>& sites, double h, Model& model) {
  const std::size_t n = sites.size();
  for (const auto& gs : cs.groups) {
    std::vector<std::int32_t> members;
    if (!gs.side.empty()) {
      members = select_side(sites, gs.side, gs.layers, h);
    } else {
      for (std::size_t i = 0; i < n; ++i) {
        bool in = true;
        for (int c = 0; c < 3; ++c) in = in && sites[i][c] >= gs.box_min[c] && sites[i][c] <= gs.box_max[c];
        if (in) members.push_back(static_cast<std::int32_t>(i));
      }
    }
    add_group(model, cs.source, gs.name, std::move(members), dof_mask(gs.dofs), motion_from(gs.motion));
  }
}

std::string groups_echo(const Model& m) {
  std::string out;
  for (const auto& g : m.groups) out += fmt::format("  group '{}': {} particles\n", g.name, g.members.size());
  return out;
}

}  // namespace swarf
