// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
// The Enclosed table around a kept deep inside (LevelSetEnclosedDeepInside) against the table
// over every touching sample (LevelSetEnclosed.cxx), on random particles in a unit box with phi
// the signed distance to two balls, clamped at the band's half width:
//   - the run that keeps the deep inside gives the full route's table (rows, particle counts
//     exactly, every number to 1e-9), with a cluster of particles inside but not deep that
//     only the deep particles' neighbour lists join to its ball;
//   - after the balls shrink by 1.5 spacings or grow by one inside the band (phi changed only
//     there, as a slide shifts it, the surface moved), the table around the kept deep inside is
//     again the full route's, and the grown balls, apart before, are one component;
//   - the same numbers, to the bit, on 1 and 2 threads, and with the surface points nearest to
//     the band's samples taken from those the first run kept or searched;
//   - the union-find (Links), joined from 1 or 2 threads at once, gives the sets, and roots, of
//     a plain serial one on random joins;
//   - every sample a slide changed is among the deep inside's near samples (where a re-run
//     looks for the band), and the particles' LevelSet array updated at the changed samples
//     only (UpdateParticleOutput) is the one made anew, to the bit.
#include "LevelSetEnclosed.h"
#include "LevelSetEnclosedSums.h"
#include "LevelSetNeighborhoods.h"
#include "LevelSetParticleOutput.h"
#include "TestCheck.h"

#include "vtkDoubleArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSMPTools.h"
#include "vtkStringArray.h"
#include "vtkTable.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <random>
#include <string>
#include <vector>

namespace
{
using lsi::test::Check;

struct Balls
{
  double Centre[2][3] = { { 0.25, 0.5, 0.5 }, { 0.75, 0.5, 0.5 } };
  double Radius = 0.2;

  double SignedDistance(const double* x) const // positive inside
  {
    double best = -HUGE_VAL;
    for (const auto& c : this->Centre)
    {
      const double d = std::sqrt((x[0] - c[0]) * (x[0] - c[0]) + (x[1] - c[1]) * (x[1] - c[1]) +
        (x[2] - c[2]) * (x[2] - c[2]));
      best = std::max(best, this->Radius - d);
    }
    return best;
  }

  // Points spread over both spheres (a Fibonacci lattice each) and their outward normals.
  void Surface(std::vector<double>& points, std::vector<double>& normals) const
  {
    const int count = 6000;
    for (const auto& c : this->Centre)
    {
      for (int k = 0; k < count; ++k)
      {
        const double z = 1.0 - (2.0 * k + 1.0) / count, r = std::sqrt(1.0 - z * z);
        const double angle = k * 2.399963229728653;
        const double n[3] = { r * std::cos(angle), r * std::sin(angle), z };
        for (int d = 0; d < 3; ++d)
        {
          points.push_back(c[d] + this->Radius * n[d]);
          normals.push_back(n[d]);
        }
      }
    }
  }
};

// Compares two tables: the same rows and names, the same particle counts, every other number
// to `tolerance` relative to its column's largest.
void CheckSameTable(vtkTable* expected, vtkTable* got, double tolerance, const std::string& what)
{
  Check(expected && got, what + ": both tables made");
  if (!expected || !got)
  {
    return;
  }
  Check(expected->GetNumberOfRows() == got->GetNumberOfRows() &&
      expected->GetNumberOfColumns() == got->GetNumberOfColumns(),
    what + ": " + std::to_string(got->GetNumberOfRows()) + " rows, expected " +
      std::to_string(expected->GetNumberOfRows()));
  if (lsi::test::Failures())
  {
    return;
  }
  for (vtkIdType c = 0; c < expected->GetNumberOfColumns(); ++c)
  {
    const std::string name = expected->GetColumnName(c);
    if (auto* names = vtkStringArray::SafeDownCast(expected->GetColumn(c)))
    {
      auto* other = vtkStringArray::SafeDownCast(got->GetColumnByName(name.c_str()));
      for (vtkIdType r = 0; other && r < names->GetNumberOfValues(); ++r)
      {
        Check(names->GetValue(r) == other->GetValue(r), what + ": row names");
      }
      continue;
    }
    auto* a = vtkDataArray::SafeDownCast(expected->GetColumn(c));
    auto* b = vtkDataArray::SafeDownCast(got->GetColumnByName(name.c_str()));
    Check(a && b, what + ": column " + name);
    if (!a || !b)
    {
      continue;
    }
    double scale = 0.0, worst = 0.0;
    for (vtkIdType k = 0; k < a->GetNumberOfValues(); ++k)
    {
      scale = std::max(scale, std::abs(a->GetVariantValue(k).ToDouble()));
      worst = std::max(
        worst, std::abs(a->GetVariantValue(k).ToDouble() - b->GetVariantValue(k).ToDouble()));
    }
    const double allowed = name == "Particles" ? 0.0 : tolerance * scale;
    Check(worst <= allowed,
      what + ": column " + name + " differs by " + std::to_string(worst) + " (" +
        std::to_string(allowed) + " allowed)");
  }
}

// Random joins among a few large sets and many small ones, in parallel, against a plain serial
// union-find: every element's root (its set's lowest member) the same.
void CheckLinks(int threads)
{
  const std::size_t n = 200000;
  std::mt19937_64 generator(11);
  // First a star: the last element joined to ever lower ones, so that the threads link the
  // same root at once; then random joins, half within a neighbourhood (chains), half anywhere.
  std::vector<std::pair<std::uint32_t, std::uint32_t>> joins;
  for (std::uint32_t k = 2; k < 100000; ++k)
  {
    joins.emplace_back(static_cast<std::uint32_t>(n - 1), static_cast<std::uint32_t>(n - k));
  }
  for (int j = 0; j < 20000; ++j)
  {
    const std::uint32_t a = static_cast<std::uint32_t>(generator() % n);
    const std::uint32_t b = generator() % 2 ? static_cast<std::uint32_t>((a + generator() % 16) % n)
                                            : static_cast<std::uint32_t>(generator() % n);
    joins.emplace_back(a, b);
  }
  std::vector<std::uint32_t> serial(n); // each set linked towards its lowest member
  for (std::uint32_t i = 0; i < n; ++i)
  {
    serial[i] = i;
  }
  auto find = [&](std::uint32_t i) {
    while (serial[i] != i)
    {
      serial[i] = serial[serial[i]]; // (path halving: the star's chain would be walked whole)
      i = serial[i];
    }
    return i;
  };
  for (const auto& join : joins)
  {
    const std::uint32_t a = find(join.first), b = find(join.second);
    serial[std::max(a, b)] = std::min(a, b);
  }
  const lsi::enclosed::Links shared(n);
  vtkSMPTools::LocalScope(vtkSMPTools::Config{ threads, "STDThread", false }, [&]() {
    vtkSMPTools::For(
      0, static_cast<vtkIdType>(joins.size()), 64, [&](vtkIdType begin, vtkIdType end) {
        for (vtkIdType k = begin; k < end; ++k)
        {
          shared.Join(joins[k].first, joins[k].second);
        }
      });
  });
  std::size_t differ = 0, roots = 0;
  for (std::uint32_t i = 0; i < n; ++i)
  {
    differ += find(i) != shared.Find(i) ? 1 : 0;
    roots += shared.Find(i) == i ? 1 : 0;
  }
  Check(differ == 0 && roots > 1 && roots < n,
    "Links joined on " + std::to_string(threads) + " threads: the serial sets' roots (" +
      std::to_string(differ) + " differ, " + std::to_string(roots) + " sets)");
}

bool SameBits(vtkTable* a, vtkTable* b)
{
  for (vtkIdType c = 0; c < a->GetNumberOfColumns(); ++c)
  {
    auto* x = vtkDataArray::SafeDownCast(a->GetColumn(c));
    auto* y = vtkDataArray::SafeDownCast(b->GetColumn(c));
    for (vtkIdType k = 0; x && y && k < x->GetNumberOfValues(); ++k)
    {
      if (x->GetVariantValue(k).ToDouble() != y->GetVariantValue(k).ToDouble())
      {
        return false;
      }
    }
  }
  return true;
}
} // namespace

int main()
{
  CheckLinks(1);
  CheckLinks(2);

  // Random particles with a scalar and a vector array (their means are columns too).
  // Random particles, and a tight cluster of `clustered` more at the first ball's centre: each
  // lists only the cluster's own particles, and the deep particles around list them.
  const vtkIdType random = 400000, clustered = 40, n = random + clustered;
  std::mt19937_64 generator(7);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(n);
  vtkNew<vtkDoubleArray> f, v;
  f->SetName("f");
  v->SetName("v");
  v->SetNumberOfComponents(3);
  f->SetNumberOfTuples(n);
  v->SetNumberOfTuples(n);
  for (vtkIdType i = 0; i < n; ++i)
  {
    double x[3] = { uniform(generator), uniform(generator), uniform(generator) };
    if (i >= random)
    {
      const Balls centre;
      for (int d = 0; d < 3; ++d)
      {
        x[d] = centre.Centre[0][d] + 1e-4 * (x[d] - 0.5);
      }
    }
    points->SetPoint(i, x);
    f->SetValue(i, 1.0 + x[0]);
    v->SetTuple3(i, x[1], -x[2], 2.0);
  }
  vtkNew<vtkPolyData> particles;
  particles->SetPoints(points);
  particles->GetPointData()->AddArray(f);
  particles->GetPointData()->AddArray(v);
  lsi::Neighborhoods geometry;
  lsi::BuildNeighborhoods(points, 24, geometry, lsi::AbortCheck());

  // phi: the signed distance to the balls, clamped at the band's half width.
  const double halfWidth = 3.0 * geometry.MeanRadius;
  Balls balls;
  std::vector<double> phi(geometry.NumberOfSamples);
  for (std::size_t i = 0; i < phi.size(); ++i)
  {
    phi[i] = std::max(-halfWidth, std::min(halfWidth, balls.SignedDistance(geometry.Position(i))));
    // The cluster inside but not deep: only the deep particles' lists (the rim's) join it to
    // its ball's component.
    phi[i] = geometry.Order[i] >= random ? 0.5 * halfWidth : phi[i];
  }
  std::vector<double> surface, normals;
  balls.Surface(surface, normals);
  lsi::EnclosedInputs in;
  in.Geometry = &geometry;
  in.Phi = &phi;
  in.FarOutside = -halfWidth;
  in.Particles = particles;
  in.ParticleCount = n;
  in.SurfacePoints = &surface;
  in.SurfaceNormals = &normals;

  vtkSmartPointer<vtkTable> full = lsi::EnclosedTable(in);
  lsi::EnclosedDeepInside deep;
  in.KeepDeepInside = &deep;
  vtkSmartPointer<vtkTable> kept = lsi::EnclosedTable(in);
  in.KeepDeepInside = nullptr;
  const std::size_t deepSamples =
    static_cast<std::size_t>(std::count_if(deep.Group.begin(), deep.Group.end(),
      [](std::uint32_t g) { return g != lsi::EnclosedDeepInside::None; })) -
    deep.Near.size();
  Check(deepSamples > 3000 && !deep.Rim.empty(),
    "a deep inside with a rim was found (" + std::to_string(deepSamples) + " samples)");
  CheckSameTable(full, kept, 1e-9, "the run that keeps the deep inside");
  Check(full && full->GetNumberOfRows() == 3,
    "two balls apart: two components and the total (" +
      std::to_string(full ? full->GetNumberOfRows() : 0) + " rows)");

  // The balls slide by `change`: phi changes only inside the band, as a slide shifts it.
  const std::vector<double> phiBefore = phi;
  const double radiusBefore = balls.Radius;
  auto slide = [&](double change) {
    balls.Radius = radiusBefore + change;
    for (std::size_t i = 0; i < phi.size(); ++i)
    {
      phi[i] = std::abs(phiBefore[i]) < halfWidth
        ? std::max(-halfWidth, std::min(halfWidth, balls.SignedDistance(geometry.Position(i))))
        : phiBefore[i];
    }
    surface.clear();
    normals.clear();
    balls.Surface(surface, normals);
  };
  // Shrinking by 1.5 spacings: samples inside the band come within a shell width of the
  // surface (they count in part now), the deep inside still counts in full.
  slide(-1.5 * geometry.MeanRadius);
  vtkSmartPointer<vtkTable> shrunkFull = lsi::EnclosedTable(in);
  in.DeepInside = &deep;
  CheckSameTable(shrunkFull, lsi::EnclosedTable(in), 1e-9, "around the deep inside, shrunk");
  in.DeepInside = nullptr;
  // Growing by a spacing: the shells meet.
  slide(geometry.MeanRadius);
  vtkSmartPointer<vtkTable> grownFull = lsi::EnclosedTable(in);
  in.DeepInside = &deep;
  vtkSmartPointer<vtkTable> grown;
  vtkSmartPointer<vtkTable> grownOneThread;
  {
    vtkSMPTools::LocalScope(
      vtkSMPTools::Config{ 2, "STDThread", false }, [&]() { grown = lsi::EnclosedTable(in); });
    vtkSMPTools::LocalScope(vtkSMPTools::Config{ 1, "STDThread", false },
      [&]() { grownOneThread = lsi::EnclosedTable(in); });
  }
  CheckSameTable(grownFull, grown, 1e-9, "around the kept deep inside, after a slide");
  // The surface points nearest to the band's samples, kept by the run that found the deep
  // inside: the distances taken from them are a search's, to the bit.
  Check(deep.Surface.Queries() > 1000 && deep.SurfaceQuery.size() == deep.Near.size(),
    "the band's nearest surface points kept (" + std::to_string(deep.Surface.Queries()) +
      " samples)");
  lsi::EnclosedDeepInside searched = deep;
  searched.SurfaceQuery.clear();
  in.DeepInside = &searched;
  Check(SameBits(grown, lsi::EnclosedTable(in)),
    "the same table to the bit with the kept surface points as with searches");
  // The same surface points in the reverse order (each far from where it lay): all searched.
  std::vector<double> reversed(surface.size()), reversedNormals(normals.size());
  const std::size_t m = surface.size() / 3;
  for (std::size_t k = 0; k < m; ++k)
  {
    std::copy(&surface[3 * k], &surface[3 * k] + 3, &reversed[3 * (m - 1 - k)]);
    std::copy(&normals[3 * k], &normals[3 * k] + 3, &reversedNormals[3 * (m - 1 - k)]);
  }
  surface.swap(reversed);
  normals.swap(reversedNormals);
  const vtkSmartPointer<vtkTable> reversedSearched = lsi::EnclosedTable(in);
  in.DeepInside = &deep;
  Check(SameBits(reversedSearched, lsi::EnclosedTable(in)),
    "the surface points renumbered: the same table to the bit as with searches");
  surface.swap(reversed);
  normals.swap(reversedNormals);
  Check(grownFull && grownFull->GetNumberOfRows() == 2,
    "the grown balls' shells meet: one component and the total (" +
      std::to_string(grownFull ? grownFull->GetNumberOfRows() : 0) + " rows)");
  Check(grown && grownOneThread && SameBits(grown, grownOneThread),
    "the same table to the bit on 1 and 2 threads");

  // The samples the slides changed, all near; the LevelSet array updated there only.
  std::vector<std::size_t> changed;
  std::vector<char> near(phi.size(), 0);
  for (std::uint32_t i : deep.Near)
  {
    near[i] = 1;
  }
  std::size_t changedFar = 0;
  for (std::size_t i = 0; i < phi.size(); ++i)
  {
    if (phi[i] != phiBefore[i])
    {
      changed.push_back(i);
      changedFar += near[i] ? 0 : 1;
    }
  }
  Check(changed.size() > 1000 && changedFar == 0,
    "every one of the " + std::to_string(changed.size()) + " samples the slides changed is near (" +
      std::to_string(changedFar) + " not)");
  vtkSmartPointer<vtkCellArray> vertices;
  vtkSmartPointer<vtkDoubleArray> spare;
  vtkNew<vtkPolyData> before, updated, remade;
  lsi::MakeParticleOutput(particles, geometry, phiBefore, {}, before, vertices, spare);
  const bool didUpdate = lsi::UpdateParticleOutput(particles, geometry, phi, changed,
    before->GetPointData()->GetArray("LevelSet"), updated, vertices, spare);
  lsi::MakeParticleOutput(particles, geometry, phi, {}, remade, vertices, spare);
  vtkDoubleArray* a = vtkDoubleArray::SafeDownCast(updated->GetPointData()->GetArray("LevelSet"));
  vtkDoubleArray* b = vtkDoubleArray::SafeDownCast(remade->GetPointData()->GetArray("LevelSet"));
  Check(didUpdate && a && b && a->GetNumberOfValues() == n && b->GetNumberOfValues() == n &&
      std::equal(a->GetPointer(0), a->GetPointer(0) + n, b->GetPointer(0)) &&
      updated->GetPointData()->GetArray("f") && updated->GetNumberOfVerts() == n,
    "the LevelSet array updated at the changed samples is the one made anew");
  vtkNew<vtkDoubleArray> shorter;
  shorter->SetNumberOfValues(n - 1);
  Check(!lsi::UpdateParticleOutput(
          particles, geometry, phi, changed, shorter, updated, vertices, spare),
    "no update from an array of another length");

  // A spare LevelSet array: its memory is reused when nothing else holds it, with every value
  // written anew (it starts as garbage); an array held elsewhere is left alone.
  auto levelSetOf = [](vtkPolyData* p) {
    return vtkDoubleArray::SafeDownCast(p->GetPointData()->GetArray("LevelSet"));
  };
  spare = vtkSmartPointer<vtkDoubleArray>::New();
  spare->SetNumberOfValues(n);
  spare->Fill(12345.0);
  const double* memory = spare->GetPointer(0);
  vtkNew<vtkPolyData> reused, reusedUpdate;
  lsi::MakeParticleOutput(particles, geometry, phi, {}, reused, vertices, spare);
  vtkDoubleArray* r = levelSetOf(reused);
  Check(!spare && r && r->GetPointer(0) == memory &&
      std::equal(r->GetPointer(0), r->GetPointer(0) + n, b->GetPointer(0)),
    "a spare array nothing else holds is reused, with the values made anew");
  spare = vtkSmartPointer<vtkDoubleArray>::New();
  spare->SetNumberOfValues(n);
  spare->Fill(12345.0);
  lsi::UpdateParticleOutput(particles, geometry, phi, changed,
    before->GetPointData()->GetArray("LevelSet"), reusedUpdate, vertices, spare);
  r = levelSetOf(reusedUpdate);
  Check(!spare && r && std::equal(r->GetPointer(0), r->GetPointer(0) + n, b->GetPointer(0)),
    "an update into a spare array gives the values made anew");
  spare = vtkSmartPointer<vtkDoubleArray>::New();
  spare->SetNumberOfValues(n);
  const vtkSmartPointer<vtkDoubleArray> holder = spare; // held elsewhere too
  vtkNew<vtkPolyData> fresh;
  lsi::MakeParticleOutput(particles, geometry, phi, {}, fresh, vertices, spare);
  r = levelSetOf(fresh);
  Check(r && r != holder.GetPointer() && r->GetPointer(0) != holder->GetPointer(0) &&
      std::equal(r->GetPointer(0), r->GetPointer(0) + n, b->GetPointer(0)),
    "a spare array held elsewhere is not written");

  if (lsi::test::Failures())
  {
    std::cerr << "deep inside tests FAILED\n";
    return EXIT_FAILURE;
  }
  std::cout << "deep inside tests passed\n";
  return EXIT_SUCCESS;
}
