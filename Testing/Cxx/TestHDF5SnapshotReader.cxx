// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
// The HDF5 snapshot reader on the snapshots make_test_snapshots.py writes (every value known):
// a GADGET-4 snapshot in two files, an AREPO-style file without smoothing lengths, each class of
// bad file, the kernels SWIFT and GADGET-4 name; then the real SWIFT snapshot of Data/SWIFT.
//   TestHDF5SnapshotReader TEST_SNAPSHOT_DIR SWIFT_FILE
#include "vtkHDF5SnapshotReader.h"

#include "MessageCounter.h"
#include "PointArraySelection.h"
#include "RefusedFile.h"
#include "TestCheck.h"

#include "vtkCommand.h"
#include "vtkCompositeDataSet.h"
#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkInformation.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkStringArray.h"

#include <cmath>
#include <cstdlib>
#include <iostream>
#include <set>
#include <string>

namespace
{
using lsi::test::Check;
using lsi::test::MessageCounter;

// make_test_snapshots.py's gas_value.
double GasValue(int i, int column)
{
  return 1.0 + 0.01 * i + 10.0 * column;
}

// A string field array's values, joined by commas ("" if there is none).
std::string FieldString(vtkPolyData* data, const char* name)
{
  vtkStringArray* array =
    data ? vtkStringArray::SafeDownCast(data->GetFieldData()->GetAbstractArray(name)) : nullptr;
  std::string joined;
  for (vtkIdType k = 0; array && k < array->GetNumberOfValues(); ++k)
  {
    joined += (k ? "," : "") + array->GetValue(k);
  }
  return joined;
}

double FieldNumber(vtkPolyData* data, const char* name, int index = 0)
{
  vtkDataArray* array = data->GetFieldData()->GetArray(name);
  return array && array->GetNumberOfTuples() > index ? array->GetTuple1(index) : NAN;
}

// Gas particles [first, first + count) of the GADGET-4 snapshot, checked value by value.
void CheckGas(vtkPolyData* gas, int first, int count, const std::string& what)
{
  Check(gas && gas->GetNumberOfPoints() == count && gas->GetNumberOfVerts() == count,
    what + ": " + std::to_string(count) + " gas particles as vertices");
  if (!gas || gas->GetNumberOfPoints() != count)
  {
    return;
  }
  vtkDataArray* density = gas->GetPointData()->GetArray("Density");
  vtkDataArray* smoothing = gas->GetPointData()->GetArray("SmoothingLength");
  vtkDataArray* ids = gas->GetPointData()->GetGlobalIds();
  vtkDataArray* velocity = gas->GetPointData()->GetArray("Velocities");
  Check(density && smoothing && ids && velocity && velocity->GetNumberOfComponents() == 3,
    what + ": Density, SmoothingLength, Velocities (3 components), ParticleIDs as global ids");
  if (!density || !smoothing || !ids || !velocity)
  {
    return;
  }
  double worst = 0.0;
  for (int k = 0; k < count; ++k)
  {
    const int i = first + k;
    double x[3];
    gas->GetPoint(k, x);
    for (int d = 0; d < 3; ++d)
    {
      worst = std::max(worst, std::abs(x[d] - GasValue(i, d)));
      worst = std::max(worst, std::abs(velocity->GetComponent(k, d) + GasValue(i, d)) / 1e4);
    }
    worst = std::max(worst, std::abs(density->GetTuple1(k) - GasValue(i, 3)) / 1e4);
    worst = std::max(worst, std::abs(smoothing->GetTuple1(k) - GasValue(i, 5)) / 1e4);
    worst = std::max(worst, std::abs(ids->GetTuple1(k) - (1000 + i)));
  }
  Check(worst < 1e-6, what + ": every value in place (worst " + std::to_string(worst) + ")");
}

void TestMultiFileGadget(const std::string& dir)
{
  for (const char* file : { "gadget4_multi.0.hdf5", "gadget4_multi.1.hdf5" })
  {
    const std::string path = dir + "/" + file;
    Check(vtkHDF5SnapshotReader::CanReadFile(path.c_str()), path + ": CanReadFile");
    vtkNew<vtkHDF5SnapshotReader> reader;
    reader->SetFileName(path.c_str());
    reader->Update();
    vtkPolyData* gas = vtkPolyData::SafeDownCast(reader->GetOutput());
    CheckGas(gas, 0, 50, path + " (both files, gas by default)");
    if (!gas)
    {
      continue;
    }
    Check(gas->GetPointData()->GetScalars() &&
        std::string(gas->GetPointData()->GetScalars()->GetName()) == "Density",
      path + ": Density is the active scalars");
    Check(FieldString(gas, "DensityArray") == "Density" &&
        FieldString(gas, "SmoothingLengthArray") == "SmoothingLength",
      path + ": the density and smoothing-length arrays are named in field data");
    Check(FieldString(gas, "MassArray") == "Masses" &&
        FieldString(gas, "SPHKernel") == "CubicSpline" &&
        FieldNumber(gas, "SupportPerSmoothingLength") == 1.0,
      path + ": GADGET's SPH field marked: masses, cubic spline, h is the support");
    vtkDataArray* masses = gas->GetPointData()->GetArray("Masses");
    Check(masses && masses->GetRange()[0] == 0.25 && masses->GetRange()[1] == 0.25,
      path + ": gas Masses from its dataset");
    Check(FieldNumber(gas, "Time") == 2.5 && FieldNumber(gas, "BoxSize") == 10.0 &&
        gas->GetInformation()->Get(vtkDataObject::DATA_TIME_STEP()) == 2.5,
      path + ": Time 2.5 and BoxSize 10 from the Header");

    // Two types: a multiblock; dark matter's masses from the MassTable.
    Check(reader->GetNumberOfParticleTypeArrays() == 2, path + ": two particle types listed");
    reader->SetParticleTypeStatus(vtkHDF5SnapshotReader::ParticleTypeName(1).c_str(), 1);
    reader->Update();
    vtkMultiBlockDataSet* blocks = vtkMultiBlockDataSet::SafeDownCast(reader->GetOutput());
    Check(blocks && blocks->GetNumberOfBlocks() == 2, path + ": gas and dark matter as 2 blocks");
    if (blocks && blocks->GetNumberOfBlocks() == 2)
    {
      vtkPolyData* dark = vtkPolyData::SafeDownCast(blocks->GetBlock(1));
      vtkDataArray* darkMasses = dark ? dark->GetPointData()->GetArray("Masses") : nullptr;
      Check(dark && dark->GetNumberOfPoints() == 40 && darkMasses &&
          darkMasses->GetRange()[0] == 0.5 && darkMasses->GetRange()[1] == 0.5,
        path + ": 40 dark-matter particles with Masses 0.5 from the MassTable");
      Check(std::string(blocks->GetMetaData(1u)->Get(vtkCompositeDataSet::NAME())) ==
          "DarkMatter (PartType1)",
        path + ": the block is named after its type");
    }
  }

  // Pieces, as MPI ranks ask for them: two halves, one across the file boundary.
  vtkNew<vtkHDF5SnapshotReader> reader;
  reader->SetFileName((dir + "/gadget4_multi.0.hdf5").c_str());
  for (int piece = 0; piece < 2; ++piece)
  {
    reader->UpdatePiece(piece, 2, 0);
    CheckGas(vtkPolyData::SafeDownCast(reader->GetOutput()), 25 * piece, 25,
      "piece " + std::to_string(piece) + " of 2");
  }
  reader->UpdatePiece(1, 3, 0);
  CheckGas(vtkPolyData::SafeDownCast(reader->GetOutput()), 16, 17, "piece 1 of 3");
  // More pieces than particles: the empty pieces read nothing and report no error.
  vtkNew<MessageCounter> errors;
  reader->AddObserver(vtkCommand::ErrorEvent, errors);
  long long total = 0;
  for (int piece = 0; piece < 64; ++piece)
  {
    reader->UpdatePiece(piece, 64, 0);
    total +=
      reader->GetOutput() ? vtkPolyData::SafeDownCast(reader->GetOutput())->GetNumberOfPoints() : 0;
  }
  Check(total == 50 && errors->Count == 0,
    "64 pieces of 50 particles: all read once, no error (got " + std::to_string(total) + ", " +
      std::to_string(errors->Count) + " errors)");
}

void TestArepoLike(const std::string& dir)
{
  const std::string path = dir + "/arepo_like.hdf5";
  vtkNew<vtkHDF5SnapshotReader> reader;
  reader->SetFileName(path.c_str());
  reader->Update();
  vtkPolyData* gas = vtkPolyData::SafeDownCast(reader->GetOutput());
  Check(gas && gas->GetNumberOfPoints() == 60, path + ": 60 gas particles");
  if (!gas)
  {
    return;
  }
  Check(FieldString(gas, "SmoothingLengthArray").empty() &&
      FieldString(gas, "DensityArray") == "Density",
    path + ": no smoothing-length array named, the density named");
  Check(FieldNumber(gas, "BoxSize", 2) == 6.0 && FieldNumber(gas, "Time") == 0.5,
    path + ": BoxSize as a 3-vector, Time 0.5");
  reader->SetParticleTypeStatus("Gas (PartType0)", 0);
  reader->SetParticleTypeStatus("Stars (PartType4)", 1);
  reader->Update();
  vtkPolyData* stars = vtkPolyData::SafeDownCast(reader->GetOutput());
  Check(stars && stars->GetNumberOfPoints() == 7 &&
      stars->GetPointData()->GetArray("GFM_StellarFormationTime"),
    path + ": stars alone: 7, with their formation times");
}

// EAGLE's gas masses are `Mass`; a MassTable of zeros gives no masses (GADGET's "in the file"),
// so dark matter without a mass dataset has none: before, it got Masses of 0, and the gas too
// (beside its Mass), which the SPH field summed to a field of zeros.
void TestEagleLike(const std::string& dir)
{
  const std::string path = dir + "/eagle_like.hdf5";
  vtkNew<vtkHDF5SnapshotReader> reader;
  reader->SetFileName(path.c_str());
  reader->Update();
  vtkPolyData* gas = vtkPolyData::SafeDownCast(reader->GetOutput());
  vtkDataArray* mass = gas ? gas->GetPointData()->GetArray("Mass") : nullptr;
  Check(gas && gas->GetNumberOfPoints() == 20 && mass && mass->GetRange()[0] == 0.25 &&
      !gas->GetPointData()->GetArray("Masses") && FieldString(gas, "MassArray") == "Mass",
    path + ": the gas's Mass read and marked, no Masses made (got MassArray '" +
      (gas ? FieldString(gas, "MassArray") : std::string()) + "')");
  reader->SetParticleTypeStatus("Gas (PartType0)", 0);
  reader->SetParticleTypeStatus("DarkMatter (PartType1)", 1);
  reader->Update();
  vtkPolyData* dark = vtkPolyData::SafeDownCast(reader->GetOutput());
  Check(dark && dark->GetNumberOfPoints() == 15 && !dark->GetPointData()->GetArray("Masses") &&
      FieldString(dark, "MassArray").empty(),
    path + ": dark matter with a MassTable mass of 0 and no dataset: no masses");
}

void TestBadFiles(const std::string& dir)
{
  struct Case
  {
    const char* File;
    const char* Expected;
    bool Readable; // CanReadFile may say yes: the problem shows only when reading
  };
  const Case cases[] = {
    { "no_such_file.hdf5", "cannot open the file", false },
    { "bad_text.hdf5", "not an HDF5 file", false },
    { "bad_not_snapshot.hdf5", "no Header group", false },
    { "bad_truncated.hdf5", "", false },
    { "bad_inconsistent.hdf5", "has 19 entries, but the file counts 20", true },
    { "bad_missing_part.0.hdf5", "bad_missing_part.1.hdf5 of the snapshot is missing", true },
    // Found by FuzzHDF5SnapshotReader: a float-to-integer overflow, a write past a 2-element
    // array, and a read of 5 columns into an array of 3.
    { "bad_count.hdf5", "holds -inf, not a particle count", true },
    { "bad_files.hdf5", "NumFilesPerSnapshot is nan, not a number of files", true },
    { "bad_rank.hdf5", "has no Coordinates (N x 3) dataset", true },
    { "bad_columns.0.hdf5", "has 5 columns, but 3 in the first part", true },
    // Found in review: rows left unset when a dataset is read from one file and not another.
    { "bad_types.0.hdf5", "is a per-particle numeric array, but not in an earlier part", true },
  };
  for (const Case& c : cases)
  {
    const std::string path = dir + "/" + c.File;
    const std::string error =
      lsi::test::CheckRefusedFile<vtkHDF5SnapshotReader>(path, c.Expected, c.Readable);
    const std::size_t quote = error.find('\'');
    std::cout << c.File << " -> " << (quote == std::string::npos ? error : error.substr(quote))
              << "\n";
  }
}

// The point array selection: every per-particle dataset listed (Masses also where the MassTable
// gives it), and the arrays chosen read alone, with the values of a full read.
void TestPointArraySelection(const std::string& dir)
{
  const std::string path = dir + "/gadget4_multi.1.hdf5";
  vtkNew<vtkHDF5SnapshotReader> reader;
  reader->SetFileName(path.c_str());
  const std::set<std::string> gas = { "Density", "InternalEnergy", "Masses", "ParticleIDs",
    "SmoothingLength", "Velocities" };
  lsi::test::CheckPointArraySelection(reader.Get(), gas, { "Density", "Masses", "SmoothingLength" },
    path + ", gas, the SPH field's arrays");
  lsi::test::CheckPointArraySelection(
    reader.Get(), gas, { "ParticleIDs", "Velocities" }, path + ", gas, no SPH array");
  reader->SetParticleTypeStatus("Gas (PartType0)", 0);
  reader->SetParticleTypeStatus("DarkMatter (PartType1)", 1);
  // The list holds every type's arrays; dark matter has three of them.
  reader->Update();
  auto* dark = vtkPolyData::SafeDownCast(reader->GetOutput());
  Check(dark &&
      lsi::test::PointArrayNames(dark) ==
        std::set<std::string>{ "Masses", "ParticleIDs", "Velocities" },
    path + ": dark matter's arrays, Masses from the MassTable");
  reader->SetPointArrayStatus("Masses", 0);
  reader->Update();
  dark = vtkPolyData::SafeDownCast(reader->GetOutput());
  Check(dark && dark->GetNumberOfPoints() == 40 && !dark->GetPointData()->GetArray("Masses") &&
      lsi::test::MarkersNameReadArrays(dark),
    path + ": dark matter without Masses: the MassTable's left unread, no MassArray marker");

  // A dataset the reader must refuse can be left unread: the rest of the snapshot reads.
  vtkNew<vtkHDF5SnapshotReader> damaged;
  damaged->SetFileName((dir + "/bad_columns.0.hdf5").c_str());
  damaged->UpdateInformation();
  damaged->SetPointArrayStatus("Velocities", 0);
  vtkNew<MessageCounter> errors;
  damaged->AddObserver(vtkCommand::ErrorEvent, errors);
  damaged->Update();
  auto* rest = vtkPolyData::SafeDownCast(damaged->GetOutput());
  Check(errors->Count == 0 && rest && rest->GetNumberOfPoints() == 20 &&
      !rest->GetPointData()->GetArray("Velocities") && rest->GetPointData()->GetArray("Density"),
    "bad_columns.0.hdf5 without its Velocities (5 columns in one part, 3 in the other): the "
    "20 particles read, no error");
}

// Header attributes that are arrays of strings keep every value (the reader used to read them
// into a buffer for one string, which overflowed).
void TestStringArrays(const std::string& dir)
{
  const std::string path = dir + "/string_arrays.hdf5";
  vtkNew<vtkHDF5SnapshotReader> reader;
  reader->SetFileName(path.c_str());
  reader->Update();
  vtkPolyData* gas = vtkPolyData::SafeDownCast(reader->GetOutput());
  Check(gas && gas->GetNumberOfPoints() == 10, path + ": 10 gas particles");
  Check(FieldString(gas, "Fixed") == "one,three",
    path + ": fixed-length strings (got " + FieldString(gas, "Fixed") + ")");
  Check(FieldString(gas, "Variable") == "alpha,beta,gamma",
    path + ": variable-length strings (got " + FieldString(gas, "Variable") + ")");
}

// The kernel each SWIFT name and each GADGET-4 Config flag marks, with SWIFT's support per h
// (the file's Kernel gamma, else the named kernel's); a name no code writes is marked as
// written, with a warning (the filter warns too); GADGET-4's WENDLAND_BIAS_CORRECTION warns that
// the stored Density is not the summed field.
void TestKernelMarkers(const std::string& dir)
{
  const struct
  {
    std::string File, Marker;
    double Support;
    std::string Warning = std::string();
  } cases[] = { { "kernel_swift_0.hdf5", "CubicSpline", 1.825742 },
    { "kernel_swift_1.hdf5", "QuarticSpline", 2.018932 },
    { "kernel_swift_2.hdf5", "QuinticSpline", 2.195775 },
    { "kernel_swift_3.hdf5", "WendlandC2", 1.936492 },
    { "kernel_swift_4.hdf5", "WendlandC4", 2.207940 },
    { "kernel_swift_5.hdf5", "WendlandC6", 2.449490 },
    { "kernel_swift_7.hdf5", "WendlandC4", 2.207940 }, // no Kernel gamma: the kernel's own
    { "kernel_gadget4_WENDLAND_C2_KERNEL.hdf5", "WendlandC2", 1.0 },
    { "kernel_gadget4_WENDLAND_C4_KERNEL.hdf5", "WendlandC4", 1.0 },
    { "kernel_gadget4_WENDLAND_C6_KERNEL.hdf5", "WendlandC6", 1.0 },
    { "kernel_swift_6.hdf5", "Gaussian", 3.0, "'Gaussian'" },
    { "kernel_gadget4_bias.hdf5", "WendlandC2", 1.0, "WENDLAND_BIAS_CORRECTION" } };
  for (const auto& c : cases)
  {
    const std::string path = dir + "/" + c.File;
    vtkNew<vtkHDF5SnapshotReader> reader;
    reader->SetFileName(path.c_str());
    vtkNew<MessageCounter> warnings;
    reader->AddObserver(vtkCommand::WarningEvent, warnings);
    reader->Update();
    vtkPolyData* gas = vtkPolyData::SafeDownCast(reader->GetOutput());
    const bool warned = !c.Warning.empty();
    Check(gas && gas->GetNumberOfPoints() == 10 && FieldString(gas, "SPHKernel") == c.Marker &&
        std::abs(FieldNumber(gas, "SupportPerSmoothingLength") - c.Support) < 1e-6 &&
        warnings->Count == (warned ? 1 : 0) &&
        (!warned || warnings->Last.find(c.Warning) != std::string::npos),
      path + ": marked " + c.Marker + ", support " + std::to_string(c.Support) + " h (got '" +
        (gas ? FieldString(gas, "SPHKernel") : std::string()) + "', " +
        std::to_string(warnings->Count) + " warnings)");
  }
}

// A SWIFT subsampled snapshot: read, with one warning that its gas is a tenth of the run's
// (a field summed from it is not the simulation's), once however often it is read.
void TestSubsampled(const std::string& dir)
{
  const std::string path = dir + "/swift_subsampled.hdf5";
  vtkNew<vtkHDF5SnapshotReader> reader;
  reader->SetFileName(path.c_str());
  vtkNew<MessageCounter> warnings;
  reader->AddObserver(vtkCommand::WarningEvent, warnings);
  reader->Update();
  reader->Modified();
  reader->Update();
  vtkPolyData* gas = vtkPolyData::SafeDownCast(reader->GetOutput());
  Check(gas && gas->GetNumberOfPoints() == 10 && warnings->Count == 1 &&
      warnings->Last.find("subsampled") != std::string::npos &&
      warnings->Last.find("PartType0 holds 0.1") != std::string::npos,
    path + ": read, with one warning that the gas is a subsample (got " +
      std::to_string(warnings->Count) + ": " + warnings->Last + ")");
}

void TestSwift(const std::string& path)
{
  vtkNew<vtkHDF5SnapshotReader> reader;
  reader->SetFileName(path.c_str());
  reader->Update();
  vtkPolyData* gas = vtkPolyData::SafeDownCast(reader->GetOutput());
  Check(gas && gas->GetNumberOfPoints() == 32768, path + ": 32,768 gas particles");
  if (!gas)
  {
    return;
  }
  vtkDataArray* density = gas->GetPointData()->GetScalars();
  Check(density && std::string(density->GetName()) == "Densities" &&
      FieldString(gas, "SmoothingLengthArray") == "SmoothingLengths" &&
      gas->GetPointData()->GetArray("Masses"),
    path + ": SWIFT's plural names recognised (Densities active, SmoothingLengths named)");
  Check(FieldString(gas, "HydroScheme/Kernel function") == "Quintic spline (M6)" &&
      std::abs(FieldNumber(gas, "HydroScheme/Kernel gamma") - 2.195775) < 1e-6,
    path + ": the kernel from HydroScheme (got '" +
      FieldString(gas, "HydroScheme/Kernel function") + "')");
  Check(FieldString(gas, "SPHKernel") == "QuinticSpline" &&
      std::abs(FieldNumber(gas, "SupportPerSmoothingLength") - 2.195775) < 1e-6 &&
      FieldString(gas, "MassArray") == "Masses",
    path + ": SWIFT's SPH field marked: quintic spline, support = Kernel gamma x h (got '" +
      FieldString(gas, "SPHKernel") + "')");
  Check(std::abs(FieldNumber(gas, "BoxSize", 2) - 6.2831853071) < 1e-9,
    path + ": BoxSize (2 pi)^3 as a 3-vector");
  std::cout << path << ": " << gas->GetNumberOfPoints() << " particles, "
            << gas->GetPointData()->GetNumberOfArrays() << " arrays, "
            << gas->GetFieldData()->GetNumberOfArrays() << " field data arrays\n";
}
} // namespace

int main(int argc, char* argv[])
{
  if (argc != 3)
  {
    std::cerr << "usage: TestHDF5SnapshotReader TEST_SNAPSHOT_DIR SWIFT_FILE\n";
    return EXIT_FAILURE;
  }
  TestMultiFileGadget(argv[1]);
  TestArepoLike(argv[1]);
  TestEagleLike(argv[1]);
  TestBadFiles(argv[1]);
  TestStringArrays(argv[1]);
  TestPointArraySelection(argv[1]);
  TestKernelMarkers(argv[1]);
  TestSubsampled(argv[1]);
  TestSwift(argv[2]);
  std::cout << (lsi::test::Failures() ? "HDF5 reader tests FAILED\n"
                                      : "HDF5 reader tests passed\n");
  return lsi::test::Failures() ? EXIT_FAILURE : EXIT_SUCCESS;
}
