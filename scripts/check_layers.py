#!/usr/bin/python3
"""Fails when a source file includes across a forbidden arrow of the layers.

    python -> app -> study -> setup -> { postprocess, lattice_gen, tool_paths } -> io -> swarf (engine)

Each folder may include its own headers and those of the layers below it; includes are spelled
from their root ("swarf/...", "io/...", "lattice_gen/..."), so the first path component names
the layer. An include of a project header spelled any other way (a bare "model.h", "../x.h")
is an error too.

Inside the engine (src/swarf/) the sub-folders are floors too, each including only its own
folder and those below it (docs/architecture.md):

    core < laws < state < geometry < neighbors < {contacts, forces} < measure < systems
         < integrate < the engine's top files (simulation*, step_settings.h, step_listener.h, ...)
         < domains (one run over several domains, issue 38: it drives a Simulation per domain)

Folders on one floor (contacts, forces) may not include each other. Usage: check_layers.py
REPOSITORY_ROOT; exit 1 with the offending lines.
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
# The engine's floors: a file may include its own folder's headers and those of lower floors.
# "" is the engine's top (src/swarf/*.h, *.cpp): the step, the World, the state archive.
ENGINE_FLOOR = {"core": 0, "laws": 1, "state": 2, "geometry": 3, "neighbors": 4, "contacts": 5, "forces": 5,
                "measure": 6, "systems": 7, "integrate": 8, "": 9, "domains": 10}
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


def engine_folder(rel_in_engine: str):
    """The engine sub-folder of a path below src/swarf/ ("" for the top), or None if unknown."""
    parts = rel_in_engine.split("/")
    folder = parts[0] if len(parts) > 1 else ""
    return folder if folder in ENGINE_FLOOR else None


def engine_error(rel: pathlib.PurePosixPath, target: str):
    """Why an engine file may not include 'target' (spelled "swarf/..."), or None."""
    own = engine_folder(rel.as_posix()[len("src/swarf/"):])
    to = engine_folder(target[len("swarf/"):])
    if own is None:
        return f"{rel.parent.as_posix()}/ is not one of the engine's floors ({', '.join(k for k in ENGINE_FLOOR if k)})"
    if to is None:
        return f"\"{target}\" is not in one of the engine's floors"
    if own == to or ENGINE_FLOOR[to] < ENGINE_FLOOR[own]:
        return None
    name = lambda f: f + "/" if f else "the engine's top"
    return (f"engine {name(own)} may not include {name(to)} (\"{target}\"): the floors are "
            "core < laws < state < geometry < neighbors < {contacts, forces} < measure < systems < integrate < top < domains")


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
            elif own == "swarf" and first == "swarf" and (why := engine_error(rel, target)):
                errors.append(f"{rel}:{n}: {why}")
    for e in errors:
        print(e)
    print(f"check_layers: {len(files)} files, {len(errors)} forbidden includes")
    return 1 if errors else 0


if __name__ == "__main__":
    sys.exit(main(pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else ".").resolve()))
