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
    print("wrote the test snapshots to", out)


if __name__ == "__main__":
    main(sys.argv[1])
