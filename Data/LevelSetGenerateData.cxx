// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
// Writes the synthetic test data (the paper's §8.2 one-component field, and our cases:
// SyntheticCases.h) as random samples with the scalar "f", to a binary .vtp (readable by Debian
// 12's ParaView 5.11, which cannot read appended-mode XML).
//   LevelSetGenerateData one-component|multi-component|adaptive-noisy|snake|sphere SAMPLES
//     OUTPUT.vtp [RANDOM_SEED] [EXACT_SURFACE.vtp]
// The optional last file receives the exact isosurface as a triangle mesh, for rendering tests:
// Flying Edges on the analytic field sampled on a 320^3 grid over the box (its error, about
// h^2 / (8 R) for grid step h and radius of curvature R, is far below a pixel).
#include "SyntheticCases.h"
#include "SyntheticParticles.h"

#include "vtkFloatArray.h"
#include "vtkFlyingEdges3D.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkXMLPolyDataWriter.h"

#include <cstdlib>
#include <iostream>
#include <memory>
#include <string>

namespace
{
bool WriteBinary(vtkPolyData* data, const char* fileName)
{
  vtkNew<vtkXMLPolyDataWriter> writer;
  writer->SetInputData(data);
  writer->SetDataModeToBinary(); // Debian 12's ParaView cannot read appended mode
  writer->SetFileName(fileName);
  return writer->Write() != 0;
}

bool WriteExactSurface(const lsi::cases::Case& c, const char* fileName)
{
  const int n = 320;
  vtkNew<vtkImageData> grid;
  grid->SetDimensions(n, n, n);
  const Eigen::Vector3d step = (c.BoxMax - c.BoxMin) / (n - 1);
  grid->SetOrigin(c.BoxMin.data());
  grid->SetSpacing(step.data());
  vtkNew<vtkFloatArray> values;
  values->SetName("f");
  values->SetNumberOfValues(static_cast<vtkIdType>(n) * n * n);
  vtkIdType id = 0;
  for (int k = 0; k < n; ++k)
  {
    for (int j = 0; j < n; ++j)
    {
      for (int i = 0; i < n; ++i)
      {
        const Eigen::Vector3d x = c.BoxMin + Eigen::Vector3d(i, j, k).cwiseProduct(step);
        values->SetValue(id++, static_cast<float>(c.Value(x) - c.IsoValue));
      }
    }
  }
  grid->GetPointData()->SetScalars(values);
  vtkNew<vtkFlyingEdges3D> contour;
  contour->SetInputData(grid);
  contour->SetValue(0, 0.0);
  contour->ComputeNormalsOn();
  contour->Update();
  return WriteBinary(contour->GetOutput(), fileName);
}
} // namespace

int main(int argc, char* argv[])
{
  if (argc < 4)
  {
    std::cerr << "usage: LevelSetGenerateData one-component|multi-component|adaptive-noisy|snake|"
                 "sphere SAMPLES OUTPUT.vtp [RANDOM_SEED] [EXACT_SURFACE.vtp]\n";
    return EXIT_FAILURE;
  }
  const std::string name = argv[1];
  const std::unique_ptr<lsi::cases::Case> c = lsi::cases::MakeCase(name);
  if (!c)
  {
    std::cerr << "unknown case " << name << "\n";
    return EXIT_FAILURE;
  }
  const std::size_t count = std::strtoull(argv[2], nullptr, 10);
  const std::uint64_t seed = argc > 4 ? std::strtoull(argv[4], nullptr, 10) : 1;
  const auto samples = c->Samples(count, seed);
  vtkSmartPointer<vtkPolyData> data = lsi::cases::MakeParticles(*c, samples);
  if (!WriteBinary(data, argv[3]))
  {
    std::cerr << "could not write " << argv[3] << "\n";
    return EXIT_FAILURE;
  }
  if (argc > 5 && !WriteExactSurface(*c, argv[5]))
  {
    std::cerr << "could not write " << argv[5] << "\n";
    return EXIT_FAILURE;
  }
  std::cout << "wrote " << count << " samples of the " << name << " case to " << argv[3]
            << " (isovalue " << c->IsoValue << ", seed centre " << c->Seeds[0].Center.transpose()
            << ", radius " << c->Seeds[0].Radius << ")\n";
  return EXIT_SUCCESS;
}
