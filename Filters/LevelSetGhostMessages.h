// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
// The message in which a rank's samples travel to another rank as ghosts
// (Distribution::WithGhosts): their positions, their values f and the bytes of each numeric
// point array, behind a short catalogue of the arrays (name, VTK type, components). Raw bytes
// rather than a vtkPolyData sent whole: VTK marshals a data set through its legacy writer, a
// copy and a parse of every value.
#ifndef LevelSetGhostMessages_h
#define LevelSetGhostMessages_h

#include "vtkSmartPointer.h"
#include "vtkType.h"

#include <string>
#include <vector>

class vtkPointSet;
class vtkPolyData;

namespace lsi
{

/// The samples `ids` of `owned`, with their values (values[id]), as one message.
std::vector<char> GhostMessage(
  vtkPointSet* owned, const std::vector<double>& values, const std::vector<vtkIdType>& ids);

/// `owned`'s points and point arrays (field data too) in a vtkPolyData of `total` points: the
/// owned ones first, room for the ghosts after them (zeros until ReadGhostMessage fills them).
vtkSmartPointer<vtkPolyData> WithRoomForGhosts(vtkPointSet* owned, vtkIdType total);

/// Puts a GhostMessage's samples into `all` from point `at` on (their values into values[at..]):
/// each array the message carries goes into `all`'s array of the same name, type and
/// components; others stay zero. False, with `problem` said, when the message is malformed or
/// holds more samples than `all` has room for.
bool ReadGhostMessage(const std::vector<char>& message, vtkPolyData* all, vtkIdType at,
  std::vector<double>& values, std::string& problem);

} // namespace lsi

#endif
