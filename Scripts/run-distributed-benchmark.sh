#!/usr/bin/env bash
# SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
# SPDX-License-Identifier: BSD-3-Clause
# The paper's case at 2M particles: 1 rank x 1 thread, 1 rank x 2 threads, 2 and 4 ranks x 1
# thread (pvbatch --symmetric under mpiexec --bind-to none, so that threads are not pinned to one
# core; on 2 cores 4 ranks are oversubscribed), time, communication and
# peak memory per rank; JSON in Results/distributed/. Run after Scripts/setup-debian12.sh.
set -eu
root=$(cd "$(dirname "$0")/.." && pwd)
plugin=$(find "$root/build" -name LevelSetIsosurface.so | head -1)
out="$root/Results/distributed"
mkdir -p "$out"
data="$out/one_component_2M.vtp"
[ -f "$data" ] || "$root/build/bin/LevelSetGenerateData" one-component 2000000 "$data"
run() {
  mpiexec --allow-run-as-root --oversubscribe --bind-to none -n "$1" pvbatch --symmetric \
    "$root/Scripts/distributed_benchmark.py" "$plugin" "$data" "$2" "$out/ranks$1_threads$2.json" \
    2>&1 | grep -v "^$"
}
run 1 1
run 1 2
run 2 1
run 4 1
