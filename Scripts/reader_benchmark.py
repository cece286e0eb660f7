# SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
# SPDX-License-Identifier: BSD-3-Clause
"""pvpython Scripts/reader_benchmark.py PLUGIN [PARTICLES [DIR]]

What the readers' point array selection (PointArrays) and regions (ReadRegion) save on a wide
snapshot. Writes an HDF5 snapshot of PARTICLES gas particles (default 2,000,000) in DIR (default
/tmp), uniform in the unit cube and stored by top-level cell (16^3 cells) as SWIFT stores them,
with SWIFT's cell table, and the arrays an IllustrisTNG-style run keeps per gas particle (16
datasets, 34 values per particle, GADGET's names for the SPH field's three). Then reads it
through ParaView's reader proxy, in turn: every array; the SPH field's three alone (Density,
SmoothingLength, Masses); the region [0.4, 0.6]^3 (0.8% of the volume) with every array; the
region with the three. The fastest of 3 reads each (the file in the page cache, so this is the
reader's own cost, not the disk's), the output's memory (ParaView's data information) and the
particles the reader scanned. Prints each against the read of every array. Then each read once
more in a pvpython process of its own, for how far it raised the process's peak resident memory
above what it held before the read (the reader's working memory: the output and whatever the
read held on the way)."""
import os
import shutil
import subprocess
import sys
import time

import h5py
import numpy as np
from paraview.simple import Delete, LoadPlugin

plugin = sys.argv[1]
count = int(sys.argv[2]) if len(sys.argv) > 2 else 2000000
folder = sys.argv[3] if len(sys.argv) > 3 else "/tmp"
peak_case = int(sys.argv[5]) if len(sys.argv) > 5 and sys.argv[4] == "--peak" else None
LoadPlugin(plugin, ns=globals())
path = os.path.join(folder, "levelset_wide_snapshot_%d.hdf5" % count)
THREE = ["Density", "SmoothingLength", "Masses"]
REGION = [0.4, 0.6] * 3
CASES = [("every array", {}), ("the three arrays", {"PointArrays": THREE}),
         ("the region, every array", {"ReadRegion": 1, "RegionBounds": REGION}),
         ("the region, the three arrays",
          {"ReadRegion": 1, "RegionBounds": REGION, "PointArrays": THREE})]


def memory_mb(field):
    """This process's resident memory now (VmRSS) or at its peak (VmHWM), in MB."""
    with open("/proc/self/status") as status:
        for line in status:
            if line.startswith(field + ":"):
                return int(line.split()[1]) / 1024.0
    return 0.0


if peak_case is not None:  # the child: one read, and how far it raised the peak above before
    reader = HDF5ParticleSnapshotReader(FileNames=[path], **CASES[peak_case][1])
    reader.UpdatePipelineInformation()
    with open("/proc/self/clear_refs", "w") as clear:
        clear.write("5")  # the peak (VmHWM) starts again from what the process holds now
    before = memory_mb("VmRSS")
    reader.UpdatePipeline()
    print("PEAK %.1f" % (memory_mb("VmHWM") - before))
    sys.exit(0)

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
side = 16  # top-level cells per side
position = rng.random((count, 3))
cell = (np.floor(position * side).astype(np.int64) * [side * side, side, 1]).sum(axis=1)
order = np.argsort(cell, kind="stable")
position, cell = position[order], cell[order]
cells = np.bincount(cell, minlength=side ** 3)
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
        if name == "Coordinates":
            values = position
        elif name == "ParticleIDs":
            values = np.arange(count, dtype=kind)
        else:
            values = rng.random(shape, dtype=np.float32).astype(kind)
        gas.create_dataset(name, data=values)
    table = f.create_group("Cells")
    table.create_group("Meta-data").attrs["size"] = np.full(3, 1.0 / side)
    index = np.stack(np.unravel_index(np.arange(side ** 3), (side,) * 3), axis=1)
    table["Centres"] = (index + 0.5) / side
    table.create_group("Counts")["PartType0"] = cells
    table.create_group("OffsetsInFile")["PartType0"] = np.concatenate([[0], np.cumsum(cells)[:-1]])
    table.create_group("Files")["PartType0"] = np.zeros(side ** 3, dtype=np.int32)
print("%s: %d gas particles, %d datasets, %d cells, %.0f MB" %
      (path, count, len(COLUMNS), side ** 3, os.path.getsize(path) / 1e6))



def read(keywords):
    """The fastest of 3 reads (s), the output's memory (MB), its particles and those scanned."""
    best = float("inf")
    for _ in range(3):
        reader = HDF5ParticleSnapshotReader(FileNames=[path], **keywords)
        reader.UpdatePipelineInformation()
        start = time.perf_counter()
        reader.UpdatePipeline()
        best = min(best, time.perf_counter() - start)
        memory = reader.GetDataInformation().GetMemorySize() / 1024.0
        points = reader.GetDataInformation().GetNumberOfPoints()
        reader.UpdatePropertyInformation()
        scanned = reader.GetProperty("ParticlesScanned").GetData()
        Delete(reader)
    return best, memory, points, scanned


for run in range(2):  # in turn, twice: this machine's speed drifts over minutes
    results = [(name, read(keywords)) for name, keywords in CASES]
    every_time, every_memory = results[0][1][0], results[0][1][1]
    print("run %d" % (run + 1))
    for name, (seconds, memory, points, scanned) in results:
        print("  %-30s %7.3f s %6.0f MB %9d particles (%9d scanned)  %6.2fx faster, %6.2fx less "
              "memory" % (name, seconds, memory, points, scanned, every_time / seconds,
                          every_memory / memory))

# Peak memory: each read in a process of its own (a process's peak never falls).
pvpython = shutil.which("pvpython") or "/usr/bin/pvpython"
print("peak resident memory a read adds (its own pvpython process, one read each)")
for k, (name, _) in enumerate(CASES):
    child = subprocess.run([pvpython, os.path.abspath(__file__), plugin, str(count), folder,
                            "--peak", str(k)], capture_output=True, text=True)
    lines = [line for line in child.stdout.splitlines() if line.startswith("PEAK ")]
    print("  %-30s %7s MB" % (name, lines[-1].split()[1] if lines else "failed"))
os.remove(path)
