#!/usr/bin/env bash
# SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
# SPDX-License-Identifier: BSD-3-Clause
# The 2M-sample benchmark behind RESULTS.md (about 6 minutes here): each case, then the
# 1- versus 2-thread comparison. Run after Scripts/setup-debian12.sh (or run-tests.sh).
set -u
bin=$(cd "$(dirname "$0")/.." && pwd)/build/bin
for args in "--case one-component" "--case one-component --paper-parameters" \
  "--case multi-component" "--case multi-component --paper-parameters" \
  "--case one-component --scheme 1 --print-table" "--case multi-component --scheme 1 --print-table"; do
  echo "=== LevelSetBenchmark --samples 2000000 $args"
  "$bin/LevelSetBenchmark" --samples 2000000 $args
done
echo "=== threads"
"$bin/LevelSetBenchmark" --samples 2000000 --case one-component --compare-threads | tail -3
