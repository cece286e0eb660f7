#!/bin/bash
# SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
# SPDX-License-Identifier: BSD-3-Clause
# Errors under MPI are decided over all ranks and reported once: a seed sphere that holds no
# particle on any rank, and an IsoValue outside the whole data's range, each give exactly one
# error message (from rank 0) and an empty surface, on 3 pvbatch ranks; so does Particle Density
# on fewer particles than NumberOfNeighbors (together: each rank holds fewer).
# Usage: TestDistributedErrors.sh MPIEXEC PVBATCH PLUGIN DATA.vtp
set -u
mpiexec=$1 pvbatch=$2 plugin=$3 data=$4
script=$(mktemp --suffix=.py)
trap 'rm -f "$script"' EXIT
cat >"$script" <<PY
import sys
from paraview import servermanager
from paraview.simple import LoadPlugin, XMLPolyDataReader
LoadPlugin("$plugin", ns=globals())
source = XMLPolyDataReader(FileName=["$data"])
for name, options in [("seed", dict(IsoValue=0.0, SeedCenter=[500, 500, 500], SeedRadius=3)),
                      ("isovalue", dict(IsoValue=1e9, SeedCenter=[64, 64, 64], SeedRadius=12))]:
    surface = LevelSetIsosurface(Input=source, Scalars=["POINTS", "f"], **options)
    surface.UpdatePipeline()
    count = servermanager.Fetch(surface).GetNumberOfPoints()
    print("CASE %s: %d surface points" % (name, count))
# Particle Density on fewer particles (on all ranks together) than NumberOfNeighbors.
from paraview.simple import MaskPoints  # noqa: E402
few = MaskPoints(Input=source, OnRatio=20000, GenerateVertices=1, RandomSampling=0)
density = ParticleDensity(Input=few, NumberOfNeighbors=64)
density.UpdatePipeline()
print("CASE density: %d points" % servermanager.Fetch(density).GetNumberOfPoints())
PY
status=0
out=$("$mpiexec" --allow-run-as-root --oversubscribe -n 3 "$pvbatch" "$script" 2>&1)
echo "$out"
seed=$(grep -c "contains no sample" <<<"$out")
iso=$(grep -c "outside the open range" <<<"$out")
failures=$(grep -c "Algorithm vtkLevelSetIsosurface.*returned failure" <<<"$out")
few=$(grep -c "fewer than NumberOfNeighbors" <<<"$out")
density_failures=$(grep -c "Algorithm vtkParticleDensity.*returned failure" <<<"$out")
echo "messages: seed $seed, isovalue $iso, executive failures $failures;" \
  "Particle Density: too few $few, executive failures $density_failures"
[ "$few" = 1 ] || { echo "FAIL: too few particles for Particle Density reported $few times"; status=1; }
[ "$density_failures" -le 1 ] || { echo "FAIL: $density_failures executives report Particle Density's failure"; status=1; }
grep -q "CASE density: 0 points" <<<"$out" || { echo "FAIL: Particle Density's output not empty"; status=1; }
[ "$failures" -le 2 ] || { echo "FAIL: $failures executives report a failure (rank 0 only: 2)"; status=1; }
[ "$seed" = 1 ] || { echo "FAIL: the empty seed sphere is reported $seed times, not once"; status=1; }
[ "$iso" = 1 ] || { echo "FAIL: the bad IsoValue is reported $iso times, not once"; status=1; }
grep -q "CASE seed: 0 surface points" <<<"$out" || { echo "FAIL: seed case not empty"; status=1; }
grep -q "CASE isovalue: 0 surface points" <<<"$out" || { echo "FAIL: isovalue case not empty"; status=1; }
exit $status
