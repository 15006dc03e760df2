// rod_laws.cpp: the list of the rod laws (see rod_laws.h).
#include "setup/rod_laws/rod_laws.h"

#include <fmt/format.h>

#include <algorithm>

#include "setup/rod_laws/bilinear.h"
#include "setup/rod_laws/johnson_cook.h"
#include "swarf/core/errors.h"

namespace swarf {

const std::vector<RodLawSetup>& rod_law_setups() {
  static const std::vector<RodLawSetup> laws{bilinear_setup::setup(), johnson_cook_setup::setup()};
  return laws;
}

const RodLawSetup& rod_law_setup(std::string_view name) {
  for (const RodLawSetup& s : rod_law_setups())
    if (std::find(s.names.begin(), s.names.end(), name) != s.names.end()) return s;
  throw InputError(fmt::format("rod.law: unknown law '{}'", name));
}

const RodLawSetup& rod_law_setup_of(const AnyRodLaw& law) {
  for (const RodLawSetup& s : rod_law_setups())
    if (s.holds(law)) return s;
  throw InputError("a rod law that no setup lists (setup/rod_laws/rod_laws.cpp)");
}

std::vector<std::string_view> rod_law_names() {
  std::vector<std::string_view> names;
  for (const RodLawSetup& s : rod_law_setups()) names.insert(names.end(), s.names.begin(), s.names.end());
  return names;
}

std::string rod_laws_with_conditions() {
  std::string out;
  for (const RodLawSetup& s : rod_law_setups())
    if (s.at_conditions)
      out += fmt::format("{}a {} rod law (--set rod.law=\"{}\")", out.empty() ? "" : " or ", s.title, s.names.front());
  return out;
}

}  // namespace swarf
