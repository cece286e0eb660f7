#!/bin/bash
# SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
# SPDX-License-Identifier: BSD-3-Clause
# The filter through a pvserver on 2 MPI ranks, as users run it: a pvpython client connects,
# applies it, fetches the result and compares it with the serial reference.
# Usage: TestPVServer.sh MPIEXEC PVSERVER PVPYTHON TestDistributed.py PLUGIN CASE DATA SEED REFERENCE
set -u
mpiexec=$1 pvserver=$2 pvpython=$3
shift 3
port=$((20000 + RANDOM % 20000))
log=$(mktemp)
"$mpiexec" --allow-run-as-root --oversubscribe -n 2 "$pvserver" --server-port=$port \
  --multi-clients=0 >"$log" 2>&1 &
server=$!
trap 'kill $server 2>/dev/null; wait $server 2>/dev/null; rm -f "$log"' EXIT
for _ in $(seq 100); do
  grep -q "Accepting connection" "$log" && break
  sleep 0.2
done
grep -q "Accepting connection" "$log" || { echo "pvserver did not start:"; cat "$log"; exit 1; }
"$pvpython" "$@" connect=$port
status=$?
echo "--- server output:"
cat "$log"
exit $status
