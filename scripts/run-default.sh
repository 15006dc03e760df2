#!/usr/bin/env bash
# Installs the dependencies, builds and runs the built-in default case into results/default.
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/install-deps.sh
./scripts/build.sh
./build/bin/swarf run --out results/default "$@"
