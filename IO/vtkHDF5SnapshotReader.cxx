// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkHDF5SnapshotReader.h"

#include "SPHKernels.h"

#include "HDF5Handles.h"
#include "SwiftCells.h"

#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkIdTypeArray.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkStringArray.h"
#include "vtk_hdf5.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <set>
#include <utility>

vtkStandardNewMacro(vtkHDF5SnapshotReader);

namespace
{
using lsi::io::Exists;
using lsi::io::Handle;
using lsi::io::NumericAttribute;
using lsi::io::QuietHDF5;

// Every attribute of `object` as a field data array, named prefix + its name: numbers as
// vtkDoubleArray, strings as vtkStringArray.
void AttributesToFieldData(hid_t object, const std::string& prefix, vtkFieldData* fields)
{
  struct Context
  {
    std::string Prefix;
    vtkFieldData* Fields;
  } context{ prefix, fields };
  auto visit = [](hid_t location, const char* name, const H5A_info_t*, void* data) -> herr_t {
    Context& c = *static_cast<Context*>(data);
    Handle attribute(H5Aopen(location, name, H5P_DEFAULT), H5Aclose);
    Handle type(H5Aget_type(attribute), H5Tclose);
    const std::string fieldName = c.Prefix + name;
    if (H5Tget_class(type) == H5T_STRING)
    {
      // One string or an array of them (every value kept, in order).
      Handle space(H5Aget_space(attribute), H5Sclose);
      const hssize_t points = H5Sget_simple_extent_npoints(space);
      const std::size_t count = points > 0 ? static_cast<std::size_t>(points) : 0;
      std::vector<std::string> values(count);
      if (H5Tis_variable_str(type) > 0)
      {
        std::vector<char*> texts(count, nullptr);
        Handle memoryType(H5Tcopy(H5T_C_S1), H5Tclose);
        H5Tset_size(memoryType, H5T_VARIABLE);
        H5Tset_cset(memoryType, H5Tget_cset(type)); // HDF5 does not convert ASCII and UTF-8
        if (count > 0 && H5Aread(attribute, memoryType, texts.data()) >= 0)
        {
          for (std::size_t k = 0; k < count; ++k)
          {
            values[k] = texts[k] ? texts[k] : "";
          }
          H5Dvlen_reclaim(memoryType, space, H5P_DEFAULT, texts.data());
        }
      }
      else
      {
        const std::size_t size = H5Tget_size(type);
        std::vector<char> text(count * size + 1, '\0');
        if (count > 0 && size > 0 && H5Aread(attribute, type, text.data()) >= 0)
        {
          for (std::size_t k = 0; k < count; ++k)
          {
            const char* begin = text.data() + k * size;
            values[k].assign(begin, std::find(begin, begin + size, '\0'));
          }
        }
      }
      vtkNew<vtkStringArray> array;
      array->SetName(fieldName.c_str());
      for (const std::string& value : values)
      {
        array->InsertNextValue(value);
      }
      c.Fields->AddArray(array);
      return 0;
    }
    const std::vector<double> values = NumericAttribute(location, name);
    if (!values.empty())
    {
      vtkNew<vtkDoubleArray> array;
      array->SetName(fieldName.c_str());
      for (double v : values)
      {
        array->InsertNextValue(v);
      }
      c.Fields->AddArray(array);
    }
    return 0;
  };
  hsize_t index = 0;
  H5Aiterate2(object, H5_INDEX_NAME, H5_ITER_INC, &index, visit, &context);
}

// The SPH kernel a file names, as the readers mark it (lsi::NamesOf), and its support
// per smoothing length. SWIFT writes HydroScheme attributes "Kernel function" (e.g. "Quintic
// spline (M6)", "Wendland C4") and "Kernel gamma" (support = gamma h; without it, the named
// kernel's gamma, as SWIFT defines h for every kernel). GADGET-4 writes its
// compile flags in Config (WENDLAND_C2_KERNEL, ..._C4_, ..._C6_; none: the cubic spline) and h
// is the support. Anything else keeps GADGET's cubic spline, h = H. A kernel name that is none
// of lsi::SPHKernel's is marked as written (the filter warns and uses the cubic spline) and
// returned in `unknown`. `biasCorrected`: GADGET-4's Config flags WENDLAND_BIAS_CORRECTION (its
// Density has Dehnen & Aly's self-contribution taken off; a field summed from the masses does
// not).
void ReadKernel(hid_t file, std::string& kernel, double& supportPerSmoothingLength,
  std::string& unknown, bool& biasCorrected)
{
  if (Exists(file, "HydroScheme"))
  {
    Handle scheme(H5Gopen2(file, "HydroScheme", H5P_DEFAULT), H5Gclose);
    vtkNew<vtkFieldData> attributes;
    AttributesToFieldData(scheme, "", attributes);
    auto* name = vtkStringArray::SafeDownCast(attributes->GetAbstractArray("Kernel function"));
    lsi::SPHKernel named = lsi::SPHKernel::CubicSpline;
    bool known = false;
    if (name && name->GetNumberOfValues() > 0 && !name->GetValue(0).empty())
    {
      const std::string written = name->GetValue(0);
      known = lsi::SPHKernelFromName(written, named);
      kernel = known ? std::string(lsi::NamesOf(named).Marker) : written;
      unknown = known ? std::string() : written;
    }
    const std::vector<double> gamma = NumericAttribute(scheme, "Kernel gamma");
    if (!gamma.empty() && gamma[0] > 0.0 && std::isfinite(gamma[0]))
    {
      supportPerSmoothingLength = gamma[0];
    }
    else if (known)
    {
      // A SWIFT file naming its kernel without its gamma: SWIFT's h is still H / gamma.
      supportPerSmoothingLength = lsi::NamesOf(named).SwiftGamma;
    }
  }
  else if (Exists(file, "Config"))
  {
    Handle config(H5Gopen2(file, "Config", H5P_DEFAULT), H5Gclose);
    const std::pair<const char*, lsi::SPHKernel> flags[] = { { "WENDLAND_C2_KERNEL",
                                                               lsi::SPHKernel::WendlandC2 },
      { "WENDLAND_C4_KERNEL", lsi::SPHKernel::WendlandC4 },
      { "WENDLAND_C6_KERNEL", lsi::SPHKernel::WendlandC6 } };
    for (const auto& flag : flags)
    {
      if (H5Aexists(config, flag.first) > 0)
      {
        kernel = lsi::NamesOf(flag.second).Marker;
      }
    }
    biasCorrected = H5Aexists(config, "WENDLAND_BIAS_CORRECTION") > 0;
  }
}

// A count read from a numeric attribute: a whole number from 0 to 2^53 (a double holds each such
// integer exactly). False for NaN, infinities, fractions and negatives, which no writer writes.
bool AsCount(double value, long long& count)
{
  if (!(value >= 0.0 && value <= 9007199254740992.0) || value != std::floor(value))
  {
    return false;
  }
  count = static_cast<long long>(value);
  return true;
}

// The VTK array type for a dataset's type (the same class, size and sign), or -1 for types we do
// not read (compound, strings, ...).
int ArrayTypeFor(hid_t type)
{
  const std::size_t size = H5Tget_size(type);
  const bool isSigned = H5Tget_sign(type) == H5T_SGN_2;
  switch (H5Tget_class(type))
  {
    case H5T_FLOAT:
      return size == 4 ? VTK_FLOAT : VTK_DOUBLE;
    case H5T_INTEGER:
      if (size <= 1)
      {
        return isSigned ? VTK_TYPE_INT8 : VTK_TYPE_UINT8;
      }
      if (size == 2)
      {
        return isSigned ? VTK_TYPE_INT16 : VTK_TYPE_UINT16;
      }
      if (size == 4)
      {
        return isSigned ? VTK_TYPE_INT32 : VTK_TYPE_UINT32;
      }
      return isSigned ? VTK_TYPE_INT64 : VTK_TYPE_UINT64;
    default:
      return -1;
  }
}

// The HDF5 memory type of a VTK array type from ArrayTypeFor: what H5Dread converts into, so
// that a dataset stored with another type in another part of the snapshot still lands right.
hid_t MemoryTypeFor(int arrayType)
{
  switch (arrayType)
  {
    case VTK_FLOAT:
      return H5T_NATIVE_FLOAT;
    case VTK_DOUBLE:
      return H5T_NATIVE_DOUBLE;
    case VTK_TYPE_INT8:
      return H5T_NATIVE_INT8;
    case VTK_TYPE_UINT8:
      return H5T_NATIVE_UINT8;
    case VTK_TYPE_INT16:
      return H5T_NATIVE_INT16;
    case VTK_TYPE_UINT16:
      return H5T_NATIVE_UINT16;
    case VTK_TYPE_INT32:
      return H5T_NATIVE_INT32;
    case VTK_TYPE_UINT32:
      return H5T_NATIVE_UINT32;
    case VTK_TYPE_INT64:
      return H5T_NATIVE_INT64;
    default:
      return H5T_NATIVE_UINT64;
  }
}

// The VTK array type of `dataset` read as a per-particle array (one row per particle, one or
// more numeric columns), with its rank and shape; -1 for a dataset that is not one (scalars,
// higher ranks, no columns, compound or string types).
int PerParticleArrayType(hid_t dataset, int& rank, hsize_t (&dims)[2])
{
  Handle space(H5Dget_space(dataset), H5Sclose);
  Handle fileType(H5Dget_type(dataset), H5Tclose);
  rank = H5Sget_simple_extent_ndims(space);
  dims[0] = 0;
  dims[1] = 1;
  if (rank < 1 || rank > 2 || H5Sget_simple_extent_dims(space, dims, nullptr) < 0 || dims[1] == 0)
  {
    return -1;
  }
  return ArrayTypeFor(fileType);
}

// The names of the datasets directly in `group`.
std::vector<std::string> DatasetNames(hid_t group)
{
  std::vector<std::string> names;
  H5G_info_t info;
  if (H5Gget_info(group, &info) < 0)
  {
    return names;
  }
  for (hsize_t i = 0; i < info.nlinks; ++i)
  {
    char name[1024] = { 0 };
    if (H5Lget_name_by_idx(
          group, ".", H5_INDEX_NAME, H5_ITER_INC, i, name, sizeof(name), H5P_DEFAULT) < 0)
    {
      continue;
    }
    H5O_info_t object;
    if (H5Oget_info_by_name(group, name, &object, H5P_DEFAULT) >= 0 &&
      object.type == H5O_TYPE_DATASET)
    {
      names.push_back(name);
    }
  }
  return names;
}

// The point arrays a reader gives for the particles of `group` in `file`: its per-particle
// numeric datasets but the positions (Coordinates), in the file's order.
std::vector<std::string> PointArrayNames(hid_t file, const std::string& group)
{
  std::vector<std::string> arrays;
  Handle particles(H5Gopen2(file, group.c_str(), H5P_DEFAULT), H5Gclose);
  if (!particles.Valid())
  {
    return arrays;
  }
  for (const std::string& name : DatasetNames(particles))
  {
    Handle dataset(H5Dopen2(particles, name.c_str(), H5P_DEFAULT), H5Dclose);
    int rank = 0;
    hsize_t dims[2];
    if (name != "Coordinates" && dataset.Valid() && PerParticleArrayType(dataset, rank, dims) >= 0)
    {
      arrays.push_back(name);
    }
  }
  return arrays;
}

const char* const DensityNames[] = { "Density", "Densities" };
// GADGET, GIZMO, AREPO and SWIFT write Masses; EAGLE, OWLS and other GADGET-3 variants Mass.
const char* const MassNames[] = { "Masses", "Mass" };
const char* const SmoothingLengthNames[] = { "SmoothingLength", "SmoothingLengths" };

template <std::size_t N>
bool OneOf(const std::string& name, const char* const (&names)[N])
{
  return std::find(std::begin(names), std::end(names), name) != std::end(names);
}
} // namespace

vtkHDF5SnapshotReader::vtkHDF5SnapshotReader() = default;
vtkHDF5SnapshotReader::~vtkHDF5SnapshotReader() = default;

std::string vtkHDF5SnapshotReader::ParticleTypeName(int number)
{
  return PartTypeName(number);
}

bool vtkHDF5SnapshotReader::CanReadFile(const char* name)
{
  QuietHDF5 quiet;
  if (!name || H5Fis_hdf5(name) <= 0)
  {
    return false;
  }
  Handle file(H5Fopen(name, H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose);
  if (!file.Valid() || !Exists(file, "Header"))
  {
    return false;
  }
  for (int t = 0; t < 64; ++t)
  {
    if (Exists(file, "PartType" + std::to_string(t)))
    {
      return true;
    }
  }
  return false;
}

bool vtkHDF5SnapshotReader::ReadMetaData(
  std::vector<ParticleType>& types, double& time, vtkFieldData* fields, std::string& problem)
{
  QuietHDF5 quiet;
  this->Parts.clear();
  this->TypeNumbers.clear();
  this->PartCounts.clear();
  this->MassTable.clear();
  this->Kernel = "CubicSpline";
  this->SupportPerSmoothingLength = 1.0;
  {
    std::ifstream exists(this->FileName);
    if (!exists)
    {
      problem = "cannot open the file";
      return false;
    }
  }
  if (H5Fis_hdf5(this->FileName.c_str()) <= 0)
  {
    problem = "not an HDF5 file";
    return false;
  }
  Handle file(H5Fopen(this->FileName.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose);
  if (!file.Valid())
  {
    problem = "the HDF5 library cannot open it (damaged or truncated?)";
    return false;
  }
  if (!Exists(file, "Header"))
  {
    problem = "not a particle snapshot: no Header group";
    return false;
  }
  Handle header(H5Gopen2(file, "Header", H5P_DEFAULT), H5Gclose);
  AttributesToFieldData(header, "", fields);
  for (const char* group : { "HydroScheme", "Units" })
  {
    if (Exists(file, group))
    {
      Handle g(H5Gopen2(file, group, H5P_DEFAULT), H5Gclose);
      AttributesToFieldData(g, std::string(group) + "/", fields);
    }
  }
  std::string unknownKernel;
  bool biasCorrected = false;
  ReadKernel(file, this->Kernel, this->SupportPerSmoothingLength, unknownKernel, biasCorrected);
  if (biasCorrected)
  {
    this->WarnOnce("GADGET-4 was built with WENDLAND_BIAS_CORRECTION: its Density has each "
                   "particle's self-contribution reduced (Dehnen & Aly 2012), so it is slightly "
                   "below the SPH field summed from Masses and SmoothingLength (Particle Density, "
                   "Level-Set Isosurface's SPH field), which has no such correction. An isovalue "
                   "taken from Density sits that much lower on the summed field.");
  }
  if (!unknownKernel.empty())
  {
    this->WarnOnce("HydroScheme names the kernel '" + unknownKernel +
      "', none of those the SPH field knows (cubic, quartic and quintic splines, Wendland C2, C4 "
      "and C6): set Level-Set Isosurface's Kernel.");
  }
  // SWIFT's subsampled snapshots keep a random fraction of a type's particles, with their
  // full-run masses, densities and smoothing lengths: a field summed from them is that fraction
  // of the simulation's.
  auto* outputType = vtkStringArray::SafeDownCast(fields->GetAbstractArray("OutputType"));
  const std::vector<double> fractions = NumericAttribute(header, "SubSampleFractions");
  if (outputType && outputType->GetNumberOfValues() > 0 && outputType->GetValue(0) == "SubSampled")
  {
    for (std::size_t t = 0; t < fractions.size(); ++t)
    {
      if (fractions[t] < 1.0)
      {
        this->WarnOnce("a subsampled snapshot: PartType" + std::to_string(t) + " holds " +
          std::to_string(fractions[t]) +
          " of the run's particles (SubSampleFractions), so a density or SPH field summed from "
          "them (Particle Density, Level-Set Isosurface's SPH field) is not the simulation's. "
          "Use a full snapshot of that type.");
      }
    }
  }
  const std::vector<double> times = NumericAttribute(header, "Time");
  time = times.empty() ? 0.0 : times[0];
  this->MassTable = NumericAttribute(header, "MassTable");

  // The files of the snapshot.
  const std::vector<double> files = NumericAttribute(header, "NumFilesPerSnapshot");
  long long parts = 1;
  // More files than any run writes (GADGET-4's largest use thousands) is a damaged header.
  if (!files.empty() && (!AsCount(files[0], parts) || parts > 1000000))
  {
    problem = "Header attribute NumFilesPerSnapshot is " + std::to_string(files[0]) +
      ", not a number of files";
    return false;
  }
  parts = std::max(parts, 1LL);
  if (parts > 1)
  {
    this->Parts = PartFileNames(this->FileName, parts);
    if (this->Parts.empty())
    {
      problem = "the snapshot is split over " + std::to_string(parts) +
        " files (NumFilesPerSnapshot), but this file is not named NAME.K.hdf5";
      return false;
    }
  }
  else
  {
    this->Parts.push_back(this->FileName);
  }

  // The particle count of every type in every part (NumPart_ThisFile, or the groups' lengths).
  std::vector<std::vector<long long>> counts;         // [part][PartType number]
  std::vector<std::vector<std::string>> arraysOf(64); // [PartType number]: its point arrays
  std::vector<char> listedArrays(64, 0);
  int numberOfTypes = 0;
  for (const std::string& name : this->Parts)
  {
    if (!std::ifstream(name))
    {
      problem = "part " + name + " of the snapshot is missing";
      return false;
    }
    Handle part(H5Fopen(name.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose);
    if (!part.Valid() || !Exists(part, "Header"))
    {
      problem = "part " + name + " of the snapshot is not a readable snapshot file";
      return false;
    }
    Handle partHeader(H5Gopen2(part, "Header", H5P_DEFAULT), H5Gclose);
    std::vector<double> thisFile = NumericAttribute(partHeader, "NumPart_ThisFile");
    std::vector<long long> partCounts;
    for (int t = 0; t < 64; ++t)
    {
      long long count = 0;
      if (t < static_cast<int>(thisFile.size()) && !AsCount(thisFile[t], count))
      {
        problem = "NumPart_ThisFile in " + name + " holds " + std::to_string(thisFile[t]) +
          ", not a particle count";
        return false;
      }
      const std::string group = "PartType" + std::to_string(t);
      if (thisFile.empty() && Exists(part, group + "/Coordinates"))
      {
        Handle coordinates(H5Dopen2(part, (group + "/Coordinates").c_str(), H5P_DEFAULT), H5Dclose);
        Handle space(H5Dget_space(coordinates), H5Sclose);
        hsize_t dims[H5S_MAX_RANK] = {};
        if (H5Sget_simple_extent_ndims(space) < 1 ||
          H5Sget_simple_extent_dims(space, dims, nullptr) < 0 ||
          !AsCount(static_cast<double>(dims[0]), count))
        {
          problem = group + "/Coordinates in " + name + " is not one row per particle";
          return false;
        }
      }
      if (count > 0 && !Exists(part, group))
      {
        problem = "NumPart_ThisFile counts " + std::to_string(count) + " particles of " + group +
          " in " + name + ", which has no such group";
        return false;
      }
      if (count > 0 && !listedArrays[t])
      {
        arraysOf[t] = PointArrayNames(part, group);
        const bool massDataset = std::any_of(arraysOf[t].begin(), arraysOf[t].end(),
          [](const std::string& array) { return OneOf(array, MassNames); });
        if (!massDataset && this->TableMass(t) > 0.0)
        {
          arraysOf[t].push_back("Masses"); // from the MassTable
        }
        listedArrays[t] = 1;
      }
      partCounts.push_back(count);
      if (count > 0 || Exists(part, group))
      {
        numberOfTypes = std::max(numberOfTypes, t + 1);
      }
    }
    counts.push_back(partCounts);
  }
  std::vector<long long> totals(static_cast<std::size_t>(numberOfTypes), 0);
  for (const auto& partCounts : counts)
  {
    for (int t = 0; t < numberOfTypes; ++t)
    {
      totals[t] += partCounts[t];
    }
  }
  if (!ListPartTypes(totals, arraysOf, types, this->TypeNumbers, problem))
  {
    return false;
  }
  for (const auto& partCounts : counts)
  {
    std::vector<long long> listed;
    for (int t : this->TypeNumbers)
    {
      listed.push_back(partCounts[t]);
    }
    this->PartCounts.push_back(listed);
  }
  return true;
}

bool vtkHDF5SnapshotReader::ReadParticles(
  std::size_t type, long long begin, long long end, vtkPolyData* output, std::string& problem)
{
  QuietHDF5 quiet;
  const int number = this->TypeNumbers[type];
  const std::string group = "PartType" + std::to_string(number);
  const long long count = end - begin;
  std::vector<std::string> names;
  std::vector<vtkSmartPointer<vtkDataArray>> arrays;
  std::vector<char> leftOut; // datasets left out of an earlier part
  long long filled = 0;      // particles of this range read so far
  long long partStart = 0;   // index of the part's first particle of this type in the snapshot
  for (std::size_t p = 0; p < this->Parts.size() && filled < count; ++p)
  {
    const long long inPart = this->PartCounts[p][type];
    const long long from = std::max(begin, partStart), to = std::min(end, partStart + inPart);
    partStart += inPart;
    if (from >= to)
    {
      continue;
    }
    Handle file(H5Fopen(this->Parts[p].c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose);
    Handle particles(file.Valid() ? H5Gopen2(file, group.c_str(), H5P_DEFAULT) : -1, H5Gclose);
    if (!particles.Valid())
    {
      problem = "cannot open " + group + " in " + this->Parts[p];
      return false;
    }
    const std::vector<std::string> here = DatasetNames(particles);
    if (names.empty())
    {
      names = here;
    }
    else if (here != names)
    {
      problem = this->Parts[p] + " has other datasets in " + group + " than the first part";
      return false;
    }
    arrays.resize(names.size());
    leftOut.resize(names.size(), 0);
    for (std::size_t d = 0; d < names.size(); ++d)
    {
      if (names[d] != "Coordinates" && !this->ReadsArray(names[d]))
      {
        continue; // left unread by the user (PointArraySelection)
      }
      Handle dataset(H5Dopen2(particles, names[d].c_str(), H5P_DEFAULT), H5Dclose);
      Handle space(H5Dget_space(dataset), H5Sclose);
      int rank = 0;
      hsize_t dims[2];
      const int arrayType = PerParticleArrayType(dataset, rank, dims);
      // A dataset that is not a per-particle numeric array is left out, in every part alike:
      // read from some parts only, the other parts' rows of its array would stay unset.
      if (arrayType < 0)
      {
        if (arrays[d])
        {
          problem = "dataset " + group + "/" + names[d] + " in " + this->Parts[p] +
            " is not a per-particle numeric array, as it is in an earlier part";
          return false;
        }
        leftOut[d] = 1;
        continue;
      }
      if (arrays[d] && static_cast<hsize_t>(arrays[d]->GetNumberOfComponents()) != dims[1])
      {
        problem = "dataset " + group + "/" + names[d] + " in " + this->Parts[p] + " has " +
          std::to_string(dims[1]) + " columns, but " +
          std::to_string(arrays[d]->GetNumberOfComponents()) + " in the first part";
        return false;
      }
      if (static_cast<long long>(dims[0]) != inPart)
      {
        problem = "dataset " + group + "/" + names[d] + " in " + this->Parts[p] + " has " +
          std::to_string(dims[0]) + " entries, but the file counts " + std::to_string(inPart) +
          " particles of this type";
        return false;
      }
      if (leftOut[d])
      {
        problem = "dataset " + group + "/" + names[d] + " in " + this->Parts[p] +
          " is a per-particle numeric array, but not in an earlier part";
        return false;
      }
      if (!arrays[d])
      {
        arrays[d] = vtk::TakeSmartPointer(vtkDataArray::CreateDataArray(arrayType));
        arrays[d]->SetName(names[d].c_str());
        arrays[d]->SetNumberOfComponents(static_cast<int>(rank == 2 ? dims[1] : 1));
        arrays[d]->SetNumberOfTuples(count);
      }
      const hsize_t start[2] = { static_cast<hsize_t>(from - (partStart - inPart)), 0 };
      const hsize_t extent[2] = { static_cast<hsize_t>(to - from), dims[1] };
      H5Sselect_hyperslab(space, H5S_SELECT_SET, start, nullptr, extent, nullptr);
      Handle memory(H5Screate_simple(rank, extent, nullptr), H5Sclose);
      void* target = arrays[d]->GetVoidPointer(filled * arrays[d]->GetNumberOfComponents());
      if (H5Dread(dataset, MemoryTypeFor(arrays[d]->GetDataType()), memory, space, H5P_DEFAULT,
            target) < 0)
      {
        problem =
          "cannot read " + group + "/" + names[d] + " in " + this->Parts[p] + " (truncated file?)";
        return false;
      }
    }
    filled += to - from;
  }

  vtkPointData* pointData = output->GetPointData();
  vtkNew<vtkPoints> points;
  bool havePoints = false;
  std::string massName;
  SPHMarkers markers;
  markers.Kernel = this->Kernel;
  markers.SupportPerSmoothingLength = this->SupportPerSmoothingLength;
  for (vtkDataArray* array : arrays)
  {
    if (!array)
    {
      continue;
    }
    const std::string name = array->GetName();
    if (name == "Coordinates" && array->GetNumberOfComponents() == 3)
    {
      points->SetData(array);
      havePoints = true;
      continue;
    }
    if (name == "ParticleIDs" && array->GetNumberOfComponents() == 1)
    {
      vtkNew<vtkIdTypeArray> ids;
      ids->DeepCopy(array);
      ids->SetName(name.c_str());
      pointData->SetGlobalIds(ids);
      continue;
    }
    pointData->AddArray(array);
    massName = massName.empty() && OneOf(name, MassNames) ? name : massName;
    markers.Density = OneOf(name, DensityNames) ? name : markers.Density;
    markers.SmoothingLength = OneOf(name, SmoothingLengthNames) ? name : markers.SmoothingLength;
  }
  if (!havePoints)
  {
    problem = group + " has no Coordinates (N x 3) dataset";
    return false;
  }
  output->SetPoints(points);
  // GADGET's MassTable gives a type's mass where it has no mass dataset; 0 there means the
  // masses are in the file, so a type with neither has none (not masses of 0).
  if (massName.empty() && this->TableMass(number) > 0.0 && this->ReadsArray("Masses"))
  {
    AddTableMasses(pointData, count, this->TableMass(number));
    massName = "Masses";
  }
  markers.Mass = massName;
  MarkSPHArrays(output, markers);
  return true;
}

bool vtkHDF5SnapshotReader::RegionCandidates(std::size_t type, const double bounds[6],
  std::vector<std::pair<long long, long long>>& ranges, std::string& problem)
{
  if (!this->Superclass::RegionCandidates(type, bounds, ranges, problem))
  {
    return false;
  }
  std::vector<long long> starts, counts; // of this type's particles in each part
  long long start = 0;
  for (const auto& partCounts : this->PartCounts)
  {
    starts.push_back(start);
    counts.push_back(partCounts[type]);
    start += partCounts[type];
  }
  // SWIFT writes the table of every cell in each part; where there is none, every particle.
  QuietHDF5 quiet;
  Handle file(H5Fopen(this->FileName.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose);
  if (file.Valid())
  {
    lsi::io::SwiftCellRanges(file, this->TypeNumbers[type], bounds, starts, counts, ranges);
  }
  return true;
}

void vtkHDF5SnapshotReader::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Parts: " << this->Parts.size() << "\n";
}
