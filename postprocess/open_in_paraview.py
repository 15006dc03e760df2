"""open_in_paraview.py: opens a swarf run in ParaView, ready to look at (a ParaView "state" as a script).

swarf run writes a copy of this file into every run directory with ParaView frames, as
DIR/open_in_paraview.py, with SWARF_RUN below filled in for that run. Open it with

    paraview --script=DIR/open_in_paraview.py        (the GUI)
    pvpython DIR/open_in_paraview.py [--screenshot OUT.png] [--size WxH]
                                                     (no GUI: renders the last time step to a PNG)

or, in the GUI, View > Python Shell > Run Script. The template itself (postprocess/ of swarf)
takes the run directory as its first argument: pvpython open_in_paraview.py DIR.

What it shows: the particles of the frame series as spheres of their own radius (Point
Gaussian, shader "Sphere", scaled by the 'radius' array), the meshes (tool, walls) in grey, the
chip surface of the end of the run translucent (a cutting run), in one render view per field
side by side with linked cameras, each with the simulated time in its corner. The fields, their
units, ranges and colour maps come from postprocess/chip_view.json, the description the rendered
pictures (render_chip.py) use too: damage, the broken-rod fraction (cividis, 0 to its maximum),
equivalent plastic strain (viridis, 0 to the 99th percentile of the last frame), von Mises
stress (in MPa, plasma, 0 to the 99th percentile) and temperature (in deg C, inferno, the lowest
to the highest); MPa and deg C through a Calculator filter on the particles, as the pictures
show them. Only the fields that the run wrote (output.fields) get a view. The camera looks along
+y at the cutting plane (x, the cutting direction, to the right; z up) in parallel projection, on
the tool's tip at the last time step when there is a tool (3 depths of cut behind it to 5
ahead), else on everything; the animation stands at the last time step. The rods are loaded
but hidden.

The frame series is read through one ParaView file-series file per part
(DIR/particles.vtu.series, DIR/<mesh name>.vtp.series, DIR/rods.vtu.series, written here from
DIR/particles.pvd so that the times are the simulated times in s), since a multi-part .pvd
opens as one multiblock whose parts each need an Extract Block.

Needs ParaView 5.10 or newer with Python (pvpython). On Debian 12, python3-paraview (which
pvpython and the GUI's Python need) conflicts with python3-vtk9, which swarf's pictures use:
see docs/outputs.md "Opening a run in ParaView" for the ways around it.
"""

# --- written by swarf run for this run (the template's is empty) ---
SWARF_RUN = {}
# --- end of the run's values ---

import json
import os
import sys
import xml.etree.ElementTree as ET

ARGV = list(getattr(sys, "argv", None) or [])  # (an embedded interpreter, the GUI's, may have none)



def load_view():
    """The view's description (postprocess/chip_view.json, which render_chip.py reads too):
    the run's copy carries it in SWARF_RUN["view"]; the template reads the file beside itself."""
    if SWARF_RUN.get("view"):
        return SWARF_RUN["view"]
    try:
        here = os.path.dirname(os.path.abspath(__file__))
    except NameError:
        here = "."
    path = os.path.join(here, "chip_view.json")
    try:
        with open(path) as f:
            return json.load(f)
    except (OSError, ValueError) as e:
        raise SystemExit("open_in_paraview.py: cannot read the view description %s: %s" % (path, e))


def run_directory():
    """The run directory: the script's own (a run's copy), the first argument (the template),
    or the one recorded by swarf (ParaView's --script may not set __file__)."""
    candidates = []
    args = [a for a in ARGV[1:] if not a.startswith("-")]
    if args and os.path.isdir(args[0]):
        candidates.append(args[0])
    try:
        candidates.append(os.path.dirname(os.path.abspath(__file__)))
    except NameError:
        pass
    if SWARF_RUN.get("run_dir"):
        candidates.append(SWARF_RUN["run_dir"])
    for c in candidates:
        if os.path.exists(os.path.join(c, "particles.pvd")):
            return os.path.abspath(c)
    raise SystemExit("open_in_paraview.py: no particles.pvd in %s (give the run directory: pvpython "
                     "open_in_paraview.py DIR)" % " or ".join(candidates or ["(nowhere)"]))


def option(name, default=None):
    """The value after --name in the arguments (pvpython only; the GUI passes none)."""
    if name in ARGV:
        i = ARGV.index(name)
        if i + 1 < len(ARGV):
            return ARGV[i + 1]
    return default


def parts_of(pvd):
    """{part name: [(time s, file relative to the run directory)]} from particles.pvd."""
    parts = {}
    for ds in ET.parse(pvd).getroot().iter("DataSet"):
        name = ds.get("name") or ("part" + ds.get("part", "0"))
        parts.setdefault(name, []).append((float(ds.get("timestep", "0")), ds.get("file")))
    return parts


def write_series(run_dir, name, entries):
    """DIR/<part name>.<ext>.series (ParaView's file series with times); returns its path."""
    ext = os.path.splitext(entries[0][1])[1]
    path = os.path.join(run_dir, name + ext + ".series")
    text = json.dumps({"file-series-version": "1.0",
                       "files": [{"name": f, "time": t} for t, f in entries]}, indent=1)
    tmp = path + ".part"
    with open(tmp, "w") as out:
        out.write(text)
    os.replace(tmp, path)
    return path


def tool_tip(servermanager, source, time):
    """(x, z) of the lowest vertex of the mesh (the one furthest ahead among the lowest) at
    'time', or None."""
    try:
        source.UpdatePipeline(time)
        data = servermanager.Fetch(source)
        pts = data.GetPoints()
        best = None
        for i in range(data.GetNumberOfPoints()):
            x, _, z = pts.GetPoint(i)
            if best is None or z < best[1] - 1e-12 or (abs(z - best[1]) <= 1e-12 and x > best[0]):
                best = (x, z)
        return best
    except Exception:  # (a ParaView without Fetch, an empty mesh: the view frames everything)
        return None


def range_of(servermanager, source, field, time):
    """(lowest, 99th percentile, highest) of the field over the particles at 'time'."""
    try:
        source.UpdatePipeline(time)
        data = servermanager.Fetch(source)
        arr = data.GetPointData().GetArray(field)
        values = sorted(arr.GetValue(i) for i in range(arr.GetNumberOfTuples()))
        if values:
            return values[0], values[min(len(values) - 1, int(0.99 * (len(values) - 1)))], values[-1]
    except Exception:  # (a ParaView without Fetch: the range ParaView knows)
        try:
            lo, hi = source.PointData[field].GetRange()
            return lo, hi, hi
        except Exception:
            pass
    return 0.0, 1.0, 1.0


def bar_range(spec, low, p99, high):
    """The colour bar's range in the bar's unit by the field's rule (chip_view.json)."""
    f, o = spec["factor"], spec["offset"]
    if spec["range"] == "min_max":
        bottom = low * f + o
        return bottom, max(high * f + o, bottom + 1.0)
    top = (high if spec["range"] == "max" else p99) * f + o
    if not top > 0:
        top = max(high * f + o, 1e-12)
    return 0.0, max(top, spec["min_top"])


def main():
    from paraview import servermanager
    from paraview.simple import (AddCameraLink, AnnotateTime, AssignViewToLayout, Calculator, ColorBy, CreateView,
                                 GetActiveViewOrCreate, GetAnimationScene, GetColorTransferFunction, GetLayout,
                                 GetOpacityTransferFunction, GetParaViewVersion, GetScalarBar, Hide, OpenDataFile,
                                 RenameSource, Render, SaveScreenshot, SetActiveView, Show)

    run_dir = run_directory()
    parts = parts_of(os.path.join(run_dir, "particles.pvd"))
    if "particles" not in parts:
        raise SystemExit("open_in_paraview.py: %s/particles.pvd lists no part 'particles'" % run_dir)
    final = {}  # parts listed only at the last time step (the chip surface)
    n_times = len(parts["particles"])
    sources = {}
    for name, entries in sorted(parts.items()):
        if len(entries) == 1 and n_times > 1:
            final[name] = os.path.join(run_dir, entries[0][1])
            continue
        src = OpenDataFile(write_series(run_dir, name, entries))
        RenameSource(name, src)
        sources[name] = src
    for name, path in final.items():
        src = OpenDataFile(path)
        RenameSource(name, src)
        sources[name] = src
    last = parts["particles"][-1][0]
    scene = GetAnimationScene()
    scene.UpdateAnimationUsingDataTimeSteps()
    scene.AnimationTime = last

    particles = sources["particles"]
    written = SWARF_RUN.get("fields")
    if written is None:  # (the template: what the last frame holds)
        written = list(particles.PointData.keys())
    view_spec = load_view()
    fields = [f for f in view_spec["fields"] if f["field"] in written]
    if not fields:  # (a run that wrote no field: the radius, in m)
        fields = [{"field": "radius", "title": "radius", "unit": "m", "factor": 1.0, "offset": 0.0,
                   "colour_map": "viridis", "range": "max", "min_top": 0.0}]
    tool = SWARF_RUN.get("tool_mesh") or ""
    depth = float(SWARF_RUN.get("depth_of_cut_m") or 0.0)
    tip = tool_tip(servermanager, sources[tool], last) if tool in sources else None

    # One view per field, side by side, cameras linked. The layout is a binary tree of cells:
    # cell c splits into 2c+1 (left, keeping its view) and 2c+2 (right).
    views = [GetActiveViewOrCreate("RenderView")]
    layout = GetLayout(views[0])
    cells = []
    try:
        if len(fields) == 2:
            layout.SplitHorizontal(0, 0.5)
            cells = [2]
        elif len(fields) == 3:
            layout.SplitHorizontal(0, 1.0 / 3.0)
            layout.SplitHorizontal(2, 0.5)
            cells = [5, 6]
        elif len(fields) == 4:
            layout.SplitHorizontal(0, 0.5)
            layout.SplitHorizontal(1, 0.5)
            layout.SplitHorizontal(2, 0.5)
            cells = [4, 5, 6]
    except Exception:
        cells = []
    for k in range(1, len(fields)):
        v = CreateView("RenderView")
        if len(cells) == len(fields) - 1:
            AssignViewToLayout(view=v, layout=layout, hint=cells[k - 1])
        else:
            AssignViewToLayout(view=v, layout=layout)
        views.append(v)
        AddCameraLink(views[0], v, "swarf_camera_%d" % k)

    # The simulated time in every view (AnnotateTime's format is Python's from ParaView 5.10 on).
    clock = AnnotateTime()
    try:
        major, minor = (int(x) for x in str(GetParaViewVersion()).split(".")[:2])
    except Exception:
        major, minor = 5, 10
    clock.Format = "t = {time:.4g} s" if (major, minor) >= (5, 10) else "t = %.4g s"

    for view, spec in zip(views, fields):
        field = spec["field"]
        SetActiveView(view)
        view.OrientationAxesVisibility = 1
        view.Background = [1.0, 1.0, 1.0]
        try:
            view.UseColorPaletteForBackground = 0  # (5.11+: else the palette's background wins)
        except Exception:
            pass
        # The bar's unit (MPa, deg C) from the array's SI unit by a Calculator, as the pictures.
        shown, array = particles, field
        if spec["factor"] != 1.0 or spec["offset"] != 0.0:
            array = "%s_%s" % (field, spec["unit"].replace(" ", ""))
            shown = Calculator(Input=particles)
            RenameSource("%s in %s" % (field, spec["unit"]), shown)
            shown.AttributeType = "Point Data"
            shown.ResultArrayName = array
            expr = field if spec["factor"] == 1.0 else "%s*%r" % (field, spec["factor"])
            if spec["offset"] != 0.0:
                expr += ("+%r" if spec["offset"] > 0 else "-%r") % abs(spec["offset"])
            shown.Function = expr
        d = Show(shown, view)
        d.SetRepresentationType("Point Gaussian")
        d.ShaderPreset = "Sphere"
        d.ScaleByArray = 1
        d.SetScaleArray = ["POINTS", "radius"]
        d.UseScaleFunction = 0  # the radius itself, not a transfer function of it
        d.GaussianRadius = 1.0
        ColorBy(d, ("POINTS", array))
        lut = GetColorTransferFunction(array)
        samples = view_spec["colour_maps"][spec["colour_map"]]
        lut.ColorSpace = "RGB"  # (linear in RGB between the samples, as render_chip.py)
        points = []
        for k, rgb in enumerate(samples):
            points += [k / float(len(samples) - 1)] + list(rgb)
        lut.RGBPoints = points
        bottom, top = bar_range(spec, *range_of(servermanager, particles, field, last))
        lut.RescaleTransferFunction(bottom, top)
        GetOpacityTransferFunction(array).RescaleTransferFunction(bottom, top)
        lut.AutomaticRescaleRangeMode = "Never"
        d.SetScalarBarVisibility(view, True)
        bar = GetScalarBar(lut, view)
        bar.Title = spec["title"] + ("" if spec["unit"] == "1" else " (%s)" % spec["unit"])
        bar.ComponentTitle = ""
        bar.Orientation = "Horizontal"  # above the uncut surface ahead of the chip, off the block
        bar.WindowLocation = "Upper Right Corner"
        bar.TitleColor = [0.0, 0.0, 0.0]
        bar.LabelColor = [0.0, 0.0, 0.0]
        t = Show(clock, view)
        t.WindowLocation = "Upper Left Corner"
        t.Color = [0.0, 0.0, 0.0]
        for name, src in sources.items():
            if name == "particles":
                continue
            if name == "rods":
                Hide(src, view)
                continue
            m = Show(src, view)
            m.SetRepresentationType("Surface")
            # Solid colour. (Not ColorBy(m, None): ParaView 5.11 raises 'invalid association
            # string NONE' for a representation that was never coloured by an array.)
            m.ColorArrayName = ["POINTS", ""]
            if name in final:  # the chip surface: the end of the run, translucent
                m.DiffuseColor = [0.95, 0.75, 0.2]
                m.AmbientColor = [0.95, 0.75, 0.2]
                m.Opacity = 0.3
            else:
                m.DiffuseColor = [0.55, 0.55, 0.58]
                m.AmbientColor = [0.55, 0.55, 0.58]

    # The camera: along +y, x to the right, z up, parallel; on the cut when there is a tool.
    # (Rendered once first: pvpython's first Render of a view resets its camera.)
    for v in views:
        Render(v)
    view = views[0]
    view.ResetCamera()
    view.CameraParallelProjection = 1
    b = particles.GetDataInformation().GetBounds()
    cy = 0.5 * (b[2] + b[3])
    if tip is not None and depth > 0:
        cx, cz, half = tip[0] + depth, tip[1] + 1.5 * depth, 4.0 * depth
    else:
        cx, cz = 0.5 * (b[0] + b[1]), 0.5 * (b[4] + b[5])
        half = 0.55 * max(b[1] - b[0], b[5] - b[4], 1e-12)
    for v in views:
        v.CameraFocalPoint = [cx, cy, cz]
        v.CameraPosition = [cx, cy - 10.0 * half, cz]
        v.CameraViewUp = [0.0, 0.0, 1.0]
        v.CameraParallelProjection = 1
        v.CameraParallelScale = half
    SetActiveView(views[0])
    for v in views:
        Render(v)

    shot = option("--screenshot")
    if shot:
        w, h = (int(x) for x in option("--size", "%dx800" % (800 * len(views))).split("x"))
        SaveScreenshot(shot, layout, ImageResolution=[w, h])
        print("wrote " + shot)


main()
