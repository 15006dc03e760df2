#!/usr/bin/python3
"""The Python module against the swarf program (ctest python_module).

Environment: PYTHONPATH holds build/python (the module), SWARF_BIN is the swarf program. A short
cut of the built-in default case runs three ways: the program on 2 threads, the module's
Simulation stepped from Python on 1 thread with a step listener, and swarf.run() in this
process. The engine gives the same bits for any thread count, so every comparison is exact:
the tool's force at every series row, the final positions and velocities, the energies.
"""
import csv
import math
import os
import subprocess
import sys
import tempfile
import unittest

import h5py
import numpy as np

import swarf

SWARF = os.environ.get("SWARF_BIN", "swarf")
# 6 us of the default cut: the tool meets the workpiece at about 4 us, so the last rows carry
# contact forces; no plots (they are the program's, not the module's).
CUT = ["integrator.end_time=6e-6", "output.plots=false", "output.series_interval=2e-7",
       "output.frame_interval=1"]


def read_series(path):
    with open(path) as f:
        rows = list(csv.DictReader(f))
    return {k: np.array([float(r[k]) for r in rows]) for k in rows[0]}


class ShortCut(unittest.TestCase):
    """The default case's first 6 us: the module against the program."""

    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.TemporaryDirectory()
        cls.cli = os.path.join(cls.tmp.name, "cli")
        args = [SWARF, "run", "--out", cls.cli, "--threads", "2"]
        for s in CUT:
            args += ["--set", s]
        subprocess.run(args, check=True, stdout=subprocess.DEVNULL)
        cls.series = read_series(os.path.join(cls.cli, "series.csv"))
        with h5py.File(os.path.join(cls.cli, "results.h5")) as f:
            cls.position = f["particles/position"][...]
            cls.velocity = f["particles/velocity"][...]

        swarf.set_threads(1)
        cls.sim = swarf.Simulation(set=CUT)
        cls.force = {}  # step -> the tool's force, N

        def record(s):
            cls.force[s.steps] = s.mesh_force("tool")
        cls.sim.add_listener(after=record)
        cls.sim.run()

    @classmethod
    def tearDownClass(cls):
        cls.tmp.cleanup()

    def test_the_tool_force_at_every_series_row_is_the_programs(self):
        # (the rows are written after the step whose end passes the row's time)
        s = self.series
        self.assertGreater(np.abs(s["force_tool_x"]).max(), 1.0, "the tool should touch the workpiece")
        for k, step in enumerate(s["step"].astype(int)):
            if step == 0:
                continue
            f = self.force[step]
            self.assertEqual(f[0], s["force_tool_x"][k], f"row {k}, step {step}")
            self.assertEqual(f[2], s["force_tool_z"][k], f"row {k}, step {step}")

    def test_the_final_state_is_the_programs_bit_for_bit(self):
        p = self.sim.particles
        self.assertEqual(self.sim.steps, int(self.series["step"][-1]))
        self.assertEqual(self.sim.time, self.series["time"][-1])
        np.testing.assert_array_equal(p.position, self.position)
        np.testing.assert_array_equal(p.velocity, self.velocity)
        e = self.sim.energies()
        for key in ("kinetic_energy", "elastic_energy", "contact_energy", "external_work", "plastic_work",
                    "contact_work"):
            self.assertEqual(e[key], self.series[key][-1], key)

    def test_swarf_run_in_this_process_writes_the_programs_series(self):
        out = os.path.join(self.tmp.name, "inproc")
        swarf.run(out=out, set=CUT, threads=1)
        with open(os.path.join(out, "series.csv")) as a, open(os.path.join(self.cli, "series.csv")) as b:
            self.assertEqual(a.read(), b.read())

    def test_the_arrays_are_views_without_copies(self):
        p = self.sim.particles
        n = len(p)
        self.assertEqual(p.position.shape, (n, 3))
        self.assertTrue(np.shares_memory(p.position, self.sim.particles.position))
        self.assertFalse(p.position.flags.writeable)
        with self.assertRaises(ValueError):
            p.position[0, 0] = 1.0
        self.assertEqual(len(self.sim.rods), self.sim.rods.ends.shape[0])
        self.assertTrue((self.sim.rods.ends[:, 0] < self.sim.rods.ends[:, 1]).all())
        self.assertEqual(self.sim.workpiece_particles, n)
        self.assertAlmostEqual(float(p.mass.sum()) / n, float(p.mass[0]), delta=1e-9 * float(p.mass[0]))
        self.assertEqual(self.sim.mesh_names, ["tool"])


TWO = """
[material]
density = 2800.0
[[particle]]
position = [0.0, 0.0, 0.0]
radius = 0.01
[[particle]]
position = [{x}, 0.0, 0.0]
velocity = [{v}, 0.0, 0.0]
radius = 0.01
[contact]
youngs_modulus = 48e9
poisson_ratio = 0.2
restitution = 1.0
friction = 0.0
[integrator]
scheme = "verlet"
dt = 1e-7
end_time = 1e-4
"""


class TwoSpheres(unittest.TestCase):
    def test_velocity_set_in_place_is_integrated(self):
        # Free flight under velocity Verlet with no force: x+ = x + h v, exactly what the
        # scheme's recurrence gives, to rounding (1e-15 m on 0.1 m).
        sim = swarf.Simulation(text=TWO.format(x=0.1, v=0.0))
        v = sim.particles.velocity
        v[1, 0] = 2.0  # m/s, in place
        for _ in range(10):
            sim.step()
        self.assertAlmostEqual(sim.particles.position[1, 0], 0.1 + 10 * 1e-7 * 2.0, delta=1e-15)
        self.assertEqual(sim.particles.position[0, 0], 0.0)

    def test_set_positions_finds_the_new_contact(self):
        # The spheres start 0.1 m apart (no pair in the contact lists); moved by hand to an
        # overlap of 1 um, far beyond the lists' skin, the next step must find the contact and
        # push them apart with Hertz's force,
        # F = 4/3 E* sqrt(R*) d^1.5 (E* = E / (2 (1 - nu^2)), R* = R/2) to the step's change of d.
        sim = swarf.Simulation(text=TWO.format(x=0.1, v=0.0))
        sim.step()
        x = np.array(sim.particles.position)
        x[1, 0] = 0.02 - 1e-6
        sim.set_positions(x)
        sim.step()
        f = sim.particles.force
        e_star = 48e9 / (2 * (1 - 0.2 ** 2))
        hertz = 4.0 / 3.0 * e_star * math.sqrt(0.005) * (1e-6) ** 1.5
        self.assertLess(f[0, 0], 0.0)
        self.assertGreater(f[1, 0], 0.0)
        self.assertAlmostEqual(f[1, 0] / hertz, 1.0, delta=0.02)

    def test_listeners_run_around_each_step_and_can_be_removed(self):
        sim = swarf.Simulation(text=TWO.format(x=0.1, v=1.0))
        seen = []
        h = sim.add_listener(before=lambda s: seen.append(("b", s.steps)), after=lambda s: seen.append(("a", s.steps)))
        sim.step()
        sim.step()
        self.assertEqual(seen, [("b", 0), ("a", 1), ("b", 1), ("a", 2)])
        sim.remove_listener(h)
        sim.step()
        self.assertEqual(len(seen), 4)

        def fail(s):
            raise ZeroDivisionError("from the listener")
        sim.add_listener(after=fail)
        with self.assertRaises(ZeroDivisionError):
            sim.step()
        self.assertEqual(sim.steps, 4)  # (the step was taken; after() came after it)

    def test_a_checkpoint_continues_bit_identically(self):
        with tempfile.TemporaryDirectory() as tmp:
            # The spheres close their gap of 0.5 mm at 50 m/s in 10 us: the checkpoint at 8 us
            # comes before the contact, the end at 40 us after it.
            a = swarf.Simulation(text=TWO.format(x=0.0205, v=-50.0))
            a.run(until=8e-6)
            a.write_checkpoint(os.path.join(tmp, "c.h5"))
            t, h = a.time, a.state_hash()
            a.run(until=4e-5)
            # (equal masses, nearly elastic: the moving sphere hands its momentum on)
            self.assertLess(a.particles.velocity[0, 0], -40.0, "the spheres should have met")
            b = swarf.Simulation.from_checkpoint(os.path.join(tmp, "c.h5"))
            self.assertEqual((b.time, b.state_hash()), (t, h))
            b.run(until=4e-5)
            self.assertEqual(a.state_hash(), b.state_hash())
            np.testing.assert_array_equal(a.particles.position, b.particles.position)


HELD_PLATE = """
[material]
density = 2800.0
[[particle]]
position = [0.0, 0.0, 0.004]
velocity = [0.0, 0.0, -10.0]
radius = 0.002
[contact]
youngs_modulus = 1e9
poisson_ratio = 0.3
restitution = 0.8
friction = 0.0
[[mesh]]
name = "plate"
box_size = [0.02, 0.02, 0.002]
origin = [0.0, 0.0, -0.001]
dynamics = "rigid_body"
density = 7800.0
fixed = "xyz"
rotation = "prescribed"
[integrator]
scheme = "verlet"
end_time = 1e-3
"""


class Coupling(unittest.TestCase):
    def test_the_impulse_handed_over_is_the_spheres_momentum_change(self):
        # A sphere bounces off a plate whose motion an outside code owns (here: it holds it
        # still). Momentum crosses the interface exactly: the impulses the exchanges report
        # add up to minus the sphere's momentum change, to rounding (1e-12 of it).
        sim = swarf.Simulation(text=HELD_PLATE)
        c = sim.couple_body(0)
        m = float(sim.particles.mass[0])
        p0 = m * np.array(sim.particles.velocity[0])
        impulse = np.zeros(3)
        x = sim.bodies[0].position
        for _ in range(100):
            ex = c.advance(x, 5e-6)
            impulse += ex["impulse"]
            self.assertGreater(ex["steps"], 0)
        p1 = m * np.array(sim.particles.velocity[0])
        self.assertGreater(p1[2], 0.0, "the sphere should have bounced")
        np.testing.assert_allclose(p1 - p0, -impulse, rtol=0, atol=1e-12 * np.abs(p1 - p0).max())
        with self.assertRaises(swarf.InputError):
            c.advance(x, -1.0)


class Errors(unittest.TestCase):
    def test_bad_input_names_the_key(self):
        with self.assertRaises(swarf.InputError) as e:
            swarf.Simulation(text="[integrator]\nbogus_key = 1\n")
        self.assertIn("bogus_key", str(e.exception))
        self.assertTrue(issubclass(swarf.InputError, ValueError))
        with self.assertRaises(swarf.InputError):
            swarf.Simulation("/nonexistent/case.toml")
        with self.assertRaises(swarf.InputError):
            swarf.set_threads(0)
        with self.assertRaises(ValueError):
            swarf.Simulation(text=TWO.format(x=0.1, v=0.0)).set_positions(np.zeros((3, 3)))

    def test_the_version_is_the_programs(self):
        out = subprocess.run([SWARF, "--version"], capture_output=True, text=True, check=True).stdout
        self.assertIn(swarf.__version__, out)


if __name__ == "__main__":
    unittest.main(verbosity=2)
