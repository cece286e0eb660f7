// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
// A GADGET binary snapshot writer for the tests, written field by field after GADGET-2's
// io_header (or GADGET-4's own header) and its blocks, independent of the reader's code: format
// 1 or 2 (labelled blocks, optionally GADGET-3's INFO block), either byte order, single or
// double precision per block, 4- or 8-byte ids, one file or several.
#ifndef GadgetWriter_h
#define GadgetWriter_h

#include "OrderedBytes.h"

#include <array>
#include <cstdint>
#include <fstream>
#include <functional>
#include <string>
#include <vector>

namespace lsi
{
namespace test
{
// Bytes in a chosen byte order, and reals in single or double precision.
class Bytes : public OrderedBytes
{
public:
  using OrderedBytes::OrderedBytes;
  void PutReal(double value, bool asDouble)
  {
    if (asDouble)
    {
      this->Put<double>(value);
    }
    else
    {
      this->Put<float>(static_cast<float>(value));
    }
  }
};

// The particles to write: counts per type in the whole snapshot, the mass table, and each
// block's value of particle g (its index within its type) as a function.
struct Particles
{
  std::array<int, 6> Counts{};
  std::array<double, 6> MassTable{};
  double Time = 0.0, Redshift = 0.0, BoxSize = 0.0;
  // value(type, g, component) of each block, by format 2 label.
  struct Column
  {
    std::string Label;
    int Components;
    bool GasOnly;
    bool Double;
    std::function<double(int, int, int)> Value;
    int OnlyType = -1; // >= 0: a block of that type alone
  };
  std::vector<Column> Columns;
  std::function<std::uint64_t(int, int)> Id;
  bool Ids64 = false;
};

struct WriteOptions
{
  int Format = 1;
  bool BigEndian = false;
  bool Cooling = false;
  bool CoolingFlagOnly = false; // the header says cooling, no NE and NH blocks are written
  int Files = 1;
  bool Info = false;    // format 2: an INFO block (GADGET-3's) describing every block
  bool Gadget4 = false; // GADGET-4's own header (192 bytes) instead of GADGET-2's
};

// Particle g of type t lies in file p of `files`: [p * n / files, (p + 1) * n / files).
inline int FirstOf(int n, int p, int files)
{
  return static_cast<int>(static_cast<long long>(n) * p / files);
}

inline void Record(std::ofstream& out, const Bytes& data, bool bigEndian)
{
  Bytes length(bigEndian);
  length.Put<std::int32_t>(static_cast<std::int32_t>(data.Data.size()));
  out.write(length.Data.data(), 4);
  out.write(data.Data.data(), static_cast<std::streamsize>(data.Data.size()));
  out.write(length.Data.data(), 4);
}

inline void Label(
  std::ofstream& out, const std::string& label, std::size_t nextBytes, bool bigEndian)
{
  Bytes data(bigEndian);
  std::string padded = label;
  padded.resize(4, ' ');
  data.Data.insert(data.Data.end(), padded.begin(), padded.end());
  data.Put<std::int32_t>(static_cast<std::int32_t>(nextBytes + 8));
  Record(out, data, bigEndian);
}

// GADGET-2's io_header, field by field, padded to 256 bytes; `count`: this file's particles.
inline Bytes Gadget2Header(
  const Particles& particles, const WriteOptions& o, const std::array<int, 6>& count)
{
  Bytes header(o.BigEndian);
  for (int t = 0; t < 6; ++t)
  {
    header.Put<std::int32_t>(count[t]);
  }
  for (int t = 0; t < 6; ++t)
  {
    header.Put<double>(particles.MassTable[t]);
  }
  header.Put<double>(particles.Time);
  header.Put<double>(particles.Redshift);
  header.Put<std::int32_t>(0); // flag_sfr
  header.Put<std::int32_t>(0); // flag_feedback
  for (int t = 0; t < 6; ++t)
  {
    header.Put<std::uint32_t>(static_cast<std::uint32_t>(particles.Counts[t]));
  }
  header.Put<std::int32_t>(o.Cooling || o.CoolingFlagOnly ? 1 : 0);
  header.Put<std::int32_t>(o.Files);
  header.Put<double>(particles.BoxSize);
  header.Put<double>(0.3);     // Omega0
  header.Put<double>(0.7);     // OmegaLambda
  header.Put<double>(0.68);    // HubbleParam
  header.Put<std::int32_t>(0); // flag_stellarage
  header.Put<std::int32_t>(0); // flag_metals
  for (int t = 0; t < 6; ++t)
  {
    header.Put<std::uint32_t>(0); // npartTotalHighWord
  }
  header.Put<std::int32_t>(0); // flag_entropy_instead_u
  header.Data.resize(256, '\0');
  return header;
}

// GADGET-4's own header (snap_io.h without GADGET2_HEADER): 64-bit counts and totals, masses,
// time, redshift, box size, number of files, then Ntrees and TotNtrees after 4 bytes of
// alignment: 192 bytes.
inline Bytes Gadget4Header(
  const Particles& particles, const WriteOptions& o, const std::array<int, 6>& count)
{
  Bytes header(o.BigEndian);
  for (int t = 0; t < 6; ++t)
  {
    header.Put<std::int64_t>(count[t]);
  }
  for (int t = 0; t < 6; ++t)
  {
    header.Put<std::int64_t>(particles.Counts[t]);
  }
  for (int t = 0; t < 6; ++t)
  {
    header.Put<double>(particles.MassTable[t]);
  }
  header.Put<double>(particles.Time);
  header.Put<double>(particles.Redshift);
  header.Put<double>(particles.BoxSize);
  header.Put<std::int32_t>(o.Files);
  header.Put<std::int32_t>(0); // (alignment)
  header.Put<std::int64_t>(0); // Ntrees
  header.Put<std::int64_t>(0); // TotNtrees
  return header;
}

// Writes the snapshot to `path` (files path.0, path.1, ... when split).
inline void WriteGadget(const std::string& path, const Particles& particles, const WriteOptions& o)
{
  for (int p = 0; p < o.Files; ++p)
  {
    std::ofstream out(o.Files > 1 ? path + "." + std::to_string(p) : path, std::ios::binary);
    std::array<int, 6> first{}, count{};
    for (int t = 0; t < 6; ++t)
    {
      first[t] = FirstOf(particles.Counts[t], p, o.Files);
      count[t] = FirstOf(particles.Counts[t], p + 1, o.Files) - first[t];
    }
    const Bytes header =
      o.Gadget4 ? Gadget4Header(particles, o, count) : Gadget2Header(particles, o, count);
    if (o.Format == 2)
    {
      Label(out, "HEAD", header.Data.size(), o.BigEndian);
    }
    Record(out, header, o.BigEndian);
    auto block = [&](const std::string& label, std::function<bool(int)> covers,
                   std::function<void(Bytes&, int, int)> put) {
      Bytes data(o.BigEndian);
      for (int t = 0; t < 6; ++t)
      {
        for (int g = first[t]; g < first[t] + count[t] && covers(t); ++g)
        {
          put(data, t, g);
        }
      }
      if (data.Data.empty())
      {
        return; // GADGET writes no block without particles
      }
      if (o.Format == 2)
      {
        Label(out, label, data.Data.size(), o.BigEndian);
      }
      Record(out, data, o.BigEndian);
    };
    // Which types a column's block holds.
    auto covers = [&](const Particles::Column& column, int t) {
      if (column.Label == "ID")
      {
        return true;
      }
      if (column.OnlyType >= 0)
      {
        return t == column.OnlyType;
      }
      return column.GasOnly ? t == 0 : (column.Label != "MASS" || particles.MassTable[t] == 0.0);
    };
    auto written = [&](const Particles::Column& column) {
      return o.Cooling || (column.Label != "NE" && column.Label != "NH");
    };
    if (o.Info) // GADGET-3's INFO: label, type, values per particle, the types present
    {
      Bytes info(o.BigEndian);
      for (const Particles::Column& column : particles.Columns)
      {
        if (!written(column))
        {
          continue;
        }
        std::string label = column.Label, type;
        label.resize(4, ' ');
        if (column.Label == "ID")
        {
          type = particles.Ids64 ? "LLONG" : "LONG";
        }
        else
        {
          type =
            std::string(column.Double ? "DOUBLE" : "FLOAT") + (column.Components > 1 ? "N" : "");
        }
        type.resize(8, ' ');
        info.Data.insert(info.Data.end(), label.begin(), label.end());
        info.Data.insert(info.Data.end(), type.begin(), type.end());
        info.Put<std::int32_t>(column.Components);
        for (int t = 0; t < 6; ++t)
        {
          info.Put<std::int32_t>(covers(column, t) ? 1 : 0);
        }
      }
      Label(out, "INFO", info.Data.size(), o.BigEndian);
      Record(out, info, o.BigEndian);
    }
    for (const Particles::Column& column : particles.Columns)
    {
      if (column.Label == "ID")
      {
        block(
          "ID", [](int) { return true; },
          [&](Bytes& data, int t, int g) {
            if (particles.Ids64)
            {
              data.Put<std::uint64_t>(particles.Id(t, g));
            }
            else
            {
              data.Put<std::uint32_t>(static_cast<std::uint32_t>(particles.Id(t, g)));
            }
          });
        continue;
      }
      if (!written(column))
      {
        continue;
      }
      block(
        column.Label, [&](int t) { return covers(column, t); },
        [&](Bytes& data, int t, int g) {
          for (int c = 0; c < column.Components; ++c)
          {
            data.PutReal(column.Value(t, g, c), column.Double);
          }
        });
    }
  }
}

} // namespace test
} // namespace lsi

#endif
