#!/usr/bin/env bash
# SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
# SPDX-License-Identifier: BSD-3-Clause
# The tests: install, build, then every CTest test (numerics, filter, accuracy at reduced size,
# plain VTK example, pvpython, ParaView GUI under Xvfb).
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
bash "$here/Scripts/setup-debian12.sh"
cd "$here/build"
ctest --output-on-failure --timeout 600
