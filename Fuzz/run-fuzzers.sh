#!/usr/bin/env bash
# SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
# SPDX-License-Identifier: BSD-3-Clause
# Builds the libFuzzer targets with clang (ASan, UBSan) in build-fuzz and runs each for a bounded
# time (FUZZ_SECONDS, default 30: the four targets in 2 minutes; FUZZ_TARGETS to run only some)
# on a copy of its corpus in Fuzz/corpus. A crash, a sanitizer report, a leak or an input that
# takes longer than 20 s fails (exit status not 0); the input is then left in build-fuzz/ as
# crash-* / timeout-*.
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
seconds=${FUZZ_SECONDS:-30}
CC=clang CXX=clang++ cmake -S "$here/Fuzz" -B "$here/build-fuzz" -DCMAKE_BUILD_TYPE=Debug >/dev/null
cmake --build "$here/build-fuzz" -j "$(nproc)"
cd "$here/build-fuzz"
targets="FuzzTipsyReader FuzzGadgetBinaryReader FuzzHDF5SnapshotReader FuzzLevelSetIsosurface"
for target in ${FUZZ_TARGETS:-$targets}; do
  corpus="$here/build-fuzz/corpus-$target"
  rm -rf "$corpus"
  cp -r "$here/Fuzz/corpus/$target" "$corpus"
  echo "=== $target, $seconds s"
  ASAN_OPTIONS=detect_leaks=0 "./bin/$target" -max_total_time="$seconds" -timeout=20 \
    -rss_limit_mb=4096 -print_final_stats=1 "$corpus" 2>&1 | grep -E "^#|stat::|ERROR|SUMMARY|Done" | tail -8
  test "${PIPESTATUS[0]}" -eq 0
done
