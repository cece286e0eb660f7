# SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
# SPDX-License-Identifier: BSD-3-Clause
"""Seconds to read a Tipsy file's auxiliary arrays, text against binary.

Writes a Tipsy file of N gas particles (default 2,000,000) with one auxiliary array beside it in
each of ChaNGa's two forms (SNAPSHOT.HI as text, SNAPSHOT.HIbin as binary floats) into a
temporary directory, then reads the gas with its mass alone, with the binary array and with
the text array, RUNS times each in turn, and prints the median seconds of each and the arrays'
own cost (the read minus the mass-only read). To compare two builds, run it for each, one after
the other (one plugin per process):

    pvpython Scripts/tipsy_aux_benchmark.py PLUGIN [--particles N] [--runs R]
"""
import os
import statistics
import struct
import sys
import tempfile
import time

import numpy as np
from paraview import servermanager
from paraview.simple import Delete, LoadPlugin


def write_files(folder, n):
    rng = np.random.default_rng(1)
    path = os.path.join(folder, "snap.std")
    gas = np.zeros((n, 12), dtype=">f4")
    gas[:, 0] = 1.0 / n
    gas[:, 1:4] = rng.random((n, 3)) - 0.5
    gas[:, 7] = 1.0
    with open(path, "wb") as out:
        out.write(struct.pack(">diiiiii", 0.0, n, 3, n, 0, 0, 0))
        out.write(gas.tobytes())
    values = rng.random(n)
    with open(path + ".HI", "w") as out:
        out.write("%d\n" % n)
        out.write("\n".join("%.7g" % v for v in values))
        out.write("\n")
    with open(path + ".HIbin", "wb") as out:
        out.write(struct.pack(">i", n) + values.astype(">f4").tobytes())
    return path


def read_seconds(path, arrays):
    reader = servermanager.sources.TipsyParticleReader(FileNames=[path])
    reader.UpdatePipelineInformation()
    reader.PointArrays = arrays
    start = time.perf_counter()
    reader.UpdatePipeline()
    seconds = time.perf_counter() - start
    Delete(reader)
    return seconds


def main(argv):
    particles, runs, plugins = 2000000, 5, []  # (one plugin)
    i = 0
    while i < len(argv):
        if argv[i] in ("--particles", "--runs"):
            value = int(argv[i + 1])
            particles, runs = (value, runs) if argv[i] == "--particles" else (particles, value)
            i += 2
        else:
            plugins.append(argv[i])
            i += 1
    if len(plugins) != 1:
        print(__doc__)
        return 1
    reads = {"mass only": ["mass"], "binary array": ["mass", "HIbin"],
             "text array": ["mass", "HI"]}
    with tempfile.TemporaryDirectory() as folder:
        path = write_files(folder, particles)
        print("Tipsy file of %d gas particles; median of %d runs, seconds" % (particles, runs))
        LoadPlugin(plugins[0], ns=globals())
        times = {name: [] for name in reads}
        for _ in range(runs):
            for name, arrays in reads.items():
                times[name].append(read_seconds(path, arrays))
        median = {name: statistics.median(t) for name, t in times.items()}
        print("plugin %s" % plugins[0])
        for name in reads:
            own = median[name] - median["mass only"]
            print("  %-14s %.3f s   the array's own %.3f s" % (name, median[name], own))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
