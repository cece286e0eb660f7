# SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
# SPDX-License-Identifier: BSD-3-Clause
"""The same surface on any number of MPI ranks.

  pvbatch TestDistributed.py PLUGIN CASE DATA.vtp SEED REFERENCE.npz --reference
      runs serially and writes the reference (isopoints, convergence table, enclosed table);
  mpiexec -n N pvbatch TestDistributed.py PLUGIN CASE DATA.vtp SEED REFERENCE.npz [PARTITION]
      runs on N ranks and compares with the reference on rank 0;
  pvpython TestDistributed.py PLUGIN CASE DATA.vtp SEED REFERENCE.npz connect=PORT
      does the same through a pvserver (mpiexec -n N pvserver --server-port=PORT).

CASE: one-component, multi-component, adaptive-noisy or snake (files of LevelSetGenerateData;
the snake's tube crosses the middle of the box in x 36 times: the flood crosses between the
ranks' halves round after round), or
swift-vz: the SWIFT Roberts flow (Data/SWIFT), the SPH interpolant of the velocity's z, 0.7, in
its periodic box, every component (tubes through the faces), or evrard: the Tipsy glass
(Data/ChaNGa) with Particle Density's summed density (64 neighbours), the SPH field's level
1 / pi (near r = 0.5), in open space.
SEED: inside (the seeds inside one rank's half) or cut (a seed across the middle, where the
ranks' parts meet). PARTITION: single-piece (the .vtp as read: rank 0 holds every particle,
the default) or distribute-points (ParaView's Distribute Points first).
Checks: every serial isopoint has a distributed one within half a spacing and the other way
round, counts within 2%, the same convergence table (iterations, band sizes, first sign
changes), the same enclosed table (rows, particles; volumes within 1e-5; centres of mass
within 1e-3 spacings), the same splat radii (within 1%, but next to points that differ).
Option seed-move: then the main seed is moved by a sixth of its radius (the same component is
flooded): every rank must hand on its last outputs (ReusedLastOutputs), which pass the same
checks again; and, where there are additional seeds, they are dropped: the flood changes, the
method runs again and gives fewer isopoints.
Option iso-change (with QuickIsoValueChanges on): then the isovalue rises until 10% fewer
particles lie above it (the serial reference run chooses it and slides too): every rank must
slide its surface (SlidLastSurface), and the result passes the same checks against the serial
slid surface.
Option output-change: then OutputType becomes Splats and back Isopoints: every rank must make
its surface output anew from its last points (RemadeSurfaceOutput), one splat per isopoint,
and back the same isopoints, which pass the same checks again.
Option curvature-change: then CurvatureWeight doubles and comes back: outside a periodic box
every rank keeps its ghosts, their neighbourhoods and the flood (NeighborSearchCount and
FloodCount unchanged), and gives back the first run's isopoints to the bit.
Option around-seed (a periodic case): PeriodicOutput "around the seed" (the points moved into
the periodic cell centred on the seed; their splat radii from points moved alike)."""
import sys
import time

import numpy as np
from paraview import servermanager
from paraview.simple import LoadPlugin, XMLPolyDataReader
from vtkmodules.util.numpy_support import vtk_to_numpy

plugin, case, path, seed, reference = sys.argv[1:6]
options = sys.argv[6:]
port = [int(o.split("=")[1]) for o in options if o.startswith("connect=")]
if port:
    from paraview.simple import Connect
    Connect("localhost", port[0])
    LoadPlugin(plugin, remote=True, ns=globals())  # the server's ranks and the proxies
else:
    LoadPlugin(plugin, ns=globals())
ranks = (servermanager.ActiveConnection.GetNumberOfDataPartitions() if port else
         servermanager.vtkProcessModule.GetProcessModule().GetNumberOfLocalPartitions())

# Isovalue and seeds of each case (Data/Synthetic/SyntheticCases.h); "inside" seeds lie in
# x < 64, one rank's half whenever the ranks split the box in x.
CASES = {
    "one-component": (0.0, {"inside": [52, 64, 60, 6], "cut": [64, 64, 64, 12]}, []),
    "multi-component": (0.5, {"inside": [44, 64, 64, 14], "cut": [44, 64, 64, 14]},
                        {"inside": [], "cut": [70, 64, 64, 14]}),
    "adaptive-noisy": (0.000839224, {"inside": [56, 64, 64, 4], "cut": [64, 64, 64, 8]}, []),
    "snake": (0.0, {"inside": [12, 7, 7, 2.5], "cut": [64, 7, 7, 2.5]}, []),
    "swift-vz": (0.7, {"inside": [1.5, 3.0, 3.0, 1.0], "cut": [0, 0, 0, 0]}, []),
    "evrard": (1.0 / np.pi, {"inside": [-0.3, 0.0, 0.0, 0.1], "cut": [0.0, 0.0, 0.0, 0.1]}, []),
}
iso, seeds, additional = CASES[case]
main = seeds[seed]
more = additional[seed] if isinstance(additional, dict) else additional

if case == "swift-vz":
    from paraview.simple import Calculator, OpenDataFile
    reader = OpenDataFile(path)
    reader.UpdatePipelineInformation()
    source = Calculator(Input=reader, ResultArrayName="f", Function="Velocities_Z")
elif case == "evrard":
    from paraview.simple import Calculator, OpenDataFile
    density = ParticleDensity(Input=OpenDataFile(path), NumberOfNeighbors=64)
    source = Calculator(Input=density, ResultArrayName="f", Function="Density")
else:
    source = XMLPolyDataReader(FileName=[path])
if "distribute-points" in options:
    from paraview.simple import DistributePoints
    source = DistributePoints(Input=source)
source.UpdatePipeline()
surface = LevelSetIsosurface(Input=source, Scalars=["POINTS", "f"], IsoValue=iso,
                             SeedCenter=main[:3], SeedRadius=main[3], AdditionalSeeds=more,
                             OutputType="Isopoints",
                             Initialization=0 if "seed-spheres" in options else 1)
if "around-seed" in options:
    surface.PeriodicOutput = 1  # the surface in the periodic cell centred on the seed
slide = "iso-change" in options
if slide:
    surface.QuickIsoValueChanges = 1
failures = []


def check(ok, what):
    print(("ok      " if ok else "FAILED  ") + what)
    if not ok:
        failures.append(what)


def column(t, name):
    return vtk_to_numpy(t.GetColumnByName(name)).astype(float)


def run():
    """Updates the filter and fetches its outputs (on rank 0 / the client)."""
    start = time.time()
    surface.UpdatePipeline()
    surface.UpdatePropertyInformation()
    seconds = time.time() - start
    points = servermanager.Fetch(surface, idx=0)
    table = servermanager.Fetch(surface, idx=2)
    enclosed = servermanager.Fetch(surface, idx=3)
    result = {
        "points": vtk_to_numpy(points.GetPoints().GetData()) if points.GetNumberOfPoints() else
        np.zeros((0, 3)),
        "band": column(table, "BandSize"),
        "mismatch": column(table, "SignMismatch"),
        "particles": column(enclosed, "Particles"),
        "volume": column(enclosed, "Volume"),
        "centre": column(enclosed, "CenterOfMass"),
        "spacing": np.array([surface.GetProperty("MeanSampleSpacing").GetElement(0)]),
        "splat_radius": vtk_to_numpy(points.GetPointData().GetArray("SplatRadius"))
        if points.GetNumberOfPoints() else np.zeros(0),
    }
    # The input's arrays interpolated onto the surface (from ghosts too near a cut), as
    # "array:NAME" (flat, for np.savez).
    data = points.GetPointData()
    for a in range(data.GetNumberOfArrays()):
        if data.GetArrayName(a) not in ("Normals", "SplatRadius"):
            result["array:" + data.GetArrayName(a)] = vtk_to_numpy(data.GetArray(a)).copy()
    print("%s, seed %s, %d rank(s) %s: %d isopoints, %d iterations, %.2f s"
          % (case, seed, ranks, " ".join(options), len(result["points"]), len(result["band"]),
             seconds))
    return result


def compare(result, serial):
    """The checks against the serial reference."""
    spacing = float(serial["spacing"][0])
    mine, theirs = result["points"], serial["points"]
    check(abs(len(mine) - len(theirs)) <= 0.02 * len(theirs),
          "isopoint counts within 2%%: %d distributed, %d serial" % (len(mine), len(theirs)))
    if len(mine) and len(theirs):
        to_mine = cKDTree(mine).query(theirs)[0] / spacing
        to_theirs = cKDTree(theirs).query(mine)[0] / spacing
        print("distances in spacings: serial->distributed max %.3g (99.9%% %.3g), "
              "distributed->serial max %.3g (99.9%% %.3g)"
              % (to_mine.max(), np.percentile(to_mine, 99.9), to_theirs.max(),
                 np.percentile(to_theirs, 99.9)))
        check(to_mine.max() <= 0.5,
              "every serial isopoint has a distributed one within 0.5 spacing")
        check(to_theirs.max() <= 0.5,
              "every distributed isopoint has a serial one within 0.5 spacing")
        # A point near a cut has neighbours that another rank keeps: its splat radius too.
        # Where the point sets differ (a point more or moved, as with the seed-sphere start),
        # the radii of the points around it differ: those within 3 splat radii are left out.
        nearest = cKDTree(theirs).query(mine)[1]
        radius = np.abs(result["splat_radius"] / serial["splat_radius"][nearest] - 1.0)
        unmatched = np.vstack([mine[to_theirs > 1e-3], theirs[to_mine > 1e-3]])
        compared = np.ones(len(mine), dtype=bool)
        if len(unmatched):
            reach = 3.0 * float(serial["splat_radius"].max())
            compared = cKDTree(unmatched).query(mine)[0] > reach
        print("splat radii: largest relative difference %.3g (%d points compared, %d near "
              "points without a counterpart left out)"
              % (radius[compared].max(), compared.sum(), len(mine) - compared.sum()))
        check(radius[compared].max() <= 0.01, "the same splat radii (within 1%)")
        # At the isopoints both runs share, each interpolated array to rounding.
        same = to_theirs <= 1e-9
        names = sorted(key for key in serial.keys() if key.startswith("array:"))
        ours = sorted(key for key in result if key.startswith("array:"))
        # (ParaView's Distribute Points drops the global ids: the SWIFT files' ParticleIDs.)
        dropped = ["array:ParticleIDs"] if "distribute-points" in options else []
        check(sorted(set(names) - set(dropped)) == sorted(set(ours) - set(dropped)),
              "the same interpolated arrays: %s, serial %s" % (ours, names))
        names = [name for name in names if name in ours]
        # (Float arrays are interpolated in float: a few of its roundings, 6e-8 each.)
        worst = 0.0
        for name in names:
            if name in result and same.any():
                ours, theirs = result[name].astype(float), serial[name].astype(float)
                difference = np.abs(ours[same] - theirs[nearest[same]]).max()
                scale = max(np.abs(theirs).max(), 1e-300)
                rounding = 1e-6 if serial[name].dtype == np.float32 else 1e-9
                worst = max(worst, difference / scale * 1e-9 / rounding)
        print("interpolated arrays %s: largest difference %.3g of their largest value (float "
              "arrays' divided by 1000; %d shared isopoints)"
              % (", ".join(name[6:] for name in names), worst, same.sum()))
        check(worst <= 1e-9, "the same interpolated arrays at shared isopoints (within 1e-9)")
    check(len(result["band"]) == len(serial["band"]),
          "the same number of iterations: %d, serial %d"
          % (len(result["band"]), len(serial["band"])))
    if len(result["band"]) == len(serial["band"]):
        band_difference = np.abs(result["band"] - serial["band"]).max()
        mismatch_difference = np.abs(result["mismatch"] - serial["mismatch"]).max()
        print("convergence table: band sizes differ by at most %d, SignMismatch by %.3g"
              % (band_difference, mismatch_difference))
        check(band_difference <= 0.001 * serial["band"].max(),
              "the same band sizes (within 0.1%)")
        check(mismatch_difference <= 1e-4, "the same SignMismatch (within 1e-4)")
    check(len(result["volume"]) == len(serial["volume"]),
          "the same enclosed rows: %d, serial %d" % (len(result["volume"]), len(serial["volume"])))
    if len(result["volume"]) == len(serial["volume"]):
        relative = np.abs(result["volume"] / serial["volume"] - 1.0).max()
        print("enclosed volumes: %s, serial %s (largest relative difference %.3g)"
              % (result["volume"], serial["volume"], relative))
        # (Each particle near the surface is weighed by its distance to the nearest surface
        # point, another rank's too: 1.4e-4 off when a rank measured to its own points only.)
        check(relative <= 1e-5, "the same enclosed volumes (within 1e-5)")
        # (In a periodic box each centre is about the component's circular mean: the same
        # whichever rank summed first. It was about the first particle met, box-sized apart.)
        moved = np.abs(result["centre"] - serial["centre"]).max() / spacing
        print("enclosed centres of mass: largest difference %.3g spacings" % moved)
        check(moved <= 1e-3, "the same centres of mass (within 1e-3 spacings)")
        check(np.abs(result["particles"] - serial["particles"]).max()
              <= 0.002 * serial["particles"].max(),
              "the same enclosed particle counts (within 0.2%)")


result = run()
if case == "evrard":
    check(surface.GetPropertyValue("UsedSPHField") == 1, "the SPH field is used")
if "--reference" in options:
    saved = dict(result)
    if slide:
        values = vtk_to_numpy(servermanager.Fetch(source).GetPointData().GetArray("f"))
        above = np.sort(values[values > iso])
        new_iso = float(above[int(0.10 * len(above))])
        surface.IsoValue = new_iso
        slid = run()
        check(surface.GetPropertyValue("SlidLastSurface") == 1,
              "the serial run slides its surface to the isovalue %.6g" % new_iso)
        saved.update({"slid_" + key: value for key, value in slid.items()})
        saved["new_iso"] = np.array([new_iso])
    np.savez(reference, **saved)
    sys.exit(1 if failures else 0)

from scipy.spatial import cKDTree  # noqa: E402

if port:
    check(ranks > 1, "the pvserver runs on %d ranks" % ranks)
serial = np.load(reference)
compare(result, serial)
if "curvature-change" in options:
    # A full re-run on the same particles: outside a periodic box every rank keeps its ghosts,
    # their neighbourhoods (no search) and the flood (no flood); back at the first
    # CurvatureWeight, the first run's isopoints to the bit.
    def counts():
        return (surface.GetPropertyValue("NeighborSearchCount"),
                surface.GetPropertyValue("FloodCount"))
    weight = surface.CurvatureWeight
    before = counts()
    surface.CurvatureWeight = 2.0 * weight
    changed = run()
    after = counts()
    if case != "swift-vz":  # (its periodic box: the images and ghosts are made again)
        check(after == before, "a CurvatureWeight change keeps the ghosts, their neighbourhoods "
              "and the flood (NeighborSearchCount, FloodCount %s -> %s)" % (before, after))
    surface.CurvatureWeight = weight
    back = run()
    check(np.array_equal(back["points"], result["points"]) and
          np.array_equal(back["splat_radius"], result["splat_radius"]),
          "back at CurvatureWeight %g: the first run's isopoints and splat radii to the bit"
          % weight)
    compare(back, serial)
if "seed-move" in options:
    # Within the same component: the same flood, so the last outputs are handed on.
    surface.SeedCenter = [main[0] - main[3] / 6.0, main[1], main[2]]
    moved = run()
    reused = surface.GetPropertyValue("ReusedLastOutputs")
    check(reused == 1, "a seed moved within its component hands on the last outputs "
          "(ReusedLastOutputs %d)" % reused)
    check(np.array_equal(moved["points"], result["points"]),
          "the same isopoints as the run before the move")
    compare(moved, serial)
    if len(more):
        # Fewer components flooded: the method runs again.
        surface.AdditionalSeeds = []
        fewer = run()
        reused = surface.GetPropertyValue("ReusedLastOutputs")
        check(reused == 0, "dropping a seed that met another component runs the method "
              "(ReusedLastOutputs %d)" % reused)
        check(len(fewer["points"]) < 0.9 * len(result["points"]),
              "and gives fewer isopoints: %d, before %d"
              % (len(fewer["points"]), len(result["points"])))
if "output-change" in options:
    # The surface output alone changes: made anew from the last points on every rank.
    surface.OutputType = "Splats"
    surface.UpdatePipeline()
    surface.UpdatePropertyInformation()
    remade = surface.GetPropertyValue("RemadeSurfaceOutput")
    splats = servermanager.Fetch(surface, idx=0)
    check(remade == 1 and splats.GetNumberOfCells() == len(result["points"]),
          "an OutputType change makes the surface output alone (RemadeSurfaceOutput %d): %d "
          "splats for %d isopoints" % (remade, splats.GetNumberOfCells(), len(result["points"])))
    surface.OutputType = "Isopoints"
    back = run()
    remade = surface.GetPropertyValue("RemadeSurfaceOutput")
    check(remade == 1 and np.array_equal(back["points"], result["points"]) and
          np.array_equal(back["splat_radius"], result["splat_radius"]),
          "and back to Isopoints, alone again (RemadeSurfaceOutput %d): the same isopoints and "
          "splat radii" % remade)
    compare(back, serial)
if slide:
    surface.IsoValue = float(serial["new_iso"][0])
    slid = run()
    check(surface.GetPropertyValue("SlidLastSurface") == 1,
          "every rank slides its surface to the isovalue %.6g" % float(serial["new_iso"][0]))
    compare(slid, {key[len("slid_"):]: serial[key] for key in serial.files
                   if key.startswith("slid_")})
if failures:
    print("FAILED: %d check(s)" % len(failures))
    sys.exit(1)
print("all checks passed")
