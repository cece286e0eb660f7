// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkTipsyParticleReader
 * @brief   Reads the gas (SPH) particles of a Tipsy "standard" binary file.
 *
 * Tipsy standard files (used by ChaNGa, Gasoline, PKDGRAV) hold a 32-byte header (double time;
 * int32 nbodies, ndim, nsph, ndark, nstar; 4 bytes padding), then nsph gas particles of 12
 * float32 each (mass, x, y, z, vx, vy, vz, rho, temp, hsmooth, metals, phi), then the dark and
 * star particles. The standard byte order is big-endian (XDR); little-endian files are
 * recognised from their header. The output is the gas particles as vertices with the point
 * arrays mass, velocity, rho, temp, hsmooth, metals and phi, stamped with the file's time.
 * Dark-matter and star particles are skipped: isosurfaces are of the gas.
 */
#ifndef vtkTipsyParticleReader_h
#define vtkTipsyParticleReader_h

#include "LevelSetIsosurfaceIOModule.h" // for export macro
#include "vtkPolyDataAlgorithm.h"

#include <string> // for std::string

class LEVELSETISOSURFACEIO_EXPORT vtkTipsyParticleReader : public vtkPolyDataAlgorithm
{
public:
  static vtkTipsyParticleReader* New();
  vtkTypeMacro(vtkTipsyParticleReader, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /** The Tipsy file to read. */
  void SetFileName(const char* name);
  const char* GetFileName() const { return this->FileName.c_str(); }
  ///@}

  /** Whether the file looks like a Tipsy standard file (a consistent header and size). */
  static bool CanReadFile(const char* name);

protected:
  vtkTipsyParticleReader();
  ~vtkTipsyParticleReader() override = default;

  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  std::string FileName;

private:
  vtkTipsyParticleReader(const vtkTipsyParticleReader&) = delete;
  void operator=(const vtkTipsyParticleReader&) = delete;
};

#endif
