// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "LevelSetSurfaceOutput.h"

#include "LevelSetArrayKinds.h"
#include "LevelSetIsopoints.h"

#include "LevelSetMLSFit.h"
#include "LevelSetSPHField.h"
#include "LevelSetSplatRadii.h"
#include "NearestNeighbors.h"
#include "Splats.h"

#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkIdList.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSMPThreadLocal.h"
#include "vtkSMPTools.h"
#include "vtkSmartPointer.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <memory>
#include <utility>

namespace lsi
{

namespace
{
// A source array's values for reading in a tight loop: straight from memory when they are
// doubles or floats (most arrays), else through the virtual GetComponent; or, for a
// one-component array given in storage order too (`stored`), from there: the samples near a
// point lie near each other in storage order, and scattered in input order.
struct ValuesOf
{
  vtkDataArray* Array = nullptr;
  const double* Doubles = nullptr;
  const float* Floats = nullptr;
  const double* Stored = nullptr;
  int Components = 1;

  explicit ValuesOf(vtkDataArray* array, const double* stored = nullptr)
    : Array(array)
    , Stored(array->GetNumberOfComponents() == 1 ? stored : nullptr)
    , Components(array->GetNumberOfComponents())
  {
    if (auto* d = vtkDoubleArray::FastDownCast(array))
    {
      this->Doubles = d->GetPointer(0);
    }
    else if (auto* f = vtkFloatArray::FastDownCast(array))
    {
      this->Floats = f->GetPointer(0);
    }
  }
  double operator()(vtkIdType tuple, int c) const
  {
    const vtkIdType k = tuple * this->Components + c;
    return this->Doubles ? this->Doubles[k]
      : this->Floats     ? this->Floats[k]
                         : this->Array->GetComponent(tuple, c);
  }
  // Component c at `sample` (storage order).
  double AtSample(const Neighborhoods& geometry, std::uint32_t sample, int c) const
  {
    return this->Stored ? this->Stored[sample] : (*this)(geometry.Order[sample], c);
  }
};
} // namespace

bool InterpolatePointArrays(const Neighborhoods& geometry, const std::vector<double>& points,
  std::size_t fitCount, const std::vector<vtkDataArray*>& sources,
  const std::vector<vtkDataArray*>& targets, const AbortCheck& aborted,
  const std::uint32_t* nearest, const std::vector<const double*>* inStorageOrder)
{
  const std::size_t count = points.size() / 3;
  std::vector<ValuesOf> values;
  for (std::size_t a = 0; a < sources.size(); ++a)
  {
    values.emplace_back(sources[a], inStorageOrder ? (*inStorageOrder)[a] : nullptr);
  }
  struct Scratch
  {
    std::shared_ptr<MLSStencil> Stencil; // for the gathers when no samples were kept
    std::vector<std::uint32_t> Ids;
    std::vector<double> Weights;
    std::vector<double> Offsets; // the samples' positions relative to the point
  };
  vtkSMPThreadLocal<Scratch> scratch;
  return ParallelForInBlocks(
    count,
    [&](std::size_t begin, std::size_t end) {
      Scratch& s = scratch.Local();
      if (!s.Stencil)
      {
        s.Stencil.reset(new MLSStencil(geometry, fitCount));
        s.Ids.resize(fitCount);
        s.Weights.resize(fitCount);
        s.Offsets.resize(3 * fitCount);
      }
      for (std::size_t i = begin; i < end; ++i)
      {
        const Eigen::Vector3d p(&points[3 * i]);
        const std::uint32_t* ids = nearest ? nearest + fitCount * i : nullptr;
        std::size_t found = 0;
        if (nearest)
        {
          found = static_cast<std::size_t>(std::find(ids, ids + fitCount, NoSample) - ids);
        }
        else
        {
          s.Stencil->Gather(p);
          found = s.Stencil->Found();
          for (std::size_t j = 0; j < found; ++j)
          {
            s.Ids[j] = s.Stencil->Sample(j);
          }
          ids = s.Ids.data();
        }
        // The fit's support reaches the farthest sample; a singular fit (samples on a plane or
        // line) takes the nearest sample's value.
        double farthest2 = 0.0, nearest2 = HUGE_VAL;
        std::size_t closest = 0;
        for (std::size_t j = 0; j < found; ++j)
        {
          const double* x = geometry.Position(ids[j]);
          double* offset = &s.Offsets[3 * j];
          for (int d = 0; d < 3; ++d)
          {
            offset[d] = x[d] - p[d];
          }
          const double d2 = offset[0] * offset[0] + offset[1] * offset[1] + offset[2] * offset[2];
          farthest2 = std::max(farthest2, d2);
          if (d2 < nearest2)
          {
            nearest2 = d2;
            closest = j;
          }
        }
        const double origin[3] = { 0.0, 0.0, 0.0 };
        const bool fitted = LinearValueWeights(
          origin, found, [&](std::size_t j) { return &s.Offsets[3 * j]; }, std::sqrt(farthest2),
          s.Weights.data());
        for (std::size_t a = 0; a < values.size(); ++a)
        {
          const ValuesOf& source = values[a];
          for (int c = 0; c < source.Components; ++c)
          {
            double value = 0.0;
            if (!fitted)
            {
              value = found ? source.AtSample(geometry, ids[closest], c) : 0.0;
            }
            for (std::size_t j = 0; fitted && j < found; ++j)
            {
              const double w = s.Weights[j];
              if (w != 0.0)
              {
                value += w * source.AtSample(geometry, ids[j], c);
              }
            }
            targets[a]->SetComponent(static_cast<vtkIdType>(i), c, value);
          }
        }
      }
    },
    aborted, 8192);
}

bool SameValuesInStorageOrder(
  vtkDataArray* array, const Neighborhoods& geometry, const std::vector<double>& values)
{
  if (!array || array->GetNumberOfComponents() != 1 ||
    array->GetNumberOfTuples() != static_cast<vtkIdType>(geometry.NumberOfSamples) ||
    values.size() != geometry.NumberOfSamples ||
    !(vtkDoubleArray::FastDownCast(array) || vtkFloatArray::FastDownCast(array)))
  {
    return false;
  }
  const ValuesOf source(array);
  std::atomic<bool> same(true);
  vtkSMPTools::For(0, static_cast<vtkIdType>(values.size()), BalancedGrain(values.size(), 1024),
    [&](vtkIdType begin, vtkIdType end) {
      for (vtkIdType i = begin; i < end && same.load(std::memory_order_relaxed); ++i)
      {
        if (!(values[i] == source(geometry.Order[i], 0)))
        {
          same = false;
        }
      }
    });
  return same;
}

bool InterpolatePointArraysSPH(const Neighborhoods& geometry, const SPHField& field,
  const std::vector<double>& points, const std::vector<vtkDataArray*>& sources,
  const std::vector<vtkDataArray*>& targets, const AbortCheck& aborted)
{
  const std::size_t count = points.size() / 3;
  std::vector<ValuesOf> values; // read straight from memory where they can be (the same values)
  for (vtkDataArray* source : sources)
  {
    values.emplace_back(source);
  }
  return ParallelForInBlocks(
    count,
    [&](std::size_t begin, std::size_t end) {
      std::vector<std::pair<vtkIdType, double>> weights; // input ids and weights
      std::vector<std::uint32_t> reaching;               // the samples reaching a group of points
      std::size_t groupEnd = begin; // where the group ends: the next starts there
      for (std::size_t i = begin; i < end; ++i)
      {
        if (i == groupEnd)
        {
          // One walk of the field's hierarchy for a group of consecutive points (near each
          // other: within the support of the sample nearest to the first); each point then
          // weighs its own samples among them, in the same order.
          std::uint32_t nearest;
          double d2, lower[3], upper[3];
          geometry.Index->Nearest(&points[3 * i], 1, &nearest, &d2);
          groupEnd = GroupEnd(
            points.data(), i, end, SPHPointGroup::Most, field.Support(nearest), lower, upper);
          field.SamplesReaching(lower, upper, reaching);
        }
        weights.clear();
        field.ForEachWeightAmong(reaching, &points[3 * i],
          [&](std::uint32_t j, double w) { weights.emplace_back(geometry.Order[j], w); });
        for (std::size_t a = 0; a < sources.size(); ++a)
        {
          const ValuesOf& source = values[a];
          for (int c = 0; c < source.Components; ++c)
          {
            double value = 0.0;
            for (const auto& weight : weights)
            {
              value += weight.second * source(weight.first, c);
            }
            targets[a]->SetComponent(static_cast<vtkIdType>(i), c, value);
          }
        }
      }
    },
    aborted, 8192);
}

bool CopyNearestSampleValues(const Neighborhoods& geometry, const std::vector<double>& points,
  const std::vector<vtkDataArray*>& sources, const std::vector<vtkDataArray*>& targets,
  const AbortCheck& aborted)
{
  const std::size_t count = points.size() / 3;
  if (count == 0 || geometry.NumberOfSamples == 0)
  {
    return true;
  }
  vtkNew<vtkIdList> from, to;
  from->SetNumberOfIds(static_cast<vtkIdType>(count));
  to->SetNumberOfIds(static_cast<vtkIdType>(count));
  vtkIdType* fromIds = from->GetPointer(0);
  if (!ParallelForInBlocks(
        count,
        [&](std::size_t begin, std::size_t end) {
          for (std::size_t i = begin; i < end; ++i)
          {
            // Of two samples equally near, the one first in coordinate order: the same choice
            // whatever the tree (each rank's own under MPI).
            std::uint32_t nearest[2] = { 0, 0 };
            double squared[2] = { 0.0, HUGE_VAL };
            const std::size_t found = geometry.Index->Nearest(&points[3 * i], 2, nearest, squared);
            std::uint32_t chosen = nearest[0];
            if (found == 2 && squared[1] == squared[0])
            {
              const double *a = geometry.Position(nearest[0]), *b = geometry.Position(nearest[1]);
              chosen = std::lexicographical_compare(b, b + 3, a, a + 3) ? nearest[1] : nearest[0];
            }
            fromIds[i] = static_cast<vtkIdType>(geometry.Order[chosen]);
          }
        },
        aborted, 8192))
  {
    return false;
  }
  for (std::size_t i = 0; i < count; ++i)
  {
    to->SetId(static_cast<vtkIdType>(i), static_cast<vtkIdType>(i));
  }
  for (std::size_t a = 0; a < sources.size(); ++a)
  {
    targets[a]->InsertTuples(to, from, sources[a]);
  }
  return true;
}

bool MakeSurfacePoints(vtkPointData* inputData, const Neighborhoods& geometry,
  const IsopointSet& isopoints, double splatScale, bool interpolateArrays,
  const char* activeScalars, const SPHField* field, vtkPolyData* surface, const AbortCheck& aborted,
  const PointCloudIndex* pointIndex, const std::vector<double>* sampledAt,
  const std::vector<double>* scalarsInStorageOrder, KeptCandidates* keptSplats,
  std::vector<double>* splatRadii)
{
  const vtkIdType m = static_cast<vtkIdType>(isopoints.Points.size() / 3);
  vtkNew<vtkPoints> coordinates;
  coordinates->SetDataTypeToDouble();
  coordinates->SetNumberOfPoints(m);
  vtkNew<vtkFloatArray> normals;
  normals->SetName("Normals");
  normals->SetNumberOfComponents(3);
  normals->SetNumberOfTuples(m);
  for (vtkIdType i = 0; i < m; ++i)
  {
    coordinates->SetPoint(i, &isopoints.Points[3 * i]);
    normals->SetTuple(i, &isopoints.Normals[3 * i]);
  }
  surface->SetPoints(coordinates);
  surface->GetPointData()->SetNormals(normals);

  std::vector<double> radii;
  if (!SplatRadii(isopoints.Points, 6, splatScale, radii, aborted, pointIndex, keptSplats))
  {
    return false;
  }
  vtkNew<vtkFloatArray> radius;
  radius->SetName("SplatRadius");
  radius->SetNumberOfValues(m);
  for (vtkIdType i = 0; i < m; ++i)
  {
    radius->SetValue(i, static_cast<float>(radii[i]));
  }
  surface->GetPointData()->AddArray(radius);
  if (splatRadii)
  {
    *splatRadii = std::move(radii); // (not read below)
  }

  if (!interpolateArrays)
  {
    return true;
  }
  // Every numeric point array of the input, except names the filter itself produces: integer
  // arrays (ids, group numbers, flags) from the nearest sample, the others interpolated.
  std::vector<vtkSmartPointer<vtkDataArray>> sources, targets, added;
  std::vector<vtkDataArray*> integerSources, integerTargets;
  std::vector<const double*> inStorageOrder; // per source: the scalars' values, else null
  vtkDataArray* scalars = activeScalars ? inputData->GetArray(activeScalars) : nullptr;
  for (int a = 0; a < inputData->GetNumberOfArrays(); ++a)
  {
    vtkDataArray* array = inputData->GetArray(a);
    if (!array || !array->GetName() || array->GetDataType() == VTK_BIT ||
      surface->GetPointData()->GetArray(array->GetName()) ||
      array->GetNumberOfTuples() != static_cast<vtkIdType>(geometry.NumberOfSamples))
    {
      continue; // malformed arrays (a tuple count other than the points') are left out too
    }
    const bool integer = HoldsLabels(array);
    vtkSmartPointer<vtkDataArray> target;
    if (integer)
    {
      target = vtkSmartPointer<vtkDataArray>::Take(array->NewInstance()); // its own type
    }
    else if (array->GetDataType() == VTK_FLOAT)
    {
      target = vtkSmartPointer<vtkFloatArray>::New();
    }
    else
    {
      target = vtkSmartPointer<vtkDoubleArray>::New();
    }
    target->SetName(array->GetName());
    target->SetNumberOfComponents(array->GetNumberOfComponents());
    target->SetNumberOfTuples(m);
    added.push_back(target);
    if (integer)
    {
      integerSources.push_back(array);
      integerTargets.push_back(target);
      continue;
    }
    vtkSmartPointer<vtkDataArray> source = array;
    if (!array->HasStandardMemoryLayout())
    {
      // Read from many threads: only arrays with plain memory are safe for that.
      source = vtkSmartPointer<vtkDoubleArray>::New();
      source->DeepCopy(array);
    }
    sources.push_back(source);
    targets.push_back(target);
    inStorageOrder.push_back(array == scalars && scalarsInStorageOrder &&
          scalarsInStorageOrder->size() == geometry.NumberOfSamples
        ? scalarsInStorageOrder->data()
        : nullptr);
  }
  std::vector<vtkDataArray*> sourceList(sources.begin(), sources.end());
  std::vector<vtkDataArray*> targetList(targets.begin(), targets.end());
  const std::size_t fitCount =
    std::min(geometry.NumberOfSamples, 2 * static_cast<std::size_t>(geometry.Stride));
  // The data refinement's nearest samples at each point, when it kept them for this many.
  const bool kept = isopoints.FitSize == fitCount &&
    isopoints.FitSamples.size() == fitCount * static_cast<std::size_t>(m);
  const std::vector<double>& at = sampledAt ? *sampledAt : isopoints.Points;
  if (field ? !InterpolatePointArraysSPH(geometry, *field, at, sourceList, targetList, aborted)
            : !InterpolatePointArrays(geometry, at, fitCount, sourceList, targetList, aborted,
                kept ? isopoints.FitSamples.data() : nullptr, &inStorageOrder))
  {
    return false;
  }
  if (!integerSources.empty() &&
    !CopyNearestSampleValues(geometry, at, integerSources, integerTargets, aborted))
  {
    return false;
  }
  for (vtkDataArray* target : added)
  {
    surface->GetPointData()->AddArray(target);
  }
  if (activeScalars && surface->GetPointData()->GetArray(activeScalars))
  {
    surface->GetPointData()->SetActiveScalars(activeScalars);
  }
  return true;
}

} // namespace lsi
