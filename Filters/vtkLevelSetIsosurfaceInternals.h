// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
// What vtkLevelSetIsosurface's two source files share: its state between executions and the
// parts of [0, 1] over which each stage reports progress. Private to the filter.
#ifndef vtkLevelSetIsosurfaceInternals_h
#define vtkLevelSetIsosurfaceInternals_h

#include "vtkLevelSetIsosurface.h"

#include "LevelSetDistribution.h"
#include "LevelSetLastOutputs.h"
#include "LevelSetNeighborCache.h"
#include "LevelSetPeriodicImages.h"

#include "vtkCellArray.h"
#include "vtkDoubleArray.h"
#include "vtkPointSet.h"
#include "vtkSmartPointer.h"

#include <memory>
#include <string>
#include <vector>

namespace lsi
{
// Each stage reports its progress over its own part of [0, 1], in proportion to its time.
constexpr double NeighborStage[2] = { 0.02, 0.33 };
constexpr double AllListsStage[2] = { 0.30, 0.33 }; // its end, under MPI or in a periodic box
constexpr double SPHFieldStage[2] = { 0.33, 0.35 };
constexpr double InitializationStage[2] = { 0.35, 0.45 };
constexpr double EvolutionStage[2] = { 0.45, 0.8 };
constexpr double IsopointStage[2] = { 0.8, 0.92 };
constexpr double SurfaceStage[2] = { 0.92, 0.98 };
constexpr double SplatStage[2] = { 0.98, 1.0 };

// The particles a full run works on (vtkLevelSetIsosurface::PrepareParticles).
struct RunParticles
{
  vtkSmartPointer<vtkPointSet> Original;   // the input's (this rank's share under MPI)
  vtkSmartPointer<vtkPointSet> Work;       // distinct, with their periodic images and MPI ghosts
  const Neighborhoods* Geometry = nullptr; // Work's
  std::vector<double> Values;              // f over Work's points, in their order
  std::vector<vtkIdType> MergedId;         // input id -> merged point, when duplicates were merged
  bool Idle = false; // under MPI, a rank left without particles by an input too small to spread
};
} // namespace lsi

struct vtkLevelSetIsosurface::Internals
{
  lsi::NeighborCache Cache;
  // This execution's periodic box: the input's points come first, then their ghost images.
  lsi::PeriodicBox Box;
  vtkIdType OriginalCount = 0;
  std::vector<vtkIdType> ImageOf;
  double SeedCenter[3] = { 0.0, 0.0, 0.0 }; // the main seed's centre, for AROUND_SEED
  lsi::Distribution* Ranks = nullptr;       // this execution's MPI ranks
  lsi::LastOutputs Last;                    // for the re-runs that reuse the last run
  // The last run's MPI ranks with its ghosts (Last.Work), when a seed move may reuse that run.
  std::unique_ptr<lsi::Distribution> LastRanks;
  vtkSmartPointer<vtkCellArray> ParticleVertices; // the particle output's, for any run's reuse
  // The LevelSet array of the output before the last, for the next output to reuse its memory
  // (lsi::MakeParticleOutput) if nothing else holds it by then.
  vtkSmartPointer<vtkDoubleArray> SpareLevelSet;
  // With no Scalars named, the name of the input's active point scalars (InputScalars): looked
  // up by name on the filter's copies of the input, which do not mark them.
  std::string ActiveScalarsName;
};

#endif
