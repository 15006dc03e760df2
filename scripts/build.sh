#!/usr/bin/env bash
# Configures and builds swarf (Release) into build/; the program is build/bin/swarf.
set -euo pipefail
cd "$(dirname "$0")/.."
cmake -S . -B build -DCMAKE_BUILD_TYPE="${SWARF_BUILD_TYPE:-Release}" "$@"
cmake --build build -j"$(nproc)"
