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
side by side with linked cameras: von Mises stress (in Pa, "Cool to Warm"), equivalent
plastic strain ("Viridis") and damage, the broken-rod fraction ("Inferno"), each ranged 0 to
the 99th percentile of the last frame (damage: 0 to its maximum). Only the fields that the run
wrote (output.fields) get a view. The camera looks along +y at the cutting plane (x, the
cutting direction, to the right; z up) in parallel projection, on the tool's tip at the last
time step when there is a tool (3 depths of cut behind it to 5 ahead), else on everything;
the animation stands at the last time step. The rods are loaded but hidden.

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

# (field, colour bar title, colour map preset), in the order of the views
FIELDS = [
    ("von_mises_stress", "von Mises stress (Pa)", "Cool to Warm"),
    ("plastic_strain", "equivalent plastic strain (1)", "Viridis (matplotlib)"),
    ("broken_fraction", "damage: broken-rod fraction (1)", "Inferno (matplotlib)"),
]


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


def top_of_range(servermanager, source, field, time, percentile):
    """The 'percentile' of the field over the particles at 'time' (numpy), else its maximum."""
    try:
        source.UpdatePipeline(time)
        data = servermanager.Fetch(source)
        arr = data.GetPointData().GetArray(field)
        values = sorted(arr.GetValue(i) for i in range(arr.GetNumberOfTuples()))
        if not values:
            return 1.0
        top = values[min(len(values) - 1, int(percentile / 100.0 * (len(values) - 1)))]
        return top if top > 0 else max(values[-1], 1e-12)
    except Exception:
        try:
            return max(source.PointData[field].GetRange()[1], 1e-12)
        except Exception:
            return 1.0


def main():
    from paraview import servermanager
    from paraview.simple import (AddCameraLink, AssignViewToLayout, ColorBy, CreateView, GetActiveViewOrCreate,
                                 GetAnimationScene, GetColorTransferFunction, GetLayout, GetOpacityTransferFunction,
                                 GetScalarBar, Hide, OpenDataFile, RenameSource, Render, SaveScreenshot, SetActiveView,
                                 Show)

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
    fields = [f for f in FIELDS if f[0] in written] or [("radius", "radius (m)", "Cool to Warm")]
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

    for view, (field, title, preset) in zip(views, fields):
        SetActiveView(view)
        view.OrientationAxesVisibility = 1
        view.Background = [1.0, 1.0, 1.0]
        try:
            view.UseColorPaletteForBackground = 0  # (5.11+: else the palette's background wins)
        except Exception:
            pass
        d = Show(particles, view)
        d.SetRepresentationType("Point Gaussian")
        d.ShaderPreset = "Sphere"
        d.ScaleByArray = 1
        d.SetScaleArray = ["POINTS", "radius"]
        d.UseScaleFunction = 0  # the radius itself, not a transfer function of it
        d.GaussianRadius = 1.0
        ColorBy(d, ("POINTS", field))
        lut = GetColorTransferFunction(field)
        lut.ApplyPreset(preset, True)
        top = top_of_range(servermanager, particles, field, last, 100.0 if field == "broken_fraction" else 99.0)
        lut.RescaleTransferFunction(0.0, top)
        GetOpacityTransferFunction(field).RescaleTransferFunction(0.0, top)
        lut.AutomaticRescaleRangeMode = "Never"
        d.SetScalarBarVisibility(view, True)
        bar = GetScalarBar(lut, view)
        bar.Title = title
        bar.ComponentTitle = ""
        bar.Orientation = "Horizontal"  # above the uncut surface ahead of the chip, off the block
        bar.WindowLocation = "Upper Right Corner"
        bar.TitleColor = [0.0, 0.0, 0.0]
        bar.LabelColor = [0.0, 0.0, 0.0]
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
