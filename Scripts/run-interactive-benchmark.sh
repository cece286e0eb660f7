#!/usr/bin/env bash
# SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
# SPDX-License-Identifier: BSD-3-Clause
# Issue 16's benchmark, in one run (about 3 minutes here): on the paper's one-component case at
# 2M particles, the first run of this filter and of the grid route (SPH interpolation onto a
# grid, Flying Edges, connectivity) per stage, with their mean distances to the exact surface;
# re-runs after an isovalue change (with QuickIsoValueChanges off and on) and a seed move (and a
# CurvatureWeight change, and output-only changes: to splats, a new SplatScale) against the grid
# route's re-contour and re-connect; a slider dragged back and forth (24 quick changes); 1
# against 2 threads (the fastest of 5 runs each); and first runs at 2M and 20M particles, each
# in a process of its own, with peak memory per particle and the profiles of their re-runs.
# Prints a table and writes Results/interactive-benchmark.json. Run after
# Scripts/setup-debian12.sh.
#   bash Scripts/run-interactive-benchmark.sh [SAMPLES [SCALING_SAMPLES]]
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
mkdir -p "$here/Results"
"$here/build/bin/LevelSetInteractive" --samples "${1:-2000000}" \
  --scaling-samples "${2:-20000000}" --json "$here/Results/interactive-benchmark.json"
echo "written: Results/interactive-benchmark.json"
