// bilinear.h: the paper's rod law in setup (rod.law = "bilinear", the default): it reads no
// keys of its own and adds no rules; its law is the base law every route builds (derived.cpp).
// Included by rod_laws.cpp only.
#pragma once

#include <variant>

#include "setup/rod_laws/rod_laws.h"

namespace swarf::bilinear_setup {

inline const std::vector<Key<RodSettings>>& keys() {
  static const std::vector<Key<RodSettings>> none;
  return none;
}

inline RodLawSetup setup() {
  return {.names = {"bilinear"},
          .title = "bilinear",
          .doc =
              "`\"bilinear\"`: the paper's elastic-plastic law with kinematic hardening (the single slope or the "
              "hardening curve above).",
          .holds = [](const AnyRodLaw& law) { return std::holds_alternative<BilinearRodLaw>(law); },
          .keys = keys,
          .rules = [](TableReader&, const CaseSettings&, bool) {},
          .build = [](const BilinearRodLaw& base, const CaseSettings&, const RodSettings&) { return AnyRodLaw(base); }};
}

}  // namespace swarf::bilinear_setup
