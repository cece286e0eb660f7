# SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
# SPDX-License-Identifier: BSD-3-Clause
"""pvpython TestEnclosedOverTime.py PLUGIN SNAPSHOT_DIR

What the surface encloses over time, the way a GUI user gets it: the GADGET-4 gas sphere's
snapshots opened as one time series, Level-Set Isosurface at a fixed density with every
component seeded, and ParaView's Plot Data Over Time on its Enclosed port (rows). Checks that the
plot has one row per time step for the Total row, and that its masses are the table's own at each
time step (the filter run at that time), to 1e-12."""
import glob
import os
import sys

from paraview import servermanager
from paraview.simple import LoadPlugin, OpenDataFile, OutputPort, PlotDataOverTime

plugin, directory = sys.argv[1:3]
LoadPlugin(plugin, ns=globals())
reader = OpenDataFile(sorted(glob.glob(os.path.join(directory, "snapshot_*.hdf5"))))
reader.UpdatePipelineInformation()
reader.ParticleTypes = ["Gas (PartType0)"]
times = list(reader.TimestepValues)
reader.UpdatePipeline(times[0])
surface = LevelSetIsosurface(Input=reader, IsoValue=1e13, SeedRadius=0.0)
direct = []
for t in times:
    surface.UpdatePipeline(t)
    table = surface.GetClientSideObject().GetOutputDataObject(3)
    total = table.GetNumberOfRows() - 1
    direct.append(table.GetValueByName(total, "Mass").ToDouble())
plot = PlotDataOverTime(Input=OutputPort(surface, 3), FieldAssociation="Rows",
                        OnlyReportSelectionStatistics=0)
plot.UpdatePipeline()
blocks = servermanager.Fetch(plot)
last = blocks.GetBlock(blocks.GetNumberOfBlocks() - 1)  # the Total row's history
plotted = [last.GetValueByName(r, "Mass").ToDouble() for r in range(last.GetNumberOfRows())]
print("time steps %s\nmass per time step (filter) %s\nmass over time (Plot Data Over Time) %s"
      % (times, direct, plotted))
ok = len(plotted) == len(times) and all(
    abs(a - b) <= 1e-12 * abs(b) for a, b in zip(plotted, direct)) and direct[0] > 0
print("all checks passed" if ok else "FAILED: the plotted masses are not the filter's")
sys.exit(0 if ok else 1)
