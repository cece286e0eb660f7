// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
// Filter-level tests: neighbour reuse across parameter changes, progress through every stage,
// and bad input (a clear error and empty outputs, never a crash or hang).
#include "vtkLevelSetIsosurface.h"

#include "MessageCounter.h"
#include "TestCheck.h"

#include "vtkCellArray.h"
#include "vtkCommand.h"
#include "vtkDoubleArray.h"
#include "vtkExecutive.h"
#include "vtkIdList.h"
#include "vtkIdTypeArray.h"
#include "vtkMinimalStandardRandomSequence.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkTable.h"
#include "vtkVariant.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <functional>
#include <iostream>
#include <limits>
#include <set>
#include <string>
#include <vector>

namespace
{
using lsi::test::Check;
using lsi::test::MessageCounter;

// Records every progress value the filter reports.
class ProgressLog : public vtkCommand
{
public:
  static ProgressLog* New() { return new ProgressLog; }
  void Execute(vtkObject*, unsigned long, void* data) override
  {
    this->Values.push_back(*static_cast<double*>(data));
  }
  std::vector<double> Values;
};

// Random samples in [0, 60]^3 of f = 20 - |x - (30, 30, 30)|, optionally with extra tweaks.
vtkNew<vtkPolyData> Ball(vtkIdType count, int components = 1)
{
  vtkNew<vtkMinimalStandardRandomSequence> random;
  random->SetSeed(11);
  vtkNew<vtkPoints> points;
  vtkNew<vtkDoubleArray> f;
  f->SetName("f");
  f->SetNumberOfComponents(components);
  for (vtkIdType i = 0; i < count; ++i)
  {
    double x[3];
    for (double& v : x)
    {
      v = random->GetNextRangeValue(0.0, 60.0);
    }
    points->InsertNextPoint(x);
    const double r =
      std::sqrt((x[0] - 30) * (x[0] - 30) + (x[1] - 30) * (x[1] - 30) + (x[2] - 30) * (x[2] - 30));
    for (int c = 0; c < components; ++c)
    {
      f->InsertNextValue(20.0 - r);
    }
  }
  vtkNew<vtkPolyData> data;
  data->SetPoints(points);
  data->GetPointData()->AddArray(f);
  return data;
}

void Configure(vtkLevelSetIsosurface* filter, vtkPolyData* input)
{
  filter->SetInputData(input);
  filter->SetOutputTypeToIsopoints();
  filter->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "f");
  filter->SetIsoValue(0.0);
  filter->SetSeedCenter(30, 30, 30);
  filter->SetSeedRadius(8);
}

// Runs a filter expected to fail: an error message naming the problem, empty outputs.
void ExpectError(vtkLevelSetIsosurface* filter, const std::string& expected, const char* what)
{
  vtkNew<MessageCounter> errors;
  filter->AddObserver(vtkCommand::ErrorEvent, errors);
  filter->Update();
  Check(errors->Count > 0, std::string(what) + ": an error is reported");
  Check(errors->Last.find(expected) != std::string::npos,
    std::string(what) + ": message mentions '" + expected + "' (got: " + errors->Last + ")");
  Check(filter->GetOutput(0)->GetNumberOfPoints() == 0, std::string(what) + ": empty isopoints");
  Check(filter->GetOutput(1)->GetNumberOfPoints() == 0, std::string(what) + ": empty particles");
}

// Issue 18: what two separate balls enclose, on random points without masses (volumes from the
// spacing): f = max(14 - |x - c1|, 10 - |x - c2|) on 200,000 random points of [0, 60]^3 (spacing
// about 1), every component seeded (SeedRadius 0). Two rows and the total, largest first,
// volumes and areas within 3% of the exact ones. (The volumes also carry the surface's own
// position error, a few hundredths of a spacing at this sampling: issue 17.)
void TestEnclosedComponents()
{
  vtkNew<vtkMinimalStandardRandomSequence> random;
  random->SetSeed(5);
  vtkNew<vtkPoints> points;
  vtkNew<vtkDoubleArray> f;
  f->SetName("f");
  const double c1[3] = { 18, 18, 18 }, c2[3] = { 42, 43, 41 };
  for (int i = 0; i < 200000; ++i)
  {
    double x[3];
    for (double& v : x)
    {
      v = random->GetNextRangeValue(0.0, 60.0);
    }
    points->InsertNextPoint(x);
    auto distance = [&](const double* c) {
      return std::sqrt((x[0] - c[0]) * (x[0] - c[0]) + (x[1] - c[1]) * (x[1] - c[1]) +
        (x[2] - c[2]) * (x[2] - c[2]));
    };
    f->InsertNextValue(std::max(14.0 - distance(c1), 10.0 - distance(c2)));
  }
  vtkNew<vtkPolyData> data;
  data->SetPoints(points);
  data->GetPointData()->AddArray(f);
  vtkNew<vtkLevelSetIsosurface> filter;
  Configure(filter, data);
  filter->SetSeedRadius(0.0);
  filter->Update();
  vtkTable* table = vtkTable::SafeDownCast(filter->GetOutputDataObject(3));
  const double pi = 3.14159265358979323846;
  const double volumes[2] = { 4.0 / 3.0 * pi * 2744.0, 4.0 / 3.0 * pi * 1000.0 };
  const double areas[2] = { 4.0 * pi * 196.0, 4.0 * pi * 100.0 };
  Check(table && table->GetNumberOfRows() == 3 && !table->GetColumnByName("Mass"),
    "enclosed: two components and the total, no Mass column without masses");
  for (int r = 0; table && r < 2 && table->GetNumberOfRows() == 3; ++r)
  {
    const double volume = table->GetValueByName(r, "Volume").ToDouble();
    const double area = table->GetValueByName(r, "SurfaceArea").ToDouble();
    std::cout << "enclosed, component " << r + 1 << ": particles "
              << table->GetValueByName(r, "Particles").ToDouble() << ", volume " << volume
              << " (exact " << volumes[r] << "), area " << area << " (exact " << areas[r] << ")\n";
    Check(std::abs(volume - volumes[r]) < 0.03 * volumes[r], "enclosed: volume within 3%");
    Check(std::abs(area - areas[r]) < 0.03 * areas[r], "enclosed: area within 3%");
  }
}

// Issue 14 (3): extreme finite lengths and steps are named in a warning, and a TimeStep above
// the stability bound is lowered to it, so the surface still comes out.
void TestExtremeParameters()
{
  vtkNew<vtkPolyData> data = Ball(20000);
  struct Case
  {
    const char* What;
    std::function<void(vtkLevelSetIsosurface*)> Set;
    const char* Expected;
    bool Surface;
  };
  const Case cases[] = {
    { "TimeStep 1e30", [](vtkLevelSetIsosurface* f) { f->SetTimeStep(1e30); }, "stability bound",
      true },
    { "Epsilon 1e-6", [](vtkLevelSetIsosurface* f) { f->SetEpsilon(1e-6); }, "narrower", false },
    { "Epsilon 1e4", [](vtkLevelSetIsosurface* f) { f->SetEpsilon(1e4); }, "smoothed over", false },
    { "TimeStep 1e-12 from the seed spheres",
      [](vtkLevelSetIsosurface* f) {
        f->SetTimeStep(1e-12);
        f->SetInitializationToSeedSpheres();
      },
      "cannot reach", false },
    { "scheme 1 with DistanceRegularization 10",
      [](vtkLevelSetIsosurface* f) {
        f->SetEvolutionScheme(1);
        f->SetDistanceRegularization(10.0);
      },
      "unstable", false },
  };
  for (const Case& c : cases)
  {
    vtkNew<vtkLevelSetIsosurface> filter;
    Configure(filter, data);
    c.Set(filter);
    vtkNew<MessageCounter> warnings;
    filter->AddObserver(vtkCommand::WarningEvent, warnings);
    filter->Update();
    std::cout << c.What << ": " << filter->GetNumberOfIsopoints() << " isopoints, warnings "
              << warnings->Count << "\n";
    Check(warnings->Count > 0 && warnings->All.find(c.Expected) != std::string::npos,
      std::string(c.What) + ": a warning that says '" + c.Expected + "' (got: " + warnings->All +
        ")");
    if (c.Surface)
    {
      Check(filter->GetNumberOfIsopoints() > 1000, std::string(c.What) + ": still a surface");
    }
  }
}

// Issue 14: a thin layer (two sheets of particles 1e-3 apart, 60 wide) passes the exact
// flatness test but its neighbourhoods are ill-conditioned across it: a warning says so. A ball
// of random particles gives no such warning.
void TestThinLayers()
{
  vtkNew<vtkMinimalStandardRandomSequence> random;
  random->SetSeed(5);
  vtkNew<vtkPoints> points;
  vtkNew<vtkDoubleArray> f;
  f->SetName("f");
  for (int i = 0; i < 20000; ++i)
  {
    const double x = random->GetNextRangeValue(0.0, 60.0);
    const double y = random->GetNextRangeValue(0.0, 60.0);
    points->InsertNextPoint(x, y, (i % 2) * 1e-3);
    f->InsertNextValue(20.0 - std::sqrt((x - 30) * (x - 30) + (y - 30) * (y - 30)));
  }
  vtkNew<vtkPolyData> layers;
  layers->SetPoints(points);
  layers->GetPointData()->AddArray(f);
  vtkNew<vtkPolyData> ball = Ball(20000);
  for (vtkPolyData* data : { layers.GetPointer(), ball.GetPointer() })
  {
    const bool thin = data == layers.GetPointer();
    vtkNew<vtkLevelSetIsosurface> filter;
    Configure(filter, data);
    filter->SetSeedCenter(30, 30, thin ? 0 : 30);
    vtkNew<MessageCounter> warnings;
    filter->AddObserver(vtkCommand::WarningEvent, warnings);
    filter->Update();
    const bool warned = warnings->All.find("thin") != std::string::npos;
    std::cout << (thin ? "two layers 1e-3 apart" : "a ball") << ": "
              << filter->GetNumberOfIsopoints() << " isopoints, warnings: " << warnings->All
              << "\n";
    Check(warned == thin,
      thin ? "two layers 1e-3 apart: no warning about thin neighbourhoods"
           : "a ball: a warning about thin neighbourhoods");
  }
}

// Two balls of radius 15 centred at x = 30 and x = 75.
vtkSmartPointer<vtkPolyData> TwoSeparateBalls(vtkIdType count)
{
  vtkNew<vtkMinimalStandardRandomSequence> random;
  random->SetSeed(5);
  vtkNew<vtkPoints> points;
  vtkNew<vtkDoubleArray> f;
  f->SetName("f");
  for (vtkIdType i = 0; i < count; ++i)
  {
    const double x[3] = { random->GetNextRangeValue(0.0, 105.0),
      random->GetNextRangeValue(0.0, 60.0), random->GetNextRangeValue(0.0, 60.0) };
    points->InsertNextPoint(x);
    auto distance = [&](double cx) {
      return std::sqrt(
        (x[0] - cx) * (x[0] - cx) + (x[1] - 30) * (x[1] - 30) + (x[2] - 30) * (x[2] - 30));
    };
    f->InsertNextValue(std::max(15.0 - distance(30.0), 15.0 - distance(75.0)));
  }
  auto data = vtkSmartPointer<vtkPolyData>::New();
  data->SetPoints(points);
  data->GetPointData()->AddArray(f);
  return data;
}

double MeanX(vtkPolyData* points)
{
  double sum = 0.0;
  for (vtkIdType i = 0; i < points->GetNumberOfPoints(); ++i)
  {
    sum += points->GetPoint(i)[0];
  }
  return points->GetNumberOfPoints() ? sum / points->GetNumberOfPoints() : 0.0;
}

// A re-run that only moved the seed inside the same component hands on the last outputs; any
// other change (another component, the isovalue, the input, the seed-sphere start) runs again.
void TestReuseAfterSeedMove()
{
  vtkSmartPointer<vtkPolyData> data = TwoSeparateBalls(60000);
  vtkNew<vtkLevelSetIsosurface> filter;
  Configure(filter, data);
  filter->SetSeedRadius(5);
  filter->Update();
  const vtkIdType count = filter->GetOutput(0)->GetNumberOfPoints();
  double first[3];
  filter->GetOutput(0)->GetPoint(count / 2, first);
  const int iterations = filter->GetNumberOfIterationsPerformed();
  Check(!filter->GetReusedLastOutputs() && count > 500, "first run computes");

  filter->SetSeedCenter(33, 29, 31); // inside the same ball
  filter->Update();
  double again[3];
  filter->GetOutput(0)->GetPoint(count / 2, again);
  Check(filter->GetReusedLastOutputs(), "a seed moved inside the component reuses the outputs");
  Check(filter->GetOutput(0)->GetNumberOfPoints() == count && again[0] == first[0] &&
      again[1] == first[1] && again[2] == first[2] &&
      filter->GetNumberOfIterationsPerformed() == iterations &&
      filter->GetOutput(1)->GetPointData()->GetArray("LevelSet") &&
      vtkTable::SafeDownCast(filter->GetOutputDataObject(3))->GetNumberOfRows() > 0,
    "the reused outputs are the last ones, all four");

  filter->SetSeedCenter(32, 31, 29); // again inside: the flood confirms it
  filter->Update();
  Check(filter->GetReusedLastOutputs() && filter->GetOutput(0)->GetNumberOfPoints() == count,
    "a second move inside the component reuses them too");

  filter->SetSeedCenter(5, 5, 5); // outside both balls: the usual error, empty outputs
  ExpectError(filter, "No sample inside the seed sphere", "a seed moved out of every component");
  Check(!filter->GetReusedLastOutputs(), "a seed moved out of the object is not a reuse");
  filter->SetSeedCenter(30, 30, 30);
  filter->Update();
  Check(!filter->GetReusedLastOutputs() && filter->GetOutput(0)->GetNumberOfPoints() == count,
    "after an error, the run is whole again");

  filter->SetSeedCenter(75, 30, 30); // the other ball
  filter->Update();
  Check(!filter->GetReusedLastOutputs() && std::abs(MeanX(filter->GetOutput(0)) - 75.0) < 1.0,
    "a seed moved to the other component runs again (mean x " +
      std::to_string(MeanX(filter->GetOutput(0))) + ")");

  filter->SetSeedCenter(30, 30, 30);
  filter->Update();
  Check(!filter->GetReusedLastOutputs() && std::abs(MeanX(filter->GetOutput(0)) - 30.0) < 1.0,
    "and back to the first one runs again");

  filter->SetSeedCenter(31, 30, 30);
  filter->SetIsoValue(1.0);
  filter->Update();
  Check(!filter->GetReusedLastOutputs(), "a seed move with an isovalue change runs again");

  filter->SetSeedCenter(30, 31, 30);
  data->GetPointData()->GetArray("f")->SetTuple1(
    0, data->GetPointData()->GetArray("f")->GetTuple1(0));
  data->GetPointData()->GetArray("f")->Modified();
  data->Modified();
  filter->Update();
  Check(!filter->GetReusedLastOutputs(), "a seed move after the input changed runs again");

  filter->SetInitializationToSeedSpheres();
  filter->Update();
  filter->SetSeedCenter(30, 30, 31);
  filter->Update();
  Check(!filter->GetReusedLastOutputs(), "the seed-sphere start always runs again");
}

// Whether two surfaces have the same points, to the bit, in the same order.
bool SamePoints(vtkPolyData* a, vtkPolyData* b)
{
  bool same = a->GetNumberOfPoints() == b->GetNumberOfPoints();
  for (vtkIdType i = 0; same && i < a->GetNumberOfPoints(); ++i)
  {
    for (int d = 0; d < 3; ++d)
    {
      same = same && a->GetPoint(i)[d] == b->GetPoint(i)[d];
    }
  }
  return same;
}

// A fresh filter on `data`, configured as `filter` is (Configure, then the settings these tests
// change), run: the outputs a re-run of `filter` must give.
vtkSmartPointer<vtkLevelSetIsosurface> FreshLike(vtkLevelSetIsosurface* filter, vtkPolyData* data)
{
  auto fresh = vtkSmartPointer<vtkLevelSetIsosurface>::New();
  Configure(fresh, data);
  fresh->SetIsoValue(filter->GetIsoValue());
  fresh->SetSeedCenter(filter->GetSeedCenter());
  fresh->SetCurvatureWeight(filter->GetCurvatureWeight());
  fresh->SetTimeStep(filter->GetTimeStep());
  fresh->SetOutputType(filter->GetOutputType());
  fresh->SetSplatScale(filter->GetSplatScale());
  fresh->SetSplatSides(filter->GetSplatSides());
  fresh->SetInterpolateArrays(filter->GetInterpolateArrays());
  fresh->Update();
  return fresh;
}

// A run whose flood would be the last one's (the same particles, scalars, isovalue, seeds and
// band) starts from that flood's level set: after a change of CurvatureWeight or TimeStep the
// flood does not run again, and the outputs are a fresh filter's to the bit. A change of the
// seeds, the isovalue, the scalars or the points floods again, with again a fresh filter's
// outputs.
void TestReuseOfFlood()
{
  vtkNew<vtkPolyData> data = Ball(20000);
  vtkNew<vtkLevelSetIsosurface> filter;
  Configure(filter, data);
  auto sameAsFresh = [&](const std::string& what) {
    vtkSmartPointer<vtkLevelSetIsosurface> fresh = FreshLike(filter, data);
    bool same = filter->GetOutput(0)->GetNumberOfPoints() > 500 &&
      SamePoints(filter->GetOutput(0), fresh->GetOutput(0));
    vtkDataArray* phi = filter->GetOutput(1)->GetPointData()->GetArray("LevelSet");
    vtkDataArray* freshPhi = fresh->GetOutput(1)->GetPointData()->GetArray("LevelSet");
    for (vtkIdType i = 0; same && phi && freshPhi && i < phi->GetNumberOfTuples(); ++i)
    {
      same = phi->GetTuple1(i) == freshPhi->GetTuple1(i);
    }
    Check(same && phi && freshPhi, what + ": the outputs are a fresh filter's");
  };
  filter->Update();
  Check(filter->GetFloodCount() == 1, "the first run floods");
  filter->SetCurvatureWeight(0.3);
  filter->Update();
  Check(filter->GetFloodCount() == 1, "a CurvatureWeight change starts from the last flood");
  sameAsFresh("after a CurvatureWeight change");
  filter->SetTimeStep(0.5 * filter->GetEffectiveTimeStep());
  filter->Update();
  Check(filter->GetFloodCount() == 1, "a TimeStep change starts from the last flood");
  sameAsFresh("after a TimeStep change");
  filter->SetSeedCenter(31, 30, 30);
  filter->SetCurvatureWeight(0.2);
  filter->Update();
  Check(filter->GetFloodCount() == 2, "moved seeds flood again");
  sameAsFresh("after a seed move");
  filter->SetIsoValue(1.0);
  filter->Update();
  Check(filter->GetFloodCount() == 3, "another isovalue floods again");
  sameAsFresh("after an isovalue change");
  // Scalars changed by a millionth (no sample changes sides, so the scale of the method does not
  // change either; the crossings the flood measures from do).
  vtkDataArray* f = data->GetPointData()->GetArray("f");
  for (vtkIdType i = 0; i < f->GetNumberOfTuples(); i += 2)
  {
    f->SetTuple1(i, f->GetTuple1(i) + 1e-6);
  }
  f->Modified();
  filter->Update();
  Check(filter->GetFloodCount() == 4, "changed scalars flood again");
  sameAsFresh("after the scalars changed");
  // Points moved by up to a five-hundredth of a spacing (the same values): new neighbourhoods,
  // a new flood.
  for (vtkIdType i = 0; i < data->GetNumberOfPoints(); ++i)
  {
    double x[3];
    data->GetPoint(i, x);
    x[0] += 1e-3 * static_cast<double>(i % 3);
    data->GetPoints()->SetPoint(i, x);
  }
  data->GetPoints()->Modified();
  filter->SetCurvatureWeight(0.25);
  filter->Update();
  Check(filter->GetFloodCount() == 5, "moved points flood again");
  sameAsFresh("after the points moved");
}

// A change of the surface output's own properties (OutputType, SplatScale, SplatSides,
// InterpolateArrays) alone makes that output anew from the last run's points, without running
// the method (no evolution, no isopoints), to a fresh filter's output to the bit; the other
// outputs are handed on. With another change too, the method runs. After a quick isovalue
// change, the slid points are the ones shown anew.
void TestRemakeOfSurfaceOutput()
{
  vtkNew<vtkPolyData> data = Ball(20000);
  vtkNew<vtkLevelSetIsosurface> filter;
  Configure(filter, data);
  filter->Update();
  auto sameAsFresh = [&](const std::string& what) {
    vtkSmartPointer<vtkLevelSetIsosurface> fresh = FreshLike(filter, data);
    vtkPolyData* a = filter->GetOutput(0);
    vtkPolyData* b = fresh->GetOutput(0);
    const bool same = a->GetNumberOfPoints() > 500 && SamePoints(a, b) &&
      a->GetNumberOfCells() == b->GetNumberOfCells() &&
      a->GetPointData()->GetNumberOfArrays() == b->GetPointData()->GetNumberOfArrays();
    Check(same, what + ": a fresh filter's surface output");
    Check(filter->GetOutput(1)->GetPointData()->GetArray("LevelSet") &&
        vtkTable::SafeDownCast(filter->GetOutputDataObject(3))->GetNumberOfRows() > 0,
      what + ": the other outputs are handed on");
  };
  auto remade = [&]() {
    return filter->GetRemadeSurfaceOutput() && filter->GetEvolutionSeconds() == 0.0 &&
      filter->GetIsopointSeconds() == 0.0 && filter->GetOutputSeconds() > 0.0;
  };
  filter->SetOutputTypeToSplats();
  filter->Update();
  Check(remade(), "an OutputType change makes the surface output alone");
  sameAsFresh("splats");
  filter->SetSplatScale(2.0);
  filter->SetSplatSides(5);
  filter->Update();
  Check(remade(), "SplatScale and SplatSides changes make the surface output alone");
  sameAsFresh("larger splats with 5 sides");
  filter->SetInterpolateArrays(false);
  filter->SetOutputTypeToIsopoints();
  filter->Update();
  Check(remade() && !filter->GetOutput(0)->GetPointData()->GetArray("f"),
    "InterpolateArrays off makes the surface output alone, without the arrays");
  sameAsFresh("isopoints without arrays");
  filter->SetInterpolateArrays(true);
  filter->SetCurvatureWeight(0.3);
  filter->Update();
  Check(filter->GetEvolutionSeconds() > 0.0 && !filter->GetRemadeSurfaceOutput(),
    "with a CurvatureWeight change the method runs");
  sameAsFresh("after a CurvatureWeight change with InterpolateArrays");

  // With QuickIsoValueChanges on (the shown points are the ones kept for a slide), and after a
  // quick isovalue change (the slid points) they are shown anew.
  filter->QuickIsoValueChangesOn();
  filter->Update();
  filter->SetOutputTypeToSplats();
  filter->Update();
  Check(remade(), "with QuickIsoValueChanges on, an OutputType change makes the output alone");
  sameAsFresh("splats, QuickIsoValueChanges on");
  filter->SetOutputTypeToIsopoints();
  filter->Update();
  filter->SetIsoValue(0.2);
  filter->Update();
  Check(filter->GetSlidLastSurface(), "a small isovalue change slides");
  vtkNew<vtkPolyData> slid;
  slid->DeepCopy(filter->GetOutput(0));
  filter->SetOutputTypeToSplats();
  filter->Update();
  bool same = remade() && filter->GetOutput(0)->GetNumberOfPoints() > 0 &&
    filter->GetOutput(0)->GetNumberOfCells() == slid->GetNumberOfPoints();
  Check(same, "the slid points are shown as splats, one each");
  filter->SetOutputTypeToIsopoints();
  filter->Update();
  same = remade() && SamePoints(filter->GetOutput(0), slid);
  Check(same, "and back as isopoints, the slid points to the bit");

  // The paper's start (seed spheres, no flood kept): the surface output is remade all the same.
  filter->QuickIsoValueChangesOff();
  filter->SetIsoValue(0.0);
  filter->SetInitializationToSeedSpheres();
  filter->Update();
  vtkNew<vtkPolyData> spheres;
  spheres->DeepCopy(filter->GetOutput(0));
  filter->SetOutputTypeToSplats();
  filter->Update();
  same = remade() && filter->GetOutput(0)->GetNumberOfCells() == spheres->GetNumberOfPoints();
  Check(same, "from the seed spheres' start, an OutputType change makes the output alone");
  filter->SetOutputTypeToIsopoints();
  filter->Update();
  Check(remade() && spheres->GetNumberOfPoints() > 500 && SamePoints(filter->GetOutput(0), spheres),
    "and back as isopoints, the same points to the bit");
}

void TestReuseOfNeighbours()
{
  vtkNew<vtkPolyData> data = Ball(20000);
  vtkNew<vtkLevelSetIsosurface> filter;
  Configure(filter, data);
  filter->Update();
  const vtkIdType first = filter->GetOutput(0)->GetNumberOfPoints();
  Check(first > 500, "isopoints produced");
  Check(filter->GetNeighborSearchCount() == 1, "neighbours built once");
  filter->SetIsoValue(-3.0); // sphere of radius 23
  filter->Update();
  Check(filter->GetNeighborSearchCount() == 1, "isovalue change reuses the neighbours");
  double p[3];
  filter->GetOutput(0)->GetPoint(0, p);
  const double r =
    std::sqrt((p[0] - 30) * (p[0] - 30) + (p[1] - 30) * (p[1] - 30) + (p[2] - 30) * (p[2] - 30));
  Check(
    std::abs(r - 23.0) < 1.5, "new isovalue gives the new sphere (r = " + std::to_string(r) + ")");
  filter->SetCurvatureWeight(0.1);
  filter->Update();
  Check(filter->GetNeighborSearchCount() == 1, "a parameter change reuses the neighbours");
  filter->SetNumberOfNeighbors(20);
  filter->Update();
  Check(filter->GetNeighborSearchCount() == 2, "NumberOfNeighbors change rebuilds them");
  data->GetPoints()->Modified(); // touched, same coordinates: recognised by its fingerprint
  filter->Update();
  Check(filter->GetNeighborSearchCount() == 2, "unchanged coordinates reuse them");
  double first0[3];
  data->GetPoint(0, first0);
  data->GetPoints()->SetPoint(0, first0[0] + 0.01, first0[1], first0[2]);
  data->GetPoints()->Modified();
  filter->Update();
  Check(filter->GetNeighborSearchCount() == 3, "moved points rebuild them");
  data->GetPoints()->SetPoint(0, first0);
  data->GetPoints()->Modified();
  filter->Update();
  Check(filter->GetNeighborSearchCount() == 3,
    "returning to earlier coordinates (an earlier time step) reuses their neighbours");
  // The other outputs: LevelSet on the particles, one table row per iteration.
  Check(filter->GetOutput(1)->GetPointData()->GetArray("LevelSet") != nullptr, "LevelSet array");
  vtkTable* table = vtkTable::SafeDownCast(filter->GetOutputDataObject(2));
  Check(table && table->GetNumberOfRows() == filter->GetNumberOfIterationsPerformed() &&
      table->GetColumnByName("SignMismatch") && table->GetColumnByName("BandSize"),
    "convergence table");
}

// The particle output's vertex cells: shared with the input where it holds one vertex per point
// in order (as this project's readers make them, 64-bit ids; or 32-bit), else made anew, one per
// point, never the input's other cells.
void TestParticleVertexCells()
{
  vtkNew<vtkPolyData> data = Ball(3000);
  const vtkIdType n = data->GetNumberOfPoints();
  auto verticesOf = [](vtkIdType count, auto idOf) {
    vtkNew<vtkIdTypeArray> ids;
    ids->SetNumberOfValues(count);
    for (vtkIdType i = 0; i < count; ++i)
    {
      ids->SetValue(i, idOf(i));
    }
    vtkNew<vtkCellArray> cells;
    cells->SetData(1, ids);
    return cells;
  };
  auto isVertexPerPoint = [n](vtkCellArray* cells) {
    if (!cells || cells->GetNumberOfCells() != n)
    {
      return false;
    }
    vtkNew<vtkIdList> ids;
    for (vtkIdType c = 0; c < n; ++c)
    {
      cells->GetCellAtId(c, ids);
      if (ids->GetNumberOfIds() != 1 || ids->GetId(0) != c)
      {
        return false;
      }
    }
    return true;
  };
  vtkNew<vtkLevelSetIsosurface> filter;
  Configure(filter, data);
  filter->Update(); // no cells in the input: made anew
  Check(isVertexPerPoint(filter->GetOutput(1)->GetVerts()), "no input cells: a vertex per point");
  vtkSmartPointer<vtkCellArray> own = verticesOf(n, [](vtkIdType i) { return i; });
  data->SetVerts(own);
  filter->Update();
  Check(filter->GetOutput(1)->GetVerts() == own.GetPointer(), "the input's vertex cells shared");
  own->ConvertTo32BitStorage();
  data->Modified();
  filter->Update();
  Check(filter->GetOutput(1)->GetVerts() == own.GetPointer(), "32-bit ids shared too");
  // Cells of the same count but two swapped, or the last one naming point 0: made anew.
  const std::vector<std::function<vtkIdType(vtkIdType)>> others = {
    [](vtkIdType i) { return i == 1 ? 2 : (i == 2 ? 1 : i); },
    [n](vtkIdType i) { return i == n - 1 ? 0 : i; }
  };
  for (const auto& idOf : others)
  {
    vtkSmartPointer<vtkCellArray> other = verticesOf(n, idOf);
    data->SetVerts(other);
    filter->Update();
    Check(filter->GetOutput(1)->GetVerts() != other.GetPointer() &&
        isVertexPerPoint(filter->GetOutput(1)->GetVerts()),
      "other vertex cells: not shared, a vertex per point");
  }
  vtkSmartPointer<vtkCellArray> fewer = verticesOf(n - 1, [](vtkIdType i) { return i; });
  data->SetVerts(fewer);
  filter->Update();
  Check(filter->GetOutput(1)->GetVerts() != fewer.GetPointer() &&
      isVertexPerPoint(filter->GetOutput(1)->GetVerts()),
    "fewer vertex cells than points: not shared, a vertex per point");
}

// The stage timers (the benchmarks' profiles) cover the run: disjoint parts of it, together
// nearly all of it, so that no stage goes untimed or is counted twice.
void TestStageTimesCoverTheRun()
{
  vtkNew<vtkPolyData> data = Ball(200000);
  vtkNew<vtkLevelSetIsosurface> filter;
  Configure(filter, data);
  const auto start = std::chrono::steady_clock::now();
  filter->Update();
  const double wall =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const double stages[7] = { filter->GetInputSeconds(), filter->GetNeighborSearchSeconds(),
    filter->GetInitializationSeconds(), filter->GetEvolutionSeconds(), filter->GetIsopointSeconds(),
    filter->GetOutputSeconds(), filter->GetParticleOutputSeconds() };
  double sum = 0.0;
  bool positive = true;
  for (double s : stages)
  {
    sum += s;
    positive = positive && s > 0.0;
  }
  Check(positive, "every stage timed");
  Check(sum <= wall && sum >= 0.8 * wall,
    "the stages cover the run: " + std::to_string(sum) + " s of " + std::to_string(wall) + " s");
}

// Progress rises from 0 to 1 and moves within each stage, not only between them (ranges of
// vtkLevelSetIsosurface::Execute: neighbours below 0.35, isopoints 0.8 to 0.92).
void TestProgressThroughStages()
{
  vtkNew<vtkPolyData> data = Ball(200000);
  vtkNew<vtkLevelSetIsosurface> filter;
  Configure(filter, data);
  vtkNew<ProgressLog> log;
  filter->AddObserver(vtkCommand::ProgressEvent, log);
  filter->Update();
  const std::vector<double>& v = log->Values;
  bool rising = !v.empty();
  for (std::size_t i = 1; i < v.size(); ++i)
  {
    rising = rising && v[i] >= v[i - 1];
  }
  Check(rising, "progress never goes back (" + std::to_string(v.size()) + " reports)");
  Check(!v.empty() && v.back() == 1.0, "progress ends at 1");
  auto distinctWithin = [&v](double from, double to) {
    std::set<double> inside;
    for (double p : v)
    {
      if (p > from && p < to)
      {
        inside.insert(p);
      }
    }
    return inside.size();
  };
  const std::size_t neighbours = distinctWithin(0.0, 0.35);
  const std::size_t isopoints = distinctWithin(0.8, 0.92);
  Check(neighbours >= 3,
    "progress moves during the neighbour search (" + std::to_string(neighbours) + " values)");
  Check(isopoints >= 3,
    "progress moves during the isopoint stage (" + std::to_string(isopoints) + " values)");
}

// Two balls of radius 8, at the centre of the box and near a corner.
vtkNew<vtkPolyData> TwoBalls(vtkIdType count)
{
  vtkNew<vtkPolyData> data = Ball(count);
  vtkDataArray* f = data->GetPointData()->GetArray("f");
  for (vtkIdType i = 0; i < count; ++i)
  {
    double x[3];
    data->GetPoint(i, x);
    auto ball = [&x](double c) {
      return 8.0 -
        std::sqrt((x[0] - c) * (x[0] - c) + (x[1] - c) * (x[1] - c) + (x[2] - c) * (x[2] - c));
    };
    f->SetComponent(i, 0, std::max(ball(30.0), ball(12.0)));
  }
  return data;
}

// Farthest isopoint from the centre ball's centre (30, 30, 30).
double FarthestFromCentre(vtkPolyData* isopoints)
{
  double farthest = 0.0;
  for (vtkIdType i = 0; i < isopoints->GetNumberOfPoints(); ++i)
  {
    double x[3];
    isopoints->GetPoint(i, x);
    farthest = std::max(farthest,
      std::sqrt((x[0] - 30) * (x[0] - 30) + (x[1] - 30) * (x[1] - 30) + (x[2] - 30) * (x[2] - 30)));
  }
  return farthest;
}

// SeedRadius 0 seeds everything; a negative radius (what ParaView's bounds domain gives a
// script whose input has no bounds yet) means a tenth of the extent, not everything.
void TestSeedRadiusMeanings()
{
  vtkNew<vtkPolyData> data = TwoBalls(100000);
  vtkNew<vtkLevelSetIsosurface> filter;
  Configure(filter, data);
  filter->SetSeedRadius(-0.2);
  filter->Update();
  const double seeded = FarthestFromCentre(filter->GetOutput(0));
  Check(filter->GetOutput(0)->GetNumberOfPoints() > 300 && seeded < 10.0,
    "a negative SeedRadius extracts only the ball at the seed (farthest isopoint " +
      std::to_string(seeded) + " from its centre)");
  filter->SetSeedRadius(0.0);
  filter->Update();
  const double all = FarthestFromCentre(filter->GetOutput(0));
  Check(all > 25.0,
    "SeedRadius 0 extracts both balls (farthest isopoint " + std::to_string(all) +
      " from the centre ball)");
}

void TestBadInput()
{
  {
    vtkNew<vtkPolyData> empty;
    vtkNew<vtkLevelSetIsosurface> filter;
    Configure(filter, empty);
    ExpectError(filter, "no points", "no points");
  }
  {
    vtkNew<vtkPolyData> few = Ball(20);
    vtkNew<vtkLevelSetIsosurface> filter;
    Configure(filter, few);
    ExpectError(filter, "fewer than NumberOfNeighbors", "too few points");
  }
  vtkNew<vtkPolyData> data = Ball(5000);
  {
    vtkNew<vtkLevelSetIsosurface> filter;
    Configure(filter, data);
    filter->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "missing");
    ExpectError(filter, "No input scalars", "missing array");
  }
  {
    vtkNew<vtkPolyData> vectors = Ball(5000, 3);
    vtkNew<vtkLevelSetIsosurface> filter;
    Configure(filter, vectors);
    ExpectError(filter, "3 components", "non-scalar array");
  }
  {
    vtkNew<vtkPolyData> nan = Ball(5000);
    vtkDoubleArray::SafeDownCast(nan->GetPointData()->GetArray("f"))
      ->SetValue(17, std::numeric_limits<double>::quiet_NaN());
    vtkNew<vtkLevelSetIsosurface> filter;
    Configure(filter, nan);
    ExpectError(filter, "NaN or infinite value at point 17", "NaN value");
  }
  {
    vtkNew<vtkPolyData> inf = Ball(5000);
    vtkDoubleArray::SafeDownCast(inf->GetPointData()->GetArray("f"))
      ->SetValue(3, std::numeric_limits<double>::infinity());
    vtkNew<vtkLevelSetIsosurface> filter;
    Configure(filter, inf);
    ExpectError(filter, "NaN or infinite", "infinite value");
  }
  {
    // NaN passes the clamp macros (infinity does not: they clamp it to a finite bound): every
    // parameter is checked before any work.
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const std::vector<std::pair<const char*, void (vtkLevelSetIsosurface::*)(double)>> setters = {
      { "CurvatureWeight", &vtkLevelSetIsosurface::SetCurvatureWeight },
      { "SplatScale", &vtkLevelSetIsosurface::SetSplatScale },
      { "SeedRadius", &vtkLevelSetIsosurface::SetSeedRadius },
      { "ConvergenceTolerance", &vtkLevelSetIsosurface::SetConvergenceTolerance },
      { "DistanceRegularization", &vtkLevelSetIsosurface::SetDistanceRegularization },
      { "TimeStep", &vtkLevelSetIsosurface::SetTimeStep },
      { "Epsilon", &vtkLevelSetIsosurface::SetEpsilon }
    };
    for (const auto& setter : setters)
    {
      vtkNew<vtkLevelSetIsosurface> filter;
      Configure(filter, data);
      (filter.GetPointer()->*setter.second)(nan);
      const std::string expected = std::string(setter.first) + " is nan";
      ExpectError(filter, expected, expected.c_str());
    }
  }
  {
    // Out-of-range values are clamped with a warning naming the property and the value used.
    vtkNew<vtkLevelSetIsosurface> filter;
    vtkNew<MessageCounter> warnings;
    filter->AddObserver(vtkCommand::WarningEvent, warnings);
    filter->SetNumberOfNeighbors(500);
    Check(filter->GetNumberOfNeighbors() == 200 && warnings->Count == 1 &&
        warnings->Last.find("NumberOfNeighbors 500 is outside [4, 200]: 200 is used") !=
          std::string::npos,
      "NumberOfNeighbors 500: clamped to 200 with a warning (got: " + warnings->Last + ")");
    filter->SetEpsilon(std::numeric_limits<double>::infinity());
    Check(
      warnings->Count == 2 && warnings->Last.find("Epsilon inf is outside") != std::string::npos,
      "Epsilon inf: clamped with a warning (got: " + warnings->Last + ")");
    filter->SetNumberOfNeighbors(30);
    Check(filter->GetNumberOfNeighbors() == 30 && warnings->Count == 2,
      "an in-range value: no warning");
  }
  {
    // One far outlier does not make 3D data look flat ("all points on a plane or line" was
    // reported): the surface of the ball is found as without it.
    vtkNew<vtkPolyData> outlier = Ball(5000);
    outlier->GetPoints()->SetPoint(123, 1e10, 30.0, 30.0);
    vtkNew<vtkLevelSetIsosurface> filter;
    Configure(filter, outlier);
    vtkNew<MessageCounter> errors;
    filter->AddObserver(vtkCommand::ErrorEvent, errors);
    filter->Update();
    std::cout << "one outlier at 1e10: " << filter->GetOutput(0)->GetNumberOfPoints()
              << " isopoints, errors " << errors->Count << " " << errors->Last << "\n";
    vtkNew<vtkLevelSetIsosurface> clean;
    Configure(clean, data);
    clean->Update();
    const double ratio = static_cast<double>(filter->GetOutput(0)->GetNumberOfPoints()) /
      static_cast<double>(clean->GetOutput(0)->GetNumberOfPoints());
    std::cout << "  without the outlier: " << clean->GetOutput(0)->GetNumberOfPoints() << "\n";
    Check(errors->Count == 0 && ratio > 0.9 && ratio < 1.1,
      "one outlier at 1e10: no flatness error, the surface found as without it");
  }
  {
    // Valid inputs but no surface (two samples above the isovalue, fewer than a neighbourhood):
    // an empty surface with a warning that says why, never silently.
    std::vector<double> values;
    vtkDataArray* f = data->GetPointData()->GetArray("f");
    for (vtkIdType i = 0; i < f->GetNumberOfTuples(); ++i)
    {
      values.push_back(f->GetTuple1(i));
    }
    std::sort(values.rbegin(), values.rend());
    vtkNew<vtkLevelSetIsosurface> filter;
    Configure(filter, data);
    filter->SetSeedRadius(0); // every component
    filter->SetIsoValue(0.5 * (values[1] + values[2]));
    vtkNew<MessageCounter> warnings, errors;
    filter->AddObserver(vtkCommand::WarningEvent, warnings);
    filter->AddObserver(vtkCommand::ErrorEvent, errors);
    filter->Update();
    std::cout << "two samples above the isovalue: " << filter->GetOutput(0)->GetNumberOfPoints()
              << " isopoints; warnings " << warnings->Count << " (" << warnings->Last
              << "), errors " << errors->Count << " (" << errors->Last << ")\n";
    Check(filter->GetOutput(0)->GetNumberOfPoints() > 0 ||
        warnings->Last.find("No isosurface was found: 2 of 5000 samples lie above IsoValue") !=
          std::string::npos,
      "an empty surface comes with a warning that says why");
  }
  {
    // An evolution that hits MaximumNumberOfIterations says so; a converged one does not.
    vtkNew<vtkLevelSetIsosurface> filter;
    Configure(filter, data);
    filter->SetInitialization(vtkLevelSetIsosurface::SEED_SPHERES);
    filter->SetMaximumNumberOfIterations(1);
    vtkNew<MessageCounter> warnings;
    filter->AddObserver(vtkCommand::WarningEvent, warnings);
    filter->Update();
    Check(warnings->Count == 1 &&
        warnings->Last.find("MaximumNumberOfIterations (1)") != std::string::npos,
      "not converged: a warning (got: " + warnings->Last + ")");
    filter->SetMaximumNumberOfIterations(500);
    filter->Update();
    Check(filter->GetConverged() && warnings->Count == 1, "converged: no further warning");
  }
  {
    // A malformed scalar array, shorter than the points: an error, not a read past its end.
    vtkNew<vtkPolyData> shortArray = Ball(5000);
    vtkDoubleArray::SafeDownCast(shortArray->GetPointData()->GetArray("f"))
      ->SetNumberOfTuples(4000);
    vtkNew<vtkLevelSetIsosurface> filter;
    Configure(filter, shortArray);
    ExpectError(filter, "has 4000 values for 5000 points", "malformed scalar array");
  }
  {
    // A malformed extra array is left out of the interpolation, not read past its end.
    vtkNew<vtkPolyData> extra = Ball(5000);
    vtkNew<vtkDoubleArray> shortArray;
    shortArray->SetName("short");
    shortArray->SetNumberOfValues(100);
    shortArray->Fill(1.0);
    extra->GetPointData()->AddArray(shortArray);
    vtkNew<vtkLevelSetIsosurface> filter;
    Configure(filter, extra);
    filter->Update();
    Check(filter->GetOutput(0)->GetNumberOfPoints() > 0 &&
        !filter->GetOutput(0)->GetPointData()->GetArray("short") &&
        filter->GetOutput(0)->GetPointData()->GetArray("f"),
      "a malformed extra array is not interpolated; the others are");
  }
  {
    // An unnamed scalar with a NaN: the message is complete (no null name streamed).
    vtkNew<vtkPolyData> unnamed = Ball(5000);
    vtkDataArray* f = unnamed->GetPointData()->GetArray("f");
    f->SetTuple1(35, std::numeric_limits<double>::quiet_NaN());
    f->SetName(nullptr);
    unnamed->GetPointData()->SetScalars(f);
    vtkNew<vtkLevelSetIsosurface> filter;
    Configure(filter, unnamed);
    filter->SetInputArrayToProcess(
      0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, vtkDataSetAttributes::SCALARS);
    ExpectError(filter, "NaN or infinite value at point 35", "unnamed array with a NaN");
  }
  {
    vtkNew<vtkLevelSetIsosurface> filter;
    Configure(filter, data);
    filter->SetIsoValue(1000.0);
    ExpectError(filter, "outside the open range", "isovalue outside the data range");
  }
  {
    vtkNew<vtkLevelSetIsosurface> filter;
    Configure(filter, data);
    filter->SetSeedCenter(500, 500, 500);
    filter->SetSeedRadius(1);
    ExpectError(filter, "contains no sample", "empty seed");
  }
  {
    // A seed in the corner, where every sample lies below the isovalue: nothing to flood.
    vtkNew<vtkLevelSetIsosurface> filter;
    Configure(filter, data);
    filter->SetSeedCenter(56, 56, 56);
    filter->SetSeedRadius(4);
    ExpectError(filter, "nothing to flood", "seed outside the object");
  }
  {
    vtkNew<vtkLevelSetIsosurface> filter;
    Configure(filter, data);
    filter->AddAdditionalSeed(-100, -100, -100, 2);
    ExpectError(filter, "contains no sample", "empty additional seed");
  }
  for (double scale : { 1e120, 1e-120 })
  {
    // Coordinates whose volumes would not fit a double (issue 14, 4): an error, not an empty
    // surface without a word. (Lengths x1e+-90 work: TestUnitsOfLength.)
    vtkNew<vtkPolyData> huge = Ball(5000);
    vtkNew<vtkPoints> scaled; // double: 1e120 does not fit a float
    scaled->SetDataTypeToDouble();
    for (vtkIdType i = 0; i < huge->GetNumberOfPoints(); ++i)
    {
      double x[3];
      huge->GetPoint(i, x);
      scaled->InsertNextPoint(scale * x[0], scale * x[1], scale * x[2]);
    }
    huge->SetPoints(scaled);
    vtkNew<vtkLevelSetIsosurface> filter;
    Configure(filter, huge);
    filter->SetSeedCenter(30 * scale, 30 * scale, 30 * scale);
    filter->SetSeedRadius(8 * scale);
    ExpectError(filter, "rescale the coordinates", "coordinates beyond 1e90");
  }
  {
    // Duplicates (issue 14): merged with a warning, values averaged; the same surface as
    // without them, and every input point keeps its LevelSet on port 1.
    vtkNew<vtkPolyData> clean = Ball(5000);
    vtkNew<vtkLevelSetIsosurface> reference;
    Configure(reference, clean);
    reference->Update();
    vtkNew<vtkPolyData> duplicated = Ball(5000);
    vtkDataArray* f = duplicated->GetPointData()->GetArray("f");
    for (vtkIdType i = 0; i < 300; ++i) // 300 exact copies appended, the copy's value off by 1
    {
      double x[3];
      duplicated->GetPoint(i, x);
      duplicated->GetPoints()->InsertNextPoint(x);
      f->InsertNextTuple1(f->GetTuple1(i));
    }
    double x[3];
    duplicated->GetPoint(11, x);
    duplicated->GetPoints()->SetPoint(12, x); // 12 joins 11 (and its copy); 12's copy is alone
    f->SetTuple1(12, f->GetTuple1(11) + 1.0);
    vtkNew<vtkLevelSetIsosurface> filter;
    Configure(filter, duplicated);
    vtkNew<MessageCounter> warnings, errors;
    filter->AddObserver(vtkCommand::WarningEvent, warnings);
    filter->AddObserver(vtkCommand::ErrorEvent, errors);
    filter->Update();
    vtkDataArray* levelSet = filter->GetOutput(1)->GetPointData()->GetArray("LevelSet");
    std::cout << "duplicates: " << warnings->Last << "; " << filter->GetNumberOfIsopoints()
              << " isopoints (" << reference->GetNumberOfIsopoints() << " without)\n";
    Check(errors->Count == 0 && warnings->Last.find("300 points coincide") != std::string::npos,
      "duplicates: merged with a warning that counts them");
    Check(filter->GetOutput(1)->GetNumberOfPoints() == 5300 && levelSet &&
        levelSet->GetTuple1(5000) == levelSet->GetTuple1(0) &&
        levelSet->GetTuple1(12) == levelSet->GetTuple1(11),
      "duplicates: every input point on port 1, copies with their point's LevelSet");
    Check(std::abs(filter->GetNumberOfIsopoints() - reference->GetNumberOfIsopoints()) <=
          0.01 * reference->GetNumberOfIsopoints() &&
        filter->GetNumberOfIsopoints() > 100,
      "duplicates: the surface of the same points without the copies");
  }
  {
    // All samples on the plane z = 30: every MLS fit is singular.
    vtkNew<vtkPolyData> flat = Ball(5000);
    for (vtkIdType i = 0; i < flat->GetNumberOfPoints(); ++i)
    {
      double x[3];
      flat->GetPoint(i, x);
      x[2] = 30.0;
      flat->GetPoints()->SetPoint(i, x);
    }
    vtkNew<vtkLevelSetIsosurface> filter;
    Configure(filter, flat);
    ExpectError(filter, "singular", "coplanar samples");
  }
  {
    // Collinear samples.
    vtkNew<vtkPolyData> line = Ball(2000);
    for (vtkIdType i = 0; i < line->GetNumberOfPoints(); ++i)
    {
      double x[3];
      line->GetPoint(i, x);
      line->GetPoints()->SetPoint(i, x[0], x[0], x[0]);
    }
    vtkNew<vtkLevelSetIsosurface> filter;
    Configure(filter, line);
    ExpectError(filter, "singular", "collinear samples");
  }
}
} // namespace

int main()
{
  TestExtremeParameters();
  TestThinLayers();
  TestEnclosedComponents();
  TestReuseOfNeighbours();
  TestReuseAfterSeedMove();
  TestReuseOfFlood();
  TestRemakeOfSurfaceOutput();
  TestProgressThroughStages();
  TestStageTimesCoverTheRun();
  TestParticleVertexCells();
  TestSeedRadiusMeanings();
  TestBadInput();
  std::cout << (lsi::test::Failures() ? "filter tests FAILED\n" : "filter tests passed\n");
  return lsi::test::Failures() ? EXIT_FAILURE : EXIT_SUCCESS;
}
