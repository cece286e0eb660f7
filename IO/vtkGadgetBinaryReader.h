// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkGadgetBinaryReader
 * @brief   Reads GADGET-1/2/3/4 binary particle snapshots (SnapFormat 1 and 2).
 *
 * GADGET-2 writes its snapshots and initial conditions in this format by default (GADGET-3,
 * GIZMO and AREPO can too): a 256-byte header (particle counts per type, mass table, time,
 * redshift, box size, cosmology, flags), then blocks of per-particle values. This reader gives:
 * - the blocks as point arrays under the names HDF5 snapshots of the same codes use:
 *   positions the points, "Velocities", "ParticleIDs" as the global ids, "Masses" (from the MASS
 *   block, or the header's mass table where a type has none), and for the gas "InternalEnergy",
 *   "Density" (the active scalars), "ElectronAbundance", "NeutralHydrogenAbundance",
 *   "SmoothingLength", "StarFormationRate", then "StellarFormationTime" and "Metallicity";
 * - format 2 (a label before each block) by its labels and GADGET-3's INFO block where there is
 *   one (each block's value type, values per particle and types), any other block whose size
 *   fits one or three values per particle of every type or of the gas under its label; format 1 by
 *   GADGET-2's order (positions, velocities, ids, masses, internal energy, density, with cooling
 *   electron and neutral-hydrogen abundances, smoothing length, ...), the header's flags saying
 *   which blocks there are, and blocks past those as "Block<N>";
 * - either byte order, single or double precision, 4- or 8-byte ids;
 * - the header as field data with HDF5 snapshots' attribute names (NumPart_ThisFile,
 *   NumPart_Total, MassTable, Time, Redshift, BoxSize, Omega0, OmegaLambda, HubbleParam, Flag_*,
 *   NumFilesPerSnapshot), Time as the output's time, and the SPH markers (GADGET's cubic spline,
 *   its smoothing length the kernel's support radius) so that filters find the SPH field;
 * - a snapshot in several files NAME.0, NAME.1, ... read as one from any of them.
 * GADGET-4's own binary header (192 bytes: 64-bit counts, no flags, no cosmology) is read too,
 * its blocks as GADGET-2's. Particle types, pieces under MPI and output: see
 * vtkParticleSnapshotReader.
 */
#ifndef vtkGadgetBinaryReader_h
#define vtkGadgetBinaryReader_h

#include "LevelSetIsosurfaceIOModule.h" // for export macro
#include "vtkParticleSnapshotReader.h"

#include <memory> // for std::unique_ptr
#include <string> // for std::string
#include <vector> // for std::vector

class LEVELSETISOSURFACEIO_EXPORT vtkGadgetBinaryReader : public vtkParticleSnapshotReader
{
public:
  static vtkGadgetBinaryReader* New();
  vtkTypeMacro(vtkGadgetBinaryReader, vtkParticleSnapshotReader);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /** Whether the file is a GADGET binary snapshot (a consistent header and records). */
  static bool CanReadFile(const char* name);

protected:
  vtkGadgetBinaryReader();
  ~vtkGadgetBinaryReader() override;

  bool ReadMetaData(std::vector<ParticleType>& types, double& time, vtkFieldData* fields,
    std::string& problem) override;
  bool ReadParticles(std::size_t type, long long begin, long long end, vtkPolyData* output,
    std::string& problem) override;

private:
  vtkGadgetBinaryReader(const vtkGadgetBinaryReader&) = delete;
  void operator=(const vtkGadgetBinaryReader&) = delete;

  struct Internals;
  std::unique_ptr<Internals> Internal;
};

#endif
