#!/usr/bin/env bash
# 'mpirun -n N swarf run' of a cut: the default cut (the tool, contacts with friction and
# sticking, the periodic width, Johnson-Cook rods softened by the heat, the heat with its clamps,
# bond formation with neighbour exchange) on a 20 x 15-cell block for 10 us, the tool touching
# from the start: 1 rank x 2 threads, 2 ranks whose slabs are cut anew every 7 steps (hundreds
# of migrations with the chip's contacts, their friction histories and the rods formed), 4 ranks
# in the boxes of Zoltan's recursive coordinate bisection (the default partition; here 2 x 2
# boxes in x and z, the periodic width never cut) made anew every 7 steps, and a checkpoint
# written by 2 ranks at 5 us continued on 3 give the same series.csv, frames and state hash,
# byte for byte.
# Usage: cut_ranks.sh SWARF   (exit 77: mpirun missing, skipped)
swarf=$1
source "$(dirname "$0")/mpi_prelude.sh"
cut=(--set "workpiece.cells=[20,2,15]" --set group.1.box_min.0=0.6e-3 --set mesh.0.origin.0=-0.016e-3
  --set output.frame_interval=2.5e-6 --set output.steady_from=5e-6 --set output.plots=false
  --set output.checkpoint_at_end=true)
OMP_NUM_THREADS=2 $MPI -n 1 "$swarf" run "${cut[@]}" --set integrator.end_time=1e-5 --out "$dir/one" >"$dir/one.log" 2>&1
$MPI -n 2 "$swarf" run "${cut[@]}" --set integrator.end_time=1e-5 --rebalance-every 7 --partition slabs \
  --out "$dir/two" >"$dir/two.log" 2>&1
$MPI -n 4 "$swarf" run "${cut[@]}" --set integrator.end_time=1e-5 --rebalance-every 7 --out "$dir/four" \
  >"$dir/four.log" 2>&1
$MPI -n 2 "$swarf" run "${cut[@]}" --set integrator.end_time=5e-6 --out "$dir/half" >"$dir/half.log" 2>&1
$MPI -n 3 "$swarf" run --restart "$dir/half/checkpoint.h5" --set integrator.end_time=1e-5 --out "$dir/rest" \
  >"$dir/rest.log" 2>&1
expect_as_one_rank two four rest
# The tool cut: its force along x (series.csv's force_tool_x, N) above 1 N in the last row.
fx=$(awk -F, 'NR == 1 { for (k = 1; k <= NF; ++k) if ($k == "force_tool_x") c = k } END { print $c }' "$dir/one/series.csv")
awk -v f="$fx" 'BEGIN { exit !(f < -1.0 || f > 1.0) }' || { echo "the tool does not cut: force_tool_x = $fx N"; fail=1; }
echo "tool force $fx N; rows $(($(wc -l <"$dir/one/series.csv") - 1)), frames $(ls "$dir/one/frames" | wc -l), state $(hash_of "$dir/one")"
exit $fail
