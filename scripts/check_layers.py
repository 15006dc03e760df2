#!/usr/bin/python3
"""Fails when a source file includes across a forbidden arrow of the layers.

    python -> app -> study -> setup -> { postprocess, lattice_gen, tool_paths } -> io -> swarf (engine)

Each folder may include its own headers and those of the layers below it; includes are spelled
from their root ("swarf/...", "io/...", "lattice_gen/..."), so the first path component names
the layer. An include of a project header spelled any other way (a bare "model.h", "../x.h")
is an error too. Usage: check_layers.py REPOSITORY_ROOT; exit 1 with the offending lines.
"""
import pathlib
import re
import sys

BELOW = {
    "swarf": set(),
    "io": {"swarf"},
    "lattice_gen": {"io", "swarf"},
    "tool_paths": {"io", "swarf"},
    "postprocess": {"io", "swarf"},
    "setup": {"postprocess", "lattice_gen", "tool_paths", "io", "swarf"},
    "study": {"setup", "postprocess", "lattice_gen", "tool_paths", "io", "swarf"},
    "app": {"study", "setup", "postprocess", "lattice_gen", "tool_paths", "io", "swarf"},
    "python": {"app", "study", "setup", "postprocess", "lattice_gen", "tool_paths", "io", "swarf"},
}
# Folders above every layer: they may include any layer's headers (and their own by bare name).
TOP = {"tests", "validation", "examples"}
ROOTS = {"swarf": "src/swarf", "io": "src/io", "setup": "src/setup", "study": "src/study",
         "app": "src/app", "python": "src/python", "lattice_gen": "lattice_gen", "tool_paths": "tool_paths",
         "postprocess": "postprocess"}
INCLUDE = re.compile(r'^\s*#\s*include\s*"([^"]+)"')
SYSTEM = re.compile(r'^\s*#\s*include\s*<([^>]+)>')
# Libraries the engine must not see (it uses Eigen, OpenMP, fmt and the standard library).
NOT_IN_ENGINE = re.compile(r'^(toml|hdf5|H5|vtk|nlohmann|openvdb|CLI|mpi|gtest|pybind11)', re.IGNORECASE)


def layer_of(rel: pathlib.PurePosixPath):
    s = rel.as_posix()
    for name, root in ROOTS.items():
        if s.startswith(root + "/"):
            return name
    return None


def main(root: pathlib.Path) -> int:
    errors = []
    files = [p for ext in ("*.h", "*.cpp", "*.in") for p in root.rglob(ext)]
    for path in sorted(files):
        rel = pathlib.PurePosixPath(path.relative_to(root).as_posix())
        if rel.parts[0] in ("build",) or rel.parts[0].startswith("."):
            continue
        own = layer_of(rel)
        if own is None and rel.parts[0] not in TOP:
            continue
        for n, line in enumerate(path.read_text(errors="replace").splitlines(), 1):
            sm = SYSTEM.match(line)
            if sm and own == "swarf" and NOT_IN_ENGINE.match(sm.group(1)):
                errors.append(f"{rel}:{n}: the engine may not include <{sm.group(1)}> "
                              f"(Eigen, OpenMP, fmt and the standard library only)")
            m = INCLUDE.match(line)
            if not m:
                continue
            target = m.group(1)
            first = target.split("/")[0]
            if own is None:  # tests, validation, examples (their own headers by relative path)
                if first in ROOTS or "/" not in target or (path.parent / target).exists():
                    continue
                errors.append(f"{rel}:{n}: include \"{target}\" is not spelled from a layer's root")
                continue
            if first not in ROOTS:
                errors.append(f"{rel}:{n}: include \"{target}\" is not spelled from a layer's root "
                              f"(swarf/, io/, lattice_gen/, tool_paths/, postprocess/, setup/, study/, app/)")
            elif first != own and first not in BELOW[own]:
                errors.append(f"{rel}:{n}: {own}/ may not include {first}/ (\"{target}\"): "
                              f"{own} may include only {', '.join(sorted(BELOW[own]) + [own])}")
    for e in errors:
        print(e)
    print(f"check_layers: {len(files)} files, {len(errors)} forbidden includes")
    return 1 if errors else 0


if __name__ == "__main__":
    sys.exit(main(pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else ".").resolve()))
