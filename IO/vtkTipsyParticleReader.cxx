// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkTipsyParticleReader.h"

#include "ByteOrder.h"
#include "SmoothingLengthNames.h"
#include "TipsyRunParameters.h"

#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkIdTypeArray.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkStringArray.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkTipsyParticleReader);

namespace
{
struct TipsyHeader
{
  double Time = 0.0;
  std::int32_t Bodies = 0, Dimensions = 0, Gas = 0, Dark = 0, Stars = 0;
  bool BigEndian = true;
  int PositionBytes = 4, VelocityBytes = 4; // 8: doubles (the file's size tells)
  // 32: the standard header, padded to 8 bytes; 28: the header as older tools and 32-bit
  // machines wrote it, without the pad (the file's size tells).
  int HeaderBytes = 32;
};

using lsi::FromBytes;

// The three record layouts of a Tipsy standard file, in file order: which column of a record
// holds what (mass 0, position 1-3 and velocity 4-6 in all of them), and how many columns.
struct Layout
{
  const char* TypeName;
  int Columns;
  std::vector<std::pair<const char*, int>> Scalars;
};
const Layout Layouts[3] = {
  { "Gas", 12,
    { { "mass", 0 }, { "rho", 7 }, { "temp", 8 }, { "hsmooth", 9 }, { "metals", 10 },
      { "phi", 11 } } },
  { "DarkMatter", 9, { { "mass", 0 }, { "eps", 7 }, { "phi", 8 } } },
  { "Stars", 11, { { "mass", 0 }, { "metals", 7 }, { "tform", 8 }, { "eps", 9 }, { "phi", 10 } } },
};

// A record's bytes: the mass, 3 positions, 3 velocities, then the other columns as floats.
std::uint64_t RecordBytes(int kind, int positionBytes, int velocityBytes)
{
  return 4ull * (Layouts[kind].Columns - 6) + 3ull * positionBytes + 3ull * velocityBytes;
}

std::uint64_t FileBytes(
  const TipsyHeader& h, int positionBytes, int velocityBytes, int headerBytes = 32)
{
  const std::uint64_t counts[3] = { static_cast<std::uint64_t>(h.Gas),
    static_cast<std::uint64_t>(h.Dark), static_cast<std::uint64_t>(h.Stars) };
  std::uint64_t bytes = static_cast<std::uint64_t>(headerBytes);
  for (int k = 0; k < 3; ++k)
  {
    bytes += counts[k] * RecordBytes(k, positionBytes, velocityBytes);
  }
  return bytes;
}

// A consistent header, and the header size and record precision the file's size fits exactly:
// the padded header (32 bytes) or the unpadded one (28), with floats or one of the
// double-precision layouts (positions; positions and velocities). Else the padded header and
// floats, with the file at least as long as they need (files with trailing bytes were always
// read so).
bool Plausible(TipsyHeader& h, std::uint64_t fileSize)
{
  if (h.Gas < 0 || h.Dark < 0 || h.Stars < 0 || h.Dimensions < 1 || h.Dimensions > 3 ||
    static_cast<std::int64_t>(h.Gas) + h.Dark + h.Stars != h.Bodies)
  {
    return false;
  }
  const int layouts[3][2] = { { 4, 4 }, { 8, 4 }, { 8, 8 } };
  for (int headerBytes : { 32, 28 })
  {
    for (const auto& layout : layouts)
    {
      // (With no particles only the header's size tells, and floats are as good as doubles.)
      if ((layout[0] == 4 || h.Bodies > 0) &&
        fileSize == FileBytes(h, layout[0], layout[1], headerBytes))
      {
        h.PositionBytes = layout[0];
        h.VelocityBytes = layout[1];
        h.HeaderBytes = headerBytes;
        return true;
      }
    }
  }
  h.PositionBytes = h.VelocityBytes = 4;
  h.HeaderBytes = 32;
  return fileSize >= FileBytes(h, 4, 4);
}

// Whether `name` is one of kind k's columns in the main file (which an auxiliary array of that
// name does not replace).
bool IsMainColumn(int kind, const std::string& name)
{
  const auto& scalars = Layouts[kind].Scalars;
  return name == "velocity" ||
    std::any_of(scalars.begin(), scalars.end(),
      [&name](const std::pair<const char*, int>& scalar) { return name == scalar.first; });
}

// The auxiliary array of the SPH smoothing lengths h among those read, "" without one
// (SmoothingLengthNames.h: each is fBall / 2).
std::string TipsySmoothingLengthArray(vtkPolyData* particles)
{
  for (const char* name : lsi::TipsySmoothingLengthNames)
  {
    vtkDataArray* array = particles->GetPointData()->GetArray(name);
    if (array && array->GetNumberOfComponents() == 1)
    {
      return name;
    }
  }
  return std::string();
}

// Reads and checks the header; tries big-endian (the standard) first, then little-endian.
bool ReadHeader(std::ifstream& file, TipsyHeader& header, std::string& problem)
{
  file.seekg(0, std::ios::end);
  const std::uint64_t size = static_cast<std::uint64_t>(file.tellg());
  file.seekg(0);
  char bytes[28];
  if (size < 28 || !file.read(bytes, 28))
  {
    problem = "shorter than a Tipsy header (28 bytes, 32 with its pad)";
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
  this->PositionBytes = header.PositionBytes;
  this->VelocityBytes = header.VelocityBytes;
  const long long counts[3] = { header.Gas, header.Dark, header.Stars };
  long long offset = header.HeaderBytes, first = 0;
  this->TypeKinds.clear();
  this->TypeOffsets.clear();
  this->TypeFirsts.clear();
  this->AuxiliaryArrays =
    lsi::io::FindTipsyAuxiliaryArrays(this->FileName, header.Bodies, &this->AuxiliaryCache);
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
      for (const auto& aux : this->AuxiliaryArrays)
      {
        if (!IsMainColumn(k, aux.Name))
        {
          type.Arrays.push_back(aux.Name);
        }
      }
      types.push_back(type);
      this->TypeKinds.push_back(k);
      this->TypeOffsets.push_back(offset);
      this->TypeFirsts.push_back(first);
    }
    offset +=
      static_cast<long long>(RecordBytes(k, this->PositionBytes, this->VelocityBytes)) * counts[k];
    first += counts[k];
  }
  // The box, from the run's parameter file (a Tipsy file does not say).
  const lsi::io::TipsyRunParameters run = lsi::io::FindTipsyRunParameters(this->FileName);
  if (!run.File.empty())
  {
    vtkNew<vtkStringArray> file;
    file->SetName("TipsyParameterFile");
    file->InsertNextValue(run.File);
    fields->AddArray(file);
  }
  const double* period = run.Period;
  if (run.Periodic &&
    std::all_of(period, period + 3, [](double L) { return L > 0.0 && std::isfinite(L); }))
  {
    vtkNew<vtkDoubleArray> box;
    box->SetName("BoxSize");
    for (int a = 0; a < 3; ++a)
    {
      box->InsertNextValue(period[a]);
    }
    fields->AddArray(box);
  }
  else if (run.Periodic)
  {
    this->WarnOnce(run.File +
      " makes the box periodic along some axes only (a period of 0 on the "
      "others): read as an open box.");
  }
  const std::pair<const char*, double> notes[] = { { "Time", header.Time },
    { "TipsyDoublePositions", this->PositionBytes == 8 ? 1.0 : 0.0 },
    { "TipsyDoubleVelocities", this->VelocityBytes == 8 ? 1.0 : 0.0 } };
  for (const auto& note : notes)
  {
    vtkNew<vtkDoubleArray> field;
    field->SetName(note.first);
    field->InsertNextValue(note.second);
    fields->AddArray(field);
  }
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
  const int kind = this->TypeKinds[type];
  const Layout& layout = Layouts[kind];
  const int pb = this->PositionBytes, vb = this->VelocityBytes;
  const std::size_t record = static_cast<std::size_t>(RecordBytes(kind, pb, vb));
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
  points->SetDataType(pb == 8 ? VTK_DOUBLE : VTK_FLOAT);
  points->SetNumberOfPoints(n);
  // The columns the user reads (PointArraySelection), with the byte each starts at: the mass
  // first, the others (column 7 on) after the positions and velocities.
  const auto columnByte = [pb, vb](int column) {
    return column == 0 ? std::size_t(0)
                       : 4 + 3 * std::size_t(pb + vb) + 4 * std::size_t(column - 7);
  };
  std::vector<std::pair<vtkSmartPointer<vtkFloatArray>, std::size_t>> scalars;
  for (const auto& scalar : layout.Scalars)
  {
    if (this->ReadsArray(scalar.first))
    {
      auto array = vtkSmartPointer<vtkFloatArray>::New();
      array->SetName(scalar.first);
      array->SetNumberOfValues(n);
      scalars.emplace_back(array, columnByte(scalar.second));
    }
  }
  vtkSmartPointer<vtkDataArray> velocity;
  if (this->ReadsArray("velocity"))
  {
    velocity = vtkSmartPointer<vtkDataArray>::Take(
      vtkDataArray::CreateDataArray(vb == 8 ? VTK_DOUBLE : VTK_FLOAT));
    velocity->SetName("velocity");
    velocity->SetNumberOfComponents(3);
    velocity->SetNumberOfTuples(n);
  }
  // A float or a double at `at`, in the file's byte order.
  const auto real = [this](const char* at, int size) {
    return size == 8 ? FromBytes<double>(at, this->BigEndian)
                     : static_cast<double>(FromBytes<float>(at, this->BigEndian));
  };
  for (vtkIdType i = 0; i < n; ++i)
  {
    const char* at = &bytes[record * static_cast<std::size_t>(i)];
    double x[3], v[3];
    for (int d = 0; d < 3; ++d)
    {
      x[d] = real(at + 4 + pb * d, pb);
      v[d] = real(at + 4 + 3 * pb + vb * d, vb);
    }
    points->SetPoint(i, x);
    if (velocity)
    {
      velocity->SetTuple(i, v);
    }
    for (auto& scalar : scalars)
    {
      scalar.first->SetValue(i, FromBytes<float>(at + scalar.second, this->BigEndian));
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
  for (const auto& aux : this->AuxiliaryArrays)
  {
    if (!IsMainColumn(kind, aux.Name) && this->ReadsArray(aux.Name))
    {
      const long long first = this->TypeFirsts[type];
      vtkSmartPointer<vtkDataArray> values =
        lsi::io::ReadTipsyAuxiliaryArray(aux, first + begin, first + end, problem);
      if (!values)
      {
        return false;
      }
      if (aux.Name == "iord" && values->GetNumberOfComponents() == 1)
      {
        // The particle orders are the particles' global ids (as HDF5's ParticleIDs).
        vtkNew<vtkIdTypeArray> ids;
        ids->DeepCopy(values);
        ids->SetName(aux.Name.c_str());
        output->GetPointData()->SetGlobalIds(ids);
        continue;
      }
      output->GetPointData()->AddArray(values);
    }
  }
  if (this->TypeKinds[type] == 0) // gas
  {
    // The smoothing length is not the hsmooth column: Gasoline, ChaNGa and PKDGRAV write the
    // gravitational softening there. Their h (half the radius fBall of the nSmooth nearest, the
    // cubic spline's support being 2 h) is an auxiliary array, when the run wrote it.
    SPHMarkers markers;
    markers.Density = "rho";
    markers.SmoothingLength = TipsySmoothingLengthArray(output);
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
