"""swarf: discrete element simulation of orthogonal metal cutting, from Python.

Build a case and step it, read and set the particles' and bodies' states as NumPy arrays
(views of the engine's storage, no copies), and call Python functions around every step:

    import swarf
    sim = swarf.Simulation("case.toml", set=["integrator.end_time=1e-5"])  # or text=..., or the default case
    forces = []
    sim.add_listener(after=lambda s: forces.append((s.time, *s.mesh_force("tool"))))
    sim.run()                                  # to the case's end time, as 'swarf run' steps it
    x = sim.particles.position                 # (n, 3) m, a read-only view
    summary = swarf.run("case.toml", out="results/a")  # 'swarf run' with every output file; summary.json
    r = swarf.load("results/a")                # summary, series, the frames' fields over time, chip surface

Units are SI (m, kg, s, N, Pa, J). Errors: InputError (a ValueError) names the file, key and
value; SimulationError (a RuntimeError) says where a run blew up. docs/python.md has the rest.
"""
from ._swarf import (  # noqa: F401
    Body,
    BodyCoupling,
    InputError,
    OutputError,
    Particles,
    Rods,
    RunStep,
    Simulation,
    SimulationError,
    __version__,
    default_case_text,
    set_threads,
)
from .results import ChipSurface, Frame, Run, load, run  # noqa: F401

__all__ = ["Body", "BodyCoupling", "ChipSurface", "Frame", "InputError", "OutputError", "Particles", "Rods", "Run",
           "RunStep", "Simulation", "SimulationError", "__version__", "default_case_text", "load", "run", "set_threads"]
