#!/bin/bash
# The width series (width.py): oblique_c45.toml at lambda = 0 with b = 0.8 and 1.6 mm (b/h = 4 and 8),
# and plane_strain_c45.toml, one after the other (8, 17 and 6 minutes on 2 threads here), then
# width.py. Usage: run_width.sh [OUT] (default results/width/).
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
out=${1:-$here/results/width}
swarf=${SWARF:-$here/../../../build/bin/swarf}
mkdir -p "$out"
for run in "b08 0.8e-3" "b16 1.6e-3"; do
  set -- $run
  "$swarf" run "$here/oblique_c45.toml" --set cut.inclination_angle=0.0 --set cut.width=$2 --out "$out/$1"
done
"$swarf" run "$here/plane_strain_c45.toml" --out "$out/plane_strain"
/usr/bin/python3 "$here/width.py" "$out" "$here"
