# SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
# SPDX-License-Identifier: BSD-3-Clause
"""mpiexec -n 2 pvbatch TestReadersMPI.py PLUGIN SNAPSHOT_DIR SWIFT_FILE GLASS_FILE

Under MPI each rank reads its own share of a snapshot: the GADGET-4 snapshot in two files, its
particles as a GADGET-2 binary snapshot in two files, the SWIFT snapshot and the Tipsy glass, each read with the ranks' process ids attached and
gathered on rank 0. Checks that every rank read a part (none the whole), and that together they
read exactly the particles one rank reads: the same ids (or coordinates) once each.
Then regions of the SWIFT snapshot, one wrapped across its periodic box's faces: together
exactly its particles inside, each once.
Then Particle Density on the glass as read (each rank holding an interleaved share): every
particle's density must be the SPH summation over its 64 nearest among all the particles
(cubic spline, support out to the 64th), computed here with scipy. Last, Level-Set Isosurface
with no Scalars named (as pvbatch --symmetric leaves them) takes the snapshot's active scalars,
and after Distribute Points (which drops them) the density the field data names."""
import os
import sys

from paraview import servermanager
from paraview.simple import DistributePoints, LoadPlugin, OpenDataFile, ProcessIdScalars

plugin, snapshots, swift, glass = sys.argv[1:5]
LoadPlugin(plugin, ns=globals())
ranks = servermanager.vtkProcessModule.GetProcessModule().GetNumberOfLocalPartitions()
failures = []


def check(ok, what):
    print(("ok      " if ok else "FAILED  ") + what)
    if not ok:
        failures.append(what)


def keys(data):
    """Particle ids, or rounded coordinates for files without ids."""
    ids = data.GetPointData().GetArray("ParticleIDs")
    if ids is not None:
        return [int(ids.GetValue(i)) for i in range(ids.GetNumberOfTuples())]
    return [tuple(round(c, 7) for c in data.GetPoint(i)) for i in range(data.GetNumberOfPoints())]


for path, count in [(snapshots + "/gadget4_multi.0.hdf5", 50), (snapshots + "/snap_format1.0", 50),
                    (swift, 32768), (glass, 28721)]:
    reader = OpenDataFile(path)
    with_ranks = ProcessIdScalars(Input=reader)
    with_ranks.UpdatePipeline()
    data = servermanager.Fetch(with_ranks)
    owner = data.GetPointData().GetArray("ProcessId")
    per_rank = [0] * ranks
    for i in range(owner.GetNumberOfTuples()):
        per_rank[int(owner.GetValue(i))] += 1
    all_keys = keys(data)
    name = path.split("/")[-1]
    print("%s: %d ranks read %s particles" % (name, ranks, per_rank))
    check(ranks > 1 and all(0 < n < count for n in per_rank),
          "%s: every rank reads a part, none the whole" % name)
    check(len(all_keys) == count and len(set(all_keys)) == count,
          "%s: together the %d particles, each once" % (name, count))

# A region (ReadRegion, RegionBounds): each rank reads a share of the particles of the SWIFT
# snapshot's cells that overlap it; together exactly the particles inside, each once. Then a
# region across the faces of its periodic box (side 2 pi), wrapped (PeriodicRegion, on by
# default): the particles with an image inside.
whole = servermanager.Fetch(OpenDataFile(swift))
two_pi = 6.283185307179586
for region, period in (([1.0, 2.5, 1.0, 2.5, 1.0, 2.5], 0.0),
                       ([5.5, 7.5, 1.0, 2.5, -0.5, 0.5], two_pi)):
    reader = OpenDataFile(swift)
    reader.ReadRegion = 1
    reader.RegionBounds = region
    with_ranks = ProcessIdScalars(Input=reader)
    with_ranks.UpdatePipeline()
    data = servermanager.Fetch(with_ranks)
    owner = data.GetPointData().GetArray("ProcessId")
    per_rank = [sum(1 for i in range(owner.GetNumberOfTuples()) if int(owner.GetValue(i)) == r)
                for r in range(ranks)]
    shifts = (-1, 0, 1) if period else (0,)
    expected = set(k for k, p in zip(keys(whole), (whole.GetPoint(i)
                                                   for i in range(whole.GetNumberOfPoints())))
                   if all(any(region[2 * a] <= p[a] + n * period <= region[2 * a + 1]
                              for n in shifts) for a in range(3)))
    got = keys(data)
    print("SWIFT region %s: %d ranks read %s particles, %d inside"
          % (region, ranks, per_rank, len(expected)))
    check(len(expected) > 0 and len(got) == len(expected) and set(got) == expected and
          all(n > 0 for n in per_rank),
          "SWIFT region %s%s: every rank reads a part, together the particles inside, each once"
          % (region, ", wrapped" if period else ""))

# Particle Density on the ranks' interleaved shares of the glass, against the summation density
# over all the particles.
import numpy as np  # noqa: E402
from scipy.spatial import cKDTree  # noqa: E402
from vtkmodules.util.numpy_support import vtk_to_numpy  # noqa: E402

density = servermanager.Fetch(ParticleDensity(Input=OpenDataFile(glass), NumberOfNeighbors=64))
x = vtk_to_numpy(density.GetPoints().GetData()).astype(float)
rho = vtk_to_numpy(density.GetPointData().GetArray("Density"))
mass_name = density.GetFieldData().GetAbstractArray("MassArray").GetValue(0)
mass = vtk_to_numpy(density.GetPointData().GetArray(mass_name)).astype(float)
distance, nearest = cKDTree(x).query(x, k=64)
H = distance[:, -1]
q = distance / H[:, None]
W = 8.0 / (np.pi * H[:, None] ** 3) * np.where(q <= 0.5, 1.0 - 6.0 * q ** 2 + 6.0 * q ** 3,
                                               2.0 * np.clip(1.0 - q, 0.0, None) ** 3)
expected = np.sum(mass[nearest] * W, axis=1)
worst = float(np.max(np.abs(rho / expected - 1.0))) if len(x) == 28721 else float("inf")
print("Particle Density on %d ranks: %d particles, largest relative difference to the "
      "summation over all particles %.3g" % (ranks, len(x), worst))
check(worst <= 1e-9, "Particle Density: every particle's density as from all the particles")

# Level-Set Isosurface with no Scalars named (as pvbatch --symmetric leaves the property): the
# snapshot's active scalars (its density), on each rank's share and its ghosts, the same surface
# as with the density named; after Distribute Points, which drops the active scalars but keeps
# the field data, the density the reader names there (DensityArray).
blob_points = []
for scalars, distribute in ((["POINTS", "Density"], False), (["POINTS", ""], False),
                            (["POINTS", ""], True)):
    source = OpenDataFile(os.path.join(snapshots, "periodic_blob.hdf5"))
    if distribute:
        source = DistributePoints(Input=source)
    blob = LevelSetIsosurface(Input=source, IsoValue=float(np.exp(-0.5)),
                              SeedCenter=[0.01, 0.01, 0.01], SeedRadius=0.02,
                              OutputType="Isopoints")
    blob.Scalars = scalars
    blob.UpdatePipeline()
    blob_points.append(servermanager.Fetch(blob).GetNumberOfPoints())
print("periodic blob on %d ranks, Scalars named, not, not after Distribute Points: %s points"
      % (ranks, blob_points))
check(blob_points[0] == blob_points[1] > 200,
      "Level-Set Isosurface with no Scalars named: the active scalars, the named run's surface")
check(blob_points[2] == blob_points[0],
      "no Scalars named after Distribute Points: the field data's DensityArray, the same surface")

print("%d failures" % len(failures))
# On success pvbatch must finalise MPI on every rank: no sys.exit. On failure, end the process
# at once: mpiexec then stops the other ranks and returns non-zero (an exception would leave
# them waiting in MPI_Finalize).
if failures:
    sys.stdout.flush()
    os._exit(1)
