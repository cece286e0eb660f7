// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
// vtkLevelSetIsosurface's re-runs that reuse the last run instead of running the method: after
// a seed move (the same flooded samples: the same outputs) and, with QuickIsoValueChanges,
// after a small isovalue change (the last surface slid onto the new level). Each checks that
// it may, and otherwise returns false: the method then runs in full.
#include "vtkLevelSetIsosurface.h"
#include "vtkLevelSetIsosurfaceInternals.h"

#include "LevelSetFloodAcross.h"
#include "LevelSetInput.h"
#include "LevelSetIsoValueSlide.h"
#include "LevelSetIsopoints.h"
#include "LevelSetPeriodicImages.h"
#include "LevelSetSeedSpheres.h"
#include "LevelSetSurfaceOutput.h"
#include "LevelSetTiming.h"

#include "vtkDataArray.h"
#include "vtkPointData.h"
#include "vtkPointSet.h"
#include "vtkPolyData.h"
#include "vtkSMPTools.h"
#include "vtkTable.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <string>
#include <utility>

namespace
{
// A point whose level lies beyond the refinement's reach strides towards it by its fit's model,
// at most this many reaches (two spacings) per stride: within the fit's samples, which reach
// about 2.3 spacings around where they were gathered. (Against one spacing: the 20% change of
// the interactive benchmark 0.31 s instead of 0.40, its points as near the level and a smaller
// largest gap; three spacings, beyond the samples, gained 0.02 s more.)
constexpr double FarStrides = 4.0;
// A fit's quadratic model stands in for a fit anew within this many reaches (a tenth of a
// spacing) of where it was made: the step that only confirms a point on its fit's zero. (The
// interactive benchmark's 10% change: 44,000 fits instead of 64,500, the slide 0.124 s instead
// of 0.143, its points 0.000634 spacings from the level against 0.000635.)
constexpr double SlideModelReach = 0.2;
} // namespace

// The last run's ranks know its ghosts, which the kept samples hold: a re-run's steps use them
// in place of this run's fresh ranks, whose communication time they add to, until the end of
// the scope.
class vtkLevelSetIsosurface::LastRanksScope
{
public:
  explicit LastRanksScope(Internals& internal)
    : Internal(internal)
    , ThisRuns(internal.Ranks)
  {
    if (internal.LastRanks)
    {
      internal.Ranks = internal.LastRanks.get();
      this->Before = internal.Ranks->CommunicationSeconds;
    }
  }
  ~LastRanksScope()
  {
    if (this->Internal.Ranks != this->ThisRuns)
    {
      this->ThisRuns->CommunicationSeconds +=
        this->Internal.Ranks->CommunicationSeconds - this->Before;
    }
    this->Internal.Ranks = this->ThisRuns;
  }
  LastRanksScope(const LastRanksScope&) = delete;
  LastRanksScope& operator=(const LastRanksScope&) = delete;

private:
  Internals& Internal;
  lsi::Distribution* ThisRuns;
  double Before = 0.0;
};

bool vtkLevelSetIsosurface::LastRanksMatch() const
{
  const Internals& internal = *this->Internal;
  return internal.Ranks->Distributed()
    ? internal.LastRanks && internal.LastRanks->Size == internal.Ranks->Size
    : !internal.LastRanks;
}

vtkMTimeType vtkLevelSetIsosurface::ModifiedAlone(vtkMTimeType alone)
{
  const vtkMTimeType before = this->GetMTime();
  const bool only = before == this->LastRunTime || before == alone;
  this->Modified();
  return only ? this->GetMTime() : 0;
}

void vtkLevelSetIsosurface::SeedsModified()
{
  this->SeedsOnlyTime = this->ModifiedAlone(this->SeedsOnlyTime);
}

void vtkLevelSetIsosurface::SetIsoValue(double value)
{
  if (this->IsoValue == value)
  {
    return;
  }
  this->IsoValue = value;
  this->IsoValueOnlyTime = this->ModifiedAlone(this->IsoValueOnlyTime);
}

vtkDataArray* vtkLevelSetIsosurface::ScalarsOf(vtkPointSet* input)
{
  int association = -1;
  return this->InputScalars(input, association);
}

void vtkLevelSetIsosurface::OutputsModified()
{
  this->OutputsOnlyTime = this->ModifiedAlone(this->OutputsOnlyTime);
}

bool vtkLevelSetIsosurface::RemakeSurfaceOutput(bool onlyOutputsChanged, vtkPointSet* input,
  vtkPolyData* surfaceOutput, vtkPolyData* particleOutput, vtkTable* convergence,
  vtkTable* enclosed)
{
  lsi::LastOutputs& last = this->Internal->Last;
  // Under MPI every rank decides with the others: all remake, or none.
  // (Whatever the start, and under MPI in a periodic box too: the surface needs no flood.)
  const lsi::Neighborhoods* geometry =
    onlyOutputsChanged ? this->LastGeometry(input, false) : nullptr;
  if (!this->Internal->Ranks->All(geometry && this->LastRanksMatch()))
  {
    return false;
  }
  const LastRanksScope lastRanks(*this->Internal);
  const lsi::Distribution& ranks = *this->Internal->Ranks;
  const auto start = lsi::Clock::now();
  vtkPointSet* work = last.Work ? last.Work.GetPointer() : input;
  // On the SPH field the arrays are its interpolants.
  std::unique_ptr<lsi::SPHField> rebuilt;
  const lsi::SPHField* field = this->LastSPHField(input, *geometry, rebuilt);
  if (!ranks.All(!last.OnField || field))
  {
    return false;
  }
  // (Under MPI the splat radii come from every point this rank found, as in a full run.)
  const std::vector<double>& nearby = last.NearbyPoints(ranks.Distributed());
  const std::unique_ptr<lsi::PointCloudIndex> nearbyIndex = lsi::IndexOfPoints(nearby);
  last.Valid = false; // until the surface is made
  if (!ranks.All(this->MakeSurfaceOutput(work, *geometry, last.ShownPoints(), nearby, field,
        nearbyIndex.get(), surfaceOutput, last.ScalarsInStorageOrder(), last.SplatsIfKept())))
  {
    return false;
  }
  particleOutput->ShallowCopy(last.Particles);
  convergence->ShallowCopy(last.Convergence);
  enclosed->ShallowCopy(last.Enclosed);
  last.Remember(surfaceOutput, particleOutput, convergence, enclosed);
  this->NumberOfIterationsPerformed = last.Iterations;
  this->Converged = last.Converged;
  this->GhostFraction = last.GhostFraction;
  this->NeighborSearchSeconds = this->InitializationSeconds = this->EvolutionSeconds =
    this->IsopointSeconds = this->CompletionSeconds = this->DataRefinementSeconds =
      this->InputSeconds = this->ParticleOutputSeconds = 0.0;
  this->OutputSeconds = lsi::SecondsSince(start);
  this->RemadeSurfaceOutput = true;
  this->LastRunTime = this->GetMTime();
  return true;
}

const lsi::SPHField* vtkLevelSetIsosurface::LastSPHField(
  vtkPointSet* input, const lsi::Neighborhoods& geometry, std::unique_ptr<lsi::SPHField>& rebuilt)
{
  const lsi::LastOutputs& last = this->Internal->Last;
  if (last.OnField && !last.Field)
  {
    rebuilt = this->RebuildSPHField(last.Work ? last.Work.GetPointer() : input, geometry);
  }
  return last.Field ? last.Field.get() : rebuilt.get();
}

std::unique_ptr<lsi::SPHField> vtkLevelSetIsosurface::RebuildSPHField(
  vtkPointSet* work, const lsi::Neighborhoods& geometry)
{
  // The last run's choices (arrays, kernel, support) from the same request on the same
  // particles, and f as the method read it (ghosts and images carry their originals' arrays):
  // the same field, without its checks' messages (they were given).
  int association = -1;
  vtkDataArray* scalars = this->InputScalars(work, association);
  std::vector<double> values;
  double range[2];
  lsi::SPHFieldArrays arrays;
  std::string choice;
  std::string problem = lsi::CheckPiece(work, scalars, association, values, range);
  if (!problem.empty() || values.size() != geometry.NumberOfSamples ||
    !lsi::FindSPHArrays(work, scalars, this->SPHRequest(), arrays, problem, choice) ||
    !problem.empty())
  {
    return nullptr;
  }
  std::unique_ptr<lsi::SPHField> field(new lsi::SPHField(geometry, arrays, values, problem));
  return field->Valid() ? std::move(field) : nullptr;
}

const lsi::Neighborhoods* vtkLevelSetIsosurface::LastGeometry(vtkPointSet* input, bool withFlood)
{
  const lsi::LastOutputs& last = this->Internal->Last;
  // (Under MPI a rank's piece may be empty, without points: its samples are in last.Work.)
  if (!last.Valid || !last.SurfaceReady || input != last.Input ||
    !(last.Work || input->GetPoints()) ||
    (withFlood && (!last.QuickCheck || this->Initialization != FLOOD)) ||
    !(lsi::InputStamp::Of(input, this->ScalarsOf(input)) == last.Stamp))
  {
    return nullptr;
  }
  // (Looked up, never searched: one not cached, after a change of NumberOfNeighbors say, would
  // only be thrown away.)
  vtkPoints* points = last.Work ? last.Work->GetPoints() : input->GetPoints();
  const lsi::Neighborhoods* geometry = this->Internal->Cache.Find(points, this->NumberOfNeighbors);
  return geometry && (!withFlood || geometry->NumberOfSamples == last.Inside.size()) ? geometry
                                                                                     : nullptr;
}

lsi::SlideResult vtkLevelSetIsosurface::SlideLastPoints(const lsi::Neighborhoods& geometry,
  const std::vector<double>& dataOffsets, const std::vector<char>& inside, bool& aborted)
{
  lsi::LastOutputs& last = this->Internal->Last;
  const lsi::IsopointSettings& settings = last.Settings;
  const double isoValue = this->IsoValue;
  lsi::SlideSettings slide;
  slide.MaximumMove = settings.DataMaximumMove;
  slide.FarMove = FarStrides * settings.DataMaximumMove;
  slide.Drift = &last.Drift;
  slide.Iterations = settings.DataIterations;
  slide.Tolerance = lsi::DataConvergedStep * settings.DataMaximumMove;
  slide.ModelReach = SlideModelReach * settings.DataMaximumMove;
  slide.Quadratic = settings.DataFitOrder == 2;
  slide.ValueChange = isoValue - last.IsoValue;
  lsi::IsopointSet& isopoints = last.Isopoints;
  std::vector<double>& centres = last.FitCentres;
  lsi::SlideResult slid;
  if (isopoints.Points.empty())
  {
    // (Under MPI a rank may hold no surface: nothing to slide. Surface that would appear here
    // leaves changed samples far from any point: the flood's check below refuses.)
    slid.Accepted = true;
  }
  else if (last.Field)
  {
    // The free boundary's points (last in the set) are shot anew from the new inside's edge of
    // the cloud, as the method does; the others slide.
    const std::size_t kept = isopoints.Points.size() - 3 * isopoints.FreeBoundaryCount;
    isopoints.Points.resize(kept);
    isopoints.Normals.resize(kept);
    isopoints.FreeBoundaryCount = 0;
    slid = lsi::SlideIsopointsOnSPHField(geometry, *last.Field, isoValue, inside, last.Inside,
      settings, slide.Drift, isopoints, this->Stage(lsi::IsopointStage));
    aborted = slid.Accepted &&
      !lsi::AddFreeBoundaryPoints(geometry, *last.Field, isoValue, inside, dataOffsets, settings,
        isopoints, this->Stage(lsi::IsopointStage));
  }
  else
  {
    slid = lsi::SlideIsopoints(
      geometry, dataOffsets, inside, slide, isopoints, centres, this->Stage(lsi::IsopointStage));
  }
  return slid;
}

bool vtkLevelSetIsosurface::AcceptSlide(const lsi::Neighborhoods& geometry,
  const std::vector<char>& inside, const lsi::SlideResult& slid,
  const lsi::PointCloudIndex* surfaceIndex, std::vector<char>& keptPoints, double& largestMove)
{
  const lsi::LastOutputs& last = this->Internal->Last;
  const lsi::Distribution& ranks = *this->Internal->Ranks;
  const lsi::IsopointSettings& settings = last.Settings;
  const lsi::IsopointSet& isopoints = last.Isopoints;
  const std::size_t pointCount = isopoints.Points.size() / 3;
  std::size_t changed = 0;
  // Under MPI only the owned samples count (each rank checks its own), and the largest move is
  // the ranks' largest.
  const vtkIdType counted = this->Internal->Box.Enabled
    ? this->Internal->OriginalCount
    : (ranks.Distributed() ? ranks.OwnedCount : VTK_ID_MAX);
  // The points the ranks keep (under MPI each keeps those nearest its own samples: together the
  // serial run's points; its others, towards its halo's edge, may have slid on cut
  // neighbourhoods): the LevelSet shift is capped by their largest move, and only they are
  // checked against the samples beyond the band.
  double keptLargestMove = slid.LargestMove();
  if (ranks.Distributed())
  {
    keptLargestMove = 0.0;
    keptPoints.resize(pointCount);
    for (std::size_t i = 0; i < pointCount; ++i)
    {
      keptPoints[i] = lsi::OwnsNearestSample(geometry, ranks, &isopoints.Points[3 * i]);
      if (keptPoints[i])
      {
        keptLargestMove = std::max(keptLargestMove, slid.Moves[i]);
      }
    }
  }
  largestMove = ranks.Max(keptLargestMove);
  // (A rank without points, whose index is null, accepts only if none of its samples changed.)
  const bool changesNear = slid.Accepted &&
    lsi::FloodChangesNearPoints(geometry, last.Inside, inside, surfaceIndex, slid.Moves,
      2.0 * settings.CellSize, changed, counted);
  // (The surface lies within about half its points' spacing of them: one cell is the margin.)
  const bool clampedClear = changesNear &&
    lsi::ClampedSamplesClear(geometry, last.Phi, last.Drift.HalfWidth, isopoints.Points,
      slid.NearBandEdge, ranks.Distributed() ? &keptPoints : nullptr, settings.CellSize);
  const bool accepted = ranks.All(clampedClear);
  vtkDebugMacro(<< "quick isovalue change: " << (accepted ? "accepted" : "refused")
                << (!slid.Accepted    ? ": " + slid.Refusal
                       : !changesNear ? std::string(": samples changed sides away from the points")
                       : !clampedClear
                       ? std::string(": a sample beyond the band would lie within a shell width")
                       : std::string())
                << "; largest move " << largestMove << ", " << changed << " samples changed sides");
  return accepted;
}

void vtkLevelSetIsosurface::KeepForSlides(vtkPointSet* work, const lsi::Neighborhoods& geometry,
  const std::vector<double>& values, const std::vector<double>& dataOffsets,
  std::unique_ptr<lsi::SPHField>& field, std::vector<double>& phi, lsi::IsopointSet& found,
  const lsi::IsopointSettings& settings, double halfWidth)
{
  lsi::LastOutputs& last = this->Internal->Last;
  lsi::ResizeMapped(last.Values, dataOffsets.size());
  const double isoValue = this->IsoValue;
  const bool onField = field != nullptr;
  vtkSMPTools::For(0, static_cast<vtkIdType>(dataOffsets.size()),
    lsi::BalancedGrain(dataOffsets.size(), 16384), [&](vtkIdType begin, vtkIdType end) {
      for (vtkIdType i = begin; i < end; ++i)
      {
        // On the SPH field, the field at the samples (to rounding): what the flood uses.
        last.Values[i] = onField ? dataOffsets[i] + isoValue : values[geometry.Order[i]];
      }
    });
  // (Read by the interpolation of a later slide or output change: the same numbers.)
  int association = -1;
  vtkDataArray* scalars = this->InputScalars(work, association);
  last.ValuesAreScalars = !onField && scalars && scalars->GetName() &&
    lsi::SameValuesInStorageOrder(
      work->GetPointData()->GetArray(scalars->GetName()), geometry, last.Values);
  last.Field = std::move(field);
  last.IsoValue = this->IsoValue;
  last.Phi = std::move(phi);
  last.Isopoints = std::move(found);
  last.Settings = settings;
  last.Drift.Reset(last.Isopoints.Points, halfWidth);
  // The data's gradient over the band, which a slide's LevelSet shift reads (kept: later
  // slides compute only the samples they bring into the band).
  lsi::GradientsInBand(
    geometry, last.Values, halfWidth, last.Phi, last.BandCandidates(geometry), &last.NearGradients);
}

bool vtkLevelSetIsosurface::FloodFromSeeds(const lsi::Neighborhoods& geometry,
  const std::vector<double>& dataOffsets, const lsi::SPHField* field, std::vector<char>& inside)
{
  // Seeds the method would refuse go the long way, which reports them.
  std::vector<std::pair<const char*, double>> seedNumbers = {
    { "SeedCenter[0]", this->SeedCenter[0] }, { "SeedCenter[1]", this->SeedCenter[1] },
    { "SeedCenter[2]", this->SeedCenter[2] }, { "SeedRadius", this->SeedRadius }
  };
  for (double value : this->AdditionalSeeds)
  {
    seedNumbers.emplace_back("AdditionalSeeds", value);
  }
  if (this->AdditionalSeeds.size() % 4 != 0 || !lsi::NonFiniteParameter(seedNumbers).empty() ||
    !lsi::CheckSeedRadii(this->AdditionalSeeds).empty())
  {
    return false;
  }
  // (The points are the last run's: so are their bounds, and with the same spheres the samples
  // in them.) Under MPI the samples are the last run's on this rank, with its ghosts, and so
  // are the ranks that trade them (LastRanksScope).
  lsi::LastOutputs& last = this->Internal->Last;
  const Internals& internal = *this->Internal;
  const lsi::Distribution& ranks = *internal.Ranks;
  const std::vector<double> spheres =
    lsi::SeedSpheres(this->SeedCenter, this->SeedRadius, this->AdditionalSeeds, last.Bounds);
  if (spheres != last.SeedSpheres || last.InSeed.size() != geometry.NumberOfSamples)
  {
    std::vector<double> seedDistance;
    lsi::SeedSphereStart seeds = lsi::SeedSphereDistance(
      geometry, spheres, last.Bounds, 0.5 * last.Spacing, seedDistance, ranks);
    if (!lsi::CheckSeedSpheres(spheres, seeds.SamplesPerSphere).empty())
    {
      return false;
    }
    last.SeedSpheres = spheres;
    last.InSeed = std::move(seeds.InSeed);
  }
  // As the method floods (FloodComponent), which adds seeds across a periodic box's faces and
  // the ranks. (Copied only where it may: the last run's seeds stay as they were.)
  const bool addsSeeds = internal.Box.Enabled || ranks.Distributed();
  std::vector<char> added = addsSeeds ? last.InSeed : std::vector<char>();
  std::vector<char>& inSeed = addsSeeds ? added : last.InSeed;
  double seedSamples = 0.0;
  if (!this->FloodComponent(geometry, dataOffsets, field, inSeed, inside, seedSamples))
  {
    return false; // aborted
  }
  if (ranks.Distributed())
  {
    // The ghosts' sides are their owners' (as the method's ghosts' phi is).
    std::vector<double> insideAtOwner(inside.begin(), inside.end());
    ranks.RefreshGhosts(insideAtOwner);
    std::copy(insideAtOwner.begin(), insideAtOwner.end(), inside.begin());
  }
  return seedSamples > 0.0;
}

bool vtkLevelSetIsosurface::SameKeptCell() const
{
  // The cell centred on the main seed moves with it (as Initialize places it).
  const lsi::PeriodicBox& box = this->Internal->Box;
  if (!box.Enabled || this->PeriodicOutput != AROUND_SEED)
  {
    return true;
  }
  double center[3];
  lsi::KeptCellCenter(this->Internal->Last.SeedSpheres, box, center);
  return std::equal(center, center + 3, this->Internal->SeedCenter);
}

bool vtkLevelSetIsosurface::ReuseAfterSeedMove(bool onlySeedsChanged, vtkPointSet* input,
  vtkPolyData* surfaceOutput, vtkPolyData* particleOutput, vtkTable* convergence,
  vtkTable* enclosed)
{
  lsi::LastOutputs& last = this->Internal->Last;
  // Under MPI every rank decides with the others: all hand on their outputs, or none.
  const lsi::Neighborhoods* geometry =
    onlySeedsChanged && last.Valid ? this->LastGeometry(input) : nullptr;
  if (!this->Internal->Ranks->All(geometry && this->LastRanksMatch()))
  {
    return false;
  }
  const LastRanksScope lastRanks(*this->Internal);
  const lsi::Distribution& ranks = *this->Internal->Ranks;
  // (The isovalue and the data are those of the last run, which checked them.) On the SPH field
  // the flood reads it between samples.
  std::unique_ptr<lsi::SPHField> rebuilt;
  const lsi::SPHField* field = this->LastSPHField(input, *geometry, rebuilt);
  if (!ranks.All(!last.OnField || field))
  {
    return false;
  }
  std::vector<char> inside;
  const bool flooded = this->FloodFromSeeds(*geometry, last.DataOffsets, field, inside);
  if (!ranks.All(flooded && inside == last.Inside && this->SameKeptCell()))
  {
    return false;
  }
  last.Restore(surfaceOutput, particleOutput, convergence, enclosed);
  this->NumberOfIterationsPerformed = last.Iterations;
  this->Converged = last.Converged;
  this->GhostFraction = last.GhostFraction;
  this->ReusedLastOutputs = true;
  this->NeighborSearchSeconds = this->InitializationSeconds = this->EvolutionSeconds =
    this->IsopointSeconds = this->CompletionSeconds = this->DataRefinementSeconds =
      this->OutputSeconds = this->InputSeconds = this->ParticleOutputSeconds = 0.0;
  this->LastRunTime = this->GetMTime();
  return true;
}

bool vtkLevelSetIsosurface::SlideAfterIsoValueChange(bool onlyIsoValueChanged, vtkPointSet* input,
  vtkPolyData* surfaceOutput, vtkPolyData* particleOutput, vtkTable* convergence,
  vtkTable* enclosed)
{
  lsi::LastOutputs& last = this->Internal->Last;
  // Under MPI every rank decides with the others: all slide, or none.
  const lsi::Neighborhoods* geometry = onlyIsoValueChanged ? this->LastGeometry(input) : nullptr;
  if (!this->Internal->Ranks->All(geometry && this->LastRanksMatch() && last.SlideReady &&
        this->QuickIsoValueChanges && this->DataRefinement && std::isfinite(this->IsoValue)))
  {
    vtkDebugMacro(<< "quick isovalue change: not possible here (the last run kept no surface "
                     "to slide, or the input or the method changed)");
    return false;
  }
  const LastRanksScope lastRanks(*this->Internal);
  const lsi::Distribution& ranks = *this->Internal->Ranks;
  // The last run's state is worked on in place (no copies of the data offsets, of phi and of
  // the points' kept samples): a refused slide returns false, and the method then runs in full
  // and rewrites it.
  last.Valid = false; // until this re-run succeeds
  // The data offsets at the new isovalue, as the method computes them (DataInStorageOrder).
  // (The last run's are not needed any more: the flood's check compares the flooded samples.)
  auto start = lsi::Clock::now();
  const double isoValue = this->IsoValue;
  std::vector<double>& dataOffsets = last.DataOffsets;
  dataOffsets.resize(last.Values.size());
  vtkSMPTools::For(0, static_cast<vtkIdType>(dataOffsets.size()),
    lsi::BalancedGrain(dataOffsets.size(), 16384), [&](vtkIdType begin, vtkIdType end) {
      for (vtkIdType i = begin; i < end; ++i)
      {
        dataOffsets[i] = last.Values[i] - isoValue;
      }
    });
  const double inputSeconds = lsi::SecondsSince(start);
  start = lsi::Clock::now();
  std::vector<char> inside;
  // (A slide needs SlideReady, with which a run on the SPH field kept it: KeepForSlides.)
  if (!this->FloodFromSeeds(
        *geometry, dataOffsets, last.Field.get(), inside)) // (decided with the other ranks)
  {
    vtkDebugMacro(<< "quick isovalue change: refused, the seeds flood nothing");
    return false;
  }
  const double floodSeconds = lsi::SecondsSince(start);
  start = lsi::Clock::now();
  lsi::IsopointSet& isopoints = last.Isopoints;
  bool aborted = false;
  lsi::SlideResult slid = this->SlideLastPoints(*geometry, dataOffsets, inside, aborted);
  if (!ranks.All(!aborted))
  {
    return false;
  }
  // A sample that changed sides lies between the old and the new level: within the way there
  // and the points' spacing (two cells) of a slid point. (The free boundary's points, shot
  // anew along the cloud's edge, count as moved the most, and as away from the band's edge.)
  const std::size_t pointCount = isopoints.Points.size() / 3;
  slid.Moves.resize(pointCount, slid.LargestMove());
  slid.NearBandEdge.resize(pointCount, 0);
  // One search index over the slid points, for this check, the splat radii and the Enclosed
  // table.
  const std::unique_ptr<lsi::PointCloudIndex> surfaceIndex =
    slid.Accepted ? lsi::IndexOfPoints(isopoints.Points) : nullptr;
  std::vector<char> keptPoints;
  double largestMove = 0.0;
  if (!this->AcceptSlide(*geometry, inside, slid, surfaceIndex.get(), keptPoints, largestMove))
  {
    return false;
  }
  // From here on the outputs are this run's.
  std::vector<double>& phi = last.Phi;
  // (The band lies among the kept deep inside's near samples, where it was found.)
  const std::vector<std::size_t> changedSamples =
    lsi::ShiftLevelSet(*geometry, last.Values, isoValue - last.IsoValue, last.Drift.HalfWidth,
      largestMove, phi, last.BandCandidates(*geometry), &last.NearGradients);
  ranks.RefreshGhosts(phi); // (a ghost's stencil may be cut: its owner's value is the serial one)
  // In a periodic box the outputs show the kept cell's points, with a search index of their
  // own, and the particles' arrays are the images' too.
  vtkPointSet* work = last.Work ? last.Work.GetPointer() : input;
  const lsi::IsopointSet* shown = &isopoints;
  const lsi::PointCloudIndex* shownIndex = surfaceIndex.get();
  lsi::IsopointSet cut, inCell;
  std::unique_ptr<lsi::PointCloudIndex> cutIndex, inCellIndex;
  // Under MPI each rank shows the points nearest its own particles (KeepOwnedIsopoints): those
  // marked kept above (a slide under MPI has no periodic box to cut first).
  if (this->Internal->Box.Enabled || ranks.Distributed())
  {
    cut = isopoints;
    this->KeepPeriodicCell(cut);
    if (ranks.Distributed() && this->Internal->Box.Enabled)
    {
      // (The splat radii's points: those this rank found in the cell, as in a full run.)
      inCell.Points = cut.Points;
      inCell.Normals = cut.Normals;
      inCellIndex = lsi::IndexOfPoints(inCell.Points);
    }
    if (ranks.Distributed() && !this->Internal->Box.Enabled)
    {
      lsi::KeepSelected(cut, lsi::ValidIndices(keptPoints));
    }
    else
    {
      this->KeepOwnedIsopoints(*geometry, cut);
    }
    cutIndex = lsi::IndexOfPoints(cut.Points);
    shown = &cut;
    shownIndex = cutIndex.get();
  }
  this->IsopointSeconds = lsi::SecondsSince(start);
  this->WarnIfRegionCut(input, *geometry, last.Field.get(), shown->Points);
  // (Under MPI the splat radii come from every point this rank found, as in a full run; the
  // Enclosed table's distances from every rank's kept points: MakeParticleOutputs.)
  const bool nearbyInCell = ranks.Distributed() && this->Internal->Box.Enabled;
  const lsi::IsopointSet& nearby =
    nearbyInCell ? inCell : (ranks.Distributed() ? isopoints : *shown);
  const lsi::PointCloudIndex* nearbyIndex =
    nearbyInCell ? inCellIndex.get() : (ranks.Distributed() ? surfaceIndex.get() : shownIndex);
  if (!ranks.All(this->MakeSurfaceOutput(work, *geometry, *shown, nearby.Points, last.Field.get(),
        nearbyIndex, surfaceOutput, last.ScalarsInStorageOrder(), last.SplatsIfKept())))
  {
    return false;
  }
  start = lsi::Clock::now();
  // (Under MPI the particles are the rank's own, as the last run spread them.)
  vtkPointSet* particles = last.Owned ? last.Owned.GetPointer() : input;
  this->MakeParticleOutputs(particles, work, *geometry, phi, std::vector<vtkIdType>(),
    last.Drift.HalfWidth, *shown, nearbyIndex, particleOutput, enclosed, nullptr, &last.DeepInside,
    &changedSamples);
  convergence->ShallowCopy(last.Convergence); // the evolution that placed the slid surface
  this->ParticleOutputSeconds = lsi::SecondsSince(start);
  if (!ranks.All(!this->CheckAbort()))
  {
    return false;
  }
  this->NumberOfIsopoints =
    static_cast<vtkIdType>(ranks.Sum(static_cast<double>(shown->Points.size() / 3)));
  this->NumberOfIterationsPerformed = last.Iterations;
  this->Converged = last.Converged;
  this->SlidLastSurface = true;
  this->GhostFraction = last.GhostFraction;
  this->NeighborSearchSeconds = this->EvolutionSeconds = this->CompletionSeconds = 0.0;
  this->DataRefinementSeconds = this->IsopointSeconds;
  this->InputSeconds = inputSeconds;
  this->InitializationSeconds = floodSeconds;
  // The state the next re-run starts from.
  // (The data offsets, phi, the points and their fits' centres are this run's already.)
  last.Remember(surfaceOutput, particleOutput, convergence, enclosed);
  last.Inside = std::move(inside);
  last.IsoValue = isoValue;
  // Each point's bound for the next slide; the free boundary's new points (shot from the new
  // inside's edge, no origin) are bound by the farthest slid point.
  const double farthest =
    slid.Bounds.empty() ? 0.0 : *std::max_element(slid.Bounds.begin(), slid.Bounds.end());
  const std::size_t slidCount = slid.Bounds.size();
  last.Drift.Bounds = std::move(slid.Bounds);
  last.Drift.Bounds.resize(pointCount, farthest);
  last.Drift.Origins.resize(3 * slidCount); // (the last free boundary's origins are not these)
  last.Drift.Origins.resize(3 * pointCount, std::numeric_limits<double>::quiet_NaN());
  // (The points shown, for a change of the surface output's properties alone: the slid ones,
  // or the cell or rank's cut of them.)
  last.ShownAreIsopoints = shown == &isopoints;
  last.Shown = last.ShownAreIsopoints ? lsi::IsopointSet() : std::move(cut);
  last.NearbyAreIsopoints = ranks.Distributed() && !nearbyInCell;
  last.Nearby = nearbyInCell ? std::move(inCell.Points) : std::vector<double>();
  this->LastRunTime = this->GetMTime();
  return true;
}
