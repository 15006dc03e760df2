#!/usr/bin/env python3
"""test_render.py: ctest 'render_chip': postprocess/render_chip.py on a tiny synthetic run directory.

Writes 5 x 2 x 4 particles (radius, broken_fraction rising along x, plastic_strain falling
along x, velocity, displacement, group; no von_mises_stress) and one fragment flung 400 radii
away as frames/particles_00000.vtu and particles_00001.vtu, a one-triangle 'tool' for frame 1
and a particles.pvd, renders under xvfb-run at 320 x 240 and checks: exit code 0, 'wrote'
printed for the damage and the plastic strain pictures, the von Mises picture skipped with a
note (the frame lacks the field), each PNG with exactly the requested size and more than one
colour (not a blank image), and the blue-to-red colour map shows (some pixels red-dominant,
some blue-dominant: the view is on the cut, so the particles are many pixels wide, not dots
in a view stretched to the fragment).
Also: a directory without frames exits non-zero with a message naming frames/.
Usage: test_render.py PATH/TO/render_chip.py. Exit 77 (skipped) without xvfb-run or vtk.
"""
import json
import os
import shutil
import subprocess
import sys
import tempfile

SKIP = 77


def main():
    script = sys.argv[1]
    xvfb = shutil.which("xvfb-run")
    if not xvfb:
        print("SKIP: xvfb-run not found (package xvfb)")
        return SKIP
    try:
        import vtk
        from vtk.util.numpy_support import vtk_to_numpy
        import numpy as np
    except ImportError as e:
        print("SKIP: no vtk module for %s: %s" % (sys.executable, e))
        return SKIP

    tmp = tempfile.mkdtemp(prefix="swarf_test_render_")
    try:
        run = os.path.join(tmp, "run")
        os.makedirs(os.path.join(run, "frames"))
        R = 1e-4
        pts = vtk.vtkPoints()
        pts.SetDataTypeToDouble()
        radius, frac, plastic, vel, disp = (vtk.vtkDoubleArray() for _ in range(5))
        group = vtk.vtkIntArray()
        for arr, name, nc in ((radius, "radius", 1), (frac, "broken_fraction", 1), (plastic, "plastic_strain", 1),
                              (vel, "velocity", 3), (disp, "displacement", 3), (group, "group", 1)):
            arr.SetName(name)
            arr.SetNumberOfComponents(nc)
        nx = 5
        for i in range(nx):
            for j in range(2):
                for k in range(4):
                    pts.InsertNextPoint(2 * R * i, 2 * R * j, 2 * R * k)
                    radius.InsertNextValue(R)
                    frac.InsertNextValue(i / (nx - 1))
                    plastic.InsertNextValue(0.3 * (nx - 1 - i) / (nx - 1))
                    vel.InsertNextTuple3(0, 0, 0)
                    disp.InsertNextTuple3(0, 0, 0)
                    group.InsertNextValue(0)
        pts.InsertNextPoint(400 * R, 0, 200 * R)  # a fragment flung far away
        for arr, v in ((radius, R), (frac, 1.0), (plastic, 0.0)):
            arr.InsertNextValue(v)
        vel.InsertNextTuple3(0, 0, 0)
        disp.InsertNextTuple3(0, 0, 0)
        group.InsertNextValue(0)
        grid = vtk.vtkUnstructuredGrid()
        grid.SetPoints(pts)
        for p in range(pts.GetNumberOfPoints()):
            grid.InsertNextCell(vtk.VTK_VERTEX, 1, [p])
        for arr in (radius, frac, plastic, vel, disp, group):
            grid.GetPointData().AddArray(arr)
        for f in (0, 1):
            w = vtk.vtkXMLUnstructuredGridWriter()
            w.SetFileName(os.path.join(run, "frames", "particles_%05d.vtu" % f))
            w.SetInputData(grid)
            assert w.Write() == 1
        tool = vtk.vtkPolyData()
        tp = vtk.vtkPoints()
        for p in ((-4 * R, -R, 3 * R), (-2 * R, -R, 10 * R), (-4 * R, 3 * R, 10 * R)):
            tp.InsertNextPoint(*p)
        tool.SetPoints(tp)
        cells = vtk.vtkCellArray()
        cells.InsertNextCell(3, [0, 1, 2])
        tool.SetPolys(cells)
        w = vtk.vtkXMLPolyDataWriter()
        w.SetFileName(os.path.join(run, "frames", "mesh_tool_00001.vtp"))
        w.SetInputData(tool)
        assert w.Write() == 1
        with open(os.path.join(run, "particles.pvd"), "w") as f:
            f.write('<?xml version="1.0"?>\n<VTKFile type="Collection" version="0.1">\n  <Collection>\n'
                    '    <DataSet timestep="0" group="" part="0" name="particles" file="frames/particles_00000.vtu"/>\n'
                    '    <DataSet timestep="2.5e-05" group="" part="0" name="particles" file="frames/particles_00001.vtu"/>\n'
                    '  </Collection>\n</VTKFile>\n')

        out = os.path.join(tmp, "picture.png")
        cmd = [xvfb, "-a", "-s", "-screen 0 1280x1024x24", sys.executable, script, run, out, "--size", "320x240"]
        r = subprocess.run(cmd, capture_output=True, text=True, timeout=120)
        print(r.stdout, r.stderr)
        ok = True

        def check(cond, what):
            nonlocal ok
            print(("ok: " if cond else "FAILED: ") + what)
            ok = ok and cond

        check(r.returncode == 0, "render_chip.py exits 0 (got %d)" % r.returncode)
        check("no point data 'von_mises_stress'" in r.stderr, "the von Mises picture skipped with a note")
        check(not os.path.exists(os.path.join(tmp, "picture_von_mises_stress.png")), "no von Mises picture")
        with open(os.path.join(os.path.dirname(os.path.abspath(script)), "chip_view.json")) as f:
            view = json.load(f)
        maps = {fd["field"]: view["colour_maps"][fd["colour_map"]] for fd in view["fields"]}
        for png, field in ((out, "broken_fraction"), (os.path.join(tmp, "picture_plastic_strain.png"), "plastic_strain")):
            check(("wrote " + png) in r.stdout, "prints 'wrote %s'" % png)
            check(os.path.exists(png), "the PNG exists")
            if not os.path.exists(png):
                continue
            rd = vtk.vtkPNGReader()
            rd.SetFileName(png)
            rd.Update()
            img = rd.GetOutput()
            dims = img.GetDimensions()
            check(dims[0] == 320 and dims[1] == 240, "size 320 x 240 (got %d x %d)" % (dims[0], dims[1]))
            a = vtk_to_numpy(img.GetPointData().GetScalars())
            a = a.reshape(-1, a.shape[-1] if a.ndim > 1 else 1)[:, :3].astype(int)
            colours = {tuple(c) for c in a[:: max(1, len(a) // 20000)]}
            check(len(colours) > 1, "more than one colour (%d sampled)" % len(colours))
            # The colour map's two ends (chip_view.json), as the lit spheres shade them: pixels whose
            # colour points the end's way in RGB (cosine > 0.985; the white background, the grey
            # tool and the other end stay below 0.95) and at least a third as bright.
            def near(end):
                e = np.array(end) * 255.0
                norm = np.linalg.norm(a, axis=1)
                cos = (a @ e) / np.maximum(norm * np.linalg.norm(e), 1e-9)
                return int(((cos > 0.985) & (norm > np.linalg.norm(e) / 3.0)).sum())
            high, low = near(maps[field][-1]), near(maps[field][0])
            check(high > 200 and low > 200, "the map's high and low ends (%s) show large, the view on the cut "
                  "(%d, %d pixels)" % (field, high, low))

        # From above (--view top): the plastic strain's picture, its map's two ends in view.
        top = os.path.join(tmp, "top.png")
        r = subprocess.run(cmd[:-3] + [top, "--size", "320x240", "--view", "top", "--fields", "plastic_strain"],
                           capture_output=True, text=True, timeout=120)
        print(r.stdout, r.stderr)
        png = os.path.join(tmp, "top_plastic_strain.png")
        check(r.returncode == 0 and ("wrote " + png) in r.stdout,
              "--view top renders %s (exit %d)" % (png, r.returncode))
        if os.path.exists(png):
            rd = vtk.vtkPNGReader()
            rd.SetFileName(png)
            rd.Update()
            a = vtk_to_numpy(rd.GetOutput().GetPointData().GetScalars())[:, :3].astype(int)
            ends = [maps["plastic_strain"][k] for k in (0, -1)]
            counts = []
            for end in ends:
                e = np.array(end) * 255.0
                norm = np.linalg.norm(a, axis=1)
                cos = (a @ e) / np.maximum(norm * np.linalg.norm(e), 1e-9)
                counts.append(int(((cos > 0.985) & (norm > np.linalg.norm(e) / 3.0)).sum()))
            check(min(counts) > 200, "the top view shows both ends of the map large (%s pixels)" % counts)

        empty = os.path.join(tmp, "empty")
        os.makedirs(empty)
        r = subprocess.run([sys.executable, script, empty], capture_output=True, text=True, timeout=60)
        check(r.returncode != 0 and "frames" in r.stderr, "no frames: non-zero exit and a message (%d: %s)"
              % (r.returncode, r.stderr.strip()))
        return 0 if ok else 1
    finally:
        shutil.rmtree(tmp, ignore_errors=True)


if __name__ == "__main__":
    sys.exit(main())
