# SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
# SPDX-License-Identifier: BSD-3-Clause
"""pvbatch Scripts/enclosed_mass_series.py PLUGIN SNAPSHOT_DIR OUT_PNG [ISOVALUE]

Issue 18's time series: the GADGET-4 gas sphere's snapshots (SNAPSHOT_DIR/snapshot_*.hdf5, opened
as one time series as File > Open does), Level-Set Isosurface at a fixed density (default 1e13,
about twelve times the median) with every component seeded, and at each time step the "Total"
row of port 3 (what the surface encloses): mass, volume, particles. Prints the table, writes it
as CSV beside the PNG, and draws mass and volume against time (matplotlib)."""
import glob
import os
import sys

from paraview.simple import LoadPlugin, OpenDataFile

plugin, directory, png = sys.argv[1:4]
iso = float(sys.argv[4]) if len(sys.argv) > 4 else 1e13
LoadPlugin(plugin, ns=globals())
files = sorted(glob.glob(os.path.join(directory, "snapshot_*.hdf5")))
reader = OpenDataFile(files)
reader.UpdatePipelineInformation()
reader.ParticleTypes = ["Gas (PartType0)"]
reader.UpdatePipeline(reader.TimestepValues[0])  # as Apply does: the arrays are known
surface = LevelSetIsosurface(Input=reader, IsoValue=iso, SeedRadius=0.0)
times = list(reader.TimestepValues)
rows = []
for t in times:
    surface.UpdatePipeline(t)
    table = surface.GetClientSideObject().GetOutputDataObject(3)
    last = table.GetNumberOfRows() - 1
    value = lambda name: table.GetValueByName(last, name).ToDouble()  # noqa: E731
    rows.append((t, value("Particles"), value("Mass"), value("Volume"), last))
print("%8s %10s %12s %12s %11s" % ("time", "particles", "mass", "volume", "components"))
for t, particles, mass, volume, components in rows:
    print("%8.3f %10d %12.4g %12.4g %11d" % (t, particles, mass, volume, components))
with open(os.path.splitext(png)[0] + ".csv", "w") as out:
    out.write("time,particles,mass,volume,components\n")
    for row in rows:
        out.write("%.6g,%d,%.6g,%.6g,%d\n" % row)

import matplotlib  # noqa: E402

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

figure, left = plt.subplots(figsize=(6, 3.5), dpi=100)
left.plot([r[0] for r in rows], [r[2] for r in rows], "o-", color="tab:blue")
left.set_xlabel("time (code units)")
left.set_ylabel("enclosed mass (code units)", color="tab:blue")
right = left.twinx()
right.plot([r[0] for r in rows], [r[3] for r in rows], "s--", color="tab:red")
right.set_ylabel("enclosed volume (code units)", color="tab:red")
left.set_title("GADGET-4 gas sphere: gas above density %.3g" % iso)
figure.tight_layout()
figure.savefig(png)
print("wrote", png)
