// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkHDF5SnapshotReader
 * @brief   Reads GADGET, GIZMO, AREPO and SWIFT HDF5 particle snapshots.
 *
 * These codes write one group per particle type, PartType0 (gas) to PartType5 (and more in
 * SWIFT), beside a Header group of attributes (NumPart_ThisFile, NumPart_Total, MassTable,
 * Time, Redshift, BoxSize, NumFilesPerSnapshot, ...). Through the HDF5 library, this reader
 * gives:
 * - every dataset of a selected type as a point array (N x k datasets as k components),
 *   Coordinates as the points, and ParticleIDs as the global ids;
 * - "Masses" from the Header's MassTable when a type has no Masses dataset;
 * - the density ("Density" in GADGET, "Densities" in SWIFT) as the active scalars, and field
 *   data "DensityArray" and "SmoothingLengthArray" naming the density and smoothing-length
 *   arrays ("SmoothingLength" / "SmoothingLengths"), so that filters find them unnamed;
 * - every attribute of Header, and of SWIFT's HydroScheme (Kernel function, Kernel gamma, ...)
 *   and Units groups, as field data (named "Units/...", "HydroScheme/..." for the latter two);
 *   Time as the output's time;
 * - a snapshot split over files name.0.hdf5, name.1.hdf5, ... (NumFilesPerSnapshot > 1) read
 *   as one from any of its files;
 * - under MPI, each rank its own contiguous share of every selected type, read as hyperslabs;
 * - with a region (ReadRegion), from a SWIFT snapshot only its cells that overlap the region
 *   (its Cells group: counts, offsets and each cell's extent).
 * Particle types: see vtkParticleSnapshotReader (gas on by default). Problems (a file that is
 * not HDF5 or not a snapshot, a missing part, datasets of inconsistent lengths) give an error
 * naming the file and an empty output.
 */
#ifndef vtkHDF5SnapshotReader_h
#define vtkHDF5SnapshotReader_h

#include "LevelSetIsosurfaceIOModule.h" // for export macro
#include "vtkParticleSnapshotReader.h"

#include <array>  // for std::array
#include <set>    // for std::set
#include <string> // for std::string
#include <vector> // for std::vector

class LEVELSETISOSURFACEIO_EXPORT vtkHDF5SnapshotReader : public vtkParticleSnapshotReader
{
public:
  static vtkHDF5SnapshotReader* New();
  vtkTypeMacro(vtkHDF5SnapshotReader, vtkParticleSnapshotReader);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /** Whether the file is HDF5 with a Header group and at least one PartType group. */
  static bool CanReadFile(const char* name);

  /** The name of particle type `number` (PartType<number>) in the selection. */
  static std::string ParticleTypeName(int number);

protected:
  vtkHDF5SnapshotReader();
  ~vtkHDF5SnapshotReader() override;

  bool ReadMetaData(std::vector<ParticleType>& types, double& time, vtkFieldData* fields,
    std::string& problem) override;
  bool ReadParticles(std::size_t type, long long begin, long long end, vtkPolyData* output,
    std::string& problem) override;
  // A SWIFT snapshot's cell table gives the parts of the file a region needs.
  bool RegionCandidates(std::size_t type, const double bounds[6],
    std::vector<std::pair<long long, long long>>& ranges, std::string& problem) override;

private:
  vtkHDF5SnapshotReader(const vtkHDF5SnapshotReader&) = delete;
  void operator=(const vtkHDF5SnapshotReader&) = delete;

  std::vector<std::string> Parts;                 // the files of the snapshot
  std::vector<int> TypeNumbers;                   // PartType number of each listed type
  std::vector<std::vector<long long>> PartCounts; // [part][listed type]: particles in that file
  std::vector<double> MassTable;                  // per PartType number
  // The MassTable's mass of PartType `number`, 0 where the table has none.
  double TableMass(int number) const
  {
    return number >= 0 && number < static_cast<int>(this->MassTable.size())
      ? this->MassTable[number]
      : 0.0;
  }
  // The SPH kernel and its support per smoothing length (SWIFT's HydroScheme "Kernel function"
  // and "Kernel gamma"; GADGET-4's Config WENDLAND_C2/C4/C6_KERNEL; else GADGET's cubic spline,
  // h = H).
  std::string Kernel = "CubicSpline";
  double SupportPerSmoothingLength = 1.0;
};

#endif
