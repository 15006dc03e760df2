// case_keys.cpp: every key of a case file, once (see case_keys.h). The docs' key tables are
// generated from these entries: edit a doc line here, then run
// 'swarf case keys --update docs/case-reference.md'.
#include "setup/case_keys.h"

namespace swarf {

const std::vector<Key<UniaxialSettings>>& uniaxial_keys() {
  using S = UniaxialSettings;
  static const std::vector<Key<S>> keys{
      {.name = "axis",
       .field = &S::axis,
       .choices = {"x", "y", "z"},
       .doc = "Bar axis. The grips are the sides `<axis>-` and `<axis>+`."},
      {.name = "grip_layers",
       .field = &S::grip_layers,
       .unit = "1",
       .range = in(1, 1000, "[]"),
       .rule = "the gauge length must stay > h/2",
       .doc = "Lattice layers held by each grip. Selection is the same as for `side`."},
      {.name = "grip_dofs",
       .field = &S::grip_dofs,
       .choices = {"axis", "xyz"},
       .doc = "`\"axis\"`: the grips hold only the axial component, so the bar contracts freely. `\"xyz\"`: "
              "clamped ends."},
      {.name = "strain_path",
       .field = &S::strain_path,
       .unit = "1",
       .default_note = "invalid, so effectively required",
       .range = in(-0.5, 0.5, "()"),
       .rule = "at least 2 entries, first 0, no two consecutive equal",
       .doc = "Turning points of the nominal strain."},
      {.name = "strain_rate",
       .field = &S::strain_rate,
       .unit = "1/s",
       .range = kStrainRate,
       .doc = "Absolute rate of change of the nominal strain."},
  };
  return keys;
}

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

const std::vector<Key<MeshSettings>>& mesh_keys() {
  using S = MeshSettings;
  static const std::vector<Key<S>> keys{
      {.name = "name",
       .field = &S::name,
       .no_default = true,
       .default_note = "`mesh<index>`",
       .rule = "non-empty; letters, digits, `_` and `-` only; unique among meshes",
       .doc = "Name used in outputs."},
      {.name = "file",
       .field = &S::file,
       .default_note = "rectangle",
       .rule = "an existing `.stl` or `.obj` file (extension in any case); not with `edge1`, `edge2`, "
               "`divisions` or `rake_angle`",
       .doc = "Mesh file, see [Mesh files](#mesh-files)."},
      {.name = "scale",
       .field = &S::scale,
       .unit = "1",
       .range = kScale,
       .doc = "Factor on the file's coordinates, for example 1e-3 for a file in mm. It has no effect on a "
              "rectangle."},
      {.name = "origin",
       .field = &S::origin,
       .unit = "m",
       .range = kCoordinate,
       .rule = "not with `file`",
       .doc = "Corner of the rectangle, or the sharp tip of a generated tool."},
      {.name = "edge1",
       .field = &S::edge1,
       .unit = "m",
       .no_default = true,
       .range = kCoordinate,
       .rule = "both edges required for a rectangle; edge1 x edge2 non-zero; not with `file`",
       .doc = "First edge of the rectangle (a parallelogram in general) from `origin`."},
      {.name = "edge2",
       .field = &S::edge2,
       .unit = "m",
       .no_default = true,
       .range = kCoordinate,
       .rule = "as `edge1`",
       .doc = "Second edge of the rectangle from `origin`."},
      {.name = "divisions",
       .field = &S::divisions,
       .unit = "1",
       .range = in(1, 1e7, "[]"),
       .rule = "product <= 1e7; not with `file`",
       .doc = "Cells n1, n2 along `edge1` and `edge2`. Each cell is cut into 2 triangles, so the rectangle has "
              "2 n1 n2 triangles."},
      {.name = "rake_angle",
       .field = &S::rake_angle,
       .unit = "deg",
       .no_default = true,
       .rule = "(-60, 60), checked when the tool is built; not with `file` or a rectangle",
       .doc = "Makes the mesh a generated cutting tool (`tool_paths/tool_geometry.h`): the rake face leaves the "
              "edge upwards, tilted back from +z by this angle."},
      {.name = "clearance_angle",
       .field = &S::clearance_angle,
       .unit = "deg",
       .rule = "(0, 45), checked when the tool is built; only with `rake_angle`",
       .doc = "The flank face leaves the edge backwards, tilted up from -x by this angle. The wedge 90 - rake - "
              "clearance must exceed 5 deg."},
      {.name = "edge_radius",
       .field = &S::edge_radius,
       .unit = "m",
       .range = kLengthOrZero,
       .rule = "only with `rake_angle`",
       .doc = "Cutting-edge radius (an arc tangent to both faces, steps of at most 5 deg); 0 = sharp."},
      {.name = "width",
       .field = &S::width,
       .unit = "m",
       .no_default = true,
       .range = kLengthOrZero,
       .rule = "> 0 when the tool is built; required with `rake_angle`",
       .doc = "Extent of the tool along y, centred on `origin`'s y."},
      {.name = "face_length",
       .field = &S::face_length,
       .unit = "m",
       .no_default = true,
       .range = kLengthOrZero,
       .rule = "> 0 when the tool is built; required with `rake_angle`",
       .doc = "Length of the rake and flank faces from the sharp tip."},
      {.name = "tool_tip",
       .field = &S::tool_tip,
       .unit = "m",
       .no_default = true,
       .default_note = "the file is not a tool",
       .range = kCoordinate,
       .rule = "only with `file`; the file must measure as a tool",
       .doc = "Makes the mesh `file` a cutting tool, as `cut.tool_file` does ([A tool from a "
              "file](#a-tool-from-a-file)): "
              "its rake and clearance angles, sharp tip and edge are measured, and it is moved so that its sharp "
              "tip sits here. The cut's analysis takes the measured rake angle."},
      {.name = "youngs_modulus",
       .field = &S::youngs_modulus,
       .unit = "Pa",
       .range = or_inf(kModulus),
       .doc = "E_w of the mesh. `inf` means rigid."},
      {.name = "poisson_ratio",
       .field = &S::poisson_ratio,
       .unit = "1",
       .range = in(-1, 0.5, "()"),
       .doc = "nu_w of the mesh. No effect when `youngs_modulus` is `inf`."},
      {.name = "parting_lead",
       .field = &S::parting_lead,
       .unit = "m",
       .range = or_inf(kLength),
       .doc = "A parting line at the mesh's lowest point (a tool's cutting edge): rods that cross the horizontal "
              "plane through that point break when it comes within this distance of their midpoint along x, the "
              "cutting direction (and up to the same distance after it has passed them). The geometric "
              "separation criterion of early finite-element cutting models: the chip separates at the edge and "
              "must form by plastic flow, instead of the lattice cleaving along the cutting plane ahead of the "
              "tool (docs/materials.md). A fraction of the particle spacing to a few of them; `inf` means none, "
              "and separation is left to the rods' failure."},
      {.name = "box_size",
       .field = &S::box_size,
       .unit = "m",
       .no_default = true,
       .range = kLength,
       .rule = "not with `file`, a rectangle, a tool or a cylinder",
       .doc = "Makes the mesh a closed box with these edges along x, y, z, centred on `origin` (12 triangles).",
       .section = "shapes"},
      {.name = "cylinder_radius",
       .field = &S::cylinder_radius,
       .unit = "m",
       .no_default = true,
       .range = kLength,
       .rule = "needs `cylinder_length`; not with `file`, a rectangle, a tool or `box_size`",
       .doc = "Makes the mesh a closed cylinder of this radius centred on `origin`: a prism with "
              "`cylinder_segments` flat sides inscribed in the round face, ends as fans (4 segments triangles).",
       .section = "shapes"},
      {.name = "cylinder_length",
       .field = &S::cylinder_length,
       .unit = "m",
       .no_default = true,
       .range = kLength,
       .rule = "only with `cylinder_radius`",
       .doc = "Length of the cylinder along its axis.",
       .section = "shapes"},
      {.name = "cylinder_axis",
       .field = &S::cylinder_axis,
       .unit = "1",
       .range = kDirection,
       .rule = "length >= 1e-6; only with `cylinder_radius`",
       .doc = "Direction of the cylinder's axis (normalised).",
       .section = "shapes"},
      {.name = "cylinder_segments",
       .field = &S::cylinder_segments,
       .unit = "1",
       .range = in(3, 100000, "[]"),
       .rule = "only with `cylinder_radius`",
       .doc = "Flat sides of the faceted cylinder. Its volume is short of the round one's by 1 - sin(t)/t, t = 2 "
              "pi / segments (0.6 % at 32).",
       .section = "shapes"},
      {.name = "dynamics",
       .field = &S::dynamics,
       .choices = {"prescribed", "rigid_body"},
       .rule = "`rigid_body` needs a closed mesh (a file, `box_size` or `cylinder_radius`), no `motion`, and "
               "`density` or `mass`",
       .doc = "`prescribed`: the mesh follows its `motion`. `rigid_body`: a rigid macro particle, moved by the "
              "contact forces and torques on its triangles, its loads and gravity (see "
              "[Rigid bodies](#rigid-bodies)).",
       .section = "rigid_body"},
      {.name = "density",
       .field = &S::density,
       .unit = "kg/m^3",
       .no_default = true,
       .range = kDensity,
       .rule = "give `density` or `mass`, not both; only with `dynamics = \"rigid_body\"`",
       .doc = "Density of the body: mass, centre of mass and principal inertia follow from the closed mesh.",
       .section = "rigid_body"},
      {.name = "mass",
       .field = &S::mass,
       .unit = "kg",
       .no_default = true,
       .range = kMass,
       .rule = "as `density`",
       .doc = "Mass of the body instead of its density (uniform: density = mass / the mesh's volume; with "
              "`inertia`, the mass as given).",
       .section = "rigid_body"},
      {.name = "centre_of_mass",
       .field = &S::centre_of_mass,
       .unit = "m",
       .default_note = "from the mesh",
       .range = kCoordinate,
       .rule = "with `inertia`",
       .doc = "Centre of mass in the mesh's coordinates (as its file or shape places it), given with `inertia`.",
       .section = "rigid_body"},
      {.name = "inertia",
       .field = &S::inertia,
       .unit = "kg m^2",
       .default_note = "from the mesh",
       .range = in(-1e9, 1e9, "[]", "within 1e9 kg m^2"),
       .rule = "6 numbers; needs `mass` and `centre_of_mass`, not `density`; principal moments positive, each at "
               "most the sum of the other two",
       .doc = "Inertia tensor about `centre_of_mass`, mesh coordinates: [Ixx, Iyy, Izz, Ixy, Iyz, Ixz] (the "
              "products of inertia as tensor entries, Ixy = -integral of x y dm). With it the mass properties are "
              "not computed from the mesh, which may then be open (a tool's faces) or stand for a body whose mass "
              "is not spread uniformly in it.",
       .section = "rigid_body"},
      {.name = "initial_velocity",
       .field = &S::initial_velocity,
       .unit = "m/s",
       .range = kVelocity,
       .rule = "only with `dynamics = \"rigid_body\"`",
       .doc = "Velocity of the centre of mass at the start (a component named in `fixed` keeps its value).",
       .section = "rigid_body"},
      {.name = "angular_velocity",
       .field = &S::angular_velocity,
       .unit = "rad/s",
       .range = kAngularVelocity,
       .rule = "along `hinge_axis` with `rotation = \"hinge\"`; only with `dynamics = \"rigid_body\"`",
       .doc = "Angular velocity at the start, world frame.",
       .section = "rigid_body"},
      {.name = "rotation",
       .field = &S::rotation,
       .choices = {"free", "hinge", "prescribed"},
       .rule = "only with `dynamics = \"rigid_body\"`",
       .doc = "`free`: Euler's equations with the full inertia. `hinge`: turns only about `hinge_axis` through "
              "the centre of mass, or through `hinge_point`. `prescribed`: keeps `angular_velocity` (zero: does "
              "not turn).",
       .section = "rigid_body"},
      {.name = "hinge_axis",
       .field = &S::hinge_axis,
       .unit = "1",
       .range = kDirection,
       .rule = "length >= 1e-6; only with `rotation = \"hinge\"`",
       .doc = "Direction of the hinge's axis, world frame (normalised). The axis passes through the centre of "
              "mass (add `fixed = \"xyz\"` for a fixed axle there), or through `hinge_point`.",
       .section = "rigid_body"},
      {.name = "hinge_point",
       .field = &S::hinge_point,
       .unit = "m",
       .default_note = "the centre of mass",
       .range = kCoordinate,
       .rule = "only with `rotation = \"hinge\"`; not with `fixed`",
       .doc = "A point of the hinge's axis, world frame, where the axle is fixed: the body turns about it and "
              "its centre of mass moves on a circle about the axis (a pendulum, an eccentric wheel). The moment "
              "of inertia and the torque are taken about the axis through this point; `initial_velocity` is "
              "replaced by angular_velocity x (centre of mass - hinge_point).",
       .section = "rigid_body"},
      {.name = "fixed",
       .field = &S::fixed,
       .default_note = "none",
       .rule = "letters of `xyz`, each once; only with `dynamics = \"rigid_body\"`",
       .doc = "Translation components of the centre of mass held at their initial velocity. `\"xyz\"` is a "
              "fixed point (with `rotation = \"free\"`) or a fixed axle (with a hinge).",
       .section = "rigid_body"},
      {.name = "force",
       .field = &S::force,
       .unit = "N",
       .range = kForce,
       .rule = "only with `dynamics = \"rigid_body\"`",
       .doc = "Constant external force at the centre of mass, world frame.",
       .section = "rigid_body"},
      {.name = "torque",
       .field = &S::torque,
       .unit = "N m",
       .range = kForce,
       .rule = "only with `dynamics = \"rigid_body\"`",
       .doc = "Constant external torque, world frame.",
       .section = "rigid_body"},
      {.name = "damping",
       .field = &S::damping,
       .unit = "N s/m",
       .range = in(0.0, 1e12, "[]", "0 to 1e12 N s/m"),
       .rule = "m / damping at least 5 steps; only with `dynamics = \"rigid_body\"`",
       .doc = "External force -damping (v - holder_velocity) on the centre of mass (a mount's damper; without a "
              "holder, a drag -damping v). Damping ratio zeta = damping / (2 sqrt(k m)) along an axis of "
              "stiffness k.",
       .section = "rigid_body"},
      {.name = "spring_stiffness",
       .field = &S::spring_stiffness,
       .unit = "N/m",
       .range = kStiffness,
       .rule = "each >= 0 and finite; the period 2 pi sqrt(m/k) at least 30 steps (of dt, or of dt_max with "
               "Newmark); only with `dynamics = \"rigid_body\"`",
       .doc = "Stiffness of a mount along x, y and z: the force -k_c (x_c - a_c(t)) on the centre of mass, where "
              "the anchor a(t) starts at the initial centre of mass and moves at `holder_velocity` (a compliant "
              "tool on its holder: natural frequency sqrt(k/m) / (2 pi), static deflection F/k).",
       .section = "rigid_body"},
      {.name = "holder_velocity",
       .field = &S::holder_velocity,
       .unit = "m/s",
       .range = kVelocity,
       .rule = "only with `dynamics = \"rigid_body\"`",
       .doc = "Velocity of the mount's anchor (the tool holder), world frame: the spring and damper pull the body "
              "along. Give the body the same `initial_velocity` to start it at the holder's speed.",
       .section = "rigid_body"},
      {.name = "torque_damping",
       .field = &S::torque_damping,
       .unit = "N m s/rad",
       .range = in(0.0, 1e12, "[]", "0 to 1e12 N m s/rad"),
       .rule = "only with `dynamics = \"rigid_body\"`",
       .doc = "External torque -torque_damping omega (a water wheel's load: with a constant torque T alone it "
              "runs up to omega = T / torque_damping).",
       .section = "rigid_body"},
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
