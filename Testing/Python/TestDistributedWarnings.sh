#!/bin/bash
# SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
# SPDX-License-Identifier: BSD-3-Clause
# Warnings under MPI are decided over all ranks and given once. The SWIFT Roberts flow with its
# masses made 3 times larger (densities in other units than the masses, to the density check):
# on 3 pvbatch ranks, exactly one warning that the stored densities are not the kernel sums,
# saying 3 times (the check's median over the particles next to the surface, every rank's), and
# on every rank the fall-back to the MLS fit: the surface gathered from the ranks is, point for
# point, the one that Field = MLS gives. With the file's own masses: no such warning, and the
# SPH field's surface (not the MLS one).
# Usage: TestDistributedWarnings.sh MPIEXEC PVBATCH PLUGIN SWIFT_FILE
set -u
# Each case in a run of its own: every warning in a run's output is its case's (mpiexec merges
# the ranks' stdout and stderr in no promised order).
run() {
  "$1" --allow-run-as-root --oversubscribe -n 3 "$2" \
    "$(dirname "$0")/TestDistributedWarnings.py" "$3" "$4" "$5" 2>&1
}
heavyOut=$(run "$@" heavy)
rightOut=$(run "$@" right)
status=0
echo "$heavyOut"
echo "$rightOut"
heavy=$(grep -c "are not the kernel sums" <<<"$heavyOut")
right=$(grep -c "are not the kernel sums" <<<"$rightOut")
factor=$(grep -o "the sums are [0-9.e+-]* times" <<<"$heavyOut" | head -1 | awk '{print $4}')
if [ "$heavy" != 1 ]; then
  echo "FAILED: $heavy density warnings with 3 times the masses on 3 ranks (expected 1)"
  status=1
fi
if ! awk -v f="${factor:-0}" 'BEGIN { exit !(f > 2.97 && f < 3.03) }'; then
  echo "FAILED: the warning's factor '$factor' (expected 3 within 1%)"
  status=1
fi
if ! grep -qE "^CASE heavy: ([1-9][0-9]*) and \1 points, largest difference 0$" <<<"$heavyOut"; then
  echo "FAILED: with 3 times the masses the surface is not the MLS fit's on every rank"
  status=1
fi
if [ "$right" != 0 ]; then
  echo "FAILED: $right density warnings with the file's masses (expected 0)"
  status=1
fi
if grep -qE "^CASE right: .*largest difference 0$" <<<"$rightOut"; then
  echo "FAILED: with the file's masses the surface is not the SPH field's"
  status=1
fi
[ "$status" = 0 ] && echo "PASSED"
exit "$status"
