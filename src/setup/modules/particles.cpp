// particles.cpp: the free particles' module of setup (see particles.h).
#include "setup/modules/particles.h"

#include "io/particle_file.h"
#include "io/path_kind.h"
#include "lattice_gen/fcc_lattice.h"
#include "setup/case_tables.h"

namespace swarf {

const std::vector<Key<ParticleSettings>>& particle_keys() {
  using S = ParticleSettings;
  static const std::vector<Key<S>> keys{
      {.name = "position",
       .field = &S::position,
       .unit = "m",
       .no_default = true,
       .default_note = "required",
       .range = kCoordinate,
       .doc = "Centre."},
      {.name = "velocity", .field = &S::velocity, .unit = "m/s", .range = kVelocity, .doc = "Initial velocity."},
      {.name = "angular_velocity",
       .field = &S::angular_velocity,
       .unit = "rad/s",
       .range = kAngularVelocity,
       .doc = "Initial angular velocity, in the world frame."},
      {.name = "radius",
       .field = &S::radius,
       .unit = "m",
       .no_default = true,
       .default_note = "required",
       .range = kRadius,
       .doc = "Radius."},
  };
  return keys;
}

const std::vector<Key<ParticlesFileSettings>>& particles_file_keys() {
  using S = ParticlesFileSettings;
  static const std::vector<Key<S>> keys{
      {.name = "file",
       .field = &S::file,
       .no_default = true,
       .default_note = "required",
       .rule = "existing file",
       .doc = "One particle per line, columns `id x y z vx vy vz` (m, m/s) separated by white space."},
      {.name = "radius",
       .field = &S::radius,
       .unit = "m",
       .no_default = true,
       .default_note = "required",
       .range = kRadius,
       .doc = "Radius of every particle of the file."},
  };
  return keys;
}

void read_particles(const CaseInput& in, CaseSettings& cs) {
  if (const toml::array* arr = entries(in, "particle")) {
    for (std::size_t k = 0; k < arr->size(); ++k) {
      TableReader r = in.reader((*arr)[k].as_table(), "particle");
      ParticleSettings p;
      r.read(particle_keys(), p);
      r.finish();  // (an unknown key, often a misspelt one, is named before the rules between keys)
      if (!r.has("radius")) r.fail("radius", nullptr, "every particle needs a radius in m");
      if (!r.has("position")) r.fail("position", nullptr, "every particle needs a position [x, y, z] in m");
      cs.particles.push_back(p);
    }
  }
}

void read_particles_file(const CaseInput& in, CaseSettings& cs) {
  if (const toml::table* t = in.table("particles")) {
    TableReader r = in.reader(t, "particles");
    auto& f = cs.particles_file;
    r.read(particles_file_keys(), f);
    r.finish();  // (an unknown key, often a misspelt one, is named before the rules between keys)
    f.file = resolve(f.file, in.directory);
    if (!r.has("file")) r.fail("file", nullptr, "[particles] needs file = \"...\" (columns id x y z vx vy vz)");
    if (!r.has("radius")) r.fail("radius", nullptr, "[particles] needs radius in m");
    if (const std::string why = file_problem(f.file, "a particles file"); !why.empty())
      r.fail("file", r.get("file"), why);
  }
}

void append_free_particles(const CaseSettings& cs, Lattice& lat, std::vector<Vec3>& free_velocity,
                           std::vector<Vec3>& free_spin) {
  for (const auto& ps : cs.particles) {
    lat.position.emplace_back(ps.position[0], ps.position[1], ps.position[2]);
    lat.radius.push_back(ps.radius);
    free_velocity.emplace_back(ps.velocity[0], ps.velocity[1], ps.velocity[2]);
    free_spin.emplace_back(ps.angular_velocity[0], ps.angular_velocity[1], ps.angular_velocity[2]);
  }
  if (!cs.particles_file.file.empty())
    for (const FreeParticleRow& row : read_particle_file(cs.particles_file.file)) {
      lat.position.push_back(row.position);
      lat.radius.push_back(cs.particles_file.radius);
      free_velocity.push_back(row.velocity);
      free_spin.emplace_back(Vec3::Zero());
    }
}

}  // namespace swarf
