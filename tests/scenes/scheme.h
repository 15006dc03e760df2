// scheme.h: the integrator lines of a test scene whose rods can break, with the Newmark step
// unless they name a scheme. "auto" chose Newmark for such scenes until it came to mean Verlet
// (issue 35: the fixed-point Newmark costs 2.3-4.2 times Verlet on the cut); the tests written
// against the Newmark step keep it.
#pragma once

#include <string>

namespace swarf::test {

inline std::string newmark_unless_named(const std::string& integrator_lines) {
  return integrator_lines.find("scheme") == std::string::npos ? "scheme = \"newmark\"\n" + integrator_lines
                                                              : integrator_lines;
}

}  // namespace swarf::test
