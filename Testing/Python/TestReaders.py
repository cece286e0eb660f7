# SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
# SPDX-License-Identifier: BSD-3-Clause
"""pvpython TestReaders.py PLUGIN DATA_DIR SNAPSHOT_DIR [SHARED_DATA_DIR]

Opens particle files as a ParaView user does (OpenDataFile, File > Open's route: the reader is
chosen by ParaView's reader factory) and checks particle counts per type, array names and
lengths, masses, Time and BoxSize:
- DATA_DIR (the repository's Data/): the three ChaNGa Tipsy files and the SWIFT snapshot;
- SNAPSHOT_DIR: the snapshots make_test_snapshots.py writes (a GADGET-4 snapshot in two files,
  an AREPO-style file, the same particles as GADGET-2 binary snapshots, SnapFormat 1 in two
  files and 2);
- SHARED_DATA_DIR (optional, ../shared/data when it is beside the clone): every HDF5 and Tipsy
  file there, the GADGET-4 gas sphere as a time series of four snapshots.
The point array selection by keyword: the SPH field's three arrays alone give the same surface
as all of them; a region by keyword, wrapped across a periodic box's faces or not. Then, with no array named by hand, Particle Density on a galaxy without density and Level-Set
Isosurface on a snapshot's own density; the Evrard glass written as a GADGET and as an EAGLE
HDF5 snapshot (Masses, or Mass with a MassTable of zeros) gives the same surface."""
import os
import sys

from paraview import servermanager
from paraview.simple import LoadPlugin, OpenDataFile

plugin, data_dir, snapshot_dir = sys.argv[1:4]
shared = sys.argv[4] if len(sys.argv) > 4 else None
LoadPlugin(plugin, ns=globals())
failures = []


def check(ok, what):
    print(("ok      " if ok else "FAILED  ") + what)
    if not ok:
        failures.append(what)


def open_file(path, types=None):
    """`types`: the names of the particle types to read (ParaView 5.11's array selection in
    Python: the names listed are on, the others off)."""
    reader = OpenDataFile(path)
    check(reader is not None, "%s: ParaView finds a reader" % os.path.basename(path))
    if reader is None:
        return None, None
    reader.UpdatePipelineInformation()
    if types is not None:
        reader.ParticleTypes = types
    reader.UpdatePipeline()
    return reader, servermanager.Fetch(reader)


def field(data, name, index=0):
    array = data.GetFieldData().GetArray(name)
    return array.GetValue(index) if array is not None else None


def check_points(data, name, count, arrays, masses=None, time=None, box=None):
    """`data`: a vtkPolyData of one type; `arrays`: names that must be there, each with one
    tuple per particle; `masses`: (min, max) of the Masses/mass array."""
    check(data is not None and data.GetNumberOfPoints() == count,
          "%s: %d particles (got %s)" % (name, count,
                                         data.GetNumberOfPoints() if data else None))
    if data is None:
        return
    point_data = data.GetPointData()
    for a in arrays:
        array = point_data.GetArray(a)
        check(array is not None and array.GetNumberOfTuples() == count,
              "%s: array %s with %d tuples" % (name, a, count))
    if masses is not None:
        mass = point_data.GetArray("Masses") or point_data.GetArray("mass")
        rng = mass.GetRange() if mass is not None else None
        check(rng is not None and abs(rng[0] - masses[0]) <= 1e-5 * abs(masses[0]) and
              abs(rng[1] - masses[1]) <= 1e-5 * abs(masses[1]),
              "%s: masses in [%g, %g] (got %s)" % (name, masses[0], masses[1], rng))
    if time is not None:
        check(field(data, "Time") is not None and abs(field(data, "Time") - time) < 1e-9,
              "%s: Time %g (got %s)" % (name, time, field(data, "Time")))
    if box is not None:
        check(field(data, "BoxSize") is not None and abs(field(data, "BoxSize") - box) < 1e-9,
              "%s: BoxSize %g (got %s)" % (name, box, field(data, "BoxSize")))


def blocks(data):
    return [data.GetBlock(i) for i in range(data.GetNumberOfBlocks())]


tipsy_gas = ["mass", "velocity", "rho", "temp", "hsmooth", "metals", "phi"]
# The repository's real files.
changa = os.path.join(data_dir, "ChaNGa")
_, glass = open_file(os.path.join(changa, "adiabtophat_glass_28721.bin"))
check_points(glass, "Evrard glass", 28721, tipsy_gas, masses=(3.48177e-05, 3.48177e-05))
_, tube = open_file(os.path.join(changa, "shocktube.std"))
check_points(tube, "shock tube", 20000, tipsy_gas, time=1.0)
_, galaxy = open_file(os.path.join(changa, "changa_run581.20000"), ["DarkMatter", "Stars"])
parts = blocks(galaxy) if galaxy is not None and galaxy.IsA("vtkMultiBlockDataSet") else [None, None]
check_points(parts[0], "galaxy dark matter", 3627, ["mass", "velocity", "eps", "phi"])
check_points(parts[1], "galaxy stars", 5321, ["mass", "velocity", "metals", "tform", "eps", "phi"])
_, swift = open_file(os.path.join(data_dir, "SWIFT", "swift_robertsflow_g32.hdf5"))
check_points(swift, "SWIFT Roberts flow", 32768,
             ["Densities", "SmoothingLengths", "Masses", "Velocities", "InternalEnergies"],
             masses=(0.00756989, 0.00756989), time=0.0, box=6.2831853071)

# PointArrays as a keyword: the arrays to read (all by default). SWIFT's 22 arrays or the SPH
# field's three alone give the same surface (its 99th-percentile density), to the bit, on the
# SPH field in both runs. (The surfaces run once: in TestReaders, not again with the shared data.)
swift_path = os.path.join(data_dir, "SWIFT", "swift_robertsflow_g32.hdf5")
rho = swift.GetPointData().GetArray("Densities") if swift is not None else None
level = sorted(rho.GetValue(i) for i in range(rho.GetNumberOfTuples()))[
    rho.GetNumberOfTuples() * 99 // 100] if rho is not None else 1.0
if shared is None:
    surfaces = []
    for arrays in (None, ["Densities", "SmoothingLengths", "Masses"]):
        snapshot = HDF5ParticleSnapshotReader(
            FileNames=[swift_path], **({} if arrays is None else {"PointArrays": arrays}))
        snapshot.UpdatePipeline()
        read = servermanager.Fetch(snapshot).GetPointData()
        names = sorted(read.GetArrayName(i) for i in range(read.GetNumberOfArrays()))
        check(len(names) == 22 if arrays is None else names == sorted(arrays),
              "SWIFT, PointArrays=%s: %d arrays read (%s)" % (arrays, len(names), names[:4]))
        level_set = LevelSetIsosurface(Input=snapshot, IsoValue=level, SeedRadius=0)
        level_set.UpdatePipeline()
        level_set.UpdatePropertyInformation()
        surfaces.append((servermanager.Fetch(level_set),
                         level_set.GetProperty("UsedSPHField").GetData()))
    (full, full_sph), (three, three_sph) = surfaces
    same = (full.GetNumberOfPoints() == three.GetNumberOfPoints() > 0 and
            all(full.GetPoint(k) == three.GetPoint(k) for k in range(full.GetNumberOfPoints())))
    check(same and full_sph == 1 and three_sph == 1,
          "SWIFT: the surface from the SPH field's three arrays alone is the full read's (%d and %d "
          "points, SPH field %s / %s)" % (full.GetNumberOfPoints(), three.GetNumberOfPoints(),
                                          full_sph, three_sph))

# ReadRegion and RegionBounds as keywords: the particles inside the box alone.
box = [1.0, 2.5, 1.0, 2.5, 1.0, 2.5]
cut = HDF5ParticleSnapshotReader(FileNames=[swift_path], ReadRegion=1, RegionBounds=box)
cut.UpdatePipeline()
cut_data = servermanager.Fetch(cut)
inside = sum(1 for i in range(swift.GetNumberOfPoints()) if all(
    box[2 * a] <= swift.GetPoint(i)[a] <= box[2 * a + 1] for a in range(3))) if swift else -1
check(cut_data.GetNumberOfPoints() == inside > 0 and all(
    box[2 * a] <= cut_data.GetPoint(i)[a] <= box[2 * a + 1]
    for i in range(cut_data.GetNumberOfPoints()) for a in range(3)),
    "SWIFT, ReadRegion=1, RegionBounds=%s: the %d particles inside (got %d)"
    % (box, inside, cut_data.GetNumberOfPoints()))

# A region around the Evrard sphere of radius 0.4 (rho = 1 / (2 pi r); the density from the
# masses alone, by Particle Density): about half the particles, the same surface as from all
# of them (within 1e-4 of the radius on average), as close to the exact sphere.
if shared is None:
    import numpy as np  # noqa: E402
    from scipy.spatial import cKDTree  # noqa: E402
    from vtkmodules.util.numpy_support import vtk_to_numpy  # noqa: E402
    glass_path = os.path.join(changa, "adiabtophat_glass_28721.bin")
    spheres = []
    for keywords in ({}, {"ReadRegion": 1, "RegionBounds": [-0.6, 0.6] * 3}):
        particles = TipsyParticleReader(FileNames=[glass_path], PointArrays=["mass"], **keywords)
        summed = ParticleDensity(Input=particles, NumberOfNeighbors=64)
        summed.UpdatePipeline()
        sphere = LevelSetIsosurface(Input=summed, IsoValue=1.0 / (2.0 * np.pi * 0.4))
        sphere.SeedRadius = 0
        sphere.UpdatePipeline()
        points = vtk_to_numpy(servermanager.Fetch(sphere).GetPoints().GetData()).astype(float)
        spheres.append((particles.GetDataInformation().GetNumberOfPoints(), points,
                        np.sqrt(np.mean((np.linalg.norm(points, axis=1) - 0.4) ** 2))))
    (n_all, all_points, all_rms), (n_box, box_points, box_rms) = spheres
    apart = cKDTree(all_points).query(box_points)[0].mean()
    check(n_box < 0.6 * n_all and apart < 4e-5 and box_rms < 1.01 * all_rms,
          "Evrard sphere r = 0.4 from the region [-0.6, 0.6]^3 (%d of %d particles): %d points, "
          "%.3g apart on average from the full read's %d, rms distance to the sphere %.5f (full "
          "read %.5f)" % (n_box, n_all, len(box_points), apart, len(all_points), box_rms, all_rms))

# ChaNGa's auxiliary arrays (SNAPSHOT.NAME beside the file) as a user meets them: listed by the
# reader ParaView picks, carried through Particle Density, and on the surface the integer ones
# (iord, a halo finder's groups) are the nearest particle's, in their own type.
if shared is None:
    import shutil  # noqa: E402
    import struct  # noqa: E402
    aux_dir = os.path.join(snapshot_dir, "tipsy_aux")
    os.makedirs(aux_dir, exist_ok=True)
    aux_glass = os.path.join(aux_dir, "glass.00100")
    shutil.copyfile(os.path.join(changa, "adiabtophat_glass_28721.bin"), aux_glass)
    n = 28721
    with open(aux_glass + ".iord", "wb") as f:
        f.write(struct.pack(">i", n) + (5000 + np.arange(n)).astype(">i4").tobytes())
    with open(aux_glass + ".amiga.grp", "w") as f:
        f.write("%d\n" % n + "".join("%d\n" % (i % 3) for i in range(n)))
    with open(aux_glass + ".HI", "w") as f:
        f.write("%d\n" % n + "".join("%.7g\n" % (0.5 + i / n) for i in range(n)))
    reader = OpenDataFile(aux_glass)
    reader.UpdatePipelineInformation()
    listed = set(reader.GetProperty("PointArrayInfo")[::2])
    check({"iord", "amiga.grp", "HI"} <= listed,
          "ChaNGa auxiliary arrays listed by the reader (%s)" % sorted(listed))
    particles = servermanager.Fetch(reader)
    tree = cKDTree(vtk_to_numpy(particles.GetPoints().GetData()).astype(float))
    iord = vtk_to_numpy(particles.GetPointData().GetArray("iord"))
    groups = vtk_to_numpy(particles.GetPointData().GetArray("amiga.grp"))
    surface = LevelSetIsosurface(Input=ParticleDensity(Input=reader, NumberOfNeighbors=64),
                                 IsoValue=1.0 / (2.0 * np.pi * 0.4), SeedRadius=0, OutputType=0)
    out = servermanager.Fetch(surface)
    at = vtk_to_numpy(out.GetPoints().GetData()).astype(float)
    nearest = tree.query(at)[1]
    on = {name: out.GetPointData().GetArray(name) for name in ("iord", "amiga.grp", "HI")}
    ok = all(a is not None for a in on.values()) and len(at) > 1000
    # (The particles' global ids; on the surface a plain array, its points not being particles.)
    ok = ok and particles.GetPointData().GetGlobalIds() is not None and \
        out.GetPointData().GetGlobalIds() is None and \
        on["iord"].GetDataTypeAsString() == "idtype" and np.array_equal(
        vtk_to_numpy(on["iord"]), iord[nearest]) and np.array_equal(
        vtk_to_numpy(on["amiga.grp"]), groups[nearest]) and on["HI"].GetDataType() == 11
    check(ok, "auxiliary arrays on the surface (%d points): iord (the particles' global ids) and "
          "amiga.grp the nearest particle's, HI interpolated (double)" % len(at))

# PeriodicRegion as a keyword: a region across the faces of the SWIFT file's periodic box (side
# 2 pi) holds the particles whose images lie inside it, wrapped or not.
across = [5.5, 7.5, 1.0, 2.5, -0.5, 0.5]
two_pi = 6.283185307179586


def inside_wrapped(x, bounds, period):
    """Whether an image x + n period of x (n from -1 to 1 on each axis) lies in `bounds`."""
    return all(any(bounds[2 * a] <= x[a] + n * period <= bounds[2 * a + 1] for n in (-1, 0, 1))
               for a in range(3))


for wrap in (0, 1):
    wrapped = HDF5ParticleSnapshotReader(FileNames=[swift_path], ReadRegion=1,
                                         RegionBounds=across, PeriodicRegion=wrap)
    wrapped.UpdatePipeline()
    expected = sum(1 for i in range(swift.GetNumberOfPoints()) if inside_wrapped(
        swift.GetPoint(i), across, two_pi if wrap else 0.0)) if swift else -1
    got = servermanager.Fetch(wrapped).GetNumberOfPoints()
    check(got == expected > 0,
          "SWIFT, RegionBounds=%s, PeriodicRegion=%d: the %d particles inside%s (got %d)"
          % (across, wrap, expected, ", wrapped" if wrap else "", got))

# A blob about the corner of a periodic box (periodic_blob.hdf5: the sphere of radius 0.08 cut
# into eight by the faces), read from the region [-0.3, 0.3]^3 across three faces: the full
# read's surface, point for point, within 0.002 of the sphere and in all eight octants about the
# corner; not wrapped, the region holds one octant of the particles and the surface is not the
# sphere.
if shared is None:
    import numpy as np  # noqa: E402
    from scipy.spatial import cKDTree  # noqa: E402
    from vtkmodules.util.numpy_support import vtk_to_numpy  # noqa: E402
    blob_path = os.path.join(snapshot_dir, "periodic_blob.hdf5")
    blobs = []
    for keywords in ({}, {"ReadRegion": 1, "RegionBounds": [-0.3, 0.3] * 3},
                     {"ReadRegion": 1, "RegionBounds": [-0.3, 0.3] * 3, "PeriodicRegion": 0}):
        particles = HDF5ParticleSnapshotReader(FileNames=[blob_path], **keywords)
        particles.UpdatePipeline()
        blob = LevelSetIsosurface(Input=particles, IsoValue=np.exp(-0.5),
                                  SeedCenter=[0.01, 0.01, 0.01], SeedRadius=0.02,
                                  OutputType="Isopoints")
        blob.UpdatePipeline()
        out = servermanager.Fetch(blob)
        points = (vtk_to_numpy(out.GetPoints().GetData()).astype(float)
                  if out.GetNumberOfPoints() else np.zeros((0, 3)))
        about = points - np.round(points)  # from the nearest image of the corner
        rms = np.sqrt(np.mean((np.linalg.norm(about, axis=1) - 0.08) ** 2)) if len(points) else 1
        octants = len(set(map(tuple, (about > 0).astype(int))))
        blobs.append((particles.GetDataInformation().GetNumberOfPoints(), points, rms, octants))
    (n_all, all_points, all_rms, _), (n_box, box_points, box_rms, box_octants), cut = blobs
    apart = (cKDTree(all_points).query(box_points)[0].max()
             if len(box_points) and len(all_points) else 1.0)
    check(n_box < 0.3 * n_all and len(box_points) == len(all_points) > 200 and apart < 1e-9 and
          box_rms < 0.002 and box_octants == 8,
          "a blob across the corner of a periodic box from the region [-0.3, 0.3]^3 (%d of %d "
          "particles): %d points (full read %d), %.3g at most from the full read's, rms distance "
          "to the sphere %.5f, %d octants" % (n_box, n_all, len(box_points), len(all_points), apart,
                                              box_rms, box_octants))
    check(cut[0] < n_box / 4 and len(cut[1]) < len(all_points) / 2 and cut[2] > 2 * box_rms,
          "the same region with PeriodicRegion=0: %d particles (one octant), %d points, rms "
          "distance to the sphere %.5f" % (cut[0], len(cut[1]), cut[2]))

# Snapshots the tests wrote.
_, gadget = open_file(os.path.join(snapshot_dir, "gadget4_multi.1.hdf5"),
                      ["Gas (PartType0)", "DarkMatter (PartType1)"])
parts = blocks(gadget) if gadget is not None and gadget.IsA("vtkMultiBlockDataSet") else [None, None]
check_points(parts[0], "GADGET-4 in two files, gas", 50,
             ["Density", "SmoothingLength", "InternalEnergy", "Velocities", "Masses"],
             masses=(0.25, 0.25), time=2.5, box=10.0)
check_points(parts[1], "GADGET-4 in two files, dark matter", 40, ["Velocities", "Masses"],
             masses=(0.5, 0.5))
_, arepo = open_file(os.path.join(snapshot_dir, "arepo_like.hdf5"))
check_points(arepo, "AREPO-style, no SmoothingLength", 60, ["Density", "Masses"], time=0.5,
             box=4.0)

# GADGET-2 binary: the GADGET-4 snapshot's particles in two files (format 1), its gas alone
# (format 2, big-endian, double precision), found by name (snap_*, snapshot_*) and content.
_, binary = open_file(os.path.join(snapshot_dir, "snap_format1.1"),
                      ["Gas (PartType0)", "DarkMatter (PartType1)"])
parts = blocks(binary) if binary is not None and binary.IsA("vtkMultiBlockDataSet") else [None, None]
check_points(parts[0], "GADGET-2 binary in two files, gas", 50,
             ["Density", "SmoothingLength", "InternalEnergy", "Velocities", "Masses"],
             masses=(0.25, 0.25), time=2.5, box=10.0)
check_points(parts[1], "GADGET-2 binary in two files, dark matter", 40, ["Velocities", "Masses"],
             masses=(0.5, 0.5))
if parts[0] is not None and gadget is not None and gadget.IsA("vtkMultiBlockDataSet"):
    hdf5_gas = gadget.GetBlock(0)
    same = all(max(abs(a - b) for a, b in zip(parts[0].GetPoint(k), hdf5_gas.GetPoint(k))) <
               1e-6 * max(abs(c) for c in hdf5_gas.GetPoint(k)) and
               abs(parts[0].GetPointData().GetArray("Density").GetValue(k) -
                   hdf5_gas.GetPointData().GetArray("Density").GetValue(k)) < 1e-5 *
               hdf5_gas.GetPointData().GetArray("Density").GetValue(k)
               for k in range(50))
    check(same, "GADGET-2 binary gas: the HDF5 snapshot's positions and densities (to single "
          "precision)")
# Its properties as keywords, as a script gives them (ParticleTypes: the names of the types to
# read, the others off): dark matter alone.
by_name = GADGETBinarySnapshotReader(FileNames=[os.path.join(snapshot_dir, "snap_format1.0")],
                                     ParticleTypes=["DarkMatter (PartType1)"])
by_name.UpdatePipeline()
check_points(servermanager.Fetch(by_name), "GADGET Binary Snapshot Reader by keyword, dark matter",
             40, ["Velocities", "Masses"], masses=(0.5, 0.5), time=2.5)
# Both parts chosen together (the file dialog's group): one time step, the snapshot once.
for pattern in ("snap_format1.%d", "gadget4_multi.%d.hdf5"):
    grouped = OpenDataFile([os.path.join(snapshot_dir, pattern % p) for p in (0, 1)])
    grouped.UpdatePipelineInformation()
    grouped.UpdatePipeline()
    check(list(grouped.TimestepValues) == [2.5] and
          grouped.GetDataInformation().GetNumberOfPoints() == 50,
          "%s, both parts opened as a group: one time step (%s), the 50 gas particles once (%d)"
          % (pattern, list(grouped.TimestepValues),
             grouped.GetDataInformation().GetNumberOfPoints()))
reader, big = open_file(os.path.join(snapshot_dir, "snapshot_format2_big"))
check(reader is not None and reader.GetXMLName() == "GadgetBinaryReader",
      "snapshot_format2_big opened by the GADGET Binary Snapshot Reader (got %s)"
      % (reader.GetXMLName() if reader else None))
check_points(big, "GADGET-2 binary format 2, big-endian", 50,
             ["Density", "SmoothingLength", "InternalEnergy", "Velocities", "Masses"],
             masses=(0.25, 0.25), time=0.75)
check(big is not None and big.GetPoints().GetDataType() == 11 and
      big.GetPointData().GetGlobalIds() is not None and
      big.GetPointData().GetGlobalIds().GetValue(49) == 1049,
      "format 2: double-precision positions, 8-byte ids as the global ids")

# ../shared/data, when it is beside the clone: every HDF5 and Tipsy file.
if shared:
    _, cube = open_file(os.path.join(shared, "changa_cube300.tbin"))
    check_points(cube, "ChaNGa cube300 (dark matter only)", 110592, ["mass", "eps", "phi"],
                 time=0.05)
    # The cosmological box with its run's parameter file beside it (as ChaNGa's testcosmo has,
    # achInFile naming it, periodic, dPeriod 1): BoxSize from it, so that a region across the
    # x faces wraps, holding the particles whose images lie inside.
    import shutil  # noqa: E402
    import numpy as np  # noqa: E402
    from vtkmodules.util.numpy_support import vtk_to_numpy  # noqa: E402
    run_dir = os.path.join(snapshot_dir, "tipsy_run")
    os.makedirs(run_dir, exist_ok=True)
    boxed = os.path.join(run_dir, "cube300.tbin")
    shutil.copyfile(os.path.join(shared, "changa_cube300.tbin"), boxed)
    with open(os.path.join(run_dir, "cosmo.param"), "w") as f:
        f.write("achInFile = cube300.tbin\nachOutName = cosmo\nbPeriodic = 1\ndPeriod = 1\n")
    reader, whole = open_file(boxed)
    box = whole.GetFieldData().GetArray("BoxSize") if whole else None
    check(box is not None and [box.GetValue(k) for k in range(3)] == [1.0, 1.0, 1.0],
          "cube300 beside cosmo.param: BoxSize 1 (got %s)"
          % ([box.GetValue(k) for k in range(box.GetNumberOfValues())] if box else None))
    x = vtk_to_numpy(whole.GetPoints().GetData()).astype(float)[:, 0]
    reader.ReadRegion = 1
    reader.RegionBounds = [0.4, 0.6, -0.5, 0.5, -0.5, 0.5]
    reader.UpdatePipeline()
    region = servermanager.Fetch(reader)
    expected = int(np.count_nonzero((x >= 0.4) | (x + 1.0 <= 0.6)))
    check(region.GetNumberOfPoints() == expected and expected > 0,
          "cube300 region x in [0.4, 0.6] wraps across the face: %d particles (expected %d)"
          % (region.GetNumberOfPoints(), expected))
    _, sod = open_file(os.path.join(shared, "swift_sodshock3d_glass_002.hdf5"))
    check_points(sod, "SWIFT Sod shock glass", 50653,
                 ["Density", "SmoothingLength", "Masses", "Acceleration", "InternalEnergy"],
                 box=1.0)
    for name in ["adiabtophat_glass_28721.bin", "shocktube.std", "changa_run581.20000"]:
        _, data = open_file(os.path.join(shared, name))
        check(data is not None and data.GetNumberOfPoints() > 0, "shared %s opens" % name)
    _, swift2 = open_file(os.path.join(shared, "swift_robertsflow_g32.hdf5"))
    check_points(swift2, "shared SWIFT Roberts flow", 32768, ["Densities"])
    series = [os.path.join(shared, "gadget4_gassphere", "snapshot_%03d.hdf5" % k)
              for k in (1, 5, 10, 15)]
    reader = OpenDataFile(series)
    reader.UpdatePipelineInformation()
    times = list(reader.TimestepValues)
    check(len(times) == 4 and abs(times[1] - 1.001953125) < 1e-9,
          "GADGET-4 gas sphere: a time series of 4 snapshots (times %s)" % times)
    for t in times:
        reader.UpdatePipeline(t)
        data = servermanager.Fetch(reader)
        check_points(data, "gas sphere at t=%g" % t, 1000,
                     ["Density", "SmoothingLength", "InternalEnergy", "Velocities", "Masses"],
                     time=t)

# No array named by hand: Particle Density on the galaxy's dark matter, then the level set on
# the SWIFT snapshot's own density (its active scalars).
galaxy_dark, _ = open_file(os.path.join(changa, "changa_run581.20000"))
density = ParticleDensity(Input=galaxy_dark)
density.UpdatePipeline()
dark = servermanager.Fetch(density)
rho = dark.GetPointData().GetScalars()
check(rho is not None and rho.GetName() == "Density" and rho.GetRange()[0] > 0,
      "Particle Density on the galaxy's dark matter: Density, positive, the active scalars")
# Each kernel as a keyword (Wendland C4, the XML's fifth entry), marked for the filter.
c4 = servermanager.Fetch(ParticleDensity(Input=galaxy_dark, Kernel=4))
marker = c4.GetFieldData().GetAbstractArray("SPHKernel")
check(marker is not None and marker.GetValue(0) == "WendlandC4",
      "Particle Density with Kernel=4: the output marked WendlandC4 (got %s)"
      % (marker.GetValue(0) if marker is not None else None))
surface = LevelSetIsosurface(Input=density, IsoValue=sorted(
    rho.GetValue(i) for i in range(rho.GetNumberOfTuples()))[dark.GetNumberOfPoints() * 9 // 10],
    SeedRadius=0)
surface.UpdatePipeline()
isosurface = servermanager.Fetch(surface)
check(isosurface.GetNumberOfPoints() > 0 and isosurface.GetPointData().GetArray("Density"),
      "Level-Set Isosurface of that density (90th percentile), no array named: %d points"
      % isosurface.GetNumberOfPoints())

# EAGLE's `Mass` with a MassTable of zeros against GADGET's `Masses`: the Evrard glass (density
# by Particle Density) written both ways gives the same surface. Before, the EAGLE file got
# Masses of 0 from its MassTable beside its Mass: a field of zeros, and no surface.
if shared is None:
    import h5py  # noqa: E402
    import numpy as np  # noqa: E402
    from vtkmodules.util.numpy_support import vtk_to_numpy  # noqa: E402
    evrard = servermanager.Fetch(ParticleDensity(
        Input=OpenDataFile(os.path.join(changa, "adiabtophat_glass_28721.bin")),
        NumberOfNeighbors=64))
    columns = {name: vtk_to_numpy(evrard.GetPointData().GetArray(name))
               for name in ("Density", "SmoothingLength", "mass")}
    surfaces = {}
    for style, mass_name in (("gadget", "Masses"), ("eagle", "Mass")):
        path = os.path.join(snapshot_dir, "evrard_%s_style.hdf5" % style)
        with h5py.File(path, "w") as f:
            n = evrard.GetNumberOfPoints()
            h = f.create_group("Header")
            h.attrs["NumPart_ThisFile"] = np.array([n, 0, 0, 0, 0, 0], dtype=np.int32)
            h.attrs["NumPart_Total"] = np.array([n, 0, 0, 0, 0, 0], dtype=np.uint32)
            h.attrs["MassTable"] = np.zeros(6)
            h.attrs["NumFilesPerSnapshot"] = np.int32(1)
            g = f.create_group("PartType0")
            g["Coordinates"] = vtk_to_numpy(evrard.GetPoints().GetData()).astype(np.float64)
            g["Density"] = columns["Density"]
            g["SmoothingLength"] = columns["SmoothingLength"]
            g[mass_name] = columns["mass"]
        surface = LevelSetIsosurface(Input=OpenDataFile(path), IsoValue=0.31831,
                                     SeedCenter=[0, 0, 0], SeedRadius=0.05, OutputType=0)
        surfaces[style] = servermanager.Fetch(surface)
    points = {style: s.GetNumberOfPoints() for style, s in surfaces.items()}
    same = points["gadget"] == points["eagle"] and points["gadget"] > 1000 and np.array_equal(
        vtk_to_numpy(surfaces["gadget"].GetPoints().GetData()),
        vtk_to_numpy(surfaces["eagle"].GetPoints().GetData()))
    check(same, "the Evrard glass as a GADGET (Masses) and an EAGLE (Mass, MassTable 0) "
          "snapshot: the same isopoints (%s)" % points)

print("%d failures" % len(failures))
sys.exit(1 if failures else 0)
