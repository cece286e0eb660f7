// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkParticleDensity.h"

#include "LevelSetParallel.h"
#include "NearestNeighbors.h"
#include "SPHKernels.h"

#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPointSet.h"
#include "vtkSMPTools.h"
#include "vtkStringArray.h"

#include <algorithm>
#include <cmath>
#include <vector>

vtkStandardNewMacro(vtkParticleDensity);

namespace
{
// The particle masses: the first array of the readers' names, or none (unit mass).
vtkDataArray* MassArray(vtkPointData* data)
{
  for (const char* name : { "Masses", "Mass", "mass" })
  {
    vtkDataArray* array = data->GetArray(name);
    if (array && array->GetNumberOfComponents() == 1)
    {
      return array;
    }
  }
  return nullptr;
}

void NameInFieldData(vtkFieldData* fields, const char* marker, const char* arrayName)
{
  vtkNew<vtkStringArray> name;
  name->SetName(marker);
  name->InsertNextValue(arrayName);
  fields->RemoveArray(marker);
  fields->AddArray(name);
}
} // namespace

int vtkParticleDensity::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPointSet* input = vtkPointSet::GetData(inputVector[0]);
  vtkPointSet* output = vtkPointSet::GetData(outputVector);
  output->ShallowCopy(input);
  const vtkIdType n = input->GetNumberOfPoints();
  const std::size_t k = static_cast<std::size_t>(this->NumberOfNeighbors);
  if (n < this->NumberOfNeighbors)
  {
    vtkErrorMacro("The input has "
      << n << " points, fewer than NumberOfNeighbors = " << this->NumberOfNeighbors << ".");
    output->Initialize();
    return 0;
  }
  std::vector<double> xyz(3 * static_cast<std::size_t>(n));
  for (vtkIdType i = 0; i < n; ++i)
  {
    input->GetPoint(i, &xyz[3 * i]);
    if (!std::isfinite(xyz[3 * i]) || !std::isfinite(xyz[3 * i + 1]) ||
      !std::isfinite(xyz[3 * i + 2]))
    {
      vtkErrorMacro("Point " << i << " has a NaN or infinite coordinate.");
      output->Initialize();
      return 0;
    }
  }
  vtkDataArray* masses = MassArray(input->GetPointData());
  if (!masses)
  {
    vtkWarningMacro("No Masses, Mass or mass point array: every particle has mass 1.");
  }
  std::vector<double> mass(static_cast<std::size_t>(n), 1.0);
  for (vtkIdType i = 0; masses && i < n; ++i)
  {
    mass[i] = masses->GetTuple1(i);
  }

  const lsi::PointCloudIndex index(xyz.data(), static_cast<std::size_t>(n));
  const lsi::SPHKernel kernel = static_cast<lsi::SPHKernel>(this->Kernel);
  vtkNew<vtkDoubleArray> density, support;
  density->SetName("Density");
  density->SetNumberOfValues(n);
  support->SetName("SmoothingLength");
  support->SetNumberOfValues(n);
  std::size_t coincident = 0;
  bool completed = false;
  // VTK's global SMP backend may be Sequential (as in ParaView 5.11): use std::threads here.
  vtkSMPTools::LocalScope(vtkSMPTools::Config{ 0, "STDThread", false }, [&]() {
    completed = lsi::ParallelForInBlocks(
      static_cast<std::size_t>(n),
      [&](std::size_t begin, std::size_t end) {
        std::vector<std::uint32_t> ids(k);
        std::vector<double> d2(k);
        for (std::size_t i = begin; i < end; ++i)
        {
          const std::size_t found = index.Nearest(&xyz[3 * i], k, ids.data(), d2.data());
          const double H = std::sqrt(d2[found - 1]);
          double rho = 0.0;
          for (std::size_t j = 0; j < found; ++j)
          {
            rho += mass[ids[j]] * lsi::SPHKernelValue(kernel, std::sqrt(d2[j]), H);
          }
          density->SetValue(static_cast<vtkIdType>(i), H > 0.0 ? rho : 0.0);
          support->SetValue(static_cast<vtkIdType>(i), H);
        }
      },
      [this](double done) {
        this->UpdateProgress(done);
        return this->CheckAbort();
      },
      8192);
  });
  if (!completed)
  {
    output->Initialize();
    return 1;
  }
  for (vtkIdType i = 0; i < n; ++i)
  {
    coincident += support->GetValue(i) == 0.0;
  }
  if (coincident > 0)
  {
    vtkWarningMacro(<< coincident << " particles have all their " << k
                    << " nearest neighbours at their own position: their density is set to 0. "
                       "Merge duplicate points first, e.g. with Clean.");
  }
  output->GetPointData()->AddArray(support);
  output->GetPointData()->AddArray(density);
  output->GetPointData()->SetActiveScalars("Density");
  if (!masses) // the unit masses the density assumed, so that the SPH field can use them
  {
    vtkNew<vtkDoubleArray> ones;
    ones->SetName("Masses");
    ones->SetNumberOfValues(n);
    ones->Fill(1.0);
    output->GetPointData()->AddArray(ones);
  }
  // What the SPH field of this density is: vtkLevelSetIsosurface reads these markers.
  vtkFieldData* fields = output->GetFieldData();
  NameInFieldData(fields, "DensityArray", "Density");
  NameInFieldData(fields, "SmoothingLengthArray", "SmoothingLength");
  NameInFieldData(fields, "MassArray", masses ? masses->GetName() : "Masses");
  const char* kernelNames[] = { "CubicSpline", "QuinticSpline", "WendlandC2" };
  NameInFieldData(fields, "SPHKernel", kernelNames[this->Kernel]);
  vtkNew<vtkDoubleArray> supportFactor; // SmoothingLength is the support radius itself
  supportFactor->SetName("SupportPerSmoothingLength");
  supportFactor->InsertNextValue(1.0);
  fields->RemoveArray("SupportPerSmoothingLength");
  fields->AddArray(supportFactor);
  return 1;
}

void vtkParticleDensity::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "NumberOfNeighbors: " << this->NumberOfNeighbors << "\n";
  os << indent << "Kernel: " << this->Kernel << "\n";
}
