// particles.h: the free particles' module of setup: [[particle]]'s and [particles]' settings, key
// tables, rules and build (the particles appended after the lattice's). Listed once in each central
// list: parse_case (case_config.cpp), the key rows (case_key_text.cpp), the case echo
// (app/case_echo.cpp) and build_model (model.cpp). Their masses are fill_particles' (model.cpp): solid
// spheres of [material]'s density.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "setup/key.h"
#include "swarf/core/vec3.h"

namespace swarf {

struct CaseInput;
struct CaseSettings;
struct Lattice;

/// [[particle]]: a single free particle (contact tests, packings written by hand).
struct ParticleSettings {
  std::array<double, 3> position{0, 0, 0};          ///< m
  std::array<double, 3> velocity{0, 0, 0};          ///< m/s
  std::array<double, 3> angular_velocity{0, 0, 0};  ///< rad/s (world frame)
  double radius = 0.0;                              ///< m
};

/// [particles]: free particles from a text file (columns id x y z vx vy vz, SI units).
struct ParticlesFileSettings {
  std::string file;
  double radius = 0.0;  ///< m
};

const std::vector<Key<ParticleSettings>>& particle_keys();
const std::vector<Key<ParticlesFileSettings>>& particles_file_keys();

/// Reads the [[particle]] tables and checks their rules.
void read_particles(const CaseInput& in, CaseSettings& cs);

/// Reads [particles] when present and checks its rules (the file is there).
void read_particles_file(const CaseInput& in, CaseSettings& cs);

/// The free particles ([[particle]] and the [particles] file) appended to the lattice's positions and
/// radii (no rods); their velocities and spins returned beside.
void append_free_particles(const CaseSettings& cs, Lattice& lat, std::vector<Vec3>& free_velocity,
                           std::vector<Vec3>& free_spin);

}  // namespace swarf
