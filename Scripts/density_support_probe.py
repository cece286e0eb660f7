# SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
# SPDX-License-Identifier: BSD-3-Clause
"""/usr/bin/python3 Scripts/density_support_probe.py [SNAPSHOT.hdf5 [GAMMA]]

What the filter's density check can see of a wrong kernel support: the gas particles' kernel
sums rho_i = sum_j m_j W(r_ij, s H_i) (gather form, the quintic spline; SWIFT's H = gamma h, the
default file and gamma the shared SWIFT Roberts flow's) at 2,000 particles drawn with a fixed
seed, against their stored densities, for support factors s around 1. Prints the median of
ln(sum / stored) and the 90th percentile of its magnitude per factor. The sums are a density
estimate for any support that holds enough neighbours, so a support a quarter too short moves
them by well under 1%: no tolerance on the ratio tells that from a right support."""
import sys

import h5py
import numpy as np
from scipy.spatial import cKDTree

from sph_comparison import kernel_shape  # (beside this script: the comparison's kernels)


def main():
    path = sys.argv[1] if len(sys.argv) > 1 else "../shared/data/swift_robertsflow_g32.hdf5"
    gamma = float(sys.argv[2]) if len(sys.argv) > 2 else 2.195775
    with h5py.File(path, "r") as f:
        gas = f["PartType0"]
        x = gas["Coordinates"][:].astype(float)
        h = gas["SmoothingLengths"][:].astype(float)
        m = gas["Masses"][:].astype(float)
        rho = gas["Densities"][:].astype(float)
        box = np.atleast_1d(f["Header"].attrs["BoxSize"]).astype(float)
    box = np.repeat(box, 3) if box.size == 1 else box
    tree = cKDTree(np.mod(x, box), boxsize=box)
    chosen = np.random.default_rng(1).choice(len(x), min(2000, len(x)), replace=False)
    print("support factor  median ln(sum/stored)  90th percentile |ln|")
    for s in (1.0, 0.95, 0.9, 0.83, 0.73, 1.1, 1.2):
        logs = []
        for i in chosen:
            support = s * gamma * h[i]
            near = tree.query_ball_point(np.mod(x[i], box), support)
            d = x[near] - x[i]
            d -= box * np.round(d / box)
            r = np.sqrt((d ** 2).sum(axis=1))
            w = kernel_shape("QuinticSpline", r / support)[0]
            logs.append(np.log((m[near] * w).sum() / support ** 3 / rho[i]))
        logs = np.array(logs)
        print("%14.2f  %21.4f  %22.4f" % (s, np.median(logs), np.percentile(np.abs(logs), 90)))


if __name__ == "__main__":
    main()
