#!/usr/bin/env bash
# SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
# SPDX-License-Identifier: BSD-3-Clause
# The filter's first runs and re-runs on the real snapshots (Scripts/sph_reruns.py: splats and
# Isopoints; first run, the method after an isovalue change, a quick 2% change, a seed move, an
# OutputType change), for this build and, given a BASE commit, for that commit's build too, in
# turn, RUNS times each (this machine's speed drifts by 5-10% over minutes: compare runs taken
# side by side). BASE is built in a git worktree under /tmp (a few minutes the first time).
# About 2 minutes per run and build here. Run after Scripts/setup-debian12.sh.
# PLUMMER_SAMPLES=N adds a synthetic case of N particles (Scripts/sph_reruns.py).
#   bash Scripts/run-sph-reruns.sh [BASE [RUNS [SHARED_DATA_DIR]]]
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
runs=${2:-1}
shared=${3:-$here/../shared/data}
plugin=lib/paraview-5.11/plugins/LevelSetIsosurface/LevelSetIsosurface.so
cmake --build "$here/build" -j "$(nproc)" --target LevelSetIsosurface >/dev/null
builds=("$here/build")
if [ -n "${1:-}" ]; then
  base=$(git -C "$here" rev-parse --short "$1")
  tree=/tmp/levelset-compare-$base
  [ -d "$tree" ] || git -C "$here" worktree add --detach "$tree" "$base" >/dev/null 2>&1
  { cmake -S "$tree" -B "$tree/build" -DCMAKE_BUILD_TYPE=Release &&
    cmake --build "$tree/build" -j "$(nproc)" --target LevelSetIsosurface; } >"$tree.log" 2>&1 ||
    { cat "$tree.log"; exit 1; }
  builds=("$tree/build" "$here/build")
fi
for ((i = 0; i < runs; ++i)); do
  for b in "${builds[@]}"; do
    label=$([ "$b" = "$here/build" ] && echo this || echo "base $base")
    echo "=== $label (run $((i + 1)) of $runs)"
    pvpython "$here/Scripts/sph_reruns.py" "$b/$plugin" "$shared" 2>/dev/null |
      grep -v '^Interpolating'
  done
done
