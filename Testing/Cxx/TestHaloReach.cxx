// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
// The halo's reach box under MPI (HaloReachBox) against the box over every sample's list, on
// clouds a rank may hold: uniform in a slab, a Plummer sphere (radii spanning three decades,
// the sparse outskirts reaching farthest), a few clusters with isolated particles far out, the
// same in other units, a cloud with a wider band (Epsilon), and one of too few samples:
//   - every radius bound (RadiusBounds, WindowRadiusBound) bounds the sample's radius;
//   - the box equals the box of every sample's x_i -+ (factor h_i + band), to the bit; so does
//     its +x side computed alone (the others then unbounded);
//   - the uniform slab needs fewer than 5% of the lists (53% with RadiusBounds alone), the
//     Plummer sphere fewer than 5%.
#include "LevelSetHaloReach.h"
#include "TestCheck.h"

#include "vtkNew.h"
#include "vtkPoints.h"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <random>
#include <string>
#include <vector>

namespace
{
using lsi::test::Check;

vtkNew<vtkPoints> Uniform(int count, double scale)
{
  std::mt19937 random(3);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  for (int i = 0; i < count; ++i) // a slab, as a rank's share of a cube split in x
  {
    points->InsertNextPoint(scale * 0.5 * unit(random), scale * unit(random), scale * unit(random));
  }
  return points;
}

vtkNew<vtkPoints> Plummer(int count, double scale)
{
  std::mt19937 random(5);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::normal_distribution<double> normal(0.0, 1.0);
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  for (int i = 0; i < count; ++i)
  {
    const double m = std::min(unit(random), 0.999);
    const double r = 1.0 / std::sqrt(std::pow(m, -2.0 / 3.0) - 1.0);
    double d[3] = { normal(random), normal(random), normal(random) };
    const double norm = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    points->InsertNextPoint(
      scale * r * d[0] / norm, scale * r * d[1] / norm, scale * r * d[2] / norm);
  }
  return points;
}

vtkNew<vtkPoints> Clusters(int count, double scale)
{
  std::mt19937 random(11);
  std::normal_distribution<double> normal(0.0, 1.0);
  std::uniform_real_distribution<double> unit(-50.0, 50.0);
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  const double centres[3][3] = { { 0, 0, 0 }, { 20, 0, 5 }, { -10, 30, 0 } };
  for (int i = 0; i < count; ++i)
  {
    const double* c = centres[i % 3];
    points->InsertNextPoint(scale * (c[0] + normal(random)), scale * (c[1] + normal(random)),
      scale * (c[2] + normal(random)));
  }
  for (int i = 0; i < 40; ++i) // isolated particles far out
  {
    points->InsertNextPoint(scale * unit(random), scale * unit(random), scale * unit(random));
  }
  return points;
}

// Every list, and the box over all of them.
void BoxOfEveryList(const lsi::Neighborhoods& g, double factor, double band, double box[6])
{
  for (int d = 0; d < 3; ++d)
  {
    box[2 * d] = HUGE_VAL;
    box[2 * d + 1] = -HUGE_VAL;
  }
  for (std::size_t i = 0; i < g.NumberOfSamples; ++i)
  {
    const double reach = factor * g.RadiusOf(i) + band;
    for (int d = 0; d < 3; ++d)
    {
      box[2 * d] = std::min(box[2 * d], g.Position(i)[d] - reach);
      box[2 * d + 1] = std::max(box[2 * d + 1], g.Position(i)[d] + reach);
    }
  }
}

std::size_t CheckCloud(const std::string& name, vtkPoints* points, int neighbors, double band)
{
  const double factor = 6.0;
  lsi::Neighborhoods halo, every;
  lsi::BuildNeighborhoods(points, neighbors, halo, lsi::AbortCheck());
  lsi::BuildNeighborhoods(points, neighbors, every, lsi::AbortCheck());
  double box[6], reference[6];
  std::size_t computed = 0;
  Check(lsi::HaloReachBox(halo, factor, band, box, computed, lsi::AbortCheck()),
    name + ": the reach box is computed");
  BoxOfEveryList(every, factor, band, reference);
  Check(
    std::equal(box, box + 6, reference), name + ": the same box as over every list, to the bit");
  // From one sample per side first, the second pass finds the farthest reaching ones.
  lsi::Neighborhoods one;
  lsi::BuildNeighborhoods(points, neighbors, one, lsi::AbortCheck());
  double fromOne[6];
  std::size_t computedFromOne = 0;
  lsi::HaloReachBox(one, factor, band, fromOne, computedFromOne, lsi::AbortCheck(), 1);
  Check(std::equal(fromOne, fromOne + 6, reference),
    name + ": the same box from one sample per side first");
  // One side only (a rank with one neighbour across +x): that side to the bit, the others
  // unbounded, and fewer lists.
  lsi::Neighborhoods oneSide;
  lsi::BuildNeighborhoods(points, neighbors, oneSide, lsi::AbortCheck());
  const bool wanted[6] = { false, true, false, false, false, false };
  double sided[6];
  std::size_t computedOneSide = 0;
  lsi::HaloReachBox(oneSide, factor, band, sided, computedOneSide, lsi::AbortCheck(),
    lsi::HaloFirstPerSide, wanted);
  Check(sided[1] == reference[1] && sided[0] == -HUGE_VAL && sided[2] == -HUGE_VAL &&
      sided[3] == HUGE_VAL && sided[4] == -HUGE_VAL && sided[5] == HUGE_VAL,
    name + ": +x alone, to the bit, the other sides unbounded");
  Check(computedOneSide <= computed,
    name + ": +x alone computes no more lists (" + std::to_string(computedOneSide) + " of " +
      std::to_string(computed) + ")");
  const std::vector<double> bounds = lsi::RadiusBounds(every);
  std::size_t wrong = 0;
  for (std::size_t i = 0; i < bounds.size(); ++i)
  {
    wrong += bounds[i] < every.RadiusOf(i) ? 1 : 0;
  }
  Check(wrong == 0,
    name + ": every radius bound bounds the radius (" + std::to_string(wrong) + " do not)");
  std::size_t wrongInWindow = 0;
  const std::size_t half = 4 * static_cast<std::size_t>(every.Stride);
  std::vector<double> scratch;
  for (std::size_t i = 0; i < every.NumberOfSamples; ++i)
  {
    wrongInWindow += lsi::WindowRadiusBound(every, i, half, scratch) < every.RadiusOf(i) ? 1 : 0;
  }
  Check(wrongInWindow == 0,
    name + ": every window bound bounds the radius (" + std::to_string(wrongInWindow) + " do not)");
  std::cout << name << ": " << computed << " of " << halo.NumberOfSamples
            << " lists computed; box x " << box[0] << " " << box[1] << "\n";
  return computed;
}
} // namespace

int main()
{
  // (At this size the halo, 6 radii deep, is a third of the slab's width on each side in x.)
  const std::size_t slab = CheckCloud("uniform slab", Uniform(200000, 1.0), 26, 0.0);
  Check(slab < 10000, "the uniform slab needs fewer than 5% of its lists");
  const std::size_t plummer = CheckCloud("Plummer sphere", Plummer(50000, 1.0), 26, 0.0);
  Check(plummer < 2500, "the Plummer sphere needs fewer than 5% of its lists");
  CheckCloud("uniform slab in other units", Uniform(200000, 3.0e-7), 26, 0.0);
  CheckCloud("Plummer sphere, wider band", Plummer(50000, 1.0), 26, 0.3);
  CheckCloud("clusters with isolated particles", Clusters(30000, 1.0), 32, 0.0);
  CheckCloud("clusters in other units", Clusters(30000, 4.0e5), 32, 0.0);
  CheckCloud("too few samples", Uniform(40, 1.0), 26, 0.0);
  std::cout << (lsi::test::Failures() ? "halo reach tests FAILED\n" : "halo reach tests passed\n");
  return lsi::test::Failures() ? 1 : 0;
}
