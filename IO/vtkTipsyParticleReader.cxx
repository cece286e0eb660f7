// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkTipsyParticleReader.h"

#include "vtkCellArray.h"
#include "vtkFloatArray.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkStreamingDemandDrivenPipeline.h"

#include <cstdint>
#include <cstring>
#include <fstream>
#include <numeric>
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

template <typename T>
T FromBytes(const char* bytes, bool bigEndian)
{
  char copy[sizeof(T)];
  std::memcpy(copy, bytes, sizeof(T));
  const std::uint16_t probe = 1;
  const bool hostLittle = *reinterpret_cast<const char*>(&probe) == 1;
  if (bigEndian == hostLittle)
  {
    for (std::size_t i = 0; i < sizeof(T) / 2; ++i)
    {
      std::swap(copy[i], copy[sizeof(T) - 1 - i]);
    }
  }
  T value;
  std::memcpy(&value, copy, sizeof(T));
  return value;
}

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
} // namespace

vtkTipsyParticleReader::vtkTipsyParticleReader()
{
  this->SetNumberOfInputPorts(0);
}

void vtkTipsyParticleReader::SetFileName(const char* name)
{
  const std::string value = name ? name : "";
  if (value != this->FileName)
  {
    this->FileName = value;
    this->Modified();
  }
}

bool vtkTipsyParticleReader::CanReadFile(const char* name)
{
  std::ifstream file(name, std::ios::binary);
  TipsyHeader header;
  std::string problem;
  return file && ReadHeader(file, header, problem);
}

int vtkTipsyParticleReader::RequestInformation(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  std::ifstream file(this->FileName, std::ios::binary);
  TipsyHeader header;
  std::string problem;
  if (!file || !ReadHeader(file, header, problem))
  {
    return 1; // RequestData reports the problem
  }
  // One time step: the file's own (a series of files gets its steps from the series reader).
  vtkInformation* info = outputVector->GetInformationObject(0);
  info->Set(vtkStreamingDemandDrivenPipeline::TIME_STEPS(), &header.Time, 1);
  const double range[2] = { header.Time, header.Time };
  info->Set(vtkStreamingDemandDrivenPipeline::TIME_RANGE(), range, 2);
  return 1;
}

int vtkTipsyParticleReader::RequestData(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkPolyData* output = vtkPolyData::GetData(outputVector);
  std::ifstream file(this->FileName, std::ios::binary);
  if (!file)
  {
    vtkErrorMacro("Cannot open the file '" << this->FileName << "'.");
    return 0;
  }
  TipsyHeader header;
  std::string problem;
  if (!ReadHeader(file, header, problem))
  {
    vtkErrorMacro("'" << this->FileName << "': " << problem << ".");
    return 0;
  }
  const vtkIdType n = header.Gas;
  std::vector<char> bytes(static_cast<std::size_t>(n) * 48);
  file.seekg(32);
  if (!file.read(bytes.data(), static_cast<std::streamsize>(bytes.size())))
  {
    vtkErrorMacro("'" << this->FileName << "': could not read " << n << " gas particles.");
    return 0;
  }
  vtkNew<vtkPoints> points;
  points->SetDataTypeToFloat();
  points->SetNumberOfPoints(n);
  const char* names[] = { "mass", "rho", "temp", "hsmooth", "metals", "phi" };
  const int columns[] = { 0, 7, 8, 9, 10, 11 };
  std::vector<vtkNew<vtkFloatArray>> scalars(6);
  for (int a = 0; a < 6; ++a)
  {
    scalars[a]->SetName(names[a]);
    scalars[a]->SetNumberOfValues(n);
  }
  vtkNew<vtkFloatArray> velocity;
  velocity->SetName("velocity");
  velocity->SetNumberOfComponents(3);
  velocity->SetNumberOfTuples(n);
  for (vtkIdType i = 0; i < n; ++i)
  {
    float v[12];
    for (int c = 0; c < 12; ++c)
    {
      v[c] = FromBytes<float>(&bytes[48 * i + 4 * c], header.BigEndian);
    }
    points->SetPoint(i, v[1], v[2], v[3]);
    velocity->SetTypedTuple(i, v + 4);
    for (int a = 0; a < 6; ++a)
    {
      scalars[a]->SetValue(i, v[columns[a]]);
    }
  }
  output->SetPoints(points);
  // One vertex cell per particle, so that ParaView draws them.
  vtkNew<vtkIdTypeArray> vertexIds;
  vertexIds->SetNumberOfValues(n);
  std::iota(vertexIds->Begin(), vertexIds->End(), vtkIdType(0));
  vtkNew<vtkCellArray> vertices;
  vertices->SetData(1, vertexIds);
  output->SetVerts(vertices);
  for (auto& array : scalars)
  {
    output->GetPointData()->AddArray(array);
  }
  output->GetPointData()->AddArray(velocity);
  output->GetPointData()->SetActiveScalars("rho");
  output->GetInformation()->Set(vtkDataObject::DATA_TIME_STEP(), header.Time);
  if (header.Dark + header.Stars > 0)
  {
    vtkWarningMacro("'" << this->FileName << "': skipped " << header.Dark << " dark and "
                        << header.Stars << " star particles (only gas is read).");
  }
  return 1;
}

void vtkTipsyParticleReader::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << this->FileName << "\n";
}
