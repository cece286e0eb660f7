// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
// GatherAndSolveOntoLevel (a quarter-reach gather with Newton's steps first, the whole reach
// only when needed) against a gather for the whole reach and SolveOntoLevel, as the data
// refinement and the quick isovalue change did before: on the SPH field of a jittered lattice
// of particles with varied smoothing lengths (a Gaussian bump of density), from points at
// every distance from the level up to the reach and beyond, along tilted directions:
//   - the same success, point and normal, to the bit, for every start;
//   - both ways taken: starts the quarter-reach gather settles and starts it hands over;
// and ValueAt (the field without its gradient) against Evaluate's value, to the bit.
#include "LevelSetNeighborhoods.h"
#include "LevelSetSPHField.h"
#include "TestCheck.h"

#include "vtkDoubleArray.h"
#include "vtkNew.h"
#include "vtkPoints.h"

#include <cmath>
#include <initializer_list>
#include <iostream>
#include <random>
#include <string>
#include <vector>

namespace
{
using lsi::test::Check;

void TestSameAsWholeReach()
{
  std::mt19937 random(11);
  std::uniform_real_distribution<double> unit(-0.5, 0.5);
  const int side = 24;
  const double spacing = 1.0 / side;
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  vtkNew<vtkDoubleArray> h, mass;
  h->SetName("h");
  mass->SetName("m");
  for (int i = 0; i < side; ++i)
  {
    for (int j = 0; j < side; ++j)
    {
      for (int k = 0; k < side; ++k)
      {
        const double x[3] = { (i + 0.5 + 0.3 * unit(random)) * spacing - 0.5,
          (j + 0.5 + 0.3 * unit(random)) * spacing - 0.5,
          (k + 0.5 + 0.3 * unit(random)) * spacing - 0.5 };
        points->InsertNextPoint(x);
        const double r2 = x[0] * x[0] + x[1] * x[1] + x[2] * x[2];
        mass->InsertNextValue(std::exp(-8.0 * r2)); // density peaks at the centre
        h->InsertNextValue((1.6 + 0.4 * unit(random)) * spacing);
      }
    }
  }
  lsi::Neighborhoods geometry;
  Check(lsi::BuildNeighborhoods(points, 24, geometry, lsi::AbortCheck()), "neighbourhoods built");
  lsi::SPHFieldArrays arrays;
  arrays.SmoothingLength = h;
  arrays.Mass = mass;
  arrays.ValuesAreDensity = true;
  arrays.SupportPerSmoothingLength = 2.0;
  std::string problem;
  const lsi::SPHField field(geometry, arrays, std::vector<double>(), problem);
  Check(field.Valid() && problem.empty(), "the SPH field is valid");
  double centre[3] = { 0.0, 0.0, 0.0 }, g[3];
  double peak;
  field.Evaluate(centre, peak, g);
  const double isoValue = 0.5 * peak; // a closed level around the centre, inside the lattice

  int starts = 0, same = 0, settledNear = 0, handedOver = 0, solved = 0;
  lsi::SPHCandidates candidates;
  for (int n = 0; n < 600; ++n)
  {
    // A start on a random ray, at a random radius; the direction tilted from the ray.
    Eigen::Vector3d ray(unit(random), unit(random), unit(random));
    ray.normalize();
    const Eigen::Vector3d start = (0.05 + 0.35 * (unit(random) + 0.5)) * ray;
    const Eigen::Vector3d direction =
      (ray + 0.3 * Eigen::Vector3d(unit(random), unit(random), unit(random))).normalized();
    const double reach = 3.0 * spacing;
    Eigen::Vector3d a = start, b = start, na(0, 0, 0), nb(0, 0, 0);
    field.Gather(a.data(), reach, candidates);
    const bool okA =
      lsi::SolveOntoLevel(field, candidates, isoValue, a, direction, reach, 1e-9 * reach, na);
    const bool okB =
      lsi::GatherAndSolveOntoLevel(field, isoValue, b, direction, reach, candidates, nb);
    // Which way the two-stage solve went.
    Eigen::Vector3d c = start, nc;
    field.Gather(c.data(), 0.25 * reach, candidates);
    const bool near = lsi::SolveOntoLevel(
      field, candidates, isoValue, c, direction, 0.25 * reach, 1e-9 * reach, nc, true);
    ++starts;
    same += okA == okB && a == b && na == nb ? 1 : 0;
    settledNear += near ? 1 : 0;
    handedOver += near ? 0 : 1;
    solved += okA ? 1 : 0;
  }
  std::cout << starts << " starts: " << solved << " reach the level, " << settledNear
            << " settled within a quarter of the reach, " << handedOver << " handed over\n";
  Check(same == starts, "the same success, point and normal as the whole-reach solve, to the bit");
  Check(settledNear > starts / 10 && handedOver > starts / 10 && solved < starts,
    "both ways taken, and some starts out of reach");

  // The value alone, at the samples (as the flood's offsets take it) and between them.
  int sameValue = 0, positive = 0, tried = 0;
  for (std::size_t j = 0; j < geometry.NumberOfSamples; j += 7)
  {
    const double* x = geometry.Position(j);
    const double between[3] = { x[0] + 0.3 * spacing, x[1] - 0.2 * spacing, x[2] };
    for (const double* at : { x, between })
    {
      double value, gradient[3];
      field.Evaluate(at, value, gradient);
      const double alone = field.ValueAt(at);
      sameValue += alone == value ? 1 : 0;
      positive += value > 0.0 ? 1 : 0;
      ++tried;
    }
  }
  Check(sameValue == tried && positive > tried / 2,
    "ValueAt gives Evaluate's value to the bit (" + std::to_string(tried) + " points)");
}
} // namespace

int main()
{
  TestSameAsWholeReach();
  const int failures = lsi::test::Failures();
  std::cout << (failures ? "SPH solve tests FAILED\n" : "SPH solve tests passed\n");
  return failures ? EXIT_FAILURE : EXIT_SUCCESS;
}
