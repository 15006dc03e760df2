#!/usr/bin/env bash
# Installs every build and run dependency of swarf from Debian 12 packages.
# Idempotent: apt skips what is already there. Needs root (or sudo).
set -euo pipefail
SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
PKGS=(
  # toolchain
  build-essential cmake g++ pkg-config git clang-format
  # numerics and I/O
  libeigen3-dev libhdf5-dev libvtk9-dev libopenvdb-dev libboost-iostreams-dev libboost-math-dev libtbb-dev
  # case files, command line, JSON, formatting
  libtomlplusplus-dev libcli11-dev nlohmann-json3-dev libfmt-dev
  # tests
  libgtest-dev
  # the Python module (src/python)
  pybind11-dev python3-dev
  # MPI (parameter studies, one run over ranks); procps: pkill for the tests that interrupt a run
  libopenmpi-dev openmpi-bin procps
  # the domains' recursive coordinate bisection over MPI ranks (Zoltan)
  libtrilinos-zoltan-dev
  # BoomerAMG (hypre) as the Newton solve's preconditioner, measured by swarf bench --preconditioner amg
  libhypre-dev
  # plots (PNG) and headless rendering
  python3 python3-numpy python3-matplotlib python3-h5py xvfb xauth
  # nearest neighbours of the chip's density (validation/cutting/compaction/chip_density.py)
  python3-scipy
)
export DEBIAN_FRONTEND=noninteractive
missing=()
for p in "${PKGS[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "install-deps: installing ${#missing[@]} packages: ${missing[*]}" >&2
  $SUDO apt-get update -qq
  $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
else
  echo "install-deps: all packages present" >&2
fi
