// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
// What the surface encloses on the multi-component case (four Gaussian blobs, two seeded): the
// Enclosed table (port 3) has one row per seeded component and a total, and each component's
// volume is within 3% of the exact volume of {f > 0.5} around its blob, integrated from the
// analytic field on a fine grid (volumes from the particles' neighbourhood radii, no masses).
#include "CaseRuns.h"
#include "SyntheticParticles.h"
#include "TestCheck.h"

#include "vtkAbstractArray.h"
#include "vtkDataArray.h"
#include "vtkTable.h"
#include "vtkVariant.h"

#include <cmath>
#include <cstdlib>
#include <iostream>
#include <string>

namespace
{
using namespace lsi::cases;

// The volume of {f > iso} that belongs to blob k (the blob whose term is largest there), by the
// midpoint rule on a grid of the given step over the case's box.
double ExactVolume(const MultiComponentCase& c, int k, double step)
{
  double volume = 0.0;
  const Eigen::Vector3d size = c.BoxMax - c.BoxMin;
  const int nx = static_cast<int>(std::ceil(size.x() / step));
  const int ny = static_cast<int>(std::ceil(size.y() / step));
  const int nz = static_cast<int>(std::ceil(size.z() / step));
  for (int i = 0; i < nx; ++i)
  {
    for (int j = 0; j < ny; ++j)
    {
      for (int l = 0; l < nz; ++l)
      {
        const Eigen::Vector3d x = c.BoxMin + step * Eigen::Vector3d(i + 0.5, j + 0.5, l + 0.5);
        if (c.Value(x) > c.IsoValue && c.Component(x) == k)
        {
          volume += step * step * step;
        }
      }
    }
  }
  return volume;
}
} // namespace

int main()
{
  MultiComponentCase c;
  const std::size_t count = 400000;
  const std::vector<Eigen::Vector3d> samples = c.Samples(count, 1);
  vtkSmartPointer<vtkPolyData> particles = MakeParticles(c, samples);
  vtkNew<vtkLevelSetIsosurface> filter;
  filter->SetInputData(particles);
  SetCaseInputs(filter, c);
  filter->Update();
  vtkTable* table = vtkTable::SafeDownCast(filter->GetOutputDataObject(3));
  using lsi::test::Check;
  Check(table && table->GetNumberOfRows() == 3,
    "3 rows (two seeded components and the total), got " +
      std::to_string(table ? table->GetNumberOfRows() : 0));
  if (lsi::test::Failures())
  {
    return EXIT_FAILURE;
  }
  vtkDataArray* volume = vtkDataArray::SafeDownCast(table->GetColumnByName("Volume"));
  vtkDataArray* centre = vtkDataArray::SafeDownCast(table->GetColumnByName("CenterOfMass"));
  double total = 0.0;
  for (vtkIdType row = 0; row < 2; ++row)
  {
    // The row's blob: the seeded blob nearest its centre of mass.
    const Eigen::Vector3d at(centre->GetTuple3(row));
    const int k = (at - c.Blobs[0].Center).norm() < (at - c.Blobs[1].Center).norm() ? 0 : 1;
    const double exact = ExactVolume(c, k, 0.4);
    const double measured = volume->GetTuple1(row);
    total += exact;
    std::cout << table->GetValueByName(row, "Name").ToString() << " (blob " << k << " at "
              << c.Blobs[k].Center.transpose() << "): volume " << measured << ", exact " << exact
              << ", ratio " << measured / exact << "\n";
    Check(std::abs(measured / exact - 1.0) <= 0.03,
      "component " + std::to_string(row + 1) + "'s volume is off by more than 3%");
  }
  std::cout << "Total: volume " << volume->GetTuple1(2) << ", exact " << total << ", ratio "
            << volume->GetTuple1(2) / total << "\n";
  Check(std::abs(volume->GetTuple1(2) / total - 1.0) <= 0.03, "total volume off by more than 3%");
  return lsi::test::Failures() ? EXIT_FAILURE : EXIT_SUCCESS;
}
