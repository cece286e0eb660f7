// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
// vtkLevelSetIsosurface's outputs from the isopoints: the surface (splats, points or vertices with
// the input's arrays), the particles' signed distances and the Enclosed table; and the warnings
// on a suspect result (no surface, thin neighbourhoods, a region cut short).
#include "vtkLevelSetIsosurface.h"
#include "vtkLevelSetIsosurfaceInternals.h"

#include "LevelSetDistribution.h"
#include "LevelSetEnclosed.h"
#include "LevelSetEnclosedDeepInside.h"
#include "LevelSetEnclosedSurface.h"
#include "LevelSetIsopoints.h"
#include "LevelSetLastOutputs.h"
#include "LevelSetParticleOutput.h"
#include "LevelSetPeriodicImages.h"
#include "LevelSetRegionFaces.h"
#include "LevelSetSPHField.h"
#include "LevelSetSplatOutput.h"
#include "LevelSetSurfaceOutput.h"
#include "LevelSetTiming.h"
#include "LevelSetVertexCells.h"

#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkNew.h"
#include "vtkPointSet.h"
#include "vtkPolyData.h"
#include "vtkSMPThreadLocal.h"
#include "vtkSMPTools.h"
#include "vtkTable.h"

#include <array>
#include <utility>

namespace
{
using lsi::Clock;
using lsi::SecondsSince;
using lsi::SplatStage;
using lsi::SurfaceStage;
} // namespace

void vtkLevelSetIsosurface::MakeParticleOutputs(vtkPointSet* original, vtkPointSet* input,
  const lsi::Neighborhoods& geometry, const std::vector<double>& phi,
  const std::vector<vtkIdType>& mergedId, double halfWidth, const lsi::IsopointSet& keptPoints,
  const lsi::PointCloudIndex* surfaceIndex, vtkPolyData* particleOutput, vtkTable* enclosed,
  lsi::EnclosedDeepInside* keep, const lsi::EnclosedDeepInside* kept,
  const std::vector<std::size_t>* changed)
{
  const lsi::Distribution& ranks = *this->Internal->Ranks;
  const lsi::LastOutputs& last = this->Internal->Last;
  // The last output's LevelSet array: updated where only some samples changed, and the spare
  // for the next run after this one.
  const vtkSmartPointer<vtkDoubleArray> previous = last.Particles
    ? vtkDoubleArray::SafeDownCast(last.Particles->GetPointData()->GetArray("LevelSet"))
    : nullptr;
  vtkDataArray* lastLevelSet = changed && mergedId.empty() ? previous.GetPointer() : nullptr;
  vtkSmartPointer<vtkDoubleArray>& spare = this->Internal->SpareLevelSet;
  if (!lastLevelSet ||
    !lsi::UpdateParticleOutput(original, geometry, phi, *changed, lastLevelSet, particleOutput,
      this->Internal->ParticleVertices, spare))
  {
    lsi::MakeParticleOutput(
      original, geometry, phi, mergedId, particleOutput, this->Internal->ParticleVertices, spare);
  }
  spare = previous;
  if (ranks.Distributed()) // this rank's share, for the benchmarks: field data of port 1
  {
    for (const auto& entry : { std::make_pair("GhostParticles", double(ranks.GhostCount)),
           std::make_pair("CommunicationSeconds", ranks.CommunicationSeconds),
           std::make_pair("InputSeconds", this->InputSeconds),
           std::make_pair("NeighborSearchSeconds", this->NeighborSearchSeconds),
           std::make_pair("InitializationSeconds", this->InitializationSeconds),
           std::make_pair("EvolutionSeconds", this->EvolutionSeconds),
           std::make_pair("IsopointSeconds", this->IsopointSeconds),
           std::make_pair("OutputSeconds", this->OutputSeconds) })
    {
      vtkNew<vtkDoubleArray> value;
      value->SetName(entry.first);
      value->InsertNextValue(entry.second);
      particleOutput->GetFieldData()->AddArray(value);
    }
  }
  lsi::EnclosedInputs inside;
  inside.Geometry = &geometry;
  inside.Phi = &phi;
  inside.FarOutside = -halfWidth;
  inside.Particles = input;
  inside.ParticleCount = this->Internal->OriginalCount;
  inside.Box = this->Internal->Box;
  inside.CellCenter = this->PeriodicOutput == AROUND_SEED ? this->Internal->SeedCenter : nullptr;
  inside.Mass = lsi::MarkedMassArray(input, this->MassArray);
  inside.Density = lsi::MarkedDensityArray(input, this->DensityArray);
  inside.SurfacePoints = &keptPoints.Points;
  inside.SurfaceNormals = &keptPoints.Normals;
  inside.SurfaceIndex = surfaceIndex;
  inside.Ranks = &ranks;
  // Under MPI: every rank's kept points within reach, which together are the serial run's
  // (LevelSetEnclosedSurface.h; in a periodic box, in the cell: SurfaceDistance indexes them
  // with their images, so no index of them alone is built).
  std::vector<double> reachedPoints, reachedNormals;
  std::unique_ptr<lsi::PointCloudIndex> reachedIndex;
  if (ranks.Distributed())
  {
    lsi::KeptSurfaceWithinReach(
      ranks, geometry, phi, keptPoints, this->Internal->Box, reachedPoints, reachedNormals);
    reachedIndex = this->Internal->Box.Enabled ? nullptr : lsi::IndexOfPoints(reachedPoints);
    inside.SurfacePoints = &reachedPoints;
    inside.SurfaceNormals = &reachedNormals;
    inside.SurfaceIndex = reachedIndex.get();
  }
  // Where it applies, the table is summed around the deep inside even for a single run: fewer
  // passes over every particle, and less memory, than the route that supports images and ranks.
  lsi::EnclosedDeepInside single;
  inside.KeepDeepInside = kept ? nullptr : (keep ? keep : &single);
  inside.DeepInside = kept;
  // (Else, in one process, each sample is its own particle: Order's ids. Under MPI the ids tell
  // the ghosts, for the full route if the deep inside kept does not serve.)
  if (ranks.Distributed() || !lsi::CanUseDeepInside(inside))
  {
    inside.OriginalIds =
      lsi::OriginalIds(geometry, this->Internal->OriginalCount, this->Internal->ImageOf);
  }
  vtkSmartPointer<vtkTable> table = lsi::EnclosedTable(inside);
  if (this->ReportsForAll()) // tables on rank 0 only, so that gathering them shows them once
  {
    enclosed->ShallowCopy(table);
  }
}

void vtkLevelSetIsosurface::KeepOwnedIsopoints(
  const lsi::Neighborhoods& geometry, lsi::IsopointSet& isopoints)
{
  const lsi::Distribution& ranks = *this->Internal->Ranks;
  if (!ranks.Distributed())
  {
    return;
  }
  // Each piece of surface near a rank's boundary is found by both ranks: the rank that owns the
  // nearest sample keeps it.
  std::vector<char> kept(isopoints.Points.size() / 3);
  for (std::size_t i = 0; i < kept.size(); ++i)
  {
    kept[i] = lsi::OwnsNearestSample(geometry, ranks, &isopoints.Points[3 * i]) ? 1 : 0;
  }
  // (Their fits' samples go with them: the arrays are interpolated over those samples, as in a
  // serial run.)
  lsi::KeepSelected(isopoints, lsi::ValidIndices(kept));
}

void vtkLevelSetIsosurface::WarnIfSuspect(const lsi::Neighborhoods& geometry,
  const std::vector<double>& dataOffsets, const std::vector<double>& phi,
  const lsi::IsopointSet& isopoints)
{
  // Valid inputs, no surface: say why, rather than return an empty output silently. And a thin
  // layer of particles: say that the fits across it are ill-conditioned.
  const lsi::Distribution& ranks = *this->Internal->Ranks;
  double stencils[2] = { static_cast<double>(geometry.ThinSamples),
    static_cast<double>(geometry.ComputedStencils) };
  ranks.Sum(stencils, 2);
  if (stencils[0] > 0.01 * stencils[1] && this->ReportsForAll())
  {
    vtkWarningMacro(<< stencils[0] << " of the " << stencils[1]
                    << " neighbourhoods the evolution used are thin: their particles spread less "
                       "than "
                    << lsi::Neighborhoods::ThinRatio
                    << " times as far in one direction as in another (a thin layer or sheet of "
                       "particles). Gradients and normals across them are ill-conditioned, and "
                       "the surface may lie off the data. More NumberOfNeighbors may help.");
  }
  // (Counted in parallel: whole numbers, the same in any order.)
  vtkSMPThreadLocal<std::array<std::size_t, 3>> local({ 0, 0, 0 });
  vtkSMPTools::For(0, static_cast<vtkIdType>(geometry.NumberOfSamples),
    lsi::BalancedGrain(geometry.NumberOfSamples, 1024), [&](vtkIdType begin, vtkIdType end) {
      std::array<std::size_t, 3>& c = local.Local();
      for (vtkIdType i = begin; i < end; ++i)
      {
        if (ranks.Owns(static_cast<std::size_t>(i)))
        {
          c[0] += dataOffsets[i] > 0.0 ? 1 : 0;
          c[1] += phi[i] > 0.0 ? 1 : 0;
          ++c[2];
        }
      }
    });
  double counts[4] = { static_cast<double>(isopoints.Points.size() / 3), 0.0, 0.0, 0.0 };
  for (const std::array<std::size_t, 3>& c : local)
  {
    for (int k = 0; k < 3; ++k)
    {
      counts[k + 1] += static_cast<double>(c[k]);
    }
  }
  ranks.Sum(counts, 4);
  this->NumberOfIsopoints = static_cast<vtkIdType>(counts[0]);
  if (counts[0] == 0.0 && this->ReportsForAll())
  {
    vtkWarningMacro("No isosurface was found: "
      << counts[1] << " of " << counts[3] << " samples lie above IsoValue " << this->IsoValue
      << ", " << counts[2]
      << " of them in the seeded region after the evolution. A component needs more samples "
         "than one neighbourhood (NumberOfNeighbors + 1 = "
      << geometry.Stride
      << ") to be found: lower IsoValue, move or enlarge the seed, or use fewer "
         "NumberOfNeighbors.");
  }
}

void vtkLevelSetIsosurface::WarnIfRegionCut(vtkPointSet* input, const lsi::Neighborhoods& geometry,
  const lsi::SPHField* field, const std::vector<double>& points)
{
  const lsi::RegionFaces region = lsi::FindRegionFaces(input, this->Internal->Box);
  const lsi::Distribution& ranks = *this->Internal->Ranks;
  double counts[2] = { static_cast<double>(
                         lsi::PointsNearRegionFaces(geometry, field, points, region)),
    static_cast<double>(points.size() / 3) };
  ranks.Sum(counts, 2);
  if (counts[0] > 0.0 && this->ReportsForAll())
  {
    const double* b = region.Bounds;
    vtkWarningMacro(<< counts[0] << " of the surface's " << counts[1]
                    << " points lie nearer to a face of the region the reader read (RegionBounds "
                    << b[0] << " " << b[1] << " " << b[2] << " " << b[3] << " " << b[4] << " "
                    << b[5] << ") than " << (field ? "a kernel support" : "two neighbourhood radii")
                    << ": the particles beyond it were not read, so the surface there is cut or "
                       "moved. Widen the region by a few smoothing lengths.");
  }
}

bool vtkLevelSetIsosurface::MakeSurfaceOutput(vtkPointSet* input,
  const lsi::Neighborhoods& geometry, const lsi::IsopointSet& isopoints,
  const std::vector<double>& nearbyPoints, const lsi::SPHField* field,
  const lsi::PointCloudIndex* surfaceIndex, vtkPolyData* output,
  const std::vector<double>* scalarsInStorageOrder, lsi::KeptCandidates* keptSplats)
{
  const auto start = Clock::now();
  int association = -1;
  vtkDataArray* scalars = this->InputScalars(input, association);
  // Around the seed, the points are moved by whole boxes into the cell centred on it, but the
  // data are sampled where they were found: the images reach only PeriodicMargin past the faces.
  const Internals& internal = *this->Internal;
  const bool aroundSeed = internal.Box.Enabled && this->PeriodicOutput == AROUND_SEED;
  lsi::IsopointSet moved;
  std::vector<double> movedNearby; // the splat radii's neighbours (under MPI every point found)
  std::unique_ptr<lsi::PointCloudIndex> movedIndex; // over movedNearby, which must outlive it
  if (aroundSeed)
  {
    moved = isopoints;
    lsi::IntoCellAround(moved.Points, internal.Box, internal.SeedCenter);
    movedNearby = nearbyPoints;
    lsi::IntoCellAround(movedNearby, internal.Box, internal.SeedCenter);
    movedIndex = lsi::IndexOfPoints(movedNearby);
  }
  vtkNew<vtkPolyData> surface;
  std::vector<double> radii; // (unrounded: the splats' corners are made from them)
  if (!lsi::MakeSurfacePoints(input->GetPointData(), geometry, aroundSeed ? moved : isopoints,
        this->SplatScale, this->InterpolateArrays, scalars ? scalars->GetName() : nullptr, field,
        surface, this->Stage(SurfaceStage), aroundSeed ? movedIndex.get() : surfaceIndex,
        aroundSeed ? &isopoints.Points : nullptr, scalarsInStorageOrder, keptSplats,
        this->OutputType == SPLATS ? &radii : nullptr))
  {
    return false;
  }
  if (this->OutputType == SPLATS)
  {
    // On the SPH field the splats' corners are solved onto the level: where they were found,
    // then moved with their centres.
    vtkNew<vtkPolyData> found;
    found->ShallowCopy(surface);
    if (aroundSeed)
    {
      vtkNew<vtkPoints> at;
      at->SetDataTypeToDouble();
      at->SetNumberOfPoints(static_cast<vtkIdType>(isopoints.Points.size() / 3));
      for (vtkIdType i = 0; i < at->GetNumberOfPoints(); ++i)
      {
        at->SetPoint(i, &isopoints.Points[3 * i]);
      }
      found->SetPoints(at);
    }
    if (!lsi::MakeSplatPolygons(found, this->SplatSides, field, this->IsoValue, output,
          this->Stage(SplatStage), &isopoints.Normals, &radii))
    {
      return false;
    }
    if (aroundSeed)
    {
      lsi::MoveSplatCorners(isopoints.Points, moved.Points, this->SplatSides, output);
    }
  }
  else
  {
    output->ShallowCopy(surface);
    output->SetVerts(lsi::VertexCells(surface->GetNumberOfPoints()));
  }
  this->OutputSeconds = SecondsSince(start);
  return true;
}
