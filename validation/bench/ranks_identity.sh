#!/usr/bin/env bash
# One case run to its end on 1 rank x 2 threads and over N MPI ranks x 1 thread (the ranks'
# regions by --partition, Zoltan's RCB boxes by default), and the two compared: series.csv and
# every ParaView frame byte for byte, the state hash of summary.json. Prints the wall times and
# exits 1 if anything differs. The whole default cut takes about 7 minutes per run on 2 cores,
# too long for ctest (which runs tests/cut_ranks.sh, 10 us of a smaller cut, instead).
# Usage: validation/bench/ranks_identity.sh [CASE|default] [RANKS] [PARTITION] [SCRATCH] [-- --set key=value ...]
#   validation/bench/ranks_identity.sh default 2 rcb
#   validation/bench/ranks_identity.sh validation/cutting/oblique/oblique_c45.toml 2 rcb
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
case_file=${1:-default}
ranks=${2:-2}
partition=${3:-rcb}
scratch=${4:-/tmp/swarf-ranks-identity}
shift $(($# < 4 ? $# : 4))
[ "${1:-}" = "--" ] && shift
swarf=$root/build/bin/swarf
args=()
[ "$case_file" != default ] && args+=("$case_file")
rm -rf "$scratch"
mkdir -p "$scratch"
MPI="mpirun --allow-run-as-root --oversubscribe --bind-to none"
export OMP_WAIT_POLICY=PASSIVE
wall() { /usr/bin/python3 -c 'import json,sys; print(json.load(open(sys.argv[1]))["run"]["wall_time_s"])' "$1/summary.json"; }
OMP_NUM_THREADS=2 $MPI -n 1 "$swarf" run "${args[@]}" "$@" --out "$scratch/one" >"$scratch/one.log" 2>&1
OMP_NUM_THREADS=1 $MPI -n "$ranks" "$swarf" run "${args[@]}" "$@" --partition "$partition" --out "$scratch/ranks" \
  >"$scratch/ranks.log" 2>&1
fail=0
cmp "$scratch/one/series.csv" "$scratch/ranks/series.csv" || { echo "series.csv differs"; fail=1; }
frames=0
for f in "$scratch/one/frames/"*; do
  frames=$((frames + 1))
  cmp -s "$f" "$scratch/ranks/frames/$(basename "$f")" || { echo "frame $(basename "$f") differs"; fail=1; }
done
h1=$(grep -o '"state_hash": "[0-9a-f]*"' "$scratch/one/summary.json")
h2=$(grep -o '"state_hash": "[0-9a-f]*"' "$scratch/ranks/summary.json")
[ "$h1" = "$h2" ] || { echo "state hash differs: $h1 against $h2"; fail=1; }
rows=$(($(wc -l <"$scratch/one/series.csv") - 1))
printf '%s: %d rows, %d frame files, %s; wall time of the steps: 1 rank x 2 threads %.1f s, %d ranks x 1 thread (%s) %.1f s: %s\n' \
  "$case_file" "$rows" "$frames" "$h1" "$(wall "$scratch/one")" "$ranks" "$partition" "$(wall "$scratch/ranks")" \
  "$([ $fail = 0 ] && echo identical || echo DIFFERENT)"
exit $fail
