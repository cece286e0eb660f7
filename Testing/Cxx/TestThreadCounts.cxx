// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
// The same input gives the same output on any number of threads: with 1, 2 and 4 threads the
// isopoints, their normals, the particles' LevelSet and the enclosed table (its sums run in
// parallel chunks) are identical, bit for bit, on the paper's case and on the adaptive noisy
// case. (Before the kd-tree's shape was fixed, 1 thread gave 9,427
// isopoints on the paper's case at 200k and 2 threads 9,420: the tree, built in one piece per
// thread, set the samples' storage order and with it the order of every result.)
#include "CaseRuns.h"
#include "SyntheticParticles.h"
#include "TestCheck.h"

#include "vtkDataArray.h"
#include "vtkTable.h"

#include <cstdlib>
#include <iostream>

namespace
{
using namespace lsi::cases;

struct Output
{
  std::vector<double> Points, Normals, LevelSet, Enclosed;
};

Output Run(vtkPolyData* particles, const Case& c, int threads)
{
  vtkNew<vtkLevelSetIsosurface> filter;
  filter->SetInputData(particles);
  SetCaseInputs(filter, c);
  filter->SetOutputTypeToIsopoints();
  filter->SetNumberOfThreads(threads);
  filter->Update();
  Output out;
  IsopointArrays(filter->GetOutput(0), out.Points, out.Normals);
  vtkDataArray* phi = filter->GetOutput(1)->GetPointData()->GetArray("LevelSet");
  for (vtkIdType i = 0; phi && i < phi->GetNumberOfTuples(); ++i)
  {
    out.LevelSet.push_back(phi->GetTuple1(i));
  }
  vtkTable* enclosed = vtkTable::SafeDownCast(filter->GetOutputDataObject(3));
  for (vtkIdType c = 0; enclosed && c < enclosed->GetNumberOfColumns(); ++c)
  {
    vtkDataArray* column = vtkArrayDownCast<vtkDataArray>(enclosed->GetColumn(c));
    for (vtkIdType r = 0; column && r < column->GetNumberOfTuples(); ++r)
    {
      for (int k = 0; k < column->GetNumberOfComponents(); ++k)
      {
        out.Enclosed.push_back(column->GetComponent(r, k));
      }
    }
  }
  return out;
}
} // namespace

int main()
{
  using lsi::test::Check;
  for (const char* name : { "one-component", "adaptive-noisy" })
  {
    const std::unique_ptr<Case> c = MakeCase(name);
    vtkSmartPointer<vtkPolyData> particles = MakeParticles(*c, c->Samples(200000, 1));
    const Output one = Run(particles, *c, 1);
    for (int threads : { 2, 4 })
    {
      const Output other = Run(particles, *c, threads);
      std::cout << name << ": " << one.Points.size() / 3 << " isopoints with 1 thread, "
                << other.Points.size() / 3 << " with " << threads << "\n";
      Check(!one.Points.empty() && other.Points == one.Points && other.Normals == one.Normals &&
          other.LevelSet == one.LevelSet,
        std::string(name) + ": " + std::to_string(threads) +
          " threads give the same isopoints, normals and LevelSet as 1, bit for bit");
      Check(!one.Enclosed.empty() && other.Enclosed == one.Enclosed,
        std::string(name) + ": " + std::to_string(threads) +
          " threads give the same enclosed table (" + std::to_string(one.Enclosed.size()) +
          " numbers) as 1, bit for bit");
    }
  }
  return lsi::test::Failures() ? EXIT_FAILURE : EXIT_SUCCESS;
}
