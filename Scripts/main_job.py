"""pvbatch main_job.py PLUGIN SAMPLES.vtp OUTPUT_STEM: the filter on the paper's one-component
case (isovalue 0, seed sphere at (64, 64, 64) radius 12, default parameters), writing
OUTPUT_STEM.vtp and OUTPUT_STEM.png."""
import sys
import time

from paraview.simple import (ColorBy, GetActiveViewOrCreate, LoadPlugin, Render, ResetCamera,
                             SaveData, SaveScreenshot, Show, XMLPolyDataReader)

plugin, samples, stem = sys.argv[1:4]
LoadPlugin(plugin, ns=globals())
particles = XMLPolyDataReader(FileName=[samples])
surface = LevelSetIsosurface(Input=particles, Scalars=["POINTS", "f"], IsoValue=0.0,
                             SeedCenter=[64.0, 64.0, 64.0], SeedRadius=12.0)
start = time.time()
surface.UpdatePipeline()
seconds = time.time() - start
table = surface.GetClientSideObject().GetOutputDataObject(2)
isopoints = surface.GetClientSideObject().GetOutputDataObject(0)
print("isopoints: %d, iterations: %d, seconds: %.2f"
      % (isopoints.GetNumberOfPoints(), table.GetNumberOfRows(), seconds))
# Binary, not appended: Debian 12's ParaView 5.11 cannot read appended-mode XML.
SaveData(stem + ".vtp", proxy=surface, DataMode="Binary")
view = GetActiveViewOrCreate("RenderView")
display = Show(surface, view)
ColorBy(display, ("POINTS", "Normals", "Z"))
display.PointSize = 3.0
view.CameraPosition = [260.0, -160.0, 160.0]
view.CameraFocalPoint = [64.0, 64.0, 64.0]
view.CameraViewUp = [0.0, 0.0, 1.0]
ResetCamera(view)
Render(view)
SaveScreenshot(stem + ".png", view, ImageResolution=[800, 800])
print("wrote %s.vtp and %s.png" % (stem, stem))
