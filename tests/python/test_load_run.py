#!/usr/bin/python3
"""swarf.run and swarf.load on a finished run (ctest python_load_run).

Environment: PYTHONPATH holds build/python (the module). The built-in default cut's first 6 us
(the tool meets the workpiece at about 4 us) runs through swarf.run() with frames every 2 us;
swarf.load reads it back and every value is compared with the file it comes from, by exact
equality: the loader copies the stored doubles (CSV text parsed by the same float(), HDF5
float64 read as float64). The Simulation's field properties are compared with results.h5 after
stepping the same case in this process: the engine gives the same bits (python_module checks
the state), and the fields are the same function of it, so equality is exact there too.
"""
import csv
import glob
import json
import os
import tempfile
import unittest

import h5py
import numpy as np

import swarf

CUT = ["integrator.end_time=6e-6", "output.plots=false", "output.series_interval=2e-7",
       "output.frame_interval=2e-6", "output.vtk=true"]


class LoadRun(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.TemporaryDirectory()
        cls.dir = os.path.join(cls.tmp.name, "run")
        swarf.set_threads(1)
        cls.force = {}  # step -> the tool's force after it, N (a listener of swarf.run)

        def record(step):
            cls.force[step.steps] = (step.time, step.mesh_force("tool"))
        cls.summary = swarf.run(out=cls.dir, set=CUT, threads=1, after=record)
        cls.loaded = swarf.load(cls.dir)

    @classmethod
    def tearDownClass(cls):
        cls.tmp.cleanup()

    def test_run_returns_the_summary(self):
        with open(os.path.join(self.dir, "summary.json")) as f:
            self.assertEqual(self.summary, json.load(f))
        self.assertEqual(self.summary["status"], "completed")
        self.assertEqual(self.loaded.summary, self.summary)

    def test_a_listener_of_run_sees_every_step(self):
        # The series' rows are written after the step whose end passes the row's time: at those
        # steps the listener saw the very time and force the row holds.
        s = self.loaded.series
        self.assertEqual(max(self.force), int(s["step"][-1]))
        self.assertGreater(np.abs(s["force_tool_x"]).max(), 1.0, "the tool should touch the workpiece")
        for k, step in enumerate(s["step"].astype(int)):
            if step == 0:
                continue
            t, f = self.force[step]
            self.assertEqual(t, s["time"][k])
            self.assertEqual(f[0], s["force_tool_x"][k], f"row {k}")
            self.assertEqual(f[2], s["force_tool_z"][k], f"row {k}")

    def test_series_is_series_csv(self):
        with open(os.path.join(self.dir, "series.csv")) as f:
            rows = list(csv.reader(f))
        s = self.loaded.series
        self.assertEqual(list(s.dtype.names), rows[0])
        self.assertEqual(len(s), len(rows) - 1)
        for j, name in enumerate(rows[0]):
            np.testing.assert_array_equal(s[name], [float(r[j]) for r in rows[1:]], err_msg=name)
        self.assertEqual(self.loaded.units["time"], "s")
        try:
            import pandas  # noqa: F401
        except ImportError:
            with self.assertRaises(ImportError):
                self.loaded.dataframe()
        else:
            np.testing.assert_array_equal(self.loaded.dataframe()["time"].to_numpy(), s["time"])

    def test_frames_are_results_h5s_and_the_vtu_frames(self):
        r = self.loaded
        vtu = sorted(glob.glob(os.path.join(self.dir, "frames", "particles_*.vtu")))
        self.assertEqual(len(r.times), len(vtu))
        self.assertEqual(len(r.times), 4, "0, 2, 4, 6 us")
        np.testing.assert_array_equal(r.times, [f.time for f in r.frames])
        self.assertEqual(r.times[0], 0.0)
        self.assertEqual(r.times[-1], self.loaded.series["time"][-1])
        with h5py.File(os.path.join(self.dir, "results.h5")) as h:
            last = r.frame(-1)
            g = h["frames"]["%05d" % (len(r.times) - 1)]
            np.testing.assert_array_equal(last.position, g["position"][...])
            for name, v in last.fields.items():
                np.testing.assert_array_equal(v, g[name][...], err_msg=name)
            # The last frame is the final state, row by row as /particles (same ids in the same order).
            np.testing.assert_array_equal(last.id, h["particles/id"][...])
            np.testing.assert_array_equal(last.position, h["particles/position"][...])
            np.testing.assert_array_equal(last.fields["von_mises_stress"], h["particles/von_mises_stress"][...])
        self.assertEqual(last.units["stress"], "Pa")
        self.assertEqual(last.units["position"], "m")
        self.assertEqual(last.fields["stress"].shape, (len(last.id), 6))
        for f in r.frames:
            self.assertEqual(sorted(f.id), sorted(r.frame(0).id))
        self.assertEqual(len(r.field("temperature")), len(r.times))
        self.assertEqual(r.frame_at(4.1e-6).number, 2)

    def test_surface_reader_matches_vtk(self):
        # The chip surface is written only once a chip has formed (not in 6 us); the tool's frames
        # come from the same writer (write_vtp), so the reader is checked on one of them.
        self.assertIsNone(self.loaded.chip_surface)
        path = sorted(glob.glob(os.path.join(self.dir, "frames", "mesh_tool_*.vtp")))[-1]
        s = swarf.ChipSurface(path)
        self.assertGreater(len(s.triangles), 0)
        try:
            import vtk
            from vtk.util.numpy_support import vtk_to_numpy
        except ImportError:
            self.skipTest("no Python vtk to compare with")
        rd = vtk.vtkXMLPolyDataReader()
        rd.SetFileName(path)
        rd.Update()
        pd = rd.GetOutput()
        np.testing.assert_array_equal(s.points, vtk_to_numpy(pd.GetPoints().GetData()))
        np.testing.assert_array_equal(s.triangles.ravel(), vtk_to_numpy(pd.GetPolys().GetConnectivityArray()))

    def test_simulation_fields_are_the_runs(self):
        sim = swarf.Simulation(set=CUT)
        sim.run()
        p = sim.particles
        with h5py.File(os.path.join(self.dir, "results.h5")) as h:
            np.testing.assert_array_equal(p.position, h["particles/position"][...])
            np.testing.assert_array_equal(p.stress, h["particles/stress"][...])
            np.testing.assert_array_equal(p.von_mises_stress, h["particles/von_mises_stress"][...])
            np.testing.assert_array_equal(p.hydrostatic_stress, h["particles/hydrostatic_stress"][...])
            np.testing.assert_array_equal(p.plastic_strain, h["particles/plastic_strain"][...])
            if "particles/temperature" in h:
                np.testing.assert_array_equal(p.temperature, h["particles/temperature"][...])
        self.assertEqual(p.stress.shape, (len(p), 6))
        self.assertGreater(np.abs(p.von_mises_stress).max(), 0.0)

    def test_load_refuses_an_unfinished_run(self):
        with tempfile.TemporaryDirectory() as d:
            with self.assertRaises(FileNotFoundError):
                swarf.load(d)


if __name__ == "__main__":
    unittest.main(verbosity=2)
