#!/usr/bin/env bash
# W1 over 2 MPI ranks by domain decomposition, side by side with OpenMP threads and LAMMPS on
# 2 ranks, in one sitting, alternated. Usage: validation/bench/run_domains.sh [ROUNDS] [SCRATCH_DIR]
# Per round, in this order: swarf serial on 1 and 2 threads, swarf on 2 ranks x 1 thread
# (swarf_domains_bench, re-cut every 1000 steps), LAMMPS on 1 and 2 ranks (validation/bench/peers),
# each 2,000 steps of W1 17^3 (19,652 particles). Prints one line per run: ns per particle-step
# of the stepping (setup excluded: swarf's bench times the steps only, LAMMPS's "Loop time"),
# with swarf's halo and exchange figures and its position hash (the same for every swarf run).
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
rounds=${1:-3}
peers=${SWARF_PEERS:-$root/validation/bench/peers}
scratch=${2:-/tmp/swarf-peers}
. "$root/validation/bench/peers_setup.sh"
bench=$root/build/bin/swarf_domains_bench
case=$root/validation/bench/w1.toml
MPI="mpirun --allow-run-as-root --oversubscribe --bind-to core -np 2"
swarf_line() {  # label, then the bench's output on stdin
  awk -v label="$1" '/ns per particle-step/ {ns=$0; sub(/.*: /, "", ns); sub(/ ns.*/, "", ns)}
    /^rank 0/ {halo=$0; sub(/.*\), halo /, "", halo); sub(/ sent.*/, "", halo); ex=$0; sub(/.*; /, "", ex); sub(/ in the.*/, "", ex)}
    /positions hash/ {h=$3}
    END {printf "| %s | %s ns | halo %s per rank and step | exchange %s s | hash %s |\n", label, ns, (halo==""?"-":halo), (ex==""?"-":ex), h}'
}
lammps_line() {  # label, log file
  /usr/bin/python3 - "$2" "$1" <<'PY'
import re, sys
log = open(sys.argv[1]).read()
t = float(re.findall(r'Loop time of (\S+) on \d+ procs for 2000 steps with 19652 atoms', log)[-1])
res = re.findall(r'W1_RESULT intact_bonds (\d+)', log)
print("| %s | %.1f ns | intact bonds %s |" % (sys.argv[2], t / (19652 * 2000) * 1e9, res[-1]))
PY
}
echo "== $(date -u +%FT%TZ) load $(cut -d' ' -f1-3 /proc/loadavg), $rounds rounds"
for r in $(seq 1 "$rounds"); do
  echo "-- round $r"
  OMP_NUM_THREADS=1 "$bench" "$case" 2000 | swarf_line "swarf serial, 1 thread"
  OMP_NUM_THREADS=2 "$bench" "$case" 2000 | swarf_line "swarf serial, 2 threads"
  OMP_NUM_THREADS=1 $MPI "$bench" "$case" 2000 --rebalance-every 1000 | swarf_line "swarf 2 ranks x 1 thread"
  (cd "$scratch/lammps" && OMP_NUM_THREADS=1 lmp -in in.w1 -log none -var nsteps 2000 > out1.log 2>&1)
  lammps_line "LAMMPS 1 rank" "$scratch/lammps/out1.log"
  (cd "$scratch/lammps" && OMP_NUM_THREADS=1 $MPI lmp -in in.w1 -log none -var nsteps 2000 > out2.log 2>&1)
  lammps_line "LAMMPS 2 ranks" "$scratch/lammps/out2.log"
done
