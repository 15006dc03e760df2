#!/usr/bin/env bash
# Installs the dependencies, builds and runs every test (the README's test command; CI runs it).
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/install-deps.sh
./scripts/build.sh
cd build
ctest --output-on-failure -j"$(nproc)" --timeout 600
