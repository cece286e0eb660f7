# SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
# SPDX-License-Identifier: BSD-3-Clause
"""pvbatch gallery.py PLUGIN DATA_DIR GLASS_FILE OUT_DIR: the README's gallery.

- one-component: the paper's field (§8.2) at 2M samples, the default splat surface;
- multi-component: our multi-component field at 2M samples, seeded in two of its blobs: the
  extracted components in colour, the exact isosurface of all components in faint grey (what
  the seeds did not touch stays out);
- evrard: the Evrard collapse glass (28,721 real SPH particles, Data/ChaNGa). Its density is
  estimated from the particles by SPH summation (cubic-spline kernel over each particle's 64
  nearest neighbours), the isosurface is that density at 1/pi (where the analytic profile
  rho = 1/(2 pi r) puts the sphere r = 0.5), coloured by the distance from the centre: the
  colour shows where the particle estimate departs from the exact sphere.

DATA_DIR holds one_component_2M.vtp, multi_component_2M.vtp and multi_component_exact.vtp from
LevelSetGenerateData (Scripts/make-gallery.sh makes them)."""
import math
import os
import sys

import numpy as np
from scipy.spatial import cKDTree
from paraview import servermanager
from paraview.simple import (ColorBy, CreateView, GetColorTransferFunction, GetScalarBar, LoadPlugin, Render,
                             SaveScreenshot, Show, TrivialProducer, XMLPolyDataReader)
from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy
from vtkmodules.vtkCommonCore import vtkPoints
from vtkmodules.vtkCommonDataModel import vtkPolyData

plugin, data_dir, glass_file, out_dir = sys.argv[1:5]
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
data = servermanager.Fetch(glass)
x = vtk_to_numpy(data.GetPoints().GetData()).astype(np.float64)
mass = vtk_to_numpy(data.GetPointData().GetArray("mass")).astype(np.float64)
distances, neighbours = cKDTree(x).query(x, k=64)
h = distances[:, -1] / 2.0  # the cubic spline reaches 2h: 64 neighbours inside
q = distances / h[:, None]
w = np.where(q < 1, 1 - 1.5 * q**2 + 0.75 * q**3, np.where(q < 2, 0.25 * (2 - q)**3, 0.0))
density = (mass[neighbours] * w).sum(axis=1) / (math.pi * h**3)
cloud = vtkPolyData()
cloud.ShallowCopy(data)
for name, values in (("sph_density", density), ("radius", np.linalg.norm(x, axis=1))):
    array = numpy_to_vtk(values, deep=1)
    array.SetName(name)
    cloud.GetPointData().AddArray(array)
source = TrivialProducer()
source.GetClientSideObject().SetOutput(cloud)
surface = LevelSetIsosurface(Input=source, Scalars=["POINTS", "sph_density"],
                             IsoValue=1.0 / math.pi, SeedCenter=[0, 0, 0], SeedRadius=0.2)
surface.UpdatePipeline()
out = surface.GetClientSideObject().GetOutputDataObject(0)
r = vtk_to_numpy(out.GetPointData().GetArray("radius"))
print("evrard: %d particles, %d splats; SPH-density isosurface at 1/pi: radius %.4f +- %.4f "
      "(exact sphere 0.5)" % (len(x), out.GetNumberOfPolys(), r.mean(), r.std()))
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
sys.stdout.flush()
os._exit(0)  # skip the render windows' teardown (it can raise an X error under Xvfb)
