// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
// The GADGET binary reader: writes small snapshots with known particles (GadgetWriter.h: field
// by field after GADGET-2's io_header or GADGET-4's own header; format 1 and 2, both byte
// orders, single and double precision, 4- and 8-byte ids, with and without cooling's blocks, one
// file or three) and checks what comes back: every value, the types and their masses (MASS block
// or mass table), the header's field data, the SPH markers, pieces across the files. Then bad
// files: a clear error and an empty output each. With a GADGET-4 HDF5 snapshot as argument
// (../shared's gas sphere), the same particles written as format 1 give the same surface to the
// bit.
#include "vtkGadgetBinaryReader.h"
#include "vtkHDF5SnapshotReader.h"
#include "vtkLevelSetIsosurface.h"

#include "GadgetWriter.h"
#include "MessageCounter.h"
#include "OrderedBytes.h"
#include "PointArraySelection.h"
#include "RefusedFile.h"
#include "TestCheck.h"

#include "vtkAbstractArray.h"
#include "vtkCommand.h"
#include "vtkCompositeDataSet.h"
#include "vtkDataArray.h"
#include "vtkDataArraySelection.h"
#include "vtkFieldData.h"
#include "vtkInformation.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPointSet.h"
#include "vtkPolyData.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkVariant.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <functional>
#include <iostream>
#include <set>
#include <string>
#include <vector>

namespace
{
using lsi::test::Bytes;
using lsi::test::Check;
using lsi::test::Label;
using lsi::test::MessageCounter;
using lsi::test::Particles;
using lsi::test::Record;
using lsi::test::WriteGadget;
using lsi::test::WriteOptions;

// Exactly representable in single precision: distinct for every block, type, particle and
// component.
double Known(int block, int t, int g, int c)
{
  return 1000.0 * t + 2.0 * g + 0.25 * block + 0.125 * c + 1.0;
}

// Gas (7), dark matter (4, equal masses in the table) and stars (3, masses in the MASS block).
Particles KnownParticles(bool doubles, bool ids64, bool extra)
{
  Particles particles;
  particles.Counts = { 7, 4, 0, 0, 3, 0 };
  particles.MassTable = { 0.0, 0.5, 0.0, 0.0, 0.0, 0.0 };
  particles.Time = 0.625;
  particles.Redshift = 0.6;
  particles.BoxSize = 100.0;
  particles.Ids64 = ids64;
  particles.Id = [ids64](int t, int g) {
    return (ids64 ? (std::uint64_t(1) << 40) : 0) + std::uint64_t(100000) * t + g + 1;
  };
  const char* labels[] = { "POS", "VEL", "ID", "MASS", "U", "RHO", "NE", "NH", "HSML" };
  for (int b = 0; b < 9; ++b)
  {
    const std::string label = labels[b];
    const int components = label == "POS" || label == "VEL" ? 3 : 1;
    const bool gasOnly = b >= 4;
    particles.Columns.push_back({ label, components, gasOnly, doubles,
      [b](int t, int g, int c) { return Known(b, t, g, c); } });
  }
  if (extra) // a block of the gas this reader does not know (format 2 only)
  {
    particles.Columns.push_back(
      { "XTRA", 1, true, false, [](int t, int g, int c) { return Known(9, t, g, c); } });
  }
  return particles;
}

std::string Field(vtkDataObject* data, const char* name, int index = 0)
{
  vtkAbstractArray* array = data->GetFieldData()->GetAbstractArray(name);
  return array && array->GetNumberOfValues() > index ? array->GetVariantValue(index).ToString()
                                                     : std::string("(none)");
}

// The largest difference between a type's arrays and the known values (HUGE_VAL if one is
// missing), for particles [begin, begin + n) of the type.
double WorstError(vtkPolyData* out, int t, int begin, bool cooling, bool extra, double tableMass)
{
  double worst = 0.0;
  for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i)
  {
    const int g = begin + static_cast<int>(i);
    double x[3];
    out->GetPoint(i, x);
    for (int c = 0; c < 3; ++c)
    {
      worst = std::max(worst, std::abs(x[c] - Known(0, t, g, c)));
    }
    auto compare = [&](const char* name, int block, int components) {
      vtkDataArray* array = out->GetPointData()->GetArray(name);
      if (!array || array->GetNumberOfComponents() != components)
      {
        worst = HUGE_VAL;
        return;
      }
      for (int c = 0; c < components; ++c)
      {
        worst = std::max(worst, std::abs(array->GetComponent(i, c) - Known(block, t, g, c)));
      }
    };
    compare("Velocities", 1, 3);
    vtkDataArray* masses = out->GetPointData()->GetArray("Masses");
    worst = std::max(worst,
      masses ? std::abs(masses->GetTuple1(i) - (tableMass > 0.0 ? tableMass : Known(3, t, g, 0)))
             : HUGE_VAL);
    if (t == 0)
    {
      compare("InternalEnergy", 4, 1);
      compare("Density", 5, 1);
      compare("SmoothingLength", 8, 1);
      if (cooling)
      {
        compare("ElectronAbundance", 6, 1);
        compare("NeutralHydrogenAbundance", 7, 1);
      }
      if (extra)
      {
        compare("XTRA", 9, 1);
      }
    }
  }
  return worst;
}

bool IdsMatch(vtkPolyData* out, int t, int begin, bool ids64)
{
  vtkDataArray* ids = out->GetPointData()->GetGlobalIds();
  if (!ids || ids->GetNumberOfTuples() != out->GetNumberOfPoints())
  {
    return false;
  }
  const auto id = KnownParticles(false, ids64, false).Id;
  for (vtkIdType i = 0; i < ids->GetNumberOfTuples(); ++i)
  {
    if (static_cast<std::uint64_t>(ids->GetVariantValue(i).ToLongLong()) !=
      id(t, begin + static_cast<int>(i)))
    {
      return false;
    }
  }
  return true;
}

void TestKnownParticles(const WriteOptions& o, bool doubles, bool ids64)
{
  const bool extra = o.Format == 2;
  const std::string what = "format " + std::to_string(o.Format) +
    (o.BigEndian ? ", big-endian" : ", little-endian") + (doubles ? ", double" : ", float") +
    (ids64 ? ", 64-bit ids" : "") + (o.Cooling ? ", cooling" : "") +
    (o.CoolingFlagOnly ? ", cooling flag without its blocks" : "") +
    (o.Gadget4 ? ", GADGET-4's header" : "") +
    (o.Files > 1 ? ", " + std::to_string(o.Files) + " files" : "");
  const std::string base = "gadget_test_" + std::to_string(o.Format) + (o.BigEndian ? "b" : "l") +
    (doubles ? "d" : "f") + (ids64 ? "8" : "4") + (o.Cooling ? "c" : "") +
    (o.CoolingFlagOnly ? "k" : "") + (o.Gadget4 ? "g" : "") + std::to_string(o.Files);
  const Particles particles = KnownParticles(doubles, ids64, extra);
  WriteGadget(base, particles, o);
  // (A snapshot in files is opened from any of them: the last.)
  const std::string open = o.Files > 1 ? base + "." + std::to_string(o.Files - 1) : base;
  Check(vtkGadgetBinaryReader::CanReadFile(open.c_str()), what + ": CanReadFile");
  vtkNew<vtkGadgetBinaryReader> reader;
  reader->SetFileName(open.c_str());
  vtkNew<MessageCounter> messages;
  reader->AddObserver(vtkCommand::WarningEvent, messages);
  reader->AddObserver(vtkCommand::ErrorEvent, messages);
  reader->Update();
  vtkPolyData* gas = vtkPolyData::SafeDownCast(reader->GetOutput());
  Check(messages->Count == 0, what + ": no message (got: " + messages->All + ")");
  Check(!gas || (gas->GetPointData()->GetArray("ElectronAbundance") != nullptr) == o.Cooling,
    what + ": ElectronAbundance read exactly where the file has it");
  Check(gas && gas->GetNumberOfPoints() == 7 && gas->GetNumberOfVerts() == 7,
    what + ": by default the 7 gas particles as vertices");
  if (!gas || gas->GetNumberOfPoints() != 7)
  {
    return;
  }
  const double worst = WorstError(gas, 0, 0, o.Cooling, extra, 0.0);
  Check(worst == 0.0,
    what + ": every gas value read back exactly (worst error " + std::to_string(worst) + ")");
  Check(IdsMatch(gas, 0, 0, ids64), what + ": ParticleIDs the global ids, exactly");
  Check(gas->GetPointData()->GetScalars() &&
      std::string(gas->GetPointData()->GetScalars()->GetName()) == "Density",
    what + ": Density the active scalars");
  Check(Field(gas, "DensityArray") == "Density" &&
      Field(gas, "SmoothingLengthArray") == "SmoothingLength" &&
      Field(gas, "MassArray") == "Masses" && Field(gas, "SPHKernel") == "CubicSpline" &&
      Field(gas, "SupportPerSmoothingLength") == "1",
    what + ": the SPH field marked (GADGET's cubic spline, support = SmoothingLength)");
  Check(std::abs(gas->GetInformation()->Get(vtkDataObject::DATA_TIME_STEP()) - 0.625) < 1e-15,
    what + ": the header's time");
  Check(Field(gas, "BoxSize") == "100" && Field(gas, "Redshift") == "0.6" &&
      Field(gas, "NumPart_Total", 4) == "3" && Field(gas, "MassTable", 1) == "0.5" &&
      Field(gas, "HubbleParam") == (o.Gadget4 ? "(none)" : "0.68") &&
      Field(gas, "NumFilesPerSnapshot") == std::to_string(o.Files) &&
      Field(gas, "Flag_Cooling") ==
        (o.Gadget4                           ? "(none)"
            : o.Cooling || o.CoolingFlagOnly ? "1"
                                             : "0"),
    what + ": the header as field data (BoxSize " + Field(gas, "BoxSize") + ", NumPart_Total[4] " +
      Field(gas, "NumPart_Total", 4) + ")");
  const int precision = gas->GetPoints()->GetDataType() == VTK_DOUBLE ? 8 : 4;
  Check(precision == (doubles ? 8 : 4), what + ": the positions' precision kept");

  // Every type: a block each, named as the HDF5 reader names them, masses from the table or
  // the MASS block.
  Check(reader->GetNumberOfParticleTypeArrays() == 3, what + ": three particle types listed");
  reader->GetParticleTypeSelection()->EnableAllArrays();
  reader->Update();
  auto* blocks = vtkMultiBlockDataSet::SafeDownCast(reader->GetOutput());
  Check(blocks && blocks->GetNumberOfBlocks() == 3, what + ": three blocks for three types");
  if (blocks && blocks->GetNumberOfBlocks() == 3)
  {
    const int types[] = { 0, 1, 4 };
    const char* names[] = { "Gas (PartType0)", "DarkMatter (PartType1)", "Stars (PartType4)" };
    for (unsigned int k = 0; k < 3; ++k)
    {
      auto* block = vtkPolyData::SafeDownCast(blocks->GetBlock(k));
      const char* name = blocks->GetMetaData(k)->Get(vtkCompositeDataSet::NAME());
      const int t = types[k];
      Check(name && std::string(name) == names[k] && block &&
          block->GetNumberOfPoints() == particles.Counts[t],
        what + ": block " + names[k] + " with " + std::to_string(particles.Counts[t]) +
          " particles");
      if (block && block->GetNumberOfPoints() == particles.Counts[t])
      {
        const double error = WorstError(block, t, 0, o.Cooling, extra, particles.MassTable[t]);
        Check(error == 0.0 && IdsMatch(block, t, 0, ids64),
          what + ": " + names[k] + " read back exactly (worst error " + std::to_string(error) +
            ")");
        Check(t == 0 || !block->GetPointData()->GetArray("Density"),
          what + ": " + names[k] + " has no gas arrays");
      }
    }
  }

  // Pieces (as under MPI): three ranks' shares of the gas, together the whole, in order.
  reader->GetParticleTypeSelection()->DisableAllArrays();
  reader->SetParticleTypeStatus("Gas (PartType0)", 1);
  int begin = 0;
  for (int piece = 0; piece < 3; ++piece)
  {
    reader->UpdatePiece(piece, 3, 0);
    vtkPolyData* share = vtkPolyData::SafeDownCast(reader->GetOutput());
    const int n = share ? static_cast<int>(share->GetNumberOfPoints()) : 0;
    Check(share && WorstError(share, 0, begin, o.Cooling, extra, 0.0) == 0.0 &&
        IdsMatch(share, 0, begin, ids64),
      what + ": piece " + std::to_string(piece) + " of 3 holds gas particles from " +
        std::to_string(begin) + ", exactly");
    begin += n;
  }
  Check(
    begin == 7, what + ": the pieces hold every gas particle once (" + std::to_string(begin) + ")");
  for (int p = 0; p < o.Files; ++p)
  {
    std::remove(o.Files > 1 ? (base + "." + std::to_string(p)).c_str() : base.c_str());
  }
}

// Each damaged or foreign file: CanReadFile false (where the file is not a snapshot), an error
// naming the problem, an empty output.
void TestBadFiles()
{
  const Particles particles = KnownParticles(false, false, false);
  WriteOptions one;
  WriteGadget("gadget_bad_source", particles, one);
  std::ifstream in("gadget_bad_source", std::ios::binary);
  const std::vector<char> good(
    (std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  auto variant = [&](const std::string& name, const std::function<void(std::vector<char>&)>& edit) {
    std::vector<char> bytes = good;
    edit(bytes);
    std::ofstream(name, std::ios::binary)
      .write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    return name;
  };
  auto putInt = [](std::vector<char>& bytes, std::size_t at, std::int32_t value) {
    std::memcpy(&bytes[at], &value, 4); // (the written files are in this machine's order)
  };
  struct Case
  {
    std::string What, Path, Expected;
  };
  std::vector<Case> cases = {
    { "missing file", "no_such_gadget_file", "cannot open" },
    { "text file",
      variant("gadget_bad_text",
        [](std::vector<char>& b) {
          const std::string text = "not a snapshot, a line of text that is long enough to probe";
          b.assign(text.begin(), text.end());
        }),
      "not a GADGET binary snapshot" },
    { "truncated file",
      variant("gadget_bad_truncated", [](std::vector<char>& b) { b.resize(b.size() - 10); }),
      "past the end of the file" },
    { "damaged record end",
      variant("gadget_bad_marker",
        [&](std::vector<char>& b) {
          putInt(b, 4 + 256, 255); // the header's closing length
        }),
      "does not end with its length" },
    { "a 200-byte header",
      variant("gadget_bad_header",
        [&](std::vector<char>& b) {
          b.erase(b.begin() + 4 + 200, b.begin() + 4 + 256); // a 200-byte header record
          putInt(b, 0, 200);
          putInt(b, 4 + 200, 200);
        }),
      "GADGET-4's 192" },
    { "negative count",
      variant("gadget_bad_count", [&](std::vector<char>& b) { putInt(b, 4, -7); }),
      "-7 particles" },
    { "positions of another count",
      variant("gadget_bad_positions",
        [&](std::vector<char>& b) {
          putInt(b, 4 + 4, 5); // 5 dark particles in the header, 4 in the blocks
        }),
      "no block of positions" },
  };
  // A snapshot in two files whose second part is missing.
  WriteOptions two;
  two.Files = 2;
  WriteGadget("gadget_bad_parts", particles, two);
  std::remove("gadget_bad_parts.1");
  cases.push_back({ "missing part", "gadget_bad_parts.0", "part gadget_bad_parts.1" });
  for (const Case& c : cases)
  {
    lsi::test::CheckRefusedFile<vtkGadgetBinaryReader>(
      c.Path, c.Expected, c.What == "missing part"); // (its first part is a snapshot's file)
    if (c.Path.rfind("gadget_bad_", 0) == 0)
    {
      std::remove(c.Path.c_str());
    }
  }
  std::remove("gadget_bad_source");
}

// A format-2 block whose size fits no particle count: a warning naming it, the rest read.
void TestLeftOutBlock()
{
  WriteOptions o;
  o.Format = 2;
  WriteGadget("gadget_left_out", KnownParticles(false, false, false), o);
  {
    std::ofstream out("gadget_left_out", std::ios::binary | std::ios::app);
    Bytes junk(false);
    junk.Data = { 'a', 'b', 'c', 'd', 'e' };
    Label(out, "JUNK", junk.Data.size(), false);
    Record(out, junk, false);
  }
  vtkNew<vtkGadgetBinaryReader> reader;
  reader->SetFileName("gadget_left_out");
  vtkNew<MessageCounter> warnings;
  reader->AddObserver(vtkCommand::WarningEvent, warnings);
  reader->Update();
  auto* gas = vtkPolyData::SafeDownCast(reader->GetOutput());
  Check(warnings->Count == 1 && warnings->Last.find("JUNK") != std::string::npos,
    "a block of 5 bytes: one warning naming it (got: " + warnings->All + ")");
  Check(gas && gas->GetNumberOfPoints() == 7 && WorstError(gas, 0, 0, false, false, 0.0) == 0.0,
    "a block of 5 bytes: the other blocks read exactly");
  std::remove("gadget_left_out");
}

// A format-2 snapshot with GADGET-3's INFO block: a block of the stars alone ("STRS", whose size
// fits neither every type nor the gas) read where INFO says, the others as before, no warning.
void TestInfoBlock()
{
  WriteOptions o;
  o.Format = 2;
  o.BigEndian = true;
  o.Info = true;
  Particles particles = KnownParticles(false, false, true);
  Particles::Column stars = { "STRS", 1, false, false,
    [](int t, int g, int c) { return Known(10, t, g, c); } };
  stars.OnlyType = 4;
  particles.Columns.push_back(stars);
  WriteGadget("gadget_info", particles, o);
  vtkNew<vtkGadgetBinaryReader> reader;
  reader->SetFileName("gadget_info");
  vtkNew<MessageCounter> messages;
  reader->AddObserver(vtkCommand::WarningEvent, messages);
  reader->AddObserver(vtkCommand::ErrorEvent, messages);
  reader->UpdateInformation();
  reader->GetParticleTypeSelection()->EnableAllArrays();
  reader->Update();
  auto* blocks = vtkMultiBlockDataSet::SafeDownCast(reader->GetOutput());
  Check(messages->Count == 0, "INFO block: no message (got: " + messages->All + ")");
  auto* gas = blocks ? vtkPolyData::SafeDownCast(blocks->GetBlock(0)) : nullptr;
  auto* star = blocks ? vtkPolyData::SafeDownCast(blocks->GetBlock(2)) : nullptr;
  Check(gas && WorstError(gas, 0, 0, false, true, 0.0) == 0.0,
    "INFO block: the gas read back exactly, XTRA too");
  vtkDataArray* ages = star ? star->GetPointData()->GetArray("STRS") : nullptr;
  double worst = ages && ages->GetNumberOfTuples() == 3 ? 0.0 : HUGE_VAL;
  for (vtkIdType i = 0; ages && i < ages->GetNumberOfTuples() && i < 3; ++i)
  {
    worst = std::max(worst, std::abs(ages->GetTuple1(i) - Known(10, 4, static_cast<int>(i), 0)));
  }
  Check(worst == 0.0 && star && WorstError(star, 4, 0, false, false, 0.0) == 0.0,
    "INFO block: the stars' own block STRS and their other values read exactly");
  Check(!gas || !gas->GetPointData()->GetArray("STRS"), "INFO block: STRS on the stars alone");
  std::remove("gadget_info");
}

// The point array selection on a snapshot in three files (format 2, big-endian, cooling): every
// block listed under its name, the blocks chosen read alone (the others skipped in every part),
// with the values of a full read; dark matter's table masses can be left unread too.
void TestPointArraySelection()
{
  WriteOptions o;
  o.Format = 2;
  o.BigEndian = true;
  o.Cooling = true;
  o.Files = 3;
  WriteGadget("gadget_arrays", KnownParticles(false, false, false), o);
  vtkNew<vtkGadgetBinaryReader> reader;
  reader->SetFileName("gadget_arrays.1");
  const std::set<std::string> gas = { "Density", "ElectronAbundance", "InternalEnergy", "Masses",
    "NeutralHydrogenAbundance", "ParticleIDs", "SmoothingLength", "Velocities" };
  lsi::test::CheckPointArraySelection(reader.Get(), gas, { "Density", "Masses", "SmoothingLength" },
    "three files, gas, the SPH field's arrays");
  lsi::test::CheckPointArraySelection(reader.Get(), gas,
    { "NeutralHydrogenAbundance", "ParticleIDs" }, "three files, gas, no SPH array");
  reader->SetParticleTypeStatus("Gas (PartType0)", 0);
  reader->SetParticleTypeStatus("DarkMatter (PartType1)", 1);
  reader->SetPointArrayStatus("Masses", 0);
  reader->Update();
  auto* dark = vtkPolyData::SafeDownCast(reader->GetOutput());
  Check(dark && dark->GetNumberOfPoints() == 4 &&
      lsi::test::PointArrayNames(dark) == std::set<std::string>{ "ParticleIDs", "Velocities" } &&
      lsi::test::MarkersNameReadArrays(dark),
    "three files, dark matter without Masses: the mass table's left unread, no MassArray marker");
  for (int part = 0; part < 3; ++part)
  {
    std::remove(("gadget_arrays." + std::to_string(part)).c_str());
  }
}

// A real GADGET snapshot (HDF5) written again as format 1: the same particles, arrays and
// markers, so the filter's SPH surface is the same to the bit.
void TestSameSurfaceAsHDF5(const std::string& hdf5)
{
  vtkNew<vtkHDF5SnapshotReader> h5;
  h5->SetFileName(hdf5.c_str());
  h5->Update();
  vtkPolyData* source = vtkPolyData::SafeDownCast(h5->GetOutput());
  Check(source && source->GetNumberOfPoints() > 0, hdf5 + ": read by the HDF5 reader");
  if (!source || source->GetNumberOfPoints() == 0)
  {
    return;
  }
  const int n = static_cast<int>(source->GetNumberOfPoints());
  vtkPointData* pd = source->GetPointData();
  Particles particles;
  particles.Counts = { n, 0, 0, 0, 0, 0 };
  vtkAbstractArray* table = source->GetFieldData()->GetAbstractArray("MassTable");
  particles.MassTable[0] = table ? table->GetVariantValue(0).ToDouble() : 0.0;
  particles.Time = std::stod(Field(source, "Time"));
  particles.BoxSize = std::stod(Field(source, "BoxSize"));
  particles.Id = [&](int, int g) {
    return static_cast<std::uint64_t>(pd->GetGlobalIds()->GetTuple1(g));
  };
  vtkDataArray* positions = source->GetPoints()->GetData();
  const bool pointsDouble = positions->GetDataType() == VTK_DOUBLE;
  auto column = [&](const std::string& label, const char* name, int components) {
    vtkDataArray* array = name ? pd->GetArray(name) : positions;
    if (array)
    {
      particles.Columns.push_back(
        { label, components, label != "POS" && label != "VEL", array->GetDataType() == VTK_DOUBLE,
          [array](int, int g, int c) { return array->GetComponent(g, c); } });
    }
  };
  column("POS", nullptr, 3);
  column("VEL", "Velocities", 3);
  particles.Columns.push_back({ "ID", 1, false, false, nullptr });
  if (particles.MassTable[0] == 0.0)
  {
    column("MASS", "Masses", 1);
  }
  column("U", "InternalEnergy", 1);
  column("RHO", "Density", 1);
  column("HSML", "SmoothingLength", 1);
  WriteGadget("gadget_from_hdf5", particles, WriteOptions());
  vtkNew<vtkGadgetBinaryReader> binary;
  binary->SetFileName("gadget_from_hdf5");
  binary->Update();
  vtkPolyData* copy = vtkPolyData::SafeDownCast(binary->GetOutput());
  Check(copy && copy->GetNumberOfPoints() == n &&
      (copy->GetPoints()->GetDataType() == VTK_DOUBLE) == pointsDouble,
    hdf5 + ": the format-1 copy holds its " + std::to_string(n) + " particles");
  if (!copy || copy->GetNumberOfPoints() != n)
  {
    return;
  }
  auto surface = [](vtkPolyData* particles, double isoValue, vtkPolyData* out) {
    vtkNew<vtkLevelSetIsosurface> filter;
    filter->SetInputData(particles);
    filter->SetIsoValue(isoValue);
    filter->SetOutputTypeToIsopoints();
    filter->SetNumberOfThreads(1);
    filter->Update();
    out->DeepCopy(filter->GetOutput());
    return filter->GetUsedSPHField();
  };
  // (The median density: a surface through the middle of the sphere's particles.)
  std::vector<double> densities(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i)
  {
    densities[i] = pd->GetArray("Density")->GetTuple1(i);
  }
  std::nth_element(densities.begin(), densities.begin() + n / 2, densities.end());
  const double isoValue = densities[n / 2];
  vtkNew<vtkPolyData> a, b;
  const bool sphA = surface(source, isoValue, a);
  const bool sphB = surface(copy, isoValue, b);
  bool same = a->GetNumberOfPoints() > 0 && a->GetNumberOfPoints() == b->GetNumberOfPoints();
  for (vtkIdType i = 0; same && i < a->GetNumberOfPoints(); ++i)
  {
    double p[3], q[3];
    a->GetPoint(i, p);
    b->GetPoint(i, q);
    same = p[0] == q[0] && p[1] == q[1] && p[2] == q[2];
  }
  Check(sphA && sphB, hdf5 + ": both runs on the SPH field the markers describe");
  Check(a->GetNumberOfPoints() >= 100, hdf5 + ": a surface of 100 isopoints or more");
  Check(same,
    hdf5 + ": the same " + std::to_string(a->GetNumberOfPoints()) +
      " isopoints from the format-1 copy as from the HDF5 file (" +
      std::to_string(b->GetNumberOfPoints()) + ")");
  std::cout << hdf5 << ": " << a->GetNumberOfPoints() << " isopoints at density " << isoValue
            << ", the same from both files\n";
  std::remove("gadget_from_hdf5");
}
} // namespace

int main(int argc, char* argv[])
{
  for (int format : { 1, 2 })
  {
    for (bool big : { false, true })
    {
      WriteOptions o;
      o.Format = format;
      o.BigEndian = big;
      TestKnownParticles(o, false, false);
      o.Cooling = true;
      TestKnownParticles(o, true, true);
      o.Files = 3;
      TestKnownParticles(o, big, !big);
    }
  }
  WriteOptions flagOnly; // format 1: the header says cooling, the blocks go U, RHO, HSML
  flagOnly.CoolingFlagOnly = true;
  TestKnownParticles(flagOnly, false, false);
  for (int format : { 1, 2 }) // GADGET-4's own header, its snapshot in three files
  {
    WriteOptions gadget4;
    gadget4.Gadget4 = true;
    gadget4.Format = format;
    gadget4.BigEndian = format == 2;
    gadget4.Files = 3;
    TestKnownParticles(gadget4, format == 2, format == 2);
  }
  TestBadFiles();
  TestLeftOutBlock();
  TestInfoBlock();
  TestPointArraySelection();
  if (argc > 1)
  {
    TestSameSurfaceAsHDF5(argv[1]);
  }
  std::cout << (lsi::test::Failures() ? "GADGET binary reader tests FAILED\n"
                                      : "GADGET binary reader tests passed\n");
  return lsi::test::Failures() ? EXIT_FAILURE : EXIT_SUCCESS;
}
