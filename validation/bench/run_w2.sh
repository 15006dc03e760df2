#!/usr/bin/env bash
# W2 side by side: swarf and the LAMMPS deck of validation/bench/peers, alternated in one sitting.
# Usage: validation/bench/run_w2.sh [ROUNDS] [SCRATCH_DIR]   (installs Debian's lammps if missing)
# SWARF_PEERS=DIR takes the peer decks from DIR instead of validation/bench/peers.
# Each round times swarf (2,000 steps, 2 then 1 threads) and LAMMPS (2 then 1 MPI ranks) once;
# the machine's speed drifts by tens of % within minutes, so the rounds alternate the codes
# and the table gives the minimum and the median over the rounds, in ns per particle-step.
# Then the physics: contacts and translational kinetic energy at steps 200 and 2,000.
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
peers=${SWARF_PEERS:-$root/validation/bench/peers}
rounds=${1:-5}
scratch=${2:-/tmp/swarf-peers}
swarf="$root/build/bin/swarf"
. "$root/validation/bench/peers_setup.sh"
cd "$root/validation/bench"
[ -f data/w2_particles.txt ] || /usr/bin/python3 gen_w2.py >/dev/null
times="$scratch/w2_times.txt"; : > "$times"
export OMP_NUM_THREADS=1
MPI="mpirun --allow-run-as-root --oversubscribe -np 2"
for r in $(seq "$rounds"); do
  for t in 2 1; do
    # the "median s" column found by its header (the table gained columns before)
    s=$(OMP_NUM_THREADS=$t "$swarf" bench w2.toml --threads "$t" --repeats 1 |
        awk -F'|' '/^\| scene/ {for (i = 1; i <= NF; i++) if ($i ~ /median s/) c = i} END {split($c, a, " "); print a[1]}')
    echo "swarf $t $s" >> "$times"
  done
  (cd "$scratch/lammps"
   s=$($MPI lmp -in in.w2 -log none -var nsteps 2000 2>&1 | awk '/Loop time/ {print $4}'); echo "lammps 2 $s" >> "$times"
   s=$(lmp -in in.w2 -log none -var nsteps 2000 2>&1 | awk '/Loop time/ {print $4}'); echo "lammps 1 $s" >> "$times")
  echo "round $r of $rounds done" >&2
done
/usr/bin/python3 - "$times" "$rounds" <<'PY'
import statistics, sys
rows = [l.split() for l in open(sys.argv[1]) if l.strip()]
print("| code | threads / ranks | ns per particle-step, min | median | rounds |")
print("|---|---|---|---|---|")
for code in ("swarf", "lammps"):
    for t in ("1", "2"):
        ns = [float(s) * 1e9 / (19683 * 2000) for c, tt, s in rows if c == code and tt == t]
        print("| %s | %s | %.1f | %.1f | %d |" % (code, t, min(ns), statistics.median(ns), len(ns)))
PY
echo "== physics: swarf (series.csv) and LAMMPS (thermo) at steps 200 and 2,000"
out="$scratch/swarf_w2"; rm -rf "$out"
"$swarf" run w2.toml --out "$out" --threads 2 >/dev/null
/usr/bin/python3 - "$out/series.csv" <<'PY'
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
for r in rows[1:]:
    if r["step"] in ("200", "2000"):
        ke_t = float(r["kinetic_energy"]) - float(r["rotational_energy"])
        print("swarf  step %s: contacts %s (pairs and walls), translational kinetic energy %.4g J, rotational %.4g J"
              % (r["step"], r["contacts"], ke_t, float(r["rotational_energy"])))
PY
cd "$scratch/lammps"
for n in 200 2000; do
  lmp -in in.w2 -log none -var nsteps $n 2>&1 | awk -v n=$n '/W2_RESULT/ {printf "LAMMPS step %s: contacts %d (pairs only), translational kinetic energy %.4g J\n", n, $5/2, $3}'
done
