// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
// The Tipsy reader: writes small Tipsy standard files with known particles (big- and
// little-endian, with dark and star particles after the gas; single precision, then double
// precision positions, and positions and velocities) and checks what comes back, with
// auxiliary arrays beside them (ChaNGa's SNAPSHOT.NAME files, text and binary) and the run's
// parameter file (the periodic box), then bad files (a
// clear error, an empty output), then the two real files given as arguments (Data/ChaNGa) with
// their particle counts and bounds.
#include "vtkTipsyParticleReader.h"

#include "MessageCounter.h"
#include "OrderedBytes.h"
#include "PointArraySelection.h"
#include "RefusedFile.h"
#include "TestCheck.h"

#include "vtkAbstractArray.h"
#include "vtkCommand.h"
#include "vtkCompositeDataSet.h"
#include "vtkDataArray.h"
#include "vtkDataSet.h"
#include "vtkFieldData.h"
#include "vtkInformation.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPointSet.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkVariant.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iostream>
#include <iterator>
#include <set>
#include <string>
#include <vector>

namespace
{
using lsi::test::Check;
using lsi::test::MessageCounter;

// Writes values in a chosen byte order.
class TipsyWriter
{
public:
  TipsyWriter(const std::string& path, bool bigEndian)
    : File(path, std::ios::binary)
    , Bytes(bigEndian)
  {
  }
  ~TipsyWriter()
  {
    this->File.write(
      this->Bytes.Data.data(), static_cast<std::streamsize>(this->Bytes.Data.size()));
  }
  template <typename T>
  void Put(T value)
  {
    this->Bytes.Put(value);
  }

private:
  std::ofstream File;
  lsi::test::OrderedBytes Bytes;
};

// Column `column` of particle i of kind k (0 gas: mass, x, y, z, vx, vy, vz, rho, temp,
// hsmooth, metals, phi; 1 dark: mass, x, y, z, vx, vy, vz, eps, phi; 2 star: mass, x, y, z, vx,
// vy, vz, metals, tform, eps, phi).
float Value(int kind, int i, int column)
{
  return static_cast<float>(kind * 100 + (i + 1) * 10) + static_cast<float>(column) * 0.5f;
}
float GasValue(int i, int column)
{
  return Value(0, i, column);
}

constexpr int GasCount = 3, DarkCount = 2, StarCount = 1;
constexpr double FileTime = 0.75;

// A position or velocity column written in double precision: a value a float cannot hold, so
// that reading it as a float shows.
double PreciseValue(int kind, int i, int column)
{
  return static_cast<double>(Value(kind, i, column)) + 1e-6 * (column + 1);
}

// A record: the mass, positions and velocities (`positionBytes`, `velocityBytes`: 4 floats, 8
// doubles), the other columns as floats.
void PutRecord(TipsyWriter& w, int kind, int i, int columns, int positionBytes, int velocityBytes)
{
  for (int c = 0; c < columns; ++c)
  {
    const int bytes = c == 0 ? 4 : c <= 3 ? positionBytes : c <= 6 ? velocityBytes : 4;
    if (bytes == 8)
    {
      w.Put<double>(PreciseValue(kind, i, c));
    }
    else
    {
      w.Put<float>(Value(kind, i, c));
    }
  }
}

void WriteTipsy(const std::string& path, bool bigEndian, int droppedBytes = 0,
  int positionBytes = 4, int velocityBytes = 4, bool padded = true)
{
  {
    TipsyWriter w(path, bigEndian);
    w.Put<double>(FileTime);
    w.Put<std::int32_t>(GasCount + DarkCount + StarCount);
    w.Put<std::int32_t>(3);
    w.Put<std::int32_t>(GasCount);
    w.Put<std::int32_t>(DarkCount);
    w.Put<std::int32_t>(StarCount);
    if (padded)
    {
      w.Put<std::int32_t>(0); // pad
    }
    const int counts[3] = { GasCount, DarkCount, StarCount }, columns[3] = { 12, 9, 11 };
    for (int k = 0; k < 3; ++k)
    {
      for (int i = 0; i < counts[k]; ++i)
      {
        PutRecord(w, k, i, columns[k], positionBytes, velocityBytes);
      }
    }
  }
  if (droppedBytes > 0)
  {
    std::ifstream in(path, std::ios::binary);
    std::vector<char> all((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    all.resize(all.size() - static_cast<std::size_t>(droppedBytes));
    std::ofstream(path, std::ios::binary)
      .write(all.data(), static_cast<std::streamsize>(all.size()));
  }
}

// Every column of every type read back exactly, in either byte order, with the standard
// header (32 bytes) or the unpadded one (28) of older tools.
void TestKnownParticles(bool bigEndian, bool padded = true)
{
  const std::string order =
    std::string(bigEndian ? "big-endian" : "little-endian") + (padded ? "" : ", unpadded header");
  const std::string path =
    std::string("tipsy_test_") + (bigEndian ? "big" : "little") + (padded ? "" : "_28") + ".std";
  WriteTipsy(path, bigEndian, 0, 4, 4, padded);
  Check(vtkTipsyParticleReader::CanReadFile(path.c_str()), order + ": CanReadFile");
  vtkNew<vtkTipsyParticleReader> reader;
  reader->SetFileName(path.c_str());
  vtkNew<MessageCounter> warnings;
  reader->AddObserver(vtkCommand::WarningEvent, warnings);
  reader->Update();
  vtkPolyData* out = vtkPolyData::SafeDownCast(reader->GetOutput());
  Check(out && out->GetNumberOfPoints() == GasCount, order + ": by default the gas particles");
  if (!out)
  {
    return;
  }
  Check(out->GetNumberOfVerts() == GasCount, order + ": one vertex per particle");
  Check(warnings->Count == 0, order + ": no warning (got: " + warnings->Last + ")");
  Check(std::abs(out->GetInformation()->Get(vtkDataObject::DATA_TIME_STEP()) - FileTime) < 1e-12,
    order + ": the file's time");
  double worst = 0.0;
  const char* names[] = { "mass", "rho", "temp", "hsmooth", "metals", "phi" };
  const int columns[] = { 0, 7, 8, 9, 10, 11 };
  for (int i = 0; i < GasCount; ++i)
  {
    double x[3];
    out->GetPoint(i, x);
    double v[3];
    vtkDataArray* velocity = out->GetPointData()->GetArray("velocity");
    Check(velocity != nullptr, order + ": velocity array");
    if (!velocity)
    {
      return;
    }
    velocity->GetTuple(i, v);
    for (int d = 0; d < 3; ++d)
    {
      worst = std::max(worst, std::abs(x[d] - GasValue(i, 1 + d)));
      worst = std::max(worst, std::abs(v[d] - GasValue(i, 4 + d)));
    }
    for (int a = 0; a < 6; ++a)
    {
      vtkDataArray* array = out->GetPointData()->GetArray(names[a]);
      Check(array != nullptr, order + ": array " + names[a]);
      if (array)
      {
        worst = std::max(worst, std::abs(array->GetTuple1(i) - GasValue(i, columns[a])));
      }
    }
  }
  Check(worst == 0.0,
    order + ": every value read back exactly (worst error " + std::to_string(worst) + ")");
  Check(out->GetPointData()->GetScalars() &&
      std::string(out->GetPointData()->GetScalars()->GetName()) == "rho",
    order + ": rho is the active scalar");

  // All three types: a multiblock, one named block per type, every column in its array.
  Check(reader->GetNumberOfParticleTypeArrays() == 3, order + ": three particle types listed");
  reader->SetParticleTypeStatus("DarkMatter", 1);
  reader->SetParticleTypeStatus("Stars", 1);
  reader->Update();
  vtkMultiBlockDataSet* blocks = vtkMultiBlockDataSet::SafeDownCast(reader->GetOutput());
  Check(blocks && blocks->GetNumberOfBlocks() == 3, order + ": three blocks for three types");
  if (!blocks || blocks->GetNumberOfBlocks() != 3)
  {
    return;
  }
  const char* typeNames[] = { "Gas", "DarkMatter", "Stars" };
  const int counts[] = { GasCount, DarkCount, StarCount };
  const std::vector<std::pair<const char*, int>> columnsOf[] = {
    { { "mass", 0 }, { "rho", 7 }, { "temp", 8 }, { "hsmooth", 9 }, { "metals", 10 },
      { "phi", 11 } },
    { { "mass", 0 }, { "eps", 7 }, { "phi", 8 } },
    { { "mass", 0 }, { "metals", 7 }, { "tform", 8 }, { "eps", 9 }, { "phi", 10 } },
  };
  worst = 0.0;
  for (unsigned int k = 0; k < 3; ++k)
  {
    vtkPolyData* block = vtkPolyData::SafeDownCast(blocks->GetBlock(k));
    const char* name = blocks->GetMetaData(k)->Get(vtkCompositeDataSet::NAME());
    Check(name && std::string(name) == typeNames[k], order + ": block named " + typeNames[k]);
    Check(
      block && block->GetNumberOfPoints() == counts[k] && block->GetNumberOfVerts() == counts[k],
      order + ": " + typeNames[k] + " has its particles as vertices");
    if (!block || block->GetNumberOfPoints() != counts[k])
    {
      continue;
    }
    for (int i = 0; i < counts[k]; ++i)
    {
      double x[3];
      block->GetPoint(i, x);
      for (int d = 0; d < 3; ++d)
      {
        worst = std::max(worst, std::abs(x[d] - Value(k, i, 1 + d)));
      }
      for (const auto& column : columnsOf[k])
      {
        vtkDataArray* array = block->GetPointData()->GetArray(column.first);
        worst = array ? std::max(worst, std::abs(array->GetTuple1(i) - Value(k, i, column.second)))
                      : HUGE_VAL;
      }
    }
  }
  Check(worst == 0.0,
    order + ": all three types read back exactly (worst error " + std::to_string(worst) + ")");
  std::remove(path.c_str());
}

// Every particle type of the Tipsy file at `path`: a multiblock, one block per type (null if
// the read failed).
vtkSmartPointer<vtkMultiBlockDataSet> ReadEveryType(const std::string& path)
{
  vtkNew<vtkTipsyParticleReader> reader;
  reader->SetFileName(path.c_str());
  reader->UpdateInformation();
  reader->SetParticleTypeStatus("DarkMatter", 1);
  reader->SetParticleTypeStatus("Stars", 1);
  reader->Update();
  return vtkMultiBlockDataSet::SafeDownCast(reader->GetOutput());
}

// Double-precision positions (ChaNGa's bDoublePos), and positions and velocities
// (bDoubleVel too): recognised from the file's size, every value read back exactly, the
// positions and velocities as doubles, the layout said in field data.
void TestDoublePrecision(int velocityBytes, bool bigEndian, bool padded = true)
{
  const std::string what = std::string("double positions") +
    (velocityBytes == 8 ? " and velocities" : "") +
    (bigEndian ? ", big-endian" : ", little-endian") + (padded ? "" : ", unpadded header");
  const std::string path = "tipsy_test_double.std";
  WriteTipsy(path, bigEndian, 0, 8, velocityBytes, padded);
  Check(vtkTipsyParticleReader::CanReadFile(path.c_str()), what + ": CanReadFile");
  const vtkSmartPointer<vtkMultiBlockDataSet> blocks = ReadEveryType(path);
  const std::vector<std::pair<const char*, int>> columnsOf[] = {
    { { "mass", 0 }, { "rho", 7 }, { "temp", 8 }, { "hsmooth", 9 }, { "metals", 10 },
      { "phi", 11 } },
    { { "mass", 0 }, { "eps", 7 }, { "phi", 8 } },
    { { "mass", 0 }, { "metals", 7 }, { "tform", 8 }, { "eps", 9 }, { "phi", 10 } },
  };
  const int counts[] = { GasCount, DarkCount, StarCount };
  double worst = blocks && blocks->GetNumberOfBlocks() == 3 ? 0.0 : HUGE_VAL;
  bool doubles = true, flagged = true;
  for (unsigned int k = 0; blocks && k < blocks->GetNumberOfBlocks() && k < 3; ++k)
  {
    vtkPolyData* block = vtkPolyData::SafeDownCast(blocks->GetBlock(k));
    vtkDataArray* velocity = block ? block->GetPointData()->GetArray("velocity") : nullptr;
    if (!block || block->GetNumberOfPoints() != counts[k] || !velocity)
    {
      worst = HUGE_VAL;
      continue;
    }
    doubles = doubles && block->GetPoints()->GetDataType() == VTK_DOUBLE &&
      velocity->GetDataType() == (velocityBytes == 8 ? VTK_DOUBLE : VTK_FLOAT);
    vtkDataArray* positionsFlag =
      vtkDataArray::SafeDownCast(block->GetFieldData()->GetAbstractArray("TipsyDoublePositions"));
    vtkDataArray* velocitiesFlag =
      vtkDataArray::SafeDownCast(block->GetFieldData()->GetAbstractArray("TipsyDoubleVelocities"));
    flagged = flagged && positionsFlag && positionsFlag->GetTuple1(0) == 1.0 && velocitiesFlag &&
      velocitiesFlag->GetTuple1(0) == (velocityBytes == 8 ? 1.0 : 0.0);
    for (int i = 0; i < counts[k]; ++i)
    {
      double x[3], v[3];
      block->GetPoint(i, x);
      velocity->GetTuple(i, v);
      for (int d = 0; d < 3; ++d)
      {
        worst = std::max(worst, std::abs(x[d] - PreciseValue(k, i, 1 + d)));
        const double expected = velocityBytes == 8 ? PreciseValue(k, i, 4 + d) : Value(k, i, 4 + d);
        worst = std::max(worst, std::abs(v[d] - expected));
      }
      for (const auto& column : columnsOf[k])
      {
        vtkDataArray* array = block->GetPointData()->GetArray(column.first);
        worst = array ? std::max(worst, std::abs(array->GetTuple1(i) - Value(k, i, column.second)))
                      : HUGE_VAL;
      }
    }
  }
  Check(worst == 0.0 && doubles && flagged,
    what + ": every value read back exactly, positions" +
      (velocityBytes == 8 ? " and velocities" : "") + " as doubles, the layout in field data " +
      "(worst error " + std::to_string(worst) + ")");
  std::remove(path.c_str());
}

// An auxiliary array file SNAPSHOT.NAME: binary (a 32-bit count, then the values in `bigEndian`
// order) or text (the count on a line, then a value a line).
template <typename T>
void WriteBinaryArray(
  const std::string& path, bool bigEndian, std::int32_t count, const std::vector<T>& values)
{
  TipsyWriter w(path, bigEndian);
  w.Put<std::int32_t>(count);
  for (T value : values)
  {
    w.Put<T>(value);
  }
}
void WriteTextArray(
  const std::string& path, long long count, const std::vector<std::string>& values)
{
  std::ofstream file(path);
  file << count << "\n";
  for (const std::string& value : values)
  {
    file << value << "\n";
  }
}

// The particle of kind k a point is (its index in the kind), from its x coordinate (see Value).
int ParticleOf(int kind, double x)
{
  return static_cast<int>(std::lround((x - Value(kind, 0, 1)) / 10.0));
}

// ChaNGa's and Gasoline's auxiliary arrays beside the snapshot (`bigEndian`: the main file's byte
// order; the binary arrays are written in both): one value per particle of the whole snapshot,
// gas first, or three for a vector (binary: x, y, z of each particle; text: all x, all y, all
// z, as ChaNGa reads them). Each type gets its share, read whole and in pieces, and with the
// array selection; files of another count, compressed files and names of the main file's
// columns are left out.
void TestAuxiliaryArrays(bool bigEndian)
{
  const std::string what = std::string("auxiliary arrays, ") +
    (bigEndian ? "big-endian snapshot" : "little-endian snapshot");
  const std::string path = "tipsy_aux.std";
  WriteTipsy(path, bigEndian);
  const int total = GasCount + DarkCount + StarCount;
  std::vector<std::int32_t> iord;
  std::vector<double> precise;
  std::vector<float> densities, vectors;
  std::vector<std::string> fractions, groups, masses, seven, curl(3 * total), two;
  for (int j = 0; j < total; ++j)
  {
    iord.push_back(1000 + 7 * j);
    precise.push_back(1.0 / 3.0 + j);
    densities.push_back(0.5f * static_cast<float>(j + 1));
    fractions.push_back(j == 2 ? "1e-3" : std::to_string(0.25 * j));
    groups.push_back(std::to_string(j % 2 == 0 ? 0 : 3000000000LL + j));
    masses.push_back("-1");
    seven.push_back("5");
    two.insert(two.end(), { "1", "2" });
    for (int d = 0; d < 3; ++d)
    {
      vectors.push_back(static_cast<float>(j) + 0.25f * static_cast<float>(d));
      curl[d * total + j] = std::to_string(10 * d + j) + ".5";
    }
  }
  seven.push_back("5");
  WriteBinaryArray(path + ".iord", true, total, iord);         // ChaNGa's XDR order
  WriteBinaryArray(path + ".rho", false, total, densities);    // the other order
  WriteBinaryArray(path + ".dbl", !bigEndian, total, precise); // doubles
  WriteBinaryArray(path + ".acc2", true, total, vectors);      // a vector
  WriteBinaryArray(path + ".short", true, total,
    std::vector<float>(densities.begin() + 1,
      densities.end())); // one value short: left out
  WriteTextArray(path + ".HI", total, fractions);
  WriteTextArray(path + ".amiga.grp", total, groups);
  WriteTextArray(path + ".mass", total, masses);     // the main file's column
  WriteTextArray(path + ".seven", total, seven);     // another count: left out
  WriteTextArray(path + ".curl", total, curl);       // a vector: all x, all y, all z
  WriteTextArray(path + ".two", total, two);         // two values a particle: left out
  WriteTextArray(path + ".HI.gz", total, fractions); // compressed: left out
  const std::vector<std::string> written = { ".iord", ".rho", ".dbl", ".acc2", ".short", ".HI",
    ".amiga.grp", ".mass", ".seven", ".curl", ".two", ".HI.gz" };

  vtkNew<vtkTipsyParticleReader> reader;
  reader->SetFileName(path.c_str());
  reader->UpdateInformation();
  reader->SetParticleTypeStatus("DarkMatter", 1);
  reader->SetParticleTypeStatus("Stars", 1);
  const int firsts[3] = { 0, GasCount, GasCount + DarkCount };
  const int counts[3] = { GasCount, DarkCount, StarCount };
  // Every particle of `blocks` against its auxiliary values; returns how many were checked.
  const auto checkValues = [&](vtkMultiBlockDataSet* blocks, const std::string& how) {
    int checked = 0;
    bool exact = blocks && blocks->GetNumberOfBlocks() == 3, absent = exact, typed = exact;
    for (unsigned int k = 0; exact && k < 3; ++k)
    {
      vtkPolyData* block = vtkPolyData::SafeDownCast(blocks->GetBlock(k));
      if (block && block->GetNumberOfPoints() == 0)
      {
        continue; // a piece without particles of this type
      }
      vtkPointData* pd = block ? block->GetPointData() : nullptr;
      vtkDataArray* a[] = { pd ? pd->GetArray("iord") : nullptr, pd ? pd->GetArray("dbl") : nullptr,
        pd ? pd->GetArray("HI") : nullptr, pd ? pd->GetArray("amiga.grp") : nullptr,
        pd ? pd->GetArray("rho") : nullptr, pd ? pd->GetArray("mass") : nullptr,
        pd ? pd->GetArray("acc2") : nullptr, pd ? pd->GetArray("curl") : nullptr };
      if (!block || std::find(std::begin(a), std::end(a), nullptr) != std::end(a))
      {
        exact = false;
        break;
      }
      typed = typed && a[0]->GetDataType() == VTK_ID_TYPE && a[0] == pd->GetGlobalIds() &&
        a[1]->GetDataType() == VTK_DOUBLE && a[3]->GetDataType() == VTK_TYPE_INT64 &&
        a[6]->GetDataType() == VTK_FLOAT && a[6]->GetNumberOfComponents() == 3 &&
        a[7]->GetNumberOfComponents() == 3;
      for (const char* left : { "short", "seven", "two", "HI.gz" })
      {
        absent = absent && !pd->GetAbstractArray(left);
      }
      for (vtkIdType p = 0; p < block->GetNumberOfPoints(); ++p)
      {
        double x[3];
        block->GetPoint(p, x);
        const int i = ParticleOf(static_cast<int>(k), x[0]);
        const int j = firsts[k] + i;
        const double rho = k == 0 ? Value(0, i, 7) : densities[j];
        exact = exact && i >= 0 && i < counts[k] && a[0]->GetTuple1(p) == iord[j] &&
          a[1]->GetTuple1(p) == precise[j] && a[2]->GetTuple1(p) == std::stod(fractions[j]) &&
          a[3]->GetTuple1(p) == std::stod(groups[j]) && a[4]->GetTuple1(p) == rho &&
          a[5]->GetTuple1(p) == Value(static_cast<int>(k), i, 0);
        for (int d = 0; d < 3; ++d)
        {
          exact = exact && a[6]->GetComponent(p, d) == vectors[3 * j + d] &&
            a[7]->GetComponent(p, d) == std::stod(curl[d * total + j]);
        }
        ++checked;
      }
    }
    Check(exact && absent && typed,
      what + ", " + how +
        ": every type's share of iord (the global ids), dbl (doubles), HI, amiga.grp (int64), "
        "rho " +
        "(gas: the main file's), the vectors acc2 (binary) and curl (text), mass the main " +
        "file's, the other files left out");
    return checked;
  };
  reader->Update();
  Check(checkValues(vtkMultiBlockDataSet::SafeDownCast(reader->GetOutput()), "whole") == total,
    what + ": every particle read");
  int pieces = 0;
  for (int piece = 0; piece < 3; ++piece)
  {
    reader->UpdatePiece(piece, 3, 0);
    pieces += checkValues(vtkMultiBlockDataSet::SafeDownCast(reader->GetOutput()),
      "piece " + std::to_string(piece) + " of 3");
  }
  Check(pieces == total, what + ": the pieces hold every particle once");
  reader->SetPointArrayStatus("iord", 0);
  reader->UpdatePiece(0, 1, 0);
  vtkMultiBlockDataSet* blocks = vtkMultiBlockDataSet::SafeDownCast(reader->GetOutput());
  vtkPolyData* gas = blocks ? vtkPolyData::SafeDownCast(blocks->GetBlock(0)) : nullptr;
  Check(gas && !gas->GetPointData()->GetArray("iord") && gas->GetPointData()->GetArray("HI"),
    what + ": an auxiliary array left unselected is not read");
  for (const std::string& suffix : written)
  {
    std::remove((path + suffix).c_str());
  }
  std::remove(path.c_str());
}

// The reader remembers what each file beside the snapshot is (a text array is read whole to be
// recognised), by its size and time: a file changed on disk is looked at again.
void TestAuxiliaryFileChanged()
{
  const std::string path = "tipsy_aux_changed.std";
  WriteTipsy(path, true);
  const int total = GasCount + DarkCount + StarCount;
  WriteTextArray(path + ".HI", total, std::vector<std::string>(total, "0.5"));
  vtkNew<vtkTipsyParticleReader> reader;
  reader->SetFileName(path.c_str());
  reader->Update();
  vtkDataSet* gas = vtkDataSet::SafeDownCast(reader->GetOutputDataObject(0));
  const bool before = gas && gas->GetPointData()->GetArray("HI");
  WriteTextArray(path + ".HI", total, std::vector<std::string>(total + 1, "0.5")); // one too many
  reader->Modified();
  reader->Update();
  gas = vtkDataSet::SafeDownCast(reader->GetOutputDataObject(0));
  Check(before && gas && !gas->GetPointData()->GetArray("HI"),
    "an auxiliary array read, then changed on disk to another count: left out on the next update");
  std::remove((path + ".HI").c_str());
  std::remove(path.c_str());
}

// A text array read in blocks: values that straddle a block's end (1 MiB) and one longer than
// a block are read whole. Leading zeros make the values long: value i is 000...0i.25, read
// back exactly; a vector's three parts likewise.
void TestLongTextValues()
{
  const std::string path = "tipsy_aux_long.std";
  WriteTipsy(path, true);
  const int total = GasCount + DarkCount + StarCount;
  std::vector<std::string> values, vector;
  for (int i = 0; i < total; ++i)
  {
    const std::size_t zeros = i == 2 ? 1500000 : 400000 + 1000 * static_cast<std::size_t>(i);
    values.push_back(std::string(zeros, '0') + std::to_string(i) + ".25");
  }
  for (int c = 0; c < 3; ++c)
  {
    for (int i = 0; i < total; ++i)
    {
      vector.push_back(std::string(300000, '0') + std::to_string(10 * i + c) + ".5");
    }
  }
  WriteTextArray(path + ".long", total, values);
  WriteTextArray(path + ".longvec", total, vector);
  const vtkSmartPointer<vtkMultiBlockDataSet> blocks = ReadEveryType(path);
  double worst = blocks ? 0.0 : HUGE_VAL;
  int first = 0;
  for (unsigned int k = 0; blocks && k < blocks->GetNumberOfBlocks(); ++k)
  {
    vtkDataSet* block = vtkDataSet::SafeDownCast(blocks->GetBlock(k));
    vtkDataArray* scalar = block ? block->GetPointData()->GetArray("long") : nullptr;
    vtkDataArray* triple = block ? block->GetPointData()->GetArray("longvec") : nullptr;
    if (!scalar || !triple || triple->GetNumberOfComponents() != 3)
    {
      worst = HUGE_VAL;
      break;
    }
    for (vtkIdType i = 0; i < block->GetNumberOfPoints(); ++i)
    {
      const int particle = first + static_cast<int>(i);
      worst = std::max(worst, std::abs(scalar->GetTuple1(i) - (particle + 0.25)));
      for (int c = 0; c < 3; ++c)
      {
        worst = std::max(worst, std::abs(triple->GetComponent(i, c) - (10 * particle + c + 0.5)));
      }
    }
    first += static_cast<int>(block->GetNumberOfPoints());
  }
  Check(worst == 0.0 && first == total,
    "text arrays with values across blocks and longer than one: every value read back exactly");
  std::remove((path + ".long").c_str());
  std::remove((path + ".longvec").c_str());
  std::remove(path.c_str());
}

// The gas's SPH field: rho and mass always, and the smoothing lengths of the auxiliary array
// Gasoline and ChaNGa write (smoothlength, SPHH, SphH, hsmall: h, the cubic spline's support
// 2 h), never the hsmooth column (their gravitational softening).
void TestSmoothingLengthMarkers()
{
  const std::string path = "tipsy_hsml.std";
  WriteTipsy(path, true);
  const int total = GasCount + DarkCount + StarCount;
  vtkNew<vtkTipsyParticleReader> reader;
  reader->SetFileName(path.c_str());
  auto marker = [&](const char* name) {
    reader->Modified();
    reader->Update();
    vtkDataObject* gas = reader->GetOutputDataObject(0);
    vtkAbstractArray* array = gas ? gas->GetFieldData()->GetAbstractArray(name) : nullptr;
    return array ? array->GetVariantValue(0).ToString() : std::string();
  };
  Check(marker("SmoothingLengthArray").empty() && marker("SPHKernel").empty() &&
      marker("DensityArray") == "rho" && marker("MassArray") == "mass",
    "no smoothing-length file: rho and mass marked, hsmooth (the softening) not");
  std::vector<float> h(total);
  for (int j = 0; j < total; ++j)
  {
    h[j] = 0.01f * static_cast<float>(j + 1);
  }
  WriteTextArray(path + ".SphH", total, std::vector<std::string>(total, "0.5"));
  Check(marker("SmoothingLengthArray") == "SphH" && marker("SupportPerSmoothingLength") == "2",
    "older ChaNGa's SphH marked as the smoothing length, support 2 h");
  WriteBinaryArray(path + ".smoothlength", true, total, h);
  const bool marked = marker("SmoothingLengthArray") == "smoothlength" &&
    marker("SupportPerSmoothingLength") == "2" && marker("SPHKernel") == "CubicSpline";
  vtkDataSet* gas = vtkDataSet::SafeDownCast(reader->GetOutputDataObject(0));
  vtkDataArray* values = gas ? gas->GetPointData()->GetArray("smoothlength") : nullptr;
  Check(marked && values && values->GetNumberOfTuples() == GasCount &&
      values->GetTuple1(GasCount - 1) == h[GasCount - 1],
    "smoothlength (before SphH) marked as the smoothing length, support 2 h, the cubic spline");
  reader->SetPointArrayStatus("smoothlength", 0);
  Check(marker("SmoothingLengthArray") == "SphH", "smoothlength unread: SphH marked");
  reader->SetPointArrayStatus("SphH", 0);
  Check(marker("SmoothingLengthArray").empty(), "both unread: no smoothing length marked");
  for (const char* extension : { ".SphH", ".smoothlength", "" })
  {
    std::remove((path + extension).c_str());
  }
}

// The run's parameter file gives the box (a Tipsy file does not): found by achOutName (numbered
// outputs) or achInFile, in the snapshot's directory or its parent, else the only .param there;
// dPeriod sets the axes not given, a period of 0 leaves the box open (with a warning).
void TestRunParameters()
{
  struct Case
  {
    std::string What, Directory, Snapshot;
    std::vector<std::pair<std::string, std::string>> Files; // name (in Directory), text
    std::vector<double> Box;                                // empty: no BoxSize
    std::string Chosen;                                     // the file read; empty: none
    int Warnings = 0;
  };
  const Case cases[] = {
    { "achOutName", "tipsy_param_a", "run.000512",
      { { "run.param", "achOutName = run\nbPeriodic = 1\ndPeriod = 2 # comoving\n" },
        { "other.param", "achOutName = other\nbPeriodic = 0\n" } },
      { 2, 2, 2 }, "run.param" },
    { "achInFile and dxPeriod", "tipsy_param_b", "ics.std",
      { { "sim.param", "achInFile = \"ics.std\"\nbPeriodic=1\ndPeriod=1\ndxPeriod = 3\n" } },
      { 3, 1, 1 }, "sim.param" },
    { "the only .param, defaults", "tipsy_param_c", "snap.std",
      { { "x.param", "bPeriodic = 1\n" } }, { 1, 1, 1 }, "x.param" },
    { "a period of 0", "tipsy_param_d", "run.000512",
      { { "run.param", "achOutName = run\nbPeriodic = 1\ndzPeriod = 0\n" } }, {}, "run.param", 1 },
    { "two files naming other runs", "tipsy_param_e", "run.000512",
      { { "a.param", "achOutName = a\nbPeriodic = 1\n" },
        { "b.param", "achOutName = b\nbPeriodic = 1\n" } },
      {}, "" },
    { "not periodic", "tipsy_param_f", "run.00100",
      { { "run.param", "achOutName = run\nbPeriodic = 0\ndPeriod = 5\n" } }, {}, "run.param" },
    { "in the parent directory", "tipsy_param_g/output", "run.000512",
      { { "../run.param", "achOutName = output/run\nbPeriodic = 1\ndPeriod = 4\n" } }, { 4, 4, 4 },
      "../run.param" },
  };
  for (const Case& c : cases)
  {
    std::system(("mkdir -p " + c.Directory).c_str());
    const std::string snapshot = c.Directory + "/" + c.Snapshot;
    WriteTipsy(snapshot, true);
    for (const auto& file : c.Files)
    {
      std::ofstream(c.Directory + "/" + file.first) << file.second;
    }
    vtkNew<vtkTipsyParticleReader> reader;
    reader->SetFileName(snapshot.c_str());
    vtkNew<MessageCounter> warnings;
    reader->AddObserver(vtkCommand::WarningEvent, warnings);
    reader->Update();
    vtkDataObject* out = reader->GetOutputDataObject(0);
    vtkFieldData* fields = out ? out->GetFieldData() : nullptr;
    vtkDataArray* box =
      fields ? vtkDataArray::SafeDownCast(fields->GetAbstractArray("BoxSize")) : nullptr;
    vtkAbstractArray* chosen = fields ? fields->GetAbstractArray("TipsyParameterFile") : nullptr;
    std::vector<double> got;
    for (vtkIdType v = 0; box && v < box->GetNumberOfValues(); ++v)
    {
      got.push_back(box->GetVariantValue(v).ToDouble());
    }
    const std::string file = chosen ? chosen->GetVariantValue(0).ToString() : std::string();
    const std::string expected = c.Chosen.empty() ? std::string() : c.Directory + "/" + c.Chosen;
    Check(out && got == c.Box && file == expected && warnings->Count == c.Warnings,
      "run parameters, " + c.What + ": BoxSize of " + std::to_string(got.size()) +
        " values, from '" + file + "', " + std::to_string(warnings->Count) + " warnings");
    for (const auto& written : c.Files)
    {
      std::remove((c.Directory + "/" + written.first).c_str());
    }
    std::remove(snapshot.c_str());
  }
  std::system("rm -rf tipsy_param_a tipsy_param_b tipsy_param_c tipsy_param_d tipsy_param_e "
              "tipsy_param_f tipsy_param_g");
}

void TestBadFiles()
{
  struct Case
  {
    std::string What;
    std::string Path;
    std::string Expected;
  };
  const std::string truncated = "tipsy_test_truncated.std";
  WriteTipsy(truncated, true, 8); // the last star particle is cut short
  const std::string text = "tipsy_test_text.std";
  std::ofstream(text) << "this is not a Tipsy file, only a line of text that is long enough\n";
  const Case cases[] = {
    { "missing file", "no_such_file.std", "cannot open" },
    { "truncated file", truncated, "not a Tipsy standard file" },
    { "text file", text, "not a Tipsy standard file" },
  };
  for (const Case& c : cases)
  {
    lsi::test::CheckRefusedFile<vtkTipsyParticleReader>(c.Path, c.Expected, false);
  }
  std::remove(truncated.c_str());
  std::remove(text.c_str());
}

// A real file: as many points as its header's gas count, finite coordinates inside the
// expected box.
void TestRealFile(const std::string& path, vtkIdType expectedGas, double halfExtent)
{
  vtkNew<vtkTipsyParticleReader> reader;
  reader->SetFileName(path.c_str());
  reader->Update();
  vtkPolyData* out = vtkPolyData::SafeDownCast(reader->GetOutput());
  Check(out && out->GetNumberOfPoints() == expectedGas,
    path + ": " + std::to_string(out ? out->GetNumberOfPoints() : -1) +
      " gas particles, expected " + std::to_string(expectedGas));
  if (!out)
  {
    return;
  }
  double bounds[6];
  out->GetBounds(bounds);
  bool inside = true;
  for (double b : bounds)
  {
    inside = inside && std::isfinite(b) && std::abs(b) <= halfExtent;
  }
  Check(inside, path + ": coordinates within +-" + std::to_string(halfExtent));
  auto marker = [&](const char* name) {
    vtkAbstractArray* array = out->GetFieldData()->GetAbstractArray(name);
    return array ? array->GetVariantValue(0).ToString() : std::string();
  };
  Check(marker("SmoothingLengthArray").empty() && marker("MassArray") == "mass" &&
      marker("DensityArray") == "rho",
    path + ": rho and mass marked, not hsmooth (the softening: no smoothlength file beside it)");
}
// The galaxy snapshot has no gas: the first type there is (dark matter) is read by default,
// and all types give the header's counts, 3,627 dark and 5,321 star particles.
void TestGalaxy(const std::string& path)
{
  vtkNew<vtkTipsyParticleReader> reader;
  reader->SetFileName(path.c_str());
  reader->Update();
  vtkPolyData* dark = vtkPolyData::SafeDownCast(reader->GetOutput());
  Check(dark && dark->GetNumberOfPoints() == 3627, path + ": dark matter by default (no gas)");
  reader->SetParticleTypeStatus("Stars", 1);
  reader->Update();
  vtkMultiBlockDataSet* blocks = vtkMultiBlockDataSet::SafeDownCast(reader->GetOutput());
  Check(blocks && blocks->GetNumberOfBlocks() == 2 &&
      vtkPolyData::SafeDownCast(blocks->GetBlock(0))->GetNumberOfPoints() == 3627 &&
      vtkPolyData::SafeDownCast(blocks->GetBlock(1))->GetNumberOfPoints() == 5321 &&
      vtkPolyData::SafeDownCast(blocks->GetBlock(1))->GetPointData()->GetArray("tform"),
    path + ": 3627 dark and 5321 star particles, stars with tform");
  std::cout << path << ": " << (blocks ? blocks->GetNumberOfPoints() : 0) << " particles\n";
}

// The point array selection on the shock tube's gas (real values): its columns listed, the SPH
// field's three read alone, then the velocities alone, with the values of a full read.
void TestPointArraySelection(const std::string& path)
{
  vtkNew<vtkTipsyParticleReader> reader;
  reader->SetFileName(path.c_str());
  const std::set<std::string> gas = { "hsmooth", "mass", "metals", "phi", "rho", "temp",
    "velocity" };
  lsi::test::CheckPointArraySelection(
    reader.Get(), gas, { "hsmooth", "mass", "rho" }, path + ", the SPH field's arrays");
  lsi::test::CheckPointArraySelection(reader.Get(), gas, { "velocity" }, path + ", no SPH array");
}
} // namespace

int main(int argc, char* argv[])
{
  TestKnownParticles(true);
  TestKnownParticles(false);
  TestKnownParticles(true, false);
  TestKnownParticles(false, false);
  TestDoublePrecision(4, true);
  TestDoublePrecision(8, true);
  TestDoublePrecision(8, false);
  TestDoublePrecision(8, true, false);
  TestAuxiliaryArrays(true);
  TestAuxiliaryArrays(false);
  TestAuxiliaryFileChanged();
  TestLongTextValues();
  TestSmoothingLengthMarkers();
  TestRunParameters();
  TestBadFiles();
  // The real files of Data/ChaNGa (see Data/README.md): the Evrard glass (28,721 gas particles
  // in the unit sphere) and the shock tube (20,000 in [-1, 1] along z).
  if (argc != 4)
  {
    std::cerr << "usage: TestTipsyReader GLASS_FILE SHOCK_TUBE_FILE GALAXY_FILE\n";
    return EXIT_FAILURE;
  }
  TestRealFile(argv[1], 28721, 1.0 + 1e-6);
  TestRealFile(argv[2], 20000, 1.0 + 1e-6);
  TestGalaxy(argv[3]);
  TestPointArraySelection(argv[2]);
  std::cout << (lsi::test::Failures() ? "Tipsy reader tests FAILED\n"
                                      : "Tipsy reader tests passed\n");
  return lsi::test::Failures() ? EXIT_FAILURE : EXIT_SUCCESS;
}
