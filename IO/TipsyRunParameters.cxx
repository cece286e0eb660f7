// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "TipsyRunParameters.h"

#include <vtksys/Directory.hxx>
#include <vtksys/SystemTools.hxx>

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <fstream>
#include <vector>

namespace lsi
{
namespace io
{
namespace
{
std::string Trimmed(const std::string& text)
{
  const auto first = text.find_first_not_of(" \t\r\"'");
  if (first == std::string::npos)
  {
    return std::string();
  }
  const auto last = text.find_last_not_of(" \t\r\"'");
  return text.substr(first, last - first + 1);
}

// Whether `name` is `prefix`, a dot and digits (ChaNGa's run.000512, Gasoline's run.00512).
bool IsNumberedOutput(const std::string& name, const std::string& prefix)
{
  if (prefix.empty() || name.size() <= prefix.size() + 1 ||
    name.compare(0, prefix.size(), prefix) != 0 || name[prefix.size()] != '.')
  {
    return false;
  }
  return std::all_of(name.begin() + static_cast<long>(prefix.size()) + 1, name.end(),
    [](unsigned char c) { return std::isdigit(c) != 0; });
}

std::vector<std::string> ParameterFilesIn(const std::string& directory)
{
  std::vector<std::string> files;
  vtksys::Directory listing;
  if (!listing.Load(directory.empty() ? "." : directory))
  {
    return files;
  }
  for (unsigned long f = 0; f < listing.GetNumberOfFiles(); ++f)
  {
    const std::string name = listing.GetFile(f);
    const std::string path = directory.empty() ? name : directory + "/" + name;
    if (name.size() > 6 && name.compare(name.size() - 6, 6, ".param") == 0 &&
      !vtksys::SystemTools::FileIsDirectory(path))
    {
      files.push_back(path);
    }
  }
  std::sort(files.begin(), files.end());
  return files;
}

double NumberOr(const std::map<std::string, std::string>& values, const char* key, double fallback)
{
  const auto found = values.find(key);
  if (found == values.end())
  {
    return fallback;
  }
  char* end = nullptr;
  const double value = std::strtod(found->second.c_str(), &end);
  return end != found->second.c_str() ? value : fallback;
}
} // namespace

std::map<std::string, std::string> ReadParameterFile(const std::string& path)
{
  std::map<std::string, std::string> values;
  std::ifstream file(path);
  std::string line;
  while (std::getline(file, line))
  {
    line = line.substr(0, line.find('#'));
    const auto equals = line.find('=');
    if (equals != std::string::npos)
    {
      const std::string key = Trimmed(line.substr(0, equals));
      if (!key.empty())
      {
        values[key] = Trimmed(line.substr(equals + 1));
      }
    }
  }
  return values;
}

TipsyRunParameters FindTipsyRunParameters(const std::string& snapshot)
{
  TipsyRunParameters run;
  const std::string directory = vtksys::SystemTools::GetFilenamePath(snapshot);
  const std::string name = vtksys::SystemTools::GetFilenameName(snapshot);
  const std::string parent = directory.empty() ? ".." : directory + "/..";
  std::string chosen;
  std::map<std::string, std::string> values;
  for (const std::string& where : { directory, parent })
  {
    for (const std::string& path : ParameterFilesIn(where))
    {
      std::map<std::string, std::string> candidate = ReadParameterFile(path);
      const std::string out =
        vtksys::SystemTools::GetFilenameName(Trimmed(candidate["achOutName"]));
      const std::string in = vtksys::SystemTools::GetFilenameName(Trimmed(candidate["achInFile"]));
      if (IsNumberedOutput(name, out) || (!in.empty() && in == name))
      {
        chosen = path;
        values.swap(candidate);
        break;
      }
    }
    if (!chosen.empty())
    {
      break;
    }
  }
  if (chosen.empty())
  {
    const std::vector<std::string> here = ParameterFilesIn(directory);
    if (here.size() != 1)
    {
      return run;
    }
    chosen = here[0];
    values = ReadParameterFile(chosen);
  }
  run.File = chosen;
  run.Periodic = NumberOr(values, "bPeriodic", 0.0) != 0.0;
  const bool periodGiven = values.count("dPeriod") > 0;
  const double period = NumberOr(values, "dPeriod", 1.0);
  const char* axes[3] = { "dxPeriod", "dyPeriod", "dzPeriod" };
  for (int a = 0; a < 3; ++a)
  {
    run.Period[a] = NumberOr(values, axes[a], periodGiven ? period : 1.0);
  }
  return run;
}
} // namespace io
} // namespace lsi
