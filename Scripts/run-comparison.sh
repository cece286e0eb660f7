#!/usr/bin/env bash
# SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
# SPDX-License-Identifier: BSD-3-Clause
# Issue 4's benchmark: for each case at 2M particles, in one process each, the level-set filter
# (defaults; unrefined; the paper's seed-sphere start), the Rosenthal-Linsen scheme and the grid
# route (SPH interpolation + Flying Edges + connectivity), with the 1- vs 2-thread comparison
# on the one-component case; then the filter alone at 20M. Tables go to stdout and
# Results/compare-*.txt, JSON to Results/compare-*.json. About 8 minutes here.
# Run after Scripts/setup-debian12.sh (or run-tests.sh), which builds build/bin.
#
#   Scripts/run-comparison.sh --sph [SHARED_DATA_DIR]
# runs only issue 13's real-data comparison (Scripts/sph_comparison.py): the filter, ParaView's
# SPH grid route and yt against the SPH field's own isosurface on the real snapshots in
# ../shared/data (default), to Results/sph-comparison.{txt,json}. About 4 minutes here; yt
# comes from Debian's python3-yt (installed here if missing).
set -eu
root=$(cd "$(dirname "$0")/.." && pwd)
bin=$root/build/bin
out=$root/Results
mkdir -p "$out"
if [ "${1:-}" = --sph ]; then
  shared=${2:-$root/../shared/data}
  if ! /usr/bin/python3 -c 'import yt' 2>/dev/null; then
    apt-get install -y python3-yt >/dev/null 2>&1 || echo "python3-yt not installed: no yt rows"
  fi
  pvpython "$root/Scripts/sph_comparison.py" \
    "$root/build/lib/paraview-5.11/plugins/LevelSetIsosurface/LevelSetIsosurface.so" "$shared" \
    --json "$out/sph-comparison.json" 2>/dev/null | grep -v '^Interpolating' | tee "$out/sph-comparison.txt"
  exit 0
fi
for c in one-component multi-component adaptive-noisy; do
  extra=""
  [ "$c" = one-component ] && extra="--compare-threads"
  echo "=== LevelSetCompare --case $c --samples 2000000 $extra"
  "$bin/LevelSetCompare" --case "$c" --samples 2000000 --json "$out/compare-$c.json" $extra \
    | tee "$out/compare-$c.txt"
done
echo "=== LevelSetCompare --case one-component --samples 20000000 --methods level-set"
"$bin/LevelSetCompare" --case one-component --samples 20000000 --methods level-set \
  --json "$out/compare-one-component-20M.json" | tee "$out/compare-one-component-20M.txt"
