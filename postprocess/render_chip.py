#!/usr/bin/python3
"""render_chip.py: PNG pictures of the workpiece, the chip and the tool at the end of a swarf run.

Usage: render_chip.py RUN_DIR [OUTPUT.png] [--size WxH] [--max-fraction F] [--frame N]
                      [--fields F1,F2,...] [--tool NAME] [--depth H] [--view side|top]

Reads the last particles frame RUN_DIR/frames/particles_NNNNN.vtu (point data radius and the
fields), the meshes of the same frame RUN_DIR/frames/mesh_<name>_NNNNN.vtp and, if present and
the frame is the last, the chip surface RUN_DIR/chip_surface.vtp (drawn translucent). Particles
are spheres of their own radius, meshes grey. One picture per field of --fields (default
broken_fraction,plastic_strain,von_mises_stress,temperature), each with its perceptually uniform
colour map, unit and range from postprocess/chip_view.json, which open_in_paraview.py reads too:
  broken_fraction     OUTPUT (default RUN_DIR/chip.png), cividis, 0 to the largest fraction (at
                      least 0.05; --max-fraction sets it)
  plastic_strain      OUTPUT's stem + _plastic_strain.png, viridis, 0 to the 99th percentile in view
  von_mises_stress    OUTPUT's stem + _von_mises_stress.png, plasma, MPa, 0 to the 99th percentile
                      in view
  temperature         OUTPUT's stem + _temperature.png, inferno, deg C, the coolest to the hottest
                      particle in view (a run with [heat]; the hottest is the point: no percentile cut)
  plastic_work        OUTPUT's stem + _plastic_work.png, viridis, MJ/m^3, 0 to the 99th percentile in
                      view (where the plastic work went; not drawn unless --fields names it)
A field the frame does not hold (output.fields left it out, or no [heat] for the temperature) is
skipped, with a note if --fields named it.

The camera looks along +y at the cutting plane x-z (x, the cutting direction, to the right;
z up), parallel projection. With a tool (--tool NAME, or the mesh reaching lowest) it frames the
cut: the particles within a few depths of cut of the tool's tip (its lowest vertex), from
3 depths behind the tip to 5 ahead and from 2 below to 5 above, so the chip, the tool and the
machined surface fill the picture and fragments flung far away stay out. --depth H is the depth
of cut in m (default: the highest particle ahead of the tool minus the tip). Without a tool it
frames the connected extent of the particles. --view top looks down from above (along -z, x to
the right, y up) at the same stretch of x widened by half the block's width either side, the
whole width in view: the chip's flow across an inclined edge and its spread. The title gives the run's name and the simulated
time of the frame (from RUN_DIR/particles.pvd). Size 1280x800 by default. Prints 'wrote PATH'
for each picture.

Rendering is offscreen but Debian's VTK needs an X server: without DISPLAY the script runs
itself again under `xvfb-run -a` if that exists, or exits with a message. Exit code 1 if the
frames are missing or no picture could be drawn, 2 on bad arguments or no X server.
Use /usr/bin/python3 (module vtk from python3-vtk9).
"""
import argparse
import glob
import json
import os
import re
import shutil
import sys
import xml.etree.ElementTree as ET

XVFB_GUARD = "SWARF_RENDER_UNDER_XVFB"


def load_view():
    """postprocess/chip_view.json: the fields' titles, units, ranges and colour maps, shared
    with open_in_paraview.py (one description of the view)."""
    path = os.path.join(os.path.dirname(os.path.abspath(__file__)), "chip_view.json")
    try:
        with open(path) as f:
            view = json.load(f)
        return {f["field"]: f for f in view["fields"]}, view["colour_maps"]
    except (OSError, ValueError, KeyError) as e:
        print("render_chip.py: cannot read the view description %s: %s" % (path, e), file=sys.stderr)
        sys.exit(1)


FIELDS, COLOUR_MAPS = load_view()
DEFAULT_FIELDS = "broken_fraction,plastic_strain,von_mises_stress,temperature"


def set_colour_map(lut, samples):
    """Fills the 256 entries of the lookup table from the colour map's equally spaced RGB
    samples, interpolated linearly (as ParaView interpolates the same points)."""
    n = lut.GetNumberOfTableValues()
    last = len(samples) - 1
    for i in range(n):
        x = i / float(n - 1) * last
        k = min(int(x), last - 1)
        w = x - k
        rgb = [(1.0 - w) * samples[k][c] + w * samples[k + 1][c] for c in range(3)]
        lut.SetTableValue(i, rgb[0], rgb[1], rgb[2], 1.0)


def fail(msg, code=1):
    print("render_chip.py: " + msg, file=sys.stderr)
    sys.exit(code)


def parse_args():
    ap = argparse.ArgumentParser(description="Render the end of a swarf run (particles coloured by damage, plastic "
                                 "strain and von Mises stress; tool; chip surface) to PNG.")
    ap.add_argument("run_dir")
    ap.add_argument("output", nargs="?", help="PNG path (default RUN_DIR/chip.png)")
    ap.add_argument("--size", default="1280x800", help="image size WxH in pixels (default 1280x800)")
    ap.add_argument("--max-fraction", type=float, default=0.0,
                    help="top of the colour bar (default: the largest broken-rod fraction, at least 0.05)")
    ap.add_argument("--frame", type=int, default=-1, help="frame number (default: the last)")
    ap.add_argument("--fields", default=None,
                    help="one picture per field, comma-separated (default %s; those the frame holds)" % DEFAULT_FIELDS)
    ap.add_argument("--tool", default="", help="name of the tool's mesh (default: the mesh reaching lowest)")
    ap.add_argument("--depth", type=float, default=0.0, help="depth of cut, m (default: from the particles)")
    ap.add_argument("--view", choices=("side", "top"), default="side",
                    help="side: along +y at the cutting plane x-z (default); top: from above, along -z, at x-y "
                         "(an oblique or finite-width cut: the chip's flow across the edge and its spread)")
    a = ap.parse_args()
    a.fields_named = a.fields is not None
    a.fields = [f for f in (a.fields if a.fields_named else DEFAULT_FIELDS).split(",") if f]
    for f in a.fields:
        if f not in FIELDS:
            fail("--fields: '%s' is not one of %s" % (f, ", ".join(FIELDS)), 2)
    if not a.fields:
        fail("--fields: give at least one of %s" % ", ".join(FIELDS), 2)
    if not (a.depth >= 0.0):
        fail("--depth must be a length >= 0 in m (got %s)" % a.depth, 2)
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


def tool_tip(np, vtk_to_numpy, meshes, tool):
    """(x, z) of the tool's tip, its lowest vertex (the one furthest ahead among the lowest), or
    None without a tool. 'meshes': (name, polydata) of the frame; 'tool': the tool's name or ''."""
    best = None
    for name, poly in meshes:
        if tool and name != tool:
            continue
        if poly.GetNumberOfPoints() == 0:
            continue
        v = vtk_to_numpy(poly.GetPoints().GetData()).astype(float)
        zmin = v[:, 2].min()
        low = v[v[:, 2] <= zmin + 1e-9 * max(1.0, abs(zmin))]
        tip = (float(low[:, 0].max()), float(zmin))
        if best is None or tip[1] < best[1]:
            best = tip
    return best


def cut_window(np, pos, rmax, tip, depth):
    """The box (lo, hi) in x-z around the cut: the particles from 3 depths behind the tip to 5
    ahead and from 2 below to 5 above (clipped to those present), grown by a radius."""
    tx, tz = tip
    if depth <= 0:
        # The uncut surface: the highest particle ahead of the tool, near it.
        ahead = pos[(pos[:, 0] > tx + 4 * rmax) & (pos[:, 0] < tx + 60 * rmax) & (pos[:, 2] < tz + 60 * rmax)]
        depth = float(ahead[:, 2].max() - tz) if len(ahead) else 0.0
        if depth <= 2 * rmax:
            depth = 10 * rmax
    box_lo = np.array([tx - 3 * depth, tz - 2 * depth])
    box_hi = np.array([tx + 5 * depth, tz + 5 * depth])
    xz = pos[:, [0, 2]]
    inside = np.all((xz >= box_lo) & (xz <= box_hi), axis=1)
    if inside.sum() < 2:
        return box_lo, box_hi, inside
    lo = np.maximum(xz[inside].min(axis=0) - rmax, box_lo)
    hi = np.minimum(xz[inside].max(axis=0) + rmax, box_hi)
    # The tool's tip stays in view (a tool that has run past the material).
    lo = np.minimum(lo, [tx - 2 * rmax, tz - 2 * rmax])
    hi = np.maximum(hi, [tx + 2 * rmax, tz + 2 * rmax])
    return lo, hi, inside


def main():
    a = parse_args()
    run_dir = a.run_dir
    if not os.path.isdir(run_dir):
        fail("run directory '%s' does not exist" % run_dir)
    frame, particles_path = frame_files(run_dir, a.frame)
    out = a.output or os.path.join(run_dir, "chip.png")
    ensure_display()

    import numpy as np
    import vtk  # after the display check: importing is slow and needs no X, rendering does
    from vtk.util.numpy_support import vtk_to_numpy, numpy_to_vtk

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
    pos = vtk_to_numpy(grid.GetPoints().GetData()).astype(float)
    rmax = float(pd.GetArray("radius").GetRange()[1])

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
    particles = vtk.vtkActor()
    particles.SetMapper(glyphs)
    ren.AddActor(particles)

    # Tools and walls of the same frame, grey.
    meshes = []
    for path in sorted(glob.glob(os.path.join(run_dir, "frames", "mesh_*_%05d.vtp" % frame))):
        name = re.fullmatch(r"mesh_(.*)_\d{5}\.vtp", os.path.basename(path)).group(1)
        act, poly = polydata_actor(vtk, path, (0.55, 0.55, 0.58))
        act.GetProperty().SetSpecular(0.3)
        ren.AddActor(act)
        meshes.append((name, poly))

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

    # The view: on the cut when there is a tool, else on the connected extent of the particles.
    tip = tool_tip(np, vtk_to_numpy, meshes, a.tool)
    if a.tool and tip is None:
        fail("no mesh '%s' in frame %d (meshes: %s)" % (a.tool, frame, ", ".join(m for m, _ in meshes) or "none"))
    if tip is not None:
        lo2, hi2, in_view = cut_window(np, pos, rmax, tip, a.depth)
        lo = [lo2[0], pos[:, 1].min() - rmax, lo2[1]]
        hi = [hi2[0], pos[:, 1].max() + rmax, hi2[1]]
        framing = "framed on the tool tip"
    else:
        lo, hi = [0.0] * 3, [0.0] * 3
        for ax in range(3):
            lo[ax], hi[ax] = connected_extent(sorted(pos[:, ax]), 4.0 * rmax)
            lo[ax] -= rmax
            hi[ax] += rmax
        in_view = (pos[:, 0] >= lo[0]) & (pos[:, 0] <= hi[0]) & (pos[:, 2] >= lo[2]) & (pos[:, 2] <= hi[2])
        framing = "framed on the particles"
    # The image's vertical axis: z seen from the side, y seen from above.
    up_ax = 2 if a.view == "side" else 1
    if a.view == "top":  # the whole width, and an inclined edge's lead either side of its middle
        half = 0.5 * (hi[1] - lo[1])
        lo[0], hi[0] = lo[0] - half, hi[0] + half
        in_view = (pos[:, 0] >= lo[0]) & (pos[:, 0] <= hi[0])
    dx, dv = hi[0] - lo[0], hi[up_ax] - lo[up_ax]
    aspect = a.width / float(a.height)
    # The content fills the band 0.16-0.92 of the height (title above, colour bar below).
    scale = 1.04 * max(dv / 1.52, dx / (1.92 * aspect))
    centre = [0.5 * (lo[0] + hi[0]), 0.5 * (lo[1] + hi[1]), 0.5 * (lo[2] + hi[2])]
    centre[up_ax] -= 0.08 * scale
    reach = 10.0 * max(dx, hi[1] - lo[1], hi[2] - lo[2])
    cam = ren.GetActiveCamera()
    cam.ParallelProjectionOn()
    cam.SetFocalPoint(*centre)
    if a.view == "side":
        cam.SetPosition(centre[0], centre[1] - reach, centre[2])
        cam.SetViewUp(0.0, 0.0, 1.0)
    else:
        cam.SetPosition(centre[0], centre[1], centre[2] + reach)
        cam.SetViewUp(0.0, 1.0, 0.0)
    cam.SetParallelScale(scale)
    ren.ResetCameraClippingRange()

    lut = vtk.vtkLookupTable()
    lut.SetNumberOfTableValues(256)
    lut.Build()
    bar = vtk.vtkScalarBarActor()
    bar.SetLookupTable(lut)
    bar.SetNumberOfLabels(5)
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
    looking = ("view along +y (x, the cutting direction, to the right; z up)" if a.view == "side"
               else "view from above, along -z (x, the cutting direction, to the right; y up)")
    text.SetInput(title + "\n%s, %.3g mm wide, %s" % (looking, 2e3 * scale * aspect, framing))

    win = vtk.vtkRenderWindow()
    win.SetOffScreenRendering(1)
    win.SetAlphaBitPlanes(1)
    win.SetMultiSamples(0)
    win.AddRenderer(ren)
    win.SetSize(a.width, a.height)

    stem = out[:-4] if out.lower().endswith(".png") else out
    wrote = 0
    for field in a.fields:
        f = FIELDS[field]
        suffix, factor, offset, fmt = f["suffix"], f["factor"], f["offset"], f["format"]
        bar_title = f["title"] + ("" if f["unit"] == "1" else " (%s)" % f["unit"])
        set_colour_map(lut, COLOUR_MAPS[f["colour_map"]])
        arr = pd.GetArray(field)
        if arr is None:
            if not a.fields_named and field == "temperature":
                continue  # (a run without [heat])
            print("render_chip.py: no point data '%s' in %s (output.fields left it out): picture skipped"
                  % (field, particles_path), file=sys.stderr)
            continue
        values = vtk_to_numpy(arr).astype(float) * factor + offset
        shown = values[in_view] if in_view.any() else values
        bottom = 0.0
        if field == "broken_fraction" and a.max_fraction > 0:
            top = a.max_fraction
        elif f["range"] == "max":
            top = max(f["min_top"], float(values.max()))
        elif f["range"] == "min_max":
            bottom = float(shown.min()) if len(shown) else 0.0
            top = max(float(shown.max()) if len(shown) else 0.0, bottom + 1.0)
        else:  # the 99th percentile of what is in view: a few extreme particles do not wash the map out
            top = float(np.percentile(shown, 99.0)) if len(shown) else 0.0
            if not top > 0:
                top = max(float(shown.max()) if len(shown) else 0.0, 1e-12)
        name = "swarf_colour_" + field
        if pd.GetArray(name) is None:
            scaled = numpy_to_vtk(np.ascontiguousarray(values), deep=1)
            scaled.SetName(name)
            pd.AddArray(scaled)
        lut.SetTableRange(bottom, top)
        glyphs.SetScalarModeToUsePointFieldData()
        glyphs.SelectColorArray(name)
        glyphs.SetLookupTable(lut)
        glyphs.SetScalarRange(bottom, top)
        glyphs.UseLookupTableScalarRangeOn()
        glyphs.ScalarVisibilityOn()
        glyphs.Modified()
        bar.SetTitle(bar_title + {"max": "", "min_max": ", the lowest to the highest in view",
                                  "p99": ", 0 to the 99th percentile in view"}[f["range"]])
        bar.SetLabelFormat(fmt)
        win.Render()

        grab = vtk.vtkWindowToImageFilter()
        grab.SetInput(win)
        grab.SetInputBufferTypeToRGB()
        grab.ReadFrontBufferOff()
        grab.Update()
        path = stem + suffix + ".png"
        tmp = path + ".part"
        writer = vtk.vtkPNGWriter()
        writer.SetFileName(tmp)
        writer.SetInputConnection(grab.GetOutputPort())
        writer.Write()
        if not os.path.exists(tmp) or os.path.getsize(tmp) == 0:
            fail("could not write %s" % path)
        os.replace(tmp, path)
        print("wrote " + path)
        wrote += 1
    if wrote == 0:
        fail("no picture drawn: the frame holds none of the fields %s" % ", ".join(a.fields))


if __name__ == "__main__":
    main()
