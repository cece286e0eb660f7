// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "LevelSetEnclosedSums.h"

#include "vtkDoubleArray.h"
#include "vtkIdTypeArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPointSet.h"
#include "vtkSMPTools.h"
#include "vtkStringArray.h"
#include "vtkTable.h"

#include <algorithm>
#include <string>

namespace lsi
{
namespace enclosed
{

Links::Links(std::size_t n)
  : Parent(new std::atomic<std::uint32_t>[n]) // (not zeroed: set in parallel below)
  , Size(n)
{
  vtkSMPTools::For(
    0, static_cast<vtkIdType>(n), BalancedGrain(n, 1024), [&](vtkIdType begin, vtkIdType end) {
      for (vtkIdType i = begin; i < end; ++i)
      {
        this->Parent[i].store(static_cast<std::uint32_t>(i), std::memory_order_relaxed);
      }
    });
}

void Sums::Add(const Sums& other)
{
  if (!other.HasReference)
  {
    return;
  }
  if (!this->HasReference)
  {
    *this = other;
    return;
  }
  this->Particles += other.Particles;
  this->Mass += other.Mass;
  this->Volume += other.Volume;
  this->Area += other.Area;
  this->Weight += other.Weight;
  this->Inside = this->Inside || other.Inside;
  for (int d = 0; d < 3; ++d)
  {
    this->Moment[d] += other.Moment[d] + other.Weight * (other.Reference[d] - this->Reference[d]);
  }
  for (int k = 0; k < 6; ++k)
  {
    this->Circular[k] += other.Circular[k];
  }
  for (std::size_t k = 0; k < this->Means.size(); ++k)
  {
    this->Means[k] += other.Means[k];
  }
}

void Pack(double key, const Sums& c, std::vector<double>& out)
{
  out.insert(out.end(),
    { key, static_cast<double>(c.Particles), c.Mass, c.Volume, c.Area, c.Weight, c.Moment[0],
      c.Moment[1], c.Moment[2], c.Reference[0], c.Reference[1], c.Reference[2],
      c.Inside ? 1.0 : 0.0, c.Circular[0], c.Circular[1], c.Circular[2], c.Circular[3],
      c.Circular[4], c.Circular[5] });
  out.insert(out.end(), c.Means.begin(), c.Means.end());
}

double FindJoined(std::map<double, double>& parent, double key)
{
  auto it = parent.find(key);
  if (it == parent.end())
  {
    parent[key] = key;
    return key;
  }
  while (parent[key] != key)
  {
    key = parent[key] = parent[parent[key]];
  }
  return key;
}

std::map<double, double> JoinedLinks(const Communicator& ranks, std::vector<double>& links)
{
  ranks.GatherAll(links);
  std::map<double, double> joined;
  for (std::size_t k = 0; k + 1 < links.size(); k += 2)
  {
    const double a = FindJoined(joined, links[k]), b = FindJoined(joined, links[k + 1]);
    if (a != b)
    {
      joined[std::max(a, b)] = std::min(a, b);
    }
  }
  return joined;
}

Sums Unpack(const double* in, std::size_t means)
{
  Sums c;
  c.Particles = static_cast<vtkIdType>(in[1]);
  c.Mass = in[2];
  c.Volume = in[3];
  c.Area = in[4];
  c.Weight = in[5];
  std::copy(in + 6, in + 9, c.Moment);
  std::copy(in + 9, in + 12, c.Reference);
  c.Inside = in[12] > 0.0;
  std::copy(in + 13, in + 19, c.Circular);
  c.HasReference = true;
  c.Means.assign(in + FixedFields, in + FixedFields + means);
  return c;
}

namespace
{
// A particle's mass, volume, part inside (the step) and the step's derivative.
struct Measures
{
  double Mass = 0.0, Volume = 0.0, Step = 0.0, StepDerivative = 0.0;
};

// From a particle's record (ReadParticle's: mass, density, then the averaged arrays' values).
Measures MeasuresOf(
  const EnclosedInputs& in, const double* record, std::size_t i, double signedDistance)
{
  const Neighborhoods& geometry = *in.Geometry;
  const double s = geometry.RadiusOf(i); // the shell's half width
  Measures m;
  m.Step = Step(signedDistance, s);
  m.StepDerivative = StepDerivative(signedDistance, s);
  m.Mass = record[0];
  const double rho = record[1];
  const double radius = geometry.RadiusOf(i);
  const int neighbors = geometry.Stride - 1;
  m.Volume = in.Mass && in.Density && rho > 0.0
    ? m.Mass / rho
    : 4.0 / 3.0 * Pi * radius * radius * radius / neighbors;
  return m;
}

double WeightOf(const EnclosedInputs& in, const Measures& m)
{
  return (in.Mass ? m.Mass : m.Volume) * m.Step;
}
} // namespace

void ReadParticle(
  const EnclosedInputs& in, const std::vector<vtkDataArray*>& arrays, vtkIdType p, double* record)
{
  record[0] = record[1] = 0.0;
  if (in.Mass)
  {
    in.Mass->GetTuple(p, &record[0]);
  }
  if (in.Density)
  {
    in.Density->GetTuple(p, &record[1]);
  }
  double* values = record + 2;
  for (vtkDataArray* array : arrays)
  {
    array->GetTuple(p, values);
    values += array->GetNumberOfComponents();
  }
}

double CentreWeight(const EnclosedInputs& in, vtkIdType p, std::size_t i, double signedDistance)
{
  double record[2];
  ReadParticle(in, std::vector<vtkDataArray*>(), p, record);
  return WeightOf(in, MeasuresOf(in, record, i, signedDistance));
}

void CircularMean(const PeriodicBox& box, const double circular[6], double mean[3])
{
  for (int d = 0; d < 3; ++d)
  {
    double turn = std::atan2(circular[2 * d + 1], circular[2 * d]) / (2.0 * Pi); // (-1/2, 1/2]
    turn -= std::floor(turn);
    mean[d] = box.Origin[d] + box.Size[d] * turn;
  }
}

void AddParticle(const EnclosedInputs& in, const std::vector<vtkDataArray*>& arrays, int components,
  vtkIdType p, std::size_t i, double signedDistance, std::vector<double>& tuple, Sums& c)
{
  tuple.resize(RecordSize(components));
  ReadParticle(in, arrays, p, tuple.data());
  AddRecord(in, tuple.data(), components, i, signedDistance, c);
}

void AddRecord(const EnclosedInputs& in, const double* record, int components, std::size_t i,
  double signedDistance, Sums& c)
{
  const Neighborhoods& geometry = *in.Geometry;
  const std::vector<double>& phi = *in.Phi;
  const Measures m = MeasuresOf(in, record, i, signedDistance);
  c.Inside = c.Inside || phi[i] > 0.0;
  c.Particles += phi[i] > 0.0 ? 1 : 0;
  c.Mass += m.Mass * m.Step;
  c.Volume += m.Volume * m.Step;
  c.Area += m.Volume * m.StepDerivative;
  const double weight = WeightOf(in, m);
  c.Weight += weight;
  const double* x = geometry.Position(i);
  if (!c.HasReference)
  {
    std::copy(x, x + 3, c.Reference);
    c.HasReference = true;
    c.Means.assign(static_cast<std::size_t>(components), 0.0);
  }
  if (in.Box.Enabled)
  {
    for (int d = 0; d < 3; ++d)
    {
      const double angle = 2.0 * Pi * (x[d] - in.Box.Origin[d]) / in.Box.Size[d];
      c.Circular[2 * d] += weight * std::cos(angle);
      c.Circular[2 * d + 1] += weight * std::sin(angle);
    }
  }
  for (int d = 0; d < 3; ++d)
  {
    c.Moment[d] += weight * (x[d] - c.Reference[d]);
  }
  for (int k = 0; k < components; ++k)
  {
    c.Means[k] += weight * record[2 + k];
  }
}

std::vector<vtkDataArray*> ArraysToAverage(const EnclosedInputs& in, int& components)
{
  vtkPointData* data = in.Particles->GetPointData();
  std::vector<vtkDataArray*> arrays;
  components = 0;
  for (int a = 0; a < data->GetNumberOfArrays(); ++a)
  {
    vtkDataArray* array = data->GetArray(a);
    if (array && array->GetName() && array->GetNumberOfTuples() >= in.ParticleCount)
    {
      arrays.push_back(array);
      components += array->GetNumberOfComponents();
    }
  }
  return arrays;
}

SurfaceDistance::SurfaceDistance(const EnclosedInputs& in, double reach)
  : In(in)
{
  if (!in.SurfacePoints || !in.SurfaceNormals || in.SurfacePoints->empty())
  {
    return;
  }
  if (!in.Box.Enabled && in.SurfaceIndex) // the points as they are, and their index
  {
    this->PointData = in.SurfacePoints->data();
    this->NormalData = in.SurfaceNormals->data();
    this->Index = in.SurfaceIndex;
    return;
  }
  // In a periodic box, also the images that reach within `reach` of the box, so that a
  // particle next to a face finds the surface across it.
  const double reaches[3] = { reach, reach, reach };
  for (std::size_t k = 0; k < in.SurfacePoints->size() / 3; ++k)
  {
    const double* x = &(*in.SurfacePoints)[3 * k];
    const double* normal = &(*in.SurfaceNormals)[3 * k];
    auto add = [&](const double* y) {
      this->Points.insert(this->Points.end(), y, y + 3);
      this->Normals.insert(this->Normals.end(), normal, normal + 3);
    };
    if (in.Box.Enabled)
    {
      ForEachPeriodicImage(x, in.Box, reaches, true, add);
    }
    else
    {
      add(x);
    }
  }
  if (!this->Points.empty())
  {
    this->Built.reset(new PointCloudIndex(this->Points.data(), this->Points.size() / 3));
    this->Index = this->Built.get();
    this->PointData = this->Points.data();
    this->NormalData = this->Normals.data();
  }
}

bool SurfaceDistance::MeasuresHeight(std::size_t i) const
{
  return this->Index && MeasuresTangentDistance((*this->In.Phi)[i], this->In.Geometry->RadiusOf(i));
}

double SurfaceDistance::operator()(std::size_t i) const
{
  const double phi = (*this->In.Phi)[i];
  if (!this->MeasuresHeight(i))
  {
    return phi;
  }
  const double reach = TangentReach * this->In.Geometry->RadiusOf(i); // (s: the shell's half width)
  std::uint32_t nearest;
  double d2;
  // (Searched within the reach used below, and a little more for the rounding of the root: a
  // point beyond it is not used, and the walk prunes sooner.)
  if (this->Index->NearestWithin(
        this->In.Geometry->Position(i), 1, reach * reach * (1.0 + 1e-9), &nearest, &d2) == 0)
  {
    return phi;
  }
  return this->Height(i, phi, nearest, d2);
}

double SurfaceDistance::Height(std::size_t i, double phi, std::uint32_t nearest, double d2) const
{
  const double reach = TangentReach * this->In.Geometry->RadiusOf(i);
  if (!(d2 < reach * reach * (1.0 + 1e-9)))
  {
    return phi; // (none within operator()'s search)
  }
  const double* x = this->In.Geometry->Position(i);
  double height = 0.0;
  for (int d = 0; d < 3; ++d)
  {
    height -= (x[d] - this->PointData[3 * nearest + d]) * this->NormalData[3 * nearest + d];
  }
  // The tangent plane only holds near its point; beyond, phi's sign decides.
  return std::sqrt(d2) < reach ? height : phi;
}

double SurfaceDistance::Keeping(std::size_t i, std::size_t q, KeptCandidates& keep) const
{
  const double phi = (*this->In.Phi)[i];
  if (!this->MeasuresHeight(i))
  {
    return phi;
  }
  // The nearest without a bound finds what the bounded search does first (the same walk,
  // the same first among equals).
  std::uint32_t ids[Candidates + 1];
  double d2[Candidates + 1];
  const std::size_t found =
    this->Index->Nearest(this->In.Geometry->Position(i), Candidates + 1, ids, d2);
  if (found == Candidates + 1)
  {
    std::copy(ids, ids + Candidates, keep.CandidatesOf(q));
    keep.SetOuter(q, std::sqrt(d2[Candidates]));
  }
  return found ? this->Height(i, phi, ids[0], d2[0]) : phi;
}

double SurfaceDistance::FromKept(std::size_t i, std::size_t q, const KeptCandidates& kept,
  const KeptCandidates::Moves& moves) const
{
  if (!this->MeasuresHeight(i))
  {
    return (*this->In.Phi)[i];
  }
  const double* x = this->In.Geometry->Position(i);
  const double reach = kept.Reach(q, x, moves);
  if (reach > 0.0)
  {
    // The nearest candidate, unless another is as near (a search takes the first it meets).
    const std::uint32_t* ids = kept.CandidatesOf(q);
    double best = HUGE_VAL, second = HUGE_VAL;
    std::uint32_t nearest = 0;
    for (std::size_t j = 0; j < Candidates; ++j)
    {
      const double d2 = PointCloudIndex::SquaredDistance(x, this->Index->Point(ids[j]));
      if (d2 < best)
      {
        second = best;
        best = d2;
        nearest = ids[j];
      }
      else
      {
        second = std::min(second, d2);
      }
    }
    // (StillNearest's margins for the rounding of the distances.)
    if (best < second && std::sqrt(best) * (1.0 + 1e-9) < reach * (1.0 - 1e-9))
    {
      return this->Height(i, (*this->In.Phi)[i], nearest, best);
    }
  }
  return (*this)(i);
}

vtkSmartPointer<vtkTable> TableOfComponents(const std::map<double, Sums>& byKey,
  const std::vector<vtkDataArray*>& arrays, int components, bool withMass)
{
  // Components with an inside particle, the largest volume first (ties: the lowest key).
  std::vector<const Sums*> found;
  for (const auto& entry : byKey)
  {
    if (entry.second.Inside)
    {
      found.push_back(&entry.second);
    }
  }
  std::stable_sort(found.begin(), found.end(),
    [&](const Sums* a, const Sums* b) { return a->Volume > b->Volume; });
  Sums total;
  total.Means.assign(static_cast<std::size_t>(components), 0.0);
  for (const Sums* part : found)
  {
    const Sums& c = *part;
    total.Particles += c.Particles;
    total.Mass += c.Mass;
    total.Volume += c.Volume;
    total.Area += c.Area;
    total.Weight += c.Weight;
    for (int d = 0; d < 3; ++d) // the total's centre: of the components' centres
    {
      total.Moment[d] += c.Moment[d] + c.Weight * c.Reference[d];
    }
    for (int k = 0; k < components; ++k)
    {
      total.Means[k] += c.Means[k];
    }
  }

  auto table = vtkSmartPointer<vtkTable>::New();
  vtkNew<vtkStringArray> name;
  name->SetName("Name");
  vtkNew<vtkIdTypeArray> particles;
  particles->SetName("Particles");
  vtkNew<vtkDoubleArray> mass, volume, area, centre;
  mass->SetName("Mass");
  volume->SetName("Volume");
  area->SetName("SurfaceArea");
  centre->SetName("CenterOfMass");
  centre->SetNumberOfComponents(3);
  std::vector<vtkSmartPointer<vtkDoubleArray>> means;
  for (vtkDataArray* array : arrays)
  {
    auto mean = vtkSmartPointer<vtkDoubleArray>::New();
    mean->SetName((std::string("Mean ") + array->GetName()).c_str());
    mean->SetNumberOfComponents(array->GetNumberOfComponents());
    means.push_back(mean);
  }
  auto addRow = [&](const std::string& label, const Sums& c, bool relative) {
    name->InsertNextValue(label);
    particles->InsertNextValue(c.Particles);
    mass->InsertNextValue(c.Mass);
    volume->InsertNextValue(c.Volume);
    area->InsertNextValue(c.Area);
    double com[3];
    for (int d = 0; d < 3; ++d)
    {
      com[d] = c.Weight > 0.0 ? (relative ? c.Reference[d] : 0.0) + c.Moment[d] / c.Weight : 0.0;
    }
    centre->InsertNextTuple(com);
    int k = 0;
    for (auto& mean : means)
    {
      std::vector<double> tuple(mean->GetNumberOfComponents());
      for (double& value : tuple)
      {
        value = c.Weight > 0.0 ? c.Means[k] / c.Weight : 0.0;
        ++k;
      }
      mean->InsertNextTuple(tuple.data());
    }
  };
  for (std::size_t r = 0; r < found.size(); ++r)
  {
    addRow("Component " + std::to_string(r + 1), *found[r], true);
  }
  addRow("Total", total, false);
  table->AddColumn(name);
  table->AddColumn(particles);
  if (withMass)
  {
    table->AddColumn(mass);
  }
  table->AddColumn(volume);
  table->AddColumn(area);
  table->AddColumn(centre);
  for (auto& mean : means)
  {
    table->AddColumn(mean);
  }
  return table;
}

} // namespace enclosed
} // namespace lsi
