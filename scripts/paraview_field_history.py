#!/usr/bin/pvbatch
"""Opens a run's field history (DIR/results.xdmf) in ParaView and saves a screenshot of its last
frame coloured by the plastic strain (docs/outputs.md, "Field history").

    xvfb-run -a pvbatch scripts/paraview_field_history.py DIR OUT.png

Both of ParaView's XDMF readers ("XDMF Reader" and "Xdmf3 Reader S") must find every frame of
/frame_time with all its particles; the script prints what each read and exits 1 otherwise.
"""
import os
import sys

import paraview.simple as pv

pv._DisableFirstRenderCameraReset()
d, png = sys.argv[1], sys.argv[2]
xdmf = d + "/results.xdmf"
ok = True
readers = [("XDMF Reader", pv.XDMFReader(FileNames=[xdmf])), ("Xdmf3 Reader S", pv.Xdmf3ReaderS(FileName=[xdmf]))]
counts = set()
for name, r in readers:
    r.UpdatePipelineInformation()
    times = list(r.TimestepValues)
    r.UpdatePipeline(times[-1])
    info = r.GetDataInformation()
    arrays = sorted(a.GetName() for a in r.PointData)
    print(f"{name}: {len(times)} times, last {times[-1]:.6g} s; {info.GetNumberOfPoints()} points; arrays {arrays}")
    counts.add((len(times), info.GetNumberOfPoints()))
    ok = ok and info.GetNumberOfPoints() > 0 and "id" in arrays
if len(counts) != 1:
    print("the two readers disagree")
    ok = False

r = readers[0][1]
times = list(r.TimestepValues)
view = pv.GetActiveViewOrCreate("RenderView")
view.ViewSize = [1000, 500]
view.ViewTime = times[-1]
disp = pv.Show(r, view)
disp.SetRepresentationType("Points")
disp.PointSize = 4
pv.ColorBy(disp, ("POINTS", "plastic_strain"))
pv.GetColorTransferFunction("plastic_strain").ApplyPreset("Viridis (matplotlib)", True)
disp.SetScalarBarVisibility(view, True)
pv.Show(pv.Text(Text=f"results.xdmf, t = {times[-1] * 1e6:.3g} us (frame {len(times)} of {len(times)})"), view)
# Along -y onto the x-z plane, 0.6 mm high around the tool's edge of the default cut at 10 us.
view.CameraPosition = [0.2e-3, -3e-3, 0.35e-3]
view.CameraFocalPoint = [0.2e-3, 0.0, 0.35e-3]
view.CameraViewUp = [0, 0, 1]
view.CameraParallelProjection = 1
view.CameraParallelScale = 0.3e-3
pv.Render(view)
pv.SaveScreenshot(png, view, ImageResolution=[1000, 500])
print("wrote", png, flush=True)
# (os._exit: ParaView's teardown under xvfb-run fails with GLXBadContext after the work is done)
os._exit(0 if ok else 1)
