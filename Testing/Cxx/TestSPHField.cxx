// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
// The SPH field on real particles: the output lies on the level of the field the particles
// define, rho(x) = sum_j m_j W(|x - x_j|, H_j), computed here by brute force over every particle
// (no tree, no filter code but the unit-tested kernels), with normals along its gradient and
// arrays interpolated as sum_j (m_j / rho_j) A_j W:
// - the Evrard glass with Particle Density's summed density (cubic spline, h = H), isopoints and
//   splat corners; the same particles in other units of length; the same field written the
//   SWIFT way (quintic spline, h = H / gamma, markers as the HDF5 reader writes them);
// - the ChaNGa shock tube with Particle Density's field (its own columns are placeholders);
// - Field = SPH without smoothing lengths is an error; Field = MLS does not use them.
//   TestSPHField GLASS_FILE SHOCKTUBE_FILE
#include "MessageCounter.h"
#include "SPHKernels.h"
#include "TestCheck.h"
#include "vtkLevelSetIsosurface.h"
#include "vtkParticleDensity.h"
#include "vtkTipsyParticleReader.h"

#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkIdTypeArray.h"
#include "vtkIntArray.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkStringArray.h"
#include "vtkTable.h"
#include "vtkVariant.h"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <iterator>
#include <string>
#include <vector>

namespace
{
using lsi::test::Check;

struct Particles
{
  std::vector<double> X, Mass, Support, Volume;
  lsi::SPHKernel Kernel = lsi::SPHKernel::CubicSpline;
};

// rho(x) and its gradient by brute force over every particle.
double FieldAt(const Particles& p, const double* x, double* gradient)
{
  double value = 0.0;
  gradient[0] = gradient[1] = gradient[2] = 0.0;
  for (std::size_t j = 0; j < p.Mass.size(); ++j)
  {
    lsi::AccumulateKernel(p.Kernel, x, &p.X[3 * j], p.Support[j], p.Mass[j], value, gradient);
  }
  return value;
}

double InterpolantAt(const Particles& p, const std::vector<double>& a, const double* x)
{
  double value = 0.0, unused[3] = { 0, 0, 0 };
  for (std::size_t j = 0; j < p.Mass.size(); ++j)
  {
    lsi::AccumulateKernel(
      p.Kernel, x, &p.X[3 * j], p.Support[j], p.Volume[j] * a[j], value, unused);
  }
  return value;
}

Particles ParticlesOf(vtkPolyData* data, const char* h, const char* m, const char* rho,
  double supportPerH, lsi::SPHKernel kernel)
{
  Particles p;
  p.Kernel = kernel;
  const vtkIdType n = data->GetNumberOfPoints();
  for (vtkIdType i = 0; i < n; ++i)
  {
    double x[3];
    data->GetPoint(i, x);
    p.X.insert(p.X.end(), x, x + 3);
    p.Mass.push_back(data->GetPointData()->GetArray(m)->GetTuple1(i));
    p.Support.push_back(supportPerH * data->GetPointData()->GetArray(h)->GetTuple1(i));
    p.Volume.push_back(p.Mass.back() / data->GetPointData()->GetArray(rho)->GetTuple1(i));
  }
  return p;
}

// The support radius of the particle nearest to x (the local length the scores use).
double LocalSupport(const Particles& p, const double* x)
{
  double best = 1e300, H = 0.0;
  for (std::size_t j = 0; j < p.Mass.size(); ++j)
  {
    const double d = std::pow(x[0] - p.X[3 * j], 2) + std::pow(x[1] - p.X[3 * j + 1], 2) +
      std::pow(x[2] - p.X[3 * j + 2], 2);
    if (d < best)
    {
      best = d;
      H = p.Support[j];
    }
  }
  return H;
}

struct Scores
{
  double MeanDistance = 0.0, MaxDistance = 0.0, MaxAngle = 0.0; // distances in local H
  std::size_t Scored = 0;
};

// Distance of (up to `samples` of) the output's points to the field's level, to first order
// |f - iso| / |grad f| (exact to rounding at the distances that pass), in local supports, and
// the angle between the output's normals and -grad f.
Scores Score(const Particles& p, vtkPolyData* out, double iso, std::size_t samples)
{
  Scores s;
  const vtkIdType n = out->GetNumberOfPoints();
  vtkDataArray* normals = out->GetPointData()->GetArray("Normals");
  const vtkIdType stride = std::max<vtkIdType>(1, n / static_cast<vtkIdType>(samples));
  for (vtkIdType i = 0; i < n; i += stride)
  {
    double x[3], g[3], normal[3];
    out->GetPoint(i, x);
    normals->GetTuple(i, normal);
    const double f = FieldAt(p, x, g);
    const double gn = std::sqrt(g[0] * g[0] + g[1] * g[1] + g[2] * g[2]);
    const double distance = std::abs(f - iso) / gn / LocalSupport(p, x);
    const double cosine = -(g[0] * normal[0] + g[1] * normal[1] + g[2] * normal[2]) / gn /
      std::sqrt(normal[0] * normal[0] + normal[1] * normal[1] + normal[2] * normal[2]);
    s.MeanDistance += distance;
    s.MaxDistance = std::max(s.MaxDistance, distance);
    s.MaxAngle = std::max(s.MaxAngle, std::acos(std::min(1.0, cosine)) * 180.0 / 3.14159265358979);
    ++s.Scored;
  }
  s.MeanDistance /= std::max<std::size_t>(1, s.Scored);
  return s;
}

vtkSmartPointer<vtkPolyData> Run(vtkPolyData* input, double iso, const double seed[3],
  double seedRadius, int outputType, vtkLevelSetIsosurface* filter = nullptr)
{
  vtkNew<vtkLevelSetIsosurface> own;
  vtkLevelSetIsosurface* f = filter ? filter : own.Get();
  f->SetInputData(input);
  f->SetIsoValue(iso);
  f->SetSeedCenter(seed[0], seed[1], seed[2]);
  f->SetSeedRadius(seedRadius);
  f->SetOutputType(outputType);
  f->Update();
  auto out = vtkSmartPointer<vtkPolyData>::New();
  out->ShallowCopy(f->GetOutput());
  return out;
}

// A quick isovalue change from `iso` to `changed` (Isopoints) and the method's own run at
// `changed`: their outputs, and the filters (whether it slid, their Enclosed tables).
struct QuickAndMethod
{
  vtkNew<vtkLevelSetIsosurface> Quick, Full;
  vtkSmartPointer<vtkPolyData> Slid, Method;
  QuickAndMethod(
    vtkPolyData* input, double iso, double changed, const double seed[3], double radius)
  {
    this->Quick->QuickIsoValueChangesOn();
    Run(input, iso, seed, radius, vtkLevelSetIsosurface::ISOPOINTS, this->Quick);
    this->Slid = Run(input, changed, seed, radius, vtkLevelSetIsosurface::ISOPOINTS, this->Quick);
    this->Method = Run(input, changed, seed, radius, vtkLevelSetIsosurface::ISOPOINTS, this->Full);
  }
};

// The mass the Enclosed table's total row gives (0 without one).
double EnclosedMass(vtkLevelSetIsosurface* filter)
{
  vtkTable* t = vtkTable::SafeDownCast(filter->GetOutputDataObject(3));
  return t && t->GetNumberOfRows() > 0
    ? t->GetValueByName(t->GetNumberOfRows() - 1, "Mass").ToDouble()
    : 0.0;
}

void Report(const std::string& what, const Scores& s, vtkIdType points)
{
  std::cout << what << ": " << points << " points, " << s.Scored
            << " scored: mean distance to the SPH level " << s.MeanDistance
            << " local supports, max " << s.MaxDistance << ", max normal angle " << s.MaxAngle
            << " deg\n";
}

// What the surface r = 0.5 encloses in the Evrard glass (rho = 1 / (2 pi r), M(<r) = r^2):
// mass 0.25, volume 4/3 pi 0.125, area pi (issue 18's targets: 2%, 3%, 3%), one component.
void TestEnclosed(vtkLevelSetIsosurface* filter)
{
  vtkTable* table = vtkTable::SafeDownCast(filter->GetOutputDataObject(3));
  const double pi = 3.14159265358979323846;
  auto column = [&](const char* name, vtkIdType row) {
    vtkAbstractArray* array = table ? table->GetColumnByName(name) : nullptr;
    return array ? array->GetVariantValue(row).ToDouble() : -1.0;
  };
  const vtkIdType rows = table ? table->GetNumberOfRows() : 0;
  const double mass = column("Mass", 0), volume = column("Volume", 0),
               area = column("SurfaceArea", 0);
  std::cout << "Evrard enclosed: " << rows << " rows; component 1: mass " << mass
            << " (0.25), volume " << volume << " (" << 4.0 / 3.0 * pi * 0.125 << "), area " << area
            << " (" << pi << "), particles " << column("Particles", 0) << "\n";
  Check(rows == 2, "enclosed: one component and the total");
  Check(std::abs(mass - 0.25) < 0.02 * 0.25, "enclosed: mass within 2% of 0.25");
  Check(std::abs(volume - 4.0 / 3.0 * pi * 0.125) < 0.03 * 4.0 / 3.0 * pi * 0.125,
    "enclosed: volume within 3% of 4/3 pi 0.5^3");
  Check(std::abs(area - pi) < 0.03 * pi, "enclosed: surface area within 3% of pi");
}

// A component that crosses the faces of a periodic box: the Evrard ball (with its summed
// density) moved so that its centre sits on the face x = 0 of the box [0, 3)^3, each particle
// wrapped into the box, and "BoxSize" field data as the HDF5 reader writes it. The surface
// r = 0.5 must come out whole: the same isopoints as the ball in open space (count within 2%,
// the same radius about the centre in the periodic metric), half of them on each side of the
// box; centred on the seed, one closed sphere; with Periodic off, a surface closed off at the
// face instead.
// The glass moved to `center` in a periodic box of side L (marked by a BoxSize field array),
// wrapped into [0, L).
vtkSmartPointer<vtkPolyData> InPeriodicBox(vtkPolyData* glass, double L, const double center[3])
{
  auto box = vtkSmartPointer<vtkPolyData>::New();
  box->DeepCopy(glass);
  for (vtkIdType i = 0; i < box->GetNumberOfPoints(); ++i)
  {
    double x[3];
    box->GetPoint(i, x);
    for (int d = 0; d < 3; ++d)
    {
      x[d] = std::fmod(x[d] + center[d] + L, L);
    }
    box->GetPoints()->SetPoint(i, x);
  }
  vtkNew<vtkDoubleArray> size;
  size->SetName("BoxSize");
  size->InsertNextValue(L);
  box->GetFieldData()->AddArray(size);
  return box;
}

void TestPeriodicBox(vtkPolyData* glass, double iso, vtkIdType openCount, double openRadius)
{
  const double L = 3.0, center[3] = { 0.0, 1.5, 1.5 };
  vtkSmartPointer<vtkPolyData> box = InPeriodicBox(glass, L, center);
  const double seed[3] = { 0.1, 1.5, 1.5 };
  auto radiusAbout = [&](const double* x, bool periodic) {
    double r2 = 0.0;
    for (int d = 0; d < 3; ++d)
    {
      double dx = x[d] - center[d];
      dx -= periodic ? L * std::round(dx / L) : 0.0;
      r2 += dx * dx;
    }
    return std::sqrt(r2);
  };
  for (int output : { vtkLevelSetIsosurface::IN_BOX, vtkLevelSetIsosurface::AROUND_SEED })
  {
    vtkNew<vtkLevelSetIsosurface> filter;
    filter->SetPeriodicOutput(output);
    auto out = Run(box, iso, seed, 0.1, vtkLevelSetIsosurface::ISOPOINTS, filter);
    const vtkIdType n = out->GetNumberOfPoints();
    double mean = 0.0, worst = 0.0;
    vtkIdType high = 0;
    for (vtkIdType i = 0; i < n; ++i)
    {
      const double r = radiusAbout(out->GetPoint(i), output == vtkLevelSetIsosurface::IN_BOX);
      mean += r;
      worst = std::max(worst, std::abs(r - openRadius));
      high += out->GetPoint(i)[0] > 1.5 ? 1 : 0;
    }
    mean /= std::max<vtkIdType>(1, n);
    std::cout << "Periodic box, " << (output ? "around the seed" : "in the box") << ": " << n
              << " isopoints (open space: " << openCount << "), " << high
              << " beyond x = 1.5, mean radius " << mean << " (open space: " << openRadius
              << "), largest deviation " << worst << "\n";
    Check(std::abs(static_cast<double>(n - openCount)) <= 0.02 * openCount &&
        std::abs(mean - openRadius) < 2e-3 && worst < 0.05,
      std::string("periodic box: the ball across the face is the whole sphere, ") +
        (output ? "centred on the seed" : "in the box"));
    // The Enclosed table's centre of mass: the ball's centre (in the periodic metric: the glass
    // is not exactly symmetric), in the cell the surface is shown in: [0, 3) in the box, the
    // cell centred on the seed (x in [-1.4, 1.6)) around it.
    vtkTable* enclosed = vtkTable::SafeDownCast(filter->GetOutputDataObject(3));
    vtkDataArray* centres =
      enclosed ? vtkDataArray::SafeDownCast(enclosed->GetColumnByName("CenterOfMass")) : nullptr;
    double com[3] = { HUGE_VAL, HUGE_VAL, HUGE_VAL };
    if (centres && centres->GetNumberOfTuples() > 0)
    {
      centres->GetTuple(0, com);
    }
    const double low = output == vtkLevelSetIsosurface::IN_BOX ? 0.0 : seed[0] - 0.5 * L;
    std::cout << "  centre of mass (" << com[0] << ", " << com[1] << ", " << com[2]
              << "), off the ball's centre by " << radiusAbout(com, true) << "\n";
    Check(radiusAbout(com, true) < 0.01 && com[0] >= low && com[0] < low + L,
      "periodic box: the centre of mass is the ball's, in the cell shown");
    if (output == vtkLevelSetIsosurface::IN_BOX)
    {
      Check(high > 0.3 * n && high < 0.7 * n, "periodic box: half the sphere on each side");
    }
    else
    {
      Check(high == 0, "periodic box, around the seed: one piece about the seed");
    }
  }
  // QuickIsoValueChanges in the box: a 2% higher isovalue slides the whole surface (the part
  // beyond the face too) onto the level r = 0.5 / 1.02, as close as the method's surface there.
  {
    auto meanRadius = [&](vtkPolyData* surface) {
      double sum = 0.0;
      for (vtkIdType i = 0; i < surface->GetNumberOfPoints(); ++i)
      {
        sum += radiusAbout(surface->GetPoint(i), true);
      }
      return sum / std::max<vtkIdType>(1, surface->GetNumberOfPoints());
    };
    vtkNew<vtkLevelSetIsosurface> quick;
    quick->QuickIsoValueChangesOn();
    Run(box, iso, seed, 0.1, vtkLevelSetIsosurface::ISOPOINTS, quick);
    auto slid = Run(box, 1.02 * iso, seed, 0.1, vtkLevelSetIsosurface::ISOPOINTS, quick);
    auto full = Run(box, 1.02 * iso, seed, 0.1, vtkLevelSetIsosurface::ISOPOINTS);
    const double n = static_cast<double>(slid->GetNumberOfPoints());
    const double fullCount = static_cast<double>(full->GetNumberOfPoints());
    std::cout << "Periodic box, isovalue 2% higher: slid " << quick->GetSlidLastSurface() << ", "
              << n << " points, mean radius " << meanRadius(slid) << " (the method's: " << fullCount
              << " points, " << meanRadius(full) << ")\n";
    Check(quick->GetSlidLastSurface() && std::abs(n - fullCount) < 0.05 * fullCount &&
        std::abs(meanRadius(slid) - meanRadius(full)) < 1e-3,
      "periodic box: a 2% isovalue change slides onto the method's level");
  }
  // The same box centred on 0 ([-1.5, 1.5)^3, as Tipsy's cosmological boxes are): the filter
  // places the box on the particles.
  auto centred = vtkSmartPointer<vtkPolyData>::New();
  centred->DeepCopy(box);
  for (vtkIdType i = 0; i < centred->GetNumberOfPoints(); ++i)
  {
    double x[3];
    centred->GetPoint(i, x);
    centred->GetPoints()->SetPoint(i, x[0] - 0.5 * L, x[1] - 0.5 * L, x[2] - 0.5 * L);
  }
  const double shiftedSeed[3] = { seed[0] - 0.5 * L, seed[1] - 0.5 * L, seed[2] - 0.5 * L };
  auto around = Run(centred, iso, shiftedSeed, 0.1, vtkLevelSetIsosurface::ISOPOINTS);
  double centredMean = 0.0;
  vtkIdType outside = 0;
  for (vtkIdType i = 0; i < around->GetNumberOfPoints(); ++i)
  {
    double x[3];
    around->GetPoint(i, x);
    outside += (x[0] < -0.5 * L || x[0] >= 0.5 * L) ? 1 : 0;
    x[0] += 0.5 * L;
    x[1] += 0.5 * L;
    x[2] += 0.5 * L;
    centredMean += radiusAbout(x, true);
  }
  centredMean /= std::max<vtkIdType>(1, around->GetNumberOfPoints());
  std::cout << "Periodic box centred on 0: " << around->GetNumberOfPoints()
            << " isopoints, mean radius " << centredMean << ", " << outside << " outside the box\n";
  Check(
    std::abs(static_cast<double>(around->GetNumberOfPoints() - openCount)) <= 0.02 * openCount &&
      std::abs(centredMean - openRadius) < 2e-3 && outside == 0,
    "periodic box centred on 0: the whole sphere, in the box");

  vtkNew<vtkLevelSetIsosurface> open;
  open->SetPeriodic(false);
  auto cut = Run(box, iso, seed, 0.1, vtkLevelSetIsosurface::ISOPOINTS, open);
  double worst = 0.0;
  for (vtkIdType i = 0; i < cut->GetNumberOfPoints(); ++i)
  {
    worst = std::max(worst, std::abs(radiusAbout(cut->GetPoint(i), true) - openRadius));
  }
  std::cout << "Periodic off: " << cut->GetNumberOfPoints()
            << " isopoints, largest deviation from the sphere " << worst << "\n";
  Check(worst > 0.2, "Periodic off: the face cuts the component (a surface closed off there)");
}

// Whether two outputs have the same points, cells and point arrays, to the bit.
bool SameOutput(vtkPolyData* a, vtkPolyData* b)
{
  bool same = a->GetNumberOfPoints() == b->GetNumberOfPoints() &&
    a->GetNumberOfCells() == b->GetNumberOfCells() &&
    a->GetPointData()->GetNumberOfArrays() == b->GetPointData()->GetNumberOfArrays();
  for (vtkIdType i = 0; same && i < a->GetNumberOfPoints(); ++i)
  {
    for (int d = 0; d < 3; ++d)
    {
      same = same && a->GetPoint(i)[d] == b->GetPoint(i)[d];
    }
  }
  for (int k = 0; same && k < a->GetPointData()->GetNumberOfArrays(); ++k)
  {
    vtkDataArray* x = a->GetPointData()->GetArray(k);
    vtkDataArray* y = x ? b->GetPointData()->GetArray(x->GetName()) : nullptr;
    same = x && y && x->GetNumberOfValues() == y->GetNumberOfValues();
    for (vtkIdType v = 0; same && v < x->GetNumberOfValues(); ++v)
    {
      same = x->GetComponent(v / x->GetNumberOfComponents(), v % x->GetNumberOfComponents()) ==
        y->GetComponent(v / y->GetNumberOfComponents(), v % y->GetNumberOfComponents());
    }
  }
  return same;
}

// A change of the surface output's properties alone on the SPH field, QuickIsoValueChanges off
// (no field kept): the output is made again from the last run's points, on the same field built
// again (the interpolated arrays are its interpolants), without running the method: a fresh
// filter's output to the bit. `what` names the input (the glass, or it in a periodic box).
void TestRemakeOnSPHField(
  vtkPolyData* input, double iso, const double seed[3], const std::string& what)
{
  vtkNew<vtkLevelSetIsosurface> filter;
  Run(input, iso, seed, 0.1, vtkLevelSetIsosurface::ISOPOINTS, filter);
  Check(filter->GetUsedSPHField(), what + ": the SPH field is used");
  auto remade = [&]() {
    return filter->GetRemadeSurfaceOutput() && filter->GetEvolutionSeconds() == 0.0 &&
      filter->GetIsopointSeconds() == 0.0 && filter->GetOutputSeconds() > 0.0;
  };
  auto sameAsFresh = [&]() {
    vtkNew<vtkLevelSetIsosurface> fresh;
    fresh->SetSplatScale(filter->GetSplatScale());
    auto out = Run(input, iso, seed, 0.1, filter->GetOutputType(), fresh);
    return out->GetNumberOfPoints() > 100 && out->GetPointData()->GetArray("TwoPlusX") &&
      SameOutput(filter->GetOutput(0), out);
  };
  filter->SetOutputTypeToSplats();
  filter->Update();
  Check(remade(), what + ": an OutputType change makes the surface output alone");
  Check(sameAsFresh(), what + ": splats with the SPH interpolants, a fresh filter's to the bit");
  filter->SetSplatScale(1.5);
  filter->Update();
  Check(remade() && sameAsFresh(), what + ": larger splats alone, a fresh filter's to the bit");
}

// A Tipsy file's particles with Particle Density's summed density and smoothing lengths (64
// neighbours), as a user makes an SPH field where a file has none.
vtkSmartPointer<vtkPolyData> WithSummedDensity(const std::string& path)
{
  vtkNew<vtkTipsyParticleReader> reader;
  reader->SetFileName(path.c_str());
  vtkNew<vtkParticleDensity> density;
  density->SetInputConnection(reader->GetOutputPort());
  density->SetNumberOfNeighbors(64);
  density->Update();
  auto particles = vtkSmartPointer<vtkPolyData>::New();
  particles->ShallowCopy(density->GetOutput());
  return particles;
}

// QuickIsoValueChanges on the SPH field: a 3% higher isovalue (the level moves about 0.015 in
// radius, a tenth of a support) slides the last surface onto the field's new level, as close to
// it as the method's own points, with as many points and the enclosed mass within 0.5%.
void TestQuickIsoValueChange(vtkPolyData* glass, const Particles& p, double iso)
{
  const double seed[3] = { 0, 0, 0 };
  const double changed = 1.03 * iso;
  QuickAndMethod runs(glass, iso, changed, seed, 0.1);
  const Scores s = Score(p, runs.Slid, changed, 400), m = Score(p, runs.Method, changed, 400);
  Report("Evrard, slid to a 3% higher isovalue", s, runs.Slid->GetNumberOfPoints());
  Report("Evrard, the method there", m, runs.Method->GetNumberOfPoints());
  Check(runs.Quick->GetSlidLastSurface(), "Evrard: a 3% isovalue change slides the surface");
  Check(s.MeanDistance < 1e-3 && s.MaxDistance < 1e-2 && s.MaxAngle < 0.5,
    "Evrard: slid points on the field's new level (mean < 0.001 H, max < 0.01 H), normals "
    "along its gradient (< 0.5 deg)");
  const double count = static_cast<double>(runs.Slid->GetNumberOfPoints());
  Check(std::abs(count - runs.Method->GetNumberOfPoints()) < 0.05 * count,
    "Evrard: as many slid points as the method's, within 5%");
  const double slidMass = EnclosedMass(runs.Quick), methodMass = EnclosedMass(runs.Full);
  std::cout << "Evrard: enclosed mass slid " << slidMass << ", method " << methodMass << "\n";
  Check(std::abs(slidMass - methodMass) < 0.005 * methodMass,
    "Evrard: the slid surface encloses the method's mass within 0.5%");
}

// The same at the cloud's edge (isovalue 0.08: the field's level lies beyond the outermost
// particles, and the surface there is made of free-boundary points, shot from the edge): the
// free boundary is shot anew from the new flood, so the change still slides, its points on the
// new level, with the method's count of points beyond the edge within 5%.
void TestQuickAtCloudEdge(vtkPolyData* glass, const Particles& p)
{
  double edge = 0.0; // the cloud's radius
  for (vtkIdType i = 0; i < glass->GetNumberOfPoints(); ++i)
  {
    const double* x = glass->GetPoint(i);
    edge = std::max(edge, std::sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]));
  }
  auto beyondEdge = [&](vtkPolyData* points) {
    double count = 0.0;
    for (vtkIdType i = 0; i < points->GetNumberOfPoints(); ++i)
    {
      const double* x = points->GetPoint(i);
      count += std::sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]) > edge ? 1.0 : 0.0;
    }
    return count;
  };
  const double iso = 0.08, changed = 1.03 * iso, seed[3] = { 0, 0, 0 };
  vtkNew<vtkLevelSetIsosurface> quick;
  quick->QuickIsoValueChangesOn();
  auto before = Run(glass, iso, seed, 0.1, vtkLevelSetIsosurface::ISOPOINTS, quick);
  auto slid = Run(glass, changed, seed, 0.1, vtkLevelSetIsosurface::ISOPOINTS, quick);
  vtkNew<vtkLevelSetIsosurface> full;
  auto method = Run(glass, changed, seed, 0.1, vtkLevelSetIsosurface::ISOPOINTS, full);
  const Scores s = Score(p, slid, changed, 400);
  Report("Evrard at the cloud's edge, slid to a 3% higher isovalue", s, slid->GetNumberOfPoints());
  std::cout << "Evrard at the cloud's edge: points beyond it, before " << beyondEdge(before)
            << ", slid " << beyondEdge(slid) << ", method " << beyondEdge(method) << "\n";
  Check(beyondEdge(before) > 50 && beyondEdge(method) > 50,
    "Evrard at the cloud's edge: the surface has free-boundary points");
  Check(quick->GetSlidLastSurface(), "Evrard at the cloud's edge: a 3% change slides");
  Check(s.MeanDistance < 1e-3 && s.MaxDistance < 1e-2,
    "Evrard at the cloud's edge: slid points on the field's new level");
  Check(std::abs(beyondEdge(slid) - beyondEdge(method)) <= 0.05 * beyondEdge(method),
    "Evrard at the cloud's edge: the method's free-boundary points, within 5%");
}

// `glass` with every particle written twice (all its arrays; field data kept), an integer
// array "tag" (the first copies 0..n-1, the second n..2n-1), and global ids that are the same
// for both copies (one particle written twice) or not (two particles at one place).
vtkSmartPointer<vtkPolyData> WrittenTwice(vtkPolyData* glass, bool sameIds)
{
  const vtkIdType n = glass->GetNumberOfPoints();
  auto twice = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  for (int copy = 0; copy < 2; ++copy)
  {
    for (vtkIdType i = 0; i < n; ++i)
    {
      points->InsertNextPoint(glass->GetPoint(i));
    }
  }
  twice->SetPoints(points);
  for (int a = 0; a < glass->GetPointData()->GetNumberOfArrays(); ++a)
  {
    vtkDataArray* array = glass->GetPointData()->GetArray(a);
    vtkSmartPointer<vtkDataArray> copies = vtk::TakeSmartPointer(array->NewInstance());
    copies->SetName(array->GetName());
    copies->SetNumberOfComponents(array->GetNumberOfComponents());
    // Two particles at each place have twice the density, as a code would store it (one
    // particle written twice keeps its own).
    const bool doubled = !sameIds && std::string(array->GetName()) == "Density";
    for (int copy = 0; copy < 2; ++copy)
    {
      for (vtkIdType i = 0; i < n; ++i)
      {
        copies->InsertNextTuple(i, array);
        if (doubled)
        {
          copies->SetTuple1(copies->GetNumberOfTuples() - 1, 2.0 * array->GetTuple1(i));
        }
      }
    }
    twice->GetPointData()->AddArray(copies);
  }
  vtkNew<vtkIntArray> tag;
  vtkNew<vtkIdTypeArray> ids;
  tag->SetName("tag");
  ids->SetName("ParticleIDs");
  for (vtkIdType j = 0; j < 2 * n; ++j)
  {
    tag->InsertNextValue(static_cast<int>(j));
    ids->InsertNextValue(sameIds ? j % n : j);
  }
  twice->GetPointData()->AddArray(tag);
  twice->GetPointData()->SetGlobalIds(ids);
  twice->GetFieldData()->ShallowCopy(glass->GetFieldData());
  return twice;
}

// Particles at one place on the SPH field: merged with a warning, the group's masses summed,
// so the field keeps its mass. Two particles at each place (distinct ids) make the field twice
// the glass's: the surface at twice the isovalue is the glass's surface at the isovalue. One
// particle written twice (the same id) is counted once: the glass's surface at the isovalue.
// The integer tag on the surface is the nearest merged particle's smallest (the first copies').
void TestDuplicates(vtkPolyData* glass, double iso, const double seed[3])
{
  const vtkSmartPointer<vtkPolyData> reference =
    Run(glass, iso, seed, 0.1, vtkLevelSetIsosurface::ISOPOINTS);
  for (bool sameIds : { false, true })
  {
    const double level = sameIds ? iso : 2.0 * iso;
    vtkNew<vtkLevelSetIsosurface> filter;
    vtkNew<lsi::test::MessageCounter> warnings;
    filter->AddObserver(vtkCommand::WarningEvent, warnings);
    const vtkSmartPointer<vtkPolyData> out =
      Run(WrittenTwice(glass, sameIds), level, seed, 0.1, vtkLevelSetIsosurface::ISOPOINTS, filter);
    double worst = out->GetNumberOfPoints() == reference->GetNumberOfPoints() ? 0.0 : HUGE_VAL;
    for (vtkIdType i = 0; worst < HUGE_VAL && i < out->GetNumberOfPoints(); ++i)
    {
      worst = std::max(worst,
        std::sqrt(vtkMath::Distance2BetweenPoints(out->GetPoint(i), reference->GetPoint(i))));
    }
    vtkDataArray* tag = out->GetPointData()->GetArray("tag");
    double largestTag = tag ? tag->GetRange()[1] : HUGE_VAL;
    const std::string what = sameIds ? "one particle written twice (same ids), at the isovalue"
                                     : "two particles at each place, at twice the isovalue";
    std::cout << "duplicates, " << what << ": " << out->GetNumberOfPoints() << " isopoints ("
              << reference->GetNumberOfPoints() << " without), moved at most " << worst
              << "; warning: " << warnings->Last << "\n";
    Check(worst < 1e-12 && warnings->Count == 1 &&
        warnings->Last.find("summed") != std::string::npos && tag &&
        tag->GetDataType() == VTK_INT && largestTag < glass->GetNumberOfPoints(),
      "duplicates on the SPH field, " + what +
        ": the glass's surface, one warning, the tag the first copies'");
  }
}

// Stored densities the kernel sums of the masses do not give: the smoothing lengths (or the
// densities' units) are not the simulation's. Particle Density's own densities and lengths
// agree (no warning), as do ones 10% off (within the codes' conventions); a support half the
// one the densities were summed with, or densities in other units, warn: with Field Automatic
// the MLS fit is used, with Field SPH the SPH field, as asked.
void TestStoredDensityCheck(vtkPolyData* glass, double iso, const double seed[3])
{
  auto scaled = [&](double factor) {
    auto copy = vtkSmartPointer<vtkPolyData>::New();
    copy->DeepCopy(glass);
    vtkDataArray* rho = copy->GetPointData()->GetArray("Density");
    for (vtkIdType i = 0; i < rho->GetNumberOfTuples(); ++i)
    {
      rho->SetTuple1(i, factor * rho->GetTuple1(i));
    }
    return copy;
  };
  struct Case
  {
    const char* What;
    double DensityFactor, Support;
    int Field;
    bool Warns;
  };
  const Case cases[] = {
    { "Particle Density's densities and lengths", 1.0, 0.0, vtkLevelSetIsosurface::AUTOMATIC_FIELD,
      false },
    { "densities 10% above the sums", 1.1, 0.0, vtkLevelSetIsosurface::AUTOMATIC_FIELD, false },
    { "supports half the densities' (Field Automatic)", 1.0, 0.5,
      vtkLevelSetIsosurface::AUTOMATIC_FIELD, true },
    { "densities in other units (Field SPH)", 1000.0, 0.0, vtkLevelSetIsosurface::SPH_FIELD, true },
  };
  for (const Case& c : cases)
  {
    vtkNew<vtkLevelSetIsosurface> filter;
    filter->SetField(c.Field);
    filter->SetSupportPerSmoothingLength(c.Support);
    vtkNew<lsi::test::MessageCounter> warnings;
    filter->AddObserver(vtkCommand::WarningEvent, warnings);
    // (The isovalue in the densities' units, as a user picks it from their range.)
    const double level = c.DensityFactor > 100.0 ? c.DensityFactor * iso : iso;
    Run(scaled(c.DensityFactor), level, seed, 0.1, vtkLevelSetIsosurface::ISOPOINTS, filter);
    const std::size_t at = warnings->All.find("are not the kernel sums");
    std::cout << "stored densities, " << c.What << ": " << filter->GetNumberOfIsopoints()
              << " isopoints, SPH field " << filter->GetUsedSPHField() << ", " << warnings->Count
              << " warnings " << warnings->All.substr(0, 300)
              << (at == std::string::npos ? std::string() : ": ..." + warnings->All.substr(at, 120))
              << "\n";
    const bool sph = c.Field == vtkLevelSetIsosurface::SPH_FIELD || !c.Warns;
    // (In other units the SPH field never reaches the isovalue: no surface, but not silently.)
    Check((at != std::string::npos) == c.Warns && filter->GetUsedSPHField() == sph &&
        (filter->GetNumberOfIsopoints() > 1000) == (c.DensityFactor < 100.0),
      std::string("stored densities, ") + c.What +
        (c.Warns ? ": a warning, and the field Field asks for" : ": no warning, the SPH field"));
  }
}

void TestEvrard(const std::string& path)
{
  vtkSmartPointer<vtkPolyData> glass = WithSummedDensity(path);
  // An array to interpolate: A = 2 + x.
  vtkNew<vtkDoubleArray> a;
  a->SetName("TwoPlusX");
  std::vector<double> values;
  for (vtkIdType i = 0; i < glass->GetNumberOfPoints(); ++i)
  {
    values.push_back(2.0 + glass->GetPoint(i)[0]);
    a->InsertNextValue(values.back());
  }
  glass->GetPointData()->AddArray(a);
  const Particles p =
    ParticlesOf(glass, "SmoothingLength", "mass", "Density", 1.0, lsi::SPHKernel::CubicSpline);

  const double iso = 1.0 / (2.0 * 3.14159265358979 * 0.5), seed[3] = { 0, 0, 0 };
  vtkNew<vtkLevelSetIsosurface> filter;
  auto isopoints = Run(glass, iso, seed, 0.1, vtkLevelSetIsosurface::ISOPOINTS, filter);
  Check(filter->GetUsedSPHField(), "Evrard with Particle Density's markers: the SPH field is used");
  const Scores s = Score(p, isopoints, iso, 400);
  Report("Evrard isopoints", s, isopoints->GetNumberOfPoints());
  Check(isopoints->GetNumberOfPoints() > 1000 && s.MeanDistance < 1e-3 && s.MaxDistance < 1e-2 &&
      s.MaxAngle < 0.5,
    "Evrard: isopoints on the SPH field's level (mean < 0.001 H, max < 0.01 H), normals along "
    "its gradient (< 0.5 deg)");
  // The summed density approximates 1 / (2 pi r): the surface is near r = 0.5.
  double meanRadius = 0.0;
  for (vtkIdType i = 0; i < isopoints->GetNumberOfPoints(); ++i)
  {
    const double* x = isopoints->GetPoint(i);
    meanRadius += std::sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]);
  }
  meanRadius /= std::max<vtkIdType>(1, isopoints->GetNumberOfPoints());
  std::cout << "Evrard: mean isopoint radius " << meanRadius << " (analytic profile: 0.5)\n";
  Check(std::abs(meanRadius - 0.5) < 0.05, "Evrard: the surface near r = 0.5");
  // The interpolated array is the SPH interpolant of A.
  double worst = 0.0;
  vtkDataArray* interpolated = isopoints->GetPointData()->GetArray("TwoPlusX");
  for (vtkIdType i = 0; interpolated && i < isopoints->GetNumberOfPoints(); i += 97)
  {
    const double exact = InterpolantAt(p, values, isopoints->GetPoint(i));
    worst = std::max(worst, std::abs(interpolated->GetTuple1(i) - exact) / std::abs(exact));
  }
  std::cout << "Evrard: interpolated array, worst relative difference " << worst << "\n";
  Check(interpolated && worst < 1e-9, "Evrard: arrays interpolated as sum (m/rho) A W");

  TestPeriodicBox(glass, iso, isopoints->GetNumberOfPoints(), meanRadius);
  TestRemakeOnSPHField(glass, iso, seed, "Evrard");
  const double boxCenter[3] = { 0.0, 1.5, 1.5 }, boxSeed[3] = { 0.1, 1.5, 1.5 };
  TestRemakeOnSPHField(InPeriodicBox(glass, 3.0, boxCenter), iso, boxSeed, "Evrard in a box");
  TestEnclosed(filter);
  TestQuickIsoValueChange(glass, p, iso);
  TestQuickAtCloudEdge(glass, p);
  TestDuplicates(glass, iso, seed);
  TestStoredDensityCheck(glass, iso, seed);

  // The default output: every splat corner on the level, its normal the field's.
  auto splats = Run(glass, iso, seed, 0.1, vtkLevelSetIsosurface::SPLATS);
  const Scores c = Score(p, splats, iso, 2000);
  Report("Evrard splat corners", c, splats->GetNumberOfPoints());
  Check(c.MeanDistance < 1e-3 && c.MaxAngle < 2.0,
    "Evrard: splat corners on the SPH level (mean < 0.001 H), normals within 2 deg");

  // Other units of length (x 1000; masses kept, so densities / 1e9): the same surface, scaled.
  auto scaled = vtkSmartPointer<vtkPolyData>::New();
  scaled->DeepCopy(glass);
  const double L = 1000.0;
  for (vtkIdType i = 0; i < scaled->GetNumberOfPoints(); ++i)
  {
    double x[3];
    scaled->GetPoint(i, x);
    scaled->GetPoints()->SetPoint(i, L * x[0], L * x[1], L * x[2]);
    vtkDataArray* h = scaled->GetPointData()->GetArray("SmoothingLength");
    h->SetTuple1(i, L * h->GetTuple1(i));
    vtkDataArray* rho = scaled->GetPointData()->GetArray("Density");
    rho->SetTuple1(i, rho->GetTuple1(i) / (L * L * L));
  }
  scaled->Modified();
  auto big = Run(scaled, iso / (L * L * L), seed, 0.1 * L, vtkLevelSetIsosurface::ISOPOINTS);
  double bigRadius = 0.0;
  for (vtkIdType i = 0; i < big->GetNumberOfPoints(); ++i)
  {
    const double* x = big->GetPoint(i);
    bigRadius += std::sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]) / L;
  }
  bigRadius /= std::max<vtkIdType>(1, big->GetNumberOfPoints());
  std::cout << "Evrard x1000: " << big->GetNumberOfPoints()
            << " isopoints (x1: " << isopoints->GetNumberOfPoints() << "), mean radius / 1000 "
            << bigRadius << "\n";
  Check(std::abs(static_cast<double>(big->GetNumberOfPoints()) - isopoints->GetNumberOfPoints()) <=
        0.01 * isopoints->GetNumberOfPoints() &&
      std::abs(bigRadius - meanRadius) < 1e-6 * meanRadius,
    "Evrard: lengths x1000 give the same surface, scaled");

  // The same particles written the SWIFT way: h = H / gamma, a support 20% wider than the
  // cubic's, and the markers the HDF5 reader writes for each of SWIFT's other kernels. The
  // filter must follow the markers: the isopoints lie on that kernel's field.
  const struct
  {
    const char* Marker;
    double Gamma;
    lsi::SPHKernel Kernel;
  } swiftKernels[] = { { "QuinticSpline", 2.195775, lsi::SPHKernel::QuinticSpline },
    { "QuarticSpline", 2.018932, lsi::SPHKernel::QuarticSpline },
    { "WendlandC4", 2.207940, lsi::SPHKernel::WendlandC4 },
    { "WendlandC6", 2.449490, lsi::SPHKernel::WendlandC6 } };
  for (const auto& k : swiftKernels)
  {
    auto swift = vtkSmartPointer<vtkPolyData>::New();
    swift->DeepCopy(glass);
    vtkDataArray* h = swift->GetPointData()->GetArray("SmoothingLength");
    for (vtkIdType i = 0; i < swift->GetNumberOfPoints(); ++i)
    {
      h->SetTuple1(i, 1.2 * h->GetTuple1(i) / k.Gamma);
    }
    vtkNew<vtkStringArray> kernel;
    kernel->SetName("SPHKernel");
    kernel->InsertNextValue(k.Marker);
    swift->GetFieldData()->RemoveArray("SPHKernel");
    swift->GetFieldData()->AddArray(kernel);
    vtkNew<vtkDoubleArray> factor;
    factor->SetName("SupportPerSmoothingLength");
    factor->InsertNextValue(k.Gamma);
    swift->GetFieldData()->RemoveArray("SupportPerSmoothingLength");
    swift->GetFieldData()->AddArray(factor);
    const Particles q = ParticlesOf(swift, "SmoothingLength", "mass", "Density", k.Gamma, k.Kernel);
    auto isopointsOf = Run(swift, iso, seed, 0.1, vtkLevelSetIsosurface::ISOPOINTS);
    const Scores sk = Score(q, isopointsOf, iso, 400);
    const std::string what =
      std::string("Evrard, SWIFT convention (") + k.Marker + ", H = gamma h)";
    Report(what, sk, isopointsOf->GetNumberOfPoints());
    Check(isopointsOf->GetNumberOfPoints() > 1000 && sk.MeanDistance < 1e-3 && sk.MaxAngle < 0.5,
      what + ": isopoints on that kernel's field's level");
    if (k.Kernel != lsi::SPHKernel::QuinticSpline)
    {
      // What the reader's marker gave before these kernels: the cubic spline, with the same
      // supports. Its surface lies off this kernel's level (the check above can fail).
      vtkNew<vtkLevelSetIsosurface> cubicFilter;
      cubicFilter->SetKernel(vtkLevelSetIsosurface::CUBIC_SPLINE);
      auto cubicOut = Run(swift, iso, seed, 0.1, vtkLevelSetIsosurface::ISOPOINTS, cubicFilter);
      const Scores wrong = Score(q, cubicOut, iso, 400);
      Report(what + ", summed with the cubic spline instead", wrong, cubicOut->GetNumberOfPoints());
      Check(wrong.MeanDistance > 1e-3, what + ": the cubic spline's surface is not this one's");
    }
  }

  // A marker that names no kernel the field knows: a warning, and the cubic spline's field.
  auto unknown = vtkSmartPointer<vtkPolyData>::New();
  unknown->DeepCopy(glass);
  vtkNew<vtkStringArray> gaussian;
  gaussian->SetName("SPHKernel");
  gaussian->InsertNextValue("Gaussian");
  unknown->GetFieldData()->RemoveArray("SPHKernel");
  unknown->GetFieldData()->AddArray(gaussian);
  vtkNew<vtkLevelSetIsosurface> warned;
  vtkNew<lsi::test::MessageCounter> warnings;
  warned->AddObserver(vtkCommand::WarningEvent, warnings);
  auto cubic = Run(unknown, iso, seed, 0.1, vtkLevelSetIsosurface::ISOPOINTS, warned);
  const Scores su = Score(p, cubic, iso, 400);
  std::cout << "Unknown kernel marker: " << warnings->Last << "\n";
  Check(warnings->All.find("'Gaussian'") != std::string::npos && su.MeanDistance < 1e-3,
    "a kernel marker the field does not know: a warning naming it, the cubic spline's field");

  // Field = MLS ignores the smoothing lengths; Field = SPH without them is an error.
  vtkNew<vtkLevelSetIsosurface> mls;
  mls->SetField(vtkLevelSetIsosurface::MLS_FIELD);
  Run(glass, iso, seed, 0.1, vtkLevelSetIsosurface::ISOPOINTS, mls);
  Check(!mls->GetUsedSPHField() && mls->GetNumberOfIsopoints() > 1000,
    "Field = MLS: the MLS fit, not the SPH field");
  auto bare = vtkSmartPointer<vtkPolyData>::New();
  bare->DeepCopy(glass);
  bare->GetPointData()->RemoveArray("SmoothingLength");
  bare->GetPointData()->RemoveArray("hsmooth"); // the Tipsy file's placeholder column
  bare->GetFieldData()->Initialize();
  vtkNew<vtkLevelSetIsosurface> forced;
  forced->SetField(vtkLevelSetIsosurface::SPH_FIELD);
  forced->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "Density");
  vtkNew<lsi::test::MessageCounter> errors;
  forced->AddObserver(vtkCommand::ErrorEvent, errors);
  auto none = Run(bare, iso, seed, 0.1, vtkLevelSetIsosurface::ISOPOINTS, forced);
  std::cout << "Field = SPH without smoothing lengths: " << errors->Last << "\n";
  Check(errors->Count == 1 && none->GetNumberOfPoints() == 0 &&
      errors->Last.find("smoothing length") != std::string::npos,
    "Field = SPH without smoothing lengths: an error that says so, and no output");

  // A snapshot's particles (densities and masses marked, as a Tipsy output without its
  // .smoothlength or an AREPO snapshot) without smoothing lengths: the fit, with a warning.
  auto marked = vtkSmartPointer<vtkPolyData>::New();
  marked->DeepCopy(bare);
  for (const auto& marker :
    { std::make_pair("DensityArray", "Density"), std::make_pair("MassArray", "mass") })
  {
    vtkNew<vtkStringArray> name;
    name->SetName(marker.first);
    name->InsertNextValue(marker.second);
    marked->GetFieldData()->AddArray(name);
  }
  for (vtkPolyData* input : { bare.Get(), marked.Get() })
  {
    vtkNew<vtkLevelSetIsosurface> automatic;
    automatic->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "Density");
    vtkNew<lsi::test::MessageCounter> warnings;
    automatic->AddObserver(vtkCommand::WarningEvent, warnings);
    Run(input, iso, seed, 0.1, vtkLevelSetIsosurface::ISOPOINTS, automatic);
    const bool said = warnings->All.find("no smoothing lengths") != std::string::npos;
    Check(!automatic->GetUsedSPHField() && automatic->GetNumberOfIsopoints() > 1000 &&
        said == (input == marked.Get()),
      input == marked.Get()
        ? "marked densities and masses, no smoothing lengths: the fit, with a warning"
        : "unmarked point data without smoothing lengths: the fit, no such warning");
  }
}

// The shock tube's own rho and hsmooth columns are placeholders (rho 0 for 17k of its 20k
// particles, hsmooth a constant 0.0027, five times below the particle spacing): its SPH field
// comes from Particle Density, as a user would make it. A planar front across the tube and the
// tube's walls, with real mass and spacing jumps.
void TestShockTube(const std::string& path)
{
  vtkSmartPointer<vtkPolyData> tube = WithSummedDensity(path);
  const Particles p =
    ParticlesOf(tube, "SmoothingLength", "mass", "Density", 1.0, lsi::SPHKernel::CubicSpline);
  // The seed: the densest particle; the isovalue: half its density.
  vtkDataArray* rho = tube->GetPointData()->GetArray("Density");
  vtkIdType densest = 0;
  for (vtkIdType i = 0; i < tube->GetNumberOfPoints(); ++i)
  {
    densest = rho->GetTuple1(i) > rho->GetTuple1(densest) ? i : densest;
  }
  double seed[3];
  tube->GetPoint(densest, seed);
  const double iso = 0.5 * rho->GetTuple1(densest);
  vtkNew<vtkLevelSetIsosurface> filter;
  auto out = Run(tube, iso, seed, 0.05, vtkLevelSetIsosurface::ISOPOINTS, filter);
  const Scores s = Score(p, out, iso, 400);
  Report("Shock tube isopoints", s, out->GetNumberOfPoints());
  Check(filter->GetUsedSPHField() && out->GetNumberOfPoints() > 200 && s.MeanDistance < 1e-3 &&
      s.MaxAngle < 1.0,
    "Shock tube: isopoints on the SPH level");
  // QuickIsoValueChanges where the surface meets the tube's walls and ends: there the level lies
  // beyond the outermost particles (the free boundary), whose values, their kernels cut, lie
  // near the isovalue and may cross it. A 0.2% higher isovalue still slides, its points on the
  // new level, as many as the method's within 5%, enclosing its mass within 0.5%.
  const double changed = 1.002 * iso;
  QuickAndMethod runs(tube, iso, changed, seed, 0.05);
  const Scores q = Score(p, runs.Slid, changed, 400);
  Report("Shock tube, slid to a 0.2% higher isovalue", q, runs.Slid->GetNumberOfPoints());
  Check(runs.Quick->GetSlidLastSurface(), "Shock tube: a 0.2% isovalue change slides the surface");
  Check(q.MeanDistance < 1e-3 && q.MaxAngle < 1.0, "Shock tube: slid points on the new SPH level");
  const double count = static_cast<double>(runs.Method->GetNumberOfPoints());
  const double slidMass = EnclosedMass(runs.Quick), methodMass = EnclosedMass(runs.Full);
  std::cout << "Shock tube, 0.2% higher: slid " << runs.Slid->GetNumberOfPoints()
            << " points, method " << count << "; enclosed mass slid " << slidMass << ", method "
            << methodMass << "\n";
  Check(std::abs(runs.Slid->GetNumberOfPoints() - count) < 0.05 * count &&
      std::abs(slidMass - methodMass) < 0.005 * methodMass,
    "Shock tube: as many slid points as the method's (5%), enclosing its mass (0.5%)");
  // At half the median density the surface runs along the walls of the dense side, whose
  // outermost particles lie at the isovalue: a change that moves 0.1% of the particles above
  // it across it flips some of them. The method's surface then leaves the walls in places (the
  // cut kernels put the level inside the outer layer), which a slid surface does not follow:
  // the quick change runs the method, and gives the fresh filter's output. (Flips a support
  // from the surface were once let through: `pvpython Scripts/sph_reruns.py PLUGIN DATA 1 0.01`
  // then printed the shock tube slid, enclosing 2.4% more volume than the method, with a third
  // fewer points.)
  std::vector<double> values(static_cast<std::size_t>(tube->GetNumberOfPoints()));
  for (vtkIdType i = 0; i < tube->GetNumberOfPoints(); ++i)
  {
    values[static_cast<std::size_t>(i)] = rho->GetTuple1(i);
  }
  std::nth_element(values.begin(), values.begin() + values.size() / 2, values.end());
  const double alongWalls = 0.5 * values[values.size() / 2];
  std::vector<double> above;
  std::copy_if(values.begin(), values.end(), std::back_inserter(above),
    [&](double v) { return v > alongWalls; });
  std::sort(above.begin(), above.end());
  const double nearWalls = above[above.size() / 1000];
  vtkNew<vtkLevelSetIsosurface> walls;
  walls->QuickIsoValueChangesOn();
  Run(tube, alongWalls, seed, 0.05, vtkLevelSetIsosurface::ISOPOINTS, walls);
  auto slidAlong = Run(tube, nearWalls, seed, 0.05, vtkLevelSetIsosurface::ISOPOINTS, walls);
  const Scores w = Score(p, slidAlong, nearWalls, 400);
  Report(
    "Shock tube along the walls, 0.1% of the particles across", w, slidAlong->GetNumberOfPoints());
  vtkNew<vtkLevelSetIsosurface> fresh;
  auto method = Run(tube, nearWalls, seed, 0.05, vtkLevelSetIsosurface::ISOPOINTS, fresh);
  std::cout << "Shock tube along the walls: slid " << walls->GetSlidLastSurface() << ", "
            << slidAlong->GetNumberOfPoints() << " points, the method's "
            << method->GetNumberOfPoints() << "; enclosed mass " << EnclosedMass(walls)
            << ", the method's " << EnclosedMass(fresh) << "\n";
  Check(!walls->GetSlidLastSurface() &&
      slidAlong->GetNumberOfPoints() == method->GetNumberOfPoints() &&
      EnclosedMass(walls) == EnclosedMass(fresh) && w.MeanDistance < 1e-3,
    "Shock tube along the walls: a change flipping the walls' outermost particles runs the "
    "method (the fresh filter's points and mass)");
}
} // namespace

int main(int argc, char* argv[])
{
  if (argc < 3)
  {
    std::cerr << "usage: TestSPHField GLASS_FILE SHOCKTUBE_FILE\n";
    return EXIT_FAILURE;
  }
  TestEvrard(argv[1]);
  TestShockTube(argv[2]);
  const int failures = lsi::test::Failures();
  std::cout << (failures ? "SPH field tests FAILED\n" : "SPH field tests passed\n");
  return failures ? EXIT_FAILURE : EXIT_SUCCESS;
}
