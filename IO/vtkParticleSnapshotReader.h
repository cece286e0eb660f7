// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkParticleSnapshotReader
 * @brief   Base of the particle snapshot readers: particle types, pieces, output assembly.
 *
 * A simulation snapshot holds particles of several types (gas, dark matter, stars, ...). A
 * subclass lists the types a file holds and reads a range of one type's particles; this class
 * does the rest, the same way for every format:
 * - the particle type selection (ParticleTypeSelection; gas on, the others off by default);
 * - the point array selection (PointArraySelection; all on by default): a snapshot of a large
 *   run holds tens of arrays per particle, and a surface needs three (density, smoothing length,
 *   mass), so the others can be left unread. The positions are always read;
 * - the output: vtkPolyData (one vertex cell per particle) when one type is selected, a
 *   vtkMultiBlockDataSet with one named block per selected type otherwise;
 * - a region (ReadRegion, RegionBounds): only the particles inside a box are kept, read a chunk
 *   at a time so that the read's memory stays bounded; a format that knows where its particles
 *   lie (SWIFT's cell table) reads only the parts of the file that may hold them; in a periodic
 *   box the region wraps across its faces (PeriodicRegion);
 * - pieces: under MPI each rank reads its own contiguous share of every selected type (with a
 *   region, of the particles that may lie inside it);
 * - the snapshot's time (DATA_TIME_STEP, and one TIME_STEPS entry), errors naming the file, an
 *   empty output on any problem.
 */
#ifndef vtkParticleSnapshotReader_h
#define vtkParticleSnapshotReader_h

#include "LevelSetIsosurfaceIOModule.h" // for export macro
#include "vtkDataObjectAlgorithm.h"
#include "vtkNew.h" // for vtkNew

#include <set>     // for std::set
#include <string>  // for std::string
#include <utility> // for std::pair
#include <vector>  // for std::vector

class vtkCellArray;
class vtkDataArraySelection;
class vtkFieldData;
class vtkPointData;
class vtkPolyData;

class LEVELSETISOSURFACEIO_EXPORT vtkParticleSnapshotReader : public vtkDataObjectAlgorithm
{
public:
  vtkTypeMacro(vtkParticleSnapshotReader, vtkDataObjectAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /** The snapshot file (for a snapshot in several files, any one of them). */
  void SetFileName(const char* name);
  const char* GetFileName() const { return this->FileName.c_str(); }
  ///@}

  ///@{
  /**
   * Which particle types to read, by name (for example "Gas (PartType0)"). The names are known
   * after UpdateInformation(). Gas is selected by default, the other types are not.
   */
  vtkDataArraySelection* GetParticleTypeSelection() { return this->ParticleTypeSelection; }
  int GetNumberOfParticleTypeArrays();
  const char* GetParticleTypeArrayName(int index);
  int GetParticleTypeArrayStatus(const char* name);
  void SetParticleTypeStatus(const char* name, int status);
  ///@}

  ///@{
  /**
   * Which point arrays to read, by name (for example "Density", "Velocities"; the ids' array,
   * "ParticleIDs", gives the global ids). The names, of every type the file holds, are known
   * after UpdateInformation(); all are selected by default. An array left unread takes no
   * memory, and a format that stores arrays apart (HDF5, GADGET) does not read it. The SPH field
   * needs the density, smoothing-length and mass arrays: without them vtkLevelSetIsosurface
   * falls back to the MLS fit (and says so).
   */
  vtkDataArraySelection* GetPointArraySelection() { return this->PointArraySelection; }
  int GetNumberOfPointArrays();
  const char* GetPointArrayName(int index);
  int GetPointArrayStatus(const char* name);
  void SetPointArrayStatus(const char* name, int status);
  ///@}

  ///@{
  /**
   * Whether to keep only the particles inside RegionBounds (off by default): the surface of one
   * halo or star in a large run's snapshot without holding the whole box in memory. Give the
   * region a margin of a few smoothing lengths around what you want to see: the field near
   * its faces misses the particles beyond them.
   */
  vtkSetMacro(ReadRegion, vtkTypeBool);
  vtkGetMacro(ReadRegion, vtkTypeBool);
  vtkBooleanMacro(ReadRegion, vtkTypeBool);
  ///@}

  ///@{
  /**
   * The region's box (xmin, xmax, ymin, ymax, zmin, zmax) in the snapshot's own coordinates
   * and units; a particle on a face is inside. Used when ReadRegion is on.
   */
  vtkSetVector6Macro(RegionBounds, double);
  vtkGetVector6Macro(RegionBounds, double);
  ///@}

  ///@{
  /**
   * Whether a region wraps across the faces of the snapshot's periodic box (on by default): with
   * a box known (the Header's BoxSize, positive: GADGET, GIZMO, AREPO and SWIFT snapshots of
   * cosmological and turbulence runs), RegionBounds may reach past its faces, and a particle is
   * inside when one of its periodic images (its position plus or minus whole boxes) is. A halo
   * cut by a face of the box is then read whole; its particles keep their positions in the box,
   * and vtkLevelSetIsosurface (Periodic on) joins them across the face. Turn off for a run whose
   * BoxSize is not periodic. No effect without a box (a Tipsy file without its run's parameter
   * file). A region's output carries
   * field data "RegionBounds" and "RegionPeriod" (the period of each axis it wrapped across, 0
   * for none).
   */
  vtkSetMacro(PeriodicRegion, vtkTypeBool);
  vtkGetMacro(PeriodicRegion, vtkTypeBool);
  vtkBooleanMacro(PeriodicRegion, vtkTypeBool);
  ///@}

  ///@{
  /**
   * How many particles a region's read takes at a time (default 4,194,304): its memory beyond
   * the particles kept.
   */
  vtkSetClampMacro(RegionChunkParticles, vtkIdType, 1, VTK_ID_MAX);
  vtkGetMacro(RegionChunkParticles, vtkIdType);
  ///@}

  /**
   * How many particles the last update read from the file, over the selected types: this
   * rank's share of every particle without a region; with one, before the test of the box,
   * those the format could not rule out (all of them, or a SWIFT snapshot's particles of the
   * cells that overlap the region).
   */
  vtkGetMacro(ParticlesScanned, long long);

  /**
   * The name of GADGET's particle type `number` (PartType<number>) in the selection, as the
   * GADGET-family readers give it: "Gas (PartType0)", "DarkMatter (PartType1)", "PartType2", ...
   */
  static std::string PartTypeName(int number);

  /**
   * Adds "Masses", `count` equal values `mass`: a type whose masses the header's mass table
   * gives (GADGET, GIZMO, AREPO) instead of a per-particle array.
   */
  static void AddTableMasses(vtkPointData* pointData, vtkIdType count, double mass);

  /** One vertex cell per point 0 .. count-1. */
  static vtkNew<vtkCellArray> VertexCells(vtkIdType count);

protected:
  vtkParticleSnapshotReader();
  ~vtkParticleSnapshotReader() override;

  /**
   * A particle type of the file: its name in the selection, how many particles it has, and the
   * names of its point arrays (the positions not among them) as ReadParticles names them.
   */
  struct ParticleType
  {
    std::string Name;
    long long Count = 0;
    bool SelectedByDefault = false;
    std::vector<std::string> Arrays;
  };

  /**
   * Reads what the file holds: its particle types, its time and its field data (header
   * attributes, units). Returns false with `problem` set (in words, without the file name) when
   * the file cannot be read.
   */
  virtual bool ReadMetaData(
    std::vector<ParticleType>& types, double& time, vtkFieldData* fields, std::string& problem) = 0;

  /**
   * Reads particles [begin, end) of type `type` (an index into ReadMetaData's list) into
   * `output`: points and the point arrays for which ReadsArray holds (no cells). Returns false
   * with `problem` set.
   */
  virtual bool ReadParticles(std::size_t type, long long begin, long long end, vtkPolyData* output,
    std::string& problem) = 0;

  /**
   * The ranges [begin, end) of particles of type `type` that may lie inside `bounds` (xmin,
   * xmax, ...), in any order: the whole type, unless the format knows where its particles lie
   * (SWIFT's cell table). Returns false with `problem` set.
   */
  virtual bool RegionCandidates(std::size_t type, const double bounds[6],
    std::vector<std::pair<long long, long long>>& ranges, std::string& problem);

  /**
   * Whether the point array `name` is to be read: selected, or not listed by ReadMetaData.
   */
  bool ReadsArray(const std::string& name);

  /**
   * A warning about the file (its name first), given once per file and message: the metadata
   * is read again for each update.
   */
  void WarnOnce(const std::string& message);

  /**
   * The files of a snapshot split over `parts` files, from the name of any one of them:
   * NAME.K or NAME.K.EXT gives NAME.0[.EXT], NAME.1[.EXT], ...; empty if the name has no such
   * number.
   */
  static std::vector<std::string> PartFileNames(const std::string& file, long long parts);

  /**
   * The GADGET family's types (GADGET, GIZMO, AREPO, SWIFT): those of `totals` (particles of each
   * type number over the snapshot) that hold particles, named by PartTypeName, with the point
   * arrays `arrays` gives for their number, gas selected by default or else the first type
   * listed. `numbers` receives each listed type's number. False with `problem` set when no type
   * holds particles.
   */
  static bool ListPartTypes(const std::vector<long long>& totals,
    const std::vector<std::vector<std::string>>& arrays, std::vector<ParticleType>& types,
    std::vector<int>& numbers, std::string& problem);

  /**
   * What a snapshot says about its SPH field: the names of its density, smoothing-length and mass
   * arrays (empty: none), its kernel ("CubicSpline", "QuinticSpline" or "WendlandC2") and the
   * kernel's support radius per smoothing length (GADGET: 1, SWIFT: its Kernel gamma, Tipsy: 2).
   */
  struct SPHMarkers
  {
    std::string Density, SmoothingLength, Mass;
    std::string Kernel = "CubicSpline";
    double SupportPerSmoothingLength = 1.0;
  };

  /**
   * Marks the SPH arrays of `particles`: the density becomes the active scalars, and field data
   * "DensityArray", "SmoothingLengthArray", "MassArray", "SPHKernel" and
   * "SupportPerSmoothingLength" say what they are, so that filters (vtkLevelSetIsosurface's SPH
   * field) find them without the user naming them. Only arrays `particles` has are marked (an
   * array may be left unread), and the kernel only with a smoothing length.
   */
  static void MarkSPHArrays(vtkPolyData* particles, const SPHMarkers& markers);

  int FillOutputPortInformation(int port, vtkInformation* info) override;
  int RequestDataObject(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  std::string FileName;
  std::set<std::string> Warned; // file and message of each warning given (WarnOnce)

private:
  vtkParticleSnapshotReader(const vtkParticleSnapshotReader&) = delete;
  void operator=(const vtkParticleSnapshotReader&) = delete;

  // Reads the meta data (again if `force` or for a new file name); false on a problem, which
  // MetaDataProblem describes.
  bool UpdateMetaData(bool force);
  // The indices of the selected types that the file has.
  std::vector<std::size_t> SelectedTypes();
  // Reads this piece's particles of the selected type `type` into `particles` (all of its share,
  // or those inside the region); false with `problem` set.
  bool ReadShare(
    std::size_t type, int piece, int pieces, vtkPolyData* particles, std::string& problem);
  bool ReadShareInRegion(
    std::size_t type, int piece, int pieces, vtkPolyData* particles, std::string& problem);
  // "(xmin, xmax, ymin, ymax, zmin, zmax)" for messages.
  std::string RegionBoundsText() const;
  // The period of each axis a region wraps across (PeriodicRegion and the Header's BoxSize,
  // one value or three; 0 where none).
  void RegionPeriod(double period[3]) const;
  // Field data "RegionBounds" (6 values) and "RegionPeriod" (3): the region read, so that a
  // filter can tell the faces beyond which no particle was read (vtkLevelSetIsosurface warns
  // when the surface comes near them).
  void AddRegionFields(vtkFieldData* fields) const;

  vtkNew<vtkDataArraySelection> ParticleTypeSelection;
  vtkNew<vtkDataArraySelection> PointArraySelection;
  std::vector<ParticleType> Types;
  double Time = 0.0;
  vtkNew<vtkFieldData> Fields;
  std::string MetaDataProblem;
  std::string MetaDataFileName;
  bool MetaDataRead = false;
  vtkTypeBool ReadRegion = 0;
  double RegionBounds[6] = { 0.0, 0.0, 0.0, 0.0, 0.0, 0.0 };
  vtkTypeBool PeriodicRegion = 1;
  vtkIdType RegionChunkParticles = 4194304;
  long long ParticlesScanned = 0;
  double ProgressFrom = 0.0, ProgressTo = 1.0; // the progress of the type being read
};

#endif
