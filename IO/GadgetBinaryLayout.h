// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
// The layout of one file of a GADGET binary snapshot (SnapFormat 1 or 2), as the GADGET-2
// user guide describes it: Fortran-style records (a 4-byte length before and after each), the
// first the header (GADGET-2's 256 bytes, or GADGET-4's own 192), then one record per block
// (positions, velocities, ids, masses, then the gas's internal energy, density, smoothing length,
// ...), each holding the values of the particle types it covers, type 0 first. Format 2 puts a
// small record before each block naming it ("POS ", "VEL ", "ID  ", ...), and GADGET-3 an INFO
// block describing the others; format 1 gives blocks in a fixed order instead. Either byte order is
// recognised from the first record's length. Plain C++: what the file holds and where, for
// vtkGadgetBinaryReader to read.
#ifndef LevelSetIsosurface_GadgetBinaryLayout_h
#define LevelSetIsosurface_GadgetBinaryLayout_h

#include <array>
#include <cstdint>
#include <istream>
#include <string>
#include <vector>

namespace lsi
{
namespace gadget
{

constexpr int NumberOfTypes = 6;

/// The header of a file: GADGET-2's io_header (the 256-byte record), or GADGET-4's own (192
/// bytes: counts, totals, mass table, time, redshift, box size, number of files).
struct Header
{
  std::array<long long, NumberOfTypes> ThisFile{}; // particles of each type in this file
  std::array<long long, NumberOfTypes> Total{};    // in the whole snapshot (high words added)
  std::array<double, NumberOfTypes> MassTable{};   // a type's mass, or 0: in the MASS block
  double Time = 0.0, Redshift = 0.0;
  double BoxSize = 0.0, Omega0 = 0.0, OmegaLambda = 0.0, HubbleParam = 0.0;
  int FlagSfr = 0, FlagFeedback = 0, FlagCooling = 0, NumFiles = 1;
  int FlagStellarAge = 0, FlagMetals = 0, FlagEntropyICs = 0;
  bool Gadget4 = false; // GADGET-4's own header: no flags, no cosmology (left 0)
};

/// One block of per-particle values: its array name (HDF5 snapshots' names: "Coordinates",
/// "Velocities", "ParticleIDs", "Masses", "InternalEnergy", "Density", "SmoothingLength", ...),
/// where its values start, and the types it covers, in type order.
struct Block
{
  std::string Name;
  std::uint64_t Offset = 0; // of its first value, from the start of the file
  int Components = 1;       // 3 for vectors
  int ValueBytes = 4;       // 4 or 8
  bool Integer = false;     // unsigned integers (the ids), else floating point
  std::array<bool, NumberOfTypes> Covers{};
};

struct FileLayout
{
  bool BigEndian = false;
  bool Format2 = false;
  Header Head;
  std::vector<Block> Blocks;
  /// Blocks not understood (a format-1 block after the order broke, a format-2 block whose size
  /// fits no particle count), left out: their labels or positions, for a message.
  std::vector<std::string> LeftOut;

  /// The block named `name` that covers `type`, or null.
  const Block* Find(const std::string& name, int type) const;
};

/// Reads the header and the blocks' places of the file `in`, `size` bytes long. False with
/// `problem` set (in words, without the file's name) when it is not such a file (a first record
/// of neither 256 or 192 bytes, format 1, nor 8, format 2, in either byte order), or damaged.
bool ReadLayout(std::istream& in, std::uint64_t size, FileLayout& layout, std::string& problem);

/// The byte offset of particle `index` of `type` (counted within this file) in `block`.
std::uint64_t ValueOffset(const FileLayout& layout, const Block& block, int type, long long index);

} // namespace gadget
} // namespace lsi

#endif
