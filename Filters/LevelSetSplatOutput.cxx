// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "LevelSetSplatOutput.h"

#include "IsopointRefinement.h"
#include "LevelSetSPHField.h"
#include "Splats.h"

#include "vtkCellArray.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkIdList.h"
#include "vtkIdTypeArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSMPTools.h"
#include "vtkSmartPointer.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace lsi
{

namespace
{
// `source` (a tuple per isopoint) with each tuple repeated for the isopoint's `sides` corners:
// in parallel, straight from memory for float and double arrays (nearly all of them), else
// through GetTuples.
vtkSmartPointer<vtkDataArray> PerCorner(vtkDataArray* source, vtkIdType count, int sides)
{
  vtkSmartPointer<vtkDataArray> copy = vtk::TakeSmartPointer(source->NewInstance());
  copy->SetName(source->GetName());
  const int components = source->GetNumberOfComponents();
  copy->SetNumberOfComponents(components);
  copy->SetNumberOfTuples(count * sides);
  auto repeat = [&](const auto* from, auto* to) {
    vtkSMPTools::For(0, count, BalancedGrain(static_cast<std::size_t>(count), 16384),
      [&](vtkIdType begin, vtkIdType end) {
        for (vtkIdType i = begin; i < end; ++i)
        {
          for (int k = 0; k < sides; ++k)
          {
            std::copy(from + i * components, from + (i + 1) * components,
              to + (i * sides + k) * components);
          }
        }
      });
  };
  vtkDoubleArray* doubles = vtkDoubleArray::FastDownCast(source);
  vtkFloatArray* floats = vtkFloatArray::FastDownCast(source);
  if (doubles && vtkDoubleArray::FastDownCast(copy))
  {
    repeat(doubles->GetPointer(0), vtkDoubleArray::FastDownCast(copy)->GetPointer(0));
  }
  else if (floats && vtkFloatArray::FastDownCast(copy))
  {
    repeat(floats->GetPointer(0), vtkFloatArray::FastDownCast(copy)->GetPointer(0));
  }
  else
  {
    vtkNew<vtkIdList> owner; // the isopoint each corner comes from
    owner->SetNumberOfIds(count * sides);
    for (vtkIdType k = 0; k < count * sides; ++k)
    {
      owner->SetId(k, k / sides);
    }
    source->GetTuples(owner, copy);
  }
  return copy;
}

// `source` (the isopoints' normals) per corner, holding `normals` (3 floats per corner).
vtkSmartPointer<vtkDataArray> CornerNormalsArray(
  vtkDataArray* source, const std::vector<float>& normals, vtkIdType count, int sides)
{
  vtkFloatArray* floats = vtkFloatArray::FastDownCast(source);
  if (floats && floats->GetNumberOfComponents() == 3) // (as MakeSurfacePoints makes them)
  {
    vtkNew<vtkFloatArray> packed;
    packed->SetName(source->GetName());
    packed->SetNumberOfComponents(3);
    packed->SetNumberOfTuples(count * sides);
    std::copy(normals.begin(), normals.end(), packed->GetPointer(0));
    return packed;
  }
  // Other layouts: the centre's tuples, their first three components then replaced.
  vtkSmartPointer<vtkDataArray> copy = PerCorner(source, count, sides);
  for (vtkIdType k = 0; k < count * sides; ++k)
  {
    for (int d = 0; d < 3; ++d)
    {
      copy->SetComponent(k, d, normals[3 * k + d]);
    }
  }
  return copy;
}
} // namespace

// Consecutive splats (near each other: the points come in spatial order) whose corners one
// gather of the SPH field's samples serves: at most this many, their centres within
// SplatGroupWidth radii of the first one's of each other (GroupEnd).
constexpr std::size_t SplatGroup = 32;
constexpr double SplatGroupWidth = 8.0;

bool MakeSplatPolygons(vtkPolyData* isopoints, int sides, const SPHField* field, double isoValue,
  vtkPolyData* splats, const AbortCheck& aborted, const std::vector<double>* unroundedNormals,
  const std::vector<double>* unroundedRadii)
{
  const vtkIdType count = isopoints->GetNumberOfPoints();
  const std::size_t pointCount = static_cast<std::size_t>(count);
  const double* exactNormals = unroundedNormals && unroundedNormals->size() == 3 * pointCount
    ? unroundedNormals->data()
    : nullptr;
  const double* exactRadii =
    unroundedRadii && unroundedRadii->size() == pointCount ? unroundedRadii->data() : nullptr;
  vtkPointData* pointData = isopoints->GetPointData();
  vtkDataArray* normals = pointData->GetArray("Normals");
  vtkDataArray* radii = pointData->GetArray("SplatRadius");
  auto radiusOf = [&](std::size_t k) {
    return exactRadii ? exactRadii[k] : radii->GetComponent(static_cast<vtkIdType>(k), 0);
  };
  const vtkIdType corners = count * sides;

  vtkNew<vtkPoints> cornerPoints;
  cornerPoints->SetDataTypeToDouble();
  cornerPoints->SetNumberOfPoints(corners);
  double* xyz = static_cast<double*>(cornerPoints->GetData()->GetVoidPointer(0));
  std::vector<float> cornerNormals(field ? 3 * static_cast<std::size_t>(corners) : 0);
  std::vector<double> centres; // (on the SPH field, for the groups' boxes)
  for (vtkIdType i = 0; field && i < count; ++i)
  {
    double c[3];
    isopoints->GetPoint(i, c);
    centres.insert(centres.end(), c, c + 3);
  }
  const bool completed = ParallelForInBlocks(
    static_cast<std::size_t>(count),
    [&](std::size_t begin, std::size_t end) {
      SPHCandidates group, candidates;
      std::size_t gatheredTo = begin; // the splats the group's candidates serve: up to here
      for (std::size_t i = begin; i < end; ++i)
      {
        double c[3], n[3];
        isopoints->GetPoint(static_cast<vtkIdType>(i), c);
        if (exactNormals)
        {
          std::copy(exactNormals + 3 * i, exactNormals + 3 * i + 3, n);
        }
        else
        {
          normals->GetTuple(static_cast<vtkIdType>(i), n);
        }
        const double radius = radiusOf(i);
        const Eigen::Vector3d normal = Eigen::Vector3d(n).normalized();
        DiskCorners(Eigen::Vector3d(c), normal, radius, sides, &xyz[3 * i * sides]);
        if (field && i == gatheredTo)
        {
          // The corners are within sqrt(2) radii of their centre (a slid one too): one gather
          // within 1.5 radii of the centres of a few consecutive splats serves them all.
          double lower[3], upper[3], widest = 0.0;
          gatheredTo =
            GroupEnd(centres.data(), i, end, SplatGroup, SplatGroupWidth * radius, lower, upper);
          for (std::size_t k = i; k < gatheredTo; ++k)
          {
            widest = std::max(widest, radiusOf(k));
          }
          field->GatherForBox(lower, upper, 1.5 * widest, group);
        }
        if (field) // (this splat's: fewer to sum at each corner)
        {
          SPHField::GatherAmong(group, c, 1.5 * radius, candidates);
        }
        for (int k = 0; field && k < sides; ++k)
        {
          double* corner = &xyz[3 * (i * sides + k)];
          // Where the surface curves away faster than the splat is wide (a rim), the line
          // through the flat corner misses the level: pull the corner halfway in and try again,
          // and else put it on the centre, so that no corner stands off the surface.
          const Eigen::Vector3d centre(c), flat(corner);
          Eigen::Vector3d cornerNormal = normal, placed = centre;
          for (double fraction : { 1.0, 0.5 })
          {
            Eigen::Vector3d p = centre + fraction * (flat - centre);
            if (SolveOntoLevel(*field, candidates, isoValue, p, normal, fraction * radius,
                  1e-6 * radius, cornerNormal))
            {
              placed = p;
              break;
            }
          }
          std::copy(placed.data(), placed.data() + 3, corner);
          for (int d = 0; d < 3; ++d)
          {
            cornerNormals[3 * (i * sides + k) + d] = static_cast<float>(cornerNormal[d]);
          }
        }
      }
    },
    aborted);
  if (!completed)
  {
    return false;
  }

  // Polygon p uses corners p * sides ... p * sides + sides - 1.
  vtkNew<vtkIdTypeArray> offsets, connectivity;
  offsets->SetNumberOfValues(count + 1);
  connectivity->SetNumberOfValues(corners);
  vtkIdType* offset = offsets->GetPointer(0);
  vtkIdType* cornerIds = connectivity->GetPointer(0);
  vtkSMPTools::For(0, count + 1, BalancedGrain(static_cast<std::size_t>(count + 1), 1024),
    [&](vtkIdType begin, vtkIdType end) {
      for (vtkIdType p = begin; p < end; ++p)
      {
        offset[p] = p * sides;
        for (vtkIdType k = p * sides; p < count && k < (p + 1) * sides; ++k)
        {
          cornerIds[k] = k;
        }
      }
    });
  vtkNew<vtkCellArray> polygons;
  polygons->SetData(offsets, connectivity);

  splats->Initialize();
  splats->SetPoints(cornerPoints);
  splats->SetPolys(polygons);
  vtkPointData* cornerData = splats->GetPointData();
  for (int a = 0; a < pointData->GetNumberOfArrays(); ++a)
  {
    vtkDataArray* source = pointData->GetArray(a);
    if (!source)
    {
      continue;
    }
    // On the SPH field each corner carries the normal solved at it above, not its centre's.
    const bool solvedNormals =
      field && source->GetName() && std::string(source->GetName()) == "Normals";
    vtkSmartPointer<vtkDataArray> copy = solvedNormals
      ? CornerNormalsArray(source, cornerNormals, count, sides)
      : PerCorner(source, count, sides);
    cornerData->AddArray(copy);
  }
  cornerData->SetActiveNormals("Normals");
  return true;
}

void MoveSplatCorners(
  const std::vector<double>& from, const std::vector<double>& to, int sides, vtkPolyData* splats)
{
  vtkPoints* corners = splats->GetPoints();
  const vtkIdType count = static_cast<vtkIdType>(from.size() / 3);
  if (!corners || corners->GetNumberOfPoints() != count * sides)
  {
    return;
  }
  for (vtkIdType i = 0; i < count; ++i)
  {
    const double shift[3] = { to[3 * i] - from[3 * i], to[3 * i + 1] - from[3 * i + 1],
      to[3 * i + 2] - from[3 * i + 2] };
    if (shift[0] == 0.0 && shift[1] == 0.0 && shift[2] == 0.0)
    {
      continue;
    }
    for (vtkIdType k = i * sides; k < (i + 1) * sides; ++k)
    {
      double x[3];
      corners->GetPoint(k, x);
      corners->SetPoint(k, x[0] + shift[0], x[1] + shift[1], x[2] + shift[2]);
    }
  }
  corners->Modified();
}

} // namespace lsi
