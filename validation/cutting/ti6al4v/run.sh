#!/usr/bin/env bash
# The Ti6Al4V cut (ti_cut.toml) with one thing changed at a time: does a chip form? Prints, per
# variant, the chip particles (summary.json chip.chip_particles), whether
# h_c was measured, how far ahead of the tip the uncut layer has yielded at the end (a chip:
# about h; an upset layer: many h) and Fc/w. About 25 s per run on 2 threads.
# Usage: validation/cutting/ti6al4v/run.sh OUT_DIR
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
swarf="$here/../../../build/bin/swarf"
out=${1:?usage: run.sh OUT_DIR}
mkdir -p "$out"
cold=(--set heat.enabled=false)
variants=(
  "as_is|"
  "no_sticking|--set contact.sticking=false"
  "cold|${cold[*]}"
  "cold_E205|${cold[*]} --set material.youngs_modulus=205e9"
  "cold_C45_curve|${cold[*]} --set material.johnson_cook_a=553.1e6 --set material.johnson_cook_b=600.8e6 --set material.johnson_cook_n=0.234"
  "cold_B1200|${cold[*]} --set material.johnson_cook_a=862e6 --set material.johnson_cook_b=1200e6 --set material.johnson_cook_n=0.34"
  "cold_A553_B212|${cold[*]} --set material.johnson_cook_a=553e6 --set material.johnson_cook_b=212e6 --set material.johnson_cook_n=0.34"
  "cold_rotated45|${cold[*]} --set workpiece.lattice_rotation=45"
  "cold_jitter0.1|${cold[*]} --set workpiece.disorder_seed=1 --set workpiece.position_jitter=0.1"
  "cold_shear_calibration|${cold[*]} --set material.calibration=shear"
  "cold_fail0.5|${cold[*]} --set material.failure_strain=1.5"
  "cold_fail0.3|${cold[*]} --set material.failure_strain=0.9"
  "C45_cold|${cold[*]} --set cut.material=\"C45\""
  "C45_cold_edge20|${cold[*]} --set cut.material=\"C45\" --set cut.edge_radius=20e-6"
)
echo "| variant | chip particles | h_c (mm) | layer yielded ahead of the tip (mm) | Fc/w (kN/m) |"
echo "|---|---|---|---|---|"
for v in "${variants[@]}"; do
  name=${v%%|*}
  read -r -a extra <<< "${v#*|}"
  "$swarf" run "$here/ti_cut.toml" --out "$out/$name" --threads 2 --set output.vtk=false "${extra[@]}" > "$out/$name.log" 2>&1
  /usr/bin/python3 - "$out/$name" "$name" <<'PY'
import json, sys
import h5py
import numpy as np
d, name = sys.argv[1], sys.argv[2]
s = json.load(open(d + "/summary.json"))
c, f = s.get("chip", {}), s.get("cutting", {})
hc = c.get("thickness_m")
# How far ahead of the tool the uncut layer has yielded at the end: the farthest particle
# that started in the layer (between the tip's height and the uncut surface) and now lies
# ahead of the tip with an equivalent plastic strain above 0.1.
with h5py.File(d + "/results.h5", "r") as h:
    x = h["particles/position"][:]
    z0 = x[:, 2] - h["particles/displacement"][:][:, 2]
    peeq = h["particles/peeq"][:]
    tip = h["cutting/tool_tip"][:]
    top = h["cutting/uncut_surface_z"][0]
layer = (z0 > tip[2]) & (z0 <= top + 1e-9) & (x[:, 0] > tip[0]) & (peeq > 0.1)
ahead = (x[layer, 0] - tip[0]).max() * 1e3 if layer.any() else 0.0
print("| %s | %s | %s | %.2f | %.1f |" % (name, c.get("chip_particles", "-"),
      "%.3f" % (hc * 1e3) if isinstance(hc, (int, float)) else "none", ahead,
      f["cutting_force_per_width_mean_N_per_m"] / 1e3))
PY
done
