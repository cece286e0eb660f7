"""Run inside the ParaView GUI: paraview --script=GuiSmoke.py --exit (under xvfb-run), with
LSI_PLUGIN and LSI_SCREENSHOT in the environment. Loads the plugin, applies the filter through
the GUI's Python, shows the isopoints and saves a screenshot."""
import os

from paraview.simple import (GetActiveViewOrCreate, LoadPlugin, MaskPoints, Render, ResetCamera,
                             SaveScreenshot, Show, Wavelet)

LoadPlugin(os.environ["LSI_PLUGIN"], ns=globals())
# Particles: a random subset of the Wavelet source's grid points, with the RTData scalar.
wavelet = Wavelet(WholeExtent=[-15, 15, -15, 15, -15, 15])
particles = MaskPoints(Input=wavelet, OnRatio=2, RandomSampling=1, GenerateVertices=1,
                       MaximumNumberofPoints=20000)
surface = LevelSetIsosurface(Input=particles, Scalars=["POINTS", "RTData"], SeedCenter=[0, 0, 0],
                             SeedRadius=5.0)
surface.IsoValue = 200.0
view = GetActiveViewOrCreate("RenderView")
display = Show(surface, view)
ResetCamera(view)
Render(view)
SaveScreenshot(os.environ["LSI_SCREENSHOT"], view, ImageResolution=[640, 480])
