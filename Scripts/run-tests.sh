#!/usr/bin/env bash
# SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
# SPDX-License-Identifier: BSD-3-Clause
# The tests: install, build, then every CTest test (numerics, filter, accuracy at reduced size,
# plain VTK example, pvpython, ParaView GUI under Xvfb), then the libFuzzer targets built with
# clang, ASan and UBSan, a bounded run each (Fuzz/run-fuzzers.sh, FUZZ_SECONDS=30).
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
bash "$here/Scripts/setup-debian12.sh"
cd "$here/build"
# Two tests at a time (this machine's cores; 15 -> 13 minutes here). The one test that times
# something, TestAbortLatency, runs alone (RUN_SERIAL).
ctest --output-on-failure --timeout 600 -j 2
bash "$here/Fuzz/run-fuzzers.sh"
