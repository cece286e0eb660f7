// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
// The readers' tests of their point array selection: the arrays listed, and a read of some of
// them alone giving exactly those arrays, with the values and positions of a read of all.
#ifndef PointArraySelection_h
#define PointArraySelection_h

#include "SameParticles.h"
#include "TestCheck.h"

#include "vtkDataArray.h"
#include "vtkDataArraySelection.h"
#include "vtkFieldData.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkStringArray.h"

#include <numeric>
#include <set>
#include <string>
#include <vector>

namespace lsi
{
namespace test
{
inline std::string Joined(const std::set<std::string>& names)
{
  std::string joined;
  for (const std::string& name : names)
  {
    joined += (joined.empty() ? "" : " ") + name;
  }
  return joined;
}

/// Whether `b` holds `a`'s positions and, for every array of `b`, `a`'s values, exactly.
inline bool SameValues(vtkPolyData* a, vtkPolyData* b)
{
  std::vector<vtkIdType> every(static_cast<std::size_t>(a->GetNumberOfPoints()));
  std::iota(every.begin(), every.end(), vtkIdType(0));
  return a->GetNumberOfPoints() == b->GetNumberOfPoints() && SameParticles(a, every, 0, b);
}

/// Whether every array the SPH markers name (DensityArray, SmoothingLengthArray, MassArray) is
/// in `data`, and the active scalars are the marked density (or none without one).
inline bool MarkersNameReadArrays(vtkPolyData* data)
{
  vtkFieldData* fields = data->GetFieldData();
  for (const char* marker : { "DensityArray", "SmoothingLengthArray", "MassArray" })
  {
    auto* name = vtkStringArray::SafeDownCast(fields->GetAbstractArray(marker));
    if (name && !data->GetPointData()->GetArray(name->GetValue(0).c_str()))
    {
      return false;
    }
  }
  auto* density = vtkStringArray::SafeDownCast(fields->GetAbstractArray("DensityArray"));
  vtkDataArray* scalars = data->GetPointData()->GetScalars();
  return density ? scalars && density->GetValue(0) == scalars->GetName() : !scalars;
}

/// `reader` (file set, one particle type selected) lists `listed` as its point arrays; reading
/// `keep` alone gives those arrays (`keep` may name the global ids' array), with the values of
/// a read of all of them, and SPH markers only for arrays read. Leaves every array selected.
template <typename Reader>
void CheckPointArraySelection(Reader* reader, const std::set<std::string>& listed,
  const std::set<std::string>& keep, const std::string& what)
{
  reader->UpdateInformation();
  std::set<std::string> names;
  for (int a = 0; a < reader->GetNumberOfPointArrays(); ++a)
  {
    names.insert(reader->GetPointArrayName(a));
    Check(reader->GetPointArrayStatus(reader->GetPointArrayName(a)) == 1,
      what + ": " + reader->GetPointArrayName(a) + " selected by default");
  }
  Check(names == listed,
    what + ": point arrays listed: " + Joined(listed) + " (got " + Joined(names) + ")");
  reader->Update();
  vtkNew<vtkPolyData> all;
  if (auto* output = vtkPolyData::SafeDownCast(reader->GetOutput()))
  {
    all->DeepCopy(output);
  }
  Check(all->GetNumberOfPoints() > 0 && PointArrayNames(all) == listed,
    what + ": all arrays read by default (got " + Joined(PointArrayNames(all)) + ")");
  for (const std::string& name : names)
  {
    reader->SetPointArrayStatus(name.c_str(), keep.count(name) ? 1 : 0);
  }
  reader->Update();
  auto* some = vtkPolyData::SafeDownCast(reader->GetOutput());
  Check(some && PointArrayNames(some) == keep,
    what + ": " + Joined(keep) + " alone read (got " +
      (some ? Joined(PointArrayNames(some)) : std::string("no output")) + ")");
  Check(
    some && SameValues(all, some), what + ": the positions and values of a read of every array");
  Check(some && MarkersNameReadArrays(some),
    what + ": SPH markers and active scalars only for arrays read");
  reader->GetPointArraySelection()->EnableAllArrays();
}
} // namespace test
} // namespace lsi

#endif
