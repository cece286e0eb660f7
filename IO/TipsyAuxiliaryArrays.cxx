// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "TipsyAuxiliaryArrays.h"

#include "ByteOrder.h"

#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkTypeInt32Array.h"
#include "vtkTypeInt64Array.h"

#include <vtksys/Directory.hxx>
#include <vtksys/SystemTools.hxx>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <system_error>
#include <vector>

namespace lsi
{
namespace io
{
namespace
{
// pynbody's "binary-int-arrays": the binary arrays written as integers (particle orders and
// halo-finder group numbers); every other binary array holds floats.
bool NamesIntegers(std::string name)
{
  std::transform(name.begin(), name.end(), name.begin(),
    [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  const auto endsWith = [&name](const std::string& end) {
    return name.size() >= end.size() &&
      name.compare(name.size() - end.size(), end.size(), end) == 0;
  };
  return name == "iord" || name == "igasorder" || name == "iordergas" || name == "grp" ||
    endsWith(".grp");
}

// A text array: a first line holding the particle count and nothing else, then exactly that
// many values (whitespace-separated), or three times as many (a vector: ChaNGa writes every
// particle's x, then every y, then every z). `integers`: no value has a fraction, an exponent,
// an infinity or a NaN.
bool IsTextArray(std::ifstream& file, long long particles, bool& integers, int& components)
{
  std::string first;
  if (!std::getline(file, first) || first.size() > 32)
  {
    return false;
  }
  const auto start = first.find_first_not_of(" \t\r");
  const auto stop = first.find_last_not_of(" \t\r");
  if (start == std::string::npos ||
    !std::all_of(first.begin() + static_cast<long>(start),
      first.begin() + static_cast<long>(stop) + 1,
      [](unsigned char c) { return std::isdigit(c) != 0; }) ||
    std::strtoll(first.c_str() + start, nullptr, 10) != particles)
  {
    return false;
  }
  long long values = 0;
  bool inValue = false;
  integers = true;
  std::vector<char> buffer(1 << 20);
  while (file)
  {
    file.read(buffer.data(), static_cast<std::streamsize>(buffer.size()));
    const std::streamsize got = file.gcount();
    for (std::streamsize i = 0; i < got; ++i)
    {
      const unsigned char c = static_cast<unsigned char>(buffer[static_cast<std::size_t>(i)]);
      const bool space = std::isspace(c) != 0;
      if (!space && !inValue)
      {
        ++values;
      }
      inValue = !space;
      if (c == '.' || c == 'e' || c == 'E' || c == 'n' || c == 'N' || c == 'i' || c == 'I')
      {
        integers = false;
      }
      else if (!space && !std::isdigit(c) && c != '-' && c != '+')
      {
        return false; // not numbers
      }
    }
  }
  components = values == 3 * particles ? 3 : 1;
  return values == particles || values == 3 * particles;
}

// A binary array: a 32-bit count equal to the particle count (either byte order), then exactly
// that many 4- or 8-byte values, or three a particle (a vector: x, y, z of each particle in
// turn, as ChaNGa reads them).
bool IsBinaryArray(
  std::ifstream& file, long long particles, std::uint64_t size, TipsyAuxiliaryArray& array)
{
  char header[4];
  if (size < 4 || !file.read(header, 4))
  {
    return false;
  }
  for (bool big : { true, false })
  {
    if (FromBytes<std::int32_t>(header, big) != particles)
    {
      continue;
    }
    for (int components : { 1, 3 })
    {
      for (int bytes : { 4, 8 })
      {
        if (size ==
          4 +
            static_cast<std::uint64_t>(bytes * components) * static_cast<std::uint64_t>(particles))
        {
          array.BigEndian = big;
          array.ValueBytes = bytes;
          array.Components = components;
          array.Integers = bytes == 4 && components == 1 && NamesIntegers(array.Name);
          return true;
        }
      }
    }
  }
  return false;
}

template <typename ArrayType>
vtkSmartPointer<vtkDataArray> NewArray(const std::string& name, long long count, int components)
{
  auto array = vtkSmartPointer<ArrayType>::New();
  array->SetName(name.c_str());
  array->SetNumberOfComponents(components);
  array->SetNumberOfTuples(static_cast<vtkIdType>(count));
  return array;
}

// The whitespace-separated values of a text file, read in large blocks (an istream's >> per
// value costs more than the parse).
class TextTokens
{
public:
  explicit TextTokens(std::istream& file)
    : File(file)
    , Buffer(1 << 20)
  {
  }
  /// The next value's characters [begin, end), valid until the next call; false at the end.
  bool Next(const char*& begin, const char*& end)
  {
    for (;;)
    {
      while (this->Position < this->Filled && IsSpace(this->Buffer[this->Position]))
      {
        ++this->Position;
      }
      std::size_t stop = this->Position;
      while (stop < this->Filled && !IsSpace(this->Buffer[stop]))
      {
        ++stop;
      }
      // (A value that reaches the block's end may go on in the next block.)
      if (stop > this->Position && (stop < this->Filled || this->AtEnd))
      {
        begin = this->Buffer.data() + this->Position;
        end = this->Buffer.data() + stop;
        this->Position = stop;
        return true;
      }
      if (this->AtEnd)
      {
        return false;
      }
      this->Refill();
    }
  }

private:
  // (std::isspace's characters in the C locale, without its call per character.)
  static bool IsSpace(char c)
  {
    return c == ' ' || c == '\n' || c == '\t' || c == '\r' || c == '\v' || c == '\f';
  }
  // Keeps the unread characters, then reads the next block after them.
  void Refill()
  {
    const std::size_t kept = this->Filled - this->Position;
    std::copy(this->Buffer.begin() + static_cast<std::ptrdiff_t>(this->Position),
      this->Buffer.begin() + static_cast<std::ptrdiff_t>(this->Filled), this->Buffer.begin());
    if (kept == this->Buffer.size())
    {
      this->Buffer.resize(2 * this->Buffer.size()); // one value longer than a block
    }
    this->File.read(
      this->Buffer.data() + kept, static_cast<std::streamsize>(this->Buffer.size() - kept));
    this->Filled = kept + static_cast<std::size_t>(this->File.gcount());
    this->Position = 0;
    this->AtEnd = !this->File;
  }
  std::istream& File;
  std::vector<char> Buffer;
  std::size_t Position = 0, Filled = 0;
  bool AtEnd = false;
};

// Sets value `k` (tuple * components + component) of `array` (vtkTypeInt64Array or
// vtkDoubleArray) from the characters [begin, end); false if they are not one number in range.
bool SetFromText(
  vtkDataArray* array, bool integers, vtkIdType k, const char* begin, const char* end)
{
  // (from_chars takes no '+', which strtod and the files allow.)
  const char* first =
    (end - begin > 1 && *begin == '+' && begin[1] != '-' && begin[1] != '+') ? begin + 1 : begin;
  std::from_chars_result parsed;
  if (integers)
  {
    long long value = 0;
    parsed = std::from_chars(first, end, value);
    static_cast<vtkTypeInt64Array*>(array)->SetValue(k, value);
  }
  else
  {
    double value = 0.0;
    parsed = std::from_chars(first, end, value);
    static_cast<vtkDoubleArray*>(array)->SetValue(k, value);
  }
  return parsed.ec == std::errc() && parsed.ptr == end;
}

vtkSmartPointer<vtkDataArray> ReadText(
  const TipsyAuxiliaryArray& aux, long long begin, long long end, std::string& problem)
{
  std::ifstream file(aux.Path, std::ios::binary);
  std::string count;
  std::getline(file, count); // the particle count
  TextTokens tokens(file);
  const int components = aux.Components;
  auto array = aux.Integers ? NewArray<vtkTypeInt64Array>(aux.Name, end - begin, components)
                            : NewArray<vtkDoubleArray>(aux.Name, end - begin, components);
  long long read = 0; // values read after the count
  const char *first = nullptr, *last = nullptr;
  for (int c = 0; c < components; ++c)
  {
    // A vector's components one after the other: every particle's x, then every y, then z.
    for (const long long skipTo = c * aux.Particles + begin;
         read < skipTo && tokens.Next(first, last);)
    {
      ++read;
    }
    for (long long i = begin; i < end; ++i, ++read)
    {
      if (!tokens.Next(first, last))
      {
        problem = "auxiliary array " + aux.Path + " ends before particle " + std::to_string(i);
        return nullptr;
      }
      if (!SetFromText(array, aux.Integers, (i - begin) * components + c, first, last))
      {
        problem =
          "auxiliary array " + aux.Path + ": \"" + std::string(first, last) + "\" is not a number";
        return nullptr;
      }
    }
  }
  return array;
}

vtkSmartPointer<vtkDataArray> ReadBinary(
  const TipsyAuxiliaryArray& aux, long long begin, long long end, std::string& problem)
{
  std::ifstream file(aux.Path, std::ios::binary);
  const long long valueBytes = static_cast<long long>(aux.ValueBytes) * aux.Components;
  std::vector<char> bytes(static_cast<std::size_t>((end - begin) * valueBytes));
  file.seekg(4 + begin * valueBytes);
  if (!file || !file.read(bytes.data(), static_cast<std::streamsize>(bytes.size())))
  {
    problem = "could not read auxiliary array " + aux.Path + " (changed since it was found?)";
    return nullptr;
  }
  const vtkIdType n = static_cast<vtkIdType>(end - begin);
  const vtkIdType values = n * aux.Components;
  vtkSmartPointer<vtkDataArray> array;
  if (aux.ValueBytes == 8)
  {
    array = NewArray<vtkDoubleArray>(aux.Name, n, aux.Components);
    for (vtkIdType k = 0; k < values; ++k)
    {
      static_cast<vtkDoubleArray*>(array.Get())
        ->SetValue(k, FromBytes<double>(&bytes[8 * static_cast<std::size_t>(k)], aux.BigEndian));
    }
  }
  else if (aux.Integers)
  {
    array = NewArray<vtkTypeInt32Array>(aux.Name, n, 1);
    for (vtkIdType k = 0; k < values; ++k)
    {
      static_cast<vtkTypeInt32Array*>(array.Get())
        ->SetValue(
          k, FromBytes<std::int32_t>(&bytes[4 * static_cast<std::size_t>(k)], aux.BigEndian));
    }
  }
  else
  {
    array = NewArray<vtkFloatArray>(aux.Name, n, aux.Components);
    for (vtkIdType k = 0; k < values; ++k)
    {
      static_cast<vtkFloatArray*>(array.Get())
        ->SetValue(k, FromBytes<float>(&bytes[4 * static_cast<std::size_t>(k)], aux.BigEndian));
    }
  }
  return array;
}

// Whether the file at array.Path is an auxiliary array of `particles` particles (and which).
bool IsAuxiliaryArray(long long particles, TipsyAuxiliaryArray& array)
{
  std::ifstream file(array.Path, std::ios::binary);
  file.seekg(0, std::ios::end);
  const std::uint64_t size = static_cast<std::uint64_t>(std::max<std::streamoff>(0, file.tellg()));
  file.seekg(0);
  if (!file)
  {
    return false;
  }
  if (IsBinaryArray(file, particles, size, array))
  {
    return true;
  }
  file.clear();
  file.seekg(0);
  array.Text = IsTextArray(file, particles, array.Integers, array.Components);
  return array.Text;
}
} // namespace

std::vector<TipsyAuxiliaryArray> FindTipsyAuxiliaryArrays(
  const std::string& snapshot, long long particles, TipsyAuxiliaryCache* cache)
{
  std::vector<TipsyAuxiliaryArray> found;
  std::string directory = vtksys::SystemTools::GetFilenamePath(snapshot);
  const std::string prefix = vtksys::SystemTools::GetFilenameName(snapshot) + ".";
  vtksys::Directory listing;
  if (particles <= 0 || !listing.Load(directory.empty() ? "." : directory))
  {
    return found;
  }
  for (unsigned long f = 0; f < listing.GetNumberOfFiles(); ++f)
  {
    const std::string name = listing.GetFile(f);
    TipsyAuxiliaryArray array;
    array.Particles = particles;
    array.Name = name.substr(std::min(prefix.size(), name.size()));
    array.Path = directory.empty() ? name : directory + "/" + name;
    if (name.size() <= prefix.size() || name.compare(0, prefix.size(), prefix) != 0 ||
      vtksys::SystemTools::GetFilenameLastExtension(name) == ".gz" ||
      vtksys::SystemTools::FileIsDirectory(array.Path))
    {
      continue;
    }
    // A file looked at before, unchanged (its size and modification time), for as many
    // particles: what was found then (a text file is read whole to be recognised).
    const TipsyAuxiliaryCache::Stamp stamp = { vtksys::SystemTools::FileLength(array.Path),
      static_cast<long long>(vtksys::SystemTools::ModifiedTime(array.Path)), particles };
    auto known = cache ? cache->Files.find(array.Path) : TipsyAuxiliaryCache::Map::iterator();
    if (cache && known != cache->Files.end() && known->second.Of == stamp)
    {
      if (known->second.IsArray)
      {
        found.push_back(known->second.Array);
      }
      continue;
    }
    const bool isArray = IsAuxiliaryArray(particles, array);
    if (isArray)
    {
      found.push_back(array);
    }
    if (cache)
    {
      cache->Files[array.Path] = { stamp, isArray, array };
    }
  }
  std::sort(found.begin(), found.end(),
    [](const TipsyAuxiliaryArray& a, const TipsyAuxiliaryArray& b) { return a.Name < b.Name; });
  return found;
}

vtkSmartPointer<vtkDataArray> ReadTipsyAuxiliaryArray(
  const TipsyAuxiliaryArray& array, long long begin, long long end, std::string& problem)
{
  return array.Text ? ReadText(array, begin, end, problem) : ReadBinary(array, begin, end, problem);
}
} // namespace io
} // namespace lsi
