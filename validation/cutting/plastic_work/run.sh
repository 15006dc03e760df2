#!/bin/bash
# The default cut at 5, 7, 10, 14 and 20 lattice layers across h (the refinement study's points,
# validation/studies/refinement.toml) and at 5, 7 and 10 layers with the tool raised by a/4 (its tip
# between two layers), each writing the particles' plastic work to results.h5; then the tables and
# the figure. One run after another on 2 threads: about 45 minutes here, the 20-layer run 25 of them.
#   validation/cutting/plastic_work/run.sh [OUT]     (OUT: default results/plastic_work)
set -e
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../../.." && pwd)
out=${1:-results/plastic_work}
swarf=$root/build/bin/swarf
case_file=$root/validation/cutting/default_cut.toml
mkdir -p "$out"
run() {
  name=$1
  shift
  [ -f "$out/$name/summary.json" ] || "$swarf" run "$case_file" --threads 2 --out "$out/$name" --set output.vtk=false \
    --set output.plots=false "$@" > "$out/$name.log" 2>&1
  echo "$name done"
}
l5=(--set workpiece.radius=2.82843e-5 --set 'workpiece.cells=[44, 2, 8]' --set 'group.1.box_min=[3.40e-3, -1.0, 0.06e-3]')
l7=(--set workpiece.radius=2.0e-5 --set 'workpiece.cells=[62, 2, 11]')
l14=(--set workpiece.radius=1.0e-5 --set 'workpiece.cells=[124, 2, 21]')
l20=(--set workpiece.radius=7.07107e-6 --set 'workpiece.cells=[176, 2, 30]')
run l05 "${l5[@]}" --set 'mesh.0.origin=[-0.05e-3, 0.06e-3, 0.40e-3]'
run l07 "${l7[@]}" --set 'mesh.0.origin=[-0.05e-3, 0.06e-3, 0.394e-3]'
run l10
run l14 "${l14[@]}" --set 'mesh.0.origin=[-0.05e-3, 0.06e-3, 0.38e-3]'
run l20 "${l20[@]}" --set 'mesh.0.origin=[-0.05e-3, 0.06e-3, 0.39e-3]'
# The tip raised by a/4 = R / sqrt(2): between two layers (h from the top centres less by a/4).
run l05s "${l5[@]}" --set 'mesh.0.origin=[-0.05e-3, 0.06e-3, 0.42e-3]'
run l07s "${l7[@]}" --set 'mesh.0.origin=[-0.05e-3, 0.06e-3, 0.40814e-3]'
run l10s --set 'mesh.0.origin=[-0.05e-3, 0.06e-3, 0.39e-3]'
cd "$out"
/usr/bin/python3 "$root/validation/cutting/energy_partition.py" l05 l07 l10 l14 l20 --png plastic_work_profile.png \
  --csv profiles.csv
/usr/bin/python3 "$here/separation_height.py" l05 l07 l10 l14 l20 l05s l07s l10s
