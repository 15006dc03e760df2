#!/usr/bin/env bash
# Builds the libFuzzer harnesses of the readers (tests/fuzz/, clang with ASan and UBSan) into
# build-fuzz/ and runs one of them, or each in turn, for SECONDS:
#   scripts/fuzz.sh case_file|case_model|stl|obj|study_file|lattice_file|checkpoint|all SECONDS
# Seeds come from tests/fuzz/corpus/<name>/; the corpus grown goes to build-fuzz/corpus/<name>/
# and findings (crash-*, timeout-*, oom-*) to build-fuzz/findings/<name>/. Once a finding is
# fixed, copy it into tests/fuzz/regressions/<name>/: the ctest suite feeds every file there
# to the same reader (tests/test_fuzz_regressions.cpp). The fuzzers run niced, one at a time.
set -euo pipefail
cd "$(dirname "$0")/.."
all=(case_file case_model stl obj study_file lattice_file checkpoint)
name=${1:?usage: scripts/fuzz.sh NAME|all SECONDS}
seconds=${2:?usage: scripts/fuzz.sh NAME|all SECONDS}
if [ "$name" = all ]; then names=("${all[@]}"); else names=("$name"); fi

# -O1 with assertions on: fast enough to fuzz, and an assert is a finding too.
mkdir -p build-fuzz
CC=clang CXX=clang++ cmake -S . -B build-fuzz -DSWARF_FUZZ=ON -DSWARF_BUILD_TESTS=OFF -DSWARF_PYTHON=OFF \
  -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g" -DCMAKE_C_FLAGS_RELWITHDEBINFO="-O1 -g" \
  > build-fuzz/configure.log
targets=()
for n in "${names[@]}"; do targets+=(--target "fuzz_$n"); done
cmake --build build-fuzz -j"${SWARF_JOBS:-2}" "${targets[@]}"

status=0
for n in "${names[@]}"; do
  mkdir -p "build-fuzz/corpus/$n" "build-fuzz/findings/$n"
  echo "== fuzz_$n for $seconds s"
  # One thread (the OpenMP loops of a stepped model), 20 s per input before it counts as a
  # hang, 2 GB before it counts as running out of memory.
  dict=()
  if [ -f "tests/fuzz/$n.dict" ]; then dict=(-dict="tests/fuzz/$n.dict"); fi
  OMP_NUM_THREADS=1 nice -n 15 "build-fuzz/bin/fuzz_$n" -max_total_time="$seconds" -timeout=20 -rss_limit_mb=2048 \
    -print_final_stats=1 -artifact_prefix="build-fuzz/findings/$n/" "${dict[@]}" "build-fuzz/corpus/$n" "tests/fuzz/corpus/$n" ||
    status=1
done
exit $status
