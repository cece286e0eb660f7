// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
// The flood's small outside pockets, filled (LevelSetFlood's FilledInside), on a random cloud
// where a random 15% of the samples lie below the isovalue: pockets of every size next to the
// flood.
// 1. Against the definition, computed here by brute force: a pocket is what a search from an
// outside neighbour of the flood reaches through outside samples (neighbour lists are not
// symmetric, so that depends on the start), and it is filled when it holds at most Stride
// samples. The inside must be the flood's reach and every such small pocket, and no other.
// 2. The same particles stored in another order (a second cloud far away moves the first in
// the storage's spatial order; its lists do not change): the same inside, particle by
// particle. Before 2026-12-02 a search marked everything it met as part of a large pocket,
// so the result depended on which start came first: on the ChaNGa shock tube, 25 particles
// changed sides between one process and two MPI ranks.
#include "LevelSetFlood.h"
#include "LevelSetFloodAcross.h"
#include "LevelSetNeighborhoods.h"
#include "TestCheck.h"

#include "vtkPoints.h"
#include "vtkSmartPointer.h"

#include <cstdint>
#include <iostream>
#include <random>
#include <vector>

namespace
{
constexpr int Neighbors = 16;

struct Cloud
{
  std::vector<double> Xyz;    // 3 per particle
  std::vector<char> Below;    // f < f_iso
  std::vector<char> NearSeed; // within the seed sphere
};

// `count` particles, uniform in a cube of side 20 (about one per unit volume), 15% of them
// below the isovalue; the seed sphere (radius 2) at the centre.
Cloud RandomCloud(int count, unsigned seed)
{
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> place(0.0, 20.0), chance(0.0, 1.0);
  Cloud cloud;
  for (int p = 0; p < count; ++p)
  {
    const double x = place(random), y = place(random), z = place(random);
    cloud.Xyz.insert(cloud.Xyz.end(), { x, y, z });
    cloud.Below.push_back(chance(random) < 0.15 ? 1 : 0);
    const double r2 = (x - 10) * (x - 10) + (y - 10) * (y - 10) + (z - 10) * (z - 10);
    cloud.NearSeed.push_back(r2 < 4.0 ? 1 : 0);
  }
  return cloud;
}

// The particles' inside (per input particle) after the flood and its filled pockets, the first
// `particles` of `points`; `flooded` (storage order) receives the flood's reach.
std::vector<char> InsideOf(const Cloud& cloud, vtkPoints* points, std::size_t particles,
  lsi::Neighborhoods& geometry, std::vector<char>& flooded)
{
  lsi::BuildNeighborhoods(points, Neighbors, geometry, lsi::AbortCheck());
  const std::size_t n = geometry.NumberOfSamples;
  std::vector<double> dataOffsets(n, 1.0);
  std::vector<char> inSeed(n, 0);
  for (std::size_t i = 0; i < n; ++i)
  {
    const std::size_t p = geometry.Order[i];
    if (p < particles)
    {
      dataOffsets[i] = cloud.Below[p] ? -1.0 : 1.0;
      inSeed[i] = cloud.NearSeed[p];
    }
    else
    {
      dataOffsets[i] = -1.0; // the far cloud: never flooded
    }
  }
  std::vector<char> inside;
  double seedSamples = 0.0;
  const std::vector<char> seeds = inSeed;
  lsi::test::Check(
    lsi::FloodAcross(geometry, lsi::Communicator(), std::vector<vtkIdType>(),
      static_cast<vtkIdType>(n), dataOffsets, inSeed, inside, seedSamples, lsi::AbortCheck()),
    "the flood ends whole");
  lsi::FloodResult result;
  flooded.clear();
  lsi::FloodFurther(geometry, dataOffsets, seeds, flooded, result, lsi::AbortCheck());
  std::vector<char> byParticle(particles, 0);
  for (std::size_t i = 0; i < n; ++i)
  {
    if (geometry.Order[i] < particles)
    {
      byParticle[geometry.Order[i]] = inside[i];
    }
  }
  return byParticle;
}

// The inside by the definition: the flood's reach, and all that a search through outside
// samples reaches from each outside neighbour of the reach when that is at most bubbleSize
// samples (storage order).
std::vector<char> InsideByDefinition(
  const lsi::Neighborhoods& geometry, const std::vector<char>& flooded, std::size_t bubbleSize)
{
  const std::size_t n = geometry.NumberOfSamples;
  std::vector<char> inside = flooded, seen(n, 0);
  std::vector<std::uint32_t> all(n);
  for (std::size_t i = 0; i < n; ++i)
  {
    all[i] = static_cast<std::uint32_t>(i);
  }
  geometry.EnsureNeighbors(all);
  for (std::size_t i = 0; i < n; ++i)
  {
    if (!flooded[i])
    {
      continue;
    }
    const std::uint32_t* around = geometry.NeighborsOf(i);
    for (int a = 1; a < geometry.Stride; ++a)
    {
      const std::uint32_t start = around[a];
      if (flooded[start])
      {
        continue;
      }
      std::vector<std::uint32_t> reached(1, start);
      seen[start] = 1;
      for (std::size_t head = 0; head < reached.size(); ++head)
      {
        const std::uint32_t* next = geometry.NeighborsOf(reached[head]);
        for (int b = 1; b < geometry.Stride; ++b)
        {
          if (!flooded[next[b]] && !seen[next[b]])
          {
            seen[next[b]] = 1;
            reached.push_back(next[b]);
          }
        }
      }
      for (const std::uint32_t j : reached)
      {
        seen[j] = 0;
        inside[j] = inside[j] || reached.size() <= bubbleSize;
      }
    }
  }
  return inside;
}
} // namespace

int main()
{
  constexpr int Particles = 8000;
  const Cloud cloud = RandomCloud(Particles, 11);
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetDataTypeToDouble();
  for (int p = 0; p < Particles; ++p)
  {
    points->InsertNextPoint(&cloud.Xyz[3 * p]);
  }
  lsi::Neighborhoods geometry;
  std::vector<char> flooded;
  const std::vector<char> inside = InsideOf(cloud, points, Particles, geometry, flooded);

  // 1. The definition.
  const std::vector<char> expected =
    InsideByDefinition(geometry, flooded, static_cast<std::size_t>(geometry.Stride));
  std::size_t reach = 0, filled = 0, wrong = 0, belowOutside = 0;
  for (std::size_t i = 0; i < geometry.NumberOfSamples; ++i)
  {
    const char got = inside[geometry.Order[i]];
    reach += flooded[i];
    filled += expected[i] && !flooded[i];
    wrong += (got != 0) != (expected[i] != 0);
    belowOutside += cloud.Below[geometry.Order[i]] && !expected[i];
  }
  std::cout << Particles << " particles: the flood reached " << reach << ", the definition fills "
            << filled << " in small pockets (" << belowOutside
            << " below the isovalue stay outside); wrong: " << wrong << "\n";
  lsi::test::Check(reach > Particles / 2, "the flood reaches most of the cloud");
  lsi::test::Check(
    filled > 100 && belowOutside > 100, "pockets both small and large lie next to it");
  lsi::test::Check(wrong == 0, "the filled pockets are the definition's");

  // 2. The same particles in another storage order.
  auto moved = vtkSmartPointer<vtkPoints>::New();
  moved->DeepCopy(points);
  std::mt19937 random(3);
  std::uniform_real_distribution<double> place(0.0, 7.0);
  for (int p = 0; p < 2000; ++p)
  {
    moved->InsertNextPoint(place(random) + 47.0, place(random) - 13.0, place(random) + 29.0);
  }
  lsi::Neighborhoods other;
  std::vector<char> otherFlooded;
  const std::vector<char> otherInside = InsideOf(cloud, moved, Particles, other, otherFlooded);
  std::size_t sameSlot = 0, changed = 0;
  for (std::size_t i = 0; i < other.NumberOfSamples; ++i)
  {
    sameSlot += i < geometry.NumberOfSamples && other.Order[i] == geometry.Order[i];
  }
  for (int p = 0; p < Particles; ++p)
  {
    changed += inside[p] != otherInside[p];
  }
  std::cout << "in another storage order (" << sameSlot << " of " << Particles
            << " in the same place): " << changed << " particles changed sides\n";
  lsi::test::Check(sameSlot < Particles / 2, "the storage order differs");
  lsi::test::Check(changed == 0, "the same inside in any order");
  std::cout << (lsi::test::Failures() ? "flood pocket tests FAILED\n"
                                      : "flood pocket tests passed\n");
  return lsi::test::Failures() ? 1 : 0;
}
