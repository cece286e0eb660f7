#!/bin/bash
# SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
# SPDX-License-Identifier: BSD-3-Clause
# Errors under MPI are decided over all ranks and reported once: a seed sphere that holds no
# particle on any rank, and an IsoValue outside the whole data's range, each give exactly one
# error message (from rank 0) and an empty surface, on 3 pvbatch ranks; so does Particle Density
# on fewer particles than NumberOfNeighbors (together: each rank holds fewer). An array shorter
# than the points (5 tuples on every rank's piece) is left out of the surface, as in serial, and
# the surface is still made: sending it over the ranks read past its end.
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
# An array with 5 tuples on every rank's piece, however many points the piece has. (Last: in
# pvbatch the programmable filter's script runs in this interpreter and may rebind its names.)
from paraview.simple import ProgrammableFilter  # noqa: E402
short = ProgrammableFilter(Input=source, OutputDataSetType="vtkPolyData", Script="""
from vtkmodules.vtkCommonCore import vtkFloatArray
out = self.GetPolyDataOutput()
out.ShallowCopy(self.GetPolyDataInput())
array = vtkFloatArray()
array.SetName("short")
array.SetNumberOfTuples(5)
array.Fill(1.0)
out.GetPointData().AddArray(array)
""")
surface = LevelSetIsosurface(Input=short, Scalars=["POINTS", "f"], IsoValue=0.0,
                             SeedCenter=[64, 64, 64], SeedRadius=12, OutputType="Isopoints")
surface.UpdatePipeline()
result = servermanager.Fetch(surface)
print("CASE short: %d surface points, 'short' array %s, 'f' array %s" % (
    result.GetNumberOfPoints(), result.GetPointData().GetArray("short") is not None,
    result.GetPointData().GetArray("f") is not None))
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
grep -qE "CASE short: [1-9][0-9]* surface points, 'short' array False, 'f' array True" <<<"$out" ||
  { echo "FAIL: with a short array, no surface, or the short array sent over the ranks"; status=1; }
exit $status
