#!/usr/bin/env bash
# SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
# SPDX-License-Identifier: BSD-3-Clause
# Is a change faster? Times LevelSetBenchmark as built from another commit (BASE) and as built
# in ./build (the working tree), in turn, RUNS times each, and prints the fastest time of each
# stage for both, with their outputs (isopoints, mean distance) to show whether they changed,
# then the mean of each stage's times (a change that spares page faults, whose cost here varies
# from run to run, shows in the mean more than in the fastest run).
# Runs taken one after the other mislead here: this machine's speed drifts by 5-10% over
# minutes, more than most single changes gain. BASE is built in a git worktree under /tmp (a
# few minutes the first time; `git worktree remove` it when done). Run after
# Scripts/setup-debian12.sh.
#   bash Scripts/compare-speed.sh BASE [RUNS [LevelSetBenchmark arguments]]
#   e.g. bash Scripts/compare-speed.sh HEAD~1 5 --samples 2000000 --threads 1
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
base=$(git -C "$here" rev-parse --short "${1:?usage: compare-speed.sh BASE [RUNS [arguments]]}")
runs=${2:-5}
shift $(($# < 2 ? $# : 2))
[ $# -gt 0 ] || set -- --samples 2000000
tree=/tmp/levelset-compare-$base
if [ ! -d "$tree" ]; then
  git -C "$here" worktree add --detach "$tree" "$base" >/dev/null 2>&1
fi
log=$tree.log
build() { # quiet unless it fails
  "$@" >"$log" 2>&1 || { cat "$log"; exit 1; }
}
build cmake -S "$tree" -B "$tree/build" -DCMAKE_BUILD_TYPE=Release
build cmake --build "$tree/build" -j "$(nproc)" --target LevelSetBenchmark
build cmake --build "$here/build" -j "$(nproc)" --target LevelSetBenchmark
for ((i = 0; i < runs; ++i)); do
  "$tree/build/bin/LevelSetBenchmark" "$@" 2>&1 | sed "s/^/base /"
  "$here/build/bin/LevelSetBenchmark" "$@" 2>&1 | sed "s/^/work /"
done | awk -v base="$base" '
  { build = $1; $1 = ""; sub(/^ /, ""); key = "" }
  /^seconds total/ { key = "total"; value = $3 }
  /^seconds neighbours/ { key = "neighbours"; value = $3 }
  /^seconds initialisation/ { key = "initialisation"; value = $3 }
  /^seconds evolution/ { key = "evolution"; value = $3 }
  /^seconds isopoints/ { key = "isopoints"; value = $3 }
  /^seconds outputs/ { key = "outputs"; value = $3 }
  /^isopoints:/ { key = "isopoints (count)"; value = $2 }
  /^mean distance L/ { key = "mean distance"; value = $4 }
  key != "" {
    if (!(key in seen)) { seen[key] = 1; order[++n] = key }
    slot = build SUBSEP key
    if (!(slot in best) || value + 0 < best[slot] + 0) best[slot] = value
    sum[slot] += value; count[slot] += 1
  }
  END {
    printf "%-20s %12s %12s %8s\n", "fastest of each", base, "work tree", "ratio"
    for (i = 1; i <= n; ++i) {
      k = order[i]; a = best["base" SUBSEP k]; b = best["work" SUBSEP k]
      printf "%-20s %12s %12s %8s\n", k, a, b, (a + 0 > 0 ? sprintf("%.3f", b / a) : "")
    }
    printf "%-20s %12s %12s %8s\n", "mean of each", base, "work tree", "ratio"
    for (i = 1; i <= n; ++i) {
      k = order[i]
      if (k == "isopoints (count)" || k == "mean distance") continue
      a = sum["base" SUBSEP k] / count["base" SUBSEP k]; b = sum["work" SUBSEP k] / count["work" SUBSEP k]
      printf "%-20s %12.4g %12.4g %8s\n", k, a, b, (a > 0 ? sprintf("%.3f", b / a) : "")
    }
  }'
