// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "LevelSetInput.h"

#include "LevelSetParallel.h"
#include "LevelSetSplines.h"

#include "vtkArrayDispatch.h"
#include "vtkDataArray.h"
#include "vtkDataObject.h"
#include "vtkPointSet.h"
#include "vtkPoints.h"
#include "vtkSMPThreadLocal.h"
#include "vtkSMPTools.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <sstream>

namespace lsi
{

std::string CheckCount(vtkIdType n, int numberOfNeighbors)
{
  std::ostringstream problem;
  if (n == 0)
  {
    problem << "The input has no points.";
  }
  else if (n < numberOfNeighbors + 1)
  {
    problem << "The input has " << n
            << " points, fewer than NumberOfNeighbors + 1 = " << numberOfNeighbors + 1 << ".";
  }
  return problem.str();
}

namespace
{
// Value i of a concrete array type, or of any vtkDataArray through GetTuple (safe from threads).
template <typename Array>
void ValueInto(Array* array, vtkIdType i, double& value)
{
  value = static_cast<double>(array->GetValue(i));
}
void ValueInto(vtkDataArray* array, vtkIdType i, double& value)
{
  array->GetTuple(i, &value);
}
template <typename Array>
void PointInto(Array* array, vtkIdType i, double x[3])
{
  for (int k = 0; k < 3; ++k)
  {
    x[k] = static_cast<double>(array->GetTypedComponent(i, k));
  }
}
void PointInto(vtkDataArray* array, vtkIdType i, double x[3])
{
  array->GetTuple(i, x);
}
} // namespace

std::string CheckPiece(vtkPointSet* input, vtkDataArray* scalars, int association,
  std::vector<double>& values, double range[2])
{
  std::ostringstream problem;
  const vtkIdType n = input->GetNumberOfPoints();
  const std::string name = scalars && scalars->GetName() ? scalars->GetName() : "";
  range[0] = DBL_MAX;
  range[1] = -DBL_MAX;
  values.clear();
  if (n == 0 || !input->GetPoints())
  {
    return std::string(); // an empty piece (under MPI) has nothing to check
  }
  if (n >= static_cast<vtkIdType>(UINT32_MAX))
  {
    problem << "The input has " << n << " points; at most 2^32 - 1 are supported.";
  }
  else if (!scalars)
  {
    problem << "No input scalars: select a point array with Scalars (SetInputArrayToProcess).";
  }
  else if (association != vtkDataObject::FIELD_ASSOCIATION_POINTS)
  {
    problem << "The array '" << name << "' is not a point array.";
  }
  else if (scalars->GetNumberOfComponents() != 1)
  {
    problem << "The array '" << name << "' has " << scalars->GetNumberOfComponents()
            << " components; a scalar (1 component) is required.";
  }
  else if (scalars->GetNumberOfTuples() != n)
  {
    problem << "The array '" << name << "' has " << scalars->GetNumberOfTuples() << " values for "
            << n << " points: a malformed point array.";
  }
  if (!problem.str().empty())
  {
    return problem.str();
  }

  // In parallel; the first bad point (lowest id) is reported, as a serial pass would.
  ResizeMappedInParallel(values, static_cast<std::size_t>(n));
  vtkSMPThreadLocal<std::array<double, 2>> ranges(std::array<double, 2>{ DBL_MAX, -DBL_MAX });
  std::atomic<vtkIdType> badValue{ n }, badPoint{ n };
  auto lower = [](std::atomic<vtkIdType>& first, vtkIdType i) {
    vtkIdType seen = first.load();
    while (i < seen && !first.compare_exchange_weak(seen, i))
    {
    }
  };
  // Through the arrays' concrete types where vtkArrayDispatch knows them (no virtual call per
  // value), else through vtkDataArray.
  // (vtkDataArray's GetComponent is not safe from threads; GetTuple into a buffer is.)
  auto readValues = [&](auto* array) {
    vtkSMPTools::For(
      0, n, BalancedGrain(static_cast<std::size_t>(n), 16384), [&](vtkIdType begin, vtkIdType end) {
        std::array<double, 2>& r = ranges.Local();
        for (vtkIdType i = begin; i < end; ++i)
        {
          ValueInto(array, i, values[i]);
          if (!std::isfinite(values[i]))
          {
            lower(badValue, i);
          }
          r[0] = std::min(r[0], values[i]);
          r[1] = std::max(r[1], values[i]);
        }
      });
  };
  if (!vtkArrayDispatch::Dispatch::Execute(scalars, readValues))
  {
    readValues(scalars);
  }
  auto checkPoints = [&](auto* array) {
    vtkSMPTools::For(
      0, n, BalancedGrain(static_cast<std::size_t>(n), 16384), [&](vtkIdType begin, vtkIdType end) {
        for (vtkIdType i = begin; i < end; ++i)
        {
          double x[3];
          PointInto(array, i, x);
          if (!std::isfinite(x[0]) || !std::isfinite(x[1]) || !std::isfinite(x[2]))
          {
            lower(badPoint, i);
          }
        }
      });
  };
  vtkDataArray* coordinates = input->GetPoints()->GetData();
  if (!vtkArrayDispatch::DispatchByValueType<vtkArrayDispatch::Reals>::Execute(
        coordinates, checkPoints))
  {
    checkPoints(coordinates);
  }
  if (badValue < n && badValue <= badPoint)
  {
    problem << "The array '" << name << "' has a NaN or infinite value at point " << badValue
            << ".";
    return problem.str();
  }
  if (badPoint < n)
  {
    problem << "Point " << badPoint << " has a NaN or infinite coordinate.";
    return problem.str();
  }
  for (const std::array<double, 2>& r : ranges)
  {
    range[0] = std::min(range[0], r[0]);
    range[1] = std::max(range[1], r[1]);
  }
  return std::string();
}

std::string CheckRangeAndSeeds(
  const double range[2], double isoValue, const std::vector<double>& additionalSeeds)
{
  if (!(isoValue > range[0] && isoValue < range[1]))
  {
    std::ostringstream problem;
    problem << "IsoValue " << isoValue << " is outside the open range of the data (" << range[0]
            << ", " << range[1] << "): no isosurface.";
    return problem.str();
  }
  return CheckSeedRadii(additionalSeeds);
}

std::string CheckSeedRadii(const std::vector<double>& additionalSeeds)
{
  std::ostringstream problem;
  for (std::size_t s = 0; s + 3 < additionalSeeds.size(); s += 4)
  {
    if (!(additionalSeeds[s + 3] > 0.0))
    {
      problem << "Additional seed " << s / 4 << " has radius " << additionalSeeds[s + 3]
              << "; radii must be positive.";
      return problem.str();
    }
  }
  return std::string();
}

std::string CheckInput(vtkPointSet* input, vtkDataArray* scalars, int association,
  int numberOfNeighbors, double isoValue, const std::vector<double>& additionalSeeds,
  std::vector<double>& values)
{
  std::string problem =
    CheckCount(input->GetPoints() ? input->GetNumberOfPoints() : 0, numberOfNeighbors);
  double range[2];
  if (problem.empty())
  {
    problem = CheckPiece(input, scalars, association, values, range);
  }
  return problem.empty() ? CheckRangeAndSeeds(range, isoValue, additionalSeeds) : problem;
}

std::string NonFiniteParameter(const std::vector<std::pair<const char*, double>>& named)
{
  for (const auto& parameter : named)
  {
    if (!std::isfinite(parameter.second))
    {
      std::ostringstream problem;
      problem << parameter.first << " is " << parameter.second
              << "; every parameter must be a finite number.";
      return problem.str();
    }
  }
  return std::string();
}

std::string CheckNeighborhoods(const Neighborhoods& geometry)
{
  std::ostringstream problem;
  if (geometry.DuplicateSamples > 0) // only after merging (LevelSetDuplicates): a bug
  {
    problem << "The input still has " << geometry.DuplicateSamples
            << " points that coincide with another point after merging them (for example point "
            << geometry.FirstDuplicate << ").";
  }
  else if (geometry.Flat)
  {
    problem << "All input points lie on one plane or line, so the MLS fit is singular "
               "everywhere: the method needs volume (3D) samples.";
  }
  return problem.str();
}

std::string CheckSeedSpheres(
  const std::vector<double>& spheres, const std::vector<std::size_t>& samplesPerSphere)
{
  std::ostringstream problem;
  for (std::size_t s = 0; s < samplesPerSphere.size(); ++s)
  {
    if (samplesPerSphere[s] == 0)
    {
      problem << "Seed sphere " << s << (s == 0 ? " (the main seed)" : " (additional)") << " at ("
              << spheres[4 * s] << ", " << spheres[4 * s + 1] << ", " << spheres[4 * s + 2]
              << ") with radius " << spheres[4 * s + 3]
              << " contains no sample. (In a script, update the input before creating the "
                 "filter, or set SeedCenter.)";
      break;
    }
  }
  return problem.str();
}

void DataInStorageOrder(const Neighborhoods& geometry, const std::vector<double>& values,
  double isoValue, std::vector<double>& dataOffsets)
{
  const std::size_t n = geometry.NumberOfSamples;
  ResizeMappedInParallel(dataOffsets, n);
  vtkSMPTools::For(
    0, static_cast<vtkIdType>(n), BalancedGrain(n, 16384), [&](vtkIdType begin, vtkIdType end) {
      for (vtkIdType i = begin; i < end; ++i)
      {
        dataOffsets[i] = values[geometry.Order[i]] - isoValue;
      }
    });
}

} // namespace lsi
