// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
// Accuracy against exact surfaces: the filter on an analytic case (Data/Synthetic), its isopoints
// scored against the case's exact isosurface. Thresholds are in units of the mean sample
// spacing on the surface, so they hold at any sample count. One sub-test per CTest test:
//   TestAccuracy NAME      (NAME from the table below)
#include "CaseRuns.h"
#include "SyntheticParticles.h"

#include <cstdlib>
#include <cstring>
#include <iostream>
#include <string>

namespace
{
using namespace lsi::cases;

struct AccuracyTest
{
  const char* Name;
  const char* CaseName;
  std::size_t Samples;
  int Scheme;
  int Initialization;
  bool PaperParameters;
  int MaximumIterations;
  double MeanDistance; // at most this many spacings; negative: not checked
  bool FullCoverage;   // every exact surface point of the seeded components within one spacing
  bool NoUnseeded;     // no isopoint on a component the seeds do not meet
  bool Converged;      // the evolution met its stopping rule
};

constexpr int Flood = vtkLevelSetIsosurface::FLOOD;
constexpr int Spheres = vtkLevelSetIsosurface::SEED_SPHERES;

const AccuracyTest Tests[] = {
  { "Sphere", "sphere", 100000, 0, Flood, false, 500, 0.2, true, false, true },
  { "OneComponent", "one-component", 200000, 0, Flood, false, 500, 0.35, true, false, true },
  // Coarse sampling (issue 17): the quadratic fit of the data refinement is unbiased by the
  // surface's curvature (0.0054 spacings measured; Delaunay 3D + Contour: 0.036).
  { "CoarseOneComponent", "one-component", 100000, 0, Flood, false, 500, 0.02, true, false, true },
  { "LocalityMultiComponent", "multi-component", 200000, 0, Flood, false, 500, 0.14, true, true,
    true },
  // The paper's parameters are absolute (tuned for spacing 1), so they run at the paper's size.
  { "PaperParametersOneComponent2M", "one-component", 2000000, 0, Spheres, true, 500, 0.35, false,
    false, false },
  { "PaperParametersMultiComponent2M", "multi-component", 2000000, 0, Spheres, true, 500, 0.14,
    false, true, false },
  { "SchemeWithoutReinitialization", "multi-component", 100000, 1, Flood, false, 300, -1.0, false,
    true, false },
  { "SeedSpheresOneComponent", "one-component", 200000, 0, Spheres, false, 500, 0.35, true, false,
    true },
  { "SchemeRosenthalLinsen", "one-component", 200000, 2, Flood, false, 500, 0.2, true, false,
    true },
};

int Run(const AccuracyTest& t)
{
  const std::unique_ptr<Case> c = MakeCase(t.CaseName);
  const std::vector<Eigen::Vector3d> samples = c->Samples(t.Samples, 1);
  vtkSmartPointer<vtkPolyData> particles = MakeParticles(*c, samples);
  const double spacing = c->SurfaceSpacing(t.Samples);
  vtkNew<vtkLevelSetIsosurface> filter;
  filter->SetInputData(particles);
  SetCaseInputs(filter, *c);
  filter->SetEvolutionScheme(t.Scheme);
  filter->SetInitialization(t.Initialization);
  filter->SetMaximumNumberOfIterations(t.MaximumIterations);
  if (t.PaperParameters)
  {
    SetPaperParameters(filter, *c);
  }
  double seconds = 0.0;
  const SurfaceMetrics m = RunAndMeasure(filter, *c, samples, spacing, seconds);
  std::cout << t.Name << ": " << c->Name << ", " << t.Samples << " samples, " << m.Isopoints
            << " isopoints, " << filter->GetNumberOfIterationsPerformed() << " iterations"
            << (filter->GetConverged() ? " (converged)" : " (limit)") << "\n  mean distance "
            << m.MeanDistance / spacing << " spacings, normal error " << m.MeanNormalAngleDegrees
            << " deg, coverage " << m.CoveredFraction << ", isopoints on unseeded components "
            << m.UnseededIsopoints << "\n";

  int failures = 0;
  auto check = [&](bool ok, const std::string& what) {
    if (!ok)
    {
      std::cerr << "FAILED: " << what << "\n";
      ++failures;
    }
  };
  check(m.Isopoints > 0, "no isopoints");
  if (t.MeanDistance > 0.0)
  {
    check(m.MeanDistance <= t.MeanDistance * spacing,
      "mean distance above " + std::to_string(t.MeanDistance) + " spacings");
    check(m.MaxNormalLengthError < 1e-5, "normals are not unit vectors");
    check(m.MeanNormalAngleDegrees < 8.0,
      "normals deviate from the exact outward normal by more than 8 degrees on average");
  }
  if (t.FullCoverage)
  {
    check(m.SurfaceProbes > 0 && m.CoveredFraction >= 1.0,
      "only a fraction " + std::to_string(m.CoveredFraction) +
        " of exact surface points lie within one spacing of an isopoint");
  }
  if (t.NoUnseeded)
  {
    check(m.UnseededIsopoints == 0,
      std::to_string(m.UnseededIsopoints) + " isopoints on unseeded components");
  }
  if (t.Converged)
  {
    check(filter->GetConverged(), "the evolution did not meet its stopping rule");
  }
  return failures ? EXIT_FAILURE : EXIT_SUCCESS;
}
} // namespace

int main(int argc, char* argv[])
{
  for (const AccuracyTest& t : Tests)
  {
    if (argc == 2 && std::strcmp(argv[1], t.Name) == 0)
    {
      return Run(t);
    }
  }
  std::cerr << "usage: TestAccuracy NAME, NAME one of:";
  for (const AccuracyTest& t : Tests)
  {
    std::cerr << " " << t.Name;
  }
  std::cerr << "\n";
  return EXIT_FAILURE;
}
