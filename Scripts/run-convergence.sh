#!/usr/bin/env bash
# SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
# SPDX-License-Identifier: BSD-3-Clause
# Accuracy against sample count on points without smoothing lengths (issue 17): the paper's
# one-component case at 50k, 100k, 200k, 500k and 2M samples, the filter, the grid route and
# (up to 200k, where it finishes in minutes) Delaunay 3D + Contour, each scored against the
# exact surface (mean distance in units of the mean sample spacing on the surface, normal error,
# seconds). JSON per size in Results/convergence/, the table on stdout. About 6 minutes here.
# Run after Scripts/setup-debian12.sh.
set -eu
root=$(cd "$(dirname "$0")/.." && pwd)
out="$root/Results/convergence"
mkdir -p "$out"
for n in 50000 100000 200000 500000 2000000; do
  methods=level-set,grid-route
  [ "$n" -le 200000 ] && methods=$methods,delaunay
  "$root/build/bin/LevelSetCompare" --case one-component --samples $n --methods $methods \
    --json "$out/one-component-$n.json" > "$out/one-component-$n.txt"
done
/usr/bin/python3 - "$out" <<'PY'
import json, sys, glob
rows = {}
for path in sorted(glob.glob(sys.argv[1] + "/one-component-*.json"), key=lambda p: int(p.split("-")[-1][:-5])):
    data = json.load(open(path))
    s = data["surface_spacing"]
    rows[data["samples"]] = (s, {m["name"]: m for m in data["methods"]})
names = ["level-set", "grid-route", "delaunay"]
print("| samples | spacing | " + " | ".join("%s: mean distance (spacings), normal error (deg), seconds" % n for n in names) + " |")
print("|---|---|" + "---|" * len(names))
for n, (s, methods) in rows.items():
    cells = []
    for name in names:
        m = methods.get(name)
        cells.append("%.4f, %.2f, %.2f" % (m["mean_distance"] / s, m["mean_normal_error_degrees"], m["seconds"]) if m else "-")
    print("| %d | %.3f | %s |" % (n, s, " | ".join(cells)))
PY
