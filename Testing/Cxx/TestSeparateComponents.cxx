// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
// A component the seed does not touch stays outside, however near: on a noisy field with clumps
// near one another (the SPH density of uniform random particles, vtkParticleDensity, IsoValue its
// 90th percentile, as in a dark-matter box), no particle above the isovalue that the flood did
// not reach is inside after the evolution. Before the evolution kept to the flood's component,
// its forcing term pulled in every clump within its band (2 eps, several spacings) of the front,
// and each clump joined brought the next within reach: here 1,564 particles of other clumps
// joined the seed's 125; on ChaNGa's cosmological box (changa_cube300.tbin) raising the isovalue
// by 2e-4 of itself grew the seed's component from 825 particles to 11,711.
#include "vtkLevelSetIsosurface.h"
#include "vtkParticleDensity.h"

#include "TestCheck.h"

#include "vtkDataArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"

#include <algorithm>
#include <cstdlib>
#include <iostream>
#include <random>
#include <string>
#include <vector>

namespace
{
// The particles' LevelSet after a run with the given iteration limit (0: the flood's start).
std::vector<double> LevelSetAfter(
  vtkPolyData* particles, double isoValue, const double seed[3], double radius, int iterations)
{
  vtkNew<vtkLevelSetIsosurface> filter;
  filter->SetInputData(particles);
  filter->SetIsoValue(isoValue);
  filter->SetSeedCenter(seed);
  filter->SetSeedRadius(radius);
  filter->SetOutputTypeToIsopoints();
  if (iterations >= 0)
  {
    filter->SetMaximumNumberOfIterations(iterations);
  }
  filter->Update();
  std::vector<double> phi;
  vtkDataArray* array = filter->GetOutput(1)->GetPointData()->GetArray("LevelSet");
  for (vtkIdType i = 0; array && i < array->GetNumberOfTuples(); ++i)
  {
    phi.push_back(array->GetTuple1(i));
  }
  return phi;
}

// A noisy field with clumps near one another, as in a dark-matter box: the SPH density
// (vtkParticleDensity) of uniform random particles, IsoValue its 90th percentile, the seed at the
// densest particle. No particle above the isovalue that the flood did not reach (outside at the
// start, a run of 0 iterations) may be inside after the evolution.
void ClumpsNearOneAnother()
{
  using lsi::test::Check;
  std::mt19937_64 random(5);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  for (int i = 0; i < 40000; ++i)
  {
    points->InsertNextPoint(u(random), u(random), u(random));
  }
  vtkNew<vtkPolyData> uniform;
  uniform->SetPoints(points);
  vtkNew<vtkParticleDensity> density;
  density->SetInputData(uniform);
  density->Update();
  vtkPolyData* particles = vtkPolyData::SafeDownCast(density->GetOutput());
  vtkDataArray* rho = particles->GetPointData()->GetArray("Density");
  std::vector<double> values(rho->GetNumberOfTuples());
  vtkIdType densest = 0;
  for (vtkIdType i = 0; i < rho->GetNumberOfTuples(); ++i)
  {
    values[i] = rho->GetTuple1(i);
    densest = values[i] > values[densest] ? i : densest;
  }
  std::vector<double> sorted = values;
  std::nth_element(sorted.begin(), sorted.begin() + sorted.size() * 9 / 10, sorted.end());
  const double isoValue = sorted[sorted.size() * 9 / 10];
  double seed[3];
  particles->GetPoint(densest, seed);
  const double radius = particles->GetPointData()->GetArray("SmoothingLength")->GetTuple1(densest);
  const std::vector<double> start = LevelSetAfter(particles, isoValue, seed, radius, 0);
  const std::vector<double> end = LevelSetAfter(particles, isoValue, seed, radius, -1);
  std::size_t joined = 0, reached = 0, inside = 0;
  for (std::size_t i = 0; i < start.size() && i < end.size(); ++i)
  {
    const bool above = values[i] > isoValue;
    reached += above && start[i] > 0.0 ? 1 : 0;
    inside += above && end[i] > 0.0 ? 1 : 0;
    joined += above && end[i] > 0.0 && !(start[i] > 0.0) ? 1 : 0;
  }
  std::cout << "clumps: the flood reached " << reached << " particles above the isovalue, "
            << inside << " are inside after the evolution, " << joined
            << " of them from other clumps\n";
  Check(reached > 50 && start.size() == end.size() && joined == 0,
    "clumps: no particle of a clump the flood did not reach is inside (" + std::to_string(joined) +
      " of " + std::to_string(inside) + ")");
}

} // namespace

int main()
{
  ClumpsNearOneAnother();
  return lsi::test::Failures() ? EXIT_FAILURE : EXIT_SUCCESS;
}
