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
// Then the gathers made once for a group of points near each other (GatherForBox,
// SPHPointGroup, SamplesReaching), which the surface's stages use, against each point's own:
//   - SPHOffsetsAtSamples (grouped) against ValueAt at every sample, to the bit;
//   - each point's candidates taken from its group's (GatherAmong) against Gather's, the same
//     candidates in the same order, and GatherAndSolveOntoLevel from them the same point and
//     normal, to the bit; ForEachWeightAmong's weights against ForEachWeight's, to the bit;
//   - densities summed where the stored ones are zero (in groups, in parallel) against a sum
//     over every particle (1e-12), through the interpolant of a constant array.
#include "LevelSetNeighborhoods.h"
#include "LevelSetSPHField.h"
#include "NearestNeighbors.h"
#include "SPHKernels.h"
#include "TestCheck.h"

#include "vtkDoubleArray.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkSMPTools.h"

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <iostream>
#include <random>
#include <string>
#include <vector>

namespace
{
using lsi::test::Check;

// A jittered lattice of side^3 particles in the unit cube about 0 (each coordinate moved by up
// to 0.15 spacings), each with a mass and a smoothing length from massOf(x) and hOf(x), called
// in that order (hOf may draw from `random`).
struct Lattice
{
  vtkNew<vtkPoints> Points;
  vtkNew<vtkDoubleArray> H, Mass;
  lsi::Neighborhoods Geometry; // built by MakeLattice (24 neighbours)
  // Its SPH arrays, each support two smoothing lengths.
  lsi::SPHFieldArrays Arrays() const
  {
    lsi::SPHFieldArrays arrays;
    arrays.SmoothingLength = this->H;
    arrays.Mass = this->Mass;
    arrays.SupportPerSmoothingLength = 2.0;
    return arrays;
  }
};
template <typename MassOf, typename HOf>
void MakeLattice(int side, std::mt19937& random, MassOf&& massOf, HOf&& hOf, Lattice& lattice)
{
  std::uniform_real_distribution<double> unit(-0.5, 0.5);
  const double spacing = 1.0 / side;
  lattice.Points->SetDataTypeToDouble();
  lattice.H->SetName("h");
  lattice.Mass->SetName("m");
  for (int i = 0; i < side; ++i)
  {
    for (int j = 0; j < side; ++j)
    {
      for (int k = 0; k < side; ++k)
      {
        const double x[3] = { (i + 0.5 + 0.3 * unit(random)) * spacing - 0.5,
          (j + 0.5 + 0.3 * unit(random)) * spacing - 0.5,
          (k + 0.5 + 0.3 * unit(random)) * spacing - 0.5 };
        lattice.Points->InsertNextPoint(x);
        lattice.Mass->InsertNextValue(massOf(x));
        lattice.H->InsertNextValue(hOf(x));
      }
    }
  }
  Check(lsi::BuildNeighborhoods(lattice.Points, 24, lattice.Geometry, lsi::AbortCheck()),
    "neighbourhoods built");
}

void TestSameAsWholeReach()
{
  std::mt19937 random(11);
  std::uniform_real_distribution<double> unit(-0.5, 0.5);
  const int side = 24;
  const double spacing = 1.0 / side;
  Lattice lattice;
  MakeLattice(
    side, random,
    [](const double* x) { // density peaks at the centre
      return std::exp(-8.0 * (x[0] * x[0] + x[1] * x[1] + x[2] * x[2]));
    },
    [&](const double*) { return (1.6 + 0.4 * unit(random)) * spacing; }, lattice);
  const lsi::Neighborhoods& geometry = lattice.Geometry;
  lsi::SPHFieldArrays arrays = lattice.Arrays();
  arrays.ValuesAreDensity = true;
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

bool SameCandidates(const lsi::SPHCandidates& a, const lsi::SPHCandidates& b)
{
  return a.X == b.X && a.Y == b.Y && a.Z == b.Z && a.H == b.H && a.Coefficient == b.Coefficient;
}

void TestGroupedGathers()
{
  // A jittered lattice, denser towards the centre (smoothing lengths that follow), as
  // TestSameAsWholeReach's; every third stored density a placeholder zero.
  std::mt19937 random(5);
  std::uniform_real_distribution<double> unit(-0.5, 0.5);
  const int side = 20;
  const double spacing = 1.0 / side;
  Lattice lattice;
  vtkNew<vtkDoubleArray> density;
  auto r2Of = [](const double* x) { return x[0] * x[0] + x[1] * x[1] + x[2] * x[2]; };
  MakeLattice(
    side, random, [&](const double* x) { return std::exp(-6.0 * r2Of(x)); },
    [&](const double* x) {
      density->InsertNextValue(density->GetNumberOfTuples() % 3 == 0 ? 0.0 : 1.0 + r2Of(x));
      return (1.5 + 0.8 * (unit(random) + 0.5)) * spacing * (1.0 + r2Of(x));
    },
    lattice);
  vtkDoubleArray* mass = lattice.Mass;
  const lsi::Neighborhoods& geometry = lattice.Geometry;
  lsi::SPHFieldArrays arrays = lattice.Arrays();
  arrays.Density = density;
  const std::size_t n = geometry.NumberOfSamples;
  std::vector<double> values(n, 1.0); // the constant array: its interpolant is sum V_j W
  std::string problem;
  const lsi::SPHField field(geometry, arrays, values, problem);
  Check(field.Valid() && field.SummedDensities == (n + 2) / 3, "the field, densities summed");

  // The densities summed where stored ones are zero, against a sum over every particle: the
  // interpolant of the constant 1 at a point, with those volumes.
  std::vector<double> volume(n);
  for (std::size_t j = 0; j < n; ++j)
  {
    const vtkIdType id = geometry.Order[j];
    double rho = density->GetValue(id);
    if (rho == 0.0)
    {
      for (std::size_t k = 0; k < n; ++k)
      {
        const double r = std::sqrt(
          lsi::PointCloudIndex::SquaredDistance(geometry.Position(j), geometry.Position(k)));
        rho += mass->GetValue(geometry.Order[k]) *
          lsi::SPHKernelValue(arrays.Kernel, r, field.Support(k));
      }
    }
    volume[j] = mass->GetValue(id) / rho;
  }
  double worst = 0.0;
  for (int t = 0; t < 200; ++t)
  {
    const double x[3] = { 0.8 * unit(random), 0.8 * unit(random), 0.8 * unit(random) };
    double sum = 0.0;
    for (std::size_t k = 0; k < n; ++k)
    {
      const double r = std::sqrt(lsi::PointCloudIndex::SquaredDistance(x, geometry.Position(k)));
      sum += volume[k] * lsi::SPHKernelValue(arrays.Kernel, r, field.Support(k));
    }
    double value, gradient[3];
    field.Evaluate(x, value, gradient);
    worst = std::max(worst, std::abs(value - sum) / std::max(sum, 1e-300));
  }
  Check(worst < 1e-12,
    "summed densities as a sum over every particle (" + std::to_string(worst) + " relative)");

  // The field at every sample, grouped, on 1 and 2 threads, against ValueAt's.
  for (int threads : { 1, 2 })
  {
    std::vector<double> offsets;
    vtkSMPTools::LocalScope(vtkSMPTools::Config{ threads, "STDThread", false },
      [&]() { lsi::SPHOffsetsAtSamples(geometry, field, 0.25, offsets, lsi::AbortCheck()); });
    std::size_t same = 0;
    for (std::size_t j = 0; j < n; ++j)
    {
      same += offsets[j] == field.ValueAt(geometry.Position(j)) - 0.25 ? 1 : 0;
    }
    Check(same == n,
      "SPHOffsetsAtSamples is ValueAt at every sample, to the bit, on " + std::to_string(threads) +
        " thread(s) (" + std::to_string(same) + " of " + std::to_string(n) + ")");
  }

  // Groups of points along short random walks (a surface's consecutive points), each with its
  // own reach.
  double peak, g[3];
  const double centre[3] = { 0.0, 0.0, 0.0 };
  field.Evaluate(centre, peak, g);
  const double isoValue = 0.5 * peak;
  int groups = 0, sameGather = 0, sameSolve = 0, sameWeights = 0, tried = 0, solved = 0;
  lsi::SPHCandidates fromGroup, own;
  std::vector<std::uint32_t> reaching;
  int split = 0; // groups ended by a jump before their most points
  for (int w = 0; w < 40; ++w, ++groups)
  {
    // A walk of 2 * Most points with a jump inside the first group (a seam of the order).
    std::vector<double> walk;
    Eigen::Vector3d x(0.6 * unit(random), 0.6 * unit(random), 0.6 * unit(random));
    std::vector<double> reaches;
    for (std::size_t k = 0; k < 2 * lsi::SPHPointGroup::Most; ++k)
    {
      x += 0.5 * spacing * Eigen::Vector3d(unit(random), unit(random), unit(random));
      x[0] -= k == lsi::SPHPointGroup::Most / 2 ? (x[0] > 0.0 ? 0.45 : -0.45) : 0.0;
      walk.insert(walk.end(), x.data(), x.data() + 3);
      reaches.push_back((2.0 + 2.0 * (unit(random) + 0.5)) * spacing);
    }
    lsi::SPHPointGroup group;
    std::size_t samplesEnd = 0; // the interpolation's groups: the next starts there
    for (std::size_t k = 0; k < reaches.size(); ++k, ++tried)
    {
      group.Hold(field, walk.data(), k, reaches.size(), [&](std::size_t q) { return reaches[q]; });
      split += group.First == k && group.Last == lsi::SPHPointGroup::Most / 2 ? 1 : 0;
      if (k == samplesEnd)
      {
        double lower[3], upper[3];
        samplesEnd = lsi::GroupEnd(
          walk.data(), k, reaches.size(), lsi::SPHPointGroup::Most, 2.0 * spacing, lower, upper);
        field.SamplesReaching(lower, upper, reaching);
      }
      const double* p = &walk[3 * k];
      const double extra = lsi::NearGatherExtra(reaches[k]);
      lsi::SPHField::GatherAmong(group.Candidates, p, extra, fromGroup);
      field.Gather(p, extra, own);
      sameGather +=
        SameCandidates(fromGroup, own) && !own.X.empty() && group.Reach(k) == reaches[k] ? 1 : 0;
      // The solve from the group's candidates and from its own gather.
      const Eigen::Vector3d direction =
        Eigen::Vector3d(p[0] + 0.2 * unit(random), p[1], p[2]).normalized();
      Eigen::Vector3d a(p), b(p), na(0, 0, 0), nb(0, 0, 0);
      const bool okA = lsi::GatherAndSolveOntoLevel(
        field, isoValue, a, direction, reaches[k], own, na, &group.Candidates);
      const bool okB =
        lsi::GatherAndSolveOntoLevel(field, isoValue, b, direction, reaches[k], own, nb);
      sameSolve += okA == okB && a == b && na == nb ? 1 : 0;
      solved += okA ? 1 : 0;
      // The interpolation weights.
      std::vector<std::pair<std::uint32_t, double>> grouped, alone;
      field.ForEachWeightAmong(
        reaching, p, [&](std::uint32_t j, double weight) { grouped.emplace_back(j, weight); });
      field.ForEachWeight(
        p, [&](std::uint32_t j, double weight) { alone.emplace_back(j, weight); });
      sameWeights += grouped == alone && !alone.empty() ? 1 : 0;
    }
  }
  Check(split >= groups, "the jumps end groups early (" + std::to_string(split) + " groups)");
  Check(sameGather == tried,
    "a point's candidates from its group's are Gather's, in order (" + std::to_string(sameGather) +
      " of " + std::to_string(tried) + ")");
  Check(sameSolve == tried && solved > tried / 10,
    "GatherAndSolveOntoLevel from the group's candidates: the same point and normal, to the bit (" +
      std::to_string(solved) + " of " + std::to_string(tried) + " reach the level)");
  Check(sameWeights == tried, "ForEachWeightAmong gives ForEachWeight's weights, to the bit");
}
} // namespace

int main()
{
  TestSameAsWholeReach();
  TestGroupedGathers();
  const int failures = lsi::test::Failures();
  std::cout << (failures ? "SPH solve tests FAILED\n" : "SPH solve tests passed\n");
  return failures ? EXIT_FAILURE : EXIT_SUCCESS;
}
