// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkParticleDensity.h"

#include "LevelSetDistribution.h"
#include "LevelSetParallel.h"
#include "NearestNeighbors.h"
#include "SPHKernels.h"

#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkMultiProcessController.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPointSet.h"
#include "vtkPolyData.h"
#include "vtkSMPTools.h"
#include "vtkStringArray.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkParticleDensity);
vtkCxxSetObjectMacro(vtkParticleDensity, Controller, vtkMultiProcessController);

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

// Appends the coordinates of `points` from point `first` on to `xyz` (xyz per point); `problem`
// names the first that is NaN or infinite.
void AppendCoordinates(
  vtkPointSet* points, vtkIdType first, std::vector<double>& xyz, std::string& problem)
{
  const vtkIdType n = points->GetNumberOfPoints();
  const std::size_t start = xyz.size();
  xyz.resize(start + 3 * static_cast<std::size_t>(std::max<vtkIdType>(0, n - first)));
  for (vtkIdType i = first; i < n; ++i)
  {
    double* x = &xyz[start + 3 * static_cast<std::size_t>(i - first)];
    points->GetPoint(i, x);
    if (problem.empty() && !(std::isfinite(x[0]) && std::isfinite(x[1]) && std::isfinite(x[2])))
    {
      problem = "Point " + std::to_string(i) + " has a NaN or infinite coordinate.";
    }
  }
}

// The bounds of the balls around the particles out to their k-th nearest among themselves
// (everywhere, when they are fewer than k): a particle's k nearest among all ranks' lie within
// its ball, since those among a rank's own lie no closer. Computed in parallel.
void NeighborReachBox(const std::vector<double>& xyz, std::size_t k, double box[6])
{
  const std::size_t n = xyz.size() / 3;
  for (int d = 0; d < 3; ++d)
  {
    box[2 * d] = n < k ? -HUGE_VAL : HUGE_VAL;
    box[2 * d + 1] = n < k ? HUGE_VAL : -HUGE_VAL;
  }
  if (n < k)
  {
    return;
  }
  const lsi::PointCloudIndex index(xyz.data(), n);
  std::vector<double> reach(n);
  // (On std::threads, as the densities below: VTK's global backend may be Sequential.)
  vtkSMPTools::LocalScope(vtkSMPTools::Config{ 0, "STDThread", false }, [&]() {
    vtkSMPTools::For(0, static_cast<vtkIdType>(n), lsi::BalancedGrain(n, 1024),
      [&](vtkIdType begin, vtkIdType end) {
        std::vector<std::uint32_t> ids(k);
        std::vector<double> d2(k);
        for (vtkIdType i = begin; i < end; ++i)
        {
          const std::size_t found = index.Nearest(&xyz[3 * i], k, ids.data(), d2.data());
          reach[i] = std::sqrt(d2[found - 1]);
        }
      });
  });
  for (std::size_t i = 0; i < n; ++i)
  {
    for (int d = 0; d < 3; ++d)
    {
      box[2 * d] = std::min(box[2 * d], xyz[3 * i + d] - reach[i]);
      box[2 * d + 1] = std::max(box[2 * d + 1], xyz[3 * i + d] + reach[i]);
    }
  }
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

vtkParticleDensity::vtkParticleDensity()
{
  this->SetController(vtkMultiProcessController::GetGlobalController());
}

vtkParticleDensity::~vtkParticleDensity()
{
  this->SetController(nullptr);
}

int vtkParticleDensity::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPointSet* input = vtkPointSet::GetData(inputVector[0]);
  vtkPointSet* output = vtkPointSet::GetData(outputVector);
  const std::size_t k = static_cast<std::size_t>(this->NumberOfNeighbors);
  // Under MPI every rank takes each decision with the others (none waits on a step another
  // skipped), and only rank 0 reports.
  lsi::Distribution ranks(this->Controller);
  const bool reports = ranks.Rank == 0;
  std::string problem;
  std::vector<double> xyz;
  AppendCoordinates(input, 0, xyz, problem);
  problem = ranks.FirstProblem(problem);
  const double total = ranks.Sum(static_cast<double>(input->GetNumberOfPoints()));
  if (problem.empty() && total < this->NumberOfNeighbors)
  {
    problem = "The input has " + std::to_string(static_cast<vtkIdType>(total)) +
      " points, fewer than NumberOfNeighbors = " + std::to_string(this->NumberOfNeighbors) + ".";
  }
  if (!problem.empty())
  {
    if (reports)
    {
      vtkErrorMacro(<< problem);
    }
    output->Initialize();
    return reports ? 0 : 1; // (the other ranks' executives would report it again)
  }
  const bool hasMasses = MassArray(input->GetPointData()) != nullptr;
  if (ranks.Max(input->GetNumberOfPoints() > 0 && !hasMasses ? 1.0 : 0.0) > 0.0 && reports)
  {
    vtkWarningMacro("No Masses, Mass or mass point array: every particle has mass 1.");
  }

  // The rank's particles (redistributed by space if the pieces are poor), then copies of the
  // other ranks' particles that their nearest may be (serial: the input alone).
  vtkSmartPointer<vtkPointSet> owned = input;
  vtkSmartPointer<vtkPointSet> work = input;
  if (ranks.Distributed())
  {
    std::string report;
    owned = ranks.Balanced(input, report);
    vtkDebugMacro(<< report);
    xyz.clear();
    AppendCoordinates(owned, 0, xyz, problem);
    double box[6];
    NeighborReachBox(xyz, k, box);
    std::vector<double> unused(static_cast<std::size_t>(owned->GetNumberOfPoints()), 0.0);
    work = ranks.WithGhosts(owned, box, std::vector<double>(), unused, problem);
    if (!work)
    {
      if (reports)
      {
        vtkErrorMacro(<< "The exchange of ghost particles failed: " << problem);
      }
      output->Initialize();
      return reports ? 0 : 1;
    }
    AppendCoordinates(work, owned->GetNumberOfPoints(), xyz, problem); // the ghosts, after
  }
  const vtkIdType n = owned->GetNumberOfPoints();
  const std::size_t all = xyz.size() / 3;
  vtkDataArray* masses = MassArray(work->GetPointData());
  std::vector<double> mass(all, 1.0);
  for (std::size_t i = 0; masses && i < all; ++i)
  {
    mass[i] = masses->GetTuple1(static_cast<vtkIdType>(i));
  }

  const lsi::PointCloudIndex index(xyz.data(), all);
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
  if (!ranks.All(completed)) // (aborted on some rank: all stop)
  {
    output->Initialize();
    return 1;
  }
  output->ShallowCopy(owned);
  for (vtkIdType i = 0; i < n; ++i)
  {
    coincident += support->GetValue(i) == 0.0;
  }
  coincident = static_cast<std::size_t>(ranks.Sum(static_cast<double>(coincident)));
  if (coincident > 0 && reports)
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
  NameInFieldData(fields, "SPHKernel", lsi::NamesOf(kernel).Marker);
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
