// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
// ChaNGa's, Gasoline's and PKDGRAV's auxiliary arrays: files beside a Tipsy snapshot named
// SNAPSHOT.NAME (run.00512.iord, run.00512.HI, run.00512.OxMassFrac, run.00512.amiga.grp), each
// one value per particle of the whole snapshot, in the snapshot's order (gas, dark matter,
// stars). Two encodings, as pynbody reads them: text (the particle count on the first line, then
// the values), and binary (a 32-bit particle count, then 32-bit floats or integers, or 64-bit
// floats; either byte order); vectors (three values a particle) as ChaNGa reads them.
#ifndef TipsyAuxiliaryArrays_h
#define TipsyAuxiliaryArrays_h

#include "vtkDataArray.h"
#include "vtkSmartPointer.h"

#include <map>
#include <string>
#include <vector>

namespace lsi
{
namespace io
{
struct TipsyAuxiliaryArray
{
  std::string Name; // what follows "SNAPSHOT." in the file's name
  std::string Path;
  bool Text = false;
  bool BigEndian = true;   // binary files
  int ValueBytes = 4;      // binary files: 4 or 8
  bool Integers = false;   // 32-bit integers (binary), or text without a fraction or an exponent
  int Components = 1;      // 3: a vector (binary: x, y, z per particle; text: all x, all y, all z)
  long long Particles = 0; // in the whole snapshot (the count the file starts with)
};

/// What FindTipsyAuxiliaryArrays found of each file it looked at, by path, with the file's size
/// and modification time and the particle count: the reader reads its metadata again on each
/// update, and a text file is read whole to be recognised.
struct TipsyAuxiliaryCache
{
  struct Stamp
  {
    unsigned long long Size;
    long long Time;
    long long Particles;
    bool operator==(const Stamp& o) const
    {
      return this->Size == o.Size && this->Time == o.Time && this->Particles == o.Particles;
    }
  };
  struct Entry
  {
    Stamp Of;                  // the file as it was looked at
    bool IsArray;              // whether it was an auxiliary array of the snapshot
    TipsyAuxiliaryArray Array; // which, if so
  };
  using Map = std::map<std::string, Entry>;
  Map Files;
};

/**
 * The auxiliary arrays beside `snapshot` that hold exactly `particles` values, one a particle,
 * or three (vectors, as acc2, the layout ChaNGa reads), sorted by name. A binary file holds
 * 32-bit integers where its name says so (iord, igasorder, iordergas, grp and NAME.grp: pynbody's
 * list), else floats. Files of another particle count or of another size are not arrays of this
 * snapshot and are left out; so are compressed ones (.gz). `cache`, if given, keeps what was
 * found of each file, which is not looked at again while unchanged.
 */
std::vector<TipsyAuxiliaryArray> FindTipsyAuxiliaryArrays(
  const std::string& snapshot, long long particles, TipsyAuxiliaryCache* cache = nullptr);

/**
 * Values `begin` to `end` (indices over the whole snapshot) of `array`, 1 or 3 components: 32-bit
 * integers (binary) or 64-bit integers (text), floats (binary 4 bytes) or doubles (binary 8 bytes,
 * text). Null, with `problem` set, when the file cannot be read so far (changed since it was
 * found).
 */
vtkSmartPointer<vtkDataArray> ReadTipsyAuxiliaryArray(
  const TipsyAuxiliaryArray& array, long long begin, long long end, std::string& problem);
} // namespace io
} // namespace lsi

#endif
