#!/usr/bin/env bash
# SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
# SPDX-License-Identifier: BSD-3-Clause
# The paper's case at 2M particles: 1 rank x 1 thread, 1 rank x 2 threads, 2 and 4 ranks x 1
# thread (pvbatch --symmetric under mpiexec --bind-to none, so that threads are not pinned to one
# core; on 2 cores 4 ranks are oversubscribed): the first run and a seed move, time,
# communication and peak memory per rank; JSON in Results/distributed/. With BASE (a commit),
# each configuration runs first with BASE's plugin (built in a git worktree under /tmp, a few
# minutes the first time), then with this build's: side by side, as this machine's speed drifts.
# Run after Scripts/setup-debian12.sh.
#   bash Scripts/run-distributed-benchmark.sh [BASE]
set -eu
root=$(cd "$(dirname "$0")/.." && pwd)
plugin=$(find "$root/build" -name LevelSetIsosurface.so | head -1)
out="$root/Results/distributed"
mkdir -p "$out"
data="$out/one_component_2M.vtp"
[ -f "$data" ] || "$root/build/bin/LevelSetGenerateData" one-component 2000000 "$data"
plugins=("$plugin")
names=(this)
if [ $# -gt 0 ]; then
  base=$(git -C "$root" rev-parse --short "$1")
  tree=/tmp/levelset-compare-$base
  [ -d "$tree" ] || git -C "$root" worktree add --detach "$tree" "$base" >/dev/null 2>&1
  log=$tree.log
  { cmake -S "$tree" -B "$tree/build" -DCMAKE_BUILD_TYPE=Release &&
    cmake --build "$tree/build" -j "$(nproc)" --target LevelSetIsosurface; } >"$log" 2>&1 ||
    { cat "$log"; exit 1; }
  plugins=("$(find "$tree/build" -name LevelSetIsosurface.so | head -1)" "$plugin")
  names=("$base" this)
fi
run() {
  for k in "${!plugins[@]}"; do
    echo "-- ${names[$k]}:"
    mpiexec --allow-run-as-root --oversubscribe --bind-to none -n "$1" pvbatch --symmetric \
      "$root/Scripts/distributed_benchmark.py" "${plugins[$k]}" "$data" "$2" \
      "$out/ranks$1_threads$2_${names[$k]}.json" 2>&1 | grep -v "^$"
  done
}
run 1 1
run 1 2
run 2 1
run 4 1
