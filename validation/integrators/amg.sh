#!/usr/bin/env bash
# The Newton solve's CG preconditioned by hypre's BoomerAMG (study/hypre_amg.h) against the
# engine's matrix-free block-Jacobi, in one sitting (issue 35 item 4), with 'swarf bench
# --preconditioner amg' on two scenes:
#   the cut: the default cut's 0.5 us from its checkpoint at 1 mm of travel (10,560 particles;
#            make it as validation/bench/README.md says: swarf run validation/cutting/default_cut.toml
#            --out /tmp/cut1mm --set integrator.end_time=1e-4 --set output.checkpoint_at_end=true)
#   the bar: the hysteresis bar's first 1 ms (validation/hysteresis/bar.toml, 3,456 particles, no
#            contacts), Newton at dt_max = 20 dt_stable (2.172 us), where the block-Jacobi needs
#            the most CG iterations
# Prints swarf bench's rows (steps, evaluations, Newton and CG iterations, wall s) and, for AMG,
# its hierarchies and the time in their setup and in the cycles; the block-Jacobi rows with the
# stages (the Krylov stage is what a preconditioner can shorten).
# Usage: validation/integrators/amg.sh [CHECKPOINT]   (default /tmp/cut1mm/checkpoint.h5)
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
swarf="$root/build/bin/swarf"
ckpt=${1:-/tmp/cut1mm/checkpoint.h5}
newton=(--set 'integrator.scheme="newmark"' --set 'integrator.solver="newton"' --threads 2 --repeats 1)
cut=("$ckpt" --set integrator.end_time=1.005e-4 "${newton[@]}")
bar=("$root/validation/hysteresis/bar.toml" --set integrator.end_time=1e-3 --set integrator.dt_max=2.172e-6 "${newton[@]}")
for scene in cut bar; do
  if [ $scene = cut ]; then args=("${cut[@]}"); else args=("${bar[@]}"); fi
  echo "## $scene"
  for variant in block_jacobi "amg" "amg --amg-nodal" "amg --amg-refresh 20 --amg-nodal" "amg --amg-refresh 20" \
                 "amg --amg-refresh 20 --amg-threshold 0.8" block_jacobi; do
    read -r -a v <<< "$variant"
    echo "### --preconditioner $variant"
    if [ "$variant" = block_jacobi ]; then
      "$swarf" bench "${args[@]}" --preconditioner block_jacobi --stages | grep -v '^|---'
    else
      "$swarf" bench "${args[@]}" --preconditioner "${v[@]}" | grep -v '^|---' | tail -2
    fi
  done
done
