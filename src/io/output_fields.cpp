// output_fields.cpp: the table of the per-particle output fields (see output_fields.h).
#include "io/output_fields.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <fstream>
#include <sstream>

#include "io/atomic_file.h"
#include "io/vtk_output.h"
#include "swarf/core/errors.h"

namespace swarf {
namespace {

void copy_vectors(const std::vector<Vec3>& v, std::size_t begin, std::size_t end, double* out) {
  for (std::size_t i = begin; i < std::min(end, v.size()); ++i)
    for (int c = 0; c < 3; ++c) out[3 * (i - begin) + c] = v[i][c];
}

// (an array the run does not hold, as the temperature without heat, leaves the zeros out was made with)
void copy(const std::vector<double>& v, std::size_t begin, std::size_t end, double* out) {
  if (v.size() < end) return;
  std::copy(v.begin() + static_cast<std::ptrdiff_t>(begin), v.begin() + static_cast<std::ptrdiff_t>(end), out);
}

// The rows. Their order is that of output.fields' allowed values and of the docs; the writers
// write them by kind (FieldKind), in this order within a kind.
constexpr std::array kFields{
    OutputField{
        .name = "velocity",
        .unit = "m/s",
        .components = 3,
        .kind = FieldKind::Motion,
        .description = "particle velocity at the end",
        .compute = [](const FieldInput& in, std::size_t b, std::size_t e,
                      double* out) { copy_vectors(in.particles.velocity, b, e, out); },
    },
    OutputField{
        .name = "displacement",
        .unit = "m",
        .components = 3,
        .kind = FieldKind::Motion,
        .doc = "position - initial position",
        .description = "position minus initial position",
        .compute =
            [](const FieldInput& in, std::size_t b, std::size_t e, double* out) {
              const Particles& p = in.particles;
              for (std::size_t i = b; i < e; ++i)
                for (int c = 0; c < 3; ++c) out[3 * (i - b) + c] = p.position[i][c] - p.initial_position[i][c];
            },
    },
    OutputField{
        .name = "radius",
        .unit = "m",
        .kind = FieldKind::Motion,
        .choice = FieldChoice::Always,
        .doc = "use it to scale glyphs (spheres)",
        .description = "particle radius",
        .compute = [](const FieldInput& in, std::size_t b, std::size_t e,
                      double* out) { copy(in.particles.radius, b, e, out); },
    },
    OutputField{
        .name = "broken_fraction",
        .unit = "1",
        .kind = FieldKind::Damage,
        .doc = "fraction of the particle's rods that are broken. It is 0 for a particle without rods. With bond "
               "formation, 1 - intact / original rods, at least 0.",
        .description = "damage: broken rods over the particle's rods at the start",
        .compute =
            [](const FieldInput& in, std::size_t b, std::size_t e, double* out) {
              for (std::size_t i = b; i < e; ++i) out[i - b] = broken_fraction_of(in.rods, i);
            },
        .results_always = true,
    },
    OutputField{
        .name = "stress",
        .unit = "Pa",
        .components = 6,
        .component_names = "XX YY ZZ XY YZ XZ",
        .kind = FieldKind::Measured,
        .doc = "the particle's stress tensor, positive in tension ([per-particle fields](#per-particle-fields)); "
               "ParaView reads 6 components as a symmetric tensor",
        .description = "virial stress of rods and contacts over 4 sqrt(2) R^3: xx, yy, zz, xy, yz, xz; positive in "
                       "tension",
        .compute =
            [](const FieldInput& in, std::size_t b, std::size_t e, double* out) {
              for (std::size_t i = b; i < e; ++i)
                for (int c = 0; c < 6; ++c) out[6 * (i - b) + c] = in.measured->stress[i][c];
            },
        .measured = true,
    },
    OutputField{
        .name = "von_mises_stress",
        .unit = "Pa",
        .kind = FieldKind::Measured,
        .doc = "sqrt(3/2 s:s), s the deviator of `stress`",
        .description = "von Mises stress sqrt(3/2 s:s)",
        .compute =
            [](const FieldInput& in, std::size_t b, std::size_t e, double* out) {
              for (std::size_t i = b; i < e; ++i) out[i - b] = von_mises(in.measured->stress[i]);
            },
        .measured = true,
    },
    OutputField{
        .name = "hydrostatic_stress",
        .unit = "Pa",
        .kind = FieldKind::Measured,
        .doc = "tr(`stress`)/3, positive in tension (the pressure is minus this)",
        .description = "trace of the stress over 3, positive in tension (pressure = -this)",
        .compute =
            [](const FieldInput& in, std::size_t b, std::size_t e, double* out) {
              for (std::size_t i = b; i < e; ++i) out[i - b] = hydrostatic(in.measured->stress[i]);
            },
        .measured = true,
    },
    OutputField{
        .name = "plastic_strain",
        .unit = "1",
        .kind = FieldKind::Measured,
        .doc = "equivalent plastic strain held by the particle's intact rods "
               "([per-particle fields](#per-particle-fields))",
        .description = "von Mises equivalent of the plastic strain tensor fitted to the particle's intact rods",
        .compute = [](const FieldInput& in, std::size_t b, std::size_t e,
                      double* out) { copy(in.measured->plastic_strain, b, e, out); },
        .measured = true,
    },
    OutputField{
        .name = "peeq",
        .unit = "1",
        .kind = FieldKind::Flow,
        .doc = "accumulated equivalent plastic strain, the time integral of the equivalent plastic strain rate, as "
               "FEM codes' PEEQ ([per-particle fields](#per-particle-fields))",
        .description = "accumulated equivalent plastic strain: the integral of the equivalent plastic strain rate",
        .compute = [](const FieldInput& in, std::size_t b, std::size_t e,
                      double* out) { copy(in.particles.peeq, b, e, out); },
        .plastic_window = true,
    },
    OutputField{
        .name = "peeq_rate",
        .unit = "1/s",
        .kind = FieldKind::Flow,
        .doc = "equivalent plastic strain rate over the last window of 32 steps "
               "([per-particle fields](#per-particle-fields))",
        .description = "equivalent plastic strain rate",
        .compute = [](const FieldInput& in, std::size_t b, std::size_t e,
                      double* out) { copy(in.particles.peeq_rate, b, e, out); },
        .plastic_window = true,
    },
    OutputField{
        .name = "temperature",
        .unit = "K",
        .kind = FieldKind::Heat,
        .doc = "only with `[heat]` ([physics.md section 10](physics.md#10-heat))",
        .description = "particle temperature at the end ([heat])",
        .compute = [](const FieldInput& in, std::size_t b, std::size_t e,
                      double* out) { copy(in.particles.temperature, b, e, out); },
        .results_with_heat = true,
    },
    OutputField{
        .name = "coordination",
        .unit = "1",
        .kind = FieldKind::Measured,
        .doc = "coordination number: the particle's intact rods, 12 inside the FCC lattice, fewer at free surfaces, "
               "along cracks and in the chip's loose fragments, 0 for a particle without rods (rods formed by bond "
               "formation count too)",
        .description = "coordination number: the particle's intact rods",
        .compute =
            [](const FieldInput& in, std::size_t b, std::size_t e, double* out) {
              const Rods& r = in.rods;
              for (std::size_t i = b; i < e; ++i) {
                double c = 0.0;
                if (i + 1 < r.row_start.size())
                  for (std::int32_t q = r.row_start[i]; q < r.row_start[i + 1]; ++q)
                    c += r.intact[r.entries[q].rod] ? 1.0 : 0.0;
                out[i - b] = c;
              }
            },
    },
    OutputField{
        .name = "plastic_work",
        .unit = "J/m^3",
        .kind = FieldKind::Flow,
        .doc = "accumulated plastic work per unit volume (plastic dissipation density): half of every plastic "
               "increment of each of the particle's rods, sigma d(eps_p) A L0, since the start, over the particle's "
               "share of the FCC lattice, 4 sqrt(2) R^3; it keeps the work of rods that broke or were exchanged since "
               "([per-particle fields](#per-particle-fields))",
        .description = "accumulated plastic work per unit volume (plastic dissipation density)",
        .compute =
            [](const FieldInput& in, std::size_t b, std::size_t e, double* out) {
              const Particles& p = in.particles;
              if (p.plastic_work.size() < e) return;
              for (std::size_t i = b; i < e; ++i) out[i - b] = p.plastic_work[i] / particle_volume(p.radius[i]);
            },
        .plastic_window = true,
    },
};

constexpr std::array<FixedArrayDoc, 4> kFixed{{
    {"group", "1 (int)", "-", "group index in group order, -1 = none"},
    {"id", "1 (int64)", "1",
     "the particle's stable id, as `/particles/id` in `results.h5`: it follows the particle when rows are reordered, "
     "removed or added"},
    {"orientation", "4", "1",
     "only with `output.orientations = true`: unit quaternion [q0 (scalar), q1, q2, q3], body to world"},
    {"angular_velocity", "3", "rad/s", "only with `output.orientations = true`: world frame"},
}};

constexpr std::string_view kBegin = "<!-- output-fields begin -->", kEnd = "<!-- output-fields end -->";

}  // namespace

std::span<const OutputField> output_fields() { return kFields; }

std::vector<const OutputField*> output_fields_in_write_order() {
  std::vector<const OutputField*> rows;
  for (const OutputField& f : kFields) rows.push_back(&f);
  std::stable_sort(rows.begin(), rows.end(),
                   [](const OutputField* a, const OutputField* b) { return a->kind < b->kind; });
  return rows;
}

const OutputField* find_output_field(std::string_view name) {
  for (const OutputField& f : kFields)
    if (f.name == name) return &f;
  return nullptr;
}

std::vector<std::string> output_field_names() {
  std::vector<std::string> names;
  for (const OutputField& f : kFields)
    if (f.choice == FieldChoice::Chosen) names.emplace_back(f.name);
  return names;
}

void compute_output_field_rows(const OutputField& f, const FieldInput& in, std::size_t begin, std::size_t end,
                               std::vector<double>& out) {
  if (f.measured && !in.measured) throw OutputError(fmt::format("output field '{}' needs the measured fields", f.name));
  out.assign((end - begin) * static_cast<std::size_t>(f.components), 0.0);
  if (end > begin) f.compute(in, begin, end, out.data());
}

std::vector<double> compute_output_field(const OutputField& f, const FieldInput& in) {
  std::vector<double> out;
  compute_output_field_rows(f, in, 0, in.particles.size(), out);
  return out;
}

bool has_field(const std::vector<std::string>& fields, std::string_view name) {
  return std::find(fields.begin(), fields.end(), name) != fields.end();
}

bool needs_particle_fields(const std::vector<std::string>& fields) {
  return std::any_of(kFields.begin(), kFields.end(), [&](const OutputField& f) {
    return f.measured && (f.choice == FieldChoice::Always || has_field(fields, f.name));
  });
}

bool needs_plastic_strain_window(const std::vector<std::string>& fields) {
  return std::any_of(kFields.begin(), kFields.end(), [&](const OutputField& f) {
    return f.plastic_window && (f.choice == FieldChoice::Always || has_field(fields, f.name));
  });
}

std::span<const FixedArrayDoc> output_fixed_arrays() { return kFixed; }

std::string output_fields_markdown() {
  std::string s = std::string(kBegin) + "\n\n| point array | components | unit | meaning |\n|---|---|---|---|\n";
  auto row = [&](std::string_view name, std::string_view components, std::string_view unit, std::string_view doc) {
    s += fmt::format("| `{}` | {} | {} |{}|\n", name, components, unit, doc.empty() ? " " : fmt::format(" {} ", doc));
  };
  for (const OutputField& f : kFields) {
    std::string components = std::to_string(f.components);
    if (!f.component_names.empty()) {
      components += " (";
      for (char c : f.component_names) components += c == ' ' ? std::string(", ") : std::string(1, c);
      components += ")";
    }
    row(f.name, components, f.unit, f.doc);
  }
  for (const FixedArrayDoc& a : kFixed) row(a.name, a.components, a.unit, a.doc);
  s += "\n" + std::string(kEnd);
  return s;
}

std::string update_output_fields_doc(const std::string& text) {
  const std::size_t b = text.find(kBegin), e = text.find(kEnd);
  if (b == std::string::npos || e == std::string::npos || e < b)
    throw InputError(fmt::format("the lines '{}' and '{}' are missing", kBegin, kEnd));
  return text.substr(0, b) + output_fields_markdown() + text.substr(e + kEnd.size());
}

void update_output_fields_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream text;
  if (!in || !(text << in.rdbuf())) throw InputError(fmt::format("'{}' cannot be read", path));
  std::string updated;
  try {
    updated = update_output_fields_doc(text.str());
  } catch (const InputError& e) {
    throw InputError(fmt::format("{}: {}", path, e.what()));
  }
  write_text_atomic(path, updated);
}

}  // namespace swarf
