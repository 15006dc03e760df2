// output_fields.h: the table of the per-particle output fields, the one place a field is declared.
//
// Each row names a field and says everything its consumers need: its unit, its number of
// components, its doc line, its results.h5 description, how its values are computed from the
// particles, the rods and the measured fields (measure/particle_fields.h), and what it needs.
// The consumers read the table: the ParaView frames (vtk_output.cpp) and through them the field
// history in results.h5 (/frames/NNNNN) and results.xdmf (field_history.cpp), the datasets
// /particles/<name> of results.h5 (app/summary.cpp), the allowed values, default and doc line of
// the key output.fields (setup/modules/output.cpp), and the table of the frames' point arrays in
// docs/outputs.md (generated: `swarf case fields --update docs/outputs.md`; ctest OutputFields.* fails when it drifts).
// A field the measure code computes already is one row in output_fields.cpp; a new physical
// quantity is its computation plus the row.
//
// The positions (the frames' points, /particles/position), results.h5's /particles/mass and the
// orientation, angular_velocity, group and id arrays are written by the writers themselves (not
// per-particle fields one chooses, and of other types): the table lists them only for the docs
// (output_fixed_arrays()).
#pragma once

#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "swarf/measure/particle_fields.h"
#include "swarf/state/particles.h"
#include "swarf/state/rods.h"

namespace swarf {

/// What a field's values are computed from: the state and, when the row says so, the measured fields.
struct FieldInput {
  const Particles& particles;
  const Rods& rods;
  const ParticleFields* measured = nullptr;  ///< non-null when a chosen row needs it (OutputField::measured)
};

/// What a field is. The frames and results.h5 write the rows kind by kind in this enum's order,
/// and in table order within a kind (the order of the frames' arrays since they were added).
enum class FieldKind { Motion, Damage, Heat, Flow, Measured };

/// Whether a field is written when output.fields names it, or always.
enum class FieldChoice { Chosen, Always };

struct OutputField {
  std::string_view name = {};  ///< the .vtu array, the results.h5 dataset /particles/<name>, the output.fields value
  std::string_view unit = {};  ///< SI ("1" for counts and ratios): the arrays' UNITS_LABEL, the datasets' 'unit'
  int components = 1;          ///< 1, 3 (a vector) or 6 (a symmetric tensor)
  std::string_view component_names = {};  ///< space-separated names of the components in the frames, or empty
  FieldKind kind = FieldKind::Motion;
  FieldChoice choice = FieldChoice::Chosen;
  std::string_view doc = {};          ///< the meaning, markdown: docs/outputs.md's table of the point arrays
  std::string_view description = {};  ///< results.h5's 'description' attribute of /particles/<name>
  /// Writes the values of the particles [begin, end), row by row, to out[0 .. (end - begin) x
  /// components): a writer may take the particles in strips (results.h5 does: a whole field at once
  /// was up to 48 B per particle more at a run's last write).
  void (*compute)(const FieldInput& in, std::size_t begin, std::size_t end, double* out) = nullptr;
  bool measured = false;           ///< needs the measured fields (particle_fields(): virial sums, plastic strain fits)
  bool plastic_window = false;     ///< needs the run to accumulate PEEQ (StepSettings::plastic_strain_window)
  bool results_always = false;     ///< results.h5 holds it whatever output.fields says (swarf post reads it)
  bool results_with_heat = false;  ///< results.h5 holds it only with [heat]
};

/// The table, in the order of the key's allowed values and of the docs.
std::span<const OutputField> output_fields();

/// The rows in the order the frames and results.h5 write them (by kind, then table order).
std::vector<const OutputField*> output_fields_in_write_order();

/// The row named 'name', or null.
const OutputField* find_output_field(std::string_view name);

/// The names output.fields may hold (the rows one chooses), in table order; its default is all of them.
std::vector<std::string> output_field_names();

/// The values of one field for the particles now (n x components).
std::vector<double> compute_output_field(const OutputField& f, const FieldInput& in);
/// Those of the particles [begin, end) into 'out' (resized to (end - begin) x components).
void compute_output_field_rows(const OutputField& f, const FieldInput& in, std::size_t begin, std::size_t end,
                               std::vector<double>& out);

/// Whether 'fields' (the names of output.fields) holds 'name'.
bool has_field(const std::vector<std::string>& fields, std::string_view name);
/// Whether a row 'fields' chooses (or an always-written one) needs the measured fields.
bool needs_particle_fields(const std::vector<std::string>& fields);
/// Whether a row 'fields' chooses needs the run to accumulate PEEQ.
bool needs_plastic_strain_window(const std::vector<std::string>& fields);

/// One array of the frames written by the writers themselves, for the docs.
struct FixedArrayDoc {
  std::string_view name, components, unit, doc;
};
std::span<const FixedArrayDoc> output_fixed_arrays();

/// The markdown table of the frames' point arrays (docs/outputs.md, "Part 0, the particles").
std::string output_fields_markdown();

/// Replaces the generated table between its markers in 'text' (the text of docs/outputs.md);
/// throws InputError when the markers are missing.
std::string update_output_fields_doc(const std::string& text);
/// update_output_fields_doc on the file 'path', rewritten in place (`swarf case fields --update`).
void update_output_fields_file(const std::string& path);

}  // namespace swarf
