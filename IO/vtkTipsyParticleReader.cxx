// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkTipsyParticleReader.h"

#include "ByteOrder.h"

#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"

#include <cstdint>
#include <cstring>
#include <fstream>
#include <vector>

vtkStandardNewMacro(vtkTipsyParticleReader);

namespace
{
struct TipsyHeader
{
  double Time = 0.0;
  std::int32_t Bodies = 0, Dimensions = 0, Gas = 0, Dark = 0, Stars = 0;
  bool BigEndian = true;
};

using lsi::FromBytes;

bool Plausible(const TipsyHeader& h, std::uint64_t fileSize)
{
  if (h.Gas < 0 || h.Dark < 0 || h.Stars < 0 || h.Dimensions < 1 || h.Dimensions > 3 ||
    static_cast<std::int64_t>(h.Gas) + h.Dark + h.Stars != h.Bodies)
  {
    return false;
  }
  const std::uint64_t needed =
    32 + 48ull * static_cast<std::uint64_t>(h.Gas) + 36ull * h.Dark + 44ull * h.Stars;
  return fileSize >= needed;
}

// Reads and checks the header; tries big-endian (the standard) first, then little-endian.
bool ReadHeader(std::ifstream& file, TipsyHeader& header, std::string& problem)
{
  file.seekg(0, std::ios::end);
  const std::uint64_t size = static_cast<std::uint64_t>(file.tellg());
  file.seekg(0);
  char bytes[32];
  if (size < 32 || !file.read(bytes, 32))
  {
    problem = "shorter than a Tipsy header (32 bytes)";
    return false;
  }
  for (bool big : { true, false })
  {
    TipsyHeader h;
    h.BigEndian = big;
    h.Time = FromBytes<double>(bytes, big);
    h.Bodies = FromBytes<std::int32_t>(bytes + 8, big);
    h.Dimensions = FromBytes<std::int32_t>(bytes + 12, big);
    h.Gas = FromBytes<std::int32_t>(bytes + 16, big);
    h.Dark = FromBytes<std::int32_t>(bytes + 20, big);
    h.Stars = FromBytes<std::int32_t>(bytes + 24, big);
    if (Plausible(h, size))
    {
      header = h;
      return true;
    }
  }
  problem = "not a Tipsy standard file (inconsistent header or truncated particle data)";
  return false;
}
// The three record layouts of a Tipsy standard file, in file order: which float of a record
// holds what (position at 1-3 and velocity at 4-6 in all of them).
struct Layout
{
  const char* TypeName;
  int Floats;
  std::vector<std::pair<const char*, int>> Scalars;
};
const Layout Layouts[3] = {
  { "Gas", 12,
    { { "mass", 0 }, { "rho", 7 }, { "temp", 8 }, { "hsmooth", 9 }, { "metals", 10 },
      { "phi", 11 } } },
  { "DarkMatter", 9, { { "mass", 0 }, { "eps", 7 }, { "phi", 8 } } },
  { "Stars", 11, { { "mass", 0 }, { "metals", 7 }, { "tform", 8 }, { "eps", 9 }, { "phi", 10 } } },
};
} // namespace

vtkTipsyParticleReader::vtkTipsyParticleReader() = default;

bool vtkTipsyParticleReader::CanReadFile(const char* name)
{
  std::ifstream file(name, std::ios::binary);
  TipsyHeader header;
  std::string problem;
  return file && ReadHeader(file, header, problem);
}

bool vtkTipsyParticleReader::ReadMetaData(
  std::vector<ParticleType>& types, double& time, vtkFieldData* fields, std::string& problem)
{
  std::ifstream file(this->FileName, std::ios::binary);
  TipsyHeader header;
  if (!file)
  {
    problem = "cannot open the file";
    return false;
  }
  if (!ReadHeader(file, header, problem))
  {
    return false;
  }
  time = header.Time;
  this->BigEndian = header.BigEndian;
  const long long counts[3] = { header.Gas, header.Dark, header.Stars };
  long long offset = 32;
  this->TypeKinds.clear();
  this->TypeOffsets.clear();
  for (int k = 0; k < 3; ++k)
  {
    if (counts[k] > 0)
    {
      ParticleType type;
      type.Name = Layouts[k].TypeName;
      type.Count = counts[k];
      type.SelectedByDefault = types.empty(); // gas, or the first type there is
      for (const auto& scalar : Layouts[k].Scalars)
      {
        type.Arrays.push_back(scalar.first);
      }
      type.Arrays.push_back("velocity");
      types.push_back(type);
      this->TypeKinds.push_back(k);
      this->TypeOffsets.push_back(offset);
    }
    offset += 4LL * Layouts[k].Floats * counts[k];
  }
  vtkNew<vtkDoubleArray> timeField;
  timeField->SetName("Time");
  timeField->InsertNextValue(header.Time);
  fields->AddArray(timeField);
  if (types.empty())
  {
    problem = "the file holds no particles";
    return false;
  }
  return true;
}

bool vtkTipsyParticleReader::ReadParticles(
  std::size_t type, long long begin, long long end, vtkPolyData* output, std::string& problem)
{
  const Layout& layout = Layouts[this->TypeKinds[type]];
  const std::size_t record = 4 * static_cast<std::size_t>(layout.Floats);
  const vtkIdType n = static_cast<vtkIdType>(end - begin);
  std::ifstream file(this->FileName, std::ios::binary);
  std::vector<char> bytes(static_cast<std::size_t>(n) * record);
  file.seekg(this->TypeOffsets[type] + begin * static_cast<long long>(record));
  if (!file || !file.read(bytes.data(), static_cast<std::streamsize>(bytes.size())))
  {
    problem = "could not read " + std::to_string(n) + " particles (truncated file?)";
    return false;
  }
  vtkNew<vtkPoints> points;
  points->SetDataTypeToFloat();
  points->SetNumberOfPoints(n);
  // The columns the user reads (PointArraySelection), with the float each comes from.
  std::vector<std::pair<vtkSmartPointer<vtkFloatArray>, int>> scalars;
  for (const auto& scalar : layout.Scalars)
  {
    if (this->ReadsArray(scalar.first))
    {
      auto array = vtkSmartPointer<vtkFloatArray>::New();
      array->SetName(scalar.first);
      array->SetNumberOfValues(n);
      scalars.emplace_back(array, scalar.second);
    }
  }
  vtkSmartPointer<vtkFloatArray> velocity;
  if (this->ReadsArray("velocity"))
  {
    velocity = vtkSmartPointer<vtkFloatArray>::New();
    velocity->SetName("velocity");
    velocity->SetNumberOfComponents(3);
    velocity->SetNumberOfTuples(n);
  }
  std::vector<float> v(layout.Floats);
  for (vtkIdType i = 0; i < n; ++i)
  {
    for (int c = 0; c < layout.Floats; ++c)
    {
      v[c] = FromBytes<float>(&bytes[record * i + 4 * c], this->BigEndian);
    }
    points->SetPoint(i, v[1], v[2], v[3]);
    if (velocity)
    {
      velocity->SetTypedTuple(i, &v[4]);
    }
    for (auto& scalar : scalars)
    {
      scalar.first->SetValue(i, v[scalar.second]);
    }
  }
  output->SetPoints(points);
  for (auto& scalar : scalars)
  {
    output->GetPointData()->AddArray(scalar.first);
  }
  if (velocity)
  {
    output->GetPointData()->AddArray(velocity);
  }
  if (this->TypeKinds[type] == 0) // gas
  {
    SPHMarkers markers; // Gasoline and ChaNGa: the cubic spline's support is 2 hsmooth
    markers.Density = "rho";
    markers.SmoothingLength = "hsmooth";
    markers.Mass = "mass";
    markers.SupportPerSmoothingLength = 2.0;
    MarkSPHArrays(output, markers);
  }
  return true;
}

void vtkTipsyParticleReader::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}
