# SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
# SPDX-License-Identifier: BSD-3-Clause
"""mpiexec -n N pvbatch --symmetric distributed_benchmark.py PLUGIN DATA.vtp THREADS OUT.json

One timed run of the filter on the paper's case under N ranks x THREADS threads: the .vtp is read
by rank 0 and spread with Distribute Points (not timed, as a parallel reader would give it), then
Level-Set Isosurface (Isopoints, NumberOfThreads = THREADS, QuickIsoValueChanges) is timed, then
a move of its seed within the same component, then a 2% isovalue change, then a CurvatureWeight
change (a full re-run on the same particles). Writes, per rank: the filter's seconds, its
seconds in communication (waiting for slower ranks included), in the seeds and the flood
(across the ranks) and in the other stages of the first run, its particles, and the peak
resident memory of the process; and the ghost fraction."""
import json
import resource
import sys
import time

import numpy as np

from paraview import servermanager
from paraview.simple import DistributePoints, LoadPlugin, XMLPolyDataReader
from vtkmodules.vtkCommonCore import vtkDoubleArray
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkIOXML import vtkXMLPolyDataReader
from vtkmodules.vtkParallelCore import vtkMultiProcessController

plugin, path, threads, out = sys.argv[1], sys.argv[2], int(sys.argv[3]), sys.argv[4]
LoadPlugin(plugin, ns=globals())
controller = vtkMultiProcessController.GetGlobalController()
rank, ranks = controller.GetLocalProcessId(), controller.GetNumberOfProcesses()

source = DistributePoints(Input=XMLPolyDataReader(FileName=[path])) if ranks > 1 else \
    XMLPolyDataReader(FileName=[path])
source.UpdatePipeline()
before = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024.0
surface = LevelSetIsosurface(Input=source, Scalars=["POINTS", "f"], IsoValue=0.0,
                             SeedCenter=[64, 64, 64], SeedRadius=12.0, CurvatureWeight=0.15,
                             OutputType="Isopoints", NumberOfThreads=threads,
                             QuickIsoValueChanges=1)
# The isovalue with 2% fewer particles above it than 0 (rank 0 reads the file, all use it).
new_iso = vtkDoubleArray()
new_iso.SetNumberOfTuples(1)
if rank == 0:
    reader = vtkXMLPolyDataReader()
    reader.SetFileName(path)
    reader.Update()
    f = vtk_to_numpy(reader.GetOutput().GetPointData().GetArray("f"))
    above = np.sort(f[f > 0.0])
    new_iso.SetValue(0, float(above[int(0.02 * len(above))]))
    del reader, f, above
controller.Broadcast(new_iso, 0)
controller.Barrier()
start = time.time()
surface.UpdatePipeline()
seconds = time.time() - start
controller.Barrier()
wall = time.time() - start
surface.UpdatePropertyInformation()
isopoints = surface.GetProperty("NumberOfIsopoints").GetElement(0)
ghost_fraction = surface.GetProperty("GhostFraction").GetElement(0)
# This rank's seeds and flood (across the ranks) in the first run: the filter reports it under
# MPI only (-1 where it does not: one rank, or a build before it).
first_run_fields = surface.GetClientSideObject().GetOutputDataObject(1).GetFieldData()
initialisation = first_run_fields.GetArray("InitializationSeconds").GetValue(0) \
    if first_run_fields.GetArray("InitializationSeconds") else -1.0
# And its other stages (-1 where not reported); what they leave of the filter's seconds is the
# spreading of the particles and the ghosts' exchange (with the neighbour search before it).
STAGES = ["Input", "NeighborSearch", "Evolution", "Isopoint", "Output"]
stages = [first_run_fields.GetArray(name + "Seconds").GetValue(0)
          if first_run_fields.GetArray(name + "Seconds") else -1.0 for name in STAGES]


def timed_rerun():
    """A re-run on every rank: its wall seconds, from the first rank's start to the last's end."""
    controller.Barrier()
    begin = time.time()
    surface.UpdatePipeline()
    controller.Barrier()
    elapsed = time.time() - begin
    surface.UpdatePropertyInformation()
    return elapsed


# Then the seed moved within its component (issue 16): the same flood, so every rank hands on
# its last outputs.
surface.SeedCenter = [66, 64, 64]
seed_move = timed_rerun()
seed_move_reused = surface.GetProperty("ReusedLastOutputs").GetElement(0)
# Then a 2% isovalue change (QuickIsoValueChanges): every rank slides its surface.
surface.IsoValue = new_iso.GetValue(0)
iso_change = timed_rerun()
iso_change_slid = surface.GetProperty("SlidLastSurface").GetElement(0)
# Then CurvatureWeight doubled: the method runs in full, on the same particles (outside a
# periodic box every rank keeps its ghosts, their neighbourhoods and the flood).
floods = surface.GetProperty("FloodCount").GetElement(0)
surface.CurvatureWeight = 0.3
curvature_change = timed_rerun()
curvature_floods = surface.GetProperty("FloodCount").GetElement(0) - floods
local = surface.GetClientSideObject().GetOutputDataObject(1).GetFieldData()
communication = local.GetArray("CommunicationSeconds")
mine = [seconds, communication.GetValue(0) if communication else 0.0,
        source.GetClientSideObject().GetOutputDataObject(0).GetNumberOfPoints(), before,
        resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024.0, initialisation] + stages
send, receive = vtkDoubleArray(), vtkDoubleArray()
for value in mine:
    send.InsertNextValue(value)
controller.Gather(send, receive, 0)
if rank == 0:
    values = len(mine)
    per_rank = [[receive.GetValue(values * r + k) for k in range(values)] for r in range(ranks)]
    result = {
        "ranks": ranks, "threads": threads, "seconds": wall,
        "isopoints": isopoints,
        "ghost_fraction": ghost_fraction,
        "seed_move_seconds": seed_move,
        "seed_move_reused": seed_move_reused,
        "isovalue_change_seconds": iso_change,
        "isovalue_change_slid": iso_change_slid,
        "curvature_weight_change_seconds": curvature_change,
        "curvature_weight_change_floods": curvature_floods,
        "per_rank": [{"filter_seconds": p[0], "communication_seconds": p[1], "particles": int(p[2]),
                      "peak_MB_before_filter": p[3], "peak_MB": p[4],
                      "initialisation_seconds": p[5] if p[5] >= 0.0 else None,
                      "stage_seconds": {name: p[6 + k] for k, name in enumerate(STAGES)
                                        if p[6 + k] >= 0.0}}
                     for p in per_rank],
    }
    print("%d rank(s) x %d thread(s): %.2f s, %d isopoints, ghosts %.1f%% of the particles"
          % (ranks, threads, wall, result["isopoints"], 100 * result["ghost_fraction"]))
    print("  seed moved within its component: %.3f s (%.1f%% of the first run), outputs %s"
          % (seed_move, 100 * seed_move / wall,
             "handed on" if result["seed_move_reused"] else "recomputed"))
    print("  isovalue 2%% change: %.3f s (%.1f%% of the first run), surface %s"
          % (iso_change, 100 * iso_change / wall,
             "slid" if result["isovalue_change_slid"] else "recomputed"))
    print("  CurvatureWeight change: %.3f s (%.1f%% of the first run), %d flood(s)"
          % (curvature_change, 100 * curvature_change / wall, curvature_floods))
    for r, p in enumerate(result["per_rank"]):
        flood = p["initialisation_seconds"]
        print("  rank %d: %d particles, filter %.2f s of which communication %.2f s and seeds "
              "and flood %s, peak memory %.0f MB (%.0f MB before the filter)"
              % (r, p["particles"], p["filter_seconds"], p["communication_seconds"],
                 "%.2f s" % flood if flood is not None else "not reported", p["peak_MB"],
                 p["peak_MB_before_filter"]))
        if p["stage_seconds"]:
            print("    stages: " + ", ".join("%s %.2f s" % (name, seconds)
                                          for name, seconds in p["stage_seconds"].items()))
    with open(out, "w") as f:
        json.dump(result, f, indent=1)
