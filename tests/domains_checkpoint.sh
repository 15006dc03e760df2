#!/usr/bin/env bash
# A checkpoint written by a run on 2 MPI ranks (domain decomposition: the gathered state,
# DomainRun::gather_simulation) and read by a serial run and by a run on 3 ranks: all three end
# with the positions of the uninterrupted serial run, bit for bit (the bench's position hash).
# Usage: domains_checkpoint.sh SWARF_DOMAINS_BENCH CASE   (exit 77: mpirun missing, skipped)
bench=$1 case=$2
source "$(dirname "$0")/mpi_prelude.sh"
hash_of() { grep -o 'positions hash [0-9a-f]*' | awk '{print $3}'; }
whole=$("$bench" "$case" 600 | hash_of)
two=$($MPI -n 2 "$bench" "$case" 600 --checkpoint-at 250 "$dir/c.h5" | hash_of)
serial=$("$bench" "$case" 600 --restart "$dir/c.h5" | hash_of)
three=$($MPI -n 3 "$bench" "$case" 600 --restart "$dir/c.h5" | hash_of)
echo "uninterrupted serial $whole; 2 ranks writing a checkpoint at step 250 $two;" \
  "serial from it $serial; 3 ranks from it $three"
[ -n "$whole" ] && [ "$two" = "$whole" ] && [ "$serial" = "$whole" ] && [ "$three" = "$whole" ]
