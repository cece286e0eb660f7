// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
// The fingerprint of an array's values (ValueFingerprint), by which a re-run tells values
// changed in place from the last run's:
//   - arrays of every value size (8, 4, 2 and 1 bytes) with the same values, in other objects,
//     have the same fingerprint; one value changed anywhere (first, last, across a block of the
//     parallel hash) changes it;
//   - doubles read from plain memory give the fingerprint that reading them one by one through
//     the array's interface gives (an array of another layout).
#include "LevelSetNeighborCache.h"
#include "TestCheck.h"

#include "vtkCharArray.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkNew.h"
#include "vtkSOADataArrayTemplate.h"
#include "vtkShortArray.h"

#include <iostream>
#include <random>
#include <string>

namespace
{
using lsi::test::Check;

// 200,000 values: several blocks of the hash, and a last block cut short.
constexpr vtkIdType Count = 200000;

template <typename ArrayType>
void CheckChangesSeen(const std::string& type, std::mt19937& random)
{
  std::uniform_int_distribution<int> small(1, 100);
  vtkNew<ArrayType> array, same;
  array->SetNumberOfValues(Count);
  same->SetNumberOfValues(Count);
  for (vtkIdType i = 0; i < Count; ++i)
  {
    const auto value = static_cast<typename ArrayType::ValueType>(small(random));
    array->SetValue(i, value);
    same->SetValue(i, value);
  }
  const std::uint64_t before = lsi::ValueFingerprint(array);
  Check(before == lsi::ValueFingerprint(same), type + ": the same values, the same fingerprint");
  for (const vtkIdType at : { vtkIdType(0), vtkIdType(65535), vtkIdType(65536), Count - 1 })
  {
    const auto kept = array->GetValue(at);
    array->SetValue(at, static_cast<typename ArrayType::ValueType>(kept + 1));
    Check(lsi::ValueFingerprint(array) != before,
      type + ": value " + std::to_string(at) + " changed in place is seen");
    array->SetValue(at, kept);
  }
  Check(lsi::ValueFingerprint(array) == before, type + ": restored values, the same fingerprint");
}
} // namespace

int main()
{
  std::mt19937 random(11);
  CheckChangesSeen<vtkDoubleArray>("double", random);
  CheckChangesSeen<vtkFloatArray>("float", random);
  CheckChangesSeen<vtkShortArray>("short", random);
  CheckChangesSeen<vtkCharArray>("char", random);

  // Three-component doubles in plain memory and in one array per component.
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  vtkNew<vtkDoubleArray> plain;
  vtkNew<vtkSOADataArrayTemplate<double>> split;
  plain->SetNumberOfComponents(3);
  split->SetNumberOfComponents(3);
  plain->SetNumberOfTuples(Count);
  split->SetNumberOfTuples(Count);
  for (vtkIdType t = 0; t < Count; ++t)
  {
    for (int c = 0; c < 3; ++c)
    {
      const double value = unit(random);
      plain->SetComponent(t, c, value);
      split->SetComponent(t, c, value);
    }
  }
  Check(plain->HasStandardMemoryLayout() && !split->HasStandardMemoryLayout(),
    "the two layouts take the two ways");
  Check(lsi::ValueFingerprint(plain) == lsi::ValueFingerprint(split),
    "doubles from plain memory hash as read one by one");

  std::cout << (lsi::test::Failures() ? "fingerprint tests FAILED\n"
                                      : "fingerprint tests passed\n");
  return lsi::test::Failures() ? 1 : 0;
}
