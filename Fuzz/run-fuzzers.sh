#!/usr/bin/env bash
# SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
# SPDX-License-Identifier: BSD-3-Clause
# Builds the libFuzzer targets with clang (ASan, UBSan) in build-fuzz and runs each for a bounded
# time (FUZZ_SECONDS, default 30: the four targets, one per core at a time, in 1 minute here;
# FUZZ_TARGETS to run only some) on a copy of its corpus in Fuzz/corpus. A crash, a sanitizer
# report, a leak or an input that takes longer than 20 s fails (exit status not 0); the input is
# then left in build-fuzz/ as crash-* / timeout-*.
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
seconds=${FUZZ_SECONDS:-30}
CC=clang CXX=clang++ cmake -S "$here/Fuzz" -B "$here/build-fuzz" -DCMAKE_BUILD_TYPE=Debug >/dev/null
cmake --build "$here/build-fuzz" -j "$(nproc)"
cd "$here/build-fuzz"
targets="FuzzTipsyReader FuzzGadgetBinaryReader FuzzHDF5SnapshotReader FuzzLevelSetIsosurface"
# One target per core at a time (each fuzzes in one process): 2 minutes -> 1 here.
run_one() {
  local target=$1 corpus="$here/build-fuzz/corpus-$1"
  rm -rf "$corpus"
  cp -r "$here/Fuzz/corpus/$target" "$corpus"
  ASAN_OPTIONS=detect_leaks=0 "./bin/$target" -max_total_time="$seconds" -timeout=20 \
    -rss_limit_mb=4096 -print_final_stats=1 "$corpus" > "log-$target" 2>&1
}
failed=0
set -- ${FUZZ_TARGETS:-$targets}
while [ $# -gt 0 ]; do
  batch=()
  for _ in $(seq "$(nproc)"); do
    [ $# -gt 0 ] || break
    batch+=("$1")
    shift
  done
  pids=()
  for target in "${batch[@]}"; do
    run_one "$target" &
    pids+=($!)
  done
  for k in "${!batch[@]}"; do
    status=0
    wait "${pids[$k]}" || status=$?
    echo "=== ${batch[$k]}, $seconds s (exit status $status)"
    grep -E "^#|stat::|ERROR|SUMMARY|Done" "log-${batch[$k]}" | tail -8 || true
    [ "$status" -eq 0 ] || failed=1
  done
done
exit "$failed"
