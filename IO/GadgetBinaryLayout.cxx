// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "GadgetBinaryLayout.h"

#include "ByteOrder.h"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace lsi
{
namespace gadget
{
namespace
{
constexpr std::uint32_t HeaderBytes = 256;        // GADGET-1/2/3's io_header
constexpr std::uint32_t Gadget4HeaderBytes = 192; // GADGET-4's own, for 6 types
constexpr std::uint32_t LabelBytes = 8; // format 2: 4 characters and the next record's length

// Whether a file's first record length (read in some byte order) starts a snapshot: a header
// of format 1 or the label of format 2.
bool StartsSnapshot(std::uint32_t firstLength)
{
  return firstLength == HeaderBytes || firstLength == Gadget4HeaderBytes ||
    firstLength == LabelBytes;
}

// Which types a block covers, by what the block holds.
enum class Coverage
{
  All,     // every type present (positions, velocities, ids, ...)
  Massive, // types present whose MassTable entry is 0 (the MASS block)
  Gas,     // type 0 (internal energy, density, smoothing length, ...)
  Stars,   // type 4 (stellar ages)
  GasStars // types 0 and 4 (metallicities)
};

struct KnownBlock
{
  const char* Label; // format 2's, without trailing blanks
  const char* Name;
  int Components;
  bool Integer;
  Coverage Covers;
};

// GADGET-2/3's blocks, in format 1's order (io.c; NE and NH only with cooling, SFR with star
// formation, AGE with stellar ages, Z with metals: the header's flags).
const KnownBlock Known[] = {
  { "POS", "Coordinates", 3, false, Coverage::All },
  { "VEL", "Velocities", 3, false, Coverage::All },
  { "ID", "ParticleIDs", 1, true, Coverage::All },
  { "MASS", "Masses", 1, false, Coverage::Massive },
  { "U", "InternalEnergy", 1, false, Coverage::Gas },
  { "RHO", "Density", 1, false, Coverage::Gas },
  { "NE", "ElectronAbundance", 1, false, Coverage::Gas },
  { "NH", "NeutralHydrogenAbundance", 1, false, Coverage::Gas },
  { "HSML", "SmoothingLength", 1, false, Coverage::Gas },
  { "SFR", "StarFormationRate", 1, false, Coverage::Gas },
  { "AGE", "StellarFormationTime", 1, false, Coverage::Stars },
  { "Z", "Metallicity", 1, false, Coverage::GasStars },
  { "POT", "Potential", 1, false, Coverage::All },
  { "ACCE", "Acceleration", 3, false, Coverage::All },
  { "ENDT", "RateOfChangeOfEntropy", 1, false, Coverage::Gas },
  { "TSTP", "TimeStep", 1, false, Coverage::All },
};

const KnownBlock* KnownByLabel(const std::string& label)
{
  for (const KnownBlock& known : Known)
  {
    if (label == known.Label)
    {
      return &known;
    }
  }
  return nullptr;
}

// Format 1's blocks in order, as the header's flags say the file has them (`cooling`: NE and
// NH; the blocks after Z depend on compile-time options no header records: not named).
std::vector<const KnownBlock*> FormatOneOrder(const Header& head, bool cooling)
{
  std::vector<const KnownBlock*> order;
  for (const KnownBlock& known : Known)
  {
    const std::string label = known.Label;
    if ((label == "NE" || label == "NH") && !cooling)
    {
      continue;
    }
    if ((label == "SFR" && !head.FlagSfr) || (label == "AGE" && !head.FlagStellarAge) ||
      (label == "Z" && !head.FlagMetals))
    {
      continue;
    }
    order.push_back(&known);
    if (label == "Z")
    {
      break;
    }
  }
  return order;
}

std::array<bool, NumberOfTypes> Covered(const Header& head, Coverage coverage)
{
  std::array<bool, NumberOfTypes> covers{};
  for (int t = 0; t < NumberOfTypes; ++t)
  {
    const bool present = head.ThisFile[t] > 0;
    switch (coverage)
    {
      case Coverage::All:
        covers[t] = present;
        break;
      case Coverage::Massive:
        covers[t] = present && head.MassTable[t] == 0.0;
        break;
      case Coverage::Gas:
        covers[t] = present && t == 0;
        break;
      case Coverage::Stars:
        covers[t] = present && t == 4;
        break;
      case Coverage::GasStars:
        covers[t] = present && (t == 0 || t == 4);
        break;
    }
  }
  return covers;
}

long long CountCovered(const Header& head, const std::array<bool, NumberOfTypes>& covers)
{
  long long count = 0;
  for (int t = 0; t < NumberOfTypes; ++t)
  {
    count += covers[t] ? head.ThisFile[t] : 0;
  }
  return count;
}

// The bytes per value of a block of `bytes` over `count` particles of `components` values: 4 or
// 8, else 0 (the size does not fit).
int ValueBytesFor(std::uint64_t bytes, long long count, int components)
{
  if (count <= 0)
  {
    return 0;
  }
  const std::uint64_t per = static_cast<std::uint64_t>(count) * components;
  for (int valueBytes : { 4, 8 })
  {
    if (bytes == per * valueBytes)
    {
      return valueBytes;
    }
  }
  return 0;
}

// Gives `block` the name and coverage of `known` if its size fits them. (Some initial
// conditions hold a MASS block of every type even where the mass table has a mass: read too.)
bool Describe(const Header& head, const KnownBlock& known, std::uint64_t bytes, Block& block)
{
  block.Name = known.Name;
  block.Components = known.Components;
  block.Integer = known.Integer;
  for (Coverage coverage : { known.Covers, Coverage::All })
  {
    block.Covers = Covered(head, coverage);
    block.ValueBytes = ValueBytesFor(bytes, CountCovered(head, block.Covers), known.Components);
    if (block.ValueBytes != 0 || known.Covers != Coverage::Massive)
    {
      break;
    }
  }
  return block.ValueBytes != 0;
}

// A block of unknown meaning: every type or the gas, one value or three per particle, as its
// size fits (in that order of preference). Named `name`.
bool DescribeUnknown(const Header& head, const std::string& name, std::uint64_t bytes, Block& block)
{
  for (Coverage coverage : { Coverage::All, Coverage::Gas })
  {
    for (int components : { 1, 3 })
    {
      const KnownBlock guess = { "", "", components, false, coverage };
      if (Describe(head, guess, bytes, block))
      {
        block.Name = name;
        return true;
      }
    }
  }
  return false;
}

// GADGET-1/2/3's 256-byte io_header.
bool ParseGadget2Header(const char* b, bool big, Header& head, std::string& problem)
{
  auto i32 = [&](int at) { return FromBytes<std::int32_t>(b + at, big); };
  auto u32 = [&](int at) { return FromBytes<std::uint32_t>(b + at, big); };
  auto f64 = [&](int at) { return FromBytes<double>(b + at, big); };
  for (int t = 0; t < NumberOfTypes; ++t)
  {
    const std::int32_t thisFile = i32(4 * t);
    if (thisFile < 0)
    {
      problem = "the header counts " + std::to_string(thisFile) + " particles of type " +
        std::to_string(t) + " (not a GADGET binary snapshot, or damaged)";
      return false;
    }
    head.ThisFile[t] = thisFile;
    head.MassTable[t] = f64(24 + 8 * t);
    head.Total[t] =
      static_cast<long long>(u32(96 + 4 * t)) + (static_cast<long long>(u32(168 + 4 * t)) << 32);
  }
  head.Time = f64(72);
  head.Redshift = f64(80);
  head.FlagSfr = i32(88);
  head.FlagFeedback = i32(92);
  head.FlagCooling = i32(120);
  head.NumFiles = std::max<std::int32_t>(1, i32(124)); // 0 in some hand-made initial conditions
  head.BoxSize = f64(128);
  head.Omega0 = f64(136);
  head.OmegaLambda = f64(144);
  head.HubbleParam = f64(152);
  head.FlagStellarAge = i32(160);
  head.FlagMetals = i32(164);
  head.FlagEntropyICs = i32(192);
  return true;
}

// GADGET-4's own header (without GADGET2_HEADER, 6 types): long long npart[6], npartTotal[6];
// double mass[6], time, redshift, BoxSize; int num_files; long long Ntrees, TotNtrees.
bool ParseGadget4Header(const char* b, bool big, Header& head, std::string& problem)
{
  for (int t = 0; t < NumberOfTypes; ++t)
  {
    const std::int64_t thisFile = FromBytes<std::int64_t>(b + 8 * t, big);
    const std::int64_t total = FromBytes<std::int64_t>(b + 48 + 8 * t, big);
    if (thisFile < 0 || thisFile > (std::int64_t(1) << 40) || total < 0)
    {
      problem = "the header counts " + std::to_string(thisFile) + " particles of type " +
        std::to_string(t) + " (damaged, or not a GADGET binary snapshot)";
      return false;
    }
    head.ThisFile[t] = thisFile;
    head.Total[t] = total;
    head.MassTable[t] = FromBytes<double>(b + 96 + 8 * t, big);
  }
  head.Time = FromBytes<double>(b + 144, big);
  head.Redshift = FromBytes<double>(b + 152, big);
  head.BoxSize = FromBytes<double>(b + 160, big);
  head.NumFiles = std::max<std::int32_t>(1, FromBytes<std::int32_t>(b + 168, big));
  head.Gadget4 = true;
  return true;
}

// Either header, then what any header must hold.
bool ParseHeader(const char* b, std::uint32_t length, bool big, Header& head, std::string& problem)
{
  if (!(length == HeaderBytes ? ParseGadget2Header(b, big, head, problem)
                              : ParseGadget4Header(b, big, head, problem)))
  {
    return false;
  }
  if (!std::isfinite(head.Time) || !std::isfinite(head.BoxSize))
  {
    problem = "the header's time or box size is not a finite number (not a GADGET binary "
              "snapshot, or damaged)";
    return false;
  }
  for (double m : head.MassTable)
  {
    if (!(m >= 0.0) || !std::isfinite(m))
    {
      problem = "the header's mass table holds " + std::to_string(m) +
        " (not a GADGET binary snapshot, or damaged)";
      return false;
    }
  }
  return true;
}

// Reads a record's length at `at`, checks the same length follows the record: its data then
// lie at at + 4, `length` bytes.
bool ReadRecord(std::istream& in, std::uint64_t size, std::uint64_t at, bool big,
  std::uint32_t& length, std::string& problem)
{
  char bytes[4];
  if (at + 4 > size || !in.seekg(static_cast<std::streamoff>(at)) || !in.read(bytes, 4))
  {
    problem = "the file ends inside a record's length at byte " + std::to_string(at);
    return false;
  }
  length = FromBytes<std::uint32_t>(bytes, big);
  const std::uint64_t end = at + 4 + static_cast<std::uint64_t>(length);
  if (end + 4 > size || !in.seekg(static_cast<std::streamoff>(end)) || !in.read(bytes, 4))
  {
    problem = "a record of " + std::to_string(length) + " bytes at byte " + std::to_string(at) +
      " runs past the end of the file (truncated?)";
    return false;
  }
  if (FromBytes<std::uint32_t>(bytes, big) != length)
  {
    problem = "the record at byte " + std::to_string(at) +
      " does not end with its length (damaged, or not a GADGET binary snapshot)";
    return false;
  }
  return true;
}

// Text of `size` characters without its trailing blanks and NULs.
std::string Trimmed(const char* text, std::size_t size = 4)
{
  std::string trimmed(text, size);
  while (!trimmed.empty() && (trimmed.back() == ' ' || trimmed.back() == '\0'))
  {
    trimmed.pop_back();
  }
  return trimmed;
}

// Where a block's record lies (format 2: with its label).
struct RecordPlace
{
  std::string Label;
  std::uint64_t Offset = 0; // of its data
  std::uint64_t Length = 0;
};

// Adds `block` to the layout, or to those left out if a block of its name came first.
void Add(const Block& block, FileLayout& layout)
{
  if (std::any_of(layout.Blocks.begin(), layout.Blocks.end(),
        [&](const Block& earlier) { return earlier.Name == block.Name; }))
  {
    layout.LeftOut.push_back(block.Name + " (again)");
    return;
  }
  layout.Blocks.push_back(block);
}

// One entry of GADGET-3's INFO block (format 2): a block's label, value type, values per
// particle and the types that have it (40 bytes: char[4], char[8], int32, int32[6]).
struct InfoEntry
{
  std::string Label;
  int ValueBytes = 4;
  bool Integer = false;
  int Components = 1;
  std::array<bool, NumberOfTypes> Present{};
};
constexpr std::uint64_t InfoEntryBytes = 40;

// The INFO block's entries (none if it is not one: a size that is no multiple of an entry, or
// above a thousand entries, or types it does not name).
std::vector<InfoEntry> ReadInfo(std::istream& in, const RecordPlace& record, bool big)
{
  std::vector<InfoEntry> entries;
  if (record.Length % InfoEntryBytes != 0 || record.Length > 1000 * InfoEntryBytes)
  {
    return entries;
  }
  std::vector<char> bytes(static_cast<std::size_t>(record.Length));
  if (!in.seekg(static_cast<std::streamoff>(record.Offset)) ||
    !in.read(bytes.data(), static_cast<std::streamsize>(bytes.size())))
  {
    return entries;
  }
  for (std::size_t at = 0; at < bytes.size(); at += InfoEntryBytes)
  {
    InfoEntry entry;
    entry.Label = Trimmed(&bytes[at]);
    const std::string type = Trimmed(&bytes[at + 4], 8);
    const std::int32_t dimensions = FromBytes<std::int32_t>(&bytes[at + 12], big);
    const bool known = type == "FLOAT" || type == "FLOATN" || type == "DOUBLE" ||
      type == "DOUBLEN" || type == "LONG" || type == "LLONG";
    if (!known || dimensions < 1 || dimensions > 64)
    {
      return std::vector<InfoEntry>();
    }
    entry.ValueBytes = type == "DOUBLE" || type == "DOUBLEN" || type == "LLONG" ? 8 : 4;
    entry.Integer = type == "LONG" || type == "LLONG";
    entry.Components = dimensions;
    for (int t = 0; t < NumberOfTypes; ++t)
    {
      entry.Present[t] = FromBytes<std::int32_t>(&bytes[at + 16 + 4 * t], big) != 0;
    }
    entries.push_back(entry);
  }
  return entries;
}

// Gives `block` what the INFO entry for its label says, if its size fits that.
bool DescribeFromInfo(const Header& head, const std::vector<InfoEntry>& info,
  const std::string& label, std::uint64_t bytes, Block& block)
{
  for (const InfoEntry& entry : info)
  {
    if (entry.Label != label)
    {
      continue;
    }
    const KnownBlock* known = KnownByLabel(label);
    block.Name = known ? known->Name : label;
    block.Components = entry.Components;
    block.ValueBytes = entry.ValueBytes;
    block.Integer = entry.Integer;
    for (int t = 0; t < NumberOfTypes; ++t)
    {
      block.Covers[t] = entry.Present[t] && head.ThisFile[t] > 0;
    }
    return ValueBytesFor(bytes, CountCovered(head, block.Covers), entry.Components) ==
      entry.ValueBytes;
  }
  return false;
}

// Format 2: each block as the INFO block (where there is one) or its label says; unknown labels
// by their size.
void NameLabelled(const Header& head, const std::vector<RecordPlace>& records,
  const std::vector<InfoEntry>& info, FileLayout& layout)
{
  for (std::size_t r = 0; r < records.size(); ++r)
  {
    if (records[r].Label == "INFO")
    {
      continue; // (read before)
    }
    Block block;
    block.Offset = records[r].Offset;
    const KnownBlock* known = KnownByLabel(records[r].Label);
    const std::string name =
      records[r].Label.empty() ? "Block" + std::to_string(r + 1) : records[r].Label;
    if (DescribeFromInfo(head, info, records[r].Label, records[r].Length, block) ||
      (known && Describe(head, *known, records[r].Length, block)) ||
      DescribeUnknown(head, name, records[r].Length, block))
    {
      Add(block, layout);
    }
    else
    {
      layout.LeftOut.push_back(name);
    }
  }
}

// Format 1: the blocks in GADGET-2's order while their sizes fit it; the others by their size,
// named Block<N> (N counted from the first block after the header).
void NameInOrder(
  const Header& head, const std::vector<RecordPlace>& records, bool cooling, FileLayout& layout)
{
  layout.Blocks.clear();
  layout.LeftOut.clear();
  const std::vector<const KnownBlock*> order = FormatOneOrder(head, cooling);
  std::size_t next = 0;     // the next block expected in `order`
  bool orderBroken = false; // a block that did not fit the order was met
  for (std::size_t r = 0; r < records.size(); ++r)
  {
    Block block;
    block.Offset = records[r].Offset;
    // Blocks covering no particle are not written: skip them in the order.
    while (next < order.size() && CountCovered(head, Covered(head, order[next]->Covers)) == 0)
    {
      ++next;
    }
    bool described = false;
    if (!orderBroken && next < order.size())
    {
      described = Describe(head, *order[next], records[r].Length, block);
      orderBroken = !described;
      next += described ? 1 : 0;
    }
    const std::string name = "Block" + std::to_string(r + 1);
    if (described || DescribeUnknown(head, name, records[r].Length, block))
    {
      Add(block, layout);
    }
    else
    {
      layout.LeftOut.push_back(name);
    }
  }
}

// How many blocks of one value per gas particle follow the block named Density.
int GasBlocksAfterDensity(
  const Header& head, const std::vector<RecordPlace>& records, const FileLayout& layout)
{
  const Block* density = layout.Find("Density", 0);
  int count = 0;
  bool after = false;
  for (const RecordPlace& record : records)
  {
    if (after)
    {
      if (ValueBytesFor(record.Length, head.ThisFile[0], 1) == 0)
      {
        break;
      }
      ++count;
    }
    after = after || (density && record.Offset == density->Offset);
  }
  return count;
}
} // namespace

const Block* FileLayout::Find(const std::string& name, int type) const
{
  for (const Block& block : this->Blocks)
  {
    if (block.Name == name && block.Covers[type])
    {
      return &block;
    }
  }
  return nullptr;
}

bool ReadLayout(std::istream& in, std::uint64_t size, FileLayout& layout, std::string& problem)
{
  layout = FileLayout();
  char first[4];
  if (size < 4 || !in.seekg(0) || !in.read(first, 4) ||
    !(StartsSnapshot(FromBytes<std::uint32_t>(first, false)) ||
      StartsSnapshot(FromBytes<std::uint32_t>(first, true))))
  {
    problem = "not a GADGET binary snapshot (its first record is neither a header of format 1, "
              "256 bytes or GADGET-4's 192, nor the 8-byte label of format 2)";
    return false;
  }
  layout.BigEndian = !StartsSnapshot(FromBytes<std::uint32_t>(first, false));
  const bool big = layout.BigEndian;
  std::uint32_t length = FromBytes<std::uint32_t>(first, big);
  layout.Format2 = length == LabelBytes;
  std::uint64_t at = 0;
  // Format 2: the label of the next block, and where that block's record starts.
  auto readLabel = [&](std::string& label) {
    std::uint32_t labelLength = 0;
    if (!ReadRecord(in, size, at, big, labelLength, problem))
    {
      return false;
    }
    char bytes[LabelBytes];
    if (labelLength != LabelBytes || !in.seekg(static_cast<std::streamoff>(at + 4)) ||
      !in.read(bytes, LabelBytes))
    {
      problem = "a block label at byte " + std::to_string(at) + " is not 8 bytes (format 2)";
      return false;
    }
    label = Trimmed(bytes);
    at += 4 + LabelBytes + 4;
    return true;
  };
  std::string label;
  if (layout.Format2 && !readLabel(label))
  {
    return false;
  }
  if (!ReadRecord(in, size, at, big, length, problem))
  {
    return false;
  }
  char header[HeaderBytes];
  if ((length != HeaderBytes && length != Gadget4HeaderBytes) ||
    !in.seekg(static_cast<std::streamoff>(at + 4)) || !in.read(header, length))
  {
    problem = "the header record is " + std::to_string(length) +
      " bytes, neither GADGET-1/2/3's 256 nor GADGET-4's 192 (a GADGET-4 built with other than "
      "6 particle types: read its HDF5 output)";
    return false;
  }
  if (!ParseHeader(header, length, big, layout.Head, problem))
  {
    return false;
  }
  at += 4 + static_cast<std::uint64_t>(length) + 4;
  // Every block's record (and label), then their names and types.
  std::vector<RecordPlace> records;
  while (at < size)
  {
    RecordPlace record;
    if (layout.Format2 && !readLabel(record.Label))
    {
      return false;
    }
    if (!ReadRecord(in, size, at, big, length, problem))
    {
      return false;
    }
    record.Offset = at + 4;
    record.Length = length;
    records.push_back(record);
    at += 4 + static_cast<std::uint64_t>(length) + 4;
  }
  const Header& head = layout.Head;
  if (layout.Format2)
  {
    std::vector<InfoEntry> info;
    for (const RecordPlace& record : records)
    {
      info = record.Label == "INFO" ? ReadInfo(in, record, big) : info;
    }
    NameLabelled(head, records, info, layout);
  }
  else
  {
    NameInOrder(head, records, head.FlagCooling != 0, layout);
    // A header may say cooling where the run wrote no NE and NH blocks (GADGET-2 writes its
    // parameter CoolingOn there, with or without cooling's blocks): then fewer than three
    // one-value gas blocks (NE, NH, HSML) follow the density, and the blocks are named without.
    if (head.FlagCooling && GasBlocksAfterDensity(head, records, layout) < 3)
    {
      NameInOrder(head, records, false, layout);
    }
  }
  const bool anyParticles = std::any_of(
    head.ThisFile.begin(), head.ThisFile.end(), [](long long count) { return count > 0; });
  if (anyParticles && !std::any_of(layout.Blocks.begin(), layout.Blocks.end(), [](const Block& b) {
        return b.Name == "Coordinates";
      }))
  {
    problem = "no block of positions fits the header's particle counts";
    return false;
  }
  return true;
}

std::uint64_t ValueOffset(const FileLayout& layout, const Block& block, int type, long long index)
{
  long long before = 0;
  for (int t = 0; t < type; ++t)
  {
    before += block.Covers[t] ? layout.Head.ThisFile[t] : 0;
  }
  const std::uint64_t valueBytes = static_cast<std::uint64_t>(block.ValueBytes) * block.Components;
  return block.Offset + static_cast<std::uint64_t>(before + index) * valueBytes;
}

} // namespace gadget
} // namespace lsi
