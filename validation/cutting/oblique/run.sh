#!/bin/bash
# The oblique-cut series: oblique_c45.toml at lambda = 0, 15, 30 deg, one after the other (each
# some 15 minutes on 2 threads), then compare.py. Usage: run.sh [OUT] (default results/).
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
out=${1:-$here/results}
swarf=${SWARF:-$here/../../../build/bin/swarf}
mkdir -p "$out"
for lambda in 0 15 30; do
  "$swarf" run "$here/oblique_c45.toml" --set cut.inclination_angle=$lambda.0 --out "$out/l$lambda"
done
/usr/bin/python3 "$here/compare.py" "$out" "$here"
