#!/usr/bin/python3
"""Renders frames of a swarf run to PNG: particles as spheres coloured by their speed |v| (m/s),
the meshes grey, seen obliquely from above. Run under xvfb-run (Debian's VTK needs an X server).

Usage: xvfb-run -a -s "-screen 0 1600x1200x24" render_speed.py RUN_DIR OUT.png FRAME [FRAME ...]
(several frames become panels side by side; the colour scale is shared, 0 to the largest speed
of the frames shown).
"""
import os
import sys
import xml.etree.ElementTree as ET

import vtk
from vtk.util.numpy_support import numpy_to_vtk, vtk_to_numpy


def frame_files(run_dir):
    root = ET.parse(os.path.join(run_dir, "particles.pvd")).getroot()
    frames = {}
    for ds in root.iter("DataSet"):
        t = float(ds.get("timestep"))
        frames.setdefault(t, {})[ds.get("name")] = os.path.join(run_dir, ds.get("file"))
    return sorted(frames.items())


def read(path):
    r = vtk.vtkXMLUnstructuredGridReader() if path.endswith(".vtu") else vtk.vtkXMLPolyDataReader()
    r.SetFileName(path)
    r.Update()
    return r.GetOutput()


def main():
    run_dir, out = sys.argv[1], sys.argv[2]
    wanted = [int(a) for a in sys.argv[3:]] or [-1]
    frames = frame_files(run_dir)
    chosen = [frames[k] for k in wanted]
    grids = []
    vmax = 0.0
    for t, parts in chosen:
        g = read(parts["particles"])
        v = vtk_to_numpy(g.GetPointData().GetArray("velocity"))
        speed = (v ** 2).sum(axis=1) ** 0.5
        vmax = max(vmax, float(speed.max()))
        arr = numpy_to_vtk(speed, deep=True)
        arr.SetName("speed")
        g.GetPointData().AddArray(arr)
        g.GetPointData().SetActiveScalars("speed")
        grids.append((t, g, parts))
    lut = vtk.vtkLookupTable()
    lut.SetHueRange(0.667, 0.0)
    lut.SetTableRange(0.0, vmax)
    lut.Build()

    win = vtk.vtkRenderWindow()
    win.SetOffScreenRendering(1)
    cols = len(grids) if len(grids) <= 2 else (len(grids) + 1) // 2
    rows = (len(grids) + cols - 1) // cols
    win.SetSize(720 * cols, 620 * rows)
    for n, (t, g, parts) in enumerate(grids):
        ren = vtk.vtkRenderer()
        c, r = n % cols, rows - 1 - n // cols
        ren.SetViewport(c / cols, r / rows, (c + 1) / cols, (r + 1) / rows)
        ren.SetBackground(1, 1, 1)
        sphere = vtk.vtkSphereSource()
        sphere.SetThetaResolution(8)
        sphere.SetPhiResolution(6)
        glyph = vtk.vtkGlyph3D()
        glyph.SetInputData(g)
        glyph.SetSourceConnection(sphere.GetOutputPort())
        glyph.SetScaleModeToDataScalingOff()
        radius = vtk_to_numpy(g.GetPointData().GetArray("radius"))[0]
        glyph.SetScaleFactor(2 * radius)
        glyph.SetColorModeToColorByScalar()
        glyph.SetInputArrayToProcess(3, 0, 0, 0, "speed")
        m = vtk.vtkPolyDataMapper()
        m.SetInputConnection(glyph.GetOutputPort())
        m.SetLookupTable(lut)
        m.SetScalarRange(0.0, vmax)
        m.SetScalarModeToUsePointFieldData()
        m.SelectColorArray("speed")
        a = vtk.vtkActor()
        a.SetMapper(m)
        ren.AddActor(a)
        for name, path in parts.items():
            if name in ("particles", "rods") or not path.endswith(".vtp"):
                continue
            mm = vtk.vtkPolyDataMapper()
            mm.SetInputData(read(path))
            mm.ScalarVisibilityOff()
            ma = vtk.vtkActor()
            ma.SetMapper(mm)
            ma.GetProperty().SetColor(0.75, 0.75, 0.75)
            ren.AddActor(ma)
        cam = ren.GetActiveCamera()
        cam.SetFocalPoint(0, 0, 0.055)
        cam.SetPosition(0.30, -0.21, 0.20)
        cam.SetViewUp(0, 0, 1)
        ren.ResetCameraClippingRange()
        txt = vtk.vtkTextActor()
        txt.SetInput(f"t = {t * 1e3:.0f} ms")
        txt.GetTextProperty().SetColor(0, 0, 0)
        txt.GetTextProperty().SetFontSize(22)
        txt.GetPositionCoordinate().SetCoordinateSystemToNormalizedViewport()
        txt.SetPosition(0.04, 0.92)
        ren.AddActor2D(txt)
        if n == len(grids) - 1:
            bar = vtk.vtkScalarBarActor()
            bar.SetLookupTable(lut)
            bar.SetTitle("speed (m/s)")
            bar.GetTitleTextProperty().SetColor(0, 0, 0)
            bar.GetLabelTextProperty().SetColor(0, 0, 0)
            bar.SetNumberOfLabels(5)
            bar.SetWidth(0.12)
            bar.SetHeight(0.5)
            bar.SetPosition(0.86, 0.25)
            ren.AddActor2D(bar)
        win.AddRenderer(ren)
    win.Render()
    w2i = vtk.vtkWindowToImageFilter()
    w2i.SetInput(win)
    w2i.Update()
    png = vtk.vtkPNGWriter()
    png.SetFileName(out)
    png.SetInputConnection(w2i.GetOutputPort())
    png.Write()
    print(f"{out}: frames at t = {', '.join(f'{t:.3g}' for t, _, _ in grids)} s, speed 0 to {vmax:.3g} m/s")


if __name__ == "__main__":
    main()
