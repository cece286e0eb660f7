// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
// vtkLevelSetIsosurface's properties and its run: RequestData, Execute (the method's steps in
// order), progress and abort. Its input, steps, outputs and re-runs are in the files
// vtkLevelSetIsosurface{Input,Steps,Outputs,ReRuns}.cxx.
#include "vtkLevelSetIsosurface.h"
#include "vtkLevelSetIsosurfaceInternals.h"

#include "LevelSetConvergenceTable.h"
#include "LevelSetDistribution.h"
#include "LevelSetDuplicates.h"
#include "LevelSetEnclosed.h"
#include "LevelSetInput.h"
#include "LevelSetIsopoints.h"
#include "LevelSetLastOutputs.h"
#include "LevelSetParameters.h"
#include "LevelSetPeriodicImages.h"
#include "LevelSetSPHField.h"
#include "LevelSetTiming.h"

#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkMultiProcessController.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointSet.h"
#include "vtkPolyData.h"
#include "vtkSMPTools.h"
#include "vtkTable.h"

#include <algorithm>
#include <utility>

vtkStandardNewMacro(vtkLevelSetIsosurface);

namespace
{
using lsi::SecondsSince;
using lsi::SPHFieldStage;

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
  std::vector<double> dataOffsets; // f - f_iso, in storage order
  bool ok = true;
  if (!field)
  {
    lsi::DataInStorageOrder(*geometry, values, this->IsoValue, dataOffsets);
  }
  else
  {
    ok = lsi::SPHOffsetsAtSamples(
      *geometry, *field, this->IsoValue, dataOffsets, this->Stage(SPHFieldStage));
  }
  if (!ranks.All(ok))
  {
    return false;
  }
  // A ghost at the halo's edge misses part of its kernel sum: its owner's value is the serial one.
  ranks.RefreshGhosts(dataOffsets);
  const lsi::SurfaceScale scale = lsi::ScaleAtSurface(*geometry, dataOffsets, ranks);
  const lsi::EvolutionSettings settings = this->ChooseEvolutionSettings(scale);
  this->InputSeconds += SecondsSince(inputStart);
  std::vector<double> phi;
  if (!this->Initialize(input, *geometry, dataOffsets, field.get(), settings, phi))
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
  // The flood's component: the evolution smooths its front and joins no other component.
  std::vector<char> flooded;
  if (this->Initialization == FLOOD && !last.QuickCheck)
  {
    flooded = lsi::LastOutputs::InsideOf(phi);
  }
  const std::vector<char>* component =
    this->Initialization != FLOOD ? nullptr : (last.QuickCheck ? &last.Inside : &flooded);
  if (!this->Evolve(*geometry, dataOffsets, component, settings, phi, iterations))
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
  // (For re-runs that show these points slid, or again: their splat radii's candidates.)
  last.Splats.Clear();
  const bool keepSplats = this->QuickIsoValueChanges && last.QuickCheck;
  ok = this->MakeSurfaceOutput(input, *geometry, isopoints, nearby.Points, field.get(),
    surfaceIndex.get(), surfaceOutput, nullptr, keepSplats ? &last.Splats : nullptr);
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
    last.Splats.Clear();
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
      if (!original)
      {
        return false; // (on every rank: the exchange failed on all)
      }
    }
    work = this->WithPeriodicImages(original, values);
    geometry = work ? this->FindNeighborhoods(work->GetPoints(), true) : nullptr;
  }
  if (!keptGhosts && geometry && geometry->DuplicateSamples > 0)
  {
    values.resize(static_cast<std::size_t>(original->GetNumberOfPoints())); // images appended
    vtkIdType merged = 0;
    // On the SPH field the masses are summed (the field keeps each group's mass).
    vtkDataArray* mass = lsi::MarkedMassArray(original, this->MassArray);
    vtkSmartPointer<vtkPointSet> distinct =
      lsi::MergeDuplicatePoints(original, values, mergedId, merged, mass);
    vtkWarningMacro(<< merged << " points coincide with another point (for example point "
                    << geometry->FirstDuplicate << "): each group was merged into one, its values "
                    << "averaged"
                    << (mass ? std::string(", its masses (") + mass->GetName() +
                             ") summed (once per global id)"
                             : std::string())
                    << ", integer arrays its smallest value.");
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
