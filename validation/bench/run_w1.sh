#!/usr/bin/env bash
# W1 side by side: swarf's bench and the LAMMPS deck of validation/bench/peers, in one sitting.
# Usage: validation/bench/run_w1.sh [SCRATCH_DIR]   (installs Debian's lammps if missing)
# SWARF_PEERS=DIR takes the peer decks from DIR instead of validation/bench/peers.
# Prints swarf's table (ns per particle-step for 1 and 2 threads, broken rods and kinetic
# energy after 2,000 steps) and LAMMPS's loop times and results for 1 and 2 MPI ranks.
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
peers=${SWARF_PEERS:-$root/validation/bench/peers}
scratch=${1:-/tmp/swarf-peers}
. "$root/validation/bench/peers_setup.sh"
echo "== swarf"
"$root/build/bin/swarf" bench "$root/validation/bench/w1.toml" --threads 1,2 --repeats 3
echo "== LAMMPS (median of 3 runs after 1 warm-up)"
cd "$scratch/lammps"
export OMP_NUM_THREADS=1
MPI="mpirun --allow-run-as-root --oversubscribe -np 2"
B=../common/bench.sh
$B lammps_w1_np1 3 1 900 -- lmp -in in.w1 -log none -var nsteps 2000 >/dev/null
$B lammps_w1_np2 3 1 900 -- $MPI lmp -in in.w1 -log none -var nsteps 2000 >/dev/null
for label in lammps_w1_np1 lammps_w1_np2; do
  /usr/bin/python3 - "out/$label.log" "$label" <<'PY'
import re, statistics, sys
log = open(sys.argv[1]).read()
loops = [float(m.group(1)) for m in re.finditer(r'Loop time of (\S+) on \d+ procs for 2000 steps with 19652 atoms', log)][1:]
ke = re.findall(r'^\s*2000\s+(\d+)\s+(\S+)', log, re.M)
res = re.findall(r'W1_RESULT intact_bonds (\d+)', log)
med = statistics.median(loops)
print("| %s | loop s median %.3f | %.1f ns/particle-step | intact bonds %s (broken %d) | kinetic energy J %s |" % (
    sys.argv[2], med, med / (19652 * 2000) * 1e9, res[-1], 111078 - int(res[-1]), ke[-1][1] if ke else "?"))
PY
done
