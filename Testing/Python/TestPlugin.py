"""pvpython test: load the built plugin, run Level-Set Isosurface on a ball of particles and
check the three outputs against the exact sphere. Usage: pvpython TestPlugin.py PLUGIN.so"""
import math
import sys

import numpy as np
from paraview.simple import LoadPlugin, TrivialProducer
from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy
from vtkmodules.vtkCommonCore import vtkPoints
from vtkmodules.vtkCommonDataModel import vtkPolyData

LoadPlugin(sys.argv[1], ns=globals())

rng = np.random.default_rng(5)
x = rng.uniform(0.0, 60.0, (30000, 3))
radius = 18.0
f = radius - np.linalg.norm(x - 30.0, axis=1)
data = vtkPolyData()
points = vtkPoints()
points.SetData(numpy_to_vtk(x, deep=1))
data.SetPoints(points)
array = numpy_to_vtk(f, deep=1)
array.SetName("density")
data.GetPointData().AddArray(array)
source = TrivialProducer()
source.GetClientSideObject().SetOutput(data)

# IsoValue given as a keyword must survive (no reset to the range when Scalars is set).
surface = LevelSetIsosurface(Input=source, Scalars=["POINTS", "density"], IsoValue=0.0,
                             SeedCenter=[30, 30, 30], SeedRadius=6.0, AdditionalSeeds=[])
surface.UpdatePipeline()
failures = []
if surface.IsoValue != 0.0:
    failures.append("IsoValue keyword was overridden: %s" % surface.IsoValue)

algorithm = surface.GetClientSideObject()
isopoints = algorithm.GetOutputDataObject(0)
p = vtk_to_numpy(isopoints.GetPoints().GetData())
n = vtk_to_numpy(isopoints.GetPointData().GetArray("Normals"))
spacing = (60.0 ** 3 / len(x)) ** (1.0 / 3.0)
distance = np.abs(np.linalg.norm(p - 30.0, axis=1) - radius)
outward = np.einsum("ij,ij->i", n, (p - 30.0) / np.linalg.norm(p - 30.0, axis=1)[:, None])
print("isopoints %d, vertices %d, mean distance %.3f (spacing %.3f), mean cos(normal, radial) %.4f"
      % (len(p), isopoints.GetNumberOfVerts(), distance.mean(), spacing, outward.mean()))
if len(p) < 1000 or isopoints.GetNumberOfVerts() != len(p):
    failures.append("too few isopoints or not one vertex per point")
if distance.mean() > 0.35 * spacing:
    failures.append("isopoints off the sphere: mean distance %.3f" % distance.mean())
if np.abs(np.linalg.norm(n, axis=1) - 1).max() > 1e-5 or outward.mean() < 0.95:
    failures.append("normals not unit or not outward")

particles = algorithm.GetOutputDataObject(1)
phi = vtk_to_numpy(particles.GetPointData().GetArray("LevelSet"))
if particles.GetNumberOfPoints() != len(x) or particles.GetPointData().GetArray("density") is None:
    failures.append("particles output lacks the input points or arrays")
if np.mean(np.sign(phi) == np.sign(f)) < 0.99:
    failures.append("final level set sign disagrees with the data")

table = algorithm.GetOutputDataObject(2)
names = [table.GetColumnName(i) for i in range(table.GetNumberOfColumns())]
expected = ["Iteration", "SignMismatch", "MaxGradientDeviation", "MeanGradientDeviation",
            "BandSize", "Seconds"]
if names != expected or table.GetNumberOfRows() < 2:
    failures.append("convergence table columns %s rows %d" % (names, table.GetNumberOfRows()))
else:
    # The default start (flood) already agrees in sign with the data nearly everywhere; the
    # evolution must keep it so (P is the fraction of samples whose sign disagrees).
    mismatch = table.GetColumnByName("SignMismatch")
    last = mismatch.GetValue(table.GetNumberOfRows() - 1)
    if not last < 0.01:
        failures.append("SignMismatch %g at the end (>= 0.01)" % last)

for failure in failures:
    print("FAILED:", failure)
sys.exit(1 if failures else 0)
