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
#include <cerrno>
#include <cstdint>
#include <cstdlib>
#include <fstream>

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
// many values (whitespace-separated). `integers`: no value has a fraction, an exponent, an
// infinity or a NaN.
bool IsTextArray(std::ifstream& file, long long particles, bool& integers)
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
  return values == particles;
}

// A binary array: a 32-bit count equal to the particle count (either byte order), then exactly
// that many 4- or 8-byte values.
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
    for (int bytes : { 4, 8 })
    {
      if (size == 4 + static_cast<std::uint64_t>(bytes) * static_cast<std::uint64_t>(particles))
      {
        array.BigEndian = big;
        array.ValueBytes = bytes;
        array.Integers = bytes == 4 && NamesIntegers(array.Name);
        return true;
      }
    }
  }
  return false;
}

template <typename ArrayType>
vtkSmartPointer<vtkDataArray> NewArray(const std::string& name, long long count)
{
  auto array = vtkSmartPointer<ArrayType>::New();
  array->SetName(name.c_str());
  array->SetNumberOfValues(static_cast<vtkIdType>(count));
  return array;
}

vtkSmartPointer<vtkDataArray> ReadText(
  const TipsyAuxiliaryArray& aux, long long begin, long long end, std::string& problem)
{
  std::ifstream file(aux.Path);
  std::string token;
  std::getline(file, token); // the particle count
  for (long long i = 0; i < begin && file >> token; ++i)
  {
  }
  auto array = aux.Integers ? NewArray<vtkTypeInt64Array>(aux.Name, end - begin)
                            : NewArray<vtkDoubleArray>(aux.Name, end - begin);
  for (long long i = begin; i < end; ++i)
  {
    char* stop = nullptr;
    errno = 0;
    if (!(file >> token))
    {
      problem = "auxiliary array " + aux.Path + " ends before particle " + std::to_string(i);
      return nullptr;
    }
    const vtkIdType at = static_cast<vtkIdType>(i - begin);
    if (aux.Integers)
    {
      static_cast<vtkTypeInt64Array*>(array.Get())
        ->SetValue(at, std::strtoll(token.c_str(), &stop, 10));
    }
    else
    {
      static_cast<vtkDoubleArray*>(array.Get())->SetValue(at, std::strtod(token.c_str(), &stop));
    }
    if (stop == token.c_str() || *stop != '\0' || errno == ERANGE)
    {
      problem = "auxiliary array " + aux.Path + ": \"" + token + "\" is not a number";
      return nullptr;
    }
  }
  return array;
}

vtkSmartPointer<vtkDataArray> ReadBinary(
  const TipsyAuxiliaryArray& aux, long long begin, long long end, std::string& problem)
{
  std::ifstream file(aux.Path, std::ios::binary);
  std::vector<char> bytes(static_cast<std::size_t>(end - begin) * aux.ValueBytes);
  file.seekg(4 + begin * aux.ValueBytes);
  if (!file || !file.read(bytes.data(), static_cast<std::streamsize>(bytes.size())))
  {
    problem = "could not read auxiliary array " + aux.Path + " (changed since it was found?)";
    return nullptr;
  }
  const vtkIdType n = static_cast<vtkIdType>(end - begin);
  vtkSmartPointer<vtkDataArray> array;
  if (aux.ValueBytes == 8)
  {
    array = NewArray<vtkDoubleArray>(aux.Name, n);
    for (vtkIdType i = 0; i < n; ++i)
    {
      static_cast<vtkDoubleArray*>(array.Get())
        ->SetValue(i, FromBytes<double>(&bytes[8 * static_cast<std::size_t>(i)], aux.BigEndian));
    }
  }
  else if (aux.Integers)
  {
    array = NewArray<vtkTypeInt32Array>(aux.Name, n);
    for (vtkIdType i = 0; i < n; ++i)
    {
      static_cast<vtkTypeInt32Array*>(array.Get())
        ->SetValue(
          i, FromBytes<std::int32_t>(&bytes[4 * static_cast<std::size_t>(i)], aux.BigEndian));
    }
  }
  else
  {
    array = NewArray<vtkFloatArray>(aux.Name, n);
    for (vtkIdType i = 0; i < n; ++i)
    {
      static_cast<vtkFloatArray*>(array.Get())
        ->SetValue(i, FromBytes<float>(&bytes[4 * static_cast<std::size_t>(i)], aux.BigEndian));
    }
  }
  return array;
}
} // namespace

std::vector<TipsyAuxiliaryArray> FindTipsyAuxiliaryArrays(
  const std::string& snapshot, long long particles)
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
    array.Name = name.substr(std::min(prefix.size(), name.size()));
    array.Path = directory.empty() ? name : directory + "/" + name;
    if (name.size() <= prefix.size() || name.compare(0, prefix.size(), prefix) != 0 ||
      vtksys::SystemTools::GetFilenameLastExtension(name) == ".gz" ||
      vtksys::SystemTools::FileIsDirectory(array.Path))
    {
      continue;
    }
    std::ifstream file(array.Path, std::ios::binary);
    file.seekg(0, std::ios::end);
    const std::uint64_t size =
      static_cast<std::uint64_t>(std::max<std::streamoff>(0, file.tellg()));
    file.seekg(0);
    if (!file)
    {
      continue;
    }
    if (IsBinaryArray(file, particles, size, array))
    {
      found.push_back(array);
      continue;
    }
    file.clear();
    file.seekg(0);
    if (IsTextArray(file, particles, array.Integers))
    {
      array.Text = true;
      found.push_back(array);
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
