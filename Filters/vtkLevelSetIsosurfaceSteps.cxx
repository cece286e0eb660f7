// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
// vtkLevelSetIsosurface's steps of the method (vtkLevelSetIsosurface.h lists them): the
// neighbours, the settings from the data's scales, the start (seed spheres or the flood with its
// signed distances), the SPH field, the evolution and the isopoints.
#include "vtkLevelSetIsosurface.h"
#include "vtkLevelSetIsosurfaceInternals.h"

#include "LevelSetConvergenceTable.h"
#include "LevelSetDistribution.h"
#include "LevelSetEvolution.h"
#include "LevelSetFlood.h"
#include "LevelSetFloodAcross.h"
#include "LevelSetFloodOnField.h"
#include "LevelSetInput.h"
#include "LevelSetIsopoints.h"
#include "LevelSetLastOutputs.h"
#include "LevelSetNeighborCache.h"
#include "LevelSetParameters.h"
#include "LevelSetPeriodicImages.h"
#include "LevelSetSPHField.h"
#include "LevelSetSPHFieldChecks.h"
#include "LevelSetSeedSpheres.h"
#include "LevelSetTiming.h"

#include "vtkDataArray.h"
#include "vtkPointSet.h"
#include "vtkTable.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace
{
using lsi::Clock;
using lsi::EvolutionStage;
using lsi::InitializationStage;
using lsi::IsopointStage;
using lsi::NeighborStage;
using lsi::SecondsSince;
} // namespace

const lsi::Neighborhoods* vtkLevelSetIsosurface::FindNeighborhoods(
  vtkPoints* points, bool duplicatesAllowed)
{
  if (this->ProgressOrAbort(NeighborStage[0]))
  {
    return nullptr;
  }
  const auto start = Clock::now();
  bool searched = false;
  const lsi::Neighborhoods* geometry = this->Internal->Cache.Get(points, this->NumberOfNeighbors,
    static_cast<std::size_t>(this->NeighborCacheSize), this->Stage(NeighborStage), searched);
  if (!geometry)
  {
    return nullptr;
  }
  // This run's time: the search's, or only the cache lookup's when the cache had them.
  this->NeighborSearchCount += searched ? 1 : 0;
  this->NeighborSearchSeconds = SecondsSince(start);
  this->SpatialSortSeconds = searched ? geometry->SortSeconds : 0.0;
  this->NearestNeighborSeconds = searched ? geometry->SearchSeconds : 0.0;
  this->TreeBuildSeconds = searched ? geometry->TreeSeconds : 0.0;
  // Every length is relative, but volumes (cubes of lengths, summed over the particles) must
  // still fit a double: refuse neighbourhood radii beyond 1e+-90 in the data's unit.
  if (!(geometry->MeanRadius > 1e-90 && geometry->MeanRadius < 1e90))
  {
    vtkErrorMacro("The particles' neighbourhood radius is "
      << geometry->MeanRadius
      << " in the data's unit of length, outside the range 1e-90 to 1e90 in which volumes (its "
         "cube, summed over the particles) fit a double: rescale the coordinates (for example "
         "with Transform).");
    return nullptr;
  }
  // Duplicates are merged by the caller (MergeDuplicates), then searched again.
  const std::string problem = lsi::CheckNeighborhoods(*geometry);
  if (!problem.empty() && !(duplicatesAllowed && geometry->DuplicateSamples > 0))
  {
    vtkErrorMacro(<< problem);
    return nullptr;
  }
  // Lists are computed as the method visits them; under MPI also those that the halo's reach
  // (HaloReachBox) and the ghosts it cuts (Distribution::Attach) need, and in a periodic box
  // those of the samples near the images' edge (SamplesBeyondImages).
  return this->ProgressOrAbort(NeighborStage[1]) ? nullptr : geometry;
}

lsi::EvolutionSettings vtkLevelSetIsosurface::ChooseEvolutionSettings(
  const lsi::SurfaceScale& scale)
{
  lsi::EvolutionSettings settings =
    lsi::ChooseEvolutionSettings(this->RequestedParameters(), scale);
  for (const std::string& concern : lsi::EvolutionConcerns(
         this->RequestedParameters(), scale, settings, this->Initialization == SEED_SPHERES))
  {
    if (this->ReportsForAll())
    {
      vtkWarningMacro(<< concern);
    }
  }
  this->MeanSampleSpacing = scale.Spacing;
  this->EffectiveEpsilon = settings.Coefficients.Epsilon;
  this->EffectiveCurvatureEpsilon = settings.Coefficients.CurvatureEpsilon;
  this->EffectiveTimeStep = settings.Coefficients.TimeStep;
  return settings;
}

lsi::RequestedParameters vtkLevelSetIsosurface::RequestedParameters() const
{
  lsi::RequestedParameters requested;
  requested.Epsilon = this->Epsilon;
  requested.CurvatureEpsilon = this->CurvatureEpsilon;
  requested.TimeStep = this->TimeStep;
  requested.CurvatureWeight = this->CurvatureWeight;
  requested.DistanceRegularization = this->DistanceRegularization;
  requested.Method = static_cast<lsi::Scheme>(this->EvolutionScheme);
  requested.ReinitializationSteps = this->ReinitializationSteps;
  requested.MaximumIterations = this->MaximumNumberOfIterations;
  requested.ConvergenceTolerance = this->ConvergenceTolerance;
  requested.Completion = this->Completion;
  requested.DataRefinement = this->DataRefinement;
  return requested;
}

bool vtkLevelSetIsosurface::Initialize(vtkPointSet* input, const lsi::Neighborhoods& geometry,
  const std::vector<double>& dataOffsets, const lsi::SPHField* field,
  const lsi::EvolutionSettings& settings, std::vector<double>& phi)
{
  const auto start = Clock::now();
  // (Its loops check for abort without reporting progress: the stage's start is reported here,
  // not checked, so that every rank goes on alike.)
  this->UpdateProgress(InitializationStage[0]);
  const lsi::Distribution& ranks = *this->Internal->Ranks;
  double bounds[6];
  this->Bounds(input, bounds);
  const std::vector<double> spheres =
    lsi::SeedSpheres(this->SeedCenter, this->SeedRadius, this->AdditionalSeeds, bounds);
  lsi::KeptCellCenter(spheres, this->Internal->Box, this->Internal->SeedCenter);
  // The same flood as the last run's (after a change of CurvatureWeight, say): start from its
  // level set.
  lsi::LastOutputs& last = this->Internal->Last;
  lsi::FloodStart flood;
  if (this->Initialization == FLOOD)
  {
    flood.Samples = geometry.BuildNumber;
    flood.Offsets = lsi::ValueFingerprint(dataOffsets);
    flood.Spheres = spheres;
    flood.HalfWidth = lsi::ReinitializationHalfWidth(settings);
    flood.Spacing = settings.Spacing;
    if (ranks.All(last.Start.SameStart(flood) && last.Start.Phi.size() == geometry.NumberOfSamples))
    {
      phi.assign(last.Start.Phi.begin(), last.Start.Phi.end());
      last.SeedSpheres = spheres;
      std::copy(bounds, bounds + 6, last.Bounds);
      last.InSeed = last.Start.InSeed;
      this->InitializationSeconds = SecondsSince(start);
      return true;
    }
  }
  const lsi::SeedSphereStart seeds =
    lsi::SeedSphereDistance(geometry, spheres, bounds, 0.5 * settings.Spacing, phi, ranks);
  const std::string problem = lsi::CheckSeedSpheres(spheres, seeds.SamplesPerSphere);
  if (!problem.empty())
  {
    if (this->ReportsForAll())
    {
      vtkErrorMacro(<< problem);
    }
    return false;
  }
  if (this->Initialization == FLOOD)
  {
    // (The seeds, for quick re-runs.)
    last.SeedSpheres = spheres;
    std::copy(bounds, bounds + 6, last.Bounds);
    last.InSeed = seeds.InSeed;
    std::vector<char> inSeed = seeds.InSeed, inside;
    double seedSamples = 0.0;
    if (!this->FloodComponent(geometry, dataOffsets, field, inSeed, inside, seedSamples))
    {
      return false;
    }
    if (seedSamples == 0.0 && this->ReportsForAll())
    {
      vtkErrorMacro("No sample inside the seed sphere(s) has a value above IsoValue "
        << this->IsoValue << ": there is nothing to flood. Move the seed into the object.");
    }
    if (seedSamples == 0.0)
    {
      return false;
    }
    // The distances to the component's crossings: once, however many rounds the flood took.
    if (!ranks.All(lsi::SignedDistanceToCrossings(geometry, dataOffsets, inside,
          lsi::ReinitializationHalfWidth(settings), phi, this->Stage(InitializationStage))))
    {
      return false;
    }
    ranks.RefreshGhosts(phi); // the owners' distances are the serial ones
    flood.Phi = lsi::CopiedInParallel(phi);
    flood.InSeed = last.InSeed;
    last.Start = std::move(flood);
    ++this->FloodCount;
  }
  this->InitializationSeconds = SecondsSince(start);
  return true;
}

bool vtkLevelSetIsosurface::FloodComponent(const lsi::Neighborhoods& geometry,
  const std::vector<double>& dataOffsets, const lsi::SPHField* field, std::vector<char>& inSeed,
  std::vector<char>& inside, double& seedSamples)
{
  // Each rank floods its samples and ghosts, across the periodic box's faces and the ranks:
  // the component is then the serial one.
  const Internals& internal = *this->Internal;
  const std::vector<vtkIdType> original = internal.Box.Enabled
    ? lsi::OriginalIds(geometry, internal.OriginalCount, internal.ImageOf)
    : std::vector<vtkIdType>();
  // On the SPH field, not across its dips between neighbours (LevelSetFloodOnField.h).
  const lsi::FloodEdgeCheck mayCross = field
    ? lsi::FieldStaysAboveBetween(geometry, *field, dataOffsets, this->IsoValue)
    : lsi::FloodEdgeCheck();
  return lsi::FloodAcross(geometry, *internal.Ranks, original, internal.OriginalCount, dataOffsets,
    inSeed, inside, seedSamples, this->Stage(InitializationStage), mayCross);
}

bool vtkLevelSetIsosurface::BuildSPHField(vtkPointSet* input, const lsi::Neighborhoods& geometry,
  const std::vector<double>& values, std::unique_ptr<lsi::SPHField>& field)
{
  this->UsedSPHField = false;
  const lsi::SPHFieldRequest request = this->SPHRequest();
  int association = -1;
  vtkDataArray* scalars = this->InputScalars(input, association);
  lsi::SPHFieldArrays arrays;
  std::string problem, choice;
  const bool sph = lsi::FindSPHArrays(input, scalars, request, arrays, problem, choice);
  if (!problem.empty())
  {
    vtkErrorMacro(<< problem);
    return false;
  }
  vtkDebugMacro(<< choice);
  if (!sph)
  {
    // A snapshot's particles (the reader marked their densities and masses) without smoothing
    // lengths: the simulation's field is not known, and a fit of the samples stands in for it.
    const bool snapshot = !lsi::MarkedArrayName(input, "DensityArray").empty() &&
      !lsi::MarkedArrayName(input, "MassArray").empty();
    if (request.Model == 0 && !arrays.SmoothingLength && snapshot && this->ReportsForAll())
    {
      vtkWarningMacro("The particles carry densities and masses but no smoothing lengths (an "
                      "AREPO snapshot; a Tipsy file without its SNAPSHOT.smoothlength, hsmooth "
                      "being the softening), so the simulation's SPH field is not known: using "
                      "the MLS fit of the samples. Name the smoothing lengths "
                      "(SmoothingLengthArray), or make them with Particle Density "
                      "(NumberOfNeighbors: the run's neighbour number, nSmooth for ChaNGa and "
                      "Gasoline).");
    }
    return true;
  }
  if (!arrays.UnknownKernel.empty() && this->ReportsForAll())
  {
    vtkWarningMacro("The input names the SPH kernel '"
      << arrays.UnknownKernel
      << "', which is none of the cubic, quartic and quintic splines and Wendland C2, C4 and C6: "
         "using the cubic spline. Set Kernel to the simulation's kernel.");
  }
  field.reset(new lsi::SPHField(geometry, arrays, values, problem));
  if (!field->Valid())
  {
    vtkErrorMacro(<< problem);
    field.reset();
    return false;
  }
  // Placeholder smoothing lengths (some files carry a constant or stale column) do not describe
  // these particles: a support far below the neighbourhood radius leaves most of space empty.
  const lsi::Distribution& ranks = *this->Internal->Ranks;
  // (Both checks measure at the same samples: found once.)
  const std::vector<std::uint32_t> nextToSurface =
    lsi::SamplesNextToSurface(geometry, values, this->IsoValue, ranks);
  const double fit =
    lsi::MedianSupportPerNeighborhoodRadius(geometry, *field, nextToSurface, ranks);
  const bool reports = this->ReportsForAll();
  const double summed = ranks.Sum(static_cast<double>(field->SummedDensities));
  if (fit < 0.5)
  {
    if (this->Field == AUTOMATIC_FIELD)
    {
      if (reports)
      {
        vtkWarningMacro("The smoothing lengths do not fit these particles: at the surface the "
                        "median kernel support is "
          << fit << " times the median distance to the " << geometry.Stride - 1
          << "th neighbour (real SPH supports hold 30 or more neighbours). Using the MLS fit of "
             "the samples; set Field to SPH to use them anyway, or make them with Particle "
             "Density.");
      }
      field.reset();
      return true;
    }
    if (reports)
    {
      vtkWarningMacro("The smoothing lengths look too small for these particles: the median "
                      "kernel support is "
        << fit << " times the median distance to the " << geometry.Stride - 1
        << "th neighbour. The SPH field is used, as Field asks, but it is spiky.");
    }
  }
  // Stored densities the kernel sums of the masses do not give (by far more than the codes'
  // conventions differ): the smoothing lengths are not the ones the simulation used with them.
  const lsi::DensityMismatch mismatch =
    lsi::StoredDensityMismatch(geometry, *field, arrays, nextToSurface, ranks);
  constexpr double tolerance = 1.25;
  if (mismatch.Factor() > tolerance)
  {
    if (reports)
    {
      vtkWarningMacro("The stored densities '"
        << arrays.Density->GetName() << "' are not the kernel sums of the masses with these "
        << "smoothing lengths: at the surface the sums are " << std::exp(mismatch.MedianLogRatio)
        << " times them (median of " << mismatch.Particles << " particles, " << mismatch.Convention
        << " form). The smoothing lengths may be a softening or stale, SupportPerSmoothingLength "
           "or Kernel not the simulation's, or the densities in other units than the masses and "
           "lengths. "
        << (this->Field == AUTOMATIC_FIELD
               ? "Using the MLS fit of the samples; set Field to SPH to use the SPH field anyway."
               : "The SPH field is used, as Field asks."));
    }
    if (this->Field == AUTOMATIC_FIELD)
    {
      field.reset();
      return true;
    }
  }
  if (summed > 0 && reports)
  {
    vtkWarningMacro(<< summed << " particles have a density that is not positive "
                    << "and finite in '" << arrays.Density->GetName()
                    << "': their volumes m / rho for the interpolated arrays use the density "
                       "summed from the masses instead.");
  }
  this->UsedSPHField = true;
  return true;
}

bool vtkLevelSetIsosurface::Evolve(const lsi::Neighborhoods& geometry,
  const std::vector<double>& dataOffsets, const std::vector<char>* component,
  const lsi::EvolutionSettings& settings, std::vector<double>& phi, vtkTable* iterations)
{
  const auto start = Clock::now();
  lsi::LevelSetEvolution evolution(geometry, dataOffsets, phi);
  evolution.SetCommunicator(*this->Internal->Ranks);
  if (component)
  {
    evolution.SetComponent(*component);
  }
  const lsi::AbortCheck progress = this->Stage(EvolutionStage);
  const bool finished = evolution.Run(
    settings,
    [&](const lsi::IterationRecord& record) {
      lsi::AppendIteration(iterations, record);
      this->NumberOfIterationsPerformed = record.Iteration;
      // The number of iterations is not known in advance: half way after 3.
      return progress(record.Iteration / (record.Iteration + 3.0));
    },
    [this](double) { return this->CheckAbort(); }); // progress comes from the observer above
  this->EvolutionSeconds = SecondsSince(start);
  if (!finished)
  {
    return false;
  }
  this->Converged = evolution.Converged();
  if (!this->Converged && this->ReportsForAll())
  {
    vtkWarningMacro("The evolution stopped at MaximumNumberOfIterations ("
      << this->MaximumNumberOfIterations
      << ") before its stopping rule held: the front was still moving, so the surface may be "
         "wrong. Raise MaximumNumberOfIterations, or check TimeStep and Epsilon.");
  }
  return this->Internal->Ranks->All(!this->ProgressOrAbort(EvolutionStage[1]));
}

bool vtkLevelSetIsosurface::ExtractIsopoints(const lsi::Neighborhoods& geometry,
  const std::vector<double>& dataOffsets, std::vector<double>& phi, const lsi::SurfaceScale& scale,
  const lsi::SPHField* field, lsi::IsopointSet& isopoints, lsi::IsopointSettings& settings)
{
  // Sub-stages in proportion to their times at 2M samples: isopoints 28%, completion 48%,
  // refinement on the data 24%.
  const lsi::AbortCheck stage = this->Stage(IsopointStage);
  const auto start = Clock::now();
  settings = lsi::ChooseIsopointSettings(this->RequestedParameters(), scale);
  if (field)
  {
    // The SPH field is exact between the particles: sample the surface twice as densely, so
    // that the splats (whose corners are solved onto the level) are small against its curvature
    // where the particles are sparse.
    settings.CellSize *= 0.5;
  }
  // The isopoints come from phi without its spurious pockets; the evolved phi is put back on
  // every way out (the particle outputs and later re-runs read it).
  struct PutBack
  {
    std::vector<double>& Phi;
    const lsi::FlippedSamples Flipped;
    ~PutBack() { this->Flipped.Restore(this->Phi); }
  } putBack{ phi, lsi::FlipSpuriousPockets(geometry, dataOffsets, phi) };
  if (!lsi::ExtractIsopoints(geometry, phi, settings, isopoints, lsi::SubRange(stage, 0.0, 0.28),
        *this->Internal->Ranks))
  {
    return false;
  }
  auto partStart = Clock::now();
  if (settings.Completion && !isopoints.Points.empty() &&
    !lsi::CompleteIsopoints(geometry, phi, settings, isopoints, lsi::SubRange(stage, 0.28, 0.76)))
  {
    return false;
  }
  this->CompletionSeconds = SecondsSince(partStart);
  partStart = Clock::now();
  if (settings.RefineOnData && !isopoints.Points.empty() &&
    !(field ? lsi::RefineIsopointsOnSPHField(geometry, *field, this->IsoValue, settings, isopoints,
                lsi::SubRange(stage, 0.76, 1.0))
            : lsi::RefineIsopointsOnData(
                geometry, dataOffsets, settings, isopoints, lsi::SubRange(stage, 0.76, 1.0))))
  {
    return false;
  }
  if (field && settings.RefineOnData &&
    !lsi::AddFreeBoundaryPoints(geometry, *field, this->IsoValue, lsi::LastOutputs::InsideOf(phi),
      dataOffsets, settings, isopoints, lsi::SubRange(stage, 1.0, 1.0)))
  {
    return false;
  }
  this->DataRefinementSeconds = SecondsSince(partStart);
  this->IsopointSeconds = SecondsSince(start);
  this->StencilSeconds = geometry.StencilSeconds;
  if (geometry.SingularSamples > 0)
  {
    vtkWarningMacro("The MLS fit was singular at "
      << geometry.SingularSamples
      << " samples (neighbourhoods on a plane or line); their gradients were taken as zero. "
         "More NumberOfNeighbors may help.");
  }
  return !this->ProgressOrAbort(IsopointStage[1]);
}

lsi::SPHFieldRequest vtkLevelSetIsosurface::SPHRequest() const
{
  lsi::SPHFieldRequest request;
  request.Model = this->Field;
  request.Kernel = this->Kernel;
  request.SupportPerSmoothingLength = this->SupportPerSmoothingLength;
  request.SmoothingLengthArray = this->SmoothingLengthArray;
  request.MassArray = this->MassArray;
  request.DensityArray = this->DensityArray;
  return request;
}
