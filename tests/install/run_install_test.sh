#!/usr/bin/env bash
# run_install_test.sh: the program as a user installs it (ctest install_prefix).
#
# 1. installs the build tree into a temporary prefix (cmake --install --prefix);
# 2. checks the installed files: the program, the post-processing scripts, the ParaView
#    script's template, the docs, LICENSE, CITATION.cff, Debian's copyright file, the man page,
#    the examples and the engine's CMake package; the man page has a section for every
#    subcommand that `swarf --help` lists, and every installed example case passes --check;
# 3. moves the prefix elsewhere (a relocated install must still find its scripts), then checks
#    that `swarf --version` names the moved prefix's share/swarf/postprocess as its scripts;
# 4. runs the built-in default case's first 2 us (about 1,700 steps) from there, with its frames
#    and plots, without
#    SWARF_POSTPROCESS_DIR, and checks that it completed, wrote open_in_paraview.py and
#    rendered the pictures (when xvfb-run and Python's vtk are there; else that the warning
#    names a missing tool, not a missing script).
# The temporary directory is removed on success and kept (its path printed) on failure.
#
# Usage: run_install_test.sh CMAKE BUILD_DIR [CONFIG]
set -euo pipefail
if [ $# -lt 2 ]; then
  echo "usage: $0 CMAKE BUILD_DIR [CONFIG]" >&2
  exit 2
fi
cmake_bin=$1 build=$2 config=${3:-}
install_config=()
[ -z "$config" ] || install_config=(--config "$config")
work=$(mktemp -d "${TMPDIR:-/tmp}/swarf-install.XXXXXX")
passed=0
trap 'if [ "$passed" = 1 ]; then rm -rf "$work"; else echo "install test: kept $work for inspection" >&2; fi' EXIT
fail() {
  echo "install test: FAILED: $1" >&2
  if [ $# -gt 1 ] && [ -f "$2" ]; then tail -n 60 "$2" >&2; fi
  exit 1
}
echo "== install test: cmake --install into $work/first"
"$cmake_bin" --install "$build" --prefix "$work/first" "${install_config[@]}" >"$work/install.log" 2>&1 ||
  fail "cmake --install" "$work/install.log"
for f in bin/swarf share/swarf/postprocess/plot_run.py share/swarf/postprocess/render_chip.py \
  share/swarf/postprocess/plot_material.py share/swarf/postprocess/study_plots.py \
  share/swarf/postprocess/open_in_paraview.py share/doc/swarf/LICENSE share/doc/swarf/CITATION.cff \
  share/doc/swarf/README.md share/doc/swarf/outputs.md share/doc/swarf/case-reference.md \
  share/doc/swarf/copyright share/swarf/examples/default_cut.toml share/swarf/examples/cut_c45.toml \
  share/swarf/examples/c45_cut_with_heat.toml share/swarf/examples/cut_tool_from_file.toml \
  share/swarf/examples/insert_r6_c7.stl share/man/man1/swarf.1.gz \
  lib/cmake/swarf/swarfConfig.cmake include/swarf/simulation.h; do
  [ -e "$work/first/$f" ] || fail "not installed: $f"
done
echo "== install test: the prefix moved to $work/moved"
mv "$work/first" "$work/moved"
prefix=$work/moved
unset SWARF_POSTPROCESS_DIR
"$prefix/bin/swarf" --version >"$work/version.txt" 2>&1 || fail "swarf --version" "$work/version.txt"
grep -qx "scripts $prefix/share/swarf/postprocess" "$work/version.txt" ||
  fail "swarf --version does not name $prefix/share/swarf/postprocess as its scripts" "$work/version.txt"
echo "== install test: the man page and the examples"
gzip -dc "$prefix/share/man/man1/swarf.1.gz" >"$work/swarf.1" || fail "share/man/man1/swarf.1.gz is not gzip"
grep -q '^\.TH SWARF 1' "$work/swarf.1" || fail "swarf.1 has no .TH line" "$work/swarf.1"
for sub in $("$prefix/bin/swarf" --help | sed -n '/^Subcommands:/,$p' | awk 'NR > 1 && /^  [a-z]/ {print $1}'); do
  grep -q "^\.SS swarf $sub\$" "$work/swarf.1" || fail "swarf.1 has no section for 'swarf $sub'" "$work/swarf.1"
done
for case in "$prefix"/share/swarf/examples/*.toml; do
  "$prefix/bin/swarf" run "$case" --check >"$work/check.log" 2>&1 || fail "swarf run $case --check" "$work/check.log"
done
echo "== install test: swarf run from the moved prefix"
(cd "$work" && "$prefix/bin/swarf" run --out "$work/out" --threads 1 --set integrator.end_time=2e-6 \
  --set output.steady_from=1e-6) >"$work/run.log" 2>&1 ||
  fail "swarf run" "$work/run.log"
[ -f "$work/out/summary.json" ] || fail "no summary.json" "$work/run.log"
[ -f "$work/out/open_in_paraview.py" ] || fail "no open_in_paraview.py" "$work/run.log"
/usr/bin/python3 -m py_compile "$work/out/open_in_paraview.py" || fail "open_in_paraview.py does not compile"
if grep -q "not found" "$work/run.log"; then fail "a script was not found" "$work/run.log"; fi
if command -v xvfb-run >/dev/null && /usr/bin/python3 -c 'import vtk, matplotlib' 2>/dev/null; then
  for png in energy.png forces.png chip.png chip_plastic_strain.png chip_von_mises_stress.png; do
    [ -s "$work/out/$png" ] || fail "no $png" "$work/run.log"
  done
else
  echo "install test: no xvfb-run or no vtk/matplotlib for /usr/bin/python3: pictures not checked"
fi
passed=1
echo "== install test: passed"
