# SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
# SPDX-License-Identifier: BSD-3-Clause
"""pvpython TestAdaptiveTracer.py PLUGIN DIR

The snapshots Scripts/make_halo_tracer_snapshot.py wrote into DIR (SWIFT's layout: a Plummer halo
in a uniform background relaxed towards a glass, Wendland C2 with support gamma h, a passive
tracer), read by the HDF5 reader as a user opens them; the isosurface exp(-1/2) of the tracer,
which crosses densities about 600 times apart. Checks, against the SPH interpolant the file
defines (sum_j m_j / rho_j A_j W(|x - x_j|, gamma h_j), evaluated here in numpy):
  - the filter used the SPH field;
  - every isopoint lies on its level: |f - iso| / (|grad f| h) below 1e-6 (h of the nearest
    particle);
  - the isopoints cover the true outer surface: of the points where rays from the tracer's
    centre cross the level once, 97% lie within h / 2 of an isopoint, all within 2 h;
  - in kpc and Msun (lengths x 1000, masses x 1e10) the same surface: point counts within 0.5%,
    each point within 0.1 h of one of the Mpc run's, the enclosed volume within 1e-5 (relative)."""
import os
import sys

import numpy as np
from scipy.spatial import cKDTree

from paraview import servermanager
from paraview.simple import Delete, LoadPlugin, OpenDataFile
from vtkmodules.util.numpy_support import vtk_to_numpy

GAMMA = 1.936492
ISO = float(np.exp(-0.5))
CENTRE = np.array([0.2, 0.0, 0.0])

plugin, directory = sys.argv[1:3]
LoadPlugin(plugin, ns=globals())
failures = []


def check(ok, what):
    print(("ok    " if ok else "FAIL  ") + what, flush=True)
    if not ok:
        failures.append(what)


def wendland_c2(q):
    """W H^3 and dW/dq H^3 on q = r / H (zero from q = 1 on)."""
    q = np.minimum(q, 1.0)
    return (21.0 / (2 * np.pi) * (1 - q) ** 4 * (1 + 4 * q),
            21.0 / (2 * np.pi) * (-20 * q * (1 - q) ** 3))


class Interpolant:
    """sum_j c_j W(|x - x_j|, H_j) and its gradient."""

    def __init__(self, x, c, H):
        self.x, self.c, self.H = x, c, H

    def evaluate(self, points):
        value, grad = np.zeros(len(points)), np.zeros((len(points), 3))
        tree = cKDTree(points)
        for start in range(0, len(self.x), 4096):
            lists = tree.query_ball_point(self.x[start:start + 4096], self.H[start:start + 4096])
            counts = np.array([len(entry) for entry in lists])
            if counts.sum() == 0:
                continue
            j = np.repeat(np.arange(start, start + len(lists)), counts)
            at = np.concatenate([np.asarray(entry, dtype=np.int64) for entry in lists if entry])
            d = points[at] - self.x[j]
            r = np.linalg.norm(d, axis=1)
            w, dw = wendland_c2(r / self.H[j])
            value += np.bincount(at, self.c[j] * w / self.H[j] ** 3, len(points))
            g = (self.c[j] * dw / self.H[j] ** 4 / np.where(r > 0, r, 1.0))[:, None] * d
            for k in range(3):
                grad[:, k] += np.bincount(at, g[:, k], len(points))
        return value, grad


def run(name):
    """The reader's particles, the filter's isopoints (points, in the file's units) and its
    enclosed volume, and whether it used the SPH field."""
    reader = OpenDataFile(os.path.join(directory, name))
    reader.UpdatePipelineInformation()
    reader.ParticleTypes = ["Gas (PartType0)"]
    reader.UpdatePipeline()
    particles = servermanager.Fetch(reader)
    if particles.IsA("vtkMultiBlockDataSet"):
        particles = particles.GetBlock(0)
    pd = particles.GetPointData()
    x = vtk_to_numpy(particles.GetPoints().GetData()).astype(float)
    arrays = {n: vtk_to_numpy(pd.GetArray(n)).astype(float)
              for n in ("Masses", "Densities", "SmoothingLengths", "PassiveTracer")}
    top = int(np.argmax(arrays["PassiveTracer"]))
    surface = LevelSetIsosurface(Input=reader, Scalars=["POINTS", "PassiveTracer"],  # noqa: F821
                                 IsoValue=ISO, SeedCenter=list(x[top]),
                                 SeedRadius=float(GAMMA * arrays["SmoothingLengths"][top]),
                                 OutputType=0)
    surface.UpdatePipeline()
    surface.UpdatePropertyInformation()
    used = surface.GetProperty("UsedSPHField").GetData()
    points = servermanager.Fetch(surface, idx=0)
    p = (vtk_to_numpy(points.GetPoints().GetData()).astype(float)
         if points.GetNumberOfPoints() else np.zeros((0, 3)))
    table = servermanager.Fetch(surface, idx=3)
    volume = table.GetValueByName(table.GetNumberOfRows() - 1, "Volume").ToDouble()
    Delete(surface)
    Delete(reader)
    return x, arrays, p, volume, used


x, a, points, volume, used = run("halo_tracer.hdf5")
h = a["SmoothingLengths"]
check(bool(used), "the filter used the SPH field (UsedSPHField %s)" % used)
check(len(points) > 1000, "%d isopoints" % len(points))
field = Interpolant(x, a["Masses"] / a["Densities"] * a["PassiveTracer"], GAMMA * h)
particles = cKDTree(x)
local_h = h[particles.query(points)[1]] if len(points) else np.ones(0)
value, grad = field.evaluate(points)
off = np.abs(value - ISO) / np.maximum(np.linalg.norm(grad, axis=1) * local_h, 1e-300)
check(len(off) > 0 and off.max() < 1e-6,
      "isopoints on the SPH interpolant's level: largest |f - iso| / (|grad f| h) %.3g"
      % (off.max() if len(off) else np.nan))

# The true outer surface along rays from the tracer's centre: the last crossing in 0.15-0.40,
# on rays that cross once (where the level folds, a ray's crossings need not be this
# component's).
rng = np.random.default_rng(7)
rays = rng.normal(size=(4000, 3))
rays /= np.linalg.norm(rays, axis=1)[:, None]
radii = np.linspace(0.15, 0.40, 101)
along = np.array([field.evaluate(CENTRE + r * rays)[0] for r in radii]) > ISO
once = (np.diff(along.astype(int), axis=0) != 0).sum(axis=0) == 1
once &= along[0] & ~along[-1]
last = np.array([np.flatnonzero(along[:, k]).max() for k in np.flatnonzero(once)])
lo, hi = radii[last], radii[last + 1]
for _ in range(40):
    mid = 0.5 * (lo + hi)
    above = field.evaluate(CENTRE + mid[:, None] * rays[once])[0] > ISO
    lo, hi = np.where(above, mid, lo), np.where(above, hi, mid)
truth = CENTRE + lo[:, None] * rays[once]
gap = (cKDTree(points).query(truth)[0] / h[particles.query(truth)[1]]
       if len(points) else np.full(len(truth), np.inf))
check(len(truth) > 1000 and np.mean(gap < 0.5) >= 0.97 and gap.max() < 2.0,
      "the true surface covered: %d ray crossings, %.4f within h/2 of an isopoint, the farthest "
      "%.3g h" % (len(truth), np.mean(gap < 0.5), gap.max()))

# The same particles in kpc and Msun.
_, _, kpc_points, kpc_volume, kpc_used = run("halo_tracer_kpc.hdf5")
kpc_points = kpc_points / 1e3
check(bool(kpc_used) and abs(len(kpc_points) - len(points)) <= 0.005 * len(points),
      "in kpc: %d isopoints against %d" % (len(kpc_points), len(points)))
moved = (cKDTree(points).query(kpc_points)[0] / h[particles.query(kpc_points)[1]]
         if len(points) and len(kpc_points) else np.array([np.inf]))
check(moved.max() < 0.1, "in kpc: every point within %.3g h of one in Mpc" % moved.max())
relative = abs(kpc_volume / 1e9 - volume) / abs(volume) if volume else np.inf
check(relative < 1e-5, "in kpc: enclosed volume %.9g Mpc^3 against %.9g (%.2g relative)"
      % (kpc_volume / 1e9, volume, relative))

if failures:
    print("%d failed" % len(failures))
    sys.exit(1)
print("all passed")
