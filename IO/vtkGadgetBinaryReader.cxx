// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkGadgetBinaryReader.h"

#include "ByteOrder.h"
#include "GadgetBinaryLayout.h"

#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkIdTypeArray.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"

#include <algorithm>
#include <cstdint>
#include <fstream>

vtkStandardNewMacro(vtkGadgetBinaryReader);

namespace gadget = lsi::gadget;

struct vtkGadgetBinaryReader::Internals
{
  struct Part
  {
    std::string File;
    gadget::FileLayout Layout;
  };
  std::vector<Part> Parts;
  std::vector<int> TypeNumbers; // GADGET type of each listed type
};

namespace
{
bool ReadLayoutOf(const std::string& name, gadget::FileLayout& layout, std::string& problem)
{
  std::ifstream file(name, std::ios::binary);
  if (!file)
  {
    problem = "cannot open the file";
    return false;
  }
  file.seekg(0, std::ios::end);
  const std::uint64_t size = static_cast<std::uint64_t>(file.tellg());
  return gadget::ReadLayout(file, size, layout, problem);
}

// The blocks covering `type`: what a part holds for it, in order.
std::string BlocksOf(const gadget::FileLayout& layout, int type)
{
  std::string list;
  for (const gadget::Block& block : layout.Blocks)
  {
    if (block.Covers[type])
    {
      list += block.Name + "/" + std::to_string(block.Components) + "x" +
        std::to_string(block.ValueBytes) + " ";
    }
  }
  return list;
}

// The point arrays the reader gives for particles of `type`: its blocks' names but the
// positions', and Masses (from the block or the mass table).
std::vector<std::string> PointArrayNames(const gadget::FileLayout& layout, int type)
{
  std::vector<std::string> arrays;
  for (const gadget::Block& block : layout.Blocks)
  {
    if (block.Covers[type] && block.Name != "Coordinates")
    {
      arrays.push_back(block.Name);
    }
  }
  if (std::find(arrays.begin(), arrays.end(), "Masses") == arrays.end())
  {
    arrays.push_back("Masses");
  }
  return arrays;
}

void AddField(vtkFieldData* fields, const char* name, const std::vector<double>& values)
{
  vtkNew<vtkDoubleArray> array;
  array->SetName(name);
  for (double value : values)
  {
    array->InsertNextValue(value);
  }
  fields->AddArray(array);
}

// Header fields under the names of the HDF5 snapshots' Header attributes (GADGET-4's own header
// has no flags and no cosmology, as its HDF5 Header; its totals are 64-bit).
void HeaderToFieldData(const gadget::Header& head, vtkFieldData* fields)
{
  std::vector<double> thisFile, total, low, high; // (the totals, and their 32-bit words)
  for (int t = 0; t < gadget::NumberOfTypes; ++t)
  {
    thisFile.push_back(static_cast<double>(head.ThisFile[t]));
    total.push_back(static_cast<double>(head.Total[t]));
    low.push_back(static_cast<double>(head.Total[t] & 0xffffffffLL));
    high.push_back(static_cast<double>(head.Total[t] >> 32));
  }
  AddField(fields, "NumPart_ThisFile", thisFile);
  AddField(fields, "NumPart_Total", head.Gadget4 ? total : low);
  AddField(fields, "MassTable", std::vector<double>(head.MassTable.begin(), head.MassTable.end()));
  AddField(fields, "Time", { head.Time });
  AddField(fields, "Redshift", { head.Redshift });
  AddField(fields, "BoxSize", { head.BoxSize });
  AddField(fields, "NumFilesPerSnapshot", { static_cast<double>(head.NumFiles) });
  if (head.Gadget4)
  {
    return;
  }
  AddField(fields, "NumPart_Total_HighWord", high);
  AddField(fields, "Omega0", { head.Omega0 });
  AddField(fields, "OmegaLambda", { head.OmegaLambda });
  AddField(fields, "HubbleParam", { head.HubbleParam });
  AddField(fields, "Flag_Sfr", { static_cast<double>(head.FlagSfr) });
  AddField(fields, "Flag_Feedback", { static_cast<double>(head.FlagFeedback) });
  AddField(fields, "Flag_Cooling", { static_cast<double>(head.FlagCooling) });
  AddField(fields, "Flag_StellarAge", { static_cast<double>(head.FlagStellarAge) });
  AddField(fields, "Flag_Metals", { static_cast<double>(head.FlagMetals) });
  AddField(fields, "Flag_Entropy_ICs", { static_cast<double>(head.FlagEntropyICs) });
}

// Swaps each `valueBytes`-byte value of `bytes` in place.
void SwapValues(char* bytes, std::size_t count, int valueBytes)
{
  for (std::size_t i = 0; i < count; ++i)
  {
    std::reverse(bytes + i * valueBytes, bytes + (i + 1) * valueBytes);
  }
}

// A new array for `block`'s values of `count` particles.
vtkSmartPointer<vtkDataArray> NewArray(const gadget::Block& block, vtkIdType count)
{
  vtkSmartPointer<vtkDataArray> array;
  if (block.Integer)
  {
    array = vtkSmartPointer<vtkIdTypeArray>::New();
  }
  else if (block.ValueBytes == 4)
  {
    array = vtkSmartPointer<vtkFloatArray>::New();
  }
  else
  {
    array = vtkSmartPointer<vtkDoubleArray>::New();
  }
  array->SetName(block.Name.c_str());
  array->SetNumberOfComponents(block.Components);
  array->SetNumberOfTuples(count);
  return array;
}

// Reads `count` particles' values of `block` from `offset` into `array` from tuple `first`.
bool ReadValues(std::ifstream& file, const gadget::Block& block, bool bigEndian,
  std::uint64_t offset, vtkIdType count, vtkDataArray* array, vtkIdType first)
{
  const std::size_t values = static_cast<std::size_t>(count) * block.Components;
  const std::size_t bytes = values * block.ValueBytes;
  const bool swap = bigEndian != lsi::HostIsBigEndian();
  file.seekg(static_cast<std::streamoff>(offset));
  if (!block.Integer)
  {
    char* target = static_cast<char*>(array->GetVoidPointer(first * block.Components));
    if (!file.read(target, static_cast<std::streamsize>(bytes)))
    {
      return false;
    }
    if (swap)
    {
      SwapValues(target, values, block.ValueBytes);
    }
    return true;
  }
  std::vector<char> raw(bytes);
  if (!file.read(raw.data(), static_cast<std::streamsize>(bytes)))
  {
    return false;
  }
  auto* ids = static_cast<vtkIdTypeArray*>(array);
  for (std::size_t i = 0; i < values; ++i)
  {
    const char* at = raw.data() + i * block.ValueBytes;
    const std::uint64_t id = block.ValueBytes == 4 ? lsi::FromBytes<std::uint32_t>(at, bigEndian)
                                                   : lsi::FromBytes<std::uint64_t>(at, bigEndian);
    ids->SetValue(first * block.Components + static_cast<vtkIdType>(i), static_cast<vtkIdType>(id));
  }
  return true;
}
} // namespace

vtkGadgetBinaryReader::vtkGadgetBinaryReader()
  : Internal(new Internals)
{
}

vtkGadgetBinaryReader::~vtkGadgetBinaryReader() = default;

bool vtkGadgetBinaryReader::CanReadFile(const char* name)
{
  gadget::FileLayout layout;
  std::string problem;
  return name && ReadLayoutOf(name, layout, problem);
}

bool vtkGadgetBinaryReader::ReadMetaData(
  std::vector<ParticleType>& types, double& time, vtkFieldData* fields, std::string& problem)
{
  Internals& internal = *this->Internal;
  internal = Internals();
  gadget::FileLayout opened;
  if (!ReadLayoutOf(this->FileName, opened, problem))
  {
    return false;
  }
  const gadget::Header& head = opened.Head;
  time = head.Time;
  HeaderToFieldData(head, fields);
  // More files than any run writes is a damaged header.
  if (head.NumFiles > 1000000)
  {
    problem = "the header says the snapshot is split over " + std::to_string(head.NumFiles) +
      " files, more than any run writes (damaged?)";
    return false;
  }
  std::vector<std::string> files = { this->FileName };
  if (head.NumFiles > 1)
  {
    files = PartFileNames(this->FileName, head.NumFiles);
    if (files.empty())
    {
      problem = "the snapshot is split over " + std::to_string(head.NumFiles) +
        " files (the header's num_files), but this file is not named NAME.K";
      return false;
    }
  }
  std::string leftOut; // blocks not understood, in any part
  for (const std::string& name : files)
  {
    Internals::Part part;
    part.File = name;
    if (name == this->FileName)
    {
      part.Layout = opened;
    }
    else if (!ReadLayoutOf(name, part.Layout, problem))
    {
      problem = "part " + name + " of the snapshot: " + problem;
      return false;
    }
    if (part.Layout.Head.NumFiles != head.NumFiles)
    {
      problem = "part " + name + " says the snapshot has " +
        std::to_string(part.Layout.Head.NumFiles) + " files, this one " +
        std::to_string(head.NumFiles);
      return false;
    }
    for (const std::string& block : part.Layout.LeftOut)
    {
      leftOut += (leftOut.empty() ? "" : ", ") + block;
    }
    internal.Parts.push_back(std::move(part));
  }
  if (!leftOut.empty())
  {
    const std::string why = "their sizes fitting no particle type's count (or a name met twice)";
    this->WarnOnce("blocks left out, " + why + ": " + leftOut);
  }
  std::vector<long long> totals(gadget::NumberOfTypes, 0);
  std::vector<std::vector<std::string>> arraysOf(gadget::NumberOfTypes);
  for (int t = 0; t < gadget::NumberOfTypes; ++t)
  {
    const Internals::Part* first = nullptr; // the first part with particles of this type
    for (const Internals::Part& part : internal.Parts)
    {
      const long long count = part.Layout.Head.ThisFile[t];
      if (count == 0)
      {
        continue;
      }
      totals[t] += count;
      first = first ? first : &part;
      // Every part must hold the same arrays for a type: an array read from some parts only
      // would leave other particles' values unset.
      if (BlocksOf(part.Layout, t) != BlocksOf(first->Layout, t))
      {
        problem = "part " + part.File + " holds other blocks for " + PartTypeName(t) + " (" +
          BlocksOf(part.Layout, t) + ") than part " + first->File + " (" +
          BlocksOf(first->Layout, t) + ")";
        return false;
      }
    }
    if (first)
    {
      arraysOf[t] = PointArrayNames(first->Layout, t);
    }
  }
  return ListPartTypes(totals, arraysOf, types, internal.TypeNumbers, problem);
}

bool vtkGadgetBinaryReader::ReadParticles(
  std::size_t type, long long begin, long long end, vtkPolyData* output, std::string& problem)
{
  const Internals& internal = *this->Internal;
  const int number = internal.TypeNumbers[type];
  const vtkIdType count = static_cast<vtkIdType>(end - begin);
  std::vector<vtkSmartPointer<vtkDataArray>> arrays;
  const gadget::FileLayout* firstLayout = nullptr;
  long long filled = 0;    // particles of this range read so far
  long long partStart = 0; // index of the part's first particle of this type in the snapshot
  for (const Internals::Part& part : internal.Parts)
  {
    const gadget::FileLayout& layout = part.Layout;
    const long long inPart = layout.Head.ThisFile[number];
    const long long from = std::max(begin, partStart), to = std::min(end, partStart + inPart);
    partStart += inPart;
    if (from >= to)
    {
      continue;
    }
    if (!firstLayout)
    {
      // One array per block of this type (every part holds the same), none for the blocks the
      // user left unread (PointArraySelection); the positions are always read.
      firstLayout = &layout;
      for (const gadget::Block& block : layout.Blocks)
      {
        if (block.Covers[number])
        {
          const bool read = block.Name == "Coordinates" || this->ReadsArray(block.Name);
          arrays.push_back(read ? NewArray(block, count) : nullptr);
        }
      }
    }
    std::ifstream file(part.File, std::ios::binary);
    std::size_t a = 0;
    for (const gadget::Block& block : layout.Blocks)
    {
      if (!block.Covers[number])
      {
        continue;
      }
      vtkDataArray* array = arrays[a++];
      if (!array)
      {
        continue; // left unread
      }
      const std::uint64_t offset =
        gadget::ValueOffset(layout, block, number, from - (partStart - inPart));
      if (!file ||
        !ReadValues(file, block, layout.BigEndian, offset, static_cast<vtkIdType>(to - from), array,
          static_cast<vtkIdType>(filled)))
      {
        problem = "cannot read block " + block.Name + " of " + part.File + " (truncated file?)";
        return false;
      }
    }
    filled += to - from;
  }

  vtkPointData* pointData = output->GetPointData();
  vtkNew<vtkPoints> points;
  bool haveMasses = false;
  SPHMarkers markers; // GADGET's cubic spline, whose support radius is its smoothing length
  for (vtkDataArray* array : arrays)
  {
    if (!array)
    {
      continue;
    }
    const std::string name = array->GetName();
    if (name == "Coordinates")
    {
      points->SetData(array);
      continue;
    }
    if (name == "ParticleIDs")
    {
      pointData->SetGlobalIds(array);
      continue;
    }
    pointData->AddArray(array);
    haveMasses = haveMasses || name == "Masses";
    markers.Density = name == "Density" ? name : markers.Density;
    markers.SmoothingLength = name == "SmoothingLength" ? name : markers.SmoothingLength;
  }
  if (!firstLayout || points->GetNumberOfPoints() != count)
  {
    problem = "no positions for " + PartTypeName(number);
    return false;
  }
  output->SetPoints(points);
  // The mass table's 0 means "in the MASS block": a type with neither has no masses (not 0).
  const double tableMass = firstLayout->Head.MassTable[number];
  if (!haveMasses && tableMass > 0.0 && this->ReadsArray("Masses"))
  {
    AddTableMasses(pointData, count, tableMass);
    haveMasses = true;
  }
  markers.Mass = haveMasses ? "Masses" : "";
  MarkSPHArrays(output, markers);
  return true;
}

void vtkGadgetBinaryReader::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Parts: " << this->Internal->Parts.size() << "\n";
}
