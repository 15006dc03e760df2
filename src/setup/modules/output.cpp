// output.cpp: the outputs' module of setup (see output.h).
#include "setup/modules/output.h"

#include <fmt/format.h>

#include <cmath>

#include "setup/case_config.h"
#include "setup/case_tables.h"
#include "swarf/core/errors.h"
#include "swarf/integrate/step_settings.h"

namespace swarf {
namespace {

// "`a`, `b` and `c`": the names of the table's rows that 'pick' selects.
template <class Pick>
std::string names_where(Pick pick) {
  std::vector<std::string> names;
  for (const OutputField& f : output_fields())
    if (pick(f)) names.push_back(fmt::format("`{}`", f.name));
  std::string s;
  for (std::size_t k = 0; k < names.size(); ++k) s += (k == 0 ? "" : k + 1 == names.size() ? " and " : ", ") + names[k];
  return s;
}

// output.fields' doc line, its lists from the table.
const std::string& fields_doc() {
  static const std::string doc = fmt::format(
      "The per-particle fields written to the ParaView frames and to `results.h5` "
      "([outputs.md](outputs.md#choosing-the-fields-outputfields)); `[]` writes none. The positions, radii "
      "and groups are always written, and `results.h5` always holds {} (`swarf post` "
      "reads it). Fewer fields make smaller frames, and without {} the frames skip computing them, and without {} "
      "the run does not accumulate PEEQ and the plastic work (a restart may not add them to the checkpoint of a run "
      "that did not hold them: they would start from zero mid-run).",
      names_where([](const OutputField& f) { return f.results_always; }),
      names_where([](const OutputField& f) { return f.measured && f.choice == FieldChoice::Chosen; }),
      names_where([](const OutputField& f) { return f.plastic_window && f.choice == FieldChoice::Chosen; }));
  return doc;
}

}  // namespace

const std::vector<Key<OutputSettings>>& output_keys() {
  using S = OutputSettings;
  static const std::vector<std::string> field_names = output_field_names();
  static const std::vector<Key<S>> keys{
      {.name = "frame_interval",
       .field = &S::frame_interval,
       .unit = "s",
       .range = or_zero(kTime),
       .doc = "Interval between ParaView frames. 0 means only the first and last states.",
       .restartable = true},
      {.name = "series_interval",
       .field = &S::series_interval,
       .unit = "s",
       .range = or_zero(kTime),
       .doc = "Interval between `series.csv` rows. 0 means end_time/2000, about 2001 rows (fewer if steps are "
              "longer than the interval).",
       .restartable = true},
      {.name = "vtk", .field = &S::vtk, .doc = "Write `particles.pvd` and `frames/*.vtu`."},
      {.name = "rods_in_vtk", .field = &S::rods_in_vtk, .doc = "Add the rods as lines (part 1) to each frame."},
      {.name = "plots",
       .field = &S::plots,
       .doc = "Write PNG plots at the end. This needs `python3` with matplotlib. In "
              "[cutting runs](outputs.md#cutting-runs) it also renders the pictures `chip.png`, "
              "`chip_plastic_strain.png` and `chip_von_mises_stress.png` from the last frame (needs VTK's Python "
              "module and `vtk = true`). If plotting or rendering fails, you get a warning and "
              "the run still completes.",
       .restartable = true},
      {.name = "progress", .field = &S::progress, .doc = "Print the progress line on stderr.", .restartable = true},
      {.name = "steady_from",
       .field = &S::steady_from,
       .unit = "s",
       .no_default = true,
       .default_note = "half of `end_time`",
       .range = in(0.0, 1e6, "[]", "0 to 1e6 s"),
       .doc = "Cutting runs: the summary's force statistics (`cutting` in summary.json) use the rows with time >= "
              "this. It is stored in `results.h5` (`/cutting/steady_from`), which `swarf post` uses.",
       .restartable = true},
      {.name = "checkpoint_every",
       .field = &S::checkpoint_every,
       .unit = "1",
       .range = in(0, 1000000000, "[]"),
       .doc = "Write the restart file `DIR/checkpoint.h5` after every this many accepted steps (newmark: "
              "rejected tries do not count). 0 means no checkpoints. See "
              "[Restart](#restart-swarf-run---restart).",
       .restartable = true},
      {.name = "checkpoint_at_end",
       .field = &S::checkpoint_at_end,
       .doc = "Also write `DIR/checkpoint.h5` after the last step, so that `swarf run --restart DIR/checkpoint.h5 "
              "--set integrator.end_time=...` extends the finished run from its end (without it, an extension "
              "continues from the last periodic checkpoint and computes the stretch after it again). See "
              "[Restart](#restart-swarf-run---restart).",
       .restartable = true},
      {.name = "orientations",
       .field = &S::orientations,
       .doc = "Integrate the spheres' orientations (unit quaternions, body to world) and write them and the "
              "angular velocities (rad/s, world frame) to `results.h5` and the ParaView frames "
              "([outputs.md](outputs.md)). Without it a sphere's orientation stays as it started (identity): "
              "nothing in a sphere's dynamics depends on it (isotropic inertia, central rods and normal forces), "
              "so it is not integrated, as LAMMPS's sphere atoms have none. Angular velocities are integrated "
              "either way."},
      {.name = "fields",
       .field = &S::fields,
       .default_note = "all",
       .choices = std::vector<std::string_view>(field_names.begin(), field_names.end()),
       .doc = fields_doc(),
       .restartable = true},
  };
  return keys;
}

void read_output(const CaseInput& in, CaseSettings& cs) {
  TableReader r = in.reader(in.table("output"), "output");
  r.read(output_keys(), cs.output);
  r.finish();  // (an unknown key, often a misspelt one, is named before the rules between keys)
}

// The run's end and its output intervals: each a finite positive time, and no more rows or
// frames than a run can write (an interval below the time's rounding would never advance the
// next output time: 'next += interval' leaves it where it is).
void check_output_schedule(const CaseSettings& cs) {
  const double end = cs.integrator.end_time;
  if (!(end > 0.0 && std::isfinite(end)))
    throw InputError(fmt::format("{}: key 'integrator.end_time' = {} s must be a finite positive time", cs.source, end));
  constexpr double kMaxRows = 1e7, kMaxFrames = 1e5;
  const double si = cs.output.series_interval, fi = cs.output.frame_interval;
  if (si > 0.0 && !(end / si <= kMaxRows))
    throw InputError(
        fmt::format("{}: key 'output.series_interval' = {} s gives {:.3g} rows over end_time = {} s; at "
                    "most {:.0e}",
                    cs.source, si, end / si, end, kMaxRows));
  if (fi > 0.0 && !(end / fi <= kMaxFrames))
    throw InputError(
        fmt::format("{}: key 'output.frame_interval' = {} s gives {:.3g} frames over end_time = {} s; at "
                    "most {:.0e}",
                    cs.source, fi, end / fi, end, kMaxFrames));
}

void build_output(const CaseSettings& cs, StepSettings& s) {
  s.sphere_orientations = cs.output.orientations;
  s.plastic_strain_window = needs_plastic_strain_window(cs.output.fields) ? 32 : 0;
}

}  // namespace swarf
