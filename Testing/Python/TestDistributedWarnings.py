# SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
# SPDX-License-Identifier: BSD-3-Clause
"""mpiexec -n 3 pvbatch TestDistributedWarnings.py PLUGIN SWIFT_FILE CASE: one of the cases that
TestDistributedWarnings.sh checks, each in a run of its own (so that every warning of the run is
the case's): heavy, the surface with 3 times the masses, or right, with the file's; each against
Field = MLS."""
import sys

import numpy as np
from paraview import servermanager
from paraview.simple import Calculator, LoadPlugin, OpenDataFile
from vtkmodules.util.numpy_support import vtk_to_numpy
LoadPlugin(sys.argv[1], ns=globals())
reader = OpenDataFile(sys.argv[2])
reader.UpdatePipelineInformation()
reader.ParticleTypes = ["Gas (PartType0)"]
vz = Calculator(Input=reader, ResultArrayName="VelocityZ", Function="Velocities_Z")
particles = servermanager.Fetch(vz)
values = vtk_to_numpy(particles.GetPointData().GetArray("VelocityZ"))
seed = [float(c) for c in vtk_to_numpy(particles.GetPoints().GetData())[np.argmax(values)]]
heavy = Calculator(Input=vz, ResultArrayName="Masses", Function="3*Masses")


def surface(source, field):
    result = LevelSetIsosurface(  # noqa: F821
        Input=source, Scalars=["POINTS", "VelocityZ"], IsoValue=0.7,
        SeedCenter=seed, Field=field, OutputType="Isopoints")
    result.UpdatePipeline()
    points = servermanager.Fetch(result).GetPoints()
    points = vtk_to_numpy(points.GetData()) if points is not None else np.zeros((0, 3))
    return points[np.lexsort(points.T)]


def difference(a, b):
    return float(np.max(np.abs(a - b))) if a.shape == b.shape and len(a) else float("inf")


name = sys.argv[3]
source = {"heavy": heavy, "right": vz}[name]
automatic = surface(source, "Automatic")
fit = surface(source, "MLS fit of the samples")
print("CASE %s: %d and %d points, largest difference %.3g" % (
    name, len(automatic), len(fit), difference(automatic, fit)), flush=True)
