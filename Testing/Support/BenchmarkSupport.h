// Pieces shared by the benchmark programs (LevelSetBenchmark, LevelSetCompare): the cases by
// name, pointing the filter at a case, reading its isopoints back, and timing 1 vs 2 threads.
#ifndef BenchmarkSupport_h
#define BenchmarkSupport_h

#include "SyntheticCases.h"
#include "vtkLevelSetIsosurface.h"

#include "vtkDataArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"

#include <array>
#include <chrono>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace lsi
{
namespace cases
{

/// The case called `name` (one-component, multi-component, adaptive-noisy, sphere), or null.
inline std::unique_ptr<Case> MakeCase(const std::string& name)
{
  if (name == "one-component") return std::unique_ptr<Case>(new OneComponentCase);
  if (name == "multi-component") return std::unique_ptr<Case>(new MultiComponentCase);
  if (name == "adaptive-noisy") return std::unique_ptr<Case>(new AdaptiveNoisyCase);
  if (name == "sphere")
    return std::unique_ptr<Case>(new SphereCase(Eigen::Vector3d(64, 64, 64), 40.0, 64.0));
  return nullptr;
}

/// The case's array ("f"), isovalue and seeds (first sphere main, the others additional).
inline void SetCaseInputs(vtkLevelSetIsosurface* filter, const Case& c)
{
  filter->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "f");
  filter->SetIsoValue(c.IsoValue);
  filter->SetSeedCenter(c.Seeds[0].Center.data());
  filter->SetSeedRadius(c.Seeds[0].Radius);
  for (std::size_t s = 1; s < c.Seeds.size(); ++s)
  {
    const Sphere3& seed = c.Seeds[s];
    filter->AddAdditionalSeed(seed.Center.x(), seed.Center.y(), seed.Center.z(), seed.Radius);
  }
}

inline double SecondsSince(std::chrono::steady_clock::time_point start)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

/// Coordinates and "Normals" of the filter's isopoint output, 3 values per point each.
inline void IsopointArrays(
  vtkPolyData* isopoints, std::vector<double>& points, std::vector<double>& normals)
{
  const vtkIdType m = isopoints->GetNumberOfPoints();
  points.resize(3 * m);
  normals.assign(3 * m, 0.0);
  vtkDataArray* n = isopoints->GetPointData()->GetArray("Normals");
  for (vtkIdType i = 0; i < m; ++i)
  {
    isopoints->GetPoint(i, &points[3 * i]);
    if (n)
    {
      n->GetTuple(i, &normals[3 * i]);
    }
  }
}

/// Seconds of a whole filter run with 1 and with 2 threads (fresh filters, same particles);
/// `configure` sets everything but the input and the thread count.
inline std::array<double, 2> SecondsWithOneAndTwoThreads(
  vtkPolyData* particles, const std::function<void(vtkLevelSetIsosurface*)>& configure)
{
  std::array<double, 2> seconds;
  for (int threads = 1; threads <= 2; ++threads)
  {
    vtkNew<vtkLevelSetIsosurface> filter;
    filter->SetInputData(particles);
    filter->SetOutputTypeToIsopoints();
    configure(filter);
    filter->SetNumberOfThreads(threads);
    const auto start = std::chrono::steady_clock::now();
    filter->Update();
    seconds[threads - 1] = SecondsSince(start);
  }
  return seconds;
}

} // namespace cases
} // namespace lsi

#endif
