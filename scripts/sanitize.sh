#!/usr/bin/env bash
# The test suite under the sanitizers (issue 18, item 4):
#   scripts/sanitize.sh asan   the whole ctest suite built with AddressSanitizer and
#                              UndefinedBehaviorSanitizer (GCC, SWARF_SANITIZE=ON) in build-asan/;
#                              undefined behaviour stops the test (halt_on_error) instead of
#                              being printed and forgotten
#   scripts/sanitize.sh tsan   the threaded tests (1 against 2 or 3 threads, the restarts on 2
#                              threads, the study's parallel jobs) built with ThreadSanitizer in
#                              build-tsan/: clang with LLVM's OpenMP runtime and its Archer tool,
#                              which tells TSan about the runtime's own barriers and tasks (GCC's
#                              libgomp is not instrumented, so under GCC every parallel loop's
#                              barrier reads as a race)
#   scripts/sanitize.sh [all]  both, one after the other
# Each step is niced; SWARF_JOBS sets the build's and ctest's parallelism (2).
set -euo pipefail
cd "$(dirname "$0")/.."
what=${1:-all}
jobs=${SWARF_JOBS:-2}

# The threaded tests (their names in tests/*.cpp): those that compare 1 and 2 (or 3) threads
# in-process, and those that run or continue the swarf binary on 2 threads.
tsan_filter='Determinism.*:Newton.SameBitsForOneAndTwoThreads:Newton.WithContactsSameBitsForOneAndTwoThreads'
tsan_filter+=':BondFormation.ACutThatFormsRodsIsBitIdenticalOnOneAndTwoThreadsAndBalancesEnergy'
tsan_filter+=':Disorder.SameSeedGivesTheSameBitsOnOneAndTwoThreadsAndInAnyOrder'
tsan_filter+=':Restart.ContinuesBitIdenticallyAndWhateverTheThreads:Restart.ACutThatFormsAndExchangesRodsContinuesBitIdentically'
tsan_filter+=':Restart.ADisorderedWorkpieceContinuesBitIdentically:Restart.AMembraneWithAContactContinuesBitIdenticallyOnTwoThreads'
tsan_filter+=':Restart.ExtendsAFinishedRunBitIdenticallyToOneLongRun'
tsan_filter+=':BodyDeterminism.OneAndTwoThreadsGiveIdenticalBits:BodyCase.ARestartFromACheckpointContinuesBitIdentically'
tsan_filter+=':Sweep.JobsTwoFailureResumeRefusalAndReport'

if [ "$what" = asan ] || [ "$what" = all ]; then
  echo "== ASan + UBSan: build-asan/"
  # (no Python module: python3 would need the sanitizer runtime preloaded)
  cmake -S . -B build-asan -DSWARF_SANITIZE=ON -DSWARF_PYTHON=OFF -DCMAKE_BUILD_TYPE=RelWithDebInfo > /dev/null
  # (every executable ctest runs: without swarf_cosim_example, the test cosim_example is 'Not Run')
  nice -n 15 cmake --build build-asan -j"$jobs" --target swarf swarf_tests swarf_cosim_example
  (cd build-asan &&
    ASAN_OPTIONS=detect_leaks=1:strict_string_checks=1:detect_stack_use_after_return=1 \
      UBSAN_OPTIONS=halt_on_error=1:print_stacktrace=1 \
      nice -n 15 ctest -j"$jobs" --output-on-failure --timeout 1800)
fi

if [ "$what" = tsan ] || [ "$what" = all ]; then
  echo "== TSan (clang, libomp + Archer): build-tsan/"
  archer=$(ls /usr/lib/llvm-*/lib/libarcher.so 2>/dev/null | tail -1)
  if [ -z "$archer" ]; then
    echo "sanitize.sh: libarcher.so (LLVM's OpenMP TSan tool) not found: apt-get install libomp-dev" >&2
    exit 1
  fi
  CC=clang CXX=clang++ cmake -S . -B build-tsan -DSWARF_PYTHON=OFF -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DCMAKE_CXX_FLAGS="-fsanitize=thread" -DCMAKE_C_FLAGS="-fsanitize=thread" \
    -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=thread" -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g" \
    -DCMAKE_C_FLAGS_RELWITHDEBINFO="-O1 -g" > /dev/null
  nice -n 15 cmake --build build-tsan -j"$jobs" --target swarf swarf_tests
  # Every name in the filter must still name a test: a renamed test would drop out silently.
  listed=$(build-tsan/bin/swarf_tests --gtest_list_tests --gtest_filter="$tsan_filter" | awk '/^[^ ]/ {s = $1} /^  / {print s $1}')
  for t in ${tsan_filter//:/ }; do
    case $t in
      *'*') grep -q "^${t%'*'}" <<< "$listed" ;;
      *) grep -qxF "$t" <<< "$listed" ;;
    esac || { echo "sanitize.sh: the TSan filter names $t, which is no test in swarf_tests" >&2; exit 1; }
  done
  echo "$(wc -l <<< "$listed") threaded tests under TSan"
  # (OMP_TOOL_LIBRARIES loads Archer into libomp; the swarf runs the tests start inherit it.
  # ignore_noninstrumented_modules: as Archer asks at start-up; without it, libomp's own
  # pthread_mutex_init and _lock, in the uninstrumented runtime, are reported as a race at the
  # first parallel region, with no frame of swarf's in either access.)
  # scripts/tsan.supp: the reports that are not swarf's (TBB's task hand-over), each explained.
  OMP_TOOL_LIBRARIES="$archer" \
    TSAN_OPTIONS="halt_on_error=1:second_deadlock_stack=1:ignore_noninstrumented_modules=1:suppressions=$PWD/scripts/tsan.supp" \
    OMP_WAIT_POLICY=PASSIVE \
    nice -n 15 build-tsan/bin/swarf_tests --gtest_filter="$tsan_filter"
fi
