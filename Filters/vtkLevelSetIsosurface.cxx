// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkLevelSetIsosurface.h"

#include "LevelSetConvergenceTable.h"
#include "LevelSetDuplicates.h"
#include "LevelSetEnclosed.h"
#include "LevelSetEvolution.h"
#include "LevelSetFlood.h"
#include "LevelSetInput.h"
#include "LevelSetIsopoints.h"
#include "LevelSetNeighborCache.h"
#include "LevelSetParameters.h"
#include "LevelSetParticleOutput.h"
#include "LevelSetPeriodicImages.h"
#include "LevelSetSPHField.h"
#include "LevelSetSeedSpheres.h"
#include "LevelSetSplatOutput.h"
#include "LevelSetSurfaceOutput.h"
#include "LevelSetTiming.h"
#include "LevelSetVertexCells.h"

#include "vtkDataArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPointSet.h"
#include "vtkPolyData.h"
#include "vtkSMPTools.h"
#include "vtkTable.h"

#include <algorithm>
#include <cstdint>
#include <utility>

vtkStandardNewMacro(vtkLevelSetIsosurface);

namespace
{
using lsi::Clock;
using lsi::SecondsSince;

// Each stage reports its progress over its own part of [0, 1], in proportion to its time.
constexpr double NeighborStage[2] = { 0.02, 0.33 };
constexpr double SPHFieldStage[2] = { 0.33, 0.35 };
constexpr double InitializationStage[2] = { 0.35, 0.45 };
constexpr double EvolutionStage[2] = { 0.45, 0.8 };
constexpr double IsopointStage[2] = { 0.8, 0.92 };
constexpr double SurfaceStage[2] = { 0.92, 0.98 };
constexpr double SplatStage[2] = { 0.98, 1.0 };
} // namespace

struct vtkLevelSetIsosurface::Internals
{
  lsi::NeighborCache Cache;
  // This execution's periodic box: the input's points come first, then their ghost images.
  lsi::PeriodicBox Box;
  vtkIdType OriginalCount = 0;
  std::vector<vtkIdType> ImageOf;
  double SeedCenter[3] = { 0.0, 0.0, 0.0 }; // the main seed's centre, for AROUND_SEED
};

vtkLevelSetIsosurface::vtkLevelSetIsosurface()
  : Internal(new Internals)
{
  this->SetNumberOfOutputPorts(4);
  this->SetInputArrayToProcess(
    0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, vtkDataSetAttributes::SCALARS);
}

vtkLevelSetIsosurface::~vtkLevelSetIsosurface() = default;

void vtkLevelSetIsosurface::AddAdditionalSeed(double cx, double cy, double cz, double radius)
{
  this->AdditionalSeeds.insert(this->AdditionalSeeds.end(), { cx, cy, cz, radius });
  this->Modified();
}

void vtkLevelSetIsosurface::RemoveAllAdditionalSeeds()
{
  if (!this->AdditionalSeeds.empty())
  {
    this->AdditionalSeeds.clear();
    this->Modified();
  }
}

void vtkLevelSetIsosurface::SetNumberOfAdditionalSeedValues(int count)
{
  const std::size_t size = static_cast<std::size_t>(std::max(0, count));
  if (size != this->AdditionalSeeds.size())
  {
    this->AdditionalSeeds.resize(size, 0.0);
    this->Modified();
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
    this->Modified();
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
    return this->GetAbortExecute() ? 1 : 0;
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
  std::vector<double> values; // f, in input order
  if (!this->ValidateInput(input, values))
  {
    return false;
  }
  vtkSmartPointer<vtkPointSet> original = input;
  vtkSmartPointer<vtkPointSet> work = this->WithPeriodicImages(input, values);
  const lsi::Neighborhoods* geometry =
    work ? this->FindNeighborhoods(work->GetPoints(), true) : nullptr;
  if (!geometry)
  {
    return false;
  }
  std::vector<vtkIdType> mergedId; // input id -> merged point, when duplicates were merged
  if (geometry->DuplicateSamples > 0)
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
    if (!geometry)
    {
      return false;
    }
  }
  input = work; // from here on: the distinct particles and their ghost images, if any
  std::unique_ptr<lsi::SPHField> field; // null: the MLS fit of the samples
  if (!this->BuildSPHField(input, *geometry, values, field))
  {
    return false;
  }
  this->CheckPeriodicMargin(*geometry, field.get());
  std::vector<double> dataOffsets, dataSign; // f - f_iso and its sign, in storage order
  if (!field)
  {
    lsi::DataInStorageOrder(*geometry, values, this->IsoValue, dataOffsets, dataSign);
  }
  else if (!lsi::SPHOffsetsAtSamples(
             *geometry, *field, this->IsoValue, dataOffsets, dataSign, this->Stage(SPHFieldStage)))
  {
    return false;
  }
  const lsi::SurfaceScale scale = lsi::ScaleAtSurface(*geometry, dataSign);
  const lsi::EvolutionSettings settings = this->ChooseEvolutionSettings(scale);
  std::vector<double> phi;
  if (!this->Initialize(input, *geometry, dataOffsets, settings, phi))
  {
    return false;
  }
  vtkNew<vtkTable> iterations = lsi::EmptyConvergenceTable();
  if (!this->Evolve(*geometry, dataSign, dataOffsets, settings, phi, iterations))
  {
    return false;
  }
  lsi::IsopointSet isopoints;
  if (!this->ExtractIsopoints(*geometry, dataOffsets, phi, scale, field.get(), isopoints))
  {
    return false;
  }
  if (!this->MakeSurfaceOutput(input, *geometry, isopoints, field.get(), surfaceOutput))
  {
    return false;
  }
  lsi::MakeParticleOutput(original, *geometry, phi, mergedId, particleOutput);
  lsi::EnclosedInputs inside;
  inside.Geometry = geometry;
  inside.Phi = &phi;
  inside.Particles = input;
  inside.ParticleCount = this->Internal->OriginalCount;
  inside.OriginalIds =
    lsi::OriginalIds(*geometry, this->Internal->OriginalCount, this->Internal->ImageOf);
  inside.Box = this->Internal->Box;
  inside.Mass = lsi::MarkedMassArray(input, this->MassArray);
  inside.Density = lsi::MarkedDensityArray(input, this->DensityArray);
  inside.SurfacePoints = &isopoints.Points;
  inside.SurfaceNormals = &isopoints.Normals;
  enclosed->ShallowCopy(lsi::EnclosedTable(inside));
  convergence->ShallowCopy(iterations);
  // An abort that arrived during the last stage still empties the outputs.
  return !this->ProgressOrAbort(1.0);
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
    vtkErrorMacro(<< badParameter);
    return false;
  }
  int association = -1;
  vtkDataArray* scalars = this->GetInputArrayToProcess(0, input, association);
  const std::string problem = lsi::CheckInput(input, scalars, association, this->NumberOfNeighbors,
    this->IsoValue, this->AdditionalSeeds, values);
  if (!problem.empty())
  {
    vtkErrorMacro(<< problem);
    return false;
  }
  return true;
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
  input->GetBounds(bounds);
  if (!lsi::PlaceBox(internal.Box, bounds, 0.5 * this->PeriodicMargin))
  {
    vtkWarningMacro("The particles (from "
      << bounds[0] << ", " << bounds[2] << ", " << bounds[4] << " to " << bounds[1] << ", "
      << bounds[3] << ", " << bounds[5]
      << ") lie neither in the periodic box [0, BoxSize) nor in one centred on 0 (BoxSize "
      << internal.Box.Size[0] << ", " << internal.Box.Size[1] << ", " << internal.Box.Size[2]
      << "): the box is not taken as periodic. Set BoxSize, or turn Periodic off to silence "
         "this.");
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

bool vtkLevelSetIsosurface::FollowAcrossFaces(const lsi::Neighborhoods& geometry,
  const std::vector<double>& dataOffsets, const lsi::EvolutionSettings& settings,
  std::vector<char>& inSeed, std::vector<double>& phi)
{
  const Internals& internal = *this->Internal;
  if (!internal.Box.Enabled)
  {
    return true;
  }
  // A particle and its images are one particle: where the flood reached one of them, it seeds
  // the others, and the flood runs again, until no new particle joins (a component that wraps
  // through several faces takes a few rounds).
  const std::vector<vtkIdType> original =
    lsi::OriginalIds(geometry, internal.OriginalCount, internal.ImageOf);
  for (int round = 0; round < 8; ++round)
  {
    std::vector<char> reached(static_cast<std::size_t>(internal.OriginalCount), 0);
    for (std::size_t i = 0; i < geometry.NumberOfSamples; ++i)
    {
      reached[original[i]] |= phi[i] > 0.0 ? 1 : 0;
    }
    bool added = false;
    for (std::size_t i = 0; i < geometry.NumberOfSamples; ++i)
    {
      if (reached[original[i]] && !inSeed[i] && !(phi[i] > 0.0) && dataOffsets[i] > 0.0)
      {
        inSeed[i] = 1;
        added = true;
      }
    }
    if (!added)
    {
      return true;
    }
    const lsi::FloodResult flood = lsi::FloodedSignedDistance(geometry, dataOffsets, inSeed,
      static_cast<std::size_t>(geometry.Stride), lsi::ReinitializationHalfWidth(settings), phi,
      this->Stage(InitializationStage));
    if (flood.Aborted)
    {
      return false;
    }
  }
  return true;
}

void vtkLevelSetIsosurface::KeepPeriodicCell(lsi::IsopointSet& isopoints)
{
  const Internals& internal = *this->Internal;
  if (!internal.Box.Enabled)
  {
    return;
  }
  // Every piece of surface is found once in the box and again in the images: keep the box,
  // then, around the seed, move each point by whole boxes into the cell centred on the seed.
  std::vector<char> kept(isopoints.Points.size() / 3);
  for (std::size_t i = 0; i < kept.size(); ++i)
  {
    kept[i] = lsi::InKeptCell(&isopoints.Points[3 * i], internal.Box, nullptr) ? 1 : 0;
  }
  lsi::IsopointSet inCell;
  lsi::AppendSelected(isopoints.Points, isopoints.Normals, lsi::ValidIndices(kept), inCell);
  isopoints.Points.swap(inCell.Points);
  isopoints.Normals.swap(inCell.Normals);
  if (this->PeriodicOutput == AROUND_SEED)
  {
    lsi::IntoCellAround(isopoints.Points, internal.Box, internal.SeedCenter);
  }
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
  if (searched)
  {
    ++this->NeighborSearchCount;
    this->NeighborSearchSeconds = SecondsSince(start);
    this->SpatialSortSeconds = geometry->SortSeconds;
    this->NearestNeighborSeconds = geometry->SearchSeconds;
    this->TreeBuildSeconds = geometry->TreeSeconds;
  }
  // The MLS gradient stencils are stored as floats (half the memory), in the data's unit of
  // length: their coefficients go as 1 / spacing, so spacings beyond 1e30 or below 1e-30
  // would overflow or vanish in float. Refuse them with a clear error instead.
  if (!(geometry->MeanRadius > 1e-30 && geometry->MeanRadius < 1e30))
  {
    vtkErrorMacro("The particles' neighbourhood radius is " << geometry->MeanRadius
                                                            << " in the data's unit of length, "
                                                               "outside the range 1e-30 to 1e30 "
                                                               "that the method's float stencils "
                                                               "hold: rescale the coordinates "
                                                               "(for example with Transform).");
    return nullptr;
  }
  // Duplicates are merged by the caller (MergeDuplicates), then searched again.
  const std::string problem = lsi::CheckNeighborhoods(*geometry);
  if (!problem.empty() && !(duplicatesAllowed && geometry->DuplicateSamples > 0))
  {
    vtkErrorMacro(<< problem);
    return nullptr;
  }
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
    vtkWarningMacro(<< concern);
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
  double bounds[6];
  input->GetBounds(bounds);
  const std::vector<double> spheres =
    lsi::SeedSpheres(this->SeedCenter, this->SeedRadius, this->AdditionalSeeds, bounds);
  for (int d = 0; d < 3; ++d) // the kept periodic cell's centre: the main seed, else the box's
  {
    this->Internal->SeedCenter[d] = spheres.empty()
      ? this->Internal->Box.Origin[d] + 0.5 * this->Internal->Box.Size[d]
      : spheres[d];
  }
  const lsi::SeedSphereStart seeds =
    lsi::SeedSphereDistance(geometry, spheres, bounds, 0.5 * settings.Spacing, phi);
  const std::string problem = lsi::CheckSeedSpheres(spheres, seeds.SamplesPerSphere);
  if (!problem.empty())
  {
    vtkErrorMacro(<< problem);
    return false;
  }
  if (this->Initialization == FLOOD)
  {
    const lsi::FloodResult flood = lsi::FloodedSignedDistance(geometry, dataOffsets, seeds.InSeed,
      static_cast<std::size_t>(geometry.Stride), lsi::ReinitializationHalfWidth(settings), phi,
      this->Stage(InitializationStage));
    std::vector<char> inSeed = seeds.InSeed;
    if (flood.Aborted || !this->FollowAcrossFaces(geometry, dataOffsets, settings, inSeed, phi))
    {
      return false;
    }
    if (flood.SeedSamples == 0)
    {
      vtkErrorMacro("No sample inside the seed sphere(s) has a value above IsoValue "
        << this->IsoValue << ": there is nothing to flood. Move the seed into the object.");
      return false;
    }
  }
  this->InitializationSeconds = SecondsSince(start);
  return true;
}

bool vtkLevelSetIsosurface::BuildSPHField(vtkPointSet* input, const lsi::Neighborhoods& geometry,
  const std::vector<double>& values, std::unique_ptr<lsi::SPHField>& field)
{
  this->UsedSPHField = false;
  lsi::SPHFieldRequest request;
  request.Model = this->Field;
  request.Kernel = this->Kernel;
  request.SupportPerSmoothingLength = this->SupportPerSmoothingLength;
  request.SmoothingLengthArray = this->SmoothingLengthArray;
  request.MassArray = this->MassArray;
  request.DensityArray = this->DensityArray;
  int association = -1;
  vtkDataArray* scalars = this->GetInputArrayToProcess(0, input, association);
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
  const double fit =
    lsi::MedianSupportPerNeighborhoodRadius(geometry, *field, values, this->IsoValue);
  if (fit < 0.5)
  {
    if (this->Field == AUTOMATIC_FIELD)
    {
      vtkWarningMacro("The smoothing lengths do not fit these particles: at the surface the "
                      "median kernel support is "
        << fit << " times the median distance to the " << geometry.Stride - 1
        << "th neighbour (real SPH supports hold 30 or more neighbours). Using the MLS fit of "
           "the samples; set Field to SPH to use them anyway, or make them with Particle "
           "Density.");
      field.reset();
      return true;
    }
    vtkWarningMacro("The smoothing lengths look too small for these particles: the median kernel "
                    "support is "
      << fit << " times the median distance to the " << geometry.Stride - 1
      << "th neighbour. The SPH field is used, as Field asks, but it is spiky.");
  }
  if (field->SummedDensities > 0)
  {
    vtkWarningMacro(<< field->SummedDensities << " particles have a density that is not positive "
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
  if (!this->Converged)
  {
    vtkWarningMacro("The evolution stopped at MaximumNumberOfIterations ("
      << this->MaximumNumberOfIterations
      << ") before its stopping rule held: the front was still moving, so the surface may be "
         "wrong. Raise MaximumNumberOfIterations, or check TimeStep and Epsilon.");
  }
  return !this->ProgressOrAbort(EvolutionStage[1]);
}

bool vtkLevelSetIsosurface::ExtractIsopoints(const lsi::Neighborhoods& geometry,
  const std::vector<double>& dataOffsets, const std::vector<double>& evolvedPhi,
  const lsi::SurfaceScale& scale, const lsi::SPHField* field, lsi::IsopointSet& isopoints)
{
  // Sub-stages in proportion to their times at 2M samples: isopoints 28%, completion 48%,
  // refinement on the data 24%.
  const lsi::AbortCheck stage = this->Stage(IsopointStage);
  const auto start = Clock::now();
  lsi::IsopointSettings settings = lsi::ChooseIsopointSettings(this->RequestedParameters(), scale);
  if (field)
  {
    // The SPH field is exact between the particles: sample the surface twice as densely, so
    // that the splats (whose corners are solved onto the level) are small against its curvature
    // where the particles are sparse.
    settings.CellSize *= 0.5;
  }
  const std::vector<double> phi = lsi::WithoutSpuriousPockets(geometry, dataOffsets, evolvedPhi);
  if (!lsi::ExtractIsopoints(geometry, phi, settings, isopoints, lsi::SubRange(stage, 0.0, 0.28)))
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
    !lsi::AddFreeBoundaryPoints(geometry, *field, this->IsoValue, phi, dataOffsets, settings,
      isopoints, lsi::SubRange(stage, 1.0, 1.0)))
  {
    return false;
  }
  this->DataRefinementSeconds = SecondsSince(partStart);
  this->KeepPeriodicCell(isopoints);
  if (isopoints.Points.empty())
  {
    // Valid inputs, no surface: say why, rather than return an empty output silently.
    const auto above = std::count_if(
      dataOffsets.begin(), dataOffsets.end(), [](double offset) { return offset > 0.0; });
    const auto inside =
      std::count_if(evolvedPhi.begin(), evolvedPhi.end(), [](double phi) { return phi > 0.0; });
    vtkWarningMacro("No isosurface was found: "
      << above << " of " << dataOffsets.size() << " samples lie above IsoValue " << this->IsoValue
      << ", " << inside
      << " of them in the seeded region after the evolution. A component needs more samples "
         "than one neighbourhood (NumberOfNeighbors + 1 = "
      << geometry.Stride
      << ") to be found: lower IsoValue, move or enlarge the seed, or use fewer "
         "NumberOfNeighbors.");
  }
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

bool vtkLevelSetIsosurface::MakeSurfaceOutput(vtkPointSet* input,
  const lsi::Neighborhoods& geometry, const lsi::IsopointSet& isopoints, const lsi::SPHField* field,
  vtkPolyData* output)
{
  const auto start = Clock::now();
  int association = -1;
  vtkDataArray* scalars = this->GetInputArrayToProcess(0, input, association);
  vtkNew<vtkPolyData> surface;
  if (!lsi::MakeSurfacePoints(input->GetPointData(), geometry, isopoints, this->SplatScale,
        this->InterpolateArrays, scalars ? scalars->GetName() : nullptr, field, surface,
        this->Stage(SurfaceStage)))
  {
    return false;
  }
  this->NumberOfIsopoints = surface->GetNumberOfPoints();
  if (this->OutputType == SPLATS)
  {
    if (!lsi::MakeSplatPolygons(
          surface, this->SplatSides, field, this->IsoValue, output, this->Stage(SplatStage)))
    {
      return false;
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
    { "NeighborSearchCount", this->NeighborSearchCount },
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
