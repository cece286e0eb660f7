// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
// A ChaNGa, Gasoline or PKDGRAV run's parameter file (NAME.param: "key = value" lines, # comments)
// beside its Tipsy snapshots: the one thing a Tipsy file does not say that the SPH field needs,
// whether the box is periodic and its size. As those codes read it: bPeriodic (default 0);
// dPeriod (default 1) sets dxPeriod, dyPeriod and dzPeriod where they are not given (each
// default 1); a period of 0 turns the box off along that axis. The box is [-L/2, L/2) per axis.
#ifndef TipsyRunParameters_h
#define TipsyRunParameters_h

#include <map>
#include <string>

namespace lsi
{
namespace io
{
/// The "key = value" lines of a parameter file (values without comments, quotes or blanks).
std::map<std::string, std::string> ReadParameterFile(const std::string& path);

struct TipsyRunParameters
{
  std::string File; // the parameter file read (empty: none found)
  bool Periodic = false;
  double Period[3] = { 1.0, 1.0, 1.0 }; // where Periodic; 0 on an axis: not periodic along it
};

/**
 * The parameter file of the run that wrote `snapshot`, looked for in the snapshot's directory,
 * then in its parent: one whose achOutName is the snapshot's name less a numbered suffix
 * (run.000512 for achOutName = run) or whose achInFile is the snapshot; else the only .param
 * file in the snapshot's own directory. None found: File empty, not periodic.
 */
TipsyRunParameters FindTipsyRunParameters(const std::string& snapshot);
} // namespace io
} // namespace lsi

#endif
