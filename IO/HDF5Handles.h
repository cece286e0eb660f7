// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
// Small helpers over the HDF5 C library shared by the HDF5 snapshot reader's files: quiet
// probing, identifiers closed at the end of their scope, links and numeric attributes.
#ifndef HDF5Handles_h
#define HDF5Handles_h

#include "vtk_hdf5.h"

#include <string>
#include <vector>

namespace lsi
{
namespace io
{
// HDF5 prints its own error stack on every failed call; a reader that probes files must not.
// This turns the printing off for its lifetime and restores it afterwards.
class QuietHDF5
{
public:
  QuietHDF5()
  {
    H5Eget_auto2(H5E_DEFAULT, &this->Function, &this->Data);
    H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  }
  ~QuietHDF5() { H5Eset_auto2(H5E_DEFAULT, this->Function, this->Data); }

private:
  H5E_auto2_t Function = nullptr;
  void* Data = nullptr;
};

// An HDF5 identifier closed by the given function when it goes out of scope.
class Handle
{
public:
  Handle(hid_t id, herr_t (*close)(hid_t))
    : Id(id)
    , Close(close)
  {
  }
  ~Handle()
  {
    if (this->Id >= 0)
    {
      this->Close(this->Id);
    }
  }
  Handle(const Handle&) = delete;
  Handle& operator=(const Handle&) = delete;
  bool Valid() const { return this->Id >= 0; }
  operator hid_t() const { return this->Id; }

private:
  hid_t Id;
  herr_t (*Close)(hid_t);
};

inline bool Exists(hid_t location, const std::string& name)
{
  return H5Lexists(location, name.c_str(), H5P_DEFAULT) > 0;
}

// A numeric attribute as doubles (empty if absent or not numeric).
inline std::vector<double> NumericAttribute(hid_t object, const char* name)
{
  std::vector<double> values;
  if (H5Aexists(object, name) <= 0)
  {
    return values;
  }
  Handle attribute(H5Aopen(object, name, H5P_DEFAULT), H5Aclose);
  Handle type(H5Aget_type(attribute), H5Tclose);
  const H5T_class_t kind = H5Tget_class(type);
  if (kind != H5T_INTEGER && kind != H5T_FLOAT)
  {
    return values;
  }
  Handle space(H5Aget_space(attribute), H5Sclose);
  const hssize_t count = H5Sget_simple_extent_npoints(space);
  values.resize(count > 0 ? static_cast<std::size_t>(count) : 0);
  if (values.empty() || H5Aread(attribute, H5T_NATIVE_DOUBLE, values.data()) < 0)
  {
    values.clear();
  }
  return values;
}
} // namespace io
} // namespace lsi

#endif
