# SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
# SPDX-License-Identifier: BSD-3-Clause
"""mpiexec -n 2 pvbatch TestReadersMPI.py PLUGIN SNAPSHOT_DIR SWIFT_FILE GLASS_FILE

Under MPI each rank reads its own share of a snapshot: the GADGET-4 snapshot in two files, the
SWIFT snapshot and the Tipsy glass, each read with the ranks' process ids attached and
gathered on rank 0. Checks that every rank read a part (none the whole), and that together they
read exactly the particles one rank reads: the same ids (or coordinates) once each."""
import os
import sys

from paraview import servermanager
from paraview.simple import LoadPlugin, OpenDataFile, ProcessIdScalars

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


for path, count in [(snapshots + "/gadget4_multi.0.hdf5", 50), (swift, 32768), (glass, 28721)]:
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

print("%d failures" % len(failures))
# On success pvbatch must finalise MPI on every rank: no sys.exit. On failure, end the process
# at once: mpiexec then stops the other ranks and returns non-zero (an exception would leave
# them waiting in MPI_Finalize).
if failures:
    sys.stdout.flush()
    os._exit(1)
