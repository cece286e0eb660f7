// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkLevelSetIsosurface.h"
#include "vtkLevelSetIsosurfaceInternals.h"

#include "LevelSetConvergenceTable.h"
#include "LevelSetDistribution.h"
#include "LevelSetDuplicates.h"
#include "LevelSetEnclosed.h"
#include "LevelSetEnclosedDeepInside.h"
#include "LevelSetEnclosedSurface.h"
#include "LevelSetEvolution.h"
#include "LevelSetFlood.h"
#include "LevelSetFloodAcross.h"
#include "LevelSetHaloReach.h"
#include "LevelSetInput.h"
#include "LevelSetIsoValueSlide.h"
#include "LevelSetIsopoints.h"
#include "LevelSetLastOutputs.h"
#include "LevelSetNeighborCache.h"
#include "LevelSetParameters.h"
#include "LevelSetParticleOutput.h"
#include "LevelSetPeriodicImages.h"
#include "LevelSetRegionFaces.h"
#include "LevelSetSPHField.h"
#include "LevelSetSeedSpheres.h"
#include "LevelSetSplatOutput.h"
#include "LevelSetSurfaceOutput.h"
#include "LevelSetTiming.h"
#include "LevelSetVertexCells.h"

#include "vtkDataArray.h"
#include "vtkDataSet.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkMultiProcessController.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPointSet.h"
#include "vtkPolyData.h"
#include "vtkSMPThreadLocal.h"
#include "vtkSMPTools.h"
#include "vtkTable.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <utility>

vtkStandardNewMacro(vtkLevelSetIsosurface);

namespace
{
using lsi::AllListsStage;
using lsi::Clock;
using lsi::EvolutionStage;
using lsi::InitializationStage;
using lsi::IsopointStage;
using lsi::NeighborStage;
using lsi::SecondsSince;
using lsi::SPHFieldStage;
using lsi::SplatStage;
using lsi::SurfaceStage;

// Under MPI, each rank receives the other ranks' particles within this many of its own
// particles' neighbourhood radii: enough for the initial signed distance (the reinitialised
// band, about 4.7 radii with the automatic Epsilon) plus one radius of whole neighbourhoods.
constexpr double HaloRadii = 6.0;
// Inputs with fewer particles per rank than this are gathered and processed on rank 0.
constexpr double SmallestSharePerRank = 2000.0;
} // namespace

vtkLevelSetIsosurface::vtkLevelSetIsosurface()
  : Internal(new Internals)
{
  this->SetNumberOfOutputPorts(4);
  this->SetInputArrayToProcess(
    0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, vtkDataSetAttributes::SCALARS);
  this->SetController(vtkMultiProcessController::GetGlobalController());
}

vtkLevelSetIsosurface::~vtkLevelSetIsosurface()
{
  this->SetController(nullptr);
}

vtkCxxSetObjectMacro(vtkLevelSetIsosurface, Controller, vtkMultiProcessController);

bool vtkLevelSetIsosurface::ReportsForAll() const
{
  return !this->Internal->Ranks || this->Internal->Ranks->Rank == 0;
}

void vtkLevelSetIsosurface::SetSeedCenter(double x, double y, double z)
{
  if (!(this->SeedCenter[0] == x && this->SeedCenter[1] == y && this->SeedCenter[2] == z))
  {
    this->SeedCenter[0] = x;
    this->SeedCenter[1] = y;
    this->SeedCenter[2] = z;
    this->SeedsModified();
  }
}

void vtkLevelSetIsosurface::SetSeedRadius(double radius)
{
  if (!(this->SeedRadius == radius))
  {
    this->SeedRadius = radius;
    this->SeedsModified();
  }
}

void vtkLevelSetIsosurface::AddAdditionalSeed(double cx, double cy, double cz, double radius)
{
  this->AdditionalSeeds.insert(this->AdditionalSeeds.end(), { cx, cy, cz, radius });
  this->SeedsModified();
}

void vtkLevelSetIsosurface::RemoveAllAdditionalSeeds()
{
  if (!this->AdditionalSeeds.empty())
  {
    this->AdditionalSeeds.clear();
    this->SeedsModified();
  }
}

void vtkLevelSetIsosurface::SetNumberOfAdditionalSeedValues(int count)
{
  const std::size_t size = static_cast<std::size_t>(std::max(0, count));
  if (size != this->AdditionalSeeds.size())
  {
    this->AdditionalSeeds.resize(size, 0.0);
    this->SeedsModified();
  }
}

void vtkLevelSetIsosurface::SetAdditionalSeedValue(int index, double value)
{
  if (index < 0 || static_cast<std::size_t>(index) >= this->AdditionalSeeds.size())
  {
    vtkErrorMacro("AdditionalSeeds value " << index << " is past the list's "
                                           << this->AdditionalSeeds.size() << " values.");
    return;
  }
  if (!(this->AdditionalSeeds[index] == value))
  {
    this->AdditionalSeeds[index] = value;
    this->SeedsModified();
  }
}

int vtkLevelSetIsosurface::GetNumberOfAdditionalSeeds() const
{
  return static_cast<int>(this->AdditionalSeeds.size() / 4);
}

int vtkLevelSetIsosurface::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPointSet");
  return 1;
}

int vtkLevelSetIsosurface::FillOutputPortInformation(int port, vtkInformation* info)
{
  info->Set(vtkDataObject::DATA_TYPE_NAME(), port >= 2 ? "vtkTable" : "vtkPolyData");
  return 1;
}

int vtkLevelSetIsosurface::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPointSet* input = vtkPointSet::GetData(inputVector[0]);
  vtkPolyData* isopoints = vtkPolyData::GetData(outputVector, 0);
  vtkPolyData* particles = vtkPolyData::GetData(outputVector, 1);
  vtkTable* convergence = vtkTable::GetData(outputVector, 2);
  vtkTable* enclosed = vtkTable::GetData(outputVector, 3);
  enclosed->Initialize();
  isopoints->Initialize();
  particles->Initialize();
  convergence->Initialize();
  if (!input)
  {
    vtkErrorMacro("Input is not a vtkPointSet.");
    return 0;
  }
  bool ok = false;
  // (Found again on this input, if no Scalars are named: InputScalars.)
  this->Internal->ActiveScalarsName.clear();
  // VTK's global SMP backend may be Sequential (as in ParaView 5.11): run our loops on
  // std::threads regardless, without touching the global state.
  vtkSMPTools::LocalScope(vtkSMPTools::Config{ this->NumberOfThreads, "STDThread", false },
    [&]() { ok = this->Execute(input, isopoints, particles, convergence, enclosed); });
  if (!ok)
  {
    isopoints->Initialize();
    particles->Initialize();
    convergence->Initialize();
    enclosed->Initialize();
    // Under MPI an error is decided over all ranks and reported by rank 0: the other ranks
    // return empty outputs without a second message from their executives.
    const bool satellite = this->Controller && this->Controller->GetLocalProcessId() > 0;
    return this->GetAbortExecute() || satellite ? 1 : 0;
  }
  return 1;
}

// The method's steps, in the paper's order; each is a function in the file of its step, and
// each check of the input comes before the work it protects.
bool vtkLevelSetIsosurface::Execute(vtkPointSet* input, vtkPolyData* surfaceOutput,
  vtkPolyData* particleOutput, vtkTable* convergence, vtkTable* enclosed)
{
  this->NumberOfIterationsPerformed = 0;
  this->Converged = false;
  this->GhostFraction = 0.0;
  this->ReusedLastOutputs = this->SlidLastSurface = this->RemadeSurfaceOutput = false;
  // Whether nothing but the seeds (or the isovalue) changed since the last run; the input is
  // checked below.
  const bool onlySeedsChanged = this->GetMTime() == this->SeedsOnlyTime;
  const bool onlyIsoValueChanged = this->GetMTime() == this->IsoValueOnlyTime;

  vtkPointSet* requested = input;
  lsi::LastOutputs& last = this->Internal->Last;
  // (Heap-held: a distributed run's ranks, with its ghosts, are kept for a seed move.)
  std::unique_ptr<lsi::Distribution> thisRunsRanks(new lsi::Distribution(this->Controller));
  lsi::Distribution& ranks = *thisRunsRanks;
  this->Internal->Ranks = &ranks;
  struct Forget // the steps below must not keep a pointer to this execution's ranks
  {
    vtkLevelSetIsosurface* Filter;
    lsi::Distribution& Ranks;
    ~Forget()
    {
      Filter->Internal->Ranks = nullptr;
      Filter->CommunicationSeconds = Ranks.CommunicationSeconds;
    }
  } forget{ this, ranks };
  if ((ranks.Distributed() || (onlySeedsChanged && last.Valid)) &&
    this->ReuseAfterSeedMove(
      onlySeedsChanged, input, surfaceOutput, particleOutput, convergence, enclosed))
  {
    return true;
  }
  if ((ranks.Distributed() || onlyIsoValueChanged) &&
    this->SlideAfterIsoValueChange(
      onlyIsoValueChanged, input, surfaceOutput, particleOutput, convergence, enclosed))
  {
    return true;
  }
  const bool onlyOutputsChanged = this->GetMTime() == this->OutputsOnlyTime;
  if ((ranks.Distributed() || onlyOutputsChanged) &&
    this->RemakeSurfaceOutput(
      onlyOutputsChanged, input, surfaceOutput, particleOutput, convergence, enclosed))
  {
    return true;
  }
  lsi::RunParticles run;
  if (!this->PrepareParticles(input, run) || run.Idle)
  {
    return run.Idle;
  }
  const vtkSmartPointer<vtkPointSet> original = run.Original;
  const lsi::Neighborhoods* geometry = run.Geometry;
  const std::vector<double>& values = run.Values;
  const std::vector<vtkIdType>& mergedId = run.MergedId;
  input = run.Work; // from here on: the distinct particles, their ghost images and MPI ghosts
  auto inputStart = lsi::Clock::now();
  std::unique_ptr<lsi::SPHField> field; // null: the MLS fit of the samples
  if (!ranks.All(this->BuildSPHField(input, *geometry, values, field)))
  {
    return false;
  }
  this->CheckPeriodicMargin(*geometry, field.get());
  std::vector<double> dataOffsets, dataSign; // f - f_iso and its sign, in storage order
  bool ok = true;
  if (!field)
  {
    lsi::DataInStorageOrder(*geometry, values, this->IsoValue, dataOffsets, dataSign);
  }
  else
  {
    ok = lsi::SPHOffsetsAtSamples(
      *geometry, *field, this->IsoValue, dataOffsets, dataSign, this->Stage(SPHFieldStage));
  }
  if (!ranks.All(ok))
  {
    return false;
  }
  // A ghost at the halo's edge misses part of its kernel sum: its owner's value is the serial one.
  ranks.RefreshGhosts(dataOffsets);
  ranks.RefreshGhosts(dataSign);
  const lsi::SurfaceScale scale = lsi::ScaleAtSurface(*geometry, dataSign, ranks);
  const lsi::EvolutionSettings settings = this->ChooseEvolutionSettings(scale);
  this->InputSeconds += SecondsSince(inputStart);
  std::vector<double> phi;
  if (!this->Initialize(input, *geometry, dataOffsets, settings, phi))
  {
    return false;
  }
  // What a later seed move needs to recognise the same flood (ReuseAfterSeedMove): runs with
  // the flood start only (a periodic cell around the seed moves with it). FloodFromSeeds floods
  // as the method does: across faces and ranks in the same rounds.
  last.QuickCheck = this->Initialization == FLOOD && mergedId.empty();
  // What a change of the surface output's properties alone needs (the last run's points and
  // input, whatever the start; any layout of ranks and box): no duplicates merged.
  last.SurfaceReady = mergedId.empty();
  // In a periodic box the method ran on the particles and their images, under MPI with ghosts:
  // a re-run needs them.
  last.Work =
    last.SurfaceReady && (this->Internal->Box.Enabled || ranks.Distributed()) ? input : nullptr;
  last.Inside = last.QuickCheck ? lsi::LastOutputs::InsideOf(phi) : std::vector<char>();
  if (!last.QuickCheck)
  {
    last.InSeed.clear();
    last.SeedSpheres.clear();
  }
  last.DataOffsets = std::vector<double>(); // (this run's, moved there at its end: no copy)
  last.Spacing = settings.Spacing;
  vtkNew<vtkTable> iterations = lsi::EmptyConvergenceTable();
  if (!this->Evolve(*geometry, dataSign, dataOffsets, settings, phi, iterations))
  {
    return false;
  }
  lsi::IsopointSet isopoints;
  lsi::IsopointSettings isopointSettings;
  ok = this->ExtractIsopoints(
    *geometry, dataOffsets, phi, scale, field.get(), isopoints, isopointSettings);
  if (!ranks.All(ok))
  {
    return false;
  }
  // In a periodic box a slide moves every point found, the images' too, and cuts the cell anew;
  // under MPI every point the rank found, then keeps its own.
  lsi::IsopointSet uncut;
  const bool keepsUncut = this->Internal->Box.Enabled || ranks.Distributed();
  if (keepsUncut && this->QuickIsoValueChanges && last.QuickCheck)
  {
    uncut = isopoints;
  }
  this->KeepPeriodicCell(isopoints);
  // Under MPI a point near the cut has neighbours that another rank keeps: the splat radii come
  // from every point this rank found (in the periodic cell), as in a serial run. (The Enclosed
  // table's distances come from every rank's kept points: MakeParticleOutputs.)
  lsi::IsopointSet allFound;
  if (ranks.Distributed())
  {
    allFound.Points = isopoints.Points;
    allFound.Normals = isopoints.Normals;
  }
  this->KeepOwnedIsopoints(*geometry, isopoints);
  this->WarnIfSuspect(*geometry, dataOffsets, phi, isopoints);
  this->WarnIfRegionCut(original, *geometry, field.get(), isopoints.Points);
  const lsi::IsopointSet& nearby = ranks.Distributed() ? allFound : isopoints;
  // One search index over those points, for the splat radii and (in one process) the Enclosed
  // table.
  const std::unique_ptr<lsi::PointCloudIndex> surfaceIndex = lsi::IndexOfPoints(nearby.Points);
  ok = this->MakeSurfaceOutput(
    input, *geometry, isopoints, nearby.Points, field.get(), surfaceIndex.get(), surfaceOutput);
  if (!ranks.All(ok))
  {
    return false;
  }
  last.OnField = field != nullptr;
  const auto particleStart = lsi::Clock::now();
  const double halfWidth = lsi::ReinitializationHalfWidth(settings);
  // (The deep inside of the Enclosed sums, for quick isovalue changes: see SlideReady below.)
  last.DeepInside = lsi::EnclosedDeepInside();
  last.NearGradients.clear();
  const bool keepDeepInside = this->QuickIsoValueChanges && last.QuickCheck;
  this->MakeParticleOutputs(original, input, *geometry, phi, mergedId, halfWidth, isopoints,
    surfaceIndex.get(), particleOutput, enclosed, keepDeepInside ? &last.DeepInside : nullptr,
    nullptr);
  this->ParticleOutputSeconds = SecondsSince(particleStart);
  if (this->ReportsForAll()) // tables on rank 0 only, so that gathering them shows them once
  {
    convergence->ShallowCopy(iterations);
  }
  // An abort that arrived during the last stage still empties the outputs.
  if (!ranks.All(!this->ProgressOrAbort(1.0)))
  {
    return false;
  }
  last.Remember(surfaceOutput, particleOutput, convergence, enclosed);
  last.Input = requested;
  // (Only what a re-run can reuse needs the stamp: its scalars' fingerprint is a pass over them.)
  last.Stamp = last.SurfaceReady ? lsi::InputStamp::Of(requested, this->ScalarsOf(requested))
                                 : lsi::InputStamp();
  last.Iterations = this->NumberOfIterationsPerformed;
  last.Converged = this->Converged;
  last.GhostFraction = this->GhostFraction;
  if (last.SurfaceReady && ranks.Distributed())
  {
    this->Internal->LastRanks = std::move(thisRunsRanks); // (`ranks` stays valid: the same object)
  }
  // What a later isovalue change needs to slide this surface (SlideAfterIsoValueChange).
  // (Under MPI a rank without surface is ready: it has nothing to slide.)
  const lsi::IsopointSet& found = keepsUncut ? uncut : isopoints;
  last.SlideReady = this->QuickIsoValueChanges && last.QuickCheck &&
    isopointSettings.RefineOnData && (field || found.FitSize > 0 || ranks.Distributed()) &&
    (!this->Internal->Box.Enabled || !uncut.Points.empty());
  last.Owned = last.SurfaceReady && ranks.Distributed() ? original : nullptr;
  if (last.Owned)
  {
    last.WorkValues = values; // (f with the ghosts' values, which came with them)
  }
  if (!last.SlideReady)
  {
    last.DeepInside = lsi::EnclosedDeepInside();
  }
  last.Values.clear();
  last.ValuesAreScalars = false;
  last.Phi.clear();
  last.Field.reset();
  last.Isopoints = lsi::IsopointSet();
  last.FitCentres.clear();
  if (last.SlideReady)
  {
    this->KeepForSlides(input, *geometry, values, dataOffsets, field, phi,
      keepsUncut ? uncut : isopoints, isopointSettings, halfWidth);
  }
  if (last.QuickCheck)
  {
    last.DataOffsets = std::move(dataOffsets);
  }
  // What the surface output was made from, for a change of its properties alone (LastOutputs::
  // ShownPoints and NearbyPoints: Isopoints, where those are they).
  last.ShownAreIsopoints = last.SlideReady && !keepsUncut;
  last.Shown =
    last.SurfaceReady && !last.ShownAreIsopoints ? std::move(isopoints) : lsi::IsopointSet();
  // (Under MPI in a periodic box, the points found in the cell: Isopoints holds every one.)
  last.NearbyAreIsopoints = last.SlideReady && ranks.Distributed() && !this->Internal->Box.Enabled;
  last.Nearby = last.SurfaceReady && ranks.Distributed() && !last.NearbyAreIsopoints
    ? std::move(allFound.Points)
    : std::vector<double>();
  this->LastRunTime = this->GetMTime();
  return true;
}

bool vtkLevelSetIsosurface::PrepareParticles(vtkPointSet* input, lsi::RunParticles& run)
{
  lsi::Distribution& ranks = *this->Internal->Ranks;
  lsi::LastOutputs& last = this->Internal->Last;
  std::vector<double>& values = run.Values;
  vtkSmartPointer<vtkPointSet>& original = run.Original;
  vtkSmartPointer<vtkPointSet>& work = run.Work;
  const lsi::Neighborhoods*& geometry = run.Geometry;
  std::vector<vtkIdType>& mergedId = run.MergedId;
  // Under MPI a full re-run on the same particles (a change of CurvatureWeight, say) keeps the
  // last run's ghosts, their neighbourhoods and the ranks that trade them.
  const lsi::Neighborhoods* keptGhosts = ranks.Distributed() ? this->KeptGhosts(input) : nullptr;
  std::unique_ptr<lsi::Distribution> keptRanks;
  vtkSmartPointer<vtkPointSet> keptOwned = last.Owned, keptWork = last.Work;
  std::vector<double> keptValues;
  if (keptGhosts)
  {
    keptRanks = std::move(this->Internal->LastRanks);
    keptValues = std::move(last.WorkValues);
  }
  last.WorkValues.clear();
  last.Valid = false; // until this run succeeds
  last.SurfaceReady = false;
  this->Internal->LastRanks.reset();
  this->InputSeconds = this->ParticleOutputSeconds = 0.0;
  auto inputStart = lsi::Clock::now();
  if (!this->ValidateInput(input, values))
  {
    return false;
  }
  this->InputSeconds = SecondsSince(inputStart);
  original = input;
  if (keptGhosts)
  {
    // The last run's particles with their ghosts (no periodic box: KeptGhosts), and f over them
    // as WithGhosts gave it.
    original = keptOwned;
    work = keptWork;
    geometry = keptGhosts;
    ranks = *keptRanks;
    ranks.CommunicationSeconds = 0.0;
    this->Internal->Box = lsi::PeriodicBox();
    this->Internal->OriginalCount = original->GetNumberOfPoints();
    this->Internal->ImageOf.clear();
    this->NeighborSearchSeconds = this->SpatialSortSeconds = this->NearestNeighborSeconds =
      this->TreeBuildSeconds = 0.0;
    values = std::move(keptValues);
    this->GhostFraction = last.GhostFraction;
  }
  else
  {
    if (ranks.Distributed())
    {
      original = this->Distribute(input, values, run.Idle);
      if (run.Idle)
      {
        return true;
      }
    }
    work = this->WithPeriodicImages(original, values);
    geometry = work ? this->FindNeighborhoods(work->GetPoints(), true) : nullptr;
  }
  if (!keptGhosts && geometry && geometry->DuplicateSamples > 0)
  {
    values.resize(static_cast<std::size_t>(original->GetNumberOfPoints())); // images appended
    vtkIdType merged = 0;
    vtkSmartPointer<vtkPointSet> distinct =
      lsi::MergeDuplicatePoints(original, values, mergedId, merged);
    vtkWarningMacro(<< merged << " points coincide with another point (for example point "
                    << geometry->FirstDuplicate
                    << "): each group was merged into one, its values averaged.");
    work = this->WithPeriodicImages(distinct, values);
    geometry = work ? this->FindNeighborhoods(work->GetPoints(), false) : nullptr;
  }
  if (!ranks.All(geometry != nullptr))
  {
    return false;
  }
  if (ranks.Distributed() && !keptGhosts)
  {
    work = this->WithGhosts(work, *geometry, values);
    if (!work)
    {
      return false;
    }
    geometry = this->FindNeighborhoods(work->GetPoints(), false);
    if (!ranks.All(geometry != nullptr))
    {
      return false;
    }
    ranks.Attach(*geometry);
    double counts[2] = { static_cast<double>(ranks.GhostCount),
      static_cast<double>(original->GetNumberOfPoints()) };
    ranks.Sum(counts, 2);
    this->GhostFraction = counts[0] / counts[1];
  }
  return true;
}

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

bool vtkLevelSetIsosurface::ValidateInput(vtkPointSet* input, std::vector<double>& values)
{
  std::vector<std::pair<const char*, double>> parameters = { { "IsoValue", this->IsoValue },
    { "SeedCenter[0]", this->SeedCenter[0] }, { "SeedCenter[1]", this->SeedCenter[1] },
    { "SeedCenter[2]", this->SeedCenter[2] }, { "SeedRadius", this->SeedRadius },
    { "Epsilon", this->Epsilon }, { "CurvatureEpsilon", this->CurvatureEpsilon },
    { "TimeStep", this->TimeStep }, { "CurvatureWeight", this->CurvatureWeight },
    { "DistanceRegularization", this->DistanceRegularization },
    { "ConvergenceTolerance", this->ConvergenceTolerance }, { "SplatScale", this->SplatScale },
    { "SupportPerSmoothingLength", this->SupportPerSmoothingLength },
    { "BoxSize[0]", this->BoxSize[0] }, { "BoxSize[1]", this->BoxSize[1] },
    { "BoxSize[2]", this->BoxSize[2] } };
  for (double value : this->AdditionalSeeds)
  {
    parameters.emplace_back("AdditionalSeeds", value);
  }
  if (this->AdditionalSeeds.size() % 4 != 0)
  {
    vtkErrorMacro("AdditionalSeeds has " << this->AdditionalSeeds.size()
                                         << " numbers, not 4 per sphere (cx, cy, cz, radius). "
                                            "Give 4 numbers per sphere.");
    return false;
  }
  const std::string badParameter = lsi::NonFiniteParameter(parameters);
  if (!badParameter.empty())
  {
    if (this->ReportsForAll())
    {
      vtkErrorMacro(<< badParameter);
    }
    return false;
  }
  int association = -1;
  vtkDataArray* scalars = this->InputScalars(input, association);
  const lsi::Distribution& ranks = *this->Internal->Ranks;
  std::string problem;
  if (!ranks.Distributed())
  {
    problem = lsi::CheckInput(input, scalars, association, this->NumberOfNeighbors, this->IsoValue,
      this->AdditionalSeeds, values);
  }
  else
  {
    // Each rank checks its piece; the count and the range are the whole input's.
    double range[2];
    problem = ranks.FirstProblem(lsi::CheckPiece(input, scalars, association, values, range));
    if (problem.empty())
    {
      const double count = ranks.Sum(static_cast<double>(values.size()));
      range[0] = -ranks.Max(-range[0]);
      range[1] = ranks.Max(range[1]);
      problem = lsi::CheckCount(static_cast<vtkIdType>(count), this->NumberOfNeighbors);
      if (problem.empty())
      {
        problem = lsi::CheckRangeAndSeeds(range, this->IsoValue, this->AdditionalSeeds);
      }
    }
  }
  if (!problem.empty())
  {
    if (this->ReportsForAll())
    {
      vtkErrorMacro(<< problem);
    }
    return false;
  }
  return true;
}

vtkDataArray* vtkLevelSetIsosurface::InputScalars(vtkDataObject* input, int& association)
{
  vtkDataArray* scalars = this->GetInputArrayToProcess(0, input, association);
  if (scalars)
  {
    return scalars;
  }
  // No array named (a script whose Scalars property the domain left empty, as pvbatch
  // --symmetric leaves it): the input's active point scalars, which the readers and Particle
  // Density set to the density; without them (ParaView's Distribute Points drops the attribute
  // but keeps the field data), the array the readers and Particle Density name as the density
  // in the field data (DensityArray). On the filter's own copies of the input (ghost images,
  // MPI ghosts), which carry the arrays but neither mark, the array of the name found first. A
  // name that the input lacks stays an error.
  vtkInformation* info = this->GetInputArrayInformation(0);
  const char* name = info && info->Has(vtkDataObject::FIELD_NAME())
    ? info->Get(vtkDataObject::FIELD_NAME())
    : nullptr;
  vtkDataSet* set = vtkDataSet::SafeDownCast(input);
  if ((name && *name) || !set)
  {
    return nullptr;
  }
  association = vtkDataObject::FIELD_ASSOCIATION_POINTS;
  if (vtkDataArray* active = set->GetPointData()->GetScalars())
  {
    this->Internal->ActiveScalarsName = active->GetName() ? active->GetName() : "";
    return active;
  }
  if (!this->Internal->ActiveScalarsName.empty())
  {
    return set->GetPointData()->GetArray(this->Internal->ActiveScalarsName.c_str());
  }
  const std::string marked = lsi::MarkedArrayName(set, "DensityArray");
  vtkDataArray* density = marked.empty() ? nullptr : set->GetPointData()->GetArray(marked.c_str());
  if (density)
  {
    this->Internal->ActiveScalarsName = marked;
  }
  return density;
}

vtkSmartPointer<vtkPointSet> vtkLevelSetIsosurface::Distribute(
  vtkPointSet* input, std::vector<double>& values, bool& idle)
{
  lsi::Distribution& ranks = *this->Internal->Ranks;
  const double count = ranks.Sum(static_cast<double>(input->GetNumberOfPoints()));
  const double smallest = std::max(SmallestSharePerRank, 20.0 * (this->NumberOfNeighbors + 1));
  vtkSmartPointer<vtkPointSet> piece;
  if (count < smallest * ranks.Size)
  {
    piece = ranks.GatheredOnFirst(input);
    vtkDebugMacro(<< count << " particles: gathered on rank 0, which processes them alone.");
    ranks.Size = 1; // a serial run from here on
    idle = ranks.Rank != 0;
    if (idle)
    {
      return nullptr;
    }
  }
  else
  {
    std::string report;
    piece = ranks.Balanced(input, report);
    vtkDebugMacro(<< (report.empty() ? std::string("the partition is kept") : report));
  }
  int association = -1;
  vtkDataArray* scalars = this->InputScalars(piece, association);
  double range[2];
  lsi::CheckPiece(piece, scalars, association, values, range); // checked before moving
  return piece;
}

vtkSmartPointer<vtkPointSet> vtkLevelSetIsosurface::WithGhosts(
  vtkPointSet* work, const lsi::Neighborhoods& owned, std::vector<double>& values)
{
  // Each owned sample's halo: HaloRadii of its own neighbourhood radii (found among this rank's
  // samples only, so never less than the serial radius), and a wider band if Epsilon asks. The
  // rank's reach box bounds them all (from the lists of the samples that can reach farthest).
  const std::size_t n = owned.NumberOfSamples;
  double band = 0.0;
  std::vector<double> support;
  this->HaloInputs(work, band, support);
  // (What a full re-run compares to keep these ghosts: KeptGhosts.)
  this->Internal->Last.HaloBand = band;
  this->Internal->Last.HaloSupport = lsi::ValueFingerprint(support);
  double reachBox[6];
  std::size_t listed = 0;
  lsi::Distribution& ranks = *this->Internal->Ranks;
  // Only the sides beyond which another rank holds samples bound what it sends here: the
  // others are left unbounded, uncomputed (a slab of a split in x needs one side of six).
  double all[6], own[6];
  this->Bounds(work, all, own); // every rank's, and this rank's
  bool wanted[6];
  for (int d = 0; d < 3; ++d)
  {
    wanted[2 * d] = all[2 * d] < own[2 * d];
    wanted[2 * d + 1] = all[2 * d + 1] > own[2 * d + 1];
  }
  // (Every rank stops here if one aborted: the exchange below needs them all.)
  if (!ranks.All(lsi::HaloReachBox(owned, HaloRadii, band, reachBox, listed,
        this->Stage(AllListsStage), lsi::HaloFirstPerSide, wanted)))
  {
    return nullptr;
  }
  vtkDebugMacro(<< "halo: " << listed << " of " << n << " neighbour lists computed");
  std::string failure;
  vtkSmartPointer<vtkPolyData> withGhosts =
    ranks.WithGhosts(work, reachBox, support, values, failure);
  if (!withGhosts)
  {
    if (this->ReportsForAll())
    {
      vtkErrorMacro(<< "The exchange of ghost particles failed: " << failure);
    }
    return nullptr;
  }
  vtkDebugMacro(<< ranks.GhostCount << " ghost particles from other ranks.");
  return withGhosts;
}

void vtkLevelSetIsosurface::HaloInputs(
  vtkPointSet* work, double& band, std::vector<double>& support)
{
  band = this->Epsilon > 0.0 ? 2.0 * std::max(this->Epsilon, this->CurvatureEpsilon) : 0.0;
  support.clear();
  // The SPH field at a point sums every particle whose kernel reaches it.
  int association = -1;
  vtkDataArray* scalars = this->InputScalars(work, association);
  lsi::SPHFieldArrays arrays;
  std::string problem, choice;
  if (lsi::FindSPHArrays(work, scalars, this->SPHRequest(), arrays, problem, choice))
  {
    const vtkIdType n = work->GetNumberOfPoints();
    support.resize(static_cast<std::size_t>(n));
    for (vtkIdType i = 0; i < n; ++i)
    {
      const double h = arrays.SmoothingLength->GetComponent(i, 0);
      support[i] = std::isfinite(h) ? std::abs(h) * arrays.SupportPerSmoothingLength : 0.0;
    }
  }
}

const lsi::Neighborhoods* vtkLevelSetIsosurface::KeptGhosts(vtkPointSet* input)
{
  const lsi::LastOutputs& last = this->Internal->Last;
  const lsi::Neighborhoods* geometry = nullptr;
  // The same input (its stamp, the neighbourhoods still cached), the same ranks, no periodic
  // box then or now, and the same halo (Epsilon's band, the kernel supports).
  if (last.Owned && last.Work && !this->Internal->Box.Enabled && this->LastRanksMatch())
  {
    std::string problem;
    const lsi::PeriodicBox box =
      lsi::FindPeriodicBox(last.Owned, this->BoxSize, this->Periodic, problem);
    double band = 0.0;
    std::vector<double> support;
    this->HaloInputs(last.Owned, band, support);
    if (!box.Enabled && problem.empty() && band == last.HaloBand &&
      lsi::ValueFingerprint(support) == last.HaloSupport)
    {
      geometry = this->LastGeometry(input, false);
    }
  }
  return this->Internal->Ranks->All(geometry != nullptr) ? geometry : nullptr;
}

vtkSmartPointer<vtkPointSet> vtkLevelSetIsosurface::WithPeriodicImages(
  vtkPointSet* input, std::vector<double>& values)
{
  Internals& internal = *this->Internal;
  std::string problem;
  internal.Box = lsi::FindPeriodicBox(input, this->BoxSize, this->Periodic, problem);
  internal.OriginalCount = input->GetNumberOfPoints();
  internal.ImageOf.clear();
  if (!problem.empty())
  {
    vtkErrorMacro(<< problem);
    return nullptr;
  }
  if (!internal.Box.Enabled)
  {
    return input;
  }
  double bounds[6];
  this->Bounds(input, bounds);
  if (!lsi::PlaceBox(internal.Box, bounds, 0.5 * this->PeriodicMargin))
  {
    if (this->ReportsForAll())
    {
      vtkWarningMacro("The particles (from "
        << bounds[0] << ", " << bounds[2] << ", " << bounds[4] << " to " << bounds[1] << ", "
        << bounds[3] << ", " << bounds[5]
        << ") lie neither in the periodic box [0, BoxSize) nor in one centred on 0 (BoxSize "
        << internal.Box.Size[0] << ", " << internal.Box.Size[1] << ", " << internal.Box.Size[2]
        << "): the box is not taken as periodic. Set BoxSize, or turn Periodic off to silence "
           "this.");
    }
    internal.Box = lsi::PeriodicBox();
    return input;
  }
  vtkSmartPointer<vtkPolyData> work =
    lsi::WithPeriodicImages(input, internal.Box, this->PeriodicMargin, internal.ImageOf);
  values.reserve(values.size() + internal.ImageOf.size());
  for (vtkIdType original : internal.ImageOf)
  {
    values.push_back(values[original]);
  }
  vtkDebugMacro(<< internal.ImageOf.size() << " ghost images across the periodic box's faces.");
  return work;
}

void vtkLevelSetIsosurface::Bounds(vtkPointSet* input, double bounds[6], double own[6])
{
  // Under MPI, the whole input's: the largest of -min and max over the ranks.
  double local[6] = { HUGE_VAL, -HUGE_VAL, HUGE_VAL, -HUGE_VAL, HUGE_VAL, -HUGE_VAL };
  if (input->GetNumberOfPoints() > 0)
  {
    lsi::PointBounds(input->GetPoints(), local);
  }
  if (own)
  {
    std::copy(local, local + 6, own);
  }
  double signedBounds[6];
  for (int d = 0; d < 3; ++d)
  {
    signedBounds[2 * d] = -local[2 * d];
    signedBounds[2 * d + 1] = local[2 * d + 1];
  }
  this->Internal->Ranks->Max(signedBounds, 6);
  for (int d = 0; d < 3; ++d)
  {
    bounds[2 * d] = -signedBounds[2 * d];
    bounds[2 * d + 1] = signedBounds[2 * d + 1];
  }
}

void vtkLevelSetIsosurface::KeepPeriodicCell(lsi::IsopointSet& isopoints)
{
  const Internals& internal = *this->Internal;
  if (!internal.Box.Enabled)
  {
    return;
  }
  // Every piece of surface is found once in the box and again in the images: keep the box.
  // (Around the seed, MakeSurfaceOutput moves the points by whole boxes once it has sampled the
  // data where the particles are.)
  std::vector<char> kept(isopoints.Points.size() / 3);
  for (std::size_t i = 0; i < kept.size(); ++i)
  {
    kept[i] = lsi::InKeptCell(&isopoints.Points[3 * i], internal.Box, nullptr) ? 1 : 0;
  }
  // (The kept points keep their fits' samples and models, for the arrays interpolated onto
  // them.)
  lsi::KeepSelected(isopoints, lsi::ValidIndices(kept));
}

void vtkLevelSetIsosurface::CheckPeriodicMargin(
  const lsi::Neighborhoods& geometry, const lsi::SPHField* field)
{
  const Internals& internal = *this->Internal;
  if (!internal.Box.Enabled)
  {
    return;
  }
  std::vector<double> supports;
  for (std::size_t i = 0; field && i < geometry.NumberOfSamples; ++i)
  {
    supports.push_back(field->Support(i));
  }
  double needed = 0.0;
  const std::size_t cut = lsi::SamplesBeyondImages(
    geometry, internal.Box, this->PeriodicMargin, internal.OriginalCount, supports, needed);
  if (cut > 0)
  {
    vtkWarningMacro(<< cut
                    << " particles near the periodic box's faces have neighbourhoods or "
                       "kernel supports that reach past the ghost images (PeriodicMargin "
                    << this->PeriodicMargin
                    << " of the box): the surface may be wrong next to the faces. A "
                       "PeriodicMargin of "
                    << std::min(0.25, 1.1 * needed) << " would hold them"
                    << (needed > 0.25 ? " (more than the largest, 0.25)." : "."));
  }
}

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
  const std::vector<double>& dataOffsets, const lsi::EvolutionSettings& settings,
  std::vector<double>& phi)
{
  const auto start = Clock::now();
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
      phi = last.Start.Phi;
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
    if (!this->FloodComponent(geometry, dataOffsets, inSeed, inside, seedSamples))
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
    flood.Phi = phi;
    flood.InSeed = last.InSeed;
    last.Start = std::move(flood);
    ++this->FloodCount;
  }
  this->InitializationSeconds = SecondsSince(start);
  return true;
}

bool vtkLevelSetIsosurface::FloodComponent(const lsi::Neighborhoods& geometry,
  const std::vector<double>& dataOffsets, std::vector<char>& inSeed, std::vector<char>& inside,
  double& seedSamples)
{
  // Each rank floods its samples and ghosts, across the periodic box's faces and the ranks:
  // the component is then the serial one.
  const Internals& internal = *this->Internal;
  const std::vector<vtkIdType> original = internal.Box.Enabled
    ? lsi::OriginalIds(geometry, internal.OriginalCount, internal.ImageOf)
    : std::vector<vtkIdType>();
  return lsi::FloodAcross(geometry, *internal.Ranks, original, internal.OriginalCount, dataOffsets,
    inSeed, inside, seedSamples, this->Stage(InitializationStage));
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
    return true;
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
  const double fit =
    lsi::MedianSupportPerNeighborhoodRadius(geometry, *field, values, this->IsoValue, ranks);
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
  const std::vector<double>& dataSign, const std::vector<double>& dataOffsets,
  const lsi::EvolutionSettings& settings, std::vector<double>& phi, vtkTable* iterations)
{
  const auto start = Clock::now();
  lsi::LevelSetEvolution evolution(geometry, dataSign, dataOffsets, phi);
  evolution.SetCommunicator(*this->Internal->Ranks);
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
  const std::vector<double>& dataOffsets, const std::vector<double>& evolvedPhi,
  const lsi::SurfaceScale& scale, const lsi::SPHField* field, lsi::IsopointSet& isopoints,
  lsi::IsopointSettings& settings)
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
  const std::vector<double> phi = lsi::WithoutSpuriousPockets(geometry, dataOffsets, evolvedPhi);
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
  vtkSMPTools::For(
    0, static_cast<vtkIdType>(geometry.NumberOfSamples), [&](vtkIdType begin, vtkIdType end) {
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

bool vtkLevelSetIsosurface::MakeSurfaceOutput(vtkPointSet* input,
  const lsi::Neighborhoods& geometry, const lsi::IsopointSet& isopoints,
  const std::vector<double>& nearbyPoints, const lsi::SPHField* field,
  const lsi::PointCloudIndex* surfaceIndex, vtkPolyData* output,
  const std::vector<double>* scalarsInStorageOrder)
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
  if (!lsi::MakeSurfacePoints(input->GetPointData(), geometry, aroundSeed ? moved : isopoints,
        this->SplatScale, this->InterpolateArrays, scalars ? scalars->GetName() : nullptr, field,
        surface, this->Stage(SurfaceStage), aroundSeed ? movedIndex.get() : surfaceIndex,
        aroundSeed ? &isopoints.Points : nullptr, scalarsInStorageOrder))
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
    if (!lsi::MakeSplatPolygons(
          found, this->SplatSides, field, this->IsoValue, output, this->Stage(SplatStage)))
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

lsi::AbortCheck vtkLevelSetIsosurface::Stage(const double range[2])
{
  return lsi::SubRange(
    [this](double progress) { return this->ProgressOrAbort(progress); }, range[0], range[1]);
}

bool vtkLevelSetIsosurface::ProgressOrAbort(double progress)
{
  if (progress >= 0.0)
  {
    this->UpdateProgress(progress);
  }
  return this->CheckAbort();
}

void vtkLevelSetIsosurface::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "SeedCenter: (" << this->SeedCenter[0] << ", " << this->SeedCenter[1] << ", "
     << this->SeedCenter[2] << ")\n";
  os << indent << "NumberOfAdditionalSeeds: " << this->GetNumberOfAdditionalSeeds() << "\n";
  os << indent << "BoxSize: (" << this->BoxSize[0] << ", " << this->BoxSize[1] << ", "
     << this->BoxSize[2] << ")\n";
  os << indent << "SmoothingLengthArray: " << this->SmoothingLengthArray << "\n";
  os << indent << "MassArray: " << this->MassArray << "\n";
  os << indent << "DensityArray: " << this->DensityArray << "\n";
  // Every other member, by name: parameters first, then the last execution's results.
  const std::pair<const char*, double> members[] = { { "IsoValue", this->IsoValue },
    { "SeedRadius", this->SeedRadius }, { "NumberOfNeighbors", this->NumberOfNeighbors },
    { "Epsilon", this->Epsilon }, { "CurvatureEpsilon", this->CurvatureEpsilon },
    { "TimeStep", this->TimeStep }, { "CurvatureWeight", this->CurvatureWeight },
    { "ReinitializationSteps", this->ReinitializationSteps },
    { "DistanceRegularization", this->DistanceRegularization },
    { "EvolutionScheme", this->EvolutionScheme },
    { "MaximumNumberOfIterations", this->MaximumNumberOfIterations },
    { "ConvergenceTolerance", this->ConvergenceTolerance },
    { "DataRefinement", this->DataRefinement }, { "Initialization", this->Initialization },
    { "Completion", this->Completion }, { "NumberOfThreads", this->NumberOfThreads },
    { "OutputType", this->OutputType }, { "SplatScale", this->SplatScale },
    { "SplatSides", this->SplatSides }, { "InterpolateArrays", this->InterpolateArrays },
    { "NeighborCacheSize", this->NeighborCacheSize }, { "Field", this->Field },
    { "Kernel", this->Kernel }, { "SupportPerSmoothingLength", this->SupportPerSmoothingLength },
    { "UsedSPHField", this->UsedSPHField }, { "Periodic", this->Periodic },
    { "PeriodicMargin", this->PeriodicMargin }, { "PeriodicOutput", this->PeriodicOutput },
    { "NeighborSearchCount", this->NeighborSearchCount }, { "FloodCount", this->FloodCount },
    { "ReusedLastOutputs", this->ReusedLastOutputs }, { "SlidLastSurface", this->SlidLastSurface },
    { "RemadeSurfaceOutput", this->RemadeSurfaceOutput },
    { "NumberOfIsopoints", static_cast<double>(this->NumberOfIsopoints) },
    { "NumberOfIterationsPerformed", this->NumberOfIterationsPerformed },
    { "Converged", this->Converged }, { "MeanSampleSpacing", this->MeanSampleSpacing },
    { "EffectiveEpsilon", this->EffectiveEpsilon },
    { "EffectiveCurvatureEpsilon", this->EffectiveCurvatureEpsilon },
    { "EffectiveTimeStep", this->EffectiveTimeStep } };
  for (const auto& member : members)
  {
    os << indent << member.first << ": " << member.second << "\n";
  }
}
