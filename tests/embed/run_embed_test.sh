#!/usr/bin/env bash
# run_embed_test.sh: swarf's engine used the way another project uses it (ctest embed_example).
#
# 1. installs the build tree into a temporary prefix (cmake --install);
# 2. checks that every header under src/swarf was installed and that each installed header
#    compiles on its own (twice in one file: the include guard) against swarf::engine;
# 3. configures examples/embed in a build directory of its own against that prefix only
#    (find_package(swarf) must resolve there) and builds it;
# 4. runs it: its exit code is its physical checks' verdict.
# Any failing stage stops the test with its log. The temporary directory is removed on
# success and kept (its path printed) on failure.
#
# Usage: run_embed_test.sh CMAKE SOURCE_DIR BUILD_DIR CXX_COMPILER [CONFIG]
set -euo pipefail
if [ $# -lt 4 ]; then
  echo "usage: $0 CMAKE SOURCE_DIR BUILD_DIR CXX_COMPILER [CONFIG]" >&2
  exit 2
fi
cmake_bin=$1 src=$2 build=$3 cxx=$4 config=${5:-}
# The install must run for the configuration that was built (its exported targets file is
# per configuration); without one, cmake --install takes the build tree's own.
install_config=()
[ -z "$config" ] || install_config=(--config "$config")

work=$(mktemp -d "${TMPDIR:-/tmp}/swarf-embed.XXXXXX")
passed=0
trap 'if [ "$passed" = 1 ]; then rm -rf "$work"; else echo "embed test: kept $work for inspection" >&2; fi' EXIT
stage() { echo "== embed test: $*"; }
fail() {
  echo "embed test: FAILED: $1" >&2
  if [ $# -gt 1 ] && [ -f "$2" ]; then tail -n 60 "$2" >&2; fi
  exit 1
}
prefix=$work/prefix
# Only the prefix may provide swarf: no package registry, and the build tree is not exported.
configure() {  # SOURCE BINARY LOG
  "$cmake_bin" -S "$1" -B "$2" -DCMAKE_BUILD_TYPE="${config:-Release}" -DCMAKE_CXX_COMPILER="$cxx" \
    -DCMAKE_PREFIX_PATH="$prefix" -DCMAKE_FIND_PACKAGE_NO_PACKAGE_REGISTRY=ON >"$3" 2>&1
}
found_in_prefix() {  # BINARY: swarf_DIR in its cache lies under the prefix
  local dir
  dir=$(sed -n 's/^swarf_DIR:[A-Z]*=//p' "$1/CMakeCache.txt")
  case "$dir" in "$prefix"/*) ;; *) fail "find_package(swarf) found '$dir', not the prefix $prefix" ;; esac
}

stage "install $build into $prefix"
"$cmake_bin" --install "$build" --prefix "$prefix" "${install_config[@]}" >"$work/install.log" 2>&1 ||
  fail "cmake --install $build" "$work/install.log"

stage "every engine header installed, each compiles alone"
(cd "$src/src/swarf" && find . -name '*.h' | sort) >"$work/source_headers.txt"
(cd "$prefix/include/swarf" && find . -name '*.h' ! -path ./version.h | sort) >"$work/installed_headers.txt"
diff "$work/source_headers.txt" "$work/installed_headers.txt" >"$work/headers.diff" ||
  fail "installed headers differ from src/swarf (< source only, > installed only)" "$work/headers.diff"
[ -f "$prefix/include/swarf/version.h" ] || fail "the generated swarf/version.h was not installed"
mkdir -p "$work/headers"
n=0
while IFS= read -r h; do
  n=$((n + 1))
  printf '#include <%s>\n#include <%s>\n' "$h" "$h" >"$work/headers/h$n.cpp"
done < <(cd "$prefix/include" && find swarf -name '*.h' | sort)
cat >"$work/headers/CMakeLists.txt" <<'EOF'
cmake_minimum_required(VERSION 3.22)
project(swarf_headers CXX)
find_package(swarf REQUIRED)
file(GLOB sources ${CMAKE_CURRENT_SOURCE_DIR}/*.cpp)
add_library(headers OBJECT ${sources})
target_link_libraries(headers PRIVATE swarf::engine)
EOF
configure "$work/headers" "$work/headers-build" "$work/headers-configure.log" ||
  fail "configuring the header check against the prefix" "$work/headers-configure.log"
found_in_prefix "$work/headers-build"
"$cmake_bin" --build "$work/headers-build" --parallel 2 >"$work/headers-build.log" 2>&1 ||
  fail "an installed header does not compile on its own" "$work/headers-build.log"
echo "$n headers"

stage "configure and build examples/embed against the prefix"
configure "$src/examples/embed" "$work/example" "$work/example-configure.log" ||
  fail "configuring examples/embed (find_package(swarf) in $prefix)" "$work/example-configure.log"
found_in_prefix "$work/example"
"$cmake_bin" --build "$work/example" --parallel 2 >"$work/example-build.log" 2>&1 ||
  fail "building examples/embed" "$work/example-build.log"

stage "run the example"
set +e
"$work/example/embed"
rc=$?
set -e
[ "$rc" = 0 ] || fail "examples/embed exited with code $rc"
passed=1
stage "passed"
