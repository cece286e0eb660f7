// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
// Periodic boxes (cosmological and turbulence runs): the particles near each face are copied,
// shifted by the box size, to the other side (ghost images, as an MPI rank's ghost particles
// would be), so that neighbourhoods, the flood and the SPH field wrap across the faces. The
// method's steps then run on originals plus images, the flood is made consistent between a
// particle and its images, and only the surface inside one periodic cell is kept: the box
// itself, or the box centred on the seed (a component that crosses a face in one piece).
#ifndef LevelSetPeriodicImages_h
#define LevelSetPeriodicImages_h

#include "LevelSetNeighborhoods.h"

#include "vtkSmartPointer.h"

#include <string>
#include <vector>

class vtkPointSet;
class vtkPolyData;

namespace lsi
{

struct PeriodicBox
{
  bool Enabled = false;
  double Size[3] = { 0.0, 0.0, 0.0 };
  // The box is [Origin, Origin + Size) on each axis: 0 for GADGET, GIZMO and SWIFT; -Size / 2
  // for Tipsy's boxes centred on 0 (PlaceBox).
  double Origin[3] = { 0.0, 0.0, 0.0 };
};

/// The box: `requested` (the BoxSize property) where positive, else the "BoxSize" field data the
/// HDF5 reader passes from the snapshot's Header (one value or three). Disabled when `periodic`
/// is off or no box is known. `problem` is set for a box that is not positive and finite.
PeriodicBox FindPeriodicBox(
  vtkPointSet* input, const double requested[3], bool periodic, std::string& problem);

/// Places the box on the particles (`bounds` as vtkDataSet::GetBounds gives them): at 0 if they
/// lie within [0, Size) (give or take `slack`, a fraction of the box), else centred on 0 if they
/// lie within [-Size / 2, Size / 2). False when they fit neither: the box does not describe
/// them.
bool PlaceBox(PeriodicBox& box, const double bounds[6], double slack);

/// Calls visit(y) for every image y = x + shift * Size of x (shift -1, 0 or +1 on each axis; the
/// zero shift only if `withZero`) that lies within reach[d] of the box on every axis d.
template <typename Visit>
void ForEachPeriodicImage(
  const double* x, const PeriodicBox& box, const double reach[3], bool withZero, Visit&& visit)
{
  for (int s = 0; s < 27; ++s)
  {
    const int shift[3] = { s % 3 - 1, (s / 3) % 3 - 1, s / 9 - 1 };
    if (!withZero && shift[0] == 0 && shift[1] == 0 && shift[2] == 0)
    {
      continue;
    }
    double y[3];
    bool near = true;
    for (int d = 0; d < 3 && near; ++d)
    {
      y[d] = x[d] + shift[d] * box.Size[d];
      near = y[d] >= box.Origin[d] - reach[d] && y[d] < box.Origin[d] + box.Size[d] + reach[d];
    }
    if (near)
    {
      visit(y);
    }
  }
}

/// The input points and point data, then the images of every point within `margin` (a fraction
/// of the box on each axis) of a face, shifted across it (faces, edges and corners); imageOf[k]
/// is the input id of point N + k. Field data are passed on.
vtkSmartPointer<vtkPolyData> WithPeriodicImages(
  vtkPointSet* input, const PeriodicBox& box, double margin, std::vector<vtkIdType>& imageOf);

/// The samples (storage order) that are one particle: each sample's original input id (-1 for
/// the ghosts of other MPI ranks, which come after the images).
std::vector<vtkIdType> OriginalIds(
  const Neighborhoods& geometry, vtkIdType originalCount, const std::vector<vtkIdType>& imageOf);

/// A particle and its images are one particle: where the flood reached one of them
/// (`reached(i)` for sample i), its other samples with f > f_iso (`dataOffsets`) not reached yet
/// become seeds (`inSeed`), for the flood to run again. `original`: OriginalIds. Returns whether
/// any seed was added.
template <typename Reached>
bool SeedImagesOfReached(const std::vector<vtkIdType>& original, vtkIdType originalCount,
  const std::vector<double>& dataOffsets, Reached&& reached, std::vector<char>& inSeed)
{
  std::vector<char> particleReached(static_cast<std::size_t>(originalCount), 0);
  for (std::size_t i = 0; i < original.size(); ++i)
  {
    if (original[i] >= 0) // not another rank's ghost
    {
      particleReached[original[i]] |= reached(i) ? 1 : 0;
    }
  }
  bool added = false;
  for (std::size_t i = 0; i < original.size(); ++i)
  {
    if (original[i] >= 0 && particleReached[original[i]] && !inSeed[i] && !reached(i) &&
      dataOffsets[i] > 0.0)
    {
      inSeed[i] = 1;
      added = true;
    }
  }
  return added;
}

/// How many original samples have a neighbourhood (or an SPH support, `supports` per sample in
/// storage order, may be empty) that reaches past the images: their neighbourhoods are cut, so
/// the margin is too small for the sampling near the faces. `needed` receives the margin (as a
/// fraction of the box) that would hold them all.
std::size_t SamplesBeyondImages(const Neighborhoods& geometry, const PeriodicBox& box,
  double margin, vtkIdType originalCount, const std::vector<double>& supports, double& needed);

/// Whether x lies in the periodic cell [Origin, Origin + Size) on each axis, or, with a `center`,
/// [center - Size / 2, center + Size / 2).
bool InKeptCell(const double* x, const PeriodicBox& box, const double* center);

/// The centre of the cell kept around the seed (PeriodicOutput "Around the seed"): the first
/// seed sphere's centre (`spheres`: 4 numbers per sphere, SeedSpheres), else the box's.
void KeptCellCenter(const std::vector<double>& spheres, const PeriodicBox& box, double center[3]);

/// Moves each point (3 doubles) by whole boxes into [center - Size / 2, center + Size / 2).
void IntoCellAround(std::vector<double>& points, const PeriodicBox& box, const double* center);

} // namespace lsi

#endif
