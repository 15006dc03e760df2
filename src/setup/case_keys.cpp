// case_keys.cpp: the keys of the tables that are not modules ([environment], [output]), once (see
// case_keys.h; the modules' keys are in setup/modules/, [cut]'s in cut_keys.cpp). The docs' key tables are
// generated from these entries: edit a doc line here, then run
// 'swarf case keys --update docs/case-reference.md'.
#include "setup/case_keys.h"

namespace swarf {

const std::vector<Key<CaseSettings>>& environment_keys() {
  using S = CaseSettings;
  static const std::vector<Key<S>> keys{
      {.name = "gravity",
       .field = &S::gravity,
       .unit = "m/s^2",
       .range = in(-1e4, 1e4, "[]", "within 1e4 m/s^2, a thousand g"),
       .doc = "Gravitational acceleration g. The force m_i g acts on every particle, prescribed ones included "
              "(their weight enters the group reactions)."},
  };
  return keys;
}

}  // namespace swarf
