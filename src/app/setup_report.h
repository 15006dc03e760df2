// setup_report.h: what a run prints before its first step: the case, the counts, the rod law
// and the lattice it makes, the step, and the uniaxial bar's prediction.
#pragma once

namespace swarf {

struct Model;

/// Prints the set-up to stdout (and a warning to stderr for a Poisson ratio the lattice cannot have).
void print_setup(const Model& m, int threads);

}  // namespace swarf
