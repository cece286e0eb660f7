// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
// vtkParticleSnapshotReader's regions (ReadRegion, RegionBounds): the candidates a format can
// name, this rank's share of them, read a chunk at a time and cut to the box.
#include "vtkParticleSnapshotReader.h"

#include "ParticleRanges.h"
#include "PeriodicRegion.h"

#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkIdList.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkVariant.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace
{
// Appends the particles of `chunk` inside `bounds` (wrapped with `period`, per axis; 0: not) to
// `points` and `pointData` (allocated with the chunk's arrays). False if the chunk lacks one of
// them or has it in another shape.
bool AppendInside(vtkPolyData* chunk, const double bounds[6], const double period[3],
  vtkPoints* points, vtkPointData* pointData)
{
  vtkNew<vtkIdList> inside;
  for (vtkIdType i = 0; i < chunk->GetNumberOfPoints(); ++i)
  {
    double x[3];
    chunk->GetPoint(i, x);
    if (lsi::io::InsidePeriodicRegion(x, bounds, period))
    {
      inside->InsertNextId(i);
    }
  }
  if (inside->GetNumberOfIds() == 0)
  {
    return true; // (VTK 9.2's InsertTuplesStartingAt reads the first id of an empty list)
  }
  const vtkIdType at = points->GetNumberOfPoints();
  points->GetData()->InsertTuplesStartingAt(at, inside, chunk->GetPoints()->GetData());
  for (int a = 0; a < pointData->GetNumberOfArrays(); ++a)
  {
    vtkAbstractArray* target = pointData->GetAbstractArray(a);
    vtkAbstractArray* source = chunk->GetPointData()->GetAbstractArray(target->GetName());
    if (!source || source->GetNumberOfComponents() != target->GetNumberOfComponents())
    {
      return false;
    }
    target->InsertTuplesStartingAt(at, inside, source);
  }
  return true;
}
} // namespace

std::string vtkParticleSnapshotReader::RegionBoundsText() const
{
  std::ostringstream text;
  text << "(";
  for (int k = 0; k < 6; ++k)
  {
    text << (k ? ", " : "") << this->RegionBounds[k];
  }
  text << ")";
  return text.str();
}

void vtkParticleSnapshotReader::RegionPeriod(double period[3]) const
{
  period[0] = period[1] = period[2] = 0.0;
  // One value (GADGET) or three (SWIFT, AREPO), as values of one array: as
  // vtkLevelSetIsosurface reads it. A size not positive (GADGET's 0: no box) wraps nothing.
  vtkDataArray* box = vtkDataArray::SafeDownCast(this->Fields->GetAbstractArray("BoxSize"));
  const vtkIdType values = box ? box->GetNumberOfValues() : 0;
  for (int a = 0; a < 3 && this->PeriodicRegion && values > 0; ++a)
  {
    const double size = box->GetVariantValue(values >= 3 ? a : 0).ToDouble();
    period[a] = size > 0.0 && std::isfinite(size) ? size : 0.0;
  }
}

void vtkParticleSnapshotReader::AddRegionFields(vtkFieldData* fields) const
{
  double period[3];
  this->RegionPeriod(period);
  vtkNew<vtkDoubleArray> bounds, periods;
  bounds->SetName("RegionBounds");
  periods->SetName("RegionPeriod");
  for (double b : this->RegionBounds)
  {
    bounds->InsertNextValue(b);
  }
  for (double p : period)
  {
    periods->InsertNextValue(p);
  }
  fields->AddArray(bounds);
  fields->AddArray(periods);
}

bool vtkParticleSnapshotReader::RegionCandidates(std::size_t type, const double*,
  std::vector<std::pair<long long, long long>>& ranges, std::string&)
{
  ranges.assign(1, { 0, this->Types[type].Count });
  return true;
}

bool vtkParticleSnapshotReader::ReadShareInRegion(
  std::size_t type, int piece, int pieces, vtkPolyData* particles, std::string& problem)
{
  // In a periodic box, the candidates of each of the region's shifts by whole boxes.
  double period[3];
  this->RegionPeriod(period);
  std::vector<lsi::io::Range> candidates;
  for (const auto& box : lsi::io::PeriodicRegionBoxes(this->RegionBounds, period))
  {
    std::vector<lsi::io::Range> ofBox;
    if (!this->RegionCandidates(type, box.data(), ofBox, problem))
    {
      return false;
    }
    candidates.insert(candidates.end(), ofBox.begin(), ofBox.end());
  }
  const long long count = this->Types[type].Count;
  for (lsi::io::Range& r : candidates) // (a damaged cell table must not send reads elsewhere)
  {
    r = { std::max(0LL, r.first), std::min(count, r.second) };
  }
  const std::vector<lsi::io::Range> share =
    lsi::io::ShareOfRanges(lsi::io::MergedRanges(candidates), piece, pieces);
  // Chunk by chunk: read, keep the particles inside the box, append them; progress and abort
  // after each chunk.
  const double shareCount = static_cast<double>(lsi::io::CountOf(share));
  long long done = 0;
  vtkNew<vtkPoints> points;
  bool first = true;
  for (const lsi::io::Range& r : share)
  {
    for (long long begin = r.first; begin < r.second; begin += this->RegionChunkParticles)
    {
      const long long end = std::min<long long>(r.second, begin + this->RegionChunkParticles);
      vtkNew<vtkPolyData> chunk;
      if (!this->ReadParticles(type, begin, end, chunk, problem))
      {
        return false;
      }
      this->ParticlesScanned += end - begin;
      if (first) // the arrays, their attributes (global ids, scalars) and the SPH markers
      {
        points->SetDataType(chunk->GetPoints()->GetDataType());
        particles->GetPointData()->CopyGlobalIdsOn(); // (off by default in VTK)
        particles->GetPointData()->CopyAllocate(chunk->GetPointData(), 0);
        particles->GetFieldData()->PassData(chunk->GetFieldData());
        first = false;
      }
      if (!AppendInside(chunk, this->RegionBounds, period, points, particles->GetPointData()))
      {
        problem = "particles " + std::to_string(begin) + " to " + std::to_string(end) +
          " do not have the arrays of the particles before them";
        return false;
      }
      done += end - begin;
      this->UpdateProgress(
        this->ProgressFrom + (this->ProgressTo - this->ProgressFrom) * done / shareCount);
      if (this->CheckAbort())
      {
        return true; // (RequestData empties the output)
      }
    }
  }
  particles->SetPoints(points);
  return true;
}
