# mpi_prelude.sh: sourced by the tests that start mpirun: skips (exit 77) without it, makes a
# scratch directory $dir removed at exit, one thread per rank, and $MPI (ranks may outnumber
# the cores; run as root in containers).
set -euo pipefail
command -v mpirun >/dev/null || { echo "mpirun not installed: skipped"; exit 77; }
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
export OMP_NUM_THREADS=1 OMP_WAIT_POLICY=PASSIVE
MPI="mpirun --allow-run-as-root --oversubscribe --bind-to none"
