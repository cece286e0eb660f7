// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "LevelSetPeriodicImages.h"

#include "LevelSetHaloReach.h"
#include "LevelSetParallel.h"

#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkIdList.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPointSet.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSMPTools.h"
#include "vtkVariant.h"

#include <algorithm>
#include <cmath>

namespace lsi
{

PeriodicBox FindPeriodicBox(
  vtkPointSet* input, const double requested[3], bool periodic, std::string& problem)
{
  PeriodicBox box;
  problem.clear();
  if (!periodic)
  {
    return box;
  }
  if (requested[0] > 0.0 || requested[1] > 0.0 || requested[2] > 0.0)
  {
    std::copy(requested, requested + 3, box.Size);
  }
  else
  {
    vtkDataArray* size =
      vtkDataArray::SafeDownCast(input->GetFieldData()->GetAbstractArray("BoxSize"));
    if (!size || size->GetNumberOfValues() < 1)
    {
      return box; // no box known: not periodic
    }
    // One value (GADGET) or three (SWIFT), stored as values of one array. GADGET writes 0
    // for a run without a box (an isolated gas sphere): not periodic.
    for (int d = 0; d < 3; ++d)
    {
      box.Size[d] = size->GetVariantValue(size->GetNumberOfValues() >= 3 ? d : 0).ToDouble();
    }
    if (!(box.Size[0] > 0.0) && !(box.Size[1] > 0.0) && !(box.Size[2] > 0.0))
    {
      return PeriodicBox();
    }
  }
  for (double L : box.Size)
  {
    if (!(L > 0.0) || !std::isfinite(L))
    {
      problem = "The periodic box size (BoxSize) must be positive and finite on every axis, not " +
        std::to_string(box.Size[0]) + " " + std::to_string(box.Size[1]) + " " +
        std::to_string(box.Size[2]) + ". Set BoxSize, or turn Periodic off.";
      return PeriodicBox();
    }
  }
  box.Enabled = true;
  return box;
}

bool PlaceBox(PeriodicBox& box, const double bounds[6], double slack)
{
  for (double origin : { 0.0, -0.5 })
  {
    bool fits = true;
    for (int d = 0; d < 3 && fits; ++d)
    {
      const double low = origin * box.Size[d], tolerance = slack * box.Size[d];
      fits = bounds[2 * d] >= low - tolerance && bounds[2 * d + 1] <= low + box.Size[d] + tolerance;
    }
    if (fits)
    {
      for (int d = 0; d < 3; ++d)
      {
        box.Origin[d] = origin * box.Size[d];
      }
      return true;
    }
  }
  return false;
}

vtkSmartPointer<vtkPolyData> WithPeriodicImages(
  vtkPointSet* input, const PeriodicBox& box, double margin, std::vector<vtkIdType>& imageOf)
{
  const vtkIdType n = input->GetNumberOfPoints();
  imageOf.clear();
  std::vector<double> shifted;
  const double reach[3] = { margin * box.Size[0], margin * box.Size[1], margin * box.Size[2] };
  for (vtkIdType i = 0; i < n; ++i)
  {
    double x[3];
    input->GetPoint(i, x);
    ForEachPeriodicImage(x, box, reach, false, [&](const double* y) {
      imageOf.push_back(i);
      shifted.insert(shifted.end(), y, y + 3);
    });
  }
  const vtkIdType images = static_cast<vtkIdType>(imageOf.size());
  auto out = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> points;
  points->SetDataType(input->GetPoints() ? input->GetPoints()->GetDataType() : VTK_DOUBLE);
  points->SetNumberOfPoints(n + images);
  for (vtkIdType i = 0; i < n; ++i)
  {
    points->SetPoint(i, input->GetPoint(i));
  }
  for (vtkIdType k = 0; k < images; ++k)
  {
    points->SetPoint(n + k, &shifted[3 * k]);
  }
  out->SetPoints(points);
  // Point data: the originals' tuples, then each image's original's.
  vtkNew<vtkIdList> ids;
  ids->SetNumberOfIds(n + images);
  for (vtkIdType i = 0; i < n; ++i)
  {
    ids->SetId(i, i);
  }
  for (vtkIdType k = 0; k < images; ++k)
  {
    ids->SetId(n + k, imageOf[k]);
  }
  vtkPointData* target = out->GetPointData();
  vtkPointData* source = input->GetPointData();
  for (int a = 0; a < source->GetNumberOfArrays(); ++a)
  {
    vtkDataArray* array = source->GetArray(a);
    if (!array || array->GetNumberOfTuples() != n)
    {
      continue; // malformed arrays are left out (the filter reports them on the original input)
    }
    vtkSmartPointer<vtkDataArray> copy = vtk::TakeSmartPointer(array->NewInstance());
    copy->SetName(array->GetName());
    copy->SetNumberOfComponents(array->GetNumberOfComponents());
    copy->SetNumberOfTuples(n + images);
    array->GetTuples(ids, copy);
    target->AddArray(copy);
    if (source->GetScalars() == array)
    {
      target->SetActiveScalars(array->GetName());
    }
  }
  out->GetFieldData()->PassData(input->GetFieldData());
  return out;
}

std::vector<vtkIdType> OriginalIds(
  const Neighborhoods& geometry, vtkIdType originalCount, const std::vector<vtkIdType>& imageOf)
{
  std::vector<vtkIdType> original(geometry.NumberOfSamples);
  vtkSMPTools::For(0, static_cast<vtkIdType>(geometry.NumberOfSamples),
    BalancedGrain(geometry.NumberOfSamples, 1024), [&](vtkIdType begin, vtkIdType end) {
      for (vtkIdType i = begin; i < end; ++i)
      {
        const vtkIdType id = geometry.Order[i];
        const std::size_t image = static_cast<std::size_t>(id - originalCount);
        original[i] = id < originalCount ? id : (image < imageOf.size() ? imageOf[image] : -1);
      }
    });
  return original;
}

std::size_t SamplesBeyondImages(const Neighborhoods& geometry, const PeriodicBox& box,
  double margin, vtkIdType originalCount, const std::vector<double>& supports, double& needed)
{
  // A sample's distance to the nearer face on axis d, and the room its reach has before the
  // images end (they end margin * L beyond each face; the neighbourhood must end before).
  auto fromFace = [&](std::size_t i, int d) {
    const double x = geometry.Position(i)[d] - box.Origin[d];
    return std::min(x, box.Size[d] - x);
  };
  auto roomOf = [&](std::size_t i, int d) { return fromFace(i, d) + margin * box.Size[d]; };
  auto support = [&](std::size_t i) { return supports.empty() ? 0.0 : supports[i]; };
  // Most samples lie too far inside for their reach to pass the images' edge: an upper bound on
  // each radius without a search (RadiusBound) says which, and only the others' neighbour
  // lists are computed (in parallel), not every sample's.
  const std::vector<std::uint32_t> near =
    IndicesWhere<std::uint32_t>(geometry.NumberOfSamples, [&](std::size_t i) {
      if (geometry.Order[i] >= originalCount)
      {
        return false;
      }
      const double room = std::min({ roomOf(i, 0), roomOf(i, 1), roomOf(i, 2) });
      return support(i) > room || RadiusBound(geometry, i) > room;
    });
  geometry.EnsureNeighbors(near);
  std::size_t count = 0;
  needed = margin;
  for (const std::uint32_t i : near)
  {
    const double reach = std::max(geometry.RadiusOf(i), support(i));
    bool cut = false;
    for (int d = 0; d < 3; ++d)
    {
      if (reach > roomOf(i, d))
      {
        cut = true;
        needed = std::max(needed, (reach - fromFace(i, d)) / box.Size[d]);
      }
    }
    count += cut ? 1 : 0;
  }
  return count;
}

bool InKeptCell(const double* x, const PeriodicBox& box, const double* center)
{
  for (int d = 0; d < 3; ++d)
  {
    const double low = center ? center[d] - 0.5 * box.Size[d] : box.Origin[d];
    if (!(x[d] >= low && x[d] < low + box.Size[d]))
    {
      return false;
    }
  }
  return true;
}

void KeptCellCenter(const std::vector<double>& spheres, const PeriodicBox& box, double center[3])
{
  for (int d = 0; d < 3; ++d)
  {
    center[d] = spheres.empty() ? box.Origin[d] + 0.5 * box.Size[d] : spheres[d];
  }
}

void IntoCellAround(std::vector<double>& points, const PeriodicBox& box, const double* center)
{
  for (std::size_t i = 0; i < points.size(); i += 3)
  {
    for (int d = 0; d < 3; ++d)
    {
      const double low = center[d] - 0.5 * box.Size[d];
      points[i + d] -= box.Size[d] * std::floor((points[i + d] - low) / box.Size[d]);
    }
  }
}

} // namespace lsi
