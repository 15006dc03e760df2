// case_config.h: the case file (TOML) as settings structs with defaults and units.
//
// Every key of a case file maps to one field of a settings struct, whose default member initialiser
// is the key's default. The key table names each key once, with its field, unit, range and doc line:
// the reader checks against it and the key tables of docs/case-reference.md are generated from it, so
// a new key is a field and an entry. The engine-facing tables are modules (setup/modules/: struct,
// key table, rules, build, echo, included below); [cut] and [environment] are here (their
// keys in cut_keys.cpp and case_keys.cpp), with CaseSettings, which holds one member per table. Reading rejects unknown
// keys, wrong types and out-of-range values with the file, the key and the value. Command-line overrides (--set
// key=value) are applied to the TOML tree before reading, so they are checked exactly like keys in the file.
#pragma once

#include <array>
#include <limits>
#include <set>
#include <string>
#include <vector>

#include "setup/key.h"
#include "setup/modules/contacts.h"
#include "setup/modules/flows.h"
#include "setup/modules/groups.h"
#include "setup/modules/heat.h"
#include "setup/modules/integrator.h"
#include "setup/modules/material.h"
#include "setup/modules/membrane.h"
#include "setup/modules/meshes.h"
#include "setup/modules/output.h"
#include "setup/modules/particles.h"
#include "setup/modules/rods.h"
#include "setup/modules/uniaxial.h"
#include "setup/modules/workpiece.h"

namespace swarf {

/// [cut]: an orthogonal cut in cutting terms. swarf derives from it the lattice, the clamps,
/// the tool, its path, the end time and the steady window (cut_case.h), and inserts them as
/// the lower-level keys the case file does not give itself (those it gives win).
struct CutSettings {
  bool enabled = false;               ///< true when the table is present
  double uncut_chip_thickness = 0.0;  ///< h, the depth of cut of orthogonal cutting (the feed in turning), m
  double cutting_speed = 0.0;         ///< v_c, m/s
  double length_of_cut = 0.0;         ///< tool travel, m; 0 = 10 h
  double width = 0.0;                 ///< b, m; 0 = plane strain (a periodic slice two cells wide)
  double rake_angle = 0.0;            ///< gamma_o (ISO 3002), deg
  double clearance_angle = 7.0;       ///< alpha_o (ISO 3002), deg
  double edge_radius = 0.0;           ///< r_n of the honed edge, m; 0 = sharp
  double inclination_angle = 0.0;     ///< lambda_s (ISO 3002), deg: an oblique cut; needs a width
  std::string tool_file;              ///< the tool's mesh (.stl or .obj), measured and placed; empty = generated
  double tool_scale = 1.0;            ///< factor on tool_file's coordinates (1e-3 for mm), 1
  double friction = 0.5;              ///< Coulomb coefficient between tool, chip and workpiece, 1
  std::string material;               ///< a material preset (material_presets.h)
  int layers = 10;                    ///< lattice layers across h, 1
  double workpiece_length = 0.0;      ///< extent of the block along x in multiples of h, 1; 0 = length_of_cut / h + 7.6
  double workpiece_height = 3.0;      ///< extent of the block along z in multiples of h, 1
  double steady_from = -1.0;          ///< tool travel from which forces are averaged, m; < 0 = half the length of cut
  // A compliant tool: a rigid body on a spring and damper to its holder along x and z.
  double tool_stiffness = 0.0;       ///< per metre of width, N/m per m; 0 = the tool follows its path rigidly
  double tool_mass = 0.0;            ///< modal mass per metre of width, kg/m
  double tool_damping_ratio = 0.05;  ///< of the mount's critical damping, 1
};

struct CaseSettings {
  std::string source;     ///< file name, or "<built-in>"
  std::string directory;  ///< directory of the case file (relative paths resolve here)
  CutSettings cut;
  std::string cut_derived;  ///< what [cut] derived, as TOML with a note per key (empty without [cut])
  WorkpieceSettings workpiece;
  MembraneSettings membrane;
  MaterialSettings material;
  RodSettings rod;
  IntegratorSettings integrator;
  std::vector<GroupSettings> groups;
  UniaxialSettings uniaxial;
  ContactSettings contact;
  HeatSettings heat;
  std::vector<MeshSettings> meshes;
  std::vector<ParticleSettings> particles;
  ParticlesFileSettings particles_file;
  std::vector<InflowSettings> inflows;
  std::vector<OutflowSettings> outflows;
  std::array<double, 3> gravity{0, 0, 0};  ///< [environment] gravity, m/s^2
  OutputSettings output;
  std::vector<std::string> overrides;  ///< the --set arguments, in order
  std::string effective_toml;          ///< the TOML tree after overrides, as read
  std::string text;                    ///< the case text as given (before overrides)
  /// What the case gave (the file, the overrides, and what [cut] derived): each table as
  /// "table" ("mesh.0" for an entry of an array of tables) and each key as "table.key"
  /// ("mesh.0.origin"). summary.json's "case" lists these keys with their values from the
  /// settings, through the key table.
  std::set<std::string> given;
};

/// Reads a case file and applies overrides ("dotted.key=value"). Throws InputError.
CaseSettings load_case(const std::string& path, const std::vector<std::string>& overrides);
/// Same, from TOML text (tests, built-in cases); 'source' names it in messages.
CaseSettings parse_case(const std::string& text, const std::string& source, const std::vector<std::string>& overrides,
                        const std::string& directory = ".");

/// The built-in default case: the C45 cut of validation/cutting/default_cut.toml (docs/default-case.md).
extern const char* const kDefaultCaseToml;
/// The same cut written as a [cut] table (examples/cut_c45.toml): it builds the same model.
extern const char* const kDefaultCutTableToml;

}  // namespace swarf
