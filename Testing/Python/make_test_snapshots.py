# SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
# SPDX-License-Identifier: BSD-3-Clause
"""/usr/bin/python3 make_test_snapshots.py OUT_DIR: writes the small HDF5 snapshots that
TestHDF5SnapshotReader and TestReaders.py read, with h5py (Debian's python3-h5py), in the layouts
of the codes the reader supports. Every value is a known function of the particle's index, so the
tests can check each one.

- gadget4_multi.0.hdf5, gadget4_multi.1.hdf5: one GADGET-4 snapshot split over two files
  (NumFilesPerSnapshot 2): 50 gas (30 + 20) with GADGET's singular names (Density,
  SmoothingLength, InternalEnergy), 40 dark matter (25 + 15) without a Masses dataset (MassTable),
  ParticleIDs, scalar BoxSize 10, Time 2.5; Density is float32 in the first file, float64 in
  the second.
- arepo_like.hdf5: AREPO style, no SmoothingLength: 60 gas with Masses and Density, 7 stars
  (PartType4) with GFM_StellarFormationTime, BoxSize as a 3-vector, Time 0.5.
- bad_not_snapshot.hdf5 (HDF5 without a Header), bad_truncated.hdf5 (half of arepo_like.hdf5),
  bad_inconsistent.hdf5 (Density shorter than Coordinates), bad_missing_part.0.hdf5 (says 2 files,
  the second is absent), bad_text.hdf5 (a text file), bad_count.hdf5 (NumPart_ThisFile -inf),
  bad_files.hdf5 (NumFilesPerSnapshot NaN), bad_rank.hdf5 (Coordinates of rank 3, no
  NumPart_ThisFile), bad_columns.0/1.hdf5 (Velocities with 3 columns, then 5),
  bad_types.0/1.hdf5 (InternalEnergy text, then numbers).
- string_arrays.hdf5: Header attributes that are arrays of strings, fixed and variable length.
- snap_format1.0, snap_format1.1: the same particles as gadget4_multi (50 gas with masses 0.25
  in a MASS block, 40 dark matter with 0.5 in the mass table) as one GADGET-2 binary snapshot
  in two files, SnapFormat 1, little-endian, single precision; snapshot_format2_big: the gas
  alone, SnapFormat 2, big-endian, double precision, 8-byte ids (both read by
  vtkGadgetBinaryReader; the header packed here with numpy's structured dtype, GADGET-2's
  io_header).
- swift_cells.0.hdf5, swift_cells.1.hdf5: a SWIFT-style snapshot of 1,000 gas particles in
  [0, 1)^3 in two files, sorted by top-level cell (4 x 4 x 4 cells, the first 32 in the first
  file), then moved by up to a tenth of a cell (as particles drift between SWIFT's tree
  rebuilds), with SWIFT's cell table (Cells/Counts, OffsetsInFile, Files, Centres, Meta-data
  size); swift_old_cells.hdf5: the same particles in one file with older SWIFT's global
  Offsets and each cell's MinPositions / MaxPositions; swift_bad_cells.hdf5: the same with an
  offset beyond the file (the reader reads every particle then).
- eagle_like.hdf5: EAGLE style (GADGET-3): 20 gas with a `Mass` dataset (not Masses), 15 dark
  matter with no mass dataset, and a MassTable of zeros (the masses are in the file, GADGET's
  convention): the gas's masses are `Mass`, the dark matter has none (not masses of 0).
- kernel_swift_<n>.hdf5 (n = 0 ... 7): 10 gas particles each, with SWIFT's HydroScheme
  attributes "Kernel function" (every name SWIFT writes, then "Gaussian", which no reader
  knows, then "Wendland C4" without a gamma) and "Kernel gamma"; kernel_gadget4_<flag>.hdf5: the same with GADGET-4's Config flag
  WENDLAND_C2_KERNEL, WENDLAND_C4_KERNEL or WENDLAND_C6_KERNEL; kernel_gadget4_bias.hdf5: WENDLAND_C2_KERNEL
  with WENDLAND_BIAS_CORRECTION.
- swift_subsampled.hdf5: 10 gas particles in a SWIFT subsampled snapshot (Header OutputType
  "SubSampled", SubSampleFractions 0.1 for the gas): the reader warns.
- periodic_blob.hdf5: 40,000 gas particles uniform in a periodic box of side 1 (BoxSize 1),
  with Density = exp(-d^2 / (2 0.08^2)), d the distance to the nearest image of the box's corner
  (0, 0, 0), and no smoothing lengths (the filter fits the density itself): its isosurface at
  exp(-1/2) is the sphere of radius 0.08 about the corner, cut into eight by the box's faces.
"""
import os
import sys

import h5py
import numpy as np


def gas_value(i, column):
    """The value of column `column` of gas particle i (over the whole snapshot)."""
    return 1.0 + 0.01 * i + 10.0 * column


def header(f, this_file, total, mass_table, time, box, files=1):
    h = f.create_group("Header")
    h.attrs["NumPart_ThisFile"] = np.array(this_file, dtype=np.uint32)
    h.attrs["NumPart_Total"] = np.array(total, dtype=np.uint64)
    h.attrs["MassTable"] = np.array(mass_table, dtype=np.float64)
    h.attrs["Time"] = np.float64(time)
    h.attrs["Redshift"] = np.float64(0.0)
    h.attrs["BoxSize"] = box
    h.attrs["NumFilesPerSnapshot"] = np.int32(files)


def gas(group, first, count, smoothing=True, masses=True, density_type=np.float32):
    i = np.arange(first, first + count)
    xyz = np.stack([gas_value(i, 0), gas_value(i, 1), gas_value(i, 2)], axis=1)
    group["Coordinates"] = xyz.astype(np.float64)
    group["Velocities"] = (-xyz).astype(np.float32)
    group["Density"] = gas_value(i, 3).astype(density_type)
    group["InternalEnergy"] = gas_value(i, 4).astype(np.float32)
    group["ParticleIDs"] = (1000 + i).astype(np.uint64)
    if smoothing:
        group["SmoothingLength"] = gas_value(i, 5).astype(np.float32)
    if masses:
        group["Masses"] = np.full(count, 0.25, dtype=np.float32)


def dark(group, first, count):
    i = np.arange(first, first + count)
    group["Coordinates"] = np.stack([-1.0 - i, 2.0 * i, 3.0 + 0 * i], axis=1).astype(np.float32)
    group["Velocities"] = np.zeros((count, 3), dtype=np.float32)
    group["ParticleIDs"] = (5000 + i).astype(np.uint64)


# GADGET-2's io_header (256 bytes): the fields before the fill, in order.
GADGET_HEADER = [("npart", "i4", 6), ("mass", "f8", 6), ("time", "f8"), ("redshift", "f8"),
                 ("flag_sfr", "i4"), ("flag_feedback", "i4"), ("npartTotal", "u4", 6),
                 ("flag_cooling", "i4"), ("num_files", "i4"), ("BoxSize", "f8"),
                 ("Omega0", "f8"), ("OmegaLambda", "f8"), ("HubbleParam", "f8"),
                 ("flag_stellarage", "i4"), ("flag_metals", "i4"),
                 ("npartTotalHighWord", "u4", 6), ("flag_entropy_instead_u", "i4")]


def write_gadget(name, this_file, total, mass_table, time, box, files, blocks, fmt, order):
    """One file of a GADGET binary snapshot: `blocks` a list of (label, array) in file order,
    `order` '<' or '>' (byte order), `fmt` 1 or 2 (labelled blocks)."""
    dtype = np.dtype([(f[0], order + f[1], f[2]) if len(f) == 3 else (f[0], order + f[1])
                      for f in GADGET_HEADER])
    head = np.zeros(1, dtype=dtype)
    head["npart"], head["mass"], head["time"] = this_file, mass_table, time
    head["npartTotal"], head["num_files"], head["BoxSize"] = total, files, box
    raw = head.tobytes() + bytes(256 - dtype.itemsize)
    with open(name, "wb") as f:
        def record(data):
            length = np.array([len(data)], dtype=order + "i4").tobytes()
            f.write(length + data + length)
        for label, data in [("HEAD", raw)] + [(l, a.astype(a.dtype.newbyteorder(order)).tobytes())
                                              for l, a in blocks]:
            if fmt == 2:
                record(label.ljust(4).encode() + np.array([len(data) + 8], order + "i4").tobytes())
            record(data)


def gadget_blocks(g0, gn, d0, dn, real, ids):
    """POS, VEL, ID, MASS (gas only: dark matter's mass is in the table), U, RHO, HSML of gas
    [g0, g0 + gn) and dark matter [d0, d0 + dn), with gas()'s and dark()'s values."""
    i, j = np.arange(g0, g0 + gn), np.arange(d0, d0 + dn)
    gas_xyz = np.stack([gas_value(i, 0), gas_value(i, 1), gas_value(i, 2)], axis=1)
    dark_xyz = np.stack([-1.0 - j, 2.0 * j, 3.0 + 0 * j], axis=1)
    blocks = [("POS", np.concatenate([gas_xyz, dark_xyz]).astype(real)),
              ("VEL", np.concatenate([-gas_xyz, np.zeros((dn, 3))]).astype(real)),
              ("ID", np.concatenate([1000 + i, 5000 + j]).astype(ids)),
              ("MASS", np.full(gn, 0.25).astype(real)),
              ("U", gas_value(i, 4).astype(real)), ("RHO", gas_value(i, 3).astype(real)),
              ("HSML", gas_value(i, 5).astype(real))]
    return [(label, data) for label, data in blocks if len(data)]


def swift_cell_snapshots(path):
    """SWIFT-style snapshots with a table of top-level cells (see the module's text)."""
    rng = np.random.default_rng(7)
    cells_per_side, n = 4, 1000
    x = rng.random((n, 3))
    cell = np.floor(x * cells_per_side).astype(int) @ [16, 4, 1]
    order = np.argsort(cell, kind="stable")
    cell = cell[order]
    x = x[order] + rng.uniform(-0.025, 0.025, (n, 3))  # drift: a tenth of a cell at most
    counts = np.bincount(cell, minlength=64)
    offsets = np.concatenate([[0], np.cumsum(counts)[:-1]])
    index = np.stack(np.unravel_index(np.arange(64), (4, 4, 4)), axis=1)
    centres = (index + 0.5) / cells_per_side
    low = np.array([x[cell == c].min(axis=0) if counts[c] else [np.inf] * 3 for c in range(64)])
    high = np.array([x[cell == c].max(axis=0) if counts[c] else [-np.inf] * 3 for c in range(64)])

    def particles(f, first, count):
        i = np.arange(first, first + count)
        g = f.create_group("PartType0")
        g["Coordinates"] = x[first:first + count]
        g["Densities"] = (1.0 + i).astype(np.float32)
        g["SmoothingLengths"] = np.full(count, 0.1, dtype=np.float32)
        g["Masses"] = np.full(count, 1e-3, dtype=np.float32)
        g["ParticleIDs"] = (7000 + i).astype(np.uint64)

    def table(f, counts_, offsets_name, offsets_, files=None, extent=False):
        cells = f.create_group("Cells")
        cells.create_group("Meta-data").attrs["size"] = np.full(3, 1.0 / cells_per_side)
        cells["Centres"] = centres
        cells.create_group("Counts")["PartType0"] = counts_.astype(np.int64)
        cells.create_group(offsets_name)["PartType0"] = offsets_.astype(np.int64)
        if files is not None:
            cells.create_group("Files")["PartType0"] = files.astype(np.int32)
        if extent:
            cells.create_group("MinPositions")["PartType0"] = low
            cells.create_group("MaxPositions")["PartType0"] = high

    split = offsets[32]  # the first 32 cells' particles in the first file
    files = np.repeat([0, 1], 32)
    for part, (first, count) in enumerate([(0, split), (split, n - split)]):
        with h5py.File(path("swift_cells.%d.hdf5" % part), "w") as f:
            header(f, [count, 0, 0, 0, 0, 0], [n, 0, 0, 0, 0, 0], [0] * 6, 1.0, np.float64(1.0),
                   files=2)
            particles(f, first, count)
            table(f, counts, "OffsetsInFile", offsets - np.where(files == 1, split, 0), files)
    for name, shift in (("swift_old_cells.hdf5", 0), ("swift_bad_cells.hdf5", 600)):
        with h5py.File(path(name), "w") as f:
            header(f, [n, 0, 0, 0, 0, 0], [n, 0, 0, 0, 0, 0], [0] * 6, 1.0, np.float64(1.0))
            particles(f, 0, n)
            table(f, counts, "Offsets", offsets + np.where(np.arange(64) == 63, shift, 0),
                  extent=True)


def periodic_blob(path):
    rng = np.random.default_rng(11)
    n = 40000
    x = rng.random((n, 3))
    d = np.minimum(x, 1.0 - x)  # to the nearest image of the corner, per axis
    with h5py.File(path("periodic_blob.hdf5"), "w") as f:
        header(f, [n, 0, 0, 0, 0, 0], [n, 0, 0, 0, 0, 0], [1.0 / n, 0, 0, 0, 0, 0], 0.0,
               np.float64(1.0))
        g = f.create_group("PartType0")
        g["Coordinates"] = x
        g["Density"] = np.exp(-np.sum(d * d, axis=1) / (2.0 * 0.08 ** 2))
        g["ParticleIDs"] = np.arange(n, dtype=np.uint64)


# SWIFT's kernel names (src/kernel_hydro.h) with its 3D gammas, and a name no code writes.
SWIFT_KERNELS = [("Cubic spline (M4)", 1.825742), ("Quartic spline (M5)", 2.018932),
                 ("Quintic spline (M6)", 2.195775), ("Wendland C2", 1.936492),
                 ("Wendland C4", 2.207940), ("Wendland C6", 2.449490), ("Gaussian", 3.0),
                 ("Wendland C4", None)]


def kernel_snapshots(path):
    for n, (name, gamma) in enumerate(SWIFT_KERNELS):
        with h5py.File(path("kernel_swift_%d.hdf5" % n), "w") as f:
            header(f, [10, 0, 0, 0, 0, 0], [10, 0, 0, 0, 0, 0], [0] * 6, 1.0, np.float64(1.0))
            gas(f.create_group("PartType0"), 0, 10)
            scheme = f.create_group("HydroScheme")
            scheme.attrs["Kernel function"] = np.bytes_(name)
            if gamma is not None:
                scheme.attrs["Kernel gamma"] = np.float32(gamma)
    for name, flags in [(flag, [flag]) for flag in
                        ["WENDLAND_C2_KERNEL", "WENDLAND_C4_KERNEL", "WENDLAND_C6_KERNEL"]] + \
            [("bias", ["WENDLAND_C2_KERNEL", "WENDLAND_BIAS_CORRECTION"])]:
        with h5py.File(path("kernel_gadget4_%s.hdf5" % name), "w") as f:
            header(f, [10, 0, 0, 0, 0, 0], [10, 0, 0, 0, 0, 0], [0] * 6, 1.0, np.float64(1.0))
            gas(f.create_group("PartType0"), 0, 10)
            config = f.create_group("Config")
            config.attrs["NTYPES"] = np.int32(6)
            for flag in flags:
                config.attrs[flag] = np.int32(1)


def main(out):
    os.makedirs(out, exist_ok=True)
    path = lambda name: os.path.join(out, name)
    # A GADGET-4 snapshot in two files.
    for part, (g0, gn, d0, dn) in enumerate([(0, 30, 0, 25), (30, 20, 25, 15)]):
        with h5py.File(path("gadget4_multi.%d.hdf5" % part), "w") as f:
            header(f, [gn, dn, 0, 0, 0, 0], [50, 40, 0, 0, 0, 0], [0, 0.5, 0, 0, 0, 0], 2.5,
                   np.float64(10.0), files=2)
            # The second file stores Density as float64, the first as float32: both are read
            # into one array, converted by HDF5.
            gas(f.create_group("PartType0"), g0, gn,
                density_type=np.float64 if part else np.float32)
            dark(f.create_group("PartType1"), d0, dn)
            f.create_group("Config").attrs["NTYPES"] = np.int32(6)
    # AREPO style: no smoothing lengths, stars, BoxSize as a vector.
    with h5py.File(path("arepo_like.hdf5"), "w") as f:
        header(f, [60, 0, 0, 0, 7, 0], [60, 0, 0, 0, 7, 0], [0] * 6, 0.5,
               np.array([4.0, 5.0, 6.0]))
        gas(f.create_group("PartType0"), 0, 60, smoothing=False)
        stars = f.create_group("PartType4")
        stars["Coordinates"] = np.arange(21, dtype=np.float64).reshape(7, 3)
        stars["Masses"] = np.full(7, 2.0)
        stars["GFM_StellarFormationTime"] = np.linspace(0.1, 0.7, 7)
    # EAGLE style: gas masses in `Mass`, a MassTable of zeros, dark matter without masses.
    with h5py.File(path("eagle_like.hdf5"), "w") as f:
        header(f, [20, 15, 0, 0, 0, 0], [20, 15, 0, 0, 0, 0], [0] * 6, 1.0, np.float64(10.0))
        g = f.create_group("PartType0")
        gas(g, 0, 20, masses=False)
        g["Mass"] = np.full(20, 0.25, dtype=np.float32)
        dark(f.create_group("PartType1"), 0, 15)
    # SWIFT's subsampled output: a tenth of the gas kept, with the run's masses.
    with h5py.File(path("swift_subsampled.hdf5"), "w") as f:
        header(f, [10, 0, 0, 0, 0, 0], [10, 0, 0, 0, 0, 0], [0] * 6, 1.0, np.float64(1.0))
        f["Header"].attrs["OutputType"] = np.bytes_("SubSampled")
        f["Header"].attrs["SubSampleFractions"] = np.array([0.1, 1, 1, 1, 1, 1, 1],
                                                           dtype=np.float32)
        gas(f.create_group("PartType0"), 0, 10)
    # Bad files.
    with h5py.File(path("bad_not_snapshot.hdf5"), "w") as f:
        f.create_group("Data")["x"] = np.arange(10.0)
    with open(path("arepo_like.hdf5"), "rb") as f:
        data = f.read()
    with open(path("bad_truncated.hdf5"), "wb") as f:
        f.write(data[: len(data) // 2])
    with h5py.File(path("bad_inconsistent.hdf5"), "w") as f:
        header(f, [20, 0, 0, 0, 0, 0], [20, 0, 0, 0, 0, 0], [0] * 6, 1.0, np.float64(1.0))
        g = f.create_group("PartType0")
        gas(g, 0, 20)
        del g["Density"]
        g["Density"] = np.ones(19, dtype=np.float32)
    with h5py.File(path("bad_missing_part.0.hdf5"), "w") as f:
        header(f, [10, 0, 0, 0, 0, 0], [20, 0, 0, 0, 0, 0], [0] * 6, 1.0, np.float64(1.0), files=2)
        gas(f.create_group("PartType0"), 0, 10)
    with open(path("bad_text.hdf5"), "w") as f:
        f.write("not an HDF5 file\n" * 10)
    # What FuzzHDF5SnapshotReader found (issue 14): a count that is no count, Coordinates of
    # rank 3, and columns that change between the files of one snapshot.
    with h5py.File(path("bad_count.hdf5"), "w") as f:
        header(f, [10, 0, 0, 0, 0, 0], [10, 0, 0, 0, 0, 0], [0] * 6, 1.0, np.float64(1.0))
        f["Header"].attrs["NumPart_ThisFile"] = np.array([-np.inf, 0, 0, 0, 0, 0])
        gas(f.create_group("PartType0"), 0, 10)
    with h5py.File(path("bad_files.hdf5"), "w") as f:
        header(f, [10, 0, 0, 0, 0, 0], [10, 0, 0, 0, 0, 0], [0] * 6, 1.0, np.float64(1.0))
        f["Header"].attrs["NumFilesPerSnapshot"] = np.float64(np.nan)
        gas(f.create_group("PartType0"), 0, 10)
    with h5py.File(path("bad_rank.hdf5"), "w") as f:
        header(f, [10, 0, 0, 0, 0, 0], [10, 0, 0, 0, 0, 0], [0] * 6, 1.0, np.float64(1.0))
        del f["Header"].attrs["NumPart_ThisFile"]  # counts from the Coordinates' rows
        f.create_group("PartType0")["Coordinates"] = np.zeros((10, 3, 2))
    for part in range(2):
        with h5py.File(path("bad_columns.%d.hdf5" % part), "w") as f:
            header(f, [10, 0, 0, 0, 0, 0], [20, 0, 0, 0, 0, 0], [0] * 6, 1.0, np.float64(1.0),
                   files=2)
            gas(f.create_group("PartType0"), 10 * part, 10)
            del f["PartType0/Velocities"]
            f["PartType0/Velocities"] = np.zeros((10, 3 + 2 * part), dtype=np.float32)
    # A dataset that is text in the first file and numbers in the second: its array's rows from
    # the first file were left unset.
    for part in range(2):
        with h5py.File(path("bad_types.%d.hdf5" % part), "w") as f:
            header(f, [10, 0, 0, 0, 0, 0], [20, 0, 0, 0, 0, 0], [0] * 6, 1.0, np.float64(1.0),
                   files=2)
            gas(f.create_group("PartType0"), 10 * part, 10)
            if part == 0:
                del f["PartType0/InternalEnergy"]
                f["PartType0/InternalEnergy"] = np.array([b"hot"] * 10, dtype="S3")
    # Arrays of strings as attributes (a fixed-length and a variable-length one): every value
    # is kept.
    with h5py.File(path("string_arrays.hdf5"), "w") as f:
        header(f, [10, 0, 0, 0, 0, 0], [10, 0, 0, 0, 0, 0], [0] * 6, 1.0, np.float64(1.0))
        f["Header"].attrs["Fixed"] = np.array([b"one", b"three"], dtype="S5")
        f["Header"].attrs.create("Variable", ["alpha", "beta", "gamma"],
                                 dtype=h5py.string_dtype())
        gas(f.create_group("PartType0"), 0, 10)
    # GADGET-2 binary: the same particles in two files (format 1), the gas alone (format 2).
    for part, (g0, gn, d0, dn) in enumerate([(0, 30, 0, 25), (30, 20, 25, 15)]):
        write_gadget(path("snap_format1.%d" % part), [gn, dn, 0, 0, 0, 0], [50, 40, 0, 0, 0, 0],
                     [0, 0.5, 0, 0, 0, 0], 2.5, 10.0, 2,
                     gadget_blocks(g0, gn, d0, dn, np.float32, np.uint32), 1, "<")
    write_gadget(path("snapshot_format2_big"), [50, 0, 0, 0, 0, 0], [50, 0, 0, 0, 0, 0],
                 [0] * 6, 0.75, 0.0, 1, gadget_blocks(0, 50, 0, 0, np.float64, np.uint64), 2, ">")
    swift_cell_snapshots(path)
    kernel_snapshots(path)
    periodic_blob(path)
    print("wrote the test snapshots to", out)


if __name__ == "__main__":
    main(sys.argv[1])
