# SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
# SPDX-License-Identifier: BSD-3-Clause
"""/usr/bin/python3 Scripts/make_halo_tracer_snapshot.py OUT_DIR [PARTICLES]

Writes a strongly adaptive SPH snapshot in SWIFT's HDF5 layout, made here (numpy, h5py; seed
fixed), for the comparison and MPI scripts: no such file is in ../shared/data.
  - PARTICLES (default 80,000) gas particles of equal mass: three quarters a Plummer halo (scale
    0.1, cut at radius 1) at the origin, a quarter uniform in the cube [-1, 1]^3, then relaxed
    towards a glass, as SPH codes' initial conditions and evolved particles are (30 steps, each
    moving a particle a quarter of its support away from its 32 nearest, weighted (1 - r/H)^3).
    Random positions are no simulation's: their SPH interpolant of a constant is off by up to
    +-20% from particle to particle; after relaxing +-3.5% (1st to 99th percentile, inside);
  - SWIFT's Wendland C2 kernel: support H = gamma h with gamma = 1.936492 ("Kernel gamma"), H
    the distance to the 57th nearest particle (SWIFT's default neighbour number for C2),
    `Densities` the gather sums rho_i = sum_j m_j W(|x_i - x_j|, H_i), `SmoothingLengths` h;
  - `PassiveTracer`, a passive scalar: exp(-|x - c|^2 / (2 s^2)) at each particle, c = (0.2, 0, 0),
    s = 0.25. Its isosurface at exp(-1/2) is near the sphere |x - c| = s, which passes 0.05 from
    the halo's centre on one side and 0.45 on the other: along it the density falls about 600
    times and the smoothing length grows about 8 times (after relaxing: 99 to 0.16, h 0.0062 to
    0.052, medians of the 20 particles nearest each end). One global kernel size cannot fit it.
Two files: halo_tracer.hdf5 (lengths in Mpc, masses 1e10 Msun, as a cosmology run keeps them)
and halo_tracer_kpc.hdf5, the same particles in kpc and Msun (lengths x 1000, masses x 1e10,
densities x 10): the same surface in other units."""
import os
import sys

import h5py
import numpy as np
from scipy.spatial import cKDTree

GAMMA = 1.936492  # SWIFT's kernel_gamma for Wendland C2
NEIGHBOURS = 57
TRACER_CENTRE = np.array([0.2, 0.0, 0.0])
TRACER_WIDTH = 0.25


def wendland_c2(q):
    """W(r, H) H^3 on q = r / H (support H)."""
    q = np.minimum(q, 1.0)
    return 21.0 / (2.0 * np.pi) * (1.0 - q) ** 4 * (1.0 + 4.0 * q)


def particles(n, rng):
    halo = (3 * n) // 4
    # Plummer: enclosed mass fraction u = r^3 / (r^2 + a^2)^(3/2), so r = a / sqrt(u^(-2/3) - 1);
    # cut at radius 1 by drawing u below the fraction inside it.
    a = 0.1
    inside = 1.0 / (1.0 + a * a) ** 1.5
    u = rng.uniform(0.0, inside, halo)
    r = a / np.sqrt(u ** (-2.0 / 3.0) - 1.0)
    direction = rng.normal(size=(halo, 3))
    direction /= np.linalg.norm(direction, axis=1)[:, None]
    background = rng.uniform(-1.0, 1.0, size=(n - halo, 3))
    return np.concatenate([r[:, None] * direction, background])


def relaxed(x, steps=30, neighbours=33, stride=0.25):
    """x moved towards a glass: each step moves every particle `stride` times its support (the
    distance to its 32nd nearest) along the weighted mean direction away from those neighbours;
    kept in the cube."""
    for _ in range(steps):
        d, j = cKDTree(x).query(x, k=neighbours)
        H = d[:, -1:]
        away = (x[:, None, :] - x[j]) / np.maximum(d, 1e-300)[:, :, None]
        w = ((1.0 - d / H) ** 3)[:, :, None]
        x = np.clip(x + stride * H * (w * away).sum(axis=1) / np.maximum(w.sum(axis=1), 1e-300),
                    -1.0, 1.0)
    return x


def main():
    out = sys.argv[1]
    n = int(sys.argv[2]) if len(sys.argv) > 2 else 80000
    os.makedirs(out, exist_ok=True)
    rng = np.random.default_rng(20261202)
    x = relaxed(particles(n, rng))
    m = np.full(n, 1.0 / n)
    tree = cKDTree(x)
    d, j = tree.query(x, k=NEIGHBOURS)
    H = d[:, -1]
    rho = (m[j] * wendland_c2(d / H[:, None])).sum(axis=1) / H**3
    tracer = np.exp(-((x - TRACER_CENTRE) ** 2).sum(axis=1) / (2.0 * TRACER_WIDTH**2))
    for name, length, mass in (("halo_tracer.hdf5", 1.0, 1.0), ("halo_tracer_kpc.hdf5", 1e3, 1e10)):
        with h5py.File(os.path.join(out, name), "w") as f:
            header = f.create_group("Header")
            header.attrs["NumPart_ThisFile"] = np.array([n, 0, 0, 0, 0, 0], dtype=np.uint64)
            header.attrs["NumPart_Total"] = np.array([n, 0, 0, 0, 0, 0], dtype=np.uint64)
            header.attrs["NumPart_Total_HighWord"] = np.zeros(6, dtype=np.uint64)
            header.attrs["MassTable"] = np.zeros(6)
            header.attrs["Time"] = np.array([1.0])
            header.attrs["NumFilesPerSnapshot"] = np.array([1], dtype=np.int32)
            header.attrs["Dimension"] = np.array([3], dtype=np.int32)
            scheme = f.create_group("HydroScheme")
            scheme.attrs["Kernel function"] = np.bytes_("Wendland C2")
            scheme.attrs["Kernel gamma"] = np.array([GAMMA], dtype=np.float32)
            scheme.attrs["Kernel target N_ngb"] = np.array([float(NEIGHBOURS)], dtype=np.float32)
            units = f.create_group("Units")
            units.attrs["Unit length in cgs (U_L)"] = np.array([3.08567758e24 / length])
            units.attrs["Unit mass in cgs (U_M)"] = np.array([1.98841e43 / mass])
            gas = f.create_group("PartType0")
            gas["Coordinates"] = (length * x).astype(np.float64)
            gas["Masses"] = (mass * m).astype(np.float32)
            gas["SmoothingLengths"] = (length * H / GAMMA).astype(np.float32)
            gas["Densities"] = (mass / length**3 * rho).astype(np.float32)
            gas["PassiveTracer"] = tracer.astype(np.float32)
            gas["ParticleIDs"] = np.arange(1, n + 1, dtype=np.uint64)
    print("wrote %d particles to %s: smoothing lengths %.3g to %.3g, densities %.3g to %.3g" % (
        n, out, H.min() / GAMMA, H.max() / GAMMA, rho.min(), rho.max()))


if __name__ == "__main__":
    main()
