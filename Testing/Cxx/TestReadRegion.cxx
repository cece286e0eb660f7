// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
// The readers' regions (ReadRegion, RegionBounds): a region's read gives exactly the particles
// of a full read that lie inside the box, in order, with every array, for chunks down to one
// particle and over 3 pieces; a SWIFT snapshot's cell table lets the HDF5 reader read fewer
// particles (ParticlesScanned), and a damaged table is not trusted; in a periodic box a region
// wraps across the faces (PeriodicRegion). First the ranges' and the periodic region's
// arithmetic (ParticleRanges.h, PeriodicRegion.h), then each reader: the HDF5 reader on SWIFT-style
// snapshots of make_test_snapshots.py (a table in two files with cell centres, older SWIFT's global
// offsets with each cell's extent, a damaged table) and the real SWIFT file, the GADGET binary
// reader on a snapshot in two files, the Tipsy reader on the real shock tube. Then progress and
// abort, bad bounds, and vtkLevelSetIsosurface's warning when a surface nears a region's faces.
//   TestReadRegion TEST_SNAPSHOT_DIR SWIFT_FILE SHOCK_TUBE_FILE
#include "ParticleRanges.h"
#include "PeriodicRegion.h"
#include "vtkGadgetBinaryReader.h"
#include "vtkHDF5SnapshotReader.h"
#include "vtkLevelSetIsosurface.h"
#include "vtkTipsyParticleReader.h"

#include "MessageCounter.h"
#include "SameParticles.h"
#include "TestCheck.h"

#include "vtkCallbackCommand.h"
#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkVariant.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <random>
#include <string>
#include <vector>

namespace
{
using lsi::io::Range;
using lsi::test::Check;
using lsi::test::MessageCounter;

std::string Text(const std::vector<Range>& ranges)
{
  std::string text;
  for (const Range& r : ranges)
  {
    text += "[" + std::to_string(r.first) + "," + std::to_string(r.second) + ")";
  }
  return text;
}

void TestRanges()
{
  const std::vector<Range> merged =
    lsi::io::MergedRanges({ { 5, 9 }, { 0, 3 }, { 3, 4 }, { 8, 12 }, { 20, 20 }, { 30, 25 } });
  Check(merged == std::vector<Range>{ { 0, 4 }, { 5, 12 } },
    "MergedRanges: sorted, touching and overlapping joined, empty dropped (got " + Text(merged) +
      ")");
  // Three pieces of [0, 4) + [5, 12) + [20, 23): 14 indices as 4, 5 and 5, in order.
  const std::vector<Range> ranges = { { 0, 4 }, { 5, 12 }, { 20, 23 } };
  const std::vector<std::vector<Range>> expected = { { { 0, 4 } }, { { 5, 10 } },
    { { 10, 12 }, { 20, 23 } } };
  for (int piece = 0; piece < 3; ++piece)
  {
    const std::vector<Range> share = lsi::io::ShareOfRanges(ranges, piece, 3);
    Check(share == expected[piece],
      "ShareOfRanges: piece " + std::to_string(piece) + " of 3 is " + Text(expected[piece]) +
        " (got " + Text(share) + ")");
  }
  long long total = 0;
  for (int piece = 0; piece < 20; ++piece)
  {
    total += lsi::io::CountOf(lsi::io::ShareOfRanges(ranges, piece, 20));
  }
  Check(lsi::io::ShareOfRanges(ranges, 0, 20).empty() && total == 14,
    "ShareOfRanges: 20 pieces of 14 indices, some empty, each index once");
}

// Whether x lies in `bounds`, or with a period on an axis (> 0) one of its images x + n period,
// n from -3 to 3 (the test's own, simpler than the reader's).
bool Inside(const double x[3], const double bounds[6], const double period[3])
{
  for (int a = 0; a < 3; ++a)
  {
    const double low = bounds[2 * a], high = bounds[2 * a + 1];
    bool in = x[a] >= low && x[a] <= high;
    for (int n = -3; n <= 3 && period[a] > 0.0 && !in; ++n)
    {
      in = high - low >= period[a] || (x[a] + n * period[a] >= low && x[a] + n * period[a] <= high);
    }
    if (!in)
    {
      return false;
    }
  }
  return true;
}

// The region's arithmetic in a periodic box (PeriodicRegion.h): a face, a drift past it, regions
// far from the box, long ones; the boxes that find a format's candidates hold every position
// accepted, in [-period, 2 period) on each axis.
void TestPeriodicRegion()
{
  using lsi::io::InsideOnAxis;
  Check(InsideOnAxis(0.5, 0.4, 0.6, 0.0) && !InsideOnAxis(1.5, 0.4, 0.6, 0.0) &&
      InsideOnAxis(0.6, 0.4, 0.6, 0.0),
    "InsideOnAxis without a period: the range alone, a face inside");
  Check(InsideOnAxis(0.05, 0.9, 1.1, 1.0) && InsideOnAxis(0.95, 0.9, 1.1, 1.0) &&
      !InsideOnAxis(0.5, 0.9, 1.1, 1.0) && InsideOnAxis(-0.05, 0.9, 1.1, 1.0) &&
      InsideOnAxis(1.05, 0.9, 1.1, 1.0) && InsideOnAxis(0.1, 0.9, 1.1, 1.0) &&
      !InsideOnAxis(0.1000001, 0.9, 1.1, 1.0),
    "InsideOnAxis, [0.9, 1.1] in a period of 1: both sides of the face, drifts past it, the "
    "region's face");
  Check(InsideOnAxis(0.95, 10.9, 11.1, 1.0) && InsideOnAxis(0.95, -9.1, -8.9, 1.0) &&
      !InsideOnAxis(0.5, 10.9, 11.1, 1.0),
    "InsideOnAxis: a region whole periods away from the box");
  Check(InsideOnAxis(0.5, 0.3, 1.3, 1.0) && InsideOnAxis(123.4, -1.0, 5.0, 1.0) &&
      !InsideOnAxis(std::nan(""), 0.3, 1.3, 1.0) && InsideOnAxis(0.7, -HUGE_VAL, HUGE_VAL, 1.0),
    "InsideOnAxis: a range of a period or more holds every finite position");
  std::mt19937 random(11);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const double period[3] = { 1.0, 2.0, 0.0 }; // z not periodic
  std::size_t accepted = 0, covered = 0, most = 0;
  for (int r = 0; r < 200; ++r)
  {
    double bounds[6];
    for (int a = 0; a < 3; ++a)
    {
      const double p = period[a] > 0.0 ? period[a] : 1.0;
      bounds[2 * a] = (unit(random) * 6.0 - 3.0) * p;
      bounds[2 * a + 1] = bounds[2 * a] + unit(random) * (r % 10 == 0 ? 1.5 : 0.6) * p;
    }
    const auto boxes = lsi::io::PeriodicRegionBoxes(bounds, period);
    most = std::max(most, boxes.size());
    for (int k = 0; k < 200; ++k)
    {
      double x[3];
      for (int a = 0; a < 3; ++a)
      {
        const double p = period[a] > 0.0 ? period[a] : 1.0;
        x[a] = period[a] > 0.0 ? (unit(random) * 3.0 - 1.0) * p
                               : bounds[4] + (unit(random) * 1.2 - 0.1) * (bounds[5] - bounds[4]);
      }
      if (!lsi::io::InsidePeriodicRegion(x, bounds, period))
      {
        continue;
      }
      ++accepted;
      covered += std::any_of(boxes.begin(), boxes.end(), [&](const std::array<double, 6>& b) {
        const double zero[3] = { 0.0, 0.0, 0.0 };
        return Inside(x, b.data(), zero);
      });
    }
  }
  Check(accepted > 1000 && covered == accepted && most <= 16,
    "PeriodicRegionBoxes: every accepted position of 200 regions lies in one of their boxes (" +
      std::to_string(covered) + " of " + std::to_string(accepted) + ", at most " +
      std::to_string(most) + " boxes)");
}

// The period of each axis a reader's region wraps across: its output's BoxSize (one value or
// three), unless PeriodicRegion is off.
void PeriodOf(vtkPolyData* particles, bool periodicRegion, double period[3])
{
  period[0] = period[1] = period[2] = 0.0;
  vtkDataArray* box = particles->GetFieldData()->GetArray("BoxSize");
  for (int a = 0; a < 3 && box && periodicRegion; ++a)
  {
    const double size = box->GetVariantValue(box->GetNumberOfValues() >= 3 ? a : 0).ToDouble();
    period[a] = size > 0.0 ? size : 0.0;
  }
}

// Whether `part` holds particles [first, first + n) of `subset` (ids into `all`): the same
// positions, and every array of the full read with the same values.
bool SameParticlesAndArrays(
  vtkPolyData* all, const std::vector<vtkIdType>& subset, vtkIdType first, vtkPolyData* part)
{
  return part && lsi::test::PointArrayNames(part) == lsi::test::PointArrayNames(all) &&
    lsi::test::SameParticles(all, subset, first, part);
}

// The same roles as a full read (global ids, active scalars, SPH markers and the other field
// data), and the region read in field data: RegionBounds `bounds`, RegionPeriod `period`.
bool SameRoles(vtkPolyData* all, vtkPolyData* part, const double bounds[6], const double period[3])
{
  auto name = [](vtkDataArray* array) { return array ? std::string(array->GetName()) : ""; };
  vtkPointData* a = all->GetPointData();
  vtkPointData* b = part->GetPointData();
  vtkDataArray* readBounds = part->GetFieldData()->GetArray("RegionBounds");
  vtkDataArray* readPeriod = part->GetFieldData()->GetArray("RegionPeriod");
  bool region = readBounds && readBounds->GetNumberOfValues() == 6 && readPeriod &&
    readPeriod->GetNumberOfValues() == 3;
  for (int k = 0; k < 6 && region; ++k)
  {
    region = readBounds->GetComponent(k, 0) == bounds[k]; // (one value per tuple)
  }
  for (int k = 0; k < 3 && region; ++k)
  {
    region = readPeriod->GetComponent(k, 0) == period[k];
  }
  return name(a->GetGlobalIds()) == name(b->GetGlobalIds()) &&
    name(a->GetScalars()) == name(b->GetScalars()) &&
    all->GetFieldData()->GetNumberOfArrays() + 2 == part->GetFieldData()->GetNumberOfArrays() &&
    region;
}

// Reads `path` whole, then the region `bounds` in chunks of 4M, `smallChunk` and 7 particles and
// in 3 pieces, and checks each against the full read's particles inside. Returns the particles
// the region's serial read scanned (or -1 where the reads failed).
template <typename Reader>
long long CheckRegion(const std::string& path, const double bounds[6], const std::string& what,
  vtkIdType smallChunk, bool periodicRegion = true)
{
  vtkNew<Reader> full;
  full->SetFileName(path.c_str());
  full->Update();
  vtkNew<vtkPolyData> all;
  if (auto* output = vtkPolyData::SafeDownCast(full->GetOutput()))
  {
    all->DeepCopy(output);
  }
  double period[3];
  PeriodOf(all, periodicRegion, period);
  std::vector<vtkIdType> inside;
  for (vtkIdType i = 0; i < all->GetNumberOfPoints(); ++i)
  {
    double x[3];
    all->GetPoint(i, x);
    if (Inside(x, bounds, period))
    {
      inside.push_back(i);
    }
  }
  Check(all->GetNumberOfPoints() > 0 && !inside.empty() &&
      static_cast<vtkIdType>(inside.size()) < all->GetNumberOfPoints(),
    what + ": the region holds some of the particles, not all (" + std::to_string(inside.size()) +
      " of " + std::to_string(all->GetNumberOfPoints()) + ")");
  Check(full->GetParticlesScanned() == all->GetNumberOfPoints(),
    what + ": a full read scans every particle");

  vtkNew<Reader> reader;
  reader->SetFileName(path.c_str());
  reader->SetReadRegion(true);
  reader->SetRegionBounds(const_cast<double*>(bounds));
  reader->SetPeriodicRegion(periodicRegion);
  long long scanned = -1;
  for (vtkIdType chunk : { vtkIdType(4194304), smallChunk, vtkIdType(7) })
  {
    reader->SetRegionChunkParticles(chunk);
    reader->Update();
    auto* region = vtkPolyData::SafeDownCast(reader->GetOutput());
    Check(region && region->GetNumberOfPoints() == static_cast<vtkIdType>(inside.size()) &&
        region->GetNumberOfVerts() == region->GetNumberOfPoints() &&
        SameParticlesAndArrays(all, inside, 0, region) && SameRoles(all, region, bounds, period),
      what + ", chunks of " + std::to_string(chunk) +
        ": the full read's particles inside, in order, with every array and role (got " +
        std::to_string(region ? region->GetNumberOfPoints() : -1) + ")");
    scanned = region ? reader->GetParticlesScanned() : -1;
  }
  // Three pieces, as MPI ranks ask for them: together the serial region, in order.
  vtkIdType first = 0;
  bool pieces = true;
  for (int piece = 0; piece < 3; ++piece)
  {
    reader->UpdatePiece(piece, 3, 0);
    auto* part = vtkPolyData::SafeDownCast(reader->GetOutput());
    pieces = pieces && part && first + part->GetNumberOfPoints() <= vtkIdType(inside.size()) &&
      (part->GetNumberOfPoints() == 0 || SameParticlesAndArrays(all, inside, first, part));
    first += part ? part->GetNumberOfPoints() : 0;
  }
  Check(pieces && first == static_cast<vtkIdType>(inside.size()),
    what + ": 3 pieces hold the region's particles once each, in order (got " +
      std::to_string(first) + ")");
  std::cout << what << ": " << inside.size() << " of " << all->GetNumberOfPoints()
            << " particles inside, " << scanned << " scanned\n";
  return scanned;
}

void TestSwiftCellTables(const std::string& dir)
{
  const double box[6] = { 0.3, 0.6, 0.1, 0.45, 0.55, 0.95 };
  // Two files, the table's OffsetsInFile and Files, cells by their centres and size.
  const long long byCentres = CheckRegion<vtkHDF5SnapshotReader>(
    dir + "/swift_cells.1.hdf5", box, "SWIFT-style cells in two files (centres)", 1);
  Check(byCentres > 0 && byCentres < 1000,
    "SWIFT-style cells in two files: fewer particles scanned than the 1,000 (got " +
      std::to_string(byCentres) + ")");
  // A slab just past a cell face: it holds particles that drifted out of the cells before it.
  const double slab[6] = { 0.505, 0.6, 0.0, 1.0, 0.0, 1.0 };
  CheckRegion<vtkHDF5SnapshotReader>(dir + "/swift_cells.0.hdf5", slab,
    "SWIFT-style cells in two files, a slab past a cell face", 1);
  // One file, older SWIFT's global Offsets, each cell's own extent: fewer still.
  const long long byExtent = CheckRegion<vtkHDF5SnapshotReader>(
    dir + "/swift_old_cells.hdf5", box, "SWIFT-style cells, global offsets (extents)", 1);
  Check(byExtent > 0 && byExtent < byCentres,
    "cells' extents: fewer particles scanned than by centres (got " + std::to_string(byExtent) +
      " against " + std::to_string(byCentres) + ")");
  // A region across a corner of the box of side 1 (x past 1, y below 0): the particles on both
  // sides of each face, those that drifted past the faces too, from the cells near them alone.
  const double corner[6] = { 0.8, 1.2, -0.15, 0.2, 0.3, 0.6 };
  const long long acrossFaces = CheckRegion<vtkHDF5SnapshotReader>(dir + "/swift_cells.1.hdf5",
    corner, "SWIFT-style cells in two files, a region across a corner of the periodic box", 1);
  Check(acrossFaces > 0 && acrossFaces < 1000,
    "a region across a corner: fewer particles scanned than the 1,000 (got " +
      std::to_string(acrossFaces) + ")");
  // A table whose last cell lies beyond the file: not trusted, every particle read.
  const long long damaged = CheckRegion<vtkHDF5SnapshotReader>(
    dir + "/swift_bad_cells.hdf5", box, "a damaged cell table", 1);
  Check(damaged == 1000,
    "a damaged cell table: every particle scanned (got " + std::to_string(damaged) + ")");
}

void TestRealSwift(const std::string& path)
{
  const double box[6] = { 1.0, 2.5, 1.0, 2.5, 1.0, 2.5 }; // in a periodic box of side 2 pi
  const long long scanned = CheckRegion<vtkHDF5SnapshotReader>(path, box, path, 97);
  Check(scanned > 0 && scanned < 32768 / 4,
    path + ": its cell table keeps the read under a quarter of the 32,768 particles (got " +
      std::to_string(scanned) + ")");
  // Across the face x = 2 pi: wrapped, the particles near x = 0 too; not wrapped, those inside
  // the box alone.
  const double across[6] = { 5.5, 7.5, 1.0, 2.5, -0.5, 0.5 };
  const long long wrapped =
    CheckRegion<vtkHDF5SnapshotReader>(path, across, path + ", across two faces", 997);
  const long long cut = CheckRegion<vtkHDF5SnapshotReader>(
    path, across, path + ", across two faces, PeriodicRegion off", 997, false);
  Check(wrapped > cut && cut > 0 && wrapped < 32768 / 4,
    path +
      ": across two faces, the cell table's read grows with the wrapped parts and stays "
      "under a quarter of the particles (got " +
      std::to_string(wrapped) + " against " + std::to_string(cut) + " scanned)");
}

void TestGadgetAndTipsy(const std::string& dir, const std::string& shockTube)
{
  // Gas particle i of the test snapshot lies at x = 1 + 0.01 i, over two files.
  const double slab[6] = { 1.1, 1.3, -100.0, 100.0, -100.0, 100.0 };
  const long long gadget = CheckRegion<vtkGadgetBinaryReader>(
    dir + "/snap_format1.0", slab, "GADGET binary, two files", 1);
  Check(gadget == 50, "GADGET binary: every gas particle scanned (no table)");
  // Its BoxSize is 10: x in [10.9, 11.2] is x in [0.9, 1.2] a box away.
  const double away[6] = { 10.9, 11.2, -100.0, 100.0, -100.0, 100.0 };
  CheckRegion<vtkGadgetBinaryReader>(
    dir + "/snap_format1.0", away, "GADGET binary, a region a box away", 1);
  const double tube[6] = { -1.0, 1.0, -1.0, 1.0, -0.2, 0.3 };
  CheckRegion<vtkTipsyParticleReader>(shockTube, tube, "the shock tube, z in [-0.2, 0.3]", 997);
}

// A region's read reports progress after each chunk and stops when aborted there: an empty
// output, the file left after the first chunk.
void TestProgressAndAbort(const std::string& shockTube)
{
  vtkNew<vtkTipsyParticleReader> reader;
  reader->SetFileName(shockTube.c_str());
  reader->ReadRegionOn();
  reader->SetRegionBounds(-1.0, 1.0, -1.0, 1.0, -0.2, 0.3);
  reader->SetRegionChunkParticles(1000);
  std::vector<double> progress;
  vtkNew<vtkCallbackCommand> record;
  record->SetClientData(&progress);
  record->SetCallback([](vtkObject*, unsigned long, void* data, void* call) {
    static_cast<std::vector<double>*>(data)->push_back(*static_cast<double*>(call));
  });
  reader->AddObserver(vtkCommand::ProgressEvent, record);
  reader->Update();
  const bool rising = std::is_sorted(progress.begin(), progress.end());
  Check(progress.size() >= 20 && rising && progress.back() == 1.0,
    "the shock tube's region in chunks of 1,000: progress after each of its 20 chunks, rising "
    "to 1 (got " +
      std::to_string(progress.size()) + " reports)");
  vtkNew<vtkCallbackCommand> abort;
  abort->SetClientData(reader.Get());
  abort->SetCallback([](vtkObject*, unsigned long, void* data, void*) {
    static_cast<vtkAlgorithm*>(data)->AbortExecuteOn();
  });
  reader->AddObserver(vtkCommand::ProgressEvent, abort);
  reader->Modified();
  reader->Update();
  auto* out = vtkPolyData::SafeDownCast(reader->GetOutput());
  Check((!out || out->GetNumberOfPoints() == 0) && reader->GetParticlesScanned() == 1000,
    "aborted at the first progress report: an empty output, one chunk read (got " +
      std::to_string(reader->GetParticlesScanned()) + " particles scanned)");
}

void TestBadBounds(const std::string& dir)
{
  vtkNew<vtkHDF5SnapshotReader> reader;
  reader->SetFileName((dir + "/swift_old_cells.hdf5").c_str());
  reader->ReadRegionOn();
  reader->SetRegionBounds(0.5, 0.4, 0.0, 1.0, 0.0, 1.0);
  vtkNew<MessageCounter> errors, warnings;
  reader->AddObserver(vtkCommand::ErrorEvent, errors);
  reader->AddObserver(vtkCommand::WarningEvent, warnings);
  reader->Update();
  auto* out = vtkPolyData::SafeDownCast(reader->GetOutput());
  Check(errors->Count == 1 && errors->Last.find("RegionBounds (0.5, 0.4") != std::string::npos &&
      (!out || out->GetNumberOfPoints() == 0),
    "xmin > xmax: an error naming RegionBounds, an empty output (got: " + errors->Last + ")");
  // (Not wrapped: in its periodic box of side 1 this region would span the box.)
  reader->PeriodicRegionOff();
  reader->SetRegionBounds(5.0, 6.0, 5.0, 6.0, 5.0, 6.0);
  reader->Update();
  out = vtkPolyData::SafeDownCast(reader->GetOutput());
  Check(errors->Count == 1 && warnings->Count == 1 &&
      warnings->Last.find("no particle inside RegionBounds") != std::string::npos && out &&
      out->GetNumberOfPoints() == 0,
    "a region beyond every particle: a warning, an empty output (got: " + warnings->Last + ")");
}
// vtkLevelSetIsosurface on a region's read warns when the surface comes near the region's faces
// (the field data RegionBounds, RegionPeriod): periodic_blob.hdf5's sphere of radius 0.08
// about the corner of its periodic box, read from [-w, w]^3 across three faces. Half-width 0.3:
// no warning, the full read's points; 0.1 (0.02 beyond the sphere, less than two neighbourhood
// radii): a warning naming RegionBounds, from the full method and again from a quick isovalue
// change; the full read (no region): none.
void TestFilterWarnsNearFaces(const std::string& dir)
{
  const std::string path = dir + "/periodic_blob.hdf5";
  auto run = [&](double halfWidth, int& warnings, std::string& text, vtkIdType& points) {
    vtkNew<vtkHDF5SnapshotReader> reader;
    reader->SetFileName(path.c_str());
    reader->SetReadRegion(halfWidth > 0.0);
    reader->SetRegionBounds(-halfWidth, halfWidth, -halfWidth, halfWidth, -halfWidth, halfWidth);
    vtkNew<vtkLevelSetIsosurface> filter;
    filter->SetInputConnection(reader->GetOutputPort());
    filter->SetIsoValue(std::exp(-0.5));
    filter->SetSeedCenter(0.01, 0.01, 0.01);
    filter->SetSeedRadius(0.02);
    filter->SetOutputTypeToIsopoints();
    filter->QuickIsoValueChangesOn();
    // The blob's file has no smoothing lengths: the fit, asked for (Automatic would say so).
    filter->SetField(vtkLevelSetIsosurface::MLS_FIELD);
    vtkNew<MessageCounter> counter;
    filter->AddObserver(vtkCommand::WarningEvent, counter);
    filter->Update();
    points = filter->GetOutput()->GetNumberOfPoints();
    filter->SetIsoValue(1.01 * std::exp(-0.5)); // a quick change: the surface slides
    filter->Update();
    warnings = counter->Count;
    text = counter->All;
    return filter->GetSlidLastSurface() != 0;
  };
  int wide = 0, tight = 0, whole = 0;
  std::string wideText, tightText, wholeText;
  vtkIdType widePoints = 0, tightPoints = 0, wholePoints = 0;
  run(0.3, wide, wideText, widePoints);
  const bool slid = run(0.1, tight, tightText, tightPoints);
  run(0.0, whole, wholeText, wholePoints);
  Check(wide == 0 && whole == 0 && widePoints == wholePoints && wholePoints > 200,
    "the blob from the region [-0.3, 0.3]^3 and from the full read: no warning, the same " +
      std::to_string(wholePoints) + " points (got " + std::to_string(wide) + " and " +
      std::to_string(whole) + " warnings, " + std::to_string(widePoints) + " points): " + wideText +
      wholeText);
  Check(slid && tight == 2 && tightText.find("RegionBounds -0.1 0.1") != std::string::npos &&
      tightText.find("Widen the region") != std::string::npos,
    "the blob from the region [-0.1, 0.1]^3: a warning naming the region, from the method and "
    "from a quick change (got " +
      std::to_string(tight) + ", slid " + std::to_string(slid) + "): " + tightText);
}
} // namespace

int main(int argc, char* argv[])
{
  if (argc != 4)
  {
    std::cerr << "usage: TestReadRegion TEST_SNAPSHOT_DIR SWIFT_FILE SHOCK_TUBE_FILE\n";
    return EXIT_FAILURE;
  }
  TestRanges();
  TestPeriodicRegion();
  TestSwiftCellTables(argv[1]);
  TestRealSwift(argv[2]);
  TestGadgetAndTipsy(argv[1], argv[3]);
  TestProgressAndAbort(argv[3]);
  TestBadBounds(argv[1]);
  TestFilterWarnsNearFaces(argv[1]);
  std::cout << (lsi::test::Failures() ? "region tests FAILED\n" : "region tests passed\n");
  return lsi::test::Failures() ? EXIT_FAILURE : EXIT_SUCCESS;
}
