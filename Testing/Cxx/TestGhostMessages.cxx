// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
// The message in which ghosts travel between ranks (LevelSetGhostMessages.h), without MPI: a
// rank's samples (float points; a double, a two-component int, a split-layout (SOA) float and a
// string array) packed for chosen ids and read into another rank's room for ghosts:
//   - the owned part of the receiver is its input, every value and array tuple to the bit;
//   - each ghost carries its sender's position, value and tuples of the arrays both ranks have
//     (same name, type and components); an array only the receiver has stays zero on ghosts, one
//     only the sender has is skipped, one with other components too;
//   - truncated, lengthened or over-long messages are refused with a reason, never read past.
#include "LevelSetGhostMessages.h"
#include "TestCheck.h"

#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSOADataArrayTemplate.h"
#include "vtkStringArray.h"

#include <iostream>
#include <string>
#include <vector>

namespace
{
using lsi::test::Check;

// A rank's particles: point i at (i, 2i, 3i) / 7 (floats), Masses 10 + i, Pair (i, -i),
// Split (SOA, 3 components) i + c / 4, Names "p<i>"; `extra` adds an array only it has and a
// Pair of 3 components in place of 2 when `otherPair`.
vtkNew<vtkPolyData> Rank(int count, int offset, bool extra, bool otherPair)
{
  vtkNew<vtkPolyData> rank;
  vtkNew<vtkPoints> points;
  points->SetDataTypeToFloat();
  vtkNew<vtkDoubleArray> masses;
  masses->SetName("Masses");
  vtkNew<vtkIntArray> pair;
  pair->SetName("Pair");
  pair->SetNumberOfComponents(otherPair ? 3 : 2);
  vtkNew<vtkSOADataArrayTemplate<float>> split;
  split->SetName("Split");
  split->SetNumberOfComponents(3);
  split->SetNumberOfTuples(count);
  vtkNew<vtkStringArray> names;
  names->SetName("Names");
  vtkNew<vtkDoubleArray> only;
  only->SetName(extra ? "SenderOnly" : "ReceiverOnly");
  for (int k = 0; k < count; ++k)
  {
    const int i = k + offset;
    points->InsertNextPoint(i / 7.0, 2 * i / 7.0, 3 * i / 7.0);
    masses->InsertNextValue(10.0 + i);
    pair->InsertNextValue(i);
    pair->InsertNextValue(-i);
    if (otherPair)
    {
      pair->InsertNextValue(0);
    }
    for (int c = 0; c < 3; ++c)
    {
      split->SetTypedComponent(k, c, static_cast<float>(i + c / 4.0));
    }
    names->InsertNextValue("p" + std::to_string(i));
    only->InsertNextValue(-1.0 - i);
  }
  rank->SetPoints(points);
  rank->GetPointData()->AddArray(masses);
  rank->GetPointData()->AddArray(pair);
  rank->GetPointData()->AddArray(split);
  rank->GetPointData()->AddArray(names);
  rank->GetPointData()->AddArray(only);
  return rank;
}

void CheckRoundTrip()
{
  const int owned = 20, sent = 30;
  vtkNew<vtkPolyData> receiver = Rank(owned, 0, false, false);
  vtkNew<vtkPolyData> sender = Rank(sent, 100, true, false);
  const std::vector<vtkIdType> ids = { 29, 0, 7, 7, 12 };
  std::vector<double> senderValues(sent);
  for (int k = 0; k < sent; ++k)
  {
    senderValues[k] = 0.5 * k - 3.0;
  }
  const std::vector<char> message = lsi::GhostMessage(sender, senderValues, ids);
  const vtkIdType total = owned + static_cast<vtkIdType>(ids.size()) + 2; // 2 from elsewhere
  vtkSmartPointer<vtkPolyData> all = lsi::WithRoomForGhosts(receiver, total);
  Check(all->GetNumberOfPoints() == total, "room for every ghost");
  std::vector<double> values(static_cast<std::size_t>(total), 99.0);
  std::string problem;
  const vtkIdType at = owned + 2;
  Check(lsi::ReadGhostMessage(message, all, at, values, problem), "the message is read");
  Check(problem.empty(), "no problem said for a good message");

  vtkPointData* arrays = all->GetPointData();
  vtkDataArray* masses = arrays->GetArray("Masses");
  vtkDataArray* pair = arrays->GetArray("Pair");
  vtkDataArray* split = arrays->GetArray("Split");
  vtkDataArray* receiverOnly = arrays->GetArray("ReceiverOnly");
  auto* names = vtkStringArray::SafeDownCast(arrays->GetAbstractArray("Names"));
  Check(masses && pair && split && receiverOnly && names, "the receiver's arrays are all there");
  Check(!arrays->GetAbstractArray("SenderOnly"), "an array only the sender has is not added");
  if (!(masses && pair && split && receiverOnly && names))
  {
    return;
  }
  Check(pair->GetDataType() == VTK_INT && split->GetDataType() == VTK_FLOAT,
    "the arrays keep their types");
  int wrong = 0;
  for (vtkIdType i = 0; i < owned; ++i)
  {
    double x[3];
    all->GetPoint(i, x);
    wrong += x[0] != static_cast<float>(i / 7.0) || x[2] != static_cast<float>(3 * i / 7.0);
    wrong += masses->GetComponent(i, 0) != 10.0 + i || pair->GetComponent(i, 1) != -i;
    wrong += split->GetComponent(i, 2) != static_cast<float>(i + 0.5);
    wrong += receiverOnly->GetComponent(i, 0) != -1.0 - i;
    wrong += names->GetValue(i) != "p" + std::to_string(i);
  }
  Check(wrong == 0, "the owned part is the receiver's input (" + std::to_string(wrong) + " off)");
  wrong = 0;
  for (std::size_t k = 0; k < ids.size(); ++k)
  {
    const vtkIdType g = at + static_cast<vtkIdType>(k);
    const int i = static_cast<int>(ids[k]) + 100;
    double x[3];
    all->GetPoint(g, x);
    wrong += x[1] != static_cast<float>(2 * i / 7.0);
    wrong += values[static_cast<std::size_t>(g)] != senderValues[static_cast<std::size_t>(ids[k])];
    wrong += masses->GetComponent(g, 0) != 10.0 + i;
    wrong += pair->GetComponent(g, 0) != i || pair->GetComponent(g, 1) != -i;
    wrong += split->GetComponent(g, 1) != static_cast<float>(i + 0.25);
    wrong += receiverOnly->GetComponent(g, 0) != 0.0;
  }
  Check(wrong == 0, "each ghost carries its sender's values (" + std::to_string(wrong) + " off)");
  // The room not filled by this message: still zeros, its values untouched.
  double x[3];
  all->GetPoint(owned, x);
  Check(x[0] == 0.0 && masses->GetComponent(owned + 1, 0) == 0.0 && values[owned] == 99.0,
    "room for other messages left as it was");

  // An array whose components differ is skipped, the rest read.
  vtkNew<vtkPolyData> odd = Rank(sent, 100, false, true);
  const std::vector<char> oddMessage = lsi::GhostMessage(odd, senderValues, ids);
  Check(lsi::ReadGhostMessage(oddMessage, all, at, values, problem),
    "a message with an array of other components is read");
  Check(pair->GetComponent(at, 0) == 129 && masses->GetComponent(at, 0) == 129 + 10.0,
    "its other arrays are read, the odd one left");

  // Broken messages: every one refused with a reason.
  std::vector<char> shorter(message.begin(), message.end() - 1);
  std::vector<char> longer = message;
  longer.push_back(0);
  std::vector<char> header(message.begin(), message.begin() + 6);
  const std::vector<std::vector<char>> broken = { shorter, longer, header, {} };
  for (const auto& bad : broken)
  {
    problem.clear();
    Check(!lsi::ReadGhostMessage(bad, all, at, values, problem) && !problem.empty(),
      "a broken message of " + std::to_string(bad.size()) + " bytes is refused");
  }
  Check(!lsi::ReadGhostMessage(message, all, total - 2, values, problem) && !problem.empty(),
    "a message with more samples than its room is refused");
}

void CheckEmpty()
{
  vtkNew<vtkPolyData> nothing;
  vtkNew<vtkPoints> points;
  nothing->SetPoints(points);
  vtkNew<vtkPolyData> sender = Rank(5, 0, false, false);
  const std::vector<double> values(5, 1.0);
  const std::vector<char> message = lsi::GhostMessage(sender, values, { 4, 3 });
  vtkSmartPointer<vtkPolyData> all = lsi::WithRoomForGhosts(nothing, 2);
  std::vector<double> into(2, 0.0);
  std::string problem;
  Check(lsi::ReadGhostMessage(message, all, 0, into, problem), "an empty rank receives ghosts");
  Check(all->GetPoint(1)[0] == static_cast<float>(3 / 7.0) && into[0] == 1.0,
    "an empty rank's ghosts have their positions and values");
}
} // namespace

int main()
{
  CheckRoundTrip();
  CheckEmpty();
  std::cout << (lsi::test::Failures() ? "ghost message tests FAILED\n"
                                      : "ghost message tests passed\n");
  return lsi::test::Failures() ? 1 : 0;
}
