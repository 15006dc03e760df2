#!/usr/bin/env bash
# 'mpirun -n N swarf run': one run over N ranks by domain decomposition gives the outputs of one
# rank, bit for bit, with 2 threads or 1 per rank (series.csv, the ParaView frames, the final state's hash in summary.json),
# and a checkpoint written on 2 ranks goes on over 3 ranks with the uninterrupted run's rows and
# state (the ledger's exact sums travel in the checkpoint), as does one interrupted by SIGTERM; the
# implicit step is refused. The case: the uniaxial bar
# (validation/hysteresis/bar.toml: rods, grips, velocity Verlet) for 0.3 ms, 5,524 steps.
# Usage: run_ranks.sh SWARF BAR_CASE   (exit 77: mpirun missing, skipped)
swarf=$1 case=$2
source "$(dirname "$0")/mpi_prelude.sh"
set_out="--set output.series_interval=6e-6 --set output.frame_interval=1e-4 --set output.checkpoint_at_end=true"
# (1 rank x 2 threads against 2 ranks x 1 thread: MPI and OpenMP; more threads than cores crawl)
OMP_NUM_THREADS=2 $MPI -n 1 "$swarf" run "$case" $set_out --set integrator.end_time=3e-4 --out "$dir/one" >"$dir/one.log" 2>&1
# (2 ranks whose slabs are cut anew every 7 steps, strays looked for every 3: hundreds of
# migrations, which must not change a bit)
$MPI -n 2 "$swarf" run "$case" $set_out --set integrator.end_time=3e-4 --rebalance-every 7 --stray-check-every 3 \
  --out "$dir/two" >"$dir/two.log" 2>&1
$MPI -n 2 "$swarf" run "$case" $set_out --set integrator.end_time=1.5e-4 --out "$dir/half" >"$dir/half.log" 2>&1
$MPI -n 3 "$swarf" run --restart "$dir/half/checkpoint.h5" --set integrator.end_time=3e-4 --out "$dir/rest" \
  >"$dir/rest.log" 2>&1
expect_as_one_rank two rest
# Of the restart, the last frames (its frames follow the first part's, which ended with a frame
# at 0.15 ms).
for kind in particles rods; do
  a=$(ls "$dir/one/frames/${kind}_"*.vtu | tail -1) b=$(ls "$dir/rest/frames/${kind}_"*.vtu | tail -1)
  cmp "$a" "$b" || { echo "the last $kind frame of the restart differs"; fail=1; }
done
grep -q '"ranks": 2' "$dir/two/summary.json" || { echo "summary.json of 2 ranks does not say so"; fail=1; }
# run.log says what the decomposition cost: the migrations, the time after the steps, the halo.
grep -Eq 'over 2 ranks: [0-9]+ migrations in [0-9]+ steps.*halo [0-9.]+ kB per step' "$dir/two/run.log" ||
  { echo "run.log of 2 ranks does not report the decomposition's cost"; fail=1; }
# A case the domains do not run yet (the bar with the implicit step) is refused by name, with
# exit code 2, before anything is written.
set +e
refusal=$($MPI -n 2 "$swarf" run "$case" --set 'integrator.scheme="newmark"' --out "$dir/cut" 2>&1)
code=$?
set -e
# (every rank meets it: said once, by rank 0)
if [ $code -ne 2 ] || [ "$(grep -c "does not support the implicit Newmark step" <<<"$refusal")" != 1 ] || [ -e "$dir/cut" ]; then
  echo "the bar with the implicit step on 2 ranks: exit code $code (2 expected), output: $refusal"
  fail=1
fi
# Interrupted: SIGTERM to the ranks (as Slurm's --signal sends it to a job's tasks; mpirun passes
# its own on only after about 2 s here) once 10 rows are written: the ranks stop after the same
# step, rank 0 writes checkpoint.h5, no summary.json, exit code 143; the checkpoint continued on
# 1 rank to 0.3 ms gives the uninterrupted run's series.csv.
$MPI -n 2 "$swarf" run "$case" $set_out --set integrator.end_time=3e-3 --set output.checkpoint_every=1000000 \
  --out "$dir/stop" >"$dir/stop.log" 2>&1 &
pid=$!
for _ in $(seq 600); do
  [ -f "$dir/stop/series.csv.part" ] && [ "$(wc -l <"$dir/stop/series.csv.part")" -ge 11 ] && break
  sleep 0.1
done
pkill -TERM -P $pid
set +e
wait $pid
code=$?
set -e
if [ $code -ne 143 ] || [ ! -f "$dir/stop/checkpoint.h5" ] || [ -e "$dir/stop/summary.json" ]; then
  echo "interrupted on 2 ranks: exit code $code (143 expected), checkpoint.h5 and no summary.json expected"
  ls "$dir/stop"
  fail=1
else
  $MPI -n 1 "$swarf" run --restart "$dir/stop/checkpoint.h5" --set integrator.end_time=3e-4 --out "$dir/stop2" \
    >"$dir/stop2.log" 2>&1
  cmp "$dir/one/series.csv" "$dir/stop2/series.csv" || { echo "the interrupted run, continued, differs"; fail=1; }
fi
set +e
"$swarf" run "$case" --rebalance-every 0 --out "$dir/bad" >"$dir/bad.log" 2>&1
code=$?
set -e
if [ $code -ne 2 ] || ! grep -q "rebalance-every 0" "$dir/bad.log"; then
  echo "--rebalance-every 0: exit code $code (2 expected): $(cat "$dir/bad.log")"
  fail=1
fi
echo "rows $(($(wc -l <"$dir/one/series.csv") - 1)), frames $(ls "$dir/one/frames" | wc -l), state $(hash_of "$dir/one")"
exit $fail
