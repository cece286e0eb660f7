# SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
# SPDX-License-Identifier: BSD-3-Clause
"""The same outputs on any number of MPI ranks, on the real snapshots in ../shared/data.

  [mpiexec -n N] pvbatch Scripts/mpi_consistency.py run PLUGIN DATA_DIR OUT.npz [distribute]
                  [only=NAME,...] [made=DIR]
      runs the filter on each snapshot (or the named ones: only=galaxy-stars,galaxy-stars-box,
      say, whose file Data/ChaNGa holds too) (as read: each rank reads its share; with `distribute`,
      after ParaView's Distribute Points, whose float coordinates differ from the file's) and
      saves, gathered on rank 0, every output the user
      sees: the particles' densities (Particle Density's where the file has none), the surface
      (splats) with its point arrays, the particles' LevelSet array, the Enclosed table;
  pvpython Scripts/mpi_consistency.py compare SERIAL.npz OTHER.npz [TOLERANCE]
      prints, per snapshot, the largest differences between two such runs: surface points (in
      splat radii), every surface array (relative to its largest value), LevelSet (in the
      particles' mean spacing), the Enclosed table's volumes and masses (relative) and centres
      of mass (in the mean spacing), and the densities (relative); with TOLERANCE, fails (exit
      1) where one of them is larger (TestMPIConsistency).
  With made=DIR, also the snapshots Scripts/make_halo_tracer_snapshot.py wrote there (SWIFT's
  layout, strongly adaptive, a passive tracer's isosurface; in Mpc and in kpc).
Scripts/run-mpi-consistency.sh runs it on 1 to 4 ranks and compares each with one process."""
import os
import sys

import numpy as np


def run(plugin, data, out, distribute, only, made=None):
    from paraview import servermanager
    from paraview.simple import Calculator, Delete, DistributePoints, LoadPlugin
    from snapshot_sources import open_snapshot
    from vtkmodules.util.numpy_support import vtk_to_numpy
    LoadPlugin(plugin, ns=globals())

    def read(path, types):
        return open_snapshot(data, path, types)

    def summed(path, types, k):
        return ParticleDensity(Input=read(path, types), NumberOfNeighbors=k)  # noqa: F821

    # name: (source, isovalue as a quantile of the density or a fixed value, scalar[, the
    # filter's other properties])
    cases = [
        ("galaxy-stars", lambda: summed("changa_run581.20000", ["Stars"], 64), 0.9, None),
        # The same in a periodic box far larger than it (Tipsy's [-1, 1)^3): the Enclosed table's
        # exchange of surface points in a box (its outer stars' shells reach past a rank's).
        ("galaxy-stars-box", lambda: summed("changa_run581.20000", ["Stars"], 64), 0.9, None,
         {"BoxSize": [2.0, 2.0, 2.0]}),
        ("cube300-dark", lambda: summed("changa_cube300.tbin", ["DarkMatter"], 32), 0.995, None),
        # The same box as a periodic one (Tipsy's [-1/2, 1/2)^3; the file carries no BoxSize):
        # what the ranks exchange, across the faces.
        ("cube300-dark-box", lambda: summed("changa_cube300.tbin", ["DarkMatter"], 32), 0.995,
         None, {"BoxSize": [1.0, 1.0, 1.0]}),
        # The densest tenth of the box: clumps near one another, which the flood tells apart by
        # the SPH field between neighbours (LevelSetFloodOnField), on each rank as in one process.
        ("cube300-clumps", lambda: summed("changa_cube300.tbin", ["DarkMatter"], 64), 0.9, None),
        ("cube300-clumps-box", lambda: summed("changa_cube300.tbin", ["DarkMatter"], 64), 0.9,
         None, {"BoxSize": [1.0, 1.0, 1.0]}),
        ("evrard-glass", lambda: summed("adiabtophat_glass_28721.bin", ["Gas"], 64), 0.3, None),
        ("changa-shocktube", lambda: summed("shocktube.std", ["Gas"], 64), 0.5, None),
        ("gadget4-gassphere", lambda: read(os.path.join("gadget4_gassphere",
                                                        "snapshot_010.hdf5"),
                                           ["Gas (PartType0)"]), 0.7, None),
        ("swift-sodshock", lambda: read("swift_sodshock3d_glass_002.hdf5", ["Gas (PartType0)"]),
         0.5, None),
        ("swift-roberts-vz", lambda: Calculator(
            Input=read("swift_robertsflow_g32.hdf5", ["Gas (PartType0)"]),
            ResultArrayName="VelocityZ", Function="Velocities_Z"), 0.7, "VelocityZ"),
    ]
    if made:
        # Made here: a Plummer halo in a uniform background, Wendland C2 (SWIFT's gamma h);
        # the tracer's isosurface crosses densities 800 times apart.
        for name, file in (("halo-tracer", "halo_tracer.hdf5"),
                           ("halo-tracer-kpc", "halo_tracer_kpc.hdf5")):
            cases.append((name, lambda file=file: read(os.path.join(made, file),
                                                       ["Gas (PartType0)"]),
                          float(np.exp(-0.5)), "PassiveTracer"))
    saved = {}
    for name, make, rule, scalar, *options in [c for c in cases if not only or c[0] in only]:
        source = make()
        if distribute:
            source = DistributePoints(Input=source)
        source.UpdatePipeline()
        particles = servermanager.Fetch(source)
        density = particles.GetFieldData().GetAbstractArray("DensityArray").GetValue(0)
        scalar = scalar or density
        values = vtk_to_numpy(particles.GetPointData().GetArray(scalar)).astype(float)
        x = vtk_to_numpy(particles.GetPoints().GetData()).astype(float)
        order = np.lexsort(x.T)  # the particles in a fixed order, whatever the ranks
        saved[name + ".density"] = vtk_to_numpy(
            particles.GetPointData().GetArray(density)).astype(float)[order]
        iso = rule if scalar != density else float(np.quantile(values, rule))
        seed = [float(c) for c in x[np.argmax(values)]]
        surface = LevelSetIsosurface(Input=source, Scalars=["POINTS", scalar],  # noqa: F821
                                     IsoValue=iso, SeedCenter=seed, **(options[0] if options
                                                                       else {}))
        surface.UpdatePipeline()
        surface.UpdatePropertyInformation()
        splats = servermanager.Fetch(surface, idx=0)
        saved[name + ".points"] = (vtk_to_numpy(splats.GetPoints().GetData()).astype(float)
                                   if splats.GetNumberOfPoints() else np.zeros((0, 3)))
        data_arrays = splats.GetPointData()
        for a in range(data_arrays.GetNumberOfArrays()):
            array = data_arrays.GetArray(a)
            if array is not None and array.GetName():
                saved[name + ".array." + array.GetName()] = vtk_to_numpy(array).astype(float)
        with_phi = servermanager.Fetch(surface, idx=1)
        phi_points = vtk_to_numpy(with_phi.GetPoints().GetData()).astype(float)
        saved[name + ".levelset"] = vtk_to_numpy(
            with_phi.GetPointData().GetArray("LevelSet")).astype(float)[np.lexsort(phi_points.T)]
        saved[name + ".spacing"] = np.array([surface.GetProperty("MeanSampleSpacing")
                                             .GetElement(0)])
        enclosed = servermanager.Fetch(surface, idx=3)
        for column in ("Volume", "Mass", "CenterOfMass"):
            if enclosed.GetColumnByName(column) is not None:
                saved[name + ".enclosed." + column] = vtk_to_numpy(
                    enclosed.GetColumnByName(column)).astype(float)
        print("%s: %d particles, %d splat points" % (name, len(x), splats.GetNumberOfPoints()),
              flush=True)
        Delete(surface)
        Delete(source)
    np.savez(out, **saved)


def compare(first, second, tolerance=None):
    from scipy.spatial import cKDTree
    a, b = np.load(first), np.load(second)
    names = sorted({k.split(".")[0] for k in a.files})
    failed = []
    print("%-18s %9s %9s %9s %9s %9s %9s %9s %9s" % (
        "snapshot", "points", "moved", "arrays", "LevelSet", "volumes", "masses", "centres",
        "density"))

    def relative(x, y):
        if x.shape != y.shape:
            return float("inf")
        return float(np.max(np.abs(x - y)) / max(np.max(np.abs(x)), 1e-300)) if x.size else 0.0

    for name in names:
        pa, pb = a[name + ".points"], b[name + ".points"]
        spacing = float(a[name + ".spacing"][0])
        moved = arrays = float("inf")
        if len(pa) == len(pb) and len(pa):
            distance, nearest = cKDTree(pa).query(pb)
            radius = a.get(name + ".array.SplatRadius")
            moved = float(np.max(distance) / (np.median(radius) if radius is not None else
                                              spacing))
            # (each point of the second run against the first run's nearest point)
            arrays = max(relative(a[k][nearest], b[k])
                         for k in a.files if k.startswith(name + ".array.") and k in b.files)
        levelset = (float(np.max(np.abs(a[name + ".levelset"] - b[name + ".levelset"]))) /
                    spacing if a[name + ".levelset"].shape == b[name + ".levelset"].shape
                    else float("inf"))

        def column(c, scale=None):
            k = name + ".enclosed." + c
            if k not in a.files:
                return float("nan")
            if a[k].shape != b[k].shape:
                return float("inf")
            return (float(np.max(np.abs(a[k] - b[k]))) / scale if scale else relative(a[k], b[k]))

        differences = [moved, arrays, levelset, column("Volume"), column("Mass"),
                       column("CenterOfMass", spacing),
                       relative(a[name + ".density"], b[name + ".density"])]
        print("%-18s %9s %9.2g %9.2g %9.2g %9.2g %9.2g %9.2g %9.2g" % (
            (name, "%d/%d" % (len(pa), len(pb))) + tuple(differences)))
        if tolerance is not None and (len(pa) != len(pb) or not all(
                d <= tolerance for d in differences if not np.isnan(d))):
            failed.append(name)
    if failed:
        print("FAILED: differences above %g in %s" % (tolerance, ", ".join(failed)))
        sys.exit(1)


if __name__ == "__main__":
    if sys.argv[1] == "run":
        only = [n for a in sys.argv[5:] if a.startswith("only=") for n in a[5:].split(",")]
        made = next((a[5:] for a in sys.argv[5:] if a.startswith("made=")), None)
        run(sys.argv[2], sys.argv[3], sys.argv[4], "distribute" in sys.argv[5:], only, made)
    else:
        compare(sys.argv[2], sys.argv[3], float(sys.argv[4]) if len(sys.argv) > 4 else None)
