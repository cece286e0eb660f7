// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
// The flood across a periodic box's faces (LevelSetFloodAcross), in one process.
// 1. Particles fill a slab periodic in x (jittered lattice, spacing 1, length 40) with images of
// those within 4 of either face beyond the other; f = cos(2 pi x / 40) is above 0 for x < 10
// and x > 30. Seeded at x < 2, the flood reaches, through the images just below x = 0, the
// particles near x = 40, which one process on a plain cloud cannot: every sample with f > 0
// (particles and images) must end inside and no other, from a flood that took more than one
// round. Without the images' ids (as outside a periodic box) the same flood must stop at the
// images: the check can fail.
// 2. A strip wound round a box periodic in x and y: f = cos(2 pi (24 y / Ly - x / Lx)) is
// above 0 on one strip that crosses the x faces 24 times before it closes (its turns 3 spacings
// wide, 3 apart). Seeded on one turn, the flood needs a round per face crossed, 13 floods going
// both ways: every sample with f > 0 must end inside (a flood that gave up after 9 floods, as
// before 2026-11-26, left 2,192 of them outside).
#include "LevelSetFloodAcross.h"
#include "LevelSetNeighborhoods.h"
#include "LevelSetPeriodicImages.h"
#include "TestCheck.h"

#include "vtkPoints.h"
#include "vtkSmartPointer.h"

#include <cmath>
#include <iostream>
#include <random>
#include <vector>

namespace
{
// An nx x ny x nz lattice of spacing 1 (x from 0.5, y from yStart, z from 0), each point moved
// by up to 0.2 on each axis.
std::vector<double> JitteredLattice(int nx, int ny, int nz, double yStart, unsigned seed)
{
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> jitter(-0.2, 0.2);
  std::vector<double> xyz;
  for (int i = 0; i < nx; ++i)
  {
    for (int j = 0; j < ny; ++j)
    {
      for (int k = 0; k < nz; ++k)
      {
        // (In turn: the order of a braced list's evaluations is fixed.)
        xyz.insert(
          xyz.end(), { i + 0.5 + jitter(random), j + yStart + jitter(random), k + jitter(random) });
      }
    }
  }
  return xyz;
}

// The points at `xyz` (3 doubles each), in double precision.
vtkSmartPointer<vtkPoints> PointsOf(const std::vector<double>& xyz)
{
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetDataTypeToDouble();
  for (std::size_t p = 0; p < xyz.size() / 3; ++p)
  {
    points->InsertNextPoint(&xyz[3 * p]);
  }
  return points;
}

void FloodAcrossOneFace()
{
  constexpr int Nx = 40, Ny = 8, Nz = 8;
  constexpr double Length = Nx, Margin = 4.0;
  const double pi = std::acos(-1.0);
  const std::vector<double> xyz = JitteredLattice(Nx, Ny, Nz, 0.0, 7);
  const vtkIdType particles = static_cast<vtkIdType>(xyz.size() / 3);
  // The images, after the particles: imageOf[k] is the particle that input id particles + k is.
  std::vector<vtkIdType> imageOf;
  const vtkSmartPointer<vtkPoints> points = PointsOf(xyz); // the particles, then their images
  for (vtkIdType p = 0; p < particles; ++p)
  {
    const double x = xyz[3 * p];
    if (x < Margin || x >= Length - Margin)
    {
      points->InsertNextPoint(x < Margin ? x + Length : x - Length, xyz[3 * p + 1], xyz[3 * p + 2]);
      imageOf.push_back(p);
    }
  }
  lsi::Neighborhoods geometry;
  lsi::BuildNeighborhoods(points, 24, geometry, lsi::AbortCheck());
  const std::size_t n = geometry.NumberOfSamples;
  const std::vector<vtkIdType> original = lsi::OriginalIds(geometry, particles, imageOf);
  // Per sample (storage order): f at its particle, and whether it is a seed.
  std::vector<double> dataOffsets(n);
  std::vector<char> seeds(n, 0);
  for (std::size_t i = 0; i < n; ++i)
  {
    const double x = xyz[3 * original[i]];
    dataOffsets[i] = std::cos(2.0 * pi * x / Length);
    seeds[i] = geometry.Position(i)[0] < 2.0 ? 1 : 0;
  }
  const lsi::Communicator oneProcess;

  // Across the faces: every sample above the isovalue, and no other.
  std::vector<char> inSeed = seeds, inside;
  double seedSamples = 0.0;
  const bool whole = lsi::FloodAcross(geometry, oneProcess, original, particles, dataOffsets,
    inSeed, inside, seedSamples, lsi::AbortCheck());
  lsi::test::Check(whole, "the flood across the faces ends whole");
  std::size_t seeded = 0, added = 0, wrong = 0, above = 0;
  for (std::size_t i = 0; i < n; ++i)
  {
    seeded += seeds[i] && dataOffsets[i] > 0.0;
    added += inSeed[i] && !seeds[i];
    above += dataOffsets[i] > 0.0;
    wrong += (inside[i] != 0) != (dataOffsets[i] > 0.0);
  }
  std::cout << n << " samples, " << above << " above the isovalue, " << seeded
            << " seeds, the images added " << added << " seeds; wrong sides: " << wrong << "\n";
  lsi::test::Check(seedSamples == static_cast<double>(seeded) && seeded > 0,
    "seedSamples == static_cast<double>(seeded) && seeded > 0");
  // The far side was reached through the images: in more than one round.
  lsi::test::Check(added > 0, "added > 0");
  lsi::test::Check(wrong == 0, "wrong == 0");

  // Without the images' ids the flood stops at them: the particles near x = 40 stay outside.
  std::vector<char> plainSeed = seeds, plainInside;
  const bool plainWhole = lsi::FloodAcross(geometry, oneProcess, std::vector<vtkIdType>(),
    particles, dataOffsets, plainSeed, plainInside, seedSamples, lsi::AbortCheck());
  lsi::test::Check(plainWhole, "the plain flood ends whole");
  std::size_t farSide = 0;
  for (std::size_t i = 0; i < n; ++i)
  {
    const double x = geometry.Position(i)[0];
    farSide += plainInside[i] && x > Length / 2 && x < Length;
  }
  lsi::test::Check(farSide == 0 && plainSeed == seeds, "farSide == 0 && plainSeed == seeds");
}

void FloodAlongAWoundStrip()
{
  constexpr int Nx = 16, Ny = 156, Nz = 4, Turns = 24;
  constexpr double Margin = 4.0;
  const double pi = std::acos(-1.0);
  const double size[2] = { Nx, Ny };
  auto f = [&](const double* x) { return std::cos(2.0 * pi * (Turns * x[1] / Ny - x[0] / Nx)); };
  const std::vector<double> xyz = JitteredLattice(Nx, Ny, Nz, 0.5, 11);
  const vtkIdType particles = static_cast<vtkIdType>(xyz.size() / 3);
  std::vector<vtkIdType> imageOf;
  const vtkSmartPointer<vtkPoints> points = PointsOf(xyz); // the particles, then their images
  // Images across the x and y faces and their edges, within Margin of the box.
  for (int sx = -1; sx <= 1; ++sx)
  {
    for (int sy = -1; sy <= 1; ++sy)
    {
      for (vtkIdType p = 0; (sx != 0 || sy != 0) && p < particles; ++p)
      {
        const double y[2] = { xyz[3 * p] + sx * size[0], xyz[3 * p + 1] + sy * size[1] };
        if (y[0] >= -Margin && y[0] < size[0] + Margin && y[1] >= -Margin &&
          y[1] < size[1] + Margin)
        {
          points->InsertNextPoint(y[0], y[1], xyz[3 * p + 2]);
          imageOf.push_back(p);
        }
      }
    }
  }
  lsi::Neighborhoods geometry;
  lsi::BuildNeighborhoods(points, 24, geometry, lsi::AbortCheck());
  const std::size_t n = geometry.NumberOfSamples;
  const std::vector<vtkIdType> original = lsi::OriginalIds(geometry, particles, imageOf);
  // Seeds: within 2 of the strip's middle at x = 8 (there 24 y / Ny - x / Nx = 0).
  const double seedAt[2] = { 8.0, 0.5 * Ny / Turns };
  std::vector<double> dataOffsets(n);
  std::vector<char> seeds(n, 0);
  for (std::size_t i = 0; i < n; ++i)
  {
    const double* x = geometry.Position(i);
    dataOffsets[i] = f(&xyz[3 * original[i]]);
    seeds[i] = std::hypot(x[0] - seedAt[0], x[1] - seedAt[1]) < 2.0 ? 1 : 0;
  }
  std::vector<char> inSeed = seeds, inside;
  double seedSamples = 0.0;
  const bool whole = lsi::FloodAcross(geometry, lsi::Communicator(), original, particles,
    dataOffsets, inSeed, inside, seedSamples, lsi::AbortCheck());
  lsi::test::Check(whole, "the wound strip's flood ends whole");
  std::size_t above = 0, wrong = 0, added = 0;
  for (std::size_t i = 0; i < n; ++i)
  {
    above += dataOffsets[i] > 0.0;
    wrong += (inside[i] != 0) != (dataOffsets[i] > 0.0);
    added += inSeed[i] && !seeds[i];
  }
  std::cout << "wound strip: " << n << " samples, " << above << " above the isovalue, the images "
            << "added " << added << " seeds; wrong sides: " << wrong << "\n";
  lsi::test::Check(seedSamples > 0 && added > 0, "seedSamples > 0 && added > 0");
  lsi::test::Check(wrong == 0, "every turn of the wound strip flooded, nothing else");
}
} // namespace

int main()
{
  FloodAcrossOneFace();
  FloodAlongAWoundStrip();
  std::cout << (lsi::test::Failures() ? "flood across tests FAILED\n"
                                      : "flood across tests passed\n");
  return lsi::test::Failures() ? 1 : 0;
}
