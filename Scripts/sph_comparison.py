# SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
# SPDX-License-Identifier: BSD-3-Clause
"""pvpython Scripts/sph_comparison.py PLUGIN SHARED_DATA_DIR [--json FILE] [--cases a,b]

Issue 13's benchmark on real particle data: for each case, the isosurface of the SPH field the
particles define, rho(x) = sum_j m_j W(|x - x_j|, H_j) with the file's kernel and smoothing
lengths, extracted by
  - this filter, default output (splats: every polygon corner is scored) and Isopoints;
  - ParaView's SPH grid route: vtkSPHInterpolator (same kernel family, one global SpatialStep
    from the median support at the isovalue, volumes from mass and density) on an image of
    half that step, Flying Edges, the connected region at the seed;
  - yt (python3-yt, when installed): load_particles with masses and smoothing lengths, SPH
    deposition (use_sph_normalization False) on an arbitrary grid of step h/4, Flying Edges.
The truth is computed here, independently of the filter's code, in numpy: the SPH field on a
grid of step (median support at the isovalue) / 10, contoured by Flying Edges, each vertex then
moved by two Newton steps on the exact field onto its level. Scores, in units of the local
smoothing length h (the file's own h of the particle nearest the point):
  distance  mean distance from the output's points to the true surface (the exact field's
            level, reached by Newton steps from each point; the truth mesh where they fail);
  normal    mean angle between the output's normals and the SPH field's exact gradient at the
            point (unsigned for the grid routes, whose orientation is a convention);
  cover     fraction of the true component's vertices within h/2 of the output (points for
            isopoints, polygons for splats and meshes), and the largest such distance;
  edges     mean distance of the midpoints of the output polygons' edges (splats, or the grid
            routes' triangles) to the level: the rendered surface between its vertices;
  off       fraction of the output's points further than h/2 from the true component's
            vertices: surface of another component (joined to the seeded one) or stray.
Prints a table per case and writes JSON."""
import json
import os
import subprocess
import sys
import tempfile
import time

import numpy as np
from scipy.spatial import cKDTree

from paraview import servermanager
from paraview.simple import Delete, LoadPlugin, OpenDataFile
from vtkmodules.numpy_interface import dataset_adapter as dsa
from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy
from vtkmodules.vtkCommonCore import vtkIdList, vtkPoints
from vtkmodules.vtkCommonDataModel import vtkCellLocator, vtkImageData, vtkPolyData
from vtkmodules.vtkFiltersCore import vtkFlyingEdges3D, vtkPolyDataConnectivityFilter
from vtkmodules.vtkFiltersPoints import (vtkSPHCubicKernel, vtkSPHInterpolator,
                                         vtkSPHQuinticKernel, vtkWendlandQuinticKernel)

PI = np.pi


# --- kernels, with q = r / H on [0, 1) (H the support) ---------------------------------------
def kernel_shape(name, q):
    """w(q) and dw/dq on q = r / H (0 from q = 1 on): W = w / H^3, dW/dr = dw/dq / H^4."""
    q = np.asarray(q, dtype=float)
    w, d = np.zeros_like(q), np.zeros_like(q)
    inside = q < 1.0
    qi = q[inside]
    if name == "CubicSpline":
        w[inside] = (8.0 / PI) * np.where(qi <= 0.5, 1 - 6 * qi**2 + 6 * qi**3, 2 * (1 - qi) ** 3)
        d[inside] = (8.0 / PI) * np.where(qi <= 0.5, -12 * qi + 18 * qi**2, -6 * (1 - qi) ** 2)
    elif name == "QuinticSpline":
        a, b, c = 1 - qi, np.maximum(2 / 3 - qi, 0), np.maximum(1 / 3 - qi, 0)
        w[inside] = 2187.0 / (40 * PI) * (a**5 - 6 * b**5 + 15 * c**5)
        d[inside] = 2187.0 / (40 * PI) * (-5 * a**4 + 30 * b**4 - 75 * c**4)
    elif name == "WendlandC2":
        w[inside] = 21.0 / (2 * PI) * (1 - qi) ** 4 * (1 + 4 * qi)
        d[inside] = 21.0 / (2 * PI) * (-20 * qi * (1 - qi) ** 3)
    elif name == "QuarticSpline":
        a, b, c = 1 - qi, np.maximum(0.6 - qi, 0), np.maximum(0.2 - qi, 0)
        w[inside] = 15625.0 / (512 * PI) * (a**4 - 5 * b**4 + 10 * c**4)
        d[inside] = 15625.0 / (512 * PI) * (-4 * a**3 + 20 * b**3 - 40 * c**3)
    elif name == "WendlandC4":
        w[inside] = 495.0 / (32 * PI) * (1 - qi) ** 6 * (1 + 6 * qi + 35 / 3 * qi**2)
        d[inside] = 495.0 / (32 * PI) * (-56 / 3 * qi * (1 - qi) ** 5 * (1 + 5 * qi))
    elif name == "WendlandC6":
        w[inside] = 1365.0 / (64 * PI) * (1 - qi) ** 8 * (1 + 8 * qi + 25 * qi**2 + 32 * qi**3)
        d[inside] = 1365.0 / (64 * PI) * (-22 * qi * (1 - qi) ** 7 * (1 + 7 * qi + 16 * qi**2))
    else:
        raise ValueError("no kernel named %r (the readers' SPHKernel markers)" % name)
    return w, d


class SPHTruth:
    """The SPH field sum_j c_j W(|x - x_j|, H_j) of the particles, evaluated exactly (scatter
    form): c_j = m_j for the density, (m_j / rho_j) A_j for an array A. With a periodic `box`
    (sizes per axis), the particles within the largest support of a face are copied across it."""

    def __init__(self, x, c, H, kernel, box=None):
        if box is not None:
            reach = H.max()
            xs, cs, Hs = [x], [c], [H]
            for shift in np.array(np.meshgrid([-1, 0, 1], [-1, 0, 1], [-1, 0, 1])).T.reshape(-1, 3):
                if not shift.any():
                    continue
                y = x + shift * box
                keep = np.all((y >= -reach) & (y < box + reach), axis=1)
                xs.append(y[keep])
                cs.append(c[keep])
                Hs.append(H[keep])
            x, c, H = np.concatenate(xs), np.concatenate(cs), np.concatenate(Hs)
        self.x, self.m, self.H, self.kernel = x, c, H, kernel
        self.tree = cKDTree(x)
        self.Hmax = H.max()

    def evaluate(self, points):
        """rho and grad rho at the points: each particle's support is searched in a tree of the
        points (exact pairs, no global search radius), in chunks of particles."""
        points = np.atleast_2d(points)
        value = np.zeros(len(points))
        grad = np.zeros((len(points), 3))
        if len(points) == 0:
            return value, grad
        tree = cKDTree(points)
        chunk = 4096
        for start in range(0, len(self.x), chunk):
            xs, Hs = self.x[start:start + chunk], self.H[start:start + chunk]
            lists = tree.query_ball_point(xs, Hs)
            counts = np.array([len(l) for l in lists])
            if counts.sum() == 0:
                continue
            j = np.repeat(np.arange(start, start + len(xs)), counts)
            owner = np.concatenate([np.asarray(l, dtype=np.int64) for l in lists if len(l)])
            d = points[owner] - self.x[j]
            r = np.linalg.norm(d, axis=1)
            H = self.H[j]
            q = r / H
            shape, slope = kernel_shape(self.kernel, q)
            w = self.m[j] * shape / H**3
            value += np.bincount(owner, weights=w, minlength=len(points))
            dw = self.m[j] * slope / H**4
            safe = np.where(r > 0, r, 1.0)
            g = (dw / safe)[:, None] * d * (r > 0)[:, None]
            for k in range(3):
                grad[:, k] += np.bincount(owner, weights=g[:, k], minlength=len(points))
        return value, grad

    def on_grid(self, origin, step, dims):
        field = np.zeros(dims[::-1])  # z, y, x
        for j in range(len(self.x)):
            lo = np.maximum(np.floor((self.x[j] - self.H[j] - origin) / step).astype(int), 0)
            hi = np.minimum(np.ceil((self.x[j] + self.H[j] - origin) / step).astype(int) + 1, dims)
            if np.any(hi <= lo):
                continue
            gx = origin[0] + step * np.arange(lo[0], hi[0])
            gy = origin[1] + step * np.arange(lo[1], hi[1])
            gz = origin[2] + step * np.arange(lo[2], hi[2])
            r2 = ((gz[:, None, None] - self.x[j, 2]) ** 2 + (gy[None, :, None] - self.x[j, 1]) ** 2
                  + (gx[None, None, :] - self.x[j, 0]) ** 2)
            field[lo[2]:hi[2], lo[1]:hi[1], lo[0]:hi[0]] += (
                self.m[j] * kernel_shape(self.kernel, np.sqrt(r2) / self.H[j])[0]
                / self.H[j] ** 3)
        return field


def image_of(field, origin, step, name="rho"):
    image = vtkImageData()
    nz, ny, nx = field.shape
    image.SetDimensions(nx, ny, nz)
    image.SetOrigin(*origin)
    image.SetSpacing(step, step, step)
    array = numpy_to_vtk(field.ravel().copy(), deep=1)
    array.SetName(name)
    image.GetPointData().SetScalars(array)
    return image


def contour(image, iso, seed, array="rho"):
    edges = vtkFlyingEdges3D()
    edges.SetInputData(image)
    edges.SetInputArrayToProcess(0, 0, 0, 0, array)
    edges.SetValue(0, iso)
    edges.ComputeNormalsOn()
    edges.Update()
    whole = vtkPolyData()
    whole.DeepCopy(edges.GetOutput())
    connect = vtkPolyDataConnectivityFilter()
    connect.SetInputData(whole)
    connect.SetExtractionModeToClosestPointRegion()
    connect.SetClosestPoint(*seed)
    connect.Update()
    region = vtkPolyData()
    region.DeepCopy(connect.GetOutput())
    return whole, region


def points_of(poly):
    if poly.GetNumberOfPoints() == 0:
        return np.zeros((0, 3))
    return vtk_to_numpy(poly.GetPoints().GetData()).astype(float)


def used_points(poly):
    """The points of a polydata that its cells use (a connectivity output keeps all)."""
    ids = vtkIdList()
    used = set()
    for c in range(poly.GetNumberOfCells()):
        poly.GetCellPoints(c, ids)
        used.update(ids.GetId(i) for i in range(ids.GetNumberOfIds()))
    idx = np.array(sorted(used), dtype=np.int64)
    return idx


class Scorer:
    def __init__(self, truth, iso, h_file, x, seed, bounds_pad, box=None, near=None,
                 outside=None):
        self.truth, self.iso, self.x, self.box = truth, iso, x, box
        self.h_tree = cKDTree(x)
        self.h_file = h_file
        # The truth: SPH field on a fine grid around the particles above a third of the
        # isovalue (or those `near` marks), contoured, vertices moved onto the exact level.
        rho_at_particles, _ = truth.evaluate(x)
        if near is None:
            near = rho_at_particles > iso / 3.0
        if not near.any():
            near[:] = True
        at_iso = np.abs(rho_at_particles - iso) < 0.5 * abs(iso)
        H_own = truth.H[:len(x)]
        self.H_iso = np.median(H_own[at_iso]) if at_iso.any() else np.median(H_own)
        self.H_iso_95 = np.quantile(H_own[at_iso], 0.95) if at_iso.any() else self.H_iso
        lo = x[near].min(axis=0) - truth.H[:len(x)][near].max() - bounds_pad
        hi = x[near].max(axis=0) + truth.H[:len(x)][near].max() + bounds_pad
        if box is not None:  # one periodic cell: the box
            lo, hi = np.zeros(3), np.asarray(box, dtype=float)
        step = self.H_iso / 10.0
        dims = np.minimum(np.ceil((hi - lo) / step).astype(int) + 1, 320)
        step = max(((hi - lo) / (dims - 1)).max(), step)
        dims = np.ceil((hi - lo) / step).astype(int) + 1
        self.grid_step = step
        self.lo, self.hi = lo, lo + step * (dims - 1)
        t = time.time()
        field = truth.on_grid(lo, step, dims)
        self.truth_seconds = time.time() - t
        # The seeded component: the surface nearest the seed, or nearest `outside` (a point
        # just outside it) where the field has pockets below the isovalue next to the seed.
        whole, region = contour(image_of(field, lo, step), iso,
                                seed if outside is None else outside)
        for poly in (whole, region):
            p = points_of(poly)
            for _ in range(2):
                v, g = truth.evaluate(p)
                g2 = np.maximum((g**2).sum(axis=1), 1e-300)
                p = p - ((v - iso) / g2)[:, None] * g
            poly.GetPoints().SetData(numpy_to_vtk(p.copy(), deep=1))
        self.whole, self.region = whole, region
        self.whole_locator = vtkCellLocator()
        self.whole_locator.SetDataSet(whole)
        self.whole_locator.BuildLocator()
        self.region_points = points_of(region)[used_points(region)]
        self.region_tree = cKDTree(self.wrap(self.region_points),
                                   boxsize=None if box is None else box)

    def wrap(self, points):
        """Into the periodic cell [0, box) (unchanged without a box)."""
        if self.box is None:
            return points
        wrapped = np.mod(points, self.box)
        return np.where(wrapped >= self.box, wrapped - self.box, wrapped)

    def local_h(self, p):
        _, nearest = self.h_tree.query(p)
        return self.h_file[nearest]

    def distance_to(self, locator, p):
        closest = [0.0, 0.0, 0.0]
        cell, sub, d2 = 0, 0, 0.0
        out = np.empty(len(p))
        import vtk
        cid = vtk.reference(0)
        sid = vtk.reference(0)
        dist2 = vtk.reference(0.0)
        for i, q in enumerate(p):
            locator.FindClosestPoint(q, closest, cid, sid, dist2)
            out[i] = np.sqrt(float(dist2))
        return out

    def level_distance(self, points):
        """Distance to the exact level in local h: Newton steps on the exact field (the foot of
        the gradient path, exact to second order); where they do not settle, the distance to
        the truth mesh (whose chords sit up to about step^2 / (8 R) off the level)."""
        if self.box is not None:  # the truth covers one periodic cell: wrap into it
            points = np.mod(points, self.box)
        h_local = self.local_h(points)
        foot = points.copy()
        for _ in range(4):
            v, g = self.truth.evaluate(foot)
            g2 = np.maximum((g**2).sum(axis=1), 1e-300)
            foot = foot - ((v - self.iso) / g2)[:, None] * g
        v, g = self.truth.evaluate(foot)
        settled = np.abs(v - self.iso) / np.sqrt(np.maximum((g**2).sum(axis=1), 1e-300)) \
            < 1e-4 * h_local
        d = np.linalg.norm(points - foot, axis=1)
        if not settled.all():
            d[~settled] = self.distance_to(self.whole_locator, points[~settled])
        return d / h_local

    def score(self, points, normals, signed, cover_poly=None):
        if len(points) == 0:
            return dict(points=0)
        if self.box is not None:
            points = np.mod(points, self.box)
        d = self.level_distance(points)
        # Between the points: the midpoints of the polygons' edges (splats) or triangles' edges
        # (meshes), where the rendered surface is furthest from its vertices.
        midpoints = edge_midpoints(cover_poly) if cover_poly is not None else None
        between = self.level_distance(midpoints) if midpoints is not None and len(midpoints) \
            else None
        _, g = self.truth.evaluate(points)
        exact = -g / np.maximum(np.linalg.norm(g, axis=1), 1e-300)[:, None]
        n = normals / np.maximum(np.linalg.norm(normals, axis=1), 1e-300)[:, None]
        cosine = (n * exact).sum(axis=1)
        if not signed:
            cosine = np.abs(cosine)
        angle = np.degrees(np.arccos(np.clip(cosine, -1, 1)))
        # Coverage of the true component.
        if cover_poly is not None and cover_poly.GetNumberOfCells() > 0:
            locator = vtkCellLocator()
            locator.SetDataSet(cover_poly)
            locator.BuildLocator()
            gap = self.distance_to(locator, self.region_points)
        else:
            gap, _ = cKDTree(points).query(self.region_points)
        gap = gap / self.local_h(self.region_points)
        # Points off the true component (the truth's vertices lie a tenth of a support apart).
        off, _ = self.region_tree.query(self.wrap(points))
        off = off / self.local_h(points)
        result = dict(points=int(len(points)), mean_distance_h=float(d.mean()),
                      max_distance_h=float(d.max()), mean_normal_deg=float(angle.mean()),
                      covered_fraction=float((gap <= 0.5).mean()), max_gap_h=float(gap.max()),
                      off_fraction=float((off > 0.5).mean()))
        if between is not None:
            result["mean_edge_midpoint_distance_h"] = float(between.mean())
            result["max_edge_midpoint_distance_h"] = float(between.max())
        return result


def seeded_particles(x, values, iso, seed, k=64):
    """The particles above the isovalue connected to the one nearest the seed through their k
    nearest neighbours: where the seeded component lies, when the particles above a third of
    the isovalue fill the whole volume (a nearly uniform box)."""
    from scipy.sparse import coo_matrix
    from scipy.sparse.csgraph import connected_components
    above = np.flatnonzero(values > iso)
    tree = cKDTree(x[above])
    _, start = tree.query(seed)
    _, lists = tree.query(x[above], k=min(k + 1, len(above)))
    rows = np.repeat(np.arange(len(above)), lists.shape[1])
    graph = coo_matrix((np.ones(rows.size), (rows, lists.ravel())), shape=(len(above),) * 2)
    _, label = connected_components(graph, directed=False)
    near = np.zeros(len(x), dtype=bool)
    near[above[label == label[start]]] = True
    return near


def edge_midpoints(poly, limit=200000):
    """The midpoints of the cells' edges (each cell's consecutive corners), at most `limit`."""
    ids = vtkIdList()
    x = points_of(poly)
    pairs = []
    step = max(1, poly.GetNumberOfCells() * 4 // limit)
    for c in range(0, poly.GetNumberOfCells(), step):
        poly.GetCellPoints(c, ids)
        k = ids.GetNumberOfIds()
        corner = [ids.GetId(i) for i in range(k)]
        pairs.extend((corner[i], corner[(i + 1) % k]) for i in range(k))
    if not pairs:
        return None
    pairs = np.array(pairs)
    return 0.5 * (x[pairs[:, 0]] + x[pairs[:, 1]])


def fetch(proxy, port=0):
    proxy.UpdatePipeline()
    return servermanager.Fetch(proxy, proxy, port) if port else servermanager.Fetch(proxy)


def main():
    args = sys.argv[1:]
    plugin, shared = args[0], args[1]
    json_path = args[args.index("--json") + 1] if "--json" in args else None
    chosen = args[args.index("--cases") + 1].split(",") if "--cases" in args else None
    LoadPlugin(plugin, ns=globals())
    data = os.path.join(shared)

    def hdf5(path, types):
        r = OpenDataFile(path)
        r.UpdatePipelineInformation()
        r.ParticleTypes = types
        return r

    def tipsy_with_density(path, types):
        r = OpenDataFile(path)
        r.UpdatePipelineInformation()
        r.ParticleTypes = types
        return ParticleDensity(Input=r, NumberOfNeighbors=64)

    def changa_output(path, softening, n_smooth=32):
        # The glass as ChaNGa writes an output of it: rho its SPH density over the nSmooth
        # nearest (Particle Density, H = fBall), the hsmooth column the gravitational softening
        # (ChaNGa's, Gasoline's and PKDGRAV's writers put it there), and h = fBall / 2 in the
        # auxiliary file SNAPSHOT.smoothlength (ChaNGa's bDohOutput), big-endian as XDR.
        r = OpenDataFile(path)
        r.UpdatePipelineInformation()
        r.ParticleTypes = ["Gas"]
        d = ParticleDensity(Input=r, NumberOfNeighbors=n_smooth)
        glass = fetch(d)
        pd = glass.GetPointData()
        x = points_of(glass)
        n = len(x)
        rows = np.zeros((n, 12), dtype=">f4")
        rows[:, 0] = vtk_to_numpy(pd.GetArray("mass"))
        rows[:, 1:4] = x
        rows[:, 7] = vtk_to_numpy(pd.GetArray("Density"))
        rows[:, 8] = 100.0
        rows[:, 9] = softening
        out_dir = tempfile.mkdtemp(prefix="changa_output_")
        snapshot = os.path.join(out_dir, "evrard.000100")
        with open(snapshot, "wb") as f:
            f.write(np.array([(1.0, n, 3, n, 0, 0, 0)],
                             dtype=">f8,>i4,>i4,>i4,>i4,>i4,>i4").tobytes())
            f.write(rows.tobytes())
        with open(snapshot + ".smoothlength", "wb") as f:
            f.write(np.array([n], dtype=">i4").tobytes())
            f.write((0.5 * vtk_to_numpy(pd.GetArray("SmoothingLength"))).astype(">f4").tobytes())
        Delete(d)
        Delete(r)
        out = OpenDataFile(snapshot)
        out.UpdatePipelineInformation()
        return out

    made = {}

    def halo_tracer(name):
        # A strongly adaptive snapshot in SWIFT's layout, made by the repository's own script
        # (a Plummer halo in a uniform background, relaxed towards a glass, Wendland C2, a
        # passive tracer whose isosurface crosses densities 600 times apart), in Mpc and in kpc.
        if "dir" not in made:
            made["dir"] = tempfile.mkdtemp(prefix="halo_tracer_")
            script = os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                  "make_halo_tracer_snapshot.py")
            subprocess.run(["/usr/bin/python3", script, made["dir"]], check=True,
                           stdout=subprocess.DEVNULL)
        return hdf5(os.path.join(made["dir"], name), ["Gas (PartType0)"])

    # name: (source maker, isovalue rule, description)
    cases = {
        "gadget4-gassphere": (
            lambda: hdf5(os.path.join(data, "gadget4_gassphere", "snapshot_010.hdf5"),
                         ["Gas (PartType0)"]),
            "GADGET-4 collapsing gas sphere, t = 2.0, 1,000 particles, cubic spline, h = H"),
        "gadget4-gassphere-t1": (
            lambda: hdf5(os.path.join(data, "gadget4_gassphere", "snapshot_005.hdf5"),
                         ["Gas (PartType0)"]),
            "GADGET-4 collapsing gas sphere, t = 1.0, 1,000 particles, cubic spline, h = H"),
        "changa-shocktube": (
            lambda: tipsy_with_density(os.path.join(data, "shocktube.std"), ["Gas"]),
            "ChaNGa shock tube, 20,000 particles, density by SPH summation (its rho and hsmooth "
            "columns are placeholders)"),
        "swift-robertsflow-vz": (
            lambda: Calculator(Input=hdf5(os.path.join(data, "swift_robertsflow_g32.hdf5"),
                                          ["Gas (PartType0)"]),
                               ResultArrayName="VelocityZ", Function="Velocities_Z"),
            "SWIFT Roberts flow, 32,768 particles in a periodic box of 2 pi, quintic spline, "
            "H = 2.195775 h: the isosurface vz = 0.7 of the SPH interpolant of the velocity, "
            "tubes through the periodic faces"),
        "evrard-summed": (
            lambda: tipsy_with_density(os.path.join(data, "adiabtophat_glass_28721.bin"),
                                       ["Gas"]),
            "Evrard glass, 28,721 particles, density by SPH summation (Particle Density, 64)"),
        "changa-evrard-output": (
            lambda: changa_output(os.path.join(data, "adiabtophat_glass_28721.bin"), 0.03),
            "the Evrard glass as ChaNGa writes an output: rho its SPH density over nSmooth = 32, "
            "h = fBall / 2 in SNAPSHOT.smoothlength, the hsmooth column the softening 0.03"),
        "changa-galaxy": (
            lambda: tipsy_with_density(os.path.join(data, "changa_run581.20000"), ["Stars"]),
            "ChaNGa galaxy stars, 5,321 particles, density by SPH summation: clustered"),
        "changa-cube300": (
            lambda: tipsy_with_density(os.path.join(data, "changa_cube300.tbin"), ["DarkMatter"]),
            "ChaNGa cosmological box, 110,592 dark-matter particles at t = 0.05, density by SPH "
            "summation: nearly uniform; the densest tenth, clumps near one another"),
        "swift-halo-tracer": (
            lambda: halo_tracer("halo_tracer.hdf5"),
            "made here (Scripts/make_halo_tracer_snapshot.py): 80,000 particles, a Plummer halo "
            "in a uniform background relaxed towards a glass, SWIFT's Wendland C2 (H = "
            "1.936492 h), the isosurface exp(-1/2) of a passive tracer's SPH interpolant: along "
            "it the density spans 600x, h 8x; also the same file in kpc and Msun"),
    }

    def hdf5_or_tipsy(path):
        r = OpenDataFile(path)
        r.UpdatePipelineInformation()
        return r

    results = {}
    for name, (make, description) in cases.items():
        if chosen and name not in chosen:
            continue
        print("=== %s: %s" % (name, description), flush=True)
        source = make()
        particles = fetch(source)
        if particles.IsA("vtkMultiBlockDataSet"):
            particles = particles.GetBlock(0)
        pd = particles.GetPointData()
        fd = particles.GetFieldData()

        def marker(key, default=None):
            a = fd.GetAbstractArray(key)
            if a is None:
                return default
            return a.GetValue(0) if a.IsA("vtkStringArray") else a.GetTuple1(0)

        x = points_of(particles)
        h_name = marker("SmoothingLengthArray")
        h = vtk_to_numpy(pd.GetArray(h_name)).astype(float)
        m = vtk_to_numpy(pd.GetArray(marker("MassArray"))).astype(float)
        rho_name = marker("DensityArray")
        rho = vtk_to_numpy(pd.GetArray(rho_name)).astype(float)
        kernel = marker("SPHKernel", "CubicSpline")
        factor = float(marker("SupportPerSmoothingLength", 1.0))
        box_array = fd.GetArray("BoxSize")
        box = None
        if box_array is not None and box_array.GetNumberOfValues() > 0:
            values = [box_array.GetValue(k) for k in range(box_array.GetNumberOfValues())]
            box = np.array(values * 3 if len(values) == 1 else values[:3], dtype=float)
            box = box if (box > 0).all() else None
        scalar = rho_name
        if name == "swift-robertsflow-vz":
            scalar = "VelocityZ"
        if name == "swift-halo-tracer":
            scalar = "PassiveTracer"
        if scalar != rho_name:
            a = vtk_to_numpy(pd.GetArray(scalar)).astype(float)
            truth = SPHTruth(x, m / rho * a, factor * h, kernel, box)
        else:
            truth = SPHTruth(x, m, factor * h, kernel, box)
        summed, _ = truth.evaluate(x)
        # The isovalue: the density at the particle ranked at the 30th percentile from the top
        # of the summed field (a surface inside the sampled region), the seed: densest particle.
        # The shock tube's dense state is a plateau (60% of its particles at 1.00 +- 0.03): its
        # isovalue is half the median, between the two states, not the plateau's noise.
        iso = float(np.quantile(summed, 0.7))
        if name == "changa-shocktube":
            iso = 0.5 * float(np.median(summed))
        if name == "swift-robertsflow-vz":
            iso = 0.7  # vz spans +-1.43: tubes around the flow's cells
        seed = x[np.argmax(summed)]
        near, outside = None, None
        if name == "swift-halo-tracer":
            # The tracer's blob: near the sphere |x - (0.2, 0, 0)| = 0.25. The truth's grid
            # covers its particles, not the whole cube.
            # The interpolant may have pockets below the isovalue inside the blob (its
            # normalisation sum_j m_j / rho_j W varies by +-3.5% here): the truth is the outer
            # surface, found from a point 0.05 outside it.
            iso = float(np.exp(-0.5))
            near = seeded_particles(x, summed, iso, seed)
            outside = np.array([0.5, 0.0, 0.0])
        if name == "changa-cube300":
            # The densest tenth (an overdensity): separate clumps, some a fraction of a support
            # apart. The truth's grid covers the seeded clump's particles.
            iso = float(np.quantile(summed, 0.9))
            near = seeded_particles(x, summed, iso, seed)
        if name in ("evrard-summed", "changa-evrard-output"):
            iso = 1.0 / (2 * PI * 0.5)  # analytic surface r = 0.5
            seed = np.zeros(3)
        if name == "changa-evrard-output":
            # Over 32 neighbours the field dips below the isovalue in a small pocket at the
            # centre, whose surface is the nearest to the origin: seed near the sphere instead.
            seed = np.array([0.4, 0.0, 0.0])
        print("  isovalue %.6g, seed (%.4g, %.4g, %.4g), kernel %s, H = %g h" % (
            iso, seed[0], seed[1], seed[2], kernel, factor), flush=True)
        t = time.time()
        scorer = Scorer(truth, iso, h, x, seed, 0.0, box, near, outside)
        print("  truth: grid step %.3g (median support at the isovalue %.3g), %d vertices in "
              "the seeded component, %.1f s" % (scorer.grid_step, scorer.H_iso,
                                                len(scorer.region_points), time.time() - t),
              flush=True)
        rows = {}
        seed_radius = float(factor * h[np.argmax(summed)])
        runs = [(1, "filter, default (splats)", {}), (0, "filter, Isopoints", {})]
        if name == "changa-evrard-output":
            # The marking the Tipsy reader made before: hsmooth (the softening) as h, support 2 h.
            runs.append((1, "filter, hsmooth as h (splats)",
                         dict(SmoothingLengthArray="hsmooth", SupportPerSmoothingLength=2.0)))
        other_units = None
        if name == "swift-halo-tracer":
            # The same particles in kpc and Msun: the output, scaled back, must be the same.
            other_units = (halo_tracer("halo_tracer_kpc.hdf5"), 1e3)
            runs.append((1, "filter, in kpc (splats)", {}, other_units))
        outputs = {}
        for output_type, label, extra, *units in runs:
            run_source, length = units[0] if units else (source, 1.0)
            t = time.time()
            f = LevelSetIsosurface(Input=run_source, Scalars=["POINTS", scalar], IsoValue=iso,
                                   SeedCenter=list(length * seed), SeedRadius=length * seed_radius,
                                   OutputType=output_type, **extra)
            out = fetch(f)
            seconds = time.time() - t
            f.UpdatePropertyInformation()
            used_sph = f.GetProperty("UsedSPHField").GetData()
            if out.GetNumberOfPoints() > 0 and length != 1.0:
                scaled = vtk_to_numpy(out.GetPoints().GetData())
                scaled /= length
                out.GetPoints().Modified()
            o = dsa.WrapDataObject(out)
            if out.GetNumberOfPoints() == 0:
                rows[label] = dict(points=0)
            else:
                p = np.asarray(o.Points, dtype=float)
                n = np.asarray(o.PointData["Normals"], dtype=float)
                outputs[label] = p
                rows[label] = scorer.score(p, n, True, out if output_type == 1 else None)
            rows[label]["seconds"] = seconds
            rows[label]["sph_field"] = bool(used_sph)
            Delete(f)
        if other_units is not None:
            a, b = outputs.get("filter, default (splats)"), outputs.get("filter, in kpc (splats)")
            if a is not None and b is not None:
                gap = cKDTree(a).query(b)[0] / scorer.local_h(b)
                print("  in kpc against in Mpc: %d and %d points, the farthest %.2e h from the "
                      "nearest" % (len(a), len(b), gap.max()))
                rows["filter, in kpc (splats)"]["largest_gap_to_mpc_output_h"] = float(gap.max())
            Delete(other_units[0])
        # ParaView's grid route.
        t = time.time()
        rows["ParaView SPH grid route"] = grid_route(particles, kernel, scorer, iso, seed,
                                                     rho_name, marker("MassArray"), scalar)
        rows["ParaView SPH grid route"]["seconds"] = time.time() - t
        if name == "swift-halo-tracer":
            # One global kernel size: the median support at the isovalue leaves the sparse side
            # with kernels shorter than the spacing (holes); the 95th percentile's fills it and
            # smooths the dense side over 8 of its own supports.
            t = time.time()
            label = "grid route, 95% support"
            rows[label] = grid_route(particles, kernel, scorer, iso, seed, rho_name,
                                     marker("MassArray"), scalar, scorer.H_iso_95)
            rows[label]["seconds"] = time.time() - t
        # yt.
        t = time.time()
        try:
            a = vtk_to_numpy(pd.GetArray(scalar)).astype(float)
            rows["yt"] = yt_route(x, m, factor * h, rho, a, kernel, scorer, iso, seed, box)
        except Exception as error:  # yt's API moves between versions: report, go on
            print("  yt failed: %r" % (error,))
            rows["yt"] = dict(points=None, note="yt failed: %r" % (error,))
        if rows["yt"].get("points") is not None:
            rows["yt"]["seconds"] = time.time() - t
        print_table(rows)
        results[name] = dict(description=description, isovalue=iso, kernel=kernel, scalar=scalar,
                             periodic_box=None if box is None else box.tolist(),
                             support_per_h=factor, truth_grid_step=scorer.grid_step,
                             median_support_at_iso=scorer.H_iso, rows=rows)
        Delete(source)
    if json_path:
        with open(json_path, "w") as out:
            json.dump(results, out, indent=1)


def grid_route(particles, kernel, scorer, iso, seed, rho_name, mass_name, scalar, support=None):
    # VTK's kernels: support = CutoffFactor x SpatialStep (cubic 2, quintic 3), one global step.
    if kernel == "QuinticSpline":
        k, cutoff = vtkSPHQuinticKernel(), 3.0
    elif kernel == "WendlandC2":  # VTK's "Wendland quintic" is the 3-D Wendland C2
        k, cutoff = vtkWendlandQuinticKernel(), 2.0
    else:
        k, cutoff = vtkSPHCubicKernel(), 2.0
    step = (scorer.H_iso if support is None else support) / cutoff
    k.SetSpatialStep(step)
    lo, hi = scorer.lo, scorer.hi  # the region the truth covers
    grid_step = step / 2.0
    dims = np.ceil((hi - lo) / grid_step).astype(int) + 1
    dims = np.minimum(dims, 400)
    image = vtkImageData()
    image.SetDimensions(*[int(d) for d in dims])
    image.SetOrigin(*lo)
    image.SetSpacing(*((hi - lo) / (dims - 1)))
    interp = vtkSPHInterpolator()
    interp.SetInputData(image)
    interp.SetSourceData(particles)
    interp.SetKernel(k)
    interp.SetDensityArrayName(rho_name)
    interp.SetMassArrayName(mass_name)
    interp.Update()
    grid = interp.GetOutput()
    whole, region = contour(grid, iso, seed, scalar)
    if region.GetNumberOfCells() == 0:
        return dict(points=0)
    p = points_of(region)[used_points(region)]
    n = vtk_to_numpy(region.GetPointData().GetNormals())[used_points(region)]
    return scorer.score(p, n.astype(float), False, region)


def yt_route(x, m, H, rho, a, kernel, scorer, iso, seed, box):
    try:
        import yt
    except ImportError:
        print("  yt: not installed (apt-get install python3-yt)")
        return dict(points=None, note="yt not installed")
    yt.set_log_level(50)
    # Particle type "io" with a density: yt interpolates ("io", "scalar") as
    # sum_j (m_j / rho_j) A_j W, unnormalised (for A = rho: sum_j m_j W).
    data = {("io", "particle_position_x"): x[:, 0], ("io", "particle_position_y"): x[:, 1],
            ("io", "particle_position_z"): x[:, 2], ("io", "particle_mass"): m,
            ("io", "smoothing_length"): H, ("io", "density"): rho, ("io", "scalar"): a}
    if box is not None:  # periodic: yt wraps its domain
        bbox = np.array([np.zeros(3), box]).T
    else:
        bbox = np.array([x.min(axis=0) - H.max(), x.max(axis=0) + H.max()]).T
    lo, hi = scorer.lo, scorer.hi
    ds = yt.load_particles(data, length_unit=1.0, mass_unit=1.0, bbox=bbox,
                           periodicity=(box is not None,) * 3)
    ds.use_sph_normalization = False
    names = {"CubicSpline": "cubic", "QuinticSpline": "quintic", "WendlandC2": "wendland2"}
    ds.kernel_name = names.get(kernel, "cubic")
    step = scorer.H_iso / 4.0
    dims = np.minimum(np.ceil((hi - lo) / step).astype(int) + 1, 320)
    grid = ds.arbitrary_grid(lo, hi, dims)
    field = np.asarray(grid[("io", "scalar")]).astype(float)  # x, y, z
    spacing = (hi - lo) / dims
    # arbitrary_grid values are cell centred.
    image = image_of(np.ascontiguousarray(field.transpose(2, 1, 0)), lo + 0.5 * spacing,
                     1.0)
    image.SetSpacing(*spacing)
    whole, region = contour(image, iso, seed)
    if region.GetNumberOfCells() == 0:
        return dict(points=0)
    p = points_of(region)[used_points(region)]
    n = vtk_to_numpy(region.GetPointData().GetNormals())[used_points(region)]
    return scorer.score(p, n.astype(float), False, region)


def print_table(rows):
    print("  %-28s %9s %10s %10s %9s %8s %9s %10s %7s %7s" % (
        "output", "points", "mean d/h", "max d/h", "normal", "cover", "max gap", "edges d/h",
        "off", "s"))
    for label, r in rows.items():
        if not r.get("points"):
            print("  %-28s %9s %s" % (label, r.get("points"), r.get("note", "no surface")))
            continue
        edges = r.get("mean_edge_midpoint_distance_h")
        print("  %-28s %9d %10.2e %10.2e %8.2f° %7.1f%% %8.3f %10s %6.1f%% %7.2f" % (
            label, r["points"], r["mean_distance_h"], r["max_distance_h"], r["mean_normal_deg"],
            100 * r["covered_fraction"], r["max_gap_h"],
            "-" if edges is None else "%.2e" % edges, 100 * r["off_fraction"],
            r.get("seconds", 0.0)), flush=True)


if __name__ == "__main__":
    main()
