# mpi_prelude.sh: sourced by the tests that start mpirun: skips (exit 77) without it, makes a
# scratch directory $dir removed at exit, one thread per rank, and $MPI (ranks may outnumber
# the cores; run as root in containers).
set -euo pipefail
command -v mpirun >/dev/null || { echo "mpirun not installed: skipped"; exit 77; }
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
export OMP_NUM_THREADS=1 OMP_WAIT_POLICY=PASSIVE
MPI="mpirun --allow-run-as-root --oversubscribe --bind-to none"

# The runs in $dir/one and $dir/<each argument> wrote the same series.csv and state hash, and
# $dir/one and $dir/two the same frames; sets fail=1 and says which differ otherwise.
fail=0
hash_of() { grep -o '"state_hash": "[0-9a-f]*"' "$1/summary.json"; }
expect_as_one_rank() {
  for d in "$@"; do
    if ! cmp "$dir/one/series.csv" "$dir/$d/series.csv"; then echo "series.csv of '$d' differs from one rank's"; fail=1; fi
    if [ "$(hash_of "$dir/one")" != "$(hash_of "$dir/$d")" ]; then
      echo "state hash of '$d' $(hash_of "$dir/$d") differs from one rank's $(hash_of "$dir/one")"
      fail=1
    fi
  done
  for f in "$dir/one/frames/"*; do
    cmp "$f" "$dir/two/frames/$(basename "$f")" || { echo "frame $(basename "$f") of 2 ranks differs"; fail=1; }
  done
}
