#!/usr/bin/env bash
# Fails (exit 1) when a C++ source of the tree is not formatted as .clang-format says, and
# lists the files. Usage: scripts/check_format.sh [ROOT]; fix with: clang-format -i FILES.
# Debian 12's clang-format (14) is the reference: another version may format differently.
set -euo pipefail
root=$(cd "${1:-$(dirname "$0")/..}" && pwd)
cd "$root"
if ! command -v clang-format >/dev/null; then
  echo "check_format: clang-format is not installed (scripts/install-deps.sh installs it)" >&2
  exit 1
fi
if git rev-parse --is-inside-work-tree >/dev/null 2>&1; then
  mapfile -t files < <(git ls-files '*.cpp' '*.h' | grep -v '^tests/data/')
else
  mapfile -t files < <(find src lattice_gen tool_paths postprocess tests validation examples \( -name '*.cpp' -o -name '*.h' \) -not -path 'tests/data/*' | sort)
fi
bad=()
for f in "${files[@]}"; do
  [ -f "$f" ] || continue
  clang-format --dry-run --Werror "$f" >/dev/null 2>&1 || bad+=("$f")
done
if [ ${#bad[@]} -gt 0 ]; then
  echo "check_format: ${#bad[@]} of ${#files[@]} files are not formatted (clang-format -i them):"
  printf '  %s\n' "${bad[@]}"
  exit 1
fi
echo "check_format: ${#files[@]} files formatted"
