// model.h: everything a run is made of, built from the case settings (the World, its
// StepSettings, and the case around them).
//
// The lattice becomes particles (structure of arrays) and rods (each stored once); the
// [[group]] tables and the [uniaxial] grips become groups with a prescribed motion. With
// workpiece.disorder_seed the particles start at the jittered positions and the rods at
// their jittered lengths (lattice_disorder.h); everything selected by position is selected
// on the ordered lattice.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "setup/case_config.h"
#include "setup/derived.h"
#include "swarf/integrate/step_settings.h"
#include "swarf/state/world.h"

namespace swarf {

/// The uniaxial test's geometry (when [uniaxial] is present).
struct UniaxialInfo {
  bool enabled = false;
  int axis = 0;                      ///< 0, 1, 2
  int grip_min = -1, grip_max = -1;  ///< group indices
  double gauge_length = 0;           ///< initial distance between the innermost gripped layers, m
  double cross_section = 0;          ///< initial cross-section, m^2 (lattice extent + one layer spacing per side)
  /// Rods crossing the plane halfway between the grips, with +1 if their end i lies on the
  /// low side: the force they carry is the bar's internal force at mid-length.
  std::vector<std::pair<std::int32_t, int>> midplane_rods;
};

/// A case built: the World the step works on (Model is one, so a Simulation takes it as
/// its World), the StepSettings for it, and what the run needs around the step.
struct Model : World {
  CaseSettings settings;  ///< the case as read
  Derived derived;        ///< what follows from it (printed, in summary.json)
  StepSettings step;      ///< the step's settings, from [integrator] and the derived step
  UniaxialInfo uniaxial;
  std::size_t lattice_particles = 0;  ///< particles 0..this-1 come from the workpiece; free ones follow
  /// Every particle's position before the workpiece's disorder (the ordered lattice's sites,
  /// then the free particles), m. Groups, grips and the cut's geometry are selected on these,
  /// so they are the same for every disorder_seed; without disorder they are the initial
  /// positions. Needed only while a run is set up: 'swarf run' frees it before the first step.
  std::vector<Vec3> sites;
};

/// Builds the model; throws InputError (naming the file and key) on anything inconsistent.
Model build_model(const CaseSettings& cs);

}  // namespace swarf
