# SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
# SPDX-License-Identifier: BSD-3-Clause
"""pvbatch gallery.py PLUGIN DATA_DIR GLASS_FILE GALAXY_FILE OUT_DIR: the README's gallery.

- one-component: the paper's field (§8.2) at 2M samples, the default splat surface;
- multi-component: our multi-component field at 2M samples, seeded in two of its blobs: the
  extracted components in colour, the exact isosurface of all components in faint grey (what
  the seeds did not touch stays out);
- evrard: the Evrard collapse glass (28,721 real SPH particles, Data/ChaNGa). Its density is
  estimated from the particles by the plugin's Particle Density filter (SPH summation, cubic
  spline over each particle's 64 nearest neighbours), the isosurface is that density at 1/pi (where the analytic profile
  rho = 1/(2 pi r) puts the sphere r = 0.5), coloured by the distance from the centre: the
  colour shows where the particle estimate departs from the exact sphere;
- galaxy: the dark matter of a ChaNGa galaxy snapshot (3,627 particles, Data/ChaNGa), which
  carries no density: Particle Density, then the level set at the median density seeded at the
  centre of mass, coloured by the particles' speed interpolated onto the surface.

DATA_DIR holds one_component_2M.vtp, multi_component_2M.vtp and multi_component_exact.vtp from
LevelSetGenerateData (Scripts/make-gallery.sh makes them)."""
import math
import os
import sys

import numpy as np
from paraview import servermanager
from paraview.simple import (Calculator, ColorBy, CreateView, GetColorTransferFunction,
                             GetScalarBar, LoadPlugin, Render, SaveScreenshot, Show,
                             XMLPolyDataReader)
from vtkmodules.util.numpy_support import vtk_to_numpy

plugin, data_dir, glass_file, galaxy_file, out_dir = sys.argv[1:6]
LoadPlugin(plugin, ns=globals())


def new_view(position, focal, up=(0, 0, 1)):
    view = CreateView("RenderView")
    view.ViewSize = [900, 700]
    view.OrientationAxesVisibility = 0
    view.UseColorPaletteForBackground = 0
    view.Background = [1.0, 1.0, 1.0]
    view.CameraPosition, view.CameraFocalPoint, view.CameraViewUp = position, focal, up
    return view


def solid(display, rgb):
    display.ColorArrayName = ["POINTS", ""]
    display.DiffuseColor = display.AmbientColor = rgb
    display.Specular = 0.3


def save(view, name):
    Render(view)
    view.ResetCamera()
    view.CameraParallelScale = view.CameraParallelScale * 0.8
    Render(view)
    path = os.path.join(out_dir, name)
    SaveScreenshot(path, view, ImageResolution=[900, 700])
    print("wrote", path)


# One component.
particles = XMLPolyDataReader(FileName=[os.path.join(data_dir, "one_component_2M.vtp")])
surface = LevelSetIsosurface(Input=particles, Scalars=["POINTS", "f"], IsoValue=0.0,
                             SeedCenter=[64, 64, 64], SeedRadius=12.0)
view = new_view([260, -160, 160], [64, 64, 64])
solid(Show(surface, view), [0.95, 0.62, 0.25])
save(view, "gallery_one_component.png")

# Multi component, two seeds.
particles = XMLPolyDataReader(FileName=[os.path.join(data_dir, "multi_component_2M.vtp")])
exact = XMLPolyDataReader(FileName=[os.path.join(data_dir, "multi_component_exact.vtp")])
seeds = [float(v) for v in os.environ["LSI_MULTI_SEEDS"].split(",")]
surface = LevelSetIsosurface(Input=particles, Scalars=["POINTS", "f"],
                             IsoValue=float(os.environ["LSI_MULTI_ISO"]),
                             SeedCenter=seeds[0:3], SeedRadius=seeds[3],
                             AdditionalSeeds=seeds[4:])
view = new_view([300, -200, 220], [64, 64, 64])
ghost = Show(exact, view)
solid(ghost, [0.6, 0.6, 0.6])
ghost.Opacity = 0.25
solid(Show(surface, view), [0.25, 0.55, 0.85])
save(view, "gallery_multi_component.png")

# Evrard glass: SPH-summation density of the real particles.
glass = TipsyParticleReader(FileNames=[glass_file])
density = ParticleDensity(Input=glass)
radius = Calculator(Input=density, ResultArrayName="radius", Function="mag(coords)")
surface = LevelSetIsosurface(Input=radius, Scalars=["POINTS", "Density"],
                             IsoValue=1.0 / math.pi, SeedCenter=[0, 0, 0], SeedRadius=0.2)
surface.UpdatePipeline()
out = surface.GetClientSideObject().GetOutputDataObject(0)
r = vtk_to_numpy(out.GetPointData().GetArray("radius"))
print("evrard: %d particles, %d splats; SPH-density isosurface at 1/pi: radius %.4f +- %.4f "
      "(exact sphere 0.5)" % (servermanager.Fetch(glass).GetNumberOfPoints(),
                              out.GetNumberOfPolys(), r.mean(), r.std()))
view = new_view([2.0, -1.6, 1.2], [0, 0, 0])
display = Show(surface, view)
ColorBy(display, ("POINTS", "radius"))
lut = GetColorTransferFunction("radius")
lut.ApplyPreset("Cool to Warm", True)
# Centred on the exact radius, wide enough for the surface's spread.
spread = max(4 * r.std(), abs(r.mean() - 0.5) + 2 * r.std())
lut.RescaleTransferFunction(0.5 - spread, 0.5 + spread)
display.SetScalarBarVisibility(view, True)
bar = GetScalarBar(lut, view)
bar.Title, bar.ComponentTitle = "distance from the centre", ""
bar.TitleColor = bar.LabelColor = [0.0, 0.0, 0.0]
save(view, "gallery_evrard.png")

# A galaxy's dark matter: no density in the file; Particle Density, then the level set.
galaxy = TipsyParticleReader(FileNames=[galaxy_file])
density = ParticleDensity(Input=galaxy)
speed = Calculator(Input=density, ResultArrayName="speed", Function="mag(velocity)")
speed.UpdatePipeline()
data = servermanager.Fetch(speed)
x = vtk_to_numpy(data.GetPoints().GetData()).astype(np.float64)
m = vtk_to_numpy(data.GetPointData().GetArray("mass")).astype(np.float64)
centre = list((x * m[:, None]).sum(axis=0) / m.sum())
median = float(np.median(vtk_to_numpy(data.GetPointData().GetArray("Density"))))
surface = LevelSetIsosurface(Input=speed, Scalars=["POINTS", "Density"], IsoValue=median,
                             SeedCenter=centre, SeedRadius=0.3)  # the Calculator made speed active
surface.UpdatePipeline()
out = surface.GetClientSideObject().GetOutputDataObject(0)
print("galaxy: %d dark-matter particles, density isosurface at the median %.4g: %d splats"
      % (len(x), median, out.GetNumberOfPolys()))
view = new_view([3.0, -4.5, 3.5], centre)
display = Show(surface, view)
ColorBy(display, ("POINTS", "speed"))
lut = GetColorTransferFunction("speed")
lut.ApplyPreset("Viridis (matplotlib)", True)
display.SetScalarBarVisibility(view, True)
bar = GetScalarBar(lut, view)
bar.Title, bar.ComponentTitle = "speed", ""
bar.TitleColor = bar.LabelColor = [0.0, 0.0, 0.0]
save(view, "gallery_galaxy.png")
sys.stdout.flush()
os._exit(0)  # skip the render windows' teardown (it can raise an X error under Xvfb)
