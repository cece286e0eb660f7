// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
// Any bytes as a point set and the filter's parameters: the filter must give an error, a warning
// or a surface, never read out of bounds, crash or hang; and never NaN in the surface, nor an
// empty or non-converged surface, nor a zero normal, without a warning or an error (checked here:
// abort otherwise). Layout (all optional, short inputs are
// padded with zeros): a flags byte, a neighbour-count byte (from 160 up it also asks for
// re-runs: QuickIsoValueChanges, a small isovalue change, a SplatScale change, each checked
// as the first run is), eight float64 parameters (raw bits,
// so NaN, infinities and extremes occur), then up to 1,000 points of four float32 each
// (x, y, z, value).
#include "MessageCounter.h"

#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkLevelSetIsosurface.h"
#include "vtkNew.h"
#include "vtkObject.h"
#include "vtkOutputWindow.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkStringArray.h"
#include "vtkVariant.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>

namespace
{
struct Bytes
{
  const std::uint8_t* Data;
  std::size_t Size, At = 0;
  template <typename T>
  T Next()
  {
    T value{};
    std::uint8_t raw[sizeof(T)] = {};
    for (std::size_t k = 0; k < sizeof(T) && this->At < this->Size; ++k)
    {
      raw[k] = this->Data[this->At++];
    }
    std::memcpy(&value, raw, sizeof(T));
    return value;
  }
  std::size_t Left() const { return this->Size - std::min(this->At, this->Size); }
};
// Whether some tuple of `normals` has length zero (a normal that could not be computed).
bool HasZeroNormal(vtkDataArray* normals)
{
  for (vtkIdType i = 0; normals && i < normals->GetNumberOfTuples(); ++i)
  {
    double n[3];
    normals->GetTuple(i, n);
    if (n[0] == 0.0 && n[1] == 0.0 && n[2] == 0.0)
    {
      return true;
    }
  }
  return false;
}

bool HasNaN(vtkDataArray* array)
{
  if (!array)
  {
    return false;
  }
  const vtkIdType n = array->GetNumberOfValues();
  for (vtkIdType k = 0; k < n; ++k)
  {
    if (std::isnan(array->GetVariantValue(k).ToDouble()))
    {
      return true;
    }
  }
  return false;
}
// The promise of issue 14, checked after every run: no NaN in the surface's points or normals,
// and no empty or non-converged surface without a warning or an error (`messages` counts them
// over the runs so far).
void Check(vtkLevelSetIsosurface* filter, lsi::test::MessageCounter* messages, vtkIdType count)
{
  vtkPolyData* surface = filter->GetOutput(0);
  if (HasNaN(surface->GetPoints() ? surface->GetPoints()->GetData() : nullptr) ||
    HasNaN(surface->GetPointData()->GetNormals()))
  {
    std::fprintf(stderr, "NaN in the surface's points or normals\n");
    std::abort();
  }
  // (An empty input gives an empty output without a word, as in VTK's filters: under MPI a rank
  // may hold no particles.)
  if (messages->Count == 0 && count > 0 &&
    (surface->GetNumberOfPoints() == 0 || HasZeroNormal(surface->GetPointData()->GetNormals()) ||
      (filter->GetNumberOfIterationsPerformed() > 0 && !filter->GetConverged())))
  {
    std::fprintf(stderr,
      "an empty or non-converged surface without a message: %lld input points, %lld output "
      "points, %lld isopoints, %d iterations, converged %d\n",
      static_cast<long long>(count), static_cast<long long>(surface->GetNumberOfPoints()),
      static_cast<long long>(filter->GetNumberOfIsopoints()),
      filter->GetNumberOfIterationsPerformed(), filter->GetConverged() ? 1 : 0);
    std::abort();
  }
}
} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  // Bad inputs are expected: no message flood. (Messages stay on, so that the filter's warning
  // and error events fire for the check below; only their display is off.)
  vtkOutputWindow::GetInstance()->SetDisplayModeToNever();
  Bytes in{ data, size };
  const std::uint8_t flags = in.Next<std::uint8_t>();
  const std::uint8_t neighborByte = in.Next<std::uint8_t>();
  const int neighbors = 4 + neighborByte % 40;
  // Its high values also re-run: QuickIsoValueChanges on, then a small isovalue change (a
  // slide, or the method) and a change of SplatScale (the output made anew from the last run).
  const bool reRuns = neighborByte >= 160;
  double parameters[8];
  for (double& p : parameters)
  {
    p = in.Next<double>();
  }
  const vtkIdType count = static_cast<vtkIdType>(std::min<std::size_t>(in.Left() / 16, 1000));
  vtkNew<vtkPoints> points;
  vtkNew<vtkFloatArray> values;
  values->SetName("f");
  for (vtkIdType i = 0; i < count; ++i)
  {
    float x[3];
    for (float& c : x)
    {
      c = in.Next<float>();
    }
    points->InsertNextPoint(x[0], x[1], x[2]);
    values->InsertNextValue(in.Next<float>());
  }
  vtkNew<vtkPolyData> input;
  input->SetPoints(points);
  input->GetPointData()->AddArray(values);
  if (flags & 8) // SPH arrays: smoothing lengths from the values, unit masses, densities
  {
    vtkNew<vtkDoubleArray> h, m;
    h->SetName("SmoothingLength");
    m->SetName("Masses");
    for (vtkIdType i = 0; i < count; ++i)
    {
      h->InsertNextValue(std::abs(values->GetValue(i)));
      m->InsertNextValue(1.0);
    }
    input->GetPointData()->AddArray(h);
    input->GetPointData()->AddArray(m);
  }
  if (flags & 16) // a periodic box from field data, as the HDF5 reader passes it
  {
    vtkNew<vtkDoubleArray> box;
    box->SetName("BoxSize");
    box->InsertNextValue(parameters[7]);
    input->GetFieldData()->AddArray(box);
    // A reader's region about the seed (its faces, where the filter checks the surface), wrapped
    // on two axes with the box's size.
    vtkNew<vtkDoubleArray> region, period;
    region->SetName("RegionBounds");
    period->SetName("RegionPeriod");
    for (int a = 0; a < 3; ++a)
    {
      region->InsertNextValue(parameters[1 + a] - parameters[4]);
      region->InsertNextValue(parameters[1 + a] + parameters[4]);
      period->InsertNextValue(a == 1 ? 0.0 : parameters[7]);
    }
    input->GetFieldData()->AddArray(region);
    input->GetFieldData()->AddArray(period);
  }
  vtkNew<vtkLevelSetIsosurface> filter;
  filter->SetInputData(input);
  filter->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "f");
  filter->SetNumberOfThreads(1);
  filter->SetMaximumNumberOfIterations(30);
  filter->SetNumberOfNeighbors(neighbors);
  filter->SetIsoValue(parameters[0]);
  filter->SetSeedCenter(parameters[1], parameters[2], parameters[3]);
  filter->SetSeedRadius(parameters[4]);
  if (flags & 32)
  {
    filter->SetEpsilon(parameters[5]);
    filter->SetTimeStep(parameters[6]);
  }
  filter->SetOutputType(
    flags & 1 ? vtkLevelSetIsosurface::ISOPOINTS : vtkLevelSetIsosurface::SPLATS);
  filter->SetInitialization(
    flags & 2 ? vtkLevelSetIsosurface::SEED_SPHERES : vtkLevelSetIsosurface::FLOOD);
  filter->SetField(
    flags & 4 ? vtkLevelSetIsosurface::SPH_FIELD : vtkLevelSetIsosurface::AUTOMATIC_FIELD);
  // Every SPH kernel (0: as marked, 1-6), chosen by the particle count, so that the inputs
  // decode as before.
  filter->SetKernel(static_cast<int>(count % 7));
  filter->SetEvolutionScheme(flags & 64 ? 1 : 0);
  filter->SetCompletion(!(flags & 128));
  vtkNew<lsi::test::MessageCounter> messages; // warnings and errors
  filter->AddObserver(vtkCommand::ErrorEvent, messages);
  filter->AddObserver(vtkCommand::WarningEvent, messages);
  filter->SetQuickIsoValueChanges(reRuns);
  filter->Update();
  Check(filter, messages, count);
  if (reRuns)
  {
    // A hundredth of the values' finite range above (the surface moves a little).
    double low = HUGE_VAL, high = -HUGE_VAL;
    for (vtkIdType i = 0; i < count; ++i)
    {
      const double v = values->GetValue(i);
      low = std::isfinite(v) ? std::min(low, v) : low;
      high = std::isfinite(v) ? std::max(high, v) : high;
    }
    const double change = high > low ? 0.01 * (high - low) : 0.0;
    if (std::isfinite(parameters[0] + change))
    {
      filter->SetIsoValue(parameters[0] + change);
      filter->Update();
      Check(filter, messages, count);
    }
    filter->SetSplatScale(2.0 * filter->GetSplatScale());
    filter->Update();
    Check(filter, messages, count);
  }
  return 0;
}
