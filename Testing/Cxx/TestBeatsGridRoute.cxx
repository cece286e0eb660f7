// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
// On the same particles, the filter beats the grid route a ParaView user takes today (SPH
// interpolation, Flying Edges, connectivity; Testing/Support/GridRoute.h) in mean distance and
// normal error against the exact surface, covers the exact surface, and stays on the seeded
// components. One case per CTest test:
//   TestBeatsGridRoute one-component|adaptive-noisy
#include "CaseRuns.h"
#include "SyntheticParticles.h"

#include <cstdlib>
#include <iostream>

int main(int argc, char* argv[])
{
  using namespace lsi::cases;
  const std::unique_ptr<Case> c = argc == 2 ? MakeCase(argv[1]) : nullptr;
  if (!c)
  {
    std::cerr << "usage: TestBeatsGridRoute one-component|multi-component|adaptive-noisy\n";
    return EXIT_FAILURE;
  }
  const std::size_t count = 300000;
  const std::vector<Eigen::Vector3d> samples = c->Samples(count, 1);
  vtkSmartPointer<vtkPolyData> particles = MakeParticles(*c, samples);
  const double spacing = c->SurfaceSpacing(count);

  vtkNew<vtkLevelSetIsosurface> filter;
  filter->SetInputData(particles);
  SetCaseInputs(filter, *c);
  double seconds = 0.0;
  const SurfaceMetrics ours = RunAndMeasure(filter, *c, samples, spacing, seconds);
  lsi::GridRouteResult grid;
  const SurfaceMetrics theirs = RunAndMeasureGridRoute(particles, *c, samples, spacing, 0, grid);
  std::cout << c->Name << ", " << count << " samples (distances in spacings)\n"
            << "  level set : distance " << ours.MeanDistance / spacing << ", normal error "
            << ours.MeanNormalAngleDegrees << " deg, coverage " << ours.CoveredFraction
            << ", on unseeded components " << ours.UnseededIsopoints << "\n"
            << "  grid route: distance " << theirs.MeanDistance / spacing << ", normal error "
            << theirs.MeanNormalAngleDegrees << " deg\n";
  if (!(ours.Isopoints > 0 && ours.MeanDistance < theirs.MeanDistance &&
        ours.MeanNormalAngleDegrees < theirs.MeanNormalAngleDegrees &&
        ours.CoveredFraction >= 0.999 && ours.UnseededIsopoints == 0))
  {
    std::cerr << "FAILED: the level set does not beat the grid route\n";
    return EXIT_FAILURE;
  }
  return EXIT_SUCCESS;
}
