#!/usr/bin/env bash
# SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
# SPDX-License-Identifier: BSD-3-Clause
# The same outputs on any number of MPI ranks, on the real snapshots of ../shared/data (about 3
# minutes here): Scripts/mpi_consistency.py runs the filter on one process, then on 2, 3 and 4
# pvbatch ranks as the files are read (each rank its share; the filter spreads them by space
# itself), and prints each run's largest differences from the one-process run. (Not after
# ParaView's Distribute Points: it stores the coordinates as floats and drops ParticleIDs, so
# its particles are not the file's.) Also on the halo-tracer snapshots that
# Scripts/make_halo_tracer_snapshot.py makes (40,000 particles). Run after Scripts/setup-debian12.sh.
#   bash Scripts/run-mpi-consistency.sh [DATA_DIR]
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
data=${1:-$here/../shared/data}
plugin=$here/build/lib/paraview-5.11/plugins/LevelSetIsosurface/LevelSetIsosurface.so
script=$here/Scripts/mpi_consistency.py
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
mpi=(mpiexec --allow-run-as-root --oversubscribe -n)
# A strongly adaptive SWIFT-layout snapshot made here, in Mpc and in kpc (none is in shared/).
/usr/bin/python3 "$here/Scripts/make_halo_tracer_snapshot.py" "$out" 40000 > /dev/null
pvbatch "$script" run "$plugin" "$data" "$out/1.npz" made="$out" > /dev/null
for ranks in 2 3 4; do
  "${mpi[@]}" "$ranks" pvbatch "$script" run "$plugin" "$data" "$out/$ranks.npz" made="$out" \
    > /dev/null
  echo "== $ranks ranks against one process"
  pvpython "$script" compare "$out/1.npz" "$out/$ranks.npz"
done
