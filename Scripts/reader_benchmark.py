# SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
# SPDX-License-Identifier: BSD-3-Clause
"""pvpython Scripts/reader_benchmark.py PLUGIN [PARTICLES [DIR]]

What the readers' point array selection (PointArrays) saves on a wide snapshot. Writes an HDF5
snapshot of PARTICLES gas particles (default 2,000,000) in DIR (default /tmp) with the arrays an
IllustrisTNG-style run keeps per gas particle (16 datasets, 34 values per particle, GADGET's
names for the SPH field's three), then reads it through ParaView's reader proxy, in turn, with
every array and with the SPH field's three alone (Density, SmoothingLength, Masses): the fastest
of 3 reads each (the file in the page cache, so this is the reader's own cost, not the disk's),
and the output's memory (ParaView's data information). Prints both and their ratios."""
import os
import sys
import time

import h5py
import numpy as np
from paraview.simple import Delete, LoadPlugin

plugin = sys.argv[1]
count = int(sys.argv[2]) if len(sys.argv) > 2 else 2000000
folder = sys.argv[3] if len(sys.argv) > 3 else "/tmp"
LoadPlugin(plugin, ns=globals())
path = os.path.join(folder, "levelset_wide_snapshot_%d.hdf5" % count)

# name: values per particle (float32 unless said)
COLUMNS = [("Coordinates", 3, np.float64), ("Velocities", 3, np.float32),
           ("ParticleIDs", 1, np.uint64), ("Masses", 1, np.float32), ("Density", 1, np.float32),
           ("SmoothingLength", 1, np.float32), ("InternalEnergy", 1, np.float32),
           ("ElectronAbundance", 1, np.float32), ("NeutralHydrogenAbundance", 1, np.float32),
           ("StarFormationRate", 1, np.float32), ("GFM_Metallicity", 1, np.float32),
           ("GFM_Metals", 10, np.float32), ("MagneticField", 3, np.float32),
           ("Potential", 1, np.float32), ("GFM_CoolingRate", 1, np.float32),
           ("CenterOfMass", 3, np.float32)]
rng = np.random.default_rng(1)
with h5py.File(path, "w") as f:
    header = f.create_group("Header")
    header.attrs["NumPart_ThisFile"] = np.array([count, 0, 0, 0, 0, 0], dtype=np.uint32)
    header.attrs["NumPart_Total"] = np.array([count, 0, 0, 0, 0, 0], dtype=np.uint64)
    header.attrs["MassTable"] = np.zeros(6)
    header.attrs["Time"] = 1.0
    header.attrs["NumFilesPerSnapshot"] = np.int32(1)
    gas = f.create_group("PartType0")
    for name, width, kind in COLUMNS:
        shape = (count,) if width == 1 else (count, width)
        values = np.arange(count, dtype=kind) if name == "ParticleIDs" else \
            rng.random(shape).astype(kind)
        gas.create_dataset(name, data=values)
print("%s: %d gas particles, %d datasets, %.0f MB" %
      (path, count, len(COLUMNS), os.path.getsize(path) / 1e6))


def read(arrays):
    """The fastest of 3 reads (s) and the output's memory (MB)."""
    best, memory = float("inf"), 0.0
    for _ in range(3):
        keywords = {} if arrays is None else {"PointArrays": arrays}
        reader = HDF5ParticleSnapshotReader(FileNames=[path], **keywords)
        reader.UpdatePipelineInformation()
        start = time.perf_counter()
        reader.UpdatePipeline()
        best = min(best, time.perf_counter() - start)
        memory = reader.GetDataInformation().GetMemorySize() / 1024.0
        Delete(reader)
    return best, memory


rows = []
for _ in range(2):  # in turn, twice: this machine's speed drifts over minutes
    rows.append((read(None), read(["Density", "SmoothingLength", "Masses"])))
for (all_time, all_memory), (three_time, three_memory) in rows:
    print("every array: %.3f s, %.0f MB; Density, SmoothingLength, Masses alone: %.3f s, %.0f MB;"
          " %.2fx faster, %.2fx less memory"
          % (all_time, all_memory, three_time, three_memory, all_time / three_time,
             all_memory / three_memory))
os.remove(path)
