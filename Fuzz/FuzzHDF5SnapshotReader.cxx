// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
// Any bytes as the content of a snapshot in valid HDF5 containers: the reader must give an error
// or particles, never read past its buffers, crash or hang. The fuzz input is not the file's
// bytes (the HDF5 library is not hardened against damaged containers, and its crashes are not
// ours) but what a file may hold: 1-3 part files, each with or without a Header, whose
// attributes (NumPart_ThisFile, NumFilesPerSnapshot, MassTable, Time, ...) take any type, length
// and value, NaN and 1e300 included; SWIFT's HydroScheme and GADGET-4's Config; and PartType
// groups of datasets of any name, rank, shape and type; SWIFT's cell table. Each snapshot is read
// whole, then with some arrays unread and a region of any box.
#include "vtkDataArraySelection.h"
#include "vtkHDF5SnapshotReader.h"
#include "vtkNew.h"
#include "vtkObject.h"

#include "vtk_hdf5.h"

#include <fuzzer/FuzzedDataProvider.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <string>
#include <unistd.h>
#include <vector>

namespace
{
// A number from the input: mostly small counts, sometimes any double's bits.
double NextNumber(FuzzedDataProvider& in)
{
  switch (in.ConsumeIntegralInRange<int>(0, 3))
  {
    case 0:
      return in.ConsumeFloatingPoint<double>(); // NaN, infinities and extremes occur
    case 1:
      return in.ConsumeIntegralInRange<int>(-3, 3);
    default:
      return in.ConsumeIntegralInRange<int>(0, 40);
  }
}

// A numeric or string HDF5 type, as the writers use.
hid_t NextType(FuzzedDataProvider& in)
{
  switch (in.ConsumeIntegralInRange<int>(0, 8))
  {
    case 0:
      return H5Tcopy(H5T_NATIVE_DOUBLE);
    case 1:
      return H5Tcopy(H5T_NATIVE_FLOAT);
    case 2:
      return H5Tcopy(H5T_NATIVE_INT);
    case 3:
      return H5Tcopy(H5T_NATIVE_LLONG);
    case 4:
      return H5Tcopy(H5T_NATIVE_UINT);
    case 5:
      return H5Tcopy(H5T_NATIVE_UCHAR);
    case 6:
      return H5Tcopy(H5T_STD_I64BE); // big-endian, as some writers use
    default:
      break;
  }
  hid_t text = H5Tcopy(H5T_C_S1);
  H5Tset_size(text, in.ConsumeBool() ? 1 + in.ConsumeIntegralInRange<int>(0, 12) : H5T_VARIABLE);
  return text;
}

// Writes `count` values of `type` from the input (numbers converted by HDF5, strings as text).
void FillBuffer(FuzzedDataProvider& in, hid_t type, std::size_t count, std::vector<char>& bytes,
  std::vector<std::string>& strings, std::vector<const char*>& pointers)
{
  if (H5Tget_class(type) == H5T_STRING)
  {
    if (H5Tis_variable_str(type) > 0)
    {
      strings.resize(count);
      pointers.resize(count);
      for (std::size_t k = 0; k < count; ++k)
      {
        strings[k] = in.ConsumeRandomLengthString(16);
        pointers[k] = strings[k].c_str();
      }
      return;
    }
    bytes = in.ConsumeBytes<char>(count * H5Tget_size(type));
    bytes.resize(count * H5Tget_size(type), 'x');
    return;
  }
  std::vector<double> numbers(count);
  for (double& v : numbers)
  {
    v = NextNumber(in);
  }
  bytes.resize(count * sizeof(double));
  std::copy(reinterpret_cast<const char*>(numbers.data()),
    reinterpret_cast<const char*>(numbers.data() + count), bytes.data());
}

const void* Buffer(
  hid_t type, const std::vector<char>& bytes, const std::vector<const char*>& pointers)
{
  return H5Tget_class(type) == H5T_STRING && H5Tis_variable_str(type) > 0
    ? static_cast<const void*>(pointers.data())
    : static_cast<const void*>(bytes.data());
}

// The memory type of FillBuffer's values.
hid_t MemoryType(hid_t type)
{
  return H5Tget_class(type) == H5T_STRING ? type : H5T_NATIVE_DOUBLE;
}

void WriteAttribute(FuzzedDataProvider& in, hid_t object, const std::string& name)
{
  const hid_t type = NextType(in);
  const int length = in.ConsumeIntegralInRange<int>(0, 8); // 0: a scalar
  const hsize_t dims[1] = { static_cast<hsize_t>(length) };
  const hid_t space = length == 0 ? H5Screate(H5S_SCALAR) : H5Screate_simple(1, dims, nullptr);
  const hid_t attribute = H5Acreate2(object, name.c_str(), type, space, H5P_DEFAULT, H5P_DEFAULT);
  std::vector<char> bytes;
  std::vector<std::string> strings;
  std::vector<const char*> pointers;
  FillBuffer(in, type, static_cast<std::size_t>(std::max(length, 1)), bytes, strings, pointers);
  if (attribute >= 0)
  {
    H5Awrite(attribute, MemoryType(type), Buffer(type, bytes, pointers));
    H5Aclose(attribute);
  }
  H5Sclose(space);
  H5Tclose(type);
}

void WriteDataset(FuzzedDataProvider& in, hid_t group, const std::string& name)
{
  const hid_t type = NextType(in);
  const int rank = in.ConsumeIntegralInRange<int>(0, 3);
  hsize_t dims[3] = { 1, 1, 1 };
  std::size_t count = 1;
  for (int k = 0; k < rank; ++k)
  {
    dims[k] = in.ConsumeIntegralInRange<hsize_t>(0, k == 0 ? 40 : 4);
    count *= dims[k];
  }
  const hid_t space = rank == 0 ? H5Screate(H5S_SCALAR) : H5Screate_simple(rank, dims, nullptr);
  const hid_t dataset =
    H5Dcreate2(group, name.c_str(), type, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  std::vector<char> bytes;
  std::vector<std::string> strings;
  std::vector<const char*> pointers;
  FillBuffer(in, type, count, bytes, strings, pointers);
  if (dataset >= 0)
  {
    if (count > 0)
    {
      H5Dwrite(
        dataset, MemoryType(type), H5S_ALL, H5S_ALL, H5P_DEFAULT, Buffer(type, bytes, pointers));
    }
    H5Dclose(dataset);
  }
  H5Sclose(space);
  H5Tclose(type);
}

std::string NextName(FuzzedDataProvider& in, const std::vector<const char*>& usual)
{
  const std::size_t pick = in.ConsumeIntegralInRange<std::size_t>(0, usual.size());
  if (pick < usual.size())
  {
    return usual[pick];
  }
  std::string name = in.ConsumeRandomLengthString(12);
  return name.empty() || name.find('/') != std::string::npos || name == "." ? "x" : name;
}

// SWIFT's table of cells (Cells/Counts/PartType0, ...): its datasets of any rank, shape, type and
// values, some missing.
void WriteCellTable(FuzzedDataProvider& in, hid_t file)
{
  const hid_t cells = H5Gcreate2(file, "Cells", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  if (cells < 0)
  {
    return;
  }
  for (const char* table :
    { "Counts", "OffsetsInFile", "Offsets", "Files", "MinPositions", "MaxPositions" })
  {
    if (in.ConsumeBool())
    {
      const hid_t group = H5Gcreate2(cells, table, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
      if (group >= 0)
      {
        WriteDataset(in, group, in.ConsumeBool() ? "PartType0" : "PartType1");
        H5Gclose(group);
      }
    }
  }
  if (in.ConsumeBool())
  {
    WriteDataset(in, cells, "Centres");
  }
  const hid_t meta = H5Gcreate2(cells, "Meta-data", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  if (meta >= 0)
  {
    WriteAttribute(in, meta, "size");
    H5Gclose(meta);
  }
  H5Gclose(cells);
}

void WritePart(FuzzedDataProvider& in, const std::string& path)
{
  const hid_t file = H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
  if (file < 0)
  {
    return;
  }
  static const std::vector<const char*> headerNames = { "NumPart_ThisFile", "NumPart_Total",
    "NumPart_Total_HighWord", "MassTable", "Time", "Redshift", "BoxSize", "NumFilesPerSnapshot" };
  static const std::vector<const char*> groupNames = { "Header", "HydroScheme", "Units", "Config",
    "PartType0", "PartType1", "PartType4", "PartType5", "PartType7" };
  static const std::vector<const char*> datasetNames = { "Coordinates", "Masses", "Density",
    "Densities", "SmoothingLength", "SmoothingLengths", "ParticleIDs", "Velocities" };
  static const std::vector<const char*> schemeNames = { "Kernel function", "Kernel gamma",
    "WENDLAND_C2_KERNEL" };
  const int groups = in.ConsumeIntegralInRange<int>(0, 6);
  for (int g = 0; g < groups && in.remaining_bytes() > 0; ++g)
  {
    const std::string name = NextName(in, groupNames);
    if (H5Lexists(file, name.c_str(), H5P_DEFAULT) > 0)
    {
      continue;
    }
    const hid_t group = H5Gcreate2(file, name.c_str(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
    if (group < 0)
    {
      continue;
    }
    const bool particles = name.rfind("PartType", 0) == 0;
    const int members = in.ConsumeIntegralInRange<int>(0, 8);
    for (int m = 0; m < members && in.remaining_bytes() > 0; ++m)
    {
      const std::string member = NextName(in,
        particles            ? datasetNames
          : name == "Header" ? headerNames
                             : schemeNames);
      if (particles)
      {
        if (H5Lexists(group, member.c_str(), H5P_DEFAULT) <= 0)
        {
          WriteDataset(in, group, member);
        }
      }
      else if (H5Aexists(group, member.c_str()) <= 0)
      {
        WriteAttribute(in, group, member);
      }
    }
    H5Gclose(group);
  }
  if (in.ConsumeBool())
  {
    WriteCellTable(in, file);
  }
  H5Fclose(file);
}
} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  vtkObject::GlobalWarningDisplayOff(); // bad files are expected: no message flood
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  FuzzedDataProvider in(data, size);
  const int parts = in.ConsumeIntegralInRange<int>(1, 3);
  const std::string stem = "/tmp/fuzz-hdf5-" + std::to_string(getpid());
  std::vector<std::string> paths;
  for (int p = 0; p < parts; ++p)
  {
    paths.push_back(parts == 1 ? stem + ".hdf5" : stem + "." + std::to_string(p) + ".hdf5");
    WritePart(in, paths.back());
  }
  vtkNew<vtkHDF5SnapshotReader> reader;
  reader->SetFileName(paths[0].c_str());
  reader->UpdateInformation();
  reader->GetParticleTypeSelection()->EnableAllArrays(); // every type: a multiblock
  reader->Update();
  // Again with some arrays left unread, and a region of any box read in small chunks.
  vtkDataArraySelection* arrays = reader->GetPointArraySelection();
  for (int a = 0; a < arrays->GetNumberOfArrays(); ++a)
  {
    arrays->SetArraySetting(arrays->GetArrayName(a), in.ConsumeBool());
  }
  double bounds[6];
  for (double& b : bounds)
  {
    b = NextNumber(in);
  }
  reader->SetReadRegion(true);
  reader->SetRegionBounds(bounds);
  reader->SetRegionChunkParticles(in.ConsumeIntegralInRange<vtkIdType>(1, 8));
  reader->Update();
  for (const std::string& path : paths)
  {
    std::remove(path.c_str());
  }
  return 0;
}
