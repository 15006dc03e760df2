#!/bin/bash
# The flow-zone runs of validation/cutting/README.md ("A sub-particle flow zone on the rake face
# against the speed trend"): the default cut, h = 0.2 mm, seed 1 of the speed x feed study, one
# run per line, 1 thread each (about 4 min at 600 m/min, 13 min at 200 m/min on this machine).
#   validation/cutting/flow_zone/run.sh OUT_DIR   then   python3 validation/cutting/flow_zone/table.py OUT_DIR
set -euo pipefail
out=${1:?usage: run.sh OUT_DIR}
here=$(cd "$(dirname "$0")" && pwd)
swarf=${SWARF:-$here/../../../build/bin/swarf}
run() {  # name speed(m/s) mu law flow_zone [tool_friction_share]
  local name=$1 v=$2 mu=$3 law=$4 fz=$5 share=${6:-0.5} t
  if [ "$v" = "10" ]; then t="--set integrator.end_time=2e-4 --set output.steady_from=1e-4"
  else t="--set integrator.end_time=6e-4 --set output.steady_from=3e-4"; fi
  "$swarf" run "$here/../default_cut.toml" --out "$out/$name" --threads 1 \
    --set workpiece.position_jitter=0.02 --set workpiece.disorder_seed=1 --set output.vtk=false \
    --set output.plots=false --set "mesh.0.velocity=[$v,0.0,0.0]" $t --set contact.friction=$mu \
    --set contact.friction_law=$law --set contact.regularization_speed=0.1 \
    --set contact.sticking_flow_zone=$fz --set heat.tool_friction_share=$share > "$out/$name.log"
}
mkdir -p "$out"
run fz200 3.33333 0.5 spring true &
run fz600 10 0.5 spring true
wait
run s200 3.33333 2.0 spring true &
run s600 10 2.0 spring true
run n600 10 2.0 spring false
wait
run r200 3.33333 2.0 regularized true &
run r600 10 2.0 regularized true
run rn600 10 2.0 regularized false
wait
run rn200 3.33333 2.0 regularized false &
run z600 10 0.5 spring true 0
wait
run z200 3.33333 0.5 spring true 0
