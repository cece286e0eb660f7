// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkTipsyParticleReader
 * @brief   Reads the gas, dark-matter and star particles of a Tipsy "standard" binary file.
 *
 * Tipsy standard files (used by ChaNGa, Gasoline, PKDGRAV) hold a 32-byte header (double time;
 * int32 nbodies, ndim, nsph, ndark, nstar; 4 bytes padding; files from older tools and 32-bit
 * machines lack the padding, a 28-byte header the file's size tells), then nsph gas particles of 12
 * float32 each (mass, x, y, z, vx, vy, vz, rho, temp, hsmooth, metals, phi), ndark dark-matter
 * particles of 9 (mass, x, y, z, vx, vy, vz, eps, phi) and nstar star particles of 11 (mass, x,
 * y, z, vx, vy, vz, metals, tform, eps, phi). The standard byte order is big-endian (XDR);
 * little-endian files are recognised from their header. Positions, or positions and
 * velocities, may be doubles (ChaNGa's bDoublePos and bDoubleVel, Gasoline's and tipsy's
 * DOUBLE_POS and DOUBLE_POS_VEL): the file does not say, its size does (exactly the header and
 * records of one layout); they are read as doubles then, and field data TipsyDoublePositions and
 * TipsyDoubleVelocities (0 or 1) say which layout was read. Each type's columns become point
 * arrays (velocity as a vector), gas's rho the active scalars. The auxiliary arrays beside the
 * file (ChaNGa's and Gasoline's SNAPSHOT.NAME files: iord, HI, OxMassFrac, acc2, ...; text or
 * binary, one value a particle or three, see TipsyAuxiliaryArrays.h) become point arrays NAME of
 * every type, except where NAME is a column of the main file (iord, the particle orders, is the
 * global ids). The gas's SPH field is marked with rho, mass and the smoothing lengths of the
 * auxiliary array smoothlength (or SPHH, SphH, hsmall; h = fBall / 2, support 2 h), never with
 * hsmooth, where Gasoline, ChaNGa and PKDGRAV write the gravitational softening. The periodic box,
 * which a Tipsy file does not hold, comes from the run's parameter file (TipsyRunParameters.h) as
 * field data BoxSize (and TipsyParameterFile, the file read). Particle types ("Gas", "DarkMatter",
 * "Stars"), pieces and output: see vtkParticleSnapshotReader.
 */
#ifndef vtkTipsyParticleReader_h
#define vtkTipsyParticleReader_h

#include "LevelSetIsosurfaceIOModule.h" // for export macro
#include "TipsyAuxiliaryArrays.h"       // for lsi::io::TipsyAuxiliaryArray
#include "vtkParticleSnapshotReader.h"

#include <string> // for std::string
#include <vector> // for std::vector

class LEVELSETISOSURFACEIO_EXPORT vtkTipsyParticleReader : public vtkParticleSnapshotReader
{
public:
  static vtkTipsyParticleReader* New();
  vtkTypeMacro(vtkTipsyParticleReader, vtkParticleSnapshotReader);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /** Whether the file looks like a Tipsy standard file (a consistent header and size). */
  static bool CanReadFile(const char* name);

protected:
  vtkTipsyParticleReader();
  ~vtkTipsyParticleReader() override = default;

  bool ReadMetaData(std::vector<ParticleType>& types, double& time, vtkFieldData* fields,
    std::string& problem) override;
  bool ReadParticles(std::size_t type, long long begin, long long end, vtkPolyData* output,
    std::string& problem) override;

private:
  vtkTipsyParticleReader(const vtkTipsyParticleReader&) = delete;
  void operator=(const vtkTipsyParticleReader&) = delete;

  bool BigEndian = true;
  int PositionBytes = 4, VelocityBytes = 4; // 8 in double-precision files (from the size)
  std::vector<int> TypeKinds;               // 0 gas, 1 dark, 2 star, per listed type
  std::vector<long long> TypeOffsets;       // byte offset of each listed type's first record
  std::vector<long long> TypeFirsts;        // index of each listed type's first particle
  std::vector<lsi::io::TipsyAuxiliaryArray> AuxiliaryArrays; // SNAPSHOT.NAME files beside it
  lsi::io::TipsyAuxiliaryCache AuxiliaryCache;               // what was found of each file
};

#endif
