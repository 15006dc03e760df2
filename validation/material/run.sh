#!/usr/bin/env bash
# The material lab's validation runs: every test on the linear-law cut (the built-in case until 2026-12-02) and on the C45 draft rod
# law, and [100] tension of the C45 draft without failure (to read the finite-strain departure at
# log strain 1). Writes the curves to OUT (default /tmp/swarf-material) and copies the PNGs and
# material.json here; prints the README's tables (table.py). Usage: run.sh [SWARF] [OUT]
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
swarf=${1:-$here/../../build/bin/swarf}
out=${2:-/tmp/swarf-material}
"$swarf" material "$here/../cutting/linear_cut.toml" --out "$out/default"
"$swarf" material "$here/c45_draft.toml" --out "$out/c45"
"$swarf" material "$here/c45_draft.toml" --test tension100 --to 1.2 --set rod.failure_strain=inf --out "$out/c45_nofail"
for case in default c45; do
  mkdir -p "$here/$case"
  cp "$out/$case"/*.png "$out/$case/material.json" "$here/$case/"
done
cp "$out/c45_nofail/material.json" "$here/c45/material_nofail.json"
/usr/bin/python3 "$here/table.py" "$here/default/material.json" "$here/c45/material.json" "$here/c45/material_nofail.json"
