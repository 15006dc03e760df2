#!/usr/bin/python3
"""render_chip.py: a PNG picture of the workpiece, the chip and the tool at the end of a swarf run.

Usage: render_chip.py RUN_DIR [OUTPUT.png] [--size WxH] [--max-fraction F] [--frame N]

Reads the last particles frame RUN_DIR/frames/particles_NNNNN.vtu (point data radius and
broken_fraction), the tool meshes of the same frame RUN_DIR/frames/mesh_<name>_NNNNN.vtp and,
if present and the frame is the last, the chip surface RUN_DIR/chip_surface.vtp (drawn translucent). Particles are
spheres of their own radius, coloured by their broken-rod fraction (0 = all rods intact,
blue, to the colour bar's top, red); meshes are grey. The view looks along +y at the cutting
plane x-z (x, the cutting direction, to the right; z up), parallel projection; the title gives
the run's name and the simulated time of the frame (from RUN_DIR/particles.pvd).
Default output RUN_DIR/chip.png, 1280x800. Prints 'wrote PATH'.

Rendering is offscreen but Debian's VTK needs an X server: without DISPLAY the script runs
itself again under `xvfb-run -a` if that exists, or exits with a message. Exit code 1 if the
frames are missing, 2 on bad arguments or no X server.
Use /usr/bin/python3 (module vtk from python3-vtk9).
"""
import argparse
import glob
import os
import re
import shutil
import sys
import xml.etree.ElementTree as ET

XVFB_GUARD = "SWARF_RENDER_UNDER_XVFB"


def fail(msg, code=1):
    print("render_chip.py: " + msg, file=sys.stderr)
    sys.exit(code)


def parse_args():
    ap = argparse.ArgumentParser(description="Render the end of a swarf run (particles by broken-rod fraction, tool, chip surface) to PNG.")
    ap.add_argument("run_dir")
    ap.add_argument("output", nargs="?", help="PNG path (default RUN_DIR/chip.png)")
    ap.add_argument("--size", default="1280x800", help="image size WxH in pixels (default 1280x800)")
    ap.add_argument("--max-fraction", type=float, default=0.0,
                    help="top of the colour bar (default: the largest broken-rod fraction, at least 0.05)")
    ap.add_argument("--frame", type=int, default=-1, help="frame number (default: the last)")
    a = ap.parse_args()
    m = re.fullmatch(r"(\d+)x(\d+)", a.size)
    if not m or int(m.group(1)) < 16 or int(m.group(2)) < 16:
        fail("--size must be WxH with W, H >= 16, e.g. 1280x800 (got '%s')" % a.size, 2)
    a.width, a.height = int(m.group(1)), int(m.group(2))
    return a


def ensure_display():
    """Re-runs this script under xvfb-run when there is no X display."""
    if os.environ.get("DISPLAY"):
        return
    if os.environ.get(XVFB_GUARD):
        fail("no X display even under xvfb-run", 2)
    xvfb = shutil.which("xvfb-run")
    if not xvfb:
        fail("no X display (DISPLAY is unset) and no xvfb-run: install xvfb, or run under an X server", 2)
    env = dict(os.environ, **{XVFB_GUARD: "1"})
    args = [xvfb, "-a", "-s", "-screen 0 1280x1024x24", sys.executable, os.path.abspath(__file__)] + sys.argv[1:]
    os.execve(xvfb, args, env)


def frame_files(run_dir, frame):
    """The particles frame (number, path): the last one, or the one asked for."""
    frames = {}
    for p in glob.glob(os.path.join(run_dir, "frames", "particles_*.vtu")):
        m = re.fullmatch(r"particles_(\d+)\.vtu", os.path.basename(p))
        if m:
            frames[int(m.group(1))] = p
    if not frames:
        fail("no particle frames in %s (expected frames/particles_NNNNN.vtu written by 'swarf run')"
             % os.path.join(run_dir, "frames"))
    if frame < 0:
        frame = max(frames)
    if frame not in frames:
        fail("frame %d not found in %s (frames %d to %d)" % (frame, os.path.join(run_dir, "frames"), min(frames), max(frames)))
    return frame, frames[frame]


def frame_time(run_dir, particles_path):
    """Simulated time (s) of the frame from particles.pvd, or None."""
    pvd = os.path.join(run_dir, "particles.pvd")
    if not os.path.exists(pvd):
        return None
    try:
        rel = os.path.relpath(particles_path, run_dir).replace(os.sep, "/")
        for ds in ET.parse(pvd).getroot().iter("DataSet"):
            if ds.get("file") == rel:
                return float(ds.get("timestep"))
    except (ET.ParseError, ValueError):
        return None
    return None


def polydata_actor(vtk, path, colour):
    """(actor, polydata) for a .vtp file in one colour."""
    r = vtk.vtkXMLPolyDataReader()
    r.SetFileName(path)
    r.Update()
    m = vtk.vtkPolyDataMapper()
    m.SetInputConnection(r.GetOutputPort())
    m.ScalarVisibilityOff()
    act = vtk.vtkActor()
    act.SetMapper(m)
    act.GetProperty().SetColor(*colour)
    return act, r.GetOutput()


def connected_extent(values, gap):
    """(low, high) of the run of sorted values around their median without a gap wider than
    'gap': the workpiece and chip, not fragments flung away."""
    n = len(values)
    m = n // 2
    i = m
    while i > 0 and values[i] - values[i - 1] <= gap:
        i -= 1
    j = m
    while j < n - 1 and values[j + 1] - values[j] <= gap:
        j += 1
    return values[i], values[j]


def main():
    a = parse_args()
    run_dir = a.run_dir
    if not os.path.isdir(run_dir):
        fail("run directory '%s' does not exist" % run_dir)
    frame, particles_path = frame_files(run_dir, a.frame)
    out = a.output or os.path.join(run_dir, "chip.png")
    ensure_display()

    import vtk  # after the display check: importing is slow and needs no X, rendering does

    reader = vtk.vtkXMLUnstructuredGridReader()
    reader.SetFileName(particles_path)
    reader.Update()
    grid = reader.GetOutput()
    n = grid.GetNumberOfPoints()
    if n == 0:
        fail("%s holds no particles" % particles_path)
    pd = grid.GetPointData()
    if pd.GetArray("radius") is None:
        fail("%s has no point data 'radius'" % particles_path)
    fraction = pd.GetArray("broken_fraction")
    top = a.max_fraction
    if top <= 0:
        top = max(0.05, fraction.GetRange()[1] if fraction is not None else 0.0)

    ren = vtk.vtkRenderer()
    ren.SetBackground(1.0, 1.0, 1.0)

    # Particles: one low-resolution sphere per particle, scaled by its radius.
    sphere = vtk.vtkSphereSource()
    sphere.SetRadius(1.0)
    sphere.SetThetaResolution(12)
    sphere.SetPhiResolution(8)
    glyphs = vtk.vtkGlyph3DMapper()
    glyphs.SetInputData(grid)
    glyphs.SetSourceConnection(sphere.GetOutputPort())
    glyphs.SetScaleArray("radius")
    glyphs.SetScaleModeToScaleByMagnitude()
    glyphs.SetScaleFactor(1.0)
    glyphs.OrientOff()
    lut = vtk.vtkLookupTable()
    lut.SetHueRange(0.667, 0.0)  # blue (intact) to red
    lut.SetNumberOfTableValues(256)
    lut.SetTableRange(0.0, top)
    lut.Build()
    if fraction is not None:
        glyphs.SetScalarModeToUsePointFieldData()
        glyphs.SelectColorArray("broken_fraction")
        glyphs.SetLookupTable(lut)
        glyphs.SetScalarRange(0.0, top)
        glyphs.UseLookupTableScalarRangeOn()
        glyphs.ScalarVisibilityOn()
    else:
        glyphs.ScalarVisibilityOff()
    particles = vtk.vtkActor()
    particles.SetMapper(glyphs)
    if fraction is None:
        particles.GetProperty().SetColor(0.2, 0.3, 0.8)
    ren.AddActor(particles)

    # Tools and walls of the same frame, grey.
    meshes = sorted(glob.glob(os.path.join(run_dir, "frames", "mesh_*_%05d.vtp" % frame)))
    mesh_bounds = []
    for path in meshes:
        act, poly = polydata_actor(vtk, path, (0.55, 0.55, 0.58))
        act.GetProperty().SetSpecular(0.3)
        ren.AddActor(act)
        mesh_bounds.append(poly.GetBounds())

    # The chip surface (end of the run), translucent over the particles: only over the last
    # frame, since over an earlier one it shows a chip that has not formed yet.
    chip_path = os.path.join(run_dir, "chip_surface.vtp")
    chip_drawn = False
    if os.path.exists(chip_path) and frame == frame_files(run_dir, -1)[0]:
        act, poly = polydata_actor(vtk, chip_path, (0.95, 0.75, 0.2))
        if poly.GetNumberOfCells() > 0:
            act.GetProperty().SetOpacity(0.3)
            ren.AddActor(act)
            ren.SetUseDepthPeeling(1)  # correct blending of the translucent surface
            chip_drawn = True

    if fraction is not None:
        bar = vtk.vtkScalarBarActor()
        bar.SetLookupTable(lut)
        bar.SetTitle("broken-rod fraction")
        bar.SetNumberOfLabels(5)
        bar.SetLabelFormat("%.2f")
        bar.SetOrientationToHorizontal()
        bar.SetPosition(0.25, 0.03)
        bar.SetWidth(0.5)
        bar.SetHeight(0.1)
        bar.UnconstrainedFontSizeOn()
        for tp in (bar.GetTitleTextProperty(), bar.GetLabelTextProperty()):
            tp.SetColor(0.0, 0.0, 0.0)
            tp.SetFontSize(max(10, a.height // 50))
            tp.ItalicOff()
            tp.ShadowOff()
        ren.AddActor2D(bar)

    t = frame_time(run_dir, particles_path)
    title = "%s   t = %s   %d particles%s%s" % (
        os.path.basename(os.path.normpath(os.path.abspath(run_dir))),
        ("%.4g ms" % (t * 1e3)) if t is not None else "(time unknown)", n,
        "   tool" if meshes else "", "   chip surface translucent" if chip_drawn else "")
    text = vtk.vtkTextActor()
    text.GetTextProperty().SetColor(0.0, 0.0, 0.0)
    text.GetTextProperty().SetFontSize(max(12, a.height // 40))
    text.GetTextProperty().SetJustificationToCentered()
    text.GetTextProperty().SetVerticalJustificationToTop()
    text.GetPositionCoordinate().SetCoordinateSystemToNormalizedViewport()
    text.SetPosition(0.5, 0.97)
    ren.AddActor2D(text)

    # Look along +y at the x-z plane (x to the right, z up), framing the workpiece and chip
    # (not stray fragments far away) between the title and the colour bar.
    from vtk.util.numpy_support import vtk_to_numpy
    pos = vtk_to_numpy(grid.GetPoints().GetData()).astype(float)
    rmax = float(pd.GetArray("radius").GetRange()[1])
    lo, hi = [0.0] * 3, [0.0] * 3
    for ax in range(3):
        lo[ax], hi[ax] = connected_extent(sorted(pos[:, ax]), 4.0 * rmax)
        lo[ax] -= rmax
        hi[ax] += rmax
    dx, dz = hi[0] - lo[0], hi[2] - lo[2]
    for b in mesh_bounds:  # tools: shown if near, but never widen the view by more than half
        lo[0], hi[0] = min(lo[0], max(b[0], lo[0] - 0.5 * dx)), max(hi[0], min(b[1], hi[0] + 0.5 * dx))
        lo[2], hi[2] = min(lo[2], max(b[4], lo[2] - 0.5 * dz)), max(hi[2], min(b[5], hi[2] + 0.5 * dz))
    dx, dz = hi[0] - lo[0], hi[2] - lo[2]
    aspect = a.width / float(a.height)
    # The content fills the band 0.16-0.92 of the height (title above, colour bar below).
    scale = 1.04 * max(dz / 1.52, dx / (1.92 * aspect))
    centre = [0.5 * (lo[0] + hi[0]), 0.5 * (lo[1] + hi[1]), 0.5 * (lo[2] + hi[2]) - 0.08 * scale]
    cam = ren.GetActiveCamera()
    cam.ParallelProjectionOn()
    cam.SetFocalPoint(*centre)
    cam.SetPosition(centre[0], centre[1] - 10.0 * max(dx, dz, hi[1] - lo[1]), centre[2])
    cam.SetViewUp(0.0, 0.0, 1.0)
    cam.SetParallelScale(scale)
    ren.ResetCameraClippingRange()
    text.SetInput(title + "\nview along +y (x, the cutting direction, to the right; z up), %.3g mm wide"
                  % (2e3 * scale * aspect))

    win = vtk.vtkRenderWindow()
    win.SetOffScreenRendering(1)
    win.SetAlphaBitPlanes(1)
    win.SetMultiSamples(0)
    win.AddRenderer(ren)
    win.SetSize(a.width, a.height)
    win.Render()

    grab = vtk.vtkWindowToImageFilter()
    grab.SetInput(win)
    grab.SetInputBufferTypeToRGB()
    grab.ReadFrontBufferOff()
    grab.Update()
    tmp = out + ".part"
    writer = vtk.vtkPNGWriter()
    writer.SetFileName(tmp)
    writer.SetInputConnection(grab.GetOutputPort())
    writer.Write()
    if not os.path.exists(tmp) or os.path.getsize(tmp) == 0:
        fail("could not write %s" % out)
    os.replace(tmp, out)
    print("wrote " + out)


if __name__ == "__main__":
    main()
