#!/usr/bin/env bash
# Configures and builds swarf (Release) into build/; the program is build/bin/swarf.
set -euo pipefail
cd "$(dirname "$0")/.."
cmake -S . -B build -DCMAKE_BUILD_TYPE="${SWARF_BUILD_TYPE:-Release}" "$@"
cmake --build build -j"$(nproc)"
# The Python module (build/python/swarf): a .pth file in the site directory of Debian's
# python3 puts build/python on its path, so that 'python3 -c "import swarf"' works from
# anywhere (what 'pip install -e' does for a package in development; docs/python.md).
if [ -f build/python/swarf/__init__.py ]; then
  site=$(/usr/bin/python3 -c 'import site; print(site.getsitepackages()[0])')
  if mkdir -p "$site" 2>/dev/null && echo "$PWD/build/python" > "$site/swarf-build.pth" 2>/dev/null; then
    echo "build.sh: python3 imports swarf from $PWD/build/python ($site/swarf-build.pth)" >&2
  else
    echo "build.sh: cannot write to $site; to import swarf: export PYTHONPATH=$PWD/build/python" >&2
  fi
fi
