// cut_keys.cpp: the keys of [cut], the cut in cutting terms (see case_keys.h; what they
// derive is cut_case.cpp). Edit a doc line here, then run
// 'swarf case keys --update docs/case-reference.md'.
#include "setup/case_keys.h"

namespace swarf {

const std::vector<Key<CutSettings>>& cut_keys() {
  using S = CutSettings;
  static const std::vector<Key<S>> keys{
      {.name = "uncut_chip_thickness",
       .field = &S::uncut_chip_thickness,
       .unit = "m",
       .no_default = true,
       .default_note = "required",
       .range = in(1e-7, 0.1, "[]", "0.1 um to 100 mm"),
       .doc = "h: the depth of cut of orthogonal cutting (the feed per revolution when a tube is turned on its "
              "end face). The tool's tip runs h below the workpiece's top particle centres."},
      {.name = "cutting_speed",
       .field = &S::cutting_speed,
       .unit = "m/s",
       .no_default = true,
       .default_note = "required",
       .range = in(0.0, 1000.0, "(]"),
       .doc = "v_c: the tool's speed along +x (60 m/min = 1 m/s). The end time is the length of cut over it."},
      {.name = "length_of_cut",
       .field = &S::length_of_cut,
       .unit = "m",
       .no_default = true,
       .default_note = "10 h",
       .range = kLength,
       .doc = "Tool travel over the run."},
      {.name = "width",
       .field = &S::width,
       .unit = "m",
       .no_default = true,
       .default_note = "plane strain",
       .range = kLengthOrZero,
       .doc = "b: width of the workpiece along the cutting edge. Not given (or 0): plane strain, a slice two "
              "cells wide and periodic across y, so the forces are per unit width without side flow; given: a "
              "block of the nearest whole number of cells (at least 2) with free sides."},
      {.name = "rake_angle",
       .field = &S::rake_angle,
       .unit = "deg",
       .no_default = true,
       .default_note = "required; with `tool_file` measured",
       .range = in(-60.0, 60.0, "()"),
       .rule = "with `tool_file`: within 0.5 deg of the measured",
       .doc = "gamma_o, the tool's orthogonal rake angle (ISO 3002): positive tilts the rake face back from the "
              "normal to the cut surface. With `tool_file` it is measured from the mesh; given as well, it must "
              "agree (a check that the file is the tool meant)."},
      {.name = "clearance_angle",
       .field = &S::clearance_angle,
       .unit = "deg",
       .range = in(0.0, 45.0, "(]"),
       .rule = "with `tool_file`: within 0.5 deg of the measured",
       .doc = "alpha_o, the tool's orthogonal clearance angle (ISO 3002) between the flank and the cut surface. With "
              "`tool_file` it is measured from the mesh; given as well, it must agree."},
      {.name = "edge_radius",
       .field = &S::edge_radius,
       .unit = "m",
       .range = kLengthOrZero,
       .rule = "below the depth of cut; not with `tool_file`",
       .doc = "r_n, radius of the honed cutting edge; 0 is a sharp edge. With `tool_file` the file's edge is "
              "used and its radius estimated from the mesh (printed)."},
      {.name = "inclination_angle",
       .field = &S::inclination_angle,
       .unit = "deg",
       .range = in(-45.0, 45.0, "[]"),
       .rule = "needs `width` (free sides); not with `tool_file`",
       .doc = "lambda_s, the cutting edge's inclination (ISO 3002): an oblique cut. The generated tool is turned "
              "about the vertical through its tip, so its edge runs at lambda to the y axis while it still moves "
              "along +x; `rake_angle` and `clearance_angle` are then the normal angles (in the section normal to "
              "the edge). The tool starts further back, so that its leading corner enters the block as an "
              "orthogonal tool's edge would, and travels `length_of_cut` beyond that lead (the middle of the "
              "width cuts `length_of_cut`). The run reports the chip flow angle eta_c beside Stabler's rule "
              "eta_c = lambda, the passive force along y and the chip's width "
              "([outputs.md](outputs.md#an-oblique-cut))."},
      {.name = "tool_file",
       .field = &S::tool_file,
       .default_note = "a generated tool",
       .rule = "an existing `.stl` or `.obj` file (relative to the case file) that measures as a tool",
       .doc = "The tool as a triangle mesh from CAD instead of the generated one, in the generated tool's frame: "
              "it cuts along +x, its cutting edge lies along y, the rake face faces +x (toward the chip) and the "
              "flank -z. Its rake and clearance angles, sharp tip and edge radius are measured from the faces "
              "next to its lowest point ([below](#a-tool-from-a-file)) and printed; it is moved so that the sharp "
              "tip sits where the generated tool's would (h below the top centres, h/4 before the block, on the "
              "middle of the width). Its edge must span the workpiece's width."},
      {.name = "tool_scale",
       .field = &S::tool_scale,
       .unit = "1",
       .range = kScale,
       .rule = "only with `tool_file`",
       .doc = "Factor on `tool_file`'s coordinates, as [[mesh]] `scale`: 1e-3 for a file in mm."},
      {.name = "friction",
       .field = &S::friction,
       .unit = "1",
       .range = in(0.0, 2.0, "[]"),
       .doc = "Coulomb coefficient of the contacts (tool-chip, chip-chip): `contact.friction`."},
      {.name = "material",
       .field = &S::material,
       .no_default = true,
       .default_note = "required",
       .choices = {"C45", "Al2024-T351", "Ti6Al4V"},
       .doc = "The workpiece material, a [preset](materials.md): `material.preset`, calibrated in tension "
              "along [100], with the contacts' Young's modulus the preset's."},
      {.name = "layers",
       .field = &S::layers,
       .unit = "1",
       .range = in(2, 200, "[]"),
       .doc = "Lattice layers across the depth of cut: the resolution. R = h / (layers sqrt 2) (FCC layers are "
              "sqrt(2) R apart along z)."},
      {.name = "workpiece_length",
       .field = &S::workpiece_length,
       .unit = "1",
       .no_default = true,
       .default_note = "length_of_cut / h + 7.6",
       .range = in(1.0, 1e4, "[]"),
       .doc = "Length of the block along x in multiples of h (rounded to whole cells); the default leaves 7.6 h "
              "of material ahead of the tool's end position."},
      {.name = "workpiece_height",
       .field = &S::workpiece_height,
       .unit = "1",
       .range = in(1.5, 100.0, "[]"),
       .doc = "Height of the block along z in multiples of h (rounded to whole cells): h of it is cut, the rest "
              "carries the cut. The upper bound is a judgement: below a few h the block's bending no longer "
              "reaches the cut, and 1000 h built a model of millions of particles for minutes before any check "
              "on the run could refuse it."},
      {.name = "steady_from",
       .field = &S::steady_from,
       .unit = "m",
       .no_default = true,
       .default_note = "half the length of cut",
       .range = kLengthOrZero,
       .rule = "below the length of cut",
       .doc = "Tool travel from which the forces and chip figures are averaged (`output.steady_from` is this "
              "over the cutting speed)."},
      {.name = "tool_stiffness",
       .field = &S::tool_stiffness,
       .unit = "N/m/m",
       .range = in(0.0, 1e15, "[]", "0 to 1e15 N/m/m, a judgement: 1e5 times a stiff spindle per mm of width"),
       .rule = "with tool_mass",
       .doc = "k/b: stiffness of a compliant tool's mount per metre of the cut's width (N/m of the tool for each m "
              "of width), the same along the cutting (x) and thrust (z) directions. Given: the tool is a rigid body "
              "(`dynamics = \"rigid_body\"`, not turning, y held) pulled along its path by a spring and damper to "
              "its holder, which moves at the cutting speed; its deflection and spectra are written "
              "([outputs.md](outputs.md#a-compliant-tool)). A holder of 2e7 N/m (20 N/um) cutting a width of 2 mm "
              "is 1e10 N/m/m. 0: the tool follows its path rigidly."},
      {.name = "tool_mass",
       .field = &S::tool_mass,
       .unit = "kg/m",
       .no_default = true,
       .default_note = "required with tool_stiffness",
       .range = in(1e-9, 1e6, "[]", "1e-9 to 1e6 kg/m, a judgement"),
       .rule = "only with tool_stiffness",
       .doc = "m/b: modal mass of the compliant tool per metre of width. Natural frequency f_n = sqrt(k/m) / (2 "
              "pi), independent of the width."},
      {.name = "tool_damping_ratio",
       .field = &S::tool_damping_ratio,
       .unit = "1",
       .range = in(0.0, 10.0, "[]"),
       .rule = "only with tool_stiffness",
       .doc = "zeta: the mount's damping as a fraction of its critical damping 2 sqrt(k m), along x and z."},
  };
  return keys;
}

}  // namespace swarf
