# SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
# SPDX-License-Identifier: BSD-3-Clause
"""Rendering test (pvbatch under xvfb-run): the surface is shaded by its normals, in both output
types, as ParaView draws them by default (the Surface representation).

  pvbatch TestShading.py PLUGIN TIPSY_FILE OUT_DIR [POINT_SIZE_FACTOR]

The Evrard collapse glass (Data/ChaNGa) has density rho(r) = 1 / (2 pi r), so the isosurface
rho = 1 / pi is the sphere r = 0.5. Seen along -z with a parallel camera and a single white
headlight, a white, purely diffuse (Lambert) sphere has brightness n_z = sqrt(1 - (x^2 + y^2) /
R^2) at screen position (x, y). The test compares every pixel within 0.9 R of the centre with
that value:
- splats (the default output);
- isopoints, drawn as lit points whose Point Size is POINT_SIZE_FACTOR (default 1.3) times the
  mean SplatRadius in pixels (points much smaller leave holes, much larger show their flat
  squares: 1.15 to 1.5 pass, 1.0 and 1.8 fail).
At least 99% of the pixels must lie within 0.1 of n_z. Unlit points (all one brightness),
inward normals (black) or holes (black background) fail it.

ParaView's own Points representation is not tested: it draws points unlit by design (it sets
ambient 1, diffuse 0 unless Render Points As Spheres is on), whatever their normals."""
import math
import os
import sys

import numpy as np
from paraview.simple import (AddLight, Calculator, CreateView, LoadPlugin, Render,
                             SaveScreenshot, Show)
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkIOImage import vtkPNGReader

plugin, tipsy_file, out_dir = sys.argv[1:4]
point_size_factor = float(sys.argv[4]) if len(sys.argv) > 4 else 1.3
LoadPlugin(plugin, ns=globals())
RADIUS = 0.5
HALF_WIDTH = 0.6  # world units from the image centre to its edge
PIXELS = 400

glass = TipsyParticleReader(FileNames=[tipsy_file])
density = Calculator(Input=glass, ResultArrayName="density",
                     Function="1 / (2 * %.17g * mag(coords))" % math.pi)

view = CreateView("RenderView")
view.ViewSize = [PIXELS, PIXELS]
view.OrientationAxesVisibility = 0
view.UseColorPaletteForBackground = 0
view.Background = [0.0, 0.0, 0.0]
view.UseLight = 0  # no light kit: one headlight of intensity 1
headlight = AddLight(view=view)
headlight.Coords = "Headlight"
headlight.Intensity = 1.0


def brightness(path):
    reader = vtkPNGReader()
    reader.SetFileName(path)
    reader.Update()
    pixels = vtk_to_numpy(reader.GetOutput().GetPointData().GetScalars())
    return pixels[:, :3].mean(axis=1).reshape(PIXELS, PIXELS) / 255.0  # row 0 at the bottom


centres = (np.arange(PIXELS) + 0.5) / PIXELS * 2 * HALF_WIDTH - HALF_WIDTH
x, y = np.meshgrid(centres, centres)
r2 = (x * x + y * y) / (RADIUS * RADIUS)
compared = r2 < 0.81
lambert = np.sqrt(np.clip(1.0 - r2, 0.0, 1.0))

failures = []
for output_type in ("Splats", "Isopoints"):
    surface = LevelSetIsosurface(Input=density, Scalars=["POINTS", "density"],
                                 IsoValue=1.0 / math.pi, SeedCenter=[0, 0, 0], SeedRadius=0.2,
                                 OutputType=output_type)
    surface.UpdatePipeline()
    display = Show(surface, view)
    display.Representation = "Surface"
    display.ColorArrayName = ["POINTS", ""]
    display.AmbientColor = display.DiffuseColor = [1.0, 1.0, 1.0]
    display.Ambient, display.Diffuse, display.Specular = 0.0, 1.0, 0.0
    if output_type == "Isopoints":
        radii = surface.GetClientSideObject().GetOutputDataObject(0).GetPointData().GetArray(
            "SplatRadius")
        mean_radius = float(vtk_to_numpy(radii).mean())
        display.PointSize = point_size_factor * mean_radius * PIXELS / (2 * HALF_WIDTH)
        print("isopoints: point size %.1f pixels" % display.PointSize)
    Render(view)
    view.CameraParallelProjection = 1
    view.CameraPosition = [0, 0, 10]
    view.CameraFocalPoint = [0, 0, 0]
    view.CameraViewUp = [0, 1, 0]
    view.CameraParallelScale = HALF_WIDTH
    path = os.path.join(out_dir, "shading_%s.png" % output_type.lower())
    Render(view)
    SaveScreenshot(path, view, ImageResolution=[PIXELS, PIXELS])
    error = np.abs(brightness(path) - lambert)[compared]
    within = float((error < 0.1).mean())
    print("%-9s: %d pixels, |brightness - n_z| median %.3f, 95th percentile %.3f, "
          "within 0.1: %.4f" % (output_type, error.size, np.median(error),
                                np.percentile(error, 95), within))
    if within < 0.99:
        failures.append("%s: only %.4f of the pixels shaded within 0.1 of Lambert's law"
                        % (output_type, within))
    display.Visibility = 0

for failure in failures:
    print("FAILED:", failure)
sys.stdout.flush()
# As in TestSplatCoverage.py: leave without tearing down the render window under Xvfb.
os._exit(1 if failures else 0)
