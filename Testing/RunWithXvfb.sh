#!/bin/bash
# SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
# SPDX-License-Identifier: BSD-3-Clause
# Runs a command under xvfb-run, on a display searched from a random number, and again (up to
# three times) when the X server refused the connection ("bad X server connection": Xvfb not
# ready under load, which happened about once per full test run here). Any other failure is
# the command's own and is returned at once.
# Usage: RunWithXvfb.sh COMMAND [ARGS...]
set -u
log=$(mktemp)
trap 'rm -f "$log"' EXIT
for attempt in 1 2 3; do
  xvfb-run -a -n $((100 + RANDOM % 800)) "$@" >"$log" 2>&1
  status=$?
  cat "$log"
  if [ $status -eq 0 ] || ! grep -q "bad X server connection" "$log"; then
    exit $status
  fi
  echo "RunWithXvfb: the X server refused the connection (attempt $attempt); trying again"
  sleep 2
done
exit $status
