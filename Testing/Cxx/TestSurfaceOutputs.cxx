// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
// What the surface output carries and how it follows time:
// - every input point array interpolated onto the isopoints reproduces a linear field exactly;
//   integer arrays (ids, groups) carry the nearest particle's values instead;
// - the scalars read in storage order (as a slide reads them) interpolate to the same numbers;
// - the splat polygons lie in the tangent planes, one per isopoint, with the splat radius;
// - on a time series the filter runs per time step, and each step keeps its neighbourhoods.
#include "vtkLevelSetIsosurface.h"

#include "LevelSetNeighborhoods.h"
#include "LevelSetSurfaceOutput.h"
#include "TestCheck.h"

#include "vtkCellArray.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkIntArray.h"
#include "vtkMath.h"
#include "vtkMinimalStandardRandomSequence.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataAlgorithm.h"
#include "vtkStreamingDemandDrivenPipeline.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <string>
#include <vector>

namespace
{
using lsi::test::Check;

double Linear(const double x[3])
{
  return 3.0 * x[0] - 2.0 * x[1] + 0.5 * x[2] + 7.0;
}

// `count` random particles in [0, 60]^3 (seeded by `seed`): f = radius - |x - 30| and, to
// interpolate, "linear" (a scalar), "velocity" (a linear vector field) and "temperature" (float).
vtkSmartPointer<vtkPolyData> Ball(int count, double radius, int seed)
{
  vtkNew<vtkMinimalStandardRandomSequence> random;
  random->SetSeed(seed);
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  vtkNew<vtkDoubleArray> f, linear, velocity;
  vtkNew<vtkFloatArray> temperature;
  f->SetName("f");
  linear->SetName("linear");
  velocity->SetName("velocity");
  velocity->SetNumberOfComponents(3);
  temperature->SetName("temperature");
  for (int i = 0; i < count; ++i)
  {
    double x[3];
    for (double& v : x)
    {
      random->Next();
      v = 60.0 * random->GetValue();
    }
    points->InsertNextPoint(x);
    f->InsertNextValue(radius -
      std::sqrt((x[0] - 30) * (x[0] - 30) + (x[1] - 30) * (x[1] - 30) + (x[2] - 30) * (x[2] - 30)));
    linear->InsertNextValue(Linear(x));
    velocity->InsertNextTuple3(x[1], -x[0], 2.0 * x[2] - 1.0);
    temperature->InsertNextValue(static_cast<float>(100.0 + x[2]));
  }
  auto data = vtkSmartPointer<vtkPolyData>::New();
  data->SetPoints(points);
  data->GetPointData()->AddArray(f);
  data->GetPointData()->AddArray(linear);
  data->GetPointData()->AddArray(velocity);
  data->GetPointData()->AddArray(temperature);
  return data;
}

void Configure(vtkLevelSetIsosurface* filter)
{
  filter->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "f");
  filter->SetIsoValue(0.0);
  filter->SetSeedCenter(30, 30, 30);
  filter->SetSeedRadius(5);
}

void TestInterpolatedArrays()
{
  vtkSmartPointer<vtkPolyData> data = Ball(30000, 18.0, 3);
  // Integer arrays (a particle id, a halo finder's group and flag pair) whose interpolants would
  // mean nothing: the surface takes the nearest particle's.
  vtkNew<vtkIdTypeArray> ids;
  vtkNew<vtkIntArray> groups;
  ids->SetName("id");
  groups->SetName("group");
  groups->SetNumberOfComponents(2);
  for (vtkIdType i = 0; i < data->GetNumberOfPoints(); ++i)
  {
    ids->InsertNextValue(1000 + 3 * i);
    groups->InsertNextTuple2(static_cast<double>(i % 7), static_cast<double>(-(i % 5)));
  }
  data->GetPointData()->AddArray(ids);
  data->GetPointData()->AddArray(groups);
  vtkNew<vtkLevelSetIsosurface> filter;
  filter->SetInputData(data);
  Configure(filter);
  filter->SetOutputTypeToIsopoints();
  filter->Update();
  vtkPolyData* out = filter->GetOutput(0);
  vtkPointData* pd = out->GetPointData();
  vtkDataArray* linear = pd->GetArray("linear");
  vtkDataArray* velocity = pd->GetArray("velocity");
  vtkDataArray* temperature = pd->GetArray("temperature");
  Check(out->GetNumberOfPoints() > 1000, "isopoints produced");
  Check(
    linear && velocity && temperature && pd->GetArray("f"), "every input array is interpolated");
  if (!(linear && velocity && temperature))
  {
    return;
  }
  Check(velocity->GetNumberOfComponents() == 3, "vector keeps its 3 components");
  Check(temperature->GetDataType() == VTK_FLOAT, "float array stays float");
  double worstScalar = 0.0, worstVector = 0.0, worstFloat = 0.0;
  for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i)
  {
    double x[3], v[3];
    out->GetPoint(i, x);
    worstScalar = std::max(worstScalar, std::abs(linear->GetComponent(i, 0) - Linear(x)));
    velocity->GetTuple(i, v);
    worstVector = std::max({ worstVector, std::abs(v[0] - x[1]), std::abs(v[1] + x[0]),
      std::abs(v[2] - (2.0 * x[2] - 1.0)) });
    worstFloat = std::max(worstFloat, std::abs(temperature->GetComponent(i, 0) - (100.0 + x[2])));
  }
  std::cout << out->GetNumberOfPoints() << " isopoints; largest error of the interpolated linear "
            << "scalar " << worstScalar << ", vector " << worstVector << ", float " << worstFloat
            << "\n";
  // Values are O(100): rounding of a 54-term weighted sum stays near 1e-12.
  Check(worstScalar < 1e-9, "linear scalar reproduced to rounding");
  Check(worstVector < 1e-9, "linear vector reproduced to rounding");
  Check(worstFloat < 1e-4, "float array reproduced to float rounding");

  // The integer arrays: their own types, and every 40th isopoint's values are those of the
  // particle nearest to it (found here by brute force).
  vtkDataArray* outIds = pd->GetArray("id");
  vtkDataArray* outGroups = pd->GetArray("group");
  Check(outIds && outIds->GetDataType() == VTK_ID_TYPE && outGroups &&
      outGroups->GetDataType() == VTK_INT && outGroups->GetNumberOfComponents() == 2,
    "integer arrays keep their types and components");
  int checked = 0, nearestValues = 0;
  for (vtkIdType i = 0; outIds && outGroups && i < out->GetNumberOfPoints(); i += 40)
  {
    double x[3], best = HUGE_VAL;
    out->GetPoint(i, x);
    vtkIdType nearest = -1;
    for (vtkIdType j = 0; j < data->GetNumberOfPoints(); ++j)
    {
      const double d2 = vtkMath::Distance2BetweenPoints(x, data->GetPoint(j));
      if (d2 < best)
      {
        best = d2;
        nearest = j;
      }
    }
    ++checked;
    nearestValues += outIds->GetComponent(i, 0) == ids->GetComponent(nearest, 0) &&
      outGroups->GetComponent(i, 0) == groups->GetComponent(nearest, 0) &&
      outGroups->GetComponent(i, 1) == groups->GetComponent(nearest, 1);
  }
  std::cout << nearestValues << " of " << checked
            << " isopoints checked carry their nearest particle's integer values\n";
  Check(checked > 20 && nearestValues == checked,
    "integer arrays: each isopoint has the nearest particle's values");

  filter->InterpolateArraysOff();
  filter->Update();
  Check(!filter->GetOutput(0)->GetPointData()->GetArray("linear") &&
      filter->GetOutput(0)->GetPointData()->GetArray("SplatRadius"),
    "InterpolateArrays off: no input arrays, still normals and splat radius");
}

// InterpolatePointArrays reading a one-component array from a copy in storage order (what a
// quick isovalue change passes for the scalars: LastOutputs::Values) gives the same numbers, to
// the bit, as reading the array itself; SameValuesInStorageOrder tells when such a copy holds
// exactly the array's values.
void TestScalarsInStorageOrder()
{
  vtkSmartPointer<vtkPolyData> data = Ball(20000, 18.0, 5);
  lsi::Neighborhoods geometry;
  lsi::BuildNeighborhoods(data->GetPoints(), 16, geometry, lsi::AbortCheck());
  vtkDataArray* f = data->GetPointData()->GetArray("f");
  vtkDataArray* temperature = data->GetPointData()->GetArray("temperature");
  vtkDataArray* velocity = data->GetPointData()->GetArray("velocity");
  auto inStorageOrder = [&](vtkDataArray* array) {
    std::vector<double> values(geometry.NumberOfSamples);
    for (std::size_t i = 0; i < values.size(); ++i)
    {
      values[i] = array->GetComponent(geometry.Order[i], 0);
    }
    return values;
  };
  std::vector<double> fStored = inStorageOrder(f);
  const std::vector<double> temperatureStored = inStorageOrder(temperature);
  Check(lsi::SameValuesInStorageOrder(f, geometry, fStored), "a double array's copy matches");
  Check(lsi::SameValuesInStorageOrder(temperature, geometry, temperatureStored),
    "a float array's copy matches");
  Check(!lsi::SameValuesInStorageOrder(velocity, geometry, inStorageOrder(velocity)),
    "a vector array is not read from a copy");
  Check(!lsi::SameValuesInStorageOrder(f, geometry, temperatureStored),
    "another array's values do not match");
  std::vector<double> changed = fStored;
  changed[changed.size() / 2] += 1e-12;
  Check(!lsi::SameValuesInStorageOrder(f, geometry, changed), "one changed value is seen");
  changed.pop_back();
  Check(!lsi::SameValuesInStorageOrder(f, geometry, changed), "a short copy does not match");

  // Points scattered through the cloud, each array interpolated both ways.
  std::vector<double> points;
  for (int k = 0; k < 500; ++k)
  {
    const double t = k / 500.0;
    points.insert(points.end(),
      { 5.0 + 50.0 * t, 30.0 + 20.0 * std::sin(7.0 * t), 30.0 + 20.0 * std::cos(11.0 * t) });
  }
  const std::vector<vtkDataArray*> sources = { f, velocity, temperature };
  auto interpolate = [&](const std::vector<const double*>* stored) {
    std::vector<vtkSmartPointer<vtkDataArray>> targets;
    std::vector<vtkDataArray*> targetList;
    for (vtkDataArray* source : sources)
    {
      vtkSmartPointer<vtkDataArray> target = vtkSmartPointer<vtkDoubleArray>::New();
      target->SetNumberOfComponents(source->GetNumberOfComponents());
      target->SetNumberOfTuples(static_cast<vtkIdType>(points.size() / 3));
      targets.push_back(target);
      targetList.push_back(target);
    }
    lsi::InterpolatePointArrays(geometry, points, 2 * static_cast<std::size_t>(geometry.Stride),
      sources, targetList, lsi::AbortCheck(), nullptr, stored);
    return targets;
  };
  const auto direct = interpolate(nullptr);
  // (The vector array's copy is ignored: only one-component arrays are read from one.)
  const std::vector<double> velocityStored = inStorageOrder(velocity);
  const std::vector<const double*> stored = { fStored.data(), velocityStored.data(),
    temperatureStored.data() };
  const auto fromCopies = interpolate(&stored);
  bool same = true;
  for (std::size_t a = 0; a < sources.size(); ++a)
  {
    for (vtkIdType i = 0; i < direct[a]->GetNumberOfTuples(); ++i)
    {
      for (int c = 0; c < direct[a]->GetNumberOfComponents(); ++c)
      {
        same = same && direct[a]->GetComponent(i, c) == fromCopies[a]->GetComponent(i, c);
      }
    }
  }
  Check(same, "arrays read in storage order interpolate to the same numbers");
  // And the copies are read: a copy with other values gives other numbers.
  for (double& v : fStored)
  {
    v += 1.0;
  }
  const auto shifted = interpolate(&stored);
  Check(std::abs(shifted[0]->GetComponent(0, 0) - direct[0]->GetComponent(0, 0) - 1.0) < 1e-9,
    "the scalars are read from the copy (a copy one higher interpolates one higher)");
}

void TestSplats()
{
  vtkSmartPointer<vtkPolyData> data = Ball(30000, 18.0, 4);
  vtkNew<vtkLevelSetIsosurface> filter;
  filter->SetInputData(data);
  Configure(filter);
  filter->Update(); // default: splats
  vtkPolyData* splats = filter->GetOutput(0);
  const vtkIdType isopoints = filter->GetNumberOfIsopoints();
  const int sides = filter->GetSplatSides();
  Check(splats->GetNumberOfPolys() == isopoints && splats->GetNumberOfVerts() == 0,
    "splats: one polygon per isopoint");
  Check(splats->GetNumberOfPoints() == isopoints * sides, "splats: `sides` corners each");
  vtkDataArray* normals = splats->GetPointData()->GetArray("Normals");
  vtkDataArray* radius = splats->GetPointData()->GetArray("SplatRadius");
  Check(normals && radius && splats->GetPointData()->GetArray("linear"),
    "splat corners carry normals, radius and the interpolated arrays");
  if (!normals || !radius || isopoints == 0)
  {
    return;
  }
  // Each polygon: corners at the splat radius from their centre, in the plane normal to n. And
  // every corner carries its splat's tuples: the same normal and radius as its first corner, and
  // the linear field interpolated at its centre (the corners' mean).
  vtkDataArray* linear = splats->GetPointData()->GetArray("linear");
  double worstPlane = 0.0, worstRadius = 0.0, meanRadius = 0.0, worstCornerCopy = 0.0;
  for (vtkIdType p = 0; p < isopoints; ++p)
  {
    double c[3] = { 0, 0, 0 };
    for (int s = 0; s < sides; ++s)
    {
      double x[3];
      splats->GetPoint(p * sides + s, x);
      for (int d = 0; d < 3; ++d)
      {
        c[d] += x[d] / sides;
      }
    }
    double n[3];
    normals->GetTuple(p * sides, n);
    const double r = radius->GetComponent(p * sides, 0);
    meanRadius += r / isopoints;
    for (int s = 0; s < sides; ++s)
    {
      double x[3];
      splats->GetPoint(p * sides + s, x);
      const double e[3] = { x[0] - c[0], x[1] - c[1], x[2] - c[2] };
      worstPlane = std::max(worstPlane, std::abs(e[0] * n[0] + e[1] * n[1] + e[2] * n[2]) / r);
      worstRadius =
        std::max(worstRadius, std::abs(std::sqrt(e[0] * e[0] + e[1] * e[1] + e[2] * e[2]) - r) / r);
      double m[3];
      normals->GetTuple(p * sides + s, m);
      worstCornerCopy = std::max({ worstCornerCopy, std::abs(m[0] - n[0]), std::abs(m[1] - n[1]),
        std::abs(m[2] - n[2]), std::abs(radius->GetComponent(p * sides + s, 0) - r),
        linear ? std::abs(linear->GetComponent(p * sides + s, 0) - Linear(c)) : HUGE_VAL });
    }
  }
  Check(worstCornerCopy < 1e-9, "every splat corner carries its splat's normal, radius and arrays");
  const double spacing = filter->GetMeanSampleSpacing();
  std::cout << isopoints << " splats; mean radius " << meanRadius << " (sample spacing " << spacing
            << "), worst out-of-plane " << worstPlane << ", worst radius error " << worstRadius
            << " (relative)\n";
  Check(worstPlane < 1e-5 && worstRadius < 1e-5, "splat corners on their tangent circle");
  Check(meanRadius > 0.2 * spacing && meanRadius < 3.0 * spacing,
    "splat radius of the order of the sample spacing");
}

// A particle time series: at time t the particles (fresh positions each step) sample a ball
// of radius 14 + 2 t.
class BallSeries : public vtkPolyDataAlgorithm
{
public:
  static BallSeries* New();
  vtkTypeMacro(BallSeries, vtkPolyDataAlgorithm);
  int Executions = 0;

protected:
  BallSeries() { this->SetNumberOfInputPorts(0); }
  int RequestInformation(
    vtkInformation*, vtkInformationVector**, vtkInformationVector* out) override
  {
    const double steps[3] = { 0.0, 1.0, 2.0 }, range[2] = { 0.0, 2.0 };
    vtkInformation* info = out->GetInformationObject(0);
    info->Set(vtkStreamingDemandDrivenPipeline::TIME_STEPS(), steps, 3);
    info->Set(vtkStreamingDemandDrivenPipeline::TIME_RANGE(), range, 2);
    return 1;
  }
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector* out) override
  {
    vtkInformation* info = out->GetInformationObject(0);
    const double t = info->Has(vtkStreamingDemandDrivenPipeline::UPDATE_TIME_STEP())
      ? info->Get(vtkStreamingDemandDrivenPipeline::UPDATE_TIME_STEP())
      : 0.0;
    vtkPolyData* output = vtkPolyData::GetData(out);
    output->ShallowCopy(Ball(20000, 14.0 + 2.0 * t, 10 + static_cast<int>(t)));
    output->GetInformation()->Set(vtkDataObject::DATA_TIME_STEP(), t);
    ++this->Executions;
    return 1;
  }
};
vtkStandardNewMacro(BallSeries);

double MeanRadius(vtkPolyData* points)
{
  double sum = 0.0;
  for (vtkIdType i = 0; i < points->GetNumberOfPoints(); ++i)
  {
    double x[3];
    points->GetPoint(i, x);
    sum +=
      std::sqrt((x[0] - 30) * (x[0] - 30) + (x[1] - 30) * (x[1] - 30) + (x[2] - 30) * (x[2] - 30));
  }
  return points->GetNumberOfPoints() ? sum / points->GetNumberOfPoints() : 0.0;
}

void TestTimeSeries()
{
  vtkNew<BallSeries> series;
  vtkNew<vtkLevelSetIsosurface> filter;
  filter->SetInputConnection(series->GetOutputPort());
  Configure(filter);
  filter->SetOutputTypeToIsopoints();
  filter->UpdateInformation();
  vtkInformation* outInfo = filter->GetOutputInformation(0);
  Check(outInfo->Length(vtkStreamingDemandDrivenPipeline::TIME_STEPS()) == 3,
    "the output advertises the input's time steps");
  int expectedSearches = 0;
  for (double t : { 0.0, 1.0, 2.0, 1.0, 0.0, 2.0 })
  {
    filter->UpdateTimeStep(t);
    const bool firstVisit = t == 0.0 ? expectedSearches < 1
      : t == 1.0                     ? expectedSearches < 2
                                     : expectedSearches < 3;
    expectedSearches += firstVisit ? 1 : 0;
    vtkPolyData* out = filter->GetOutput(0);
    const double r = MeanRadius(out);
    const double dataTime = out->GetInformation()->Has(vtkDataObject::DATA_TIME_STEP())
      ? out->GetInformation()->Get(vtkDataObject::DATA_TIME_STEP())
      : -1.0;
    std::cout << "time " << t << ": " << out->GetNumberOfPoints() << " isopoints, mean radius " << r
              << " (exact " << 14.0 + 2.0 * t << "), neighbour searches so far "
              << filter->GetNeighborSearchCount() << "\n";
    // Steps differ by 2; the surface sits within a fraction of the spacing (2.2) of the exact one.
    Check(std::abs(r - (14.0 + 2.0 * t)) < 0.5,
      "time " + std::to_string(t) + ": the surface of that step");
    Check(dataTime == t, "time " + std::to_string(t) + ": output stamped with its time");
    Check(filter->GetNeighborSearchCount() == expectedSearches,
      "time " + std::to_string(t) + ": neighbours searched once per time step");
  }
  // Changing the isovalue at a step reuses that step's neighbourhoods.
  filter->SetIsoValue(-2.0);
  filter->UpdateTimeStep(2.0);
  Check(filter->GetNeighborSearchCount() == expectedSearches,
    "isovalue change reuses the step's neighbours");
  Check(std::abs(MeanRadius(filter->GetOutput(0)) - 20.0) < 0.5,
    "new isovalue at time 2 (f = 18 - r = -2 at r = 20)");
}
} // namespace

// CopyNearestSampleValues where two samples are equally near (points midway between two grid
// samples, the distances exactly equal): the one first in coordinate order gives its value,
// whatever the input's order (each rank's tree is its own under MPI).
void TestNearestTies()
{
  std::vector<vtkIdType> picked[2];
  for (int reversed = 0; reversed < 2; ++reversed)
  {
    vtkNew<vtkPoints> grid;
    vtkNew<vtkIntArray> ids;
    const int n = 6;
    for (int k = 0; k < n * n * n; ++k)
    {
      const int j = reversed ? n * n * n - 1 - k : k;
      grid->InsertNextPoint(j % n, (j / n) % n, j / (n * n));
      ids->InsertNextValue(j);
    }
    lsi::Neighborhoods geometry;
    lsi::BuildNeighborhoods(grid, 8, geometry, lsi::AbortCheck());
    std::vector<double> points;
    for (int k = 0; k < n - 1; ++k)
    {
      points.insert(points.end(), { k + 0.5, 2.0, 3.0 }); // between (k, 2, 3) and (k + 1, 2, 3)
      points.insert(points.end(), { 1.0, k + 0.5, 4.0 }); // between (1, k, 4) and (1, k + 1, 4)
    }
    vtkNew<vtkIntArray> out;
    out->SetNumberOfTuples(static_cast<vtkIdType>(points.size() / 3));
    lsi::CopyNearestSampleValues(geometry, points, { ids }, { out }, lsi::AbortCheck());
    for (vtkIdType i = 0; i < out->GetNumberOfTuples(); ++i)
    {
      picked[reversed].push_back(out->GetValue(i));
    }
  }
  bool first = true;
  for (std::size_t i = 0; i < picked[0].size(); ++i)
  {
    const int k = static_cast<int>(i / 2);
    const vtkIdType expected = i % 2 == 0 ? k + 2 * 6 + 3 * 36 : 1 + k * 6 + 4 * 36;
    first = first && picked[0][i] == expected && picked[1][i] == expected;
  }
  Check(first && picked[0].size() == 10,
    "nearest-value ties: the sample first in coordinate order, in either input order");
}

int main()
{
  TestInterpolatedArrays();
  TestNearestTies();
  TestScalarsInStorageOrder();
  TestSplats();
  TestTimeSeries();
  std::cout << (lsi::test::Failures() ? "surface output tests FAILED\n"
                                      : "surface output tests passed\n");
  return lsi::test::Failures() ? EXIT_FAILURE : EXIT_SUCCESS;
}
