// case_keys.cpp: the keys of the tables that are not modules ([environment], [output]), once (see
// case_keys.h; the modules' keys are in setup/modules/, [cut]'s in cut_keys.cpp). The docs' key tables are
// generated from these entries: edit a doc line here, then run
// 'swarf case keys --update docs/case-reference.md'.
#include "setup/case_keys.h"

namespace swarf {

const std::vector<Key<CaseSettings>>& environment_keys() {
  using S = CaseSettings;
  static const std::vector<Key<S>> keys{
      {.name = "gravity",
       .field = &S::gravity,
       .unit = "m/s^2",
       .range = in(-1e4, 1e4, "[]", "within 1e4 m/s^2, a thousand g"),
       .doc = "Gravitational acceleration g. The force m_i g acts on every particle, prescribed ones included "
              "(their weight enters the group reactions)."},
  };
  return keys;
}

const std::vector<Key<OutputSettings>>& output_keys() {
  using S = OutputSettings;
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
       .choices = std::vector<std::string_view>(kParticleFieldNames.begin(), kParticleFieldNames.end()),
       .doc = "The per-particle fields written to the ParaView frames and to `results.h5` "
              "([outputs.md](outputs.md#choosing-the-fields-outputfields)); `[]` writes none. The positions, radii "
              "and groups are always written, and `results.h5` always holds `broken_fraction` (`swarf post` "
              "reads it). Fewer fields make smaller frames, and without `stress`, `von_mises_stress`, "
              "`hydrostatic_stress` and `plastic_strain` the frames skip computing them, and without `peeq` and "
              "`peeq_rate` the run does not accumulate PEEQ (a restart that adds them starts it from the "
              "checkpoint's values).",
       .restartable = true},
  };
  return keys;
}

}  // namespace swarf
