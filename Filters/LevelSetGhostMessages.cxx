// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "LevelSetGhostMessages.h"

#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkPointData.h"
#include "vtkPointSet.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"

#include <cstdint>
#include <cstring>

namespace lsi
{

namespace
{

// Whether a point array travels as bytes: numeric, named, whole bytes per value (not bits).
// The others (strings, bits) keep their default on the ghosts; nothing interpolates them.
bool Travels(vtkAbstractArray* array)
{
  auto* numbers = vtkDataArray::SafeDownCast(array);
  return numbers && numbers->GetName() && numbers->GetDataType() != VTK_BIT &&
    numbers->GetDataTypeSize() > 0;
}

// `array` with the standard (array of structures) memory layout: itself, or a copy.
vtkSmartPointer<vtkDataArray> Contiguous(vtkDataArray* array)
{
  if (array->HasStandardMemoryLayout())
  {
    return array;
  }
  auto copy = vtk::TakeSmartPointer(vtkDataArray::CreateDataArray(array->GetDataType()));
  copy->SetName(array->GetName());
  copy->SetNumberOfComponents(array->GetNumberOfComponents());
  copy->SetNumberOfTuples(array->GetNumberOfTuples());
  copy->InsertTuples(0, array->GetNumberOfTuples(), 0, array);
  return copy;
}

void Append(std::vector<char>& message, const void* bytes, std::size_t count)
{
  const char* from = static_cast<const char*>(bytes);
  message.insert(message.end(), from, from + count);
}

template <typename T>
void AppendValue(std::vector<char>& message, T value)
{
  Append(message, &value, sizeof(T));
}

// Reads a message front to back; every read checks that the bytes are there.
struct Cursor
{
  const std::vector<char>& Message;
  std::size_t At = 0;

  bool Take(void* to, std::size_t count)
  {
    if (count > this->Message.size() - this->At)
    {
      return false;
    }
    if (to && count > 0)
    {
      std::memcpy(to, this->Message.data() + this->At, count);
    }
    this->At += count;
    return true;
  }
  template <typename T>
  bool TakeValue(T& value)
  {
    return this->Take(&value, sizeof(T));
  }
};

} // namespace

std::vector<char> GhostMessage(
  vtkPointSet* owned, const std::vector<double>& values, const std::vector<vtkIdType>& ids)
{
  const std::size_t count = ids.size();
  std::vector<vtkSmartPointer<vtkDataArray>> arrays;
  vtkPointData* pointData = owned->GetPointData();
  for (int a = 0; a < pointData->GetNumberOfArrays(); ++a)
  {
    if (Travels(pointData->GetAbstractArray(a)))
    {
      arrays.push_back(Contiguous(pointData->GetArray(a)));
    }
  }
  std::vector<char> message;
  AppendValue<std::uint64_t>(message, count);
  AppendValue<std::uint32_t>(message, static_cast<std::uint32_t>(arrays.size()));
  std::size_t arrayBytes = 0;
  for (const auto& array : arrays)
  {
    const std::string name = array->GetName();
    AppendValue<std::uint32_t>(message, static_cast<std::uint32_t>(name.size()));
    Append(message, name.data(), name.size());
    AppendValue<std::int32_t>(message, array->GetDataType());
    AppendValue<std::int32_t>(message, array->GetNumberOfComponents());
    arrayBytes += count * array->GetNumberOfComponents() * array->GetDataTypeSize();
  }
  message.reserve(message.size() + count * 4 * sizeof(double) + arrayBytes);
  for (const vtkIdType id : ids)
  {
    double x[3];
    owned->GetPoint(id, x);
    Append(message, x, sizeof(x));
  }
  for (const vtkIdType id : ids)
  {
    AppendValue<double>(message, values[static_cast<std::size_t>(id)]);
  }
  for (const auto& array : arrays)
  {
    const std::size_t tupleBytes =
      static_cast<std::size_t>(array->GetNumberOfComponents()) * array->GetDataTypeSize();
    const char* bytes = static_cast<const char*>(array->GetVoidPointer(0));
    for (const vtkIdType id : ids)
    {
      Append(message, bytes + static_cast<std::size_t>(id) * tupleBytes, tupleBytes);
    }
  }
  return message;
}

vtkSmartPointer<vtkPolyData> WithRoomForGhosts(vtkPointSet* owned, vtkIdType total)
{
  auto all = vtkSmartPointer<vtkPolyData>::New();
  const vtkIdType n = owned->GetNumberOfPoints();
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(total);
  auto* xyz = vtkDoubleArray::SafeDownCast(points->GetData());
  std::fill(xyz->GetPointer(0), xyz->GetPointer(0) + 3 * total, 0.0);
  if (n > 0)
  {
    xyz->InsertTuples(0, n, 0, owned->GetPoints()->GetData());
  }
  all->SetPoints(points);
  vtkPointData* from = owned->GetPointData();
  for (int a = 0; a < from->GetNumberOfArrays(); ++a)
  {
    vtkAbstractArray* array = from->GetAbstractArray(a);
    if (!array || !array->GetName())
    {
      continue;
    }
    vtkSmartPointer<vtkAbstractArray> joined = Travels(array)
      ? vtk::TakeSmartPointer<vtkAbstractArray>(vtkDataArray::CreateDataArray(array->GetDataType()))
      : vtk::TakeSmartPointer(array->NewInstance());
    joined->SetName(array->GetName());
    joined->SetNumberOfComponents(array->GetNumberOfComponents());
    joined->SetNumberOfTuples(total);
    if (auto* numbers = vtkDataArray::SafeDownCast(joined))
    {
      numbers->Fill(0.0);
    }
    if (n > 0)
    {
      joined->InsertTuples(0, n, 0, array);
    }
    all->GetPointData()->AddArray(joined);
  }
  all->GetFieldData()->ShallowCopy(owned->GetFieldData());
  return all;
}

bool ReadGhostMessage(const std::vector<char>& message, vtkPolyData* all, vtkIdType at,
  std::vector<double>& values, std::string& problem)
{
  problem = "a malformed ghost message";
  Cursor cursor{ message };
  std::uint64_t count = 0;
  std::uint32_t arrayCount = 0;
  if (!cursor.TakeValue(count) || !cursor.TakeValue(arrayCount))
  {
    return false;
  }
  const std::uint64_t room =
    static_cast<std::uint64_t>(std::max<vtkIdType>(all->GetNumberOfPoints() - at, 0));
  if (at < 0 || count > room || values.size() < static_cast<std::size_t>(at + count))
  {
    problem = "a ghost message with more samples than were announced";
    return false;
  }
  struct Layout
  {
    std::string Name;
    std::int32_t Type = 0;
    std::int32_t Components = 0;
  };
  std::vector<Layout> layouts(arrayCount);
  for (Layout& layout : layouts)
  {
    std::uint32_t length = 0;
    if (!cursor.TakeValue(length) || length > message.size())
    {
      return false;
    }
    layout.Name.resize(length);
    if (!cursor.Take(&layout.Name[0], length) || !cursor.TakeValue(layout.Type) ||
      !cursor.TakeValue(layout.Components) || layout.Components <= 0)
    {
      return false;
    }
  }
  auto* xyz = vtkDoubleArray::SafeDownCast(all->GetPoints()->GetData());
  if (!cursor.Take(xyz->GetPointer(3 * at), count * 3 * sizeof(double)) ||
    !cursor.Take(values.data() + at, count * sizeof(double)))
  {
    return false;
  }
  for (const Layout& layout : layouts)
  {
    auto* into =
      vtkDataArray::SafeDownCast(all->GetPointData()->GetAbstractArray(layout.Name.c_str()));
    const bool matches = into && into->GetDataType() == layout.Type &&
      into->GetNumberOfComponents() == layout.Components && into->HasStandardMemoryLayout();
    std::size_t typeSize = matches ? static_cast<std::size_t>(into->GetDataTypeSize()) : 0;
    if (!matches)
    {
      // Not one of this rank's arrays: skipped, its size from a scratch array of its type.
      auto scratch = vtk::TakeSmartPointer(vtkDataArray::CreateDataArray(layout.Type));
      if (!scratch || scratch->GetDataTypeSize() <= 0)
      {
        return false;
      }
      typeSize = static_cast<std::size_t>(scratch->GetDataTypeSize());
    }
    const std::size_t bytes = count * static_cast<std::size_t>(layout.Components) * typeSize;
    void* to = matches ? into->GetVoidPointer(at * layout.Components) : nullptr;
    if (!cursor.Take(to, bytes))
    {
      return false;
    }
  }
  if (cursor.At != message.size())
  {
    return false;
  }
  problem.clear();
  return true;
}

} // namespace lsi
