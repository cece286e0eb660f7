// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
// vtkSetClampMacro, but not silent: a value outside [min, max] is clamped with a warning that
// names the property and the value used. NaN is stored as given, so that the filter's parameter
// check reports it as an error.
#ifndef vtkLevelSetMacros_h
#define vtkLevelSetMacros_h

#include "vtkSetGet.h"

#define vtkSetClampWarnMacro(name, type, min, max)                                                 \
  vtkSetClampWarnThenMacro(name, type, min, max, Modified)

// The same, calling `touch` (a member function) instead of Modified when the value changes.
#define vtkSetClampWarnThenMacro(name, type, min, max, touch)                                      \
  virtual void Set##name(type value)                                                               \
  {                                                                                                \
    const type clamped = value < (min) ? (min) : (value > (max) ? (max) : value);                  \
    if (clamped != value && value == value)                                                        \
    {                                                                                              \
      vtkWarningMacro(#name " " << value << " is outside [" << (min) << ", " << (max)              \
                                << "]: " << clamped << " is used.");                               \
    }                                                                                              \
    if (!(this->name == clamped))                                                                  \
    {                                                                                              \
      this->name = clamped;                                                                        \
      this->touch();                                                                               \
    }                                                                                              \
  }

#endif
