// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
// Particle Density on real particles: the Evrard collapse glass, whose density is
// rho(r) = 1 / (2 pi r) (its own rho column is a placeholder), radially binned against that
// profile; the same glass in other units (lengths x 1000, masses x 7) gives the same density up
// to the units' factor; the ChaNGa galaxy's dark matter, which carries no density at all.
//   TestParticleDensity GLASS_FILE GALAXY_FILE
#include "vtkParticleDensity.h"
#include "vtkTipsyParticleReader.h"

#include "TestCheck.h"

#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkStringArray.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iomanip>
#include <iostream>
#include <string>
#include <vector>

namespace
{
using lsi::test::Check;

vtkSmartPointer<vtkPolyData> Read(const std::string& path)
{
  vtkNew<vtkTipsyParticleReader> reader;
  reader->SetFileName(path.c_str());
  reader->Update();
  return vtkPolyData::SafeDownCast(reader->GetOutput());
}

vtkSmartPointer<vtkPolyData> Density(vtkPolyData* particles)
{
  vtkNew<vtkParticleDensity> density;
  density->SetInputData(particles);
  density->Update();
  return vtkPolyData::SafeDownCast(density->GetOutput());
}

void TestEvrardProfile(vtkPolyData* glass)
{
  vtkSmartPointer<vtkPolyData> out = Density(glass);
  vtkDataArray* rho = out ? out->GetPointData()->GetArray("Density") : nullptr;
  Check(rho && out->GetPointData()->GetScalars() == rho, "Density is the active scalars");
  vtkStringArray* marker = out
    ? vtkStringArray::SafeDownCast(out->GetFieldData()->GetAbstractArray("DensityArray"))
    : nullptr;
  Check(marker && marker->GetValue(0) == "Density", "field data names the density array");
  if (!rho)
  {
    return;
  }
  // Bins of width 0.1 in r over [0.1, 0.9]: the mean of rho / (1 / (2 pi r)) in each.
  const int bins = 8;
  std::vector<double> sum(bins, 0.0);
  std::vector<int> count(bins, 0);
  for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i)
  {
    double x[3];
    out->GetPoint(i, x);
    const double r = std::sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]);
    const int b = static_cast<int>(std::floor((r - 0.1) / 0.1));
    if (b >= 0 && b < bins)
    {
      sum[b] += rho->GetTuple1(i) * 2.0 * 3.14159265358979323846 * r;
      ++count[b];
    }
  }
  std::cout << "Evrard glass, 28,721 particles, 64 neighbours, cubic spline:\n"
            << "| r | particles | mean rho / (1 / (2 pi r)) |\n|---|---|---|\n";
  double worst = 0.0;
  for (int b = 0; b < bins; ++b)
  {
    const double ratio = count[b] ? sum[b] / count[b] : 0.0;
    worst = std::max(worst, std::abs(ratio - 1.0));
    std::cout << "| " << std::fixed << std::setprecision(1) << 0.1 + 0.1 * b << "-" << 0.2 + 0.1 * b
              << " | " << count[b] << " | " << std::setprecision(4) << ratio << " |\n";
  }
  std::cout << "largest deviation: " << worst << "\n";
  Check(worst < 0.05, "the density within 5% of 1 / (2 pi r) in every bin for 0.1 < r < 0.9");
}

// The same particles in other units: lengths x 1000, masses x 7. Density scales by
// 7 / 1000^3, the smoothing lengths by 1000; nothing else may change.
void TestUnits(vtkPolyData* glass)
{
  vtkNew<vtkPolyData> scaled;
  scaled->DeepCopy(glass);
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(glass->GetNumberOfPoints());
  vtkDataArray* mass = scaled->GetPointData()->GetArray("mass");
  for (vtkIdType i = 0; i < glass->GetNumberOfPoints(); ++i)
  {
    double x[3];
    glass->GetPoint(i, x);
    points->SetPoint(i, 1000.0 * x[0], 1000.0 * x[1], 1000.0 * x[2]);
    mass->SetTuple1(i, 7.0 * glass->GetPointData()->GetArray("mass")->GetTuple1(i));
  }
  scaled->SetPoints(points);
  vtkSmartPointer<vtkPolyData> a = Density(glass), b = Density(scaled);
  double worst = 0.0;
  for (vtkIdType i = 0; i < glass->GetNumberOfPoints(); ++i)
  {
    const double ra = a->GetPointData()->GetArray("Density")->GetTuple1(i);
    const double rb = b->GetPointData()->GetArray("Density")->GetTuple1(i);
    const double ha = a->GetPointData()->GetArray("SmoothingLength")->GetTuple1(i);
    const double hb = b->GetPointData()->GetArray("SmoothingLength")->GetTuple1(i);
    worst =
      std::max({ worst, std::abs(rb / (ra * 7e-9) - 1.0), std::abs(hb / (ha * 1000.0) - 1.0) });
  }
  std::cout << "other units: largest relative difference " << std::scientific << worst << "\n";
  Check(worst < 1e-5, "the density in other units is the same up to the units' factor");
}

void TestGalaxy(const std::string& path)
{
  vtkSmartPointer<vtkPolyData> dark = Read(path); // no gas: dark matter by default
  Check(dark && dark->GetNumberOfPoints() == 3627 && !dark->GetPointData()->GetArray("rho"),
    path + ": 3,627 dark-matter particles without a density");
  if (!dark || dark->GetNumberOfPoints() == 0)
  {
    return;
  }
  vtkSmartPointer<vtkPolyData> out = Density(dark);
  vtkDataArray* rho = out->GetPointData()->GetArray("Density");
  // The halo is centrally concentrated: the densest tenth of the particles lies nearer the
  // centre of mass than the rest, and every density is finite and positive.
  const vtkIdType n = out->GetNumberOfPoints();
  double centre[3] = { 0, 0, 0 }, total = 0.0;
  vtkDataArray* mass = out->GetPointData()->GetArray("mass");
  bool positive = true;
  for (vtkIdType i = 0; i < n; ++i)
  {
    double x[3];
    out->GetPoint(i, x);
    const double m = mass->GetTuple1(i);
    for (int d = 0; d < 3; ++d)
    {
      centre[d] += m * x[d];
    }
    total += m;
    positive = positive && std::isfinite(rho->GetTuple1(i)) && rho->GetTuple1(i) > 0.0;
  }
  std::vector<std::pair<double, double>> byDensity; // (rho, r)
  for (vtkIdType i = 0; i < n; ++i)
  {
    double x[3];
    out->GetPoint(i, x);
    const double r = std::sqrt(std::pow(x[0] - centre[0] / total, 2) +
      std::pow(x[1] - centre[1] / total, 2) + std::pow(x[2] - centre[2] / total, 2));
    byDensity.emplace_back(rho->GetTuple1(i), r);
  }
  std::sort(byDensity.rbegin(), byDensity.rend());
  double inner = 0.0, outer = 0.0;
  const std::size_t tenth = byDensity.size() / 10;
  for (std::size_t i = 0; i < byDensity.size(); ++i)
  {
    (i < tenth ? inner : outer) += byDensity[i].second;
  }
  inner /= tenth;
  outer /= byDensity.size() - tenth;
  std::cout << path << ": densest tenth at mean radius " << inner << ", the rest at " << outer
            << "\n";
  Check(positive, path + ": every density finite and positive");
  Check(inner < 0.5 * outer, path + ": the densest particles lie at the halo's centre");
}
} // namespace

int main(int argc, char* argv[])
{
  if (argc != 3)
  {
    std::cerr << "usage: TestParticleDensity GLASS_FILE GALAXY_FILE\n";
    return EXIT_FAILURE;
  }
  vtkSmartPointer<vtkPolyData> glass = Read(argv[1]);
  Check(glass && glass->GetNumberOfPoints() == 28721, "the Evrard glass read");
  if (glass)
  {
    TestEvrardProfile(glass);
    TestUnits(glass);
  }
  TestGalaxy(argv[2]);
  std::cout << (lsi::test::Failures() ? "particle density tests FAILED\n"
                                      : "particle density tests passed\n");
  return lsi::test::Failures() ? EXIT_FAILURE : EXIT_SUCCESS;
}
