// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
// vtkLevelSetIsosurface's input: its checks, and where its particles are: spread over the MPI
// ranks with ghosts from the neighbouring ranks, and with their images in a periodic box.
#include "vtkLevelSetIsosurface.h"
#include "vtkLevelSetIsosurfaceInternals.h"

#include "LevelSetDistribution.h"
#include "LevelSetHaloReach.h"
#include "LevelSetInput.h"
#include "LevelSetIsopoints.h"
#include "LevelSetLastOutputs.h"
#include "LevelSetNeighborCache.h"
#include "LevelSetPeriodicImages.h"
#include "LevelSetSPHField.h"

#include "vtkDataArray.h"
#include "vtkDataSet.h"
#include "vtkInformation.h"
#include "vtkPointSet.h"
#include "vtkPolyData.h"

#include <algorithm>
#include <utility>

namespace
{
using lsi::AllListsStage;
// Under MPI, each rank receives the other ranks' particles within this many of its own
// particles' neighbourhood radii: enough for the initial signed distance (the reinitialised
// band, about 4.7 radii with the automatic Epsilon) plus one radius of whole neighbourhoods.
constexpr double HaloRadii = 6.0;
// Inputs with fewer particles per rank than this are gathered and processed on rank 0.
constexpr double SmallestSharePerRank = 2000.0;
} // namespace

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
    if (!piece)
    {
      if (this->ReportsForAll())
      {
        vtkErrorMacro(<< "The particles could not be spread over the ranks: " << report << ".");
      }
      return nullptr;
    }
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
