# SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
# SPDX-License-Identifier: BSD-3-Clause
"""pvbatch main_job.py PLUGIN SAMPLES.vtp OUTPUT_STEM: the filter on the paper's one-component
case (isovalue 0, seed sphere at (64, 64, 64) radius 12, default parameters), writing the
surface (oriented splats, the default output) to OUTPUT_STEM.vtp and a picture to
OUTPUT_STEM.png."""
import os
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
splats = surface.GetClientSideObject().GetOutputDataObject(0)
print("splats (one per isopoint): %d, iterations: %d, seconds: %.2f"
      % (splats.GetNumberOfPolys(), table.GetNumberOfRows(), seconds))
# Binary, not appended: Debian 12's ParaView 5.11 cannot read appended-mode XML.
SaveData(stem + ".vtp", proxy=surface, DataMode="Binary")
view = GetActiveViewOrCreate("RenderView")
display = Show(surface, view)
ColorBy(display, ("POINTS", "Normals", "Z"))
view.CameraPosition = [260.0, -160.0, 160.0]
view.CameraFocalPoint = [64.0, 64.0, 64.0]
view.CameraViewUp = [0.0, 0.0, 1.0]
ResetCamera(view)
Render(view)
SaveScreenshot(stem + ".png", view, ImageResolution=[800, 800])
print("wrote %s.vtp and %s.png" % (stem, stem))
sys.stdout.flush()
os._exit(0)  # skip the render window's teardown (it can raise an X error under Xvfb)
