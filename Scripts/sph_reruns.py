# SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
# SPDX-License-Identifier: BSD-3-Clause
"""pvpython Scripts/sph_reruns.py PLUGIN SHARED_DATA_DIR [REPEATS [FRACTION]]

Seconds of the filter on the SPH field of the real snapshots in ../shared/data, through
ParaView's proxies, for the default output (splats) and for Isopoints. The cases and isovalue
rules are Scripts/sph_comparison.py's, but taken on the scalar array the source carries (the
comparison takes its 70th percentile, median and seed on the field it sums itself), so the
GADGET-4 isovalue and the seeds can differ slightly from the comparison's:
  first    a fresh filter's first run (neighbour search included);
  method   the method in full after a change of the isovalue by a part in 1e9 (the
           neighbours kept: what an isovalue change costs with QuickIsoValueChanges off);
  quick    a change that moves 2% (FRACTION) of the particles above the isovalue across it, with
           QuickIsoValueChanges on, from a fresh filter's first run; `slid` says whether the
           last surface was slid (1) or the method ran (0); `vs method` compares its output
           with the method's at that isovalue (a fresh filter): the relative differences of the
           enclosed volume (the Enclosed table's total) and of the number of points;
  seed     after the method's re-run, the seed centre moved by a thousandth of the data's
           extent (the same flood); `reused` says whether the last outputs were handed on;
  output   then OutputType changed to the other one (splats <-> isopoints): the surface output
           made anew from the last run's points, on the SPH field built again.
The fastest of REPEATS (default 3) of each. One line per case and output; the points and a
checksum of their coordinates show that two builds give the same output.
With PLUMMER_SAMPLES=N in the environment, a last case made here: N equal-mass particles of an
ellipsoidal Plummer sphere (axes 1, 0.8, 0.6; numpy's generator, seed 3), their density and
smoothing lengths by Particle Density (64 neighbours), the isovalue the median density: a
surface through half a million to millions of particles of adaptive sampling, as real
snapshots have (one run of each, whatever REPEATS).
Scripts/run-sph-reruns.sh runs it for a base commit's build and this one's, in turn."""
import os
import sys
import time

import numpy as np
from paraview import servermanager
from paraview.simple import Calculator, Delete, LoadPlugin, PVTrivialProducer
from snapshot_sources import open_snapshot
from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy
from vtkmodules.vtkCommonCore import vtkPoints
from vtkmodules.vtkCommonDataModel import vtkPolyData


def fetch(proxy):
    data = servermanager.Fetch(proxy)
    if data.IsA("vtkMultiBlockDataSet"):
        data = data.GetBlock(0)
    return data


KEPT = []


def enclosed_volume(proxy):
    """The Enclosed table's total volume (its last row)."""
    table = servermanager.Fetch(proxy, idx=3)
    column = table.GetColumnByName("Volume")
    return column.GetValue(table.GetNumberOfRows() - 1) if column else float("nan")


def plummer(count):
    """Equal-mass particles of an ellipsoidal Plummer sphere (total mass 1), as a source."""
    rng = np.random.default_rng(3)
    q = 1.0 / np.sqrt(rng.uniform(0.0, 0.99, count) ** (-2.0 / 3.0) - 1.0)
    direction = rng.normal(size=(count, 3))
    direction /= np.linalg.norm(direction, axis=1)[:, None]
    x = direction * q[:, None] * np.array([1.0, 0.8, 0.6])
    data = vtkPolyData()
    points = vtkPoints()
    points.SetData(numpy_to_vtk(x, deep=True))
    data.SetPoints(points)
    mass = numpy_to_vtk(np.full(count, 1.0 / count), deep=True)
    mass.SetName("Masses")
    data.GetPointData().AddArray(mass)
    producer = PVTrivialProducer()
    producer.GetClientSideObject().SetOutput(data)
    producer.UpdatePipeline()
    KEPT.append(data)  # (the data must outlive the producer's use of it)
    return ParticleDensity(Input=producer, NumberOfNeighbors=64)


def main():
    plugin, data = sys.argv[1], sys.argv[2]
    repeats = int(sys.argv[3]) if len(sys.argv) > 3 else 3
    fraction = float(sys.argv[4]) if len(sys.argv) > 4 else 0.02
    LoadPlugin(plugin, ns=globals())

    def hdf5(path, types):
        return open_snapshot(data, path, types)

    def tipsy_with_density(path, types):
        return ParticleDensity(Input=open_snapshot(data, path, types), NumberOfNeighbors=64)

    # name: (source maker, scalar (None: the density the source marks), isovalue rule)
    quantile = lambda q: (lambda v: float(np.quantile(v, q)))
    cases = [
        ("gadget4-gassphere",
         lambda: hdf5(os.path.join("gadget4_gassphere", "snapshot_010.hdf5"), ["Gas (PartType0)"]),
         None, quantile(0.7)),
        ("evrard-summed",
         lambda: tipsy_with_density("adiabtophat_glass_28721.bin", ["Gas"]),
         None, lambda v: 1.0 / np.pi),
        ("changa-shocktube",
         lambda: tipsy_with_density("shocktube.std", ["Gas"]),
         None, lambda v: 0.5 * float(np.median(v))),
        ("changa-cube300",
         lambda: tipsy_with_density("changa_cube300.tbin", ["DarkMatter"]),
         None, quantile(0.9)),
        ("swift-robertsflow-vz",
         lambda: Calculator(Input=hdf5("swift_robertsflow_g32.hdf5", ["Gas (PartType0)"]),
                            ResultArrayName="VelocityZ", Function="Velocities_Z"),
         "VelocityZ", lambda v: 0.7),
    ]
    plummer_samples = int(os.environ.get("PLUMMER_SAMPLES", "0"))
    if plummer_samples > 0:
        cases.append(("plummer-%d" % plummer_samples, lambda: plummer(plummer_samples), None,
                      quantile(0.5)))
    print("%-22s %-9s %9s %9s %9s %5s %17s %9s %6s %9s %9s %14s" % (
        "case", "output", "first s", "method s", "quick s", "slid", "vs method vol pts",
        "seed s", "reused", "output s", "points", "checksum"))
    for name, make, scalar, rule in cases:
        source = make()
        particles = fetch(source)
        marked = particles.GetFieldData().GetAbstractArray("DensityArray")
        scalar = scalar or marked.GetValue(0)
        values = vtk_to_numpy(particles.GetPointData().GetArray(scalar)).astype(float)
        x = vtk_to_numpy(particles.GetPoints().GetData())
        iso = rule(values)
        seed = list(x[np.argmax(values)]) if name != "evrard-summed" else [0.0, 0.0, 0.0]
        extent = float(np.max(np.ptp(x, axis=0)))  # for the seed move
        above = np.sort(values[values > iso])
        moved = float(above[int(fraction * len(above))])
        for output_type, label in ((1, "splats"), (0, "isopoints")):
            settings = dict(Input=source, Scalars=["POINTS", scalar], IsoValue=iso,
                            SeedCenter=seed, OutputType=output_type)
            first = method = quick = moved_seed = remake = float("inf")
            slid = reused = -1
            versus = (float("nan"), float("nan"))
            for r in range(1 if name.startswith("plummer") else repeats):
                f = LevelSetIsosurface(**settings)
                t = time.time()
                f.UpdatePipeline()
                first = min(first, time.time() - t)
                f.IsoValue = iso * (1.0 + 1e-9 * (r + 1))
                t = time.time()
                f.UpdatePipeline()
                method = min(method, time.time() - t)
                out = fetch(f)
                f.SeedCenter = [seed[0] + 1e-3 * extent, seed[1], seed[2]]
                t = time.time()
                f.UpdatePipeline()
                moved_seed = min(moved_seed, time.time() - t)
                f.UpdatePropertyInformation()
                reused = f.GetProperty("ReusedLastOutputs").GetData()
                f.OutputType = 1 - output_type
                t = time.time()
                f.UpdatePipeline()
                remake = min(remake, time.time() - t)
                Delete(f)
                g = LevelSetIsosurface(QuickIsoValueChanges=1, **settings)
                g.UpdatePipeline()
                g.IsoValue = moved
                t = time.time()
                g.UpdatePipeline()
                quick = min(quick, time.time() - t)
                g.UpdatePropertyInformation()
                slid = g.GetProperty("SlidLastSurface").GetData()
                if r == 0:
                    m = LevelSetIsosurface(**dict(settings, IsoValue=moved))
                    m.UpdatePipeline()
                    volume = [enclosed_volume(x) for x in (g, m)]
                    counts = [fetch(x).GetNumberOfPoints() for x in (g, m)]
                    versus = (volume[0] / volume[1] - 1.0 if volume[1] else float("nan"),
                              counts[0] / max(1, counts[1]) - 1.0)
                    Delete(m)
                Delete(g)
            points = vtk_to_numpy(out.GetPoints().GetData()) if out.GetNumberOfPoints() else []
            checksum = float(np.sum(np.asarray(points, dtype=float) * [1.0, 2.0, 3.0]))
            print("%-22s %-9s %9.3f %9.3f %9.3f %5d %8.1e %8.1e %9.4f %6d %9.4f %9d %14.8g" % (
                name, label, first, method, quick, slid, versus[0], versus[1], moved_seed,
                reused, remake, out.GetNumberOfPoints(), checksum), flush=True)
        Delete(source)


if __name__ == "__main__":
    main()
