#!/usr/bin/env bash
# The tests: install, build, then every CTest test (numerics, filter, accuracy at reduced size,
# plain VTK example, pvpython, ParaView GUI under Xvfb).
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
bash "$here/Scripts/setup-debian12.sh"
cd "$here/build"
ctest --output-on-failure --timeout 600
