#!/usr/bin/env bash
# Newton against Verlet on the same cut at several cutting speeds, alternated in one sitting
# (issue 35 item 4): examples/cut_c45.toml (C45 with heat, Johnson-Cook rods, sticking) at
# 5 lattice layers across h = 0.2 mm and 0.4 mm of travel, 2 threads, each speed run as
# Verlet, then Newton (dt_max 10 stable steps, the default), then Newton with dt_max 19.9 stable steps (about the most
# it allows). Prints one Markdown row per run: speed, scheme, steps, force evaluations, wall time
# (summary.json run.wall_time_s), Fc/w and Ft/w with their 95 % intervals.
# Usage: validation/integrators/speed_breakeven.sh OUT_DIR [SPEED ...]   (m/s; default 10 3 1 0.3)
# SWARF_EXTRA="--set KEY=VALUE ..." adds overrides to every run. The first series (README,
# "Newton against Verlet over the cutting speed") set SWARF_EXTRA="--set material.johnson_cook_c=0":
# Newton did not converge with Johnson-Cook's rate term then. Since Newton reads the rate factor at
# the step start's rate (integrate/newton.cpp) it runs with it; see the README section "Newton with
# Johnson-Cook's rate term" for what that lag costs.
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
out=${1:?usage: speed_breakeven.sh OUT_DIR [SPEED ...]}
shift
speeds=${*:-10 3 1 0.3}
swarf="$root/build/bin/swarf"
read -r -a user_extra <<< "${SWARF_EXTRA:-}"
common=("${user_extra[@]}" --threads 2 --set cut.layers=5 --set cut.length_of_cut=0.4e-3 --set output.vtk=false --set output.plots=false)
newton=(--set 'integrator.scheme="newmark"' --set 'integrator.solver="newton"')
mkdir -p "$out"
echo "| v (m/s) | scheme | steps | force evaluations | wall (s) | Fc/w (kN/m) | Ft/w (kN/m) |"
echo "|---|---|---|---|---|---|---|"
for v in $speeds; do
  for scheme in verlet newton newton20; do
    dir="$out/v${v}_$scheme"
    extra=()
    [ "$scheme" != verlet ] && extra=("${newton[@]}")
    if [ "$scheme" = newton20 ]; then
      # dt_max = 19.9 stable steps (the printout rounds it to 3 digits; 20 is the cap): the stable step from the --check printout of this case
      dts=$("$swarf" run "$root/examples/cut_c45.toml" --out "$dir.chk" --check "${common[@]}" "${extra[@]}" \
            --set cut.cutting_speed="$v" | sed -n 's/.*stable step \([0-9.e+-]*\) s.*/\1/p' | head -1)
      extra+=(--set "integrator.dt_max=$(python3 -c "print(19.9 * $dts)")")
    fi
    "$swarf" run "$root/examples/cut_c45.toml" --out "$dir" "${common[@]}" "${extra[@]}" \
      --set cut.cutting_speed="$v" > "$dir.log" 2>&1 || { echo "| $v | $scheme | failed: see $dir.log |"; continue; }
    /usr/bin/python3 - "$dir/summary.json" "$v" "$scheme" <<'PY'
import json, sys
s = json.load(open(sys.argv[1]))
c, r = s["cutting"], s["run"]
print("| %s | %s | %s | %s | %.1f | %.1f +- %.1f | %.1f +- %.1f |" % (
    sys.argv[2], sys.argv[3], r.get("steps", "?"), r.get("force_evaluations", "?"), r["wall_time_s"],
    c["cutting_force_per_width_mean_N_per_m"] / 1e3, (c.get("cutting_force_per_width_ci95_N_per_m") or float("nan")) / 1e3,
    c["thrust_force_per_width_mean_N_per_m"] / 1e3, (c.get("thrust_force_per_width_ci95_N_per_m") or float("nan")) / 1e3))
PY
  done
done
