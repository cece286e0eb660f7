// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkLevelSetIsosurface
 * @brief   Smooth local isosurface of scattered point data by a variational level-set method.
 *
 * vtkLevelSetIsosurface extracts the components of the isosurface {f = IsoValue} of a point
 * scalar f that meet a region of interest given by seed spheres, directly on the scattered
 * samples of any vtkPointSet (no resampling to a grid). It implements Rosenthal, Molchanov,
 * Linsen et al., "Variational Level-Set Detection of Local Isosurfaces from Unstructured
 * Point-based Volume Data". Its steps, each in a file of its own:
 * 1. neighbourhoods: each sample's n nearest neighbours and MLS stencils
 *    (LevelSetNeighborhoods), kept across re-executions;
 * 2. parameters from the mean sample spacing at the isovalue (LevelSetParameters);
 * 3. the initial level set phi: by default flooded from the seeds through the neighbour graph
 *    over the samples with f > IsoValue, so phi starts at the signed distance to the surface of
 *    the seeded components (LevelSetFlood); or, as in the paper, the signed distance to the seed
 *    spheres (LevelSetSeedSpheres);
 * 4. the evolution of phi by gradient descent of the paper's functional (eq. 9, or eq. 13, or
 *    Rosenthal and Linsen's eq. 16) on the band around its zero level, with MLS estimates of
 *    gradient and divergence (LevelSetEvolution), each step followed by the reinitialisation
 *    of eq. 10 (LevelSetReinitialization);
 * 5. isopoints: zero crossings between neighbours projected by Newton's method onto the zero
 *    level of the MLS approximation (LevelSetIsopoints);
 * 6. completion on tangent planes, so that the set renders without holes (LevelSetCompletion);
 * 7. refinement on the data: each isopoint slides to the zero of f - IsoValue, where f is the
 *    SPH field on particles with smoothing lengths and masses (LevelSetSPHField, see Field), else
 *    an MLS fit of the samples (LevelSetDataRefinement);
 * 8. outputs (LevelSetSurfaceOutput, LevelSetSplatOutput, LevelSetParticleOutput,
 *    LevelSetConvergenceTable).
 *
 * Outputs: port 0, the surface: by default oriented splats (one small polygon per isopoint in
 * its tangent plane, so that the default Surface representation shows a closed shaded surface),
 * or the isopoints themselves (one vertex per point, for the Points or Point Gaussian
 * representation). Both carry unit "Normals" pointing out of the region where f > IsoValue, a
 * "SplatRadius" (the local isopoint spacing, for Point Gaussian's scale array) and, unless
 * InterpolateArrays is off, every point array of the input interpolated by an MLS linear fit
 * (a linear field is reproduced exactly). Port 1, the input samples as vertices with their point
 * data and a "LevelSet" array (the final phi); port 2, a vtkTable with one row per iteration
 * (Iteration, SignMismatch, MaxGradientDeviation, MeanGradientDeviation, BandSize, Seconds);
 * port 3, a vtkTable of what the surface encloses, one row per connected component and a total
 * (particles, mass, volume, surface area, centre of mass, mass-weighted means of every array:
 * LevelSetEnclosed.h says how).
 *
 * The neighbourhoods (and MLS stencils) depend only on the points: they are kept across
 * re-executions for the last NeighborCacheSize point sets (recognised by their coordinates), so
 * on a time series each time step keeps its own, and changing the isovalue or the seed, or
 * returning to a time step, does not search again.
 *
 * Threads: loops run in vtkSMPTools with the STDThread backend on NumberOfThreads threads
 * (0: all cores), whatever the global backend is.
 *
 * MPI (pvbatch, pvserver): with the particles spread over the ranks of Controller (by default
 * the global controller), every rank runs the method on its own particles plus ghost copies of
 * the other ranks' particles within a halo (LevelSetDistribution): the ghosts' level set is
 * refreshed from its owners after every step, the flood crosses ranks, sums and the stopping
 * rule are global, and each isopoint is made by the rank that owns its nearest particle. A poor
 * partition (a file read by rank 0 alone, interleaved pieces) is first redistributed by space;
 * inputs too small to spread are gathered and processed on rank 0. Tables are on rank 0.
 *
 * @sa vtkSPHInterpolator vtkFlyingEdges3D vtkPCANormalEstimation
 */
#ifndef vtkLevelSetIsosurface_h
#define vtkLevelSetIsosurface_h

#include "LevelSetIsosurfaceFiltersModule.h" // for export macro
#include "vtkLevelSetMacros.h"               // for vtkSetClampWarnMacro
#include "vtkPolyDataAlgorithm.h"
#include "vtkSmartPointer.h" // for vtkSmartPointer

#include <functional> // for std::function
#include <memory>     // for std::unique_ptr
#include <string>     // for std::string
#include <vector>     // for std::vector

class vtkDataArray;
class vtkMultiProcessController;
class vtkPoints;
class vtkPointSet;
class vtkTable;
namespace lsi
{
struct EnclosedDeepInside;
class PointCloudIndex;
struct EvolutionSettings;
struct IsopointSet;
struct IsopointSettings;
struct Neighborhoods;
struct RequestedParameters;
struct RunParticles;
class Distribution;
class SPHField;
struct SPHFieldRequest;
class KeptCandidates;
struct SlideResult;
struct SurfaceScale;
}

class LEVELSETISOSURFACEFILTERS_EXPORT vtkLevelSetIsosurface : public vtkPolyDataAlgorithm
{
public:
  static vtkLevelSetIsosurface* New();
  vtkTypeMacro(vtkLevelSetIsosurface, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum EvolutionSchemes
  {
    VARIATIONAL_WITH_REINITIALIZATION = 0,
    VARIATIONAL_WITHOUT_REINITIALIZATION = 1,
    ROSENTHAL_LINSEN = 2
  };

  ///@{
  /** The isovalue of the input scalars (SetInputArrayToProcess(0, ...)). Default 0. */
  void SetIsoValue(double value);
  vtkGetMacro(IsoValue, double);
  ///@}

  ///@{
  /** Quick re-runs after isovalue changes, for exploring (default off). When on, and nothing but
   * IsoValue changed since the last run, the last surface slides onto the new level instead of the
   * method running again: each point by the refinement on the data (the MLS fit, from the samples
   * of its last fit, the first step from that fit's quadratic model; a level beyond half a spacing
   * is reached in strides of at most two spacings along the data's gradient, each from the samples
   * nearest to where the last ended; or the SPH field, within one kernel support, its free
   * boundary shot anew from the new inside's edge of the cloud), several times faster. The flood
   * from the seeds runs at the new isovalue and may change only next to the slid surface, no
   * further from it than the surface moved there; every point must land between the new inside
   * and outside, within the band the last full run resolved (about 8 spacings from where it put
   * the surface, at the default parameters), and no particle beyond that band (whose LevelSet
   * stays clamped) may come within its neighbourhood radius plus a cell of the new surface: the
   * Enclosed table weighs those by their distance, which the clamped LevelSet lacks (about 6
   * spacings of move in all at the default parameters). Otherwise (a larger change, a component
   * joined or lost, a cavity opened) the method runs in full. (On the SPH field, where the surface
   * lies beyond the edge of the particle cloud, the free boundary, a point whose nearest particles
   * lay all inside the last flood and still do may slide; a particle on the cloud's edge that
   * changes sides away from the slid surface runs the method, whose surface may then leave the
   * edge.) In a periodic box every point slides, those beyond the faces too, and the kept cell
   * is cut anew. Under MPI (in a periodic box too) every rank slides the points it found, and
   * all slide or none. A point's move counts
   * from where the last full run put it: a slider dragged back and forth keeps sliding. The points
   * then lie on the same level as the full method's, as many as the last run's (crowding where the
   * surface shrank); the LevelSet array is the last one moved by the change over the data's
   * gradient (within the band), so it and the Enclosed table match a full run to first order in the
   * change (after a move of several spacings the LevelSet array near the new surface is the last
   * run's from that depth: within the method's own error of the signed distance, but not the
   * method's). Off: every run is the full method, whatever ran before (reproducible from the
   * parameters alone). SlidLastSurface tells which happened. */
  vtkSetMacro(QuickIsoValueChanges, bool);
  vtkGetMacro(QuickIsoValueChanges, bool);
  vtkBooleanMacro(QuickIsoValueChanges, bool);
  ///@}

  ///@{
  /** Centre and radius of the main seed sphere. A radius of 0 (the default) seeds the whole
   * data set (its bounding box), so every component is extracted. A negative radius means a
   * tenth of the data's largest extent (ParaView's default: a script that creates the filter
   * before its input has bounds gets -0.2 from the bounds domain). Default centre (0, 0, 0).
   * With the flood start, a re-run that only moved the seeds and floods the same samples
   * hands on the last outputs (ReusedLastOutputs; under MPI when every rank does); in a periodic
   * box with PeriodicOutput AROUND_SEED, only if the main seed's centre did not move (the kept cell
   * follows it). */
  void SetSeedCenter(double x, double y, double z);
  void SetSeedCenter(const double center[3])
  {
    this->SetSeedCenter(center[0], center[1], center[2]);
  }
  vtkGetVector3Macro(SeedCenter, double);
  void SetSeedRadius(double radius);
  vtkGetMacro(SeedRadius, double);
  ///@}

  ///@{
  /** Additional seed spheres (centre x, y, z and radius): the seed is the union of all. */
  void AddAdditionalSeed(double cx, double cy, double cz, double radius);
  void RemoveAllAdditionalSeeds();
  int GetNumberOfAdditionalSeeds() const;
  /** The seeds as ParaView's proxy sets them: the length of its flat list (cx, cy, cz, r per
   * sphere), then each value, so that a list whose length is not a multiple of 4 is an error
   * when the filter runs instead of losing its tail silently. */
  void SetNumberOfAdditionalSeedValues(int count);
  void SetAdditionalSeedValue(int index, double value);
  ///@}

  ///@{
  /** Number of nearest neighbours of each sample for the MLS fits. Default 26. */
  vtkSetClampWarnMacro(NumberOfNeighbors, int, 4, 200);
  vtkGetMacro(NumberOfNeighbors, int);
  ///@}

  ///@{
  /** Width eps of the smoothed delta and sign of the main term (band: |phi| < 2 eps).
   * 0 (default): automatic, 2.5 x the mean sample spacing. */
  vtkSetClampWarnMacro(Epsilon, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(Epsilon, double);
  ///@}

  ///@{
  /** Width eps' of the smoothed delta of the curvature term. 0 (default): equal to eps. */
  vtkSetClampWarnMacro(CurvatureEpsilon, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(CurvatureEpsilon, double);
  ///@}

  ///@{
  /** Time step dt. 0 (default): automatic, 0.45 eps^2 (the paper's [0.3, 0.6] eps^2), limited so
   * that CurvatureWeight x dt <= 0.4 spacing^2. */
  vtkSetClampWarnMacro(TimeStep, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(TimeStep, double);
  ///@}

  ///@{
  /** Weight lambda of the mean-curvature (smoothing) term, without units: the term's
   * coefficient is lambda times the mean sample spacing at the isovalue (the paper's lambda at
   * spacing 1), so that the same data in any unit of length give the same surface.
   * Default 0.05. */
  vtkSetClampWarnMacro(CurvatureWeight, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(CurvatureWeight, double);
  ///@}

  ///@{
  /** Pseudo-time steps of the reinitialisation (eq. 10) after each iteration. Default 2. */
  vtkSetClampWarnMacro(ReinitializationSteps, int, 0, 100);
  vtkGetMacro(ReinitializationSteps, int);
  ///@}

  ///@{
  /** Weight mu of the distance-regularisation term of the scheme without reinitialisation
   * (eq. 13). Default 0.1. Unused by the default scheme. */
  vtkSetClampWarnMacro(DistanceRegularization, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(DistanceRegularization, double);
  ///@}

  ///@{
  /**
   * VARIATIONAL_WITH_REINITIALIZATION (0, default), VARIATIONAL_WITHOUT_REINITIALIZATION (1)
   * or ROSENTHAL_LINSEN (2: the earlier method the paper compares against, eq. 16 with
   * reinitialisation; phi relaxes towards (f - f_iso) / |grad f|).
   */
  vtkSetClampWarnMacro(EvolutionScheme, int, VARIATIONAL_WITH_REINITIALIZATION, ROSENTHAL_LINSEN);
  vtkGetMacro(EvolutionScheme, int);
  void SetEvolutionSchemeToWithReinitialization()
  {
    this->SetEvolutionScheme(VARIATIONAL_WITH_REINITIALIZATION);
  }
  void SetEvolutionSchemeToWithoutReinitialization()
  {
    this->SetEvolutionScheme(VARIATIONAL_WITHOUT_REINITIALIZATION);
  }
  void SetEvolutionSchemeToRosenthalLinsen() { this->SetEvolutionScheme(ROSENTHAL_LINSEN); }
  ///@}

  ///@{
  /** Upper bound on the iterations. Default 500. */
  vtkSetClampWarnMacro(MaximumNumberOfIterations, int, 0, VTK_INT_MAX);
  vtkGetMacro(MaximumNumberOfIterations, int);
  ///@}

  ///@{
  /** Stopping rule: the evolution stops when, for 3 iterations in a row, at most this fraction
   * of the band's samples changed sign for the first time (the front no longer advances
   * anywhere). Default 0.0001. */
  vtkSetClampWarnMacro(ConvergenceTolerance, double, 0.0, 1.0);
  vtkGetMacro(ConvergenceTolerance, double);
  ///@}

  ///@{
  /** Complete the isopoints on tangent planes (paper Fig. 3) for hole-free rendering.
   * Default on. */
  vtkSetMacro(Completion, bool);
  vtkGetMacro(Completion, bool);
  vtkBooleanMacro(Completion, bool);
  ///@}

  ///@{
  /**
   * Final refinement on the data (default on). The level set only uses the sign of
   * f - IsoValue, which places the surface to a fraction of the sample spacing. This slides
   * each isopoint along its normal (at most half a spacing) to the zero of a moving-least-
   * squares fit of f - IsoValue over 2 (n + 1) nearby samples, and takes the normal from that
   * fit's gradient. The fit averages over its samples, so noisy data stay smooth.
   */
  vtkSetMacro(DataRefinement, bool);
  vtkGetMacro(DataRefinement, bool);
  vtkBooleanMacro(DataRefinement, bool);
  ///@}

  enum Fields
  {
    AUTOMATIC_FIELD = 0, // the SPH field when the input has smoothing lengths and masses
    MLS_FIELD = 1,       // the MLS fit of the samples, always
    SPH_FIELD = 2        // the SPH field, or an error if the input cannot give it
  };
  ///@{
  /**
   * Which field the surface is the isosurface of, in the refinement on the data, the normals
   * and the interpolated arrays. AUTOMATIC_FIELD (default): on SPH particles (a smoothing
   * length array and a mass array, as the readers and Particle Density mark them) the field the
   * simulation defines, rho(x) = sum_j m_j W(|x - x_j|, H_j) for the density and
   * A(x) = sum_j (m_j / rho_j) A_j W(|x - x_j|, H_j) for any other array, with each particle's
   * own support H_j (not normalised); the samples' signs come from it too. On other point data
   * (sensors, no smoothing lengths) the MLS fit of the samples, as on smoothing lengths that
   * do not describe the particles (LevelSetSPHFieldChecks.h: supports far below the spacing,
   * or stored densities more than 1.25 times off the kernel sums of the masses), with a
   * warning. MLS_FIELD and SPH_FIELD force one (SPH_FIELD still warns); SPH_FIELD is an error
   * without smoothing lengths and masses.
   */
  vtkSetClampWarnMacro(Field, int, AUTOMATIC_FIELD, SPH_FIELD);
  vtkGetMacro(Field, int);
  ///@}

  enum Kernels
  {
    AUTOMATIC_KERNEL = 0, // the kernel the reader marked ("SPHKernel"), else the cubic spline
    CUBIC_SPLINE = 1,     // M4: GADGET, GIZMO, Gasoline, ChaNGa
    QUINTIC_SPLINE = 2,   // M6: SWIFT's "Quintic spline (M6)"
    WENDLAND_C2 = 3,      // SWIFT's, GADGET-4's (WENDLAND_C2_KERNEL) and others'
    QUARTIC_SPLINE = 4,   // M5: SWIFT's "Quartic spline (M5)"
    WENDLAND_C4 = 5,      // SWIFT's and GADGET-4's (WENDLAND_C4_KERNEL)
    WENDLAND_C6 = 6       // SWIFT's and GADGET-4's (WENDLAND_C6_KERNEL)
  };
  ///@{
  /**
   * The SPH kernel of the field (see Field). Default AUTOMATIC_KERNEL: the kernel the reader
   * marked (SWIFT's HydroScheme "Kernel function", GADGET-4's Config flags), else the cubic
   * spline; a marker that names no kernel here gives a warning and the cubic spline.
   */
  vtkSetClampWarnMacro(Kernel, int, AUTOMATIC_KERNEL, WENDLAND_C6);
  vtkGetMacro(Kernel, int);
  ///@}

  ///@{
  /**
   * The kernel's support radius H per smoothing length h, H = SupportPerSmoothingLength h.
   * 0 (default): as the reader marked it ("SupportPerSmoothingLength" field data: GADGET and
   * GIZMO 1, SWIFT its Kernel gamma, Tipsy 2), else 2 for Gasoline's and ChaNGa's names
   * (smoothlength, SPHH, SphH, hsmall, hsmooth), else 1.
   */
  vtkSetClampWarnMacro(SupportPerSmoothingLength, double, 0.0, 100.0);
  vtkGetMacro(SupportPerSmoothingLength, double);
  ///@}

  ///@{
  /**
   * The point arrays of the SPH field. Empty (default): the arrays the reader marked
   * (field data "SmoothingLengthArray", "MassArray", "DensityArray"), else the usual names
   * (SmoothingLength(s), smoothlength; Masses, Mass, mass; Density, Densities, rho; not a
   * Tipsy file's hsmooth, the gravitational softening in Gasoline's and ChaNGa's). Without a
   * density array the densities are summed from the masses.
   */
  vtkSetStdStringFromCharMacro(SmoothingLengthArray);
  vtkGetCharFromStdStringMacro(SmoothingLengthArray);
  vtkSetStdStringFromCharMacro(MassArray);
  vtkGetCharFromStdStringMacro(MassArray);
  vtkSetStdStringFromCharMacro(DensityArray);
  vtkGetCharFromStdStringMacro(DensityArray);
  ///@}

  ///@{
  /**
   * Periodic boxes (default on): when the box is known, from BoxSize or the "BoxSize" field
   * data the HDF5 reader passes from the snapshot's Header, the box wraps ([0, BoxSize), or
   * [-BoxSize/2, BoxSize/2) when the particles lie around 0, as in Tipsy boxes): the
   * particles within PeriodicMargin of a face are copied across it (ghost images), so that
   * neighbourhoods, the flood and the SPH field continue through the faces, and a component
   * that crosses a face is one closed surface. The seeded component is followed through the
   * faces. Off: the box's faces are edges of the data.
   */
  vtkSetMacro(Periodic, bool);
  vtkGetMacro(Periodic, bool);
  vtkBooleanMacro(Periodic, bool);
  ///@}

  ///@{
  /** The periodic box's size on each axis (the box is [0, BoxSize)). (0, 0, 0) (default): the
   * snapshot's "BoxSize" field data (one value or three); without it, no periodic box. */
  vtkSetVector3Macro(BoxSize, double);
  vtkGetVector3Macro(BoxSize, double);
  ///@}

  ///@{
  /** How far the ghost images reach beyond each face, as a fraction of the box (default 0.1:
   * up to 1.7 times the particles). It must hold the neighbourhoods and kernel supports of the
   * particles near the faces; a warning says when it does not, and what would. */
  vtkSetClampWarnMacro(PeriodicMargin, double, 0.01, 0.25);
  vtkGetMacro(PeriodicMargin, double);
  ///@}

  enum PeriodicOutputs
  {
    IN_BOX = 0,     // the surface inside [0, BoxSize): a component crossing a face is cut there
    AROUND_SEED = 1 // the surface inside the box centred on the seed: the component in one piece
  };
  ///@{
  /** Which periodic cell the surface is given in (periodic boxes only). Default IN_BOX. */
  vtkSetClampWarnMacro(PeriodicOutput, int, IN_BOX, AROUND_SEED);
  vtkGetMacro(PeriodicOutput, int);
  ///@}

  enum Initializations
  {
    SEED_SPHERES = 0, // the paper: phi starts as the distance to the seed spheres
    FLOOD = 1         // start at the answer: flood f > f_iso from the seeds (default)
  };
  ///@{
  /**
   * How phi starts. FLOOD (default): the samples with f > IsoValue connected to the seeds
   * through the neighbour graph are the inside (on the SPH field, not across a dip of the field
   * below IsoValue between two neighbours near the surface: LevelSetFloodOnField.h), and phi
   * starts as the signed distance to their
   * boundary, so the evolution only smooths the front (a few iterations instead of tens), and
   * keeps to that component: samples above IsoValue that the flood did not reach count as
   * outside, so another component near the front (a clump a few spacings away) is never pulled
   * in. SEED_SPHERES: the paper's start, the signed distance to the seed spheres; the front then
   * grows to every component of f > IsoValue it comes within its band (2 eps) of.
   */
  vtkSetClampWarnMacro(Initialization, int, SEED_SPHERES, FLOOD);
  vtkGetMacro(Initialization, int);
  void SetInitializationToSeedSpheres() { this->SetInitialization(SEED_SPHERES); }
  void SetInitializationToFlood() { this->SetInitialization(FLOOD); }
  ///@}

  enum OutputTypes
  {
    ISOPOINTS = 0, // one vertex per isopoint
    SPLATS = 1     // one oriented polygon per isopoint (default)
  };
  ///@{
  /** What port 0 holds: SPLATS (default), a closed surface of small oriented polygons that any
   * renderer or exporter draws, or ISOPOINTS, the points themselves (one vertex each). A change
   * of this, SplatScale, SplatSides or InterpolateArrays alone makes port 0 anew from the last
   * run's points, without running the method (on the SPH field, with that field: kept by
   * QuickIsoValueChanges, else built again); the other ports are handed on. */
  vtkSetClampWarnThenMacro(OutputType, int, ISOPOINTS, SPLATS, OutputsModified);
  vtkGetMacro(OutputType, int);
  void SetOutputTypeToIsopoints() { this->SetOutputType(ISOPOINTS); }
  void SetOutputTypeToSplats() { this->SetOutputType(SPLATS); }
  ///@}

  ///@{
  /** Splat radius (the "SplatRadius" array, and the size of the polygons) relative to the
   * distance from each isopoint to its 6th nearest isopoint. Default 1. */
  vtkSetClampWarnThenMacro(SplatScale, double, 0.01, 100.0, OutputsModified);
  vtkGetMacro(SplatScale, double);
  ///@}

  ///@{
  /** Corners of each splat polygon. Default 8. */
  vtkSetClampWarnThenMacro(SplatSides, int, 3, 64, OutputsModified);
  vtkGetMacro(SplatSides, int);
  ///@}

  ///@{
  /** Interpolate every point array of the input onto the surface (MLS linear fit over the
   * 2 (NumberOfNeighbors + 1) nearest particles), so it can be coloured by any particle
   * quantity. Default on. */
  virtual void SetInterpolateArrays(bool interpolate)
  {
    if (this->InterpolateArrays != interpolate)
    {
      this->InterpolateArrays = interpolate;
      this->OutputsModified();
    }
  }
  vtkGetMacro(InterpolateArrays, bool);
  vtkBooleanMacro(InterpolateArrays, bool);
  ///@}

  ///@{
  /** How many particle geometries (e.g. time steps) keep their neighbourhoods for reuse.
   * Each costs roughly 200 bytes per particle with 26 neighbours (neighbour lists, positions,
   * kd-tree, and MLS stencils where the surface passed). Default 4. */
  vtkSetClampWarnMacro(NeighborCacheSize, int, 1, 1000);
  vtkGetMacro(NeighborCacheSize, int);
  ///@}

  ///@{
  /** Threads for the parallel loops; 0 (default) uses all cores. */
  vtkSetClampWarnMacro(NumberOfThreads, int, 0, 1024);
  vtkGetMacro(NumberOfThreads, int);
  ///@}

  ///@{
  /** Read-only results of the last execution. */
  vtkGetMacro(NeighborSearchCount, int); // how many times the neighbourhoods were built
  // How many times the flood ran (Initialization FLOOD): a run whose particles, scalars,
  // IsoValue, seeds and band are the last flood's (a change of CurvatureWeight, TimeStep or an
  // output property, say) starts from that flood's level set instead.
  vtkGetMacro(FloodCount, int);
  // Whether the last run only moved the seeds within the same flooded samples and handed on
  // the run before's outputs (the evolution, isopoint and output stages then take 0 s).
  vtkGetMacro(ReusedLastOutputs, bool);
  // Whether the last run slid the run before's surface onto a new IsoValue (QuickIsoValueChanges)
  // instead of running the method: the evolution then takes 0 s.
  vtkGetMacro(SlidLastSurface, bool);
  // Whether the last run only made the surface output anew from the run before's points (a
  // change of OutputType, SplatScale, SplatSides or InterpolateArrays alone; under MPI when
  // every rank did) and handed on the other outputs.
  vtkGetMacro(RemadeSurfaceOutput, bool);
  vtkGetMacro(NumberOfIsopoints, vtkIdType);
  vtkGetMacro(NumberOfIterationsPerformed, int);
  vtkGetMacro(Converged, bool);
  vtkGetMacro(UsedSPHField, bool); // whether the last run used the SPH field (see Field)
  vtkGetMacro(MeanSampleSpacing, double);
  /** Under MPI: this rank's seconds in communication (waiting for slower ranks included), and
   * the ghost particles over all ranks as a fraction of the particles. */
  vtkGetMacro(CommunicationSeconds, double);
  vtkGetMacro(GhostFraction, double);
  vtkGetMacro(EffectiveEpsilon, double);
  vtkGetMacro(EffectiveCurvatureEpsilon, double);
  vtkGetMacro(EffectiveTimeStep, double);
  // spatial sort + nearest neighbours (only the cache lookup when it held them: the sort, nearest
  // and tree times are then 0)
  vtkGetMacro(NeighborSearchSeconds, double);
  vtkGetMacro(SpatialSortSeconds, double);
  vtkGetMacro(NearestNeighborSeconds, double); // kd-tree build + queries
  vtkGetMacro(TreeBuildSeconds, double);
  vtkGetMacro(StencilSeconds, double); // MLS stencils, computed on demand (all runs so far)
  vtkGetMacro(InitializationSeconds, double);
  vtkGetMacro(EvolutionSeconds, double);
  vtkGetMacro(IsopointSeconds, double); // includes the completion
  vtkGetMacro(CompletionSeconds, double);
  vtkGetMacro(DataRefinementSeconds, double); // included in IsopointSeconds
  vtkGetMacro(OutputSeconds, double);         // splat radii, interpolated arrays, polygons
  // checking the input, f - f_iso at the samples (or the SPH field there) and the global scales
  vtkGetMacro(InputSeconds, double);
  vtkGetMacro(ParticleOutputSeconds, double); // the Particles and Enclosed outputs
  ///@}

  ///@{
  /**
   * The MPI controller whose ranks hold the particles (by default the global controller). With
   * more than one rank the filter runs distributed; null or one rank is a serial run.
   */
  virtual void SetController(vtkMultiProcessController*);
  vtkGetObjectMacro(Controller, vtkMultiProcessController);
  ///@}

protected:
  vtkLevelSetIsosurface();
  ~vtkLevelSetIsosurface() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int FillOutputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  double IsoValue = 0.0;
  bool QuickIsoValueChanges = false;
  double SeedCenter[3] = { 0.0, 0.0, 0.0 };
  double SeedRadius = 0.0;
  std::vector<double> AdditionalSeeds; // 4 per sphere (a multiple of 4, checked on execution)
  int NumberOfNeighbors = 26;
  double Epsilon = 0.0;
  double CurvatureEpsilon = 0.0;
  double TimeStep = 0.0;
  double CurvatureWeight = 0.05;
  int ReinitializationSteps = 2;
  double DistanceRegularization = 0.1;
  int EvolutionScheme = VARIATIONAL_WITH_REINITIALIZATION;
  int MaximumNumberOfIterations = 500;
  double ConvergenceTolerance = 1e-4;
  bool Completion = true;
  int Initialization = FLOOD;
  bool DataRefinement = true;
  int NumberOfThreads = 0;
  vtkMultiProcessController* Controller = nullptr;
  int OutputType = SPLATS;
  double SplatScale = 1.0;
  int SplatSides = 8;
  bool InterpolateArrays = true;
  int NeighborCacheSize = 4;
  int Field = AUTOMATIC_FIELD;
  int Kernel = AUTOMATIC_KERNEL;
  double SupportPerSmoothingLength = 0.0;
  std::string SmoothingLengthArray, MassArray, DensityArray;
  bool Periodic = true;
  double BoxSize[3] = { 0.0, 0.0, 0.0 };
  double PeriodicMargin = 0.1;
  int PeriodicOutput = IN_BOX;

  // Read-only results of the last execution (see the getters).
  int NeighborSearchCount = 0, NumberOfIterationsPerformed = 0, FloodCount = 0;
  vtkIdType NumberOfIsopoints = 0;
  bool Converged = false, UsedSPHField = false;
  double CommunicationSeconds = 0.0, GhostFraction = 0.0;
  double MeanSampleSpacing = 0.0, EffectiveEpsilon = 0.0, EffectiveCurvatureEpsilon = 0.0,
         EffectiveTimeStep = 0.0;
  double NeighborSearchSeconds = 0.0, SpatialSortSeconds = 0.0, NearestNeighborSeconds = 0.0,
         TreeBuildSeconds = 0.0, StencilSeconds = 0.0, InitializationSeconds = 0.0,
         EvolutionSeconds = 0.0, IsopointSeconds = 0.0, CompletionSeconds = 0.0,
         DataRefinementSeconds = 0.0, OutputSeconds = 0.0, InputSeconds = 0.0,
         ParticleOutputSeconds = 0.0;

private:
  // Marks the filter modified. Returns its new modification time when nothing but changes of
  // one kind, whose last such time is `alone`, came since the last run; else 0.
  vtkMTimeType ModifiedAlone(vtkMTimeType alone);
  // Seed changes mark the filter modified through this: when nothing else changed since the
  // last run, SeedsOnlyTime is the filter's modification time after them.
  void SeedsModified();
  // With only the seeds moved since the last run: floods from the new seeds and, if the same
  // samples are flooded, hands on the last outputs. False: run the method. Under MPI every
  // rank calls it on every run (it decides with the others).
  bool ReuseAfterSeedMove(bool onlySeedsChanged, vtkPointSet* input, vtkPolyData* surfaceOutput,
    vtkPolyData* particleOutput, vtkTable* convergence, vtkTable* enclosed);
  // Whether the kept periodic cell is the last run's (PeriodicOutput AROUND_SEED centres it on
  // the main seed of the last flood's spheres).
  bool SameKeptCell() const;
  // Likewise for IsoValue: IsoValueOnlyTime is the modification time after an isovalue change
  // when nothing else changed since the last run; and for the surface output's own properties
  // (OutputType, SplatScale, SplatSides, InterpolateArrays): OutputsOnlyTime.
  vtkMTimeType LastRunTime = 0, SeedsOnlyTime = 0, IsoValueOnlyTime = 0, OutputsOnlyTime = 0;
  void OutputsModified();
  // With only the surface output's properties changed since the last run: makes the surface
  // output anew from the points the last run showed, and hands on its other outputs. False
  // (nothing kept, or the input changed): run the method. Under MPI every rank calls it on
  // every run (it decides with the others).
  bool RemakeSurfaceOutput(bool onlyOutputsChanged, vtkPointSet* input, vtkPolyData* surfaceOutput,
    vtkPolyData* particleOutput, vtkTable* convergence, vtkTable* enclosed);
  // The SPH field the last run used, built again on its particles (`work`: with their ghosts
  // and images) when it was not kept; null if it cannot be.
  std::unique_ptr<lsi::SPHField> RebuildSPHField(
    vtkPointSet* work, const lsi::Neighborhoods& geometry);
  // The SPH field the last run used: the one it kept (for quick isovalue changes), else built
  // again (RebuildSPHField, held by `rebuilt`); null on point data, or if it cannot be built.
  const lsi::SPHField* LastSPHField(vtkPointSet* input, const lsi::Neighborhoods& geometry,
    std::unique_ptr<lsi::SPHField>& rebuilt);
  bool ReusedLastOutputs = false, SlidLastSurface = false, RemadeSurfaceOutput = false;
  // With only IsoValue changed since the last run and QuickIsoValueChanges on: slides the last
  // surface onto the new level (LevelSetIsoValueSlide.h) if the checks there allow. False: run
  // the method. Under MPI every rank calls it on every run (it decides with the others).
  bool SlideAfterIsoValueChange(bool onlyIsoValueChanged, vtkPointSet* input,
    vtkPolyData* surfaceOutput, vtkPolyData* particleOutput, vtkTable* convergence,
    vtkTable* enclosed);
  // A quick isovalue change's slide of the last run's points (LastOutputs::Isopoints, in place)
  // onto the new level, over the data's MLS fit or the SPH field (whose free boundary's points
  // are shot anew); `aborted` if the user stopped it.
  lsi::SlideResult SlideLastPoints(const lsi::Neighborhoods& geometry,
    const std::vector<double>& dataOffsets, const std::vector<char>& inside, bool& aborted);
  // Whether the slid points stand for the method's surface, decided with the other ranks: the
  // slide reached the level, every sample that changed sides lies near a slid point, and no
  // sample beyond the band comes within a shell width (LevelSetIsoValueSlide.h). Gives the
  // points this rank keeps under MPI and the largest move of any rank's kept points.
  bool AcceptSlide(const lsi::Neighborhoods& geometry, const std::vector<char>& inside,
    const lsi::SlideResult& slid, const lsi::PointCloudIndex* surfaceIndex,
    std::vector<char>& keptPoints, double& largestMove);
  // At the end of a full run that a later isovalue change may slide (LastOutputs::SlideReady):
  // keeps what the slide needs (the values and phi in storage order, the field, the points
  // `found` with their fits, the band's gradients), moving field, phi and found there.
  void KeepForSlides(vtkPointSet* work, const lsi::Neighborhoods& geometry,
    const std::vector<double>& values, const std::vector<double>& dataOffsets,
    std::unique_ptr<lsi::SPHField>& field, std::vector<double>& phi, lsi::IsopointSet& found,
    const lsi::IsopointSettings& settings, double halfWidth);
  // The array the scalars come from (SetInputArrayToProcess(0, ...)), or null.
  vtkDataArray* ScalarsOf(vtkPointSet* input);
  // The array to process (Scalars), or the input's active point scalars when none is named.
  vtkDataArray* InputScalars(vtkDataObject* input, int& association);
  // The geometry the last run searched, if still cached and of this input (no search); else
  // null. `withFlood`: also the last run's flood kept (QuickCheck, the flood start), which a seed
  // move or a slide needs and a remake of the surface output does not.
  const lsi::Neighborhoods* LastGeometry(vtkPointSet* input, bool withFlood = true);
  // The flood from the current seeds over `dataOffsets` (f - f_iso per sample) on the last
  // run's geometry (and its points: their bounds and, for the same spheres, the samples in them
  // are kept); false if the seeds are refused or reach no sample above the isovalue.
  bool FloodFromSeeds(const lsi::Neighborhoods& geometry, const std::vector<double>& dataOffsets,
    const lsi::SPHField* field, std::vector<char>& inside);

  vtkLevelSetIsosurface(const vtkLevelSetIsosurface&) = delete;
  void operator=(const vtkLevelSetIsosurface&) = delete;

  // The method's steps (see the class documentation). Each returns false when the filter must
  // stop: an error (reported) or an abort.
  bool Execute(vtkPointSet* input, vtkPolyData* surfaceOutput, vtkPolyData* particleOutput,
    vtkTable* convergence, vtkTable* enclosed);
  // The particles a full run works on (lsi::RunParticles): checked, spread over the ranks,
  // duplicates merged, with their periodic images and MPI ghosts and their neighbourhoods (or,
  // under MPI, the last run's, kept for a re-run on the same particles). False on bad input or
  // an abort; `run.Idle` on a rank left without particles.
  bool PrepareParticles(vtkPointSet* input, lsi::RunParticles& run);
  bool ValidateInput(vtkPointSet* input, std::vector<double>& values);
  vtkSmartPointer<vtkPointSet> Distribute(
    vtkPointSet* input, std::vector<double>& values, bool& idle);
  vtkSmartPointer<vtkPointSet> WithGhosts(
    vtkPointSet* work, const lsi::Neighborhoods& owned, std::vector<double>& values);
  // Under MPI, what sizes a rank's halo besides its neighbourhood radii: the band Epsilon asks
  // for, and each particle's kernel support on the SPH field (else none).
  void HaloInputs(vtkPointSet* work, double& band, std::vector<double>& support);
  // Under MPI, for a full re-run on the same particles with the same halo: the last run's
  // neighbourhoods with its ghosts (kept with its ranks), else null. Decided with the others.
  const lsi::Neighborhoods* KeptGhosts(vtkPointSet* input);
  // The flood of the seeds' component (`inside`), the method's and a quick re-run's, across the
  // periodic box's faces and the ranks (LevelSetFloodAcross.h); seeds are added to `inSeed`.
  // False if aborted.
  /// (field: the SPH field, whose dips below IsoValue between neighbours the flood does not
  /// cross; null on point data.)
  bool FloodComponent(const lsi::Neighborhoods& geometry, const std::vector<double>& dataOffsets,
    const lsi::SPHField* field, std::vector<char>& inSeed, std::vector<char>& inside,
    double& seedSamples);
  void KeepOwnedIsopoints(const lsi::Neighborhoods& geometry, lsi::IsopointSet& isopoints);
  void WarnIfSuspect(const lsi::Neighborhoods& geometry, const std::vector<double>& dataOffsets,
    const std::vector<double>& phi, const lsi::IsopointSet& isopoints);
  // Warns when the surface (this rank's points) comes within the field's reach of a face of the
  // region a reader read (LevelSetRegionFaces.h), where the particles beyond were not read.
  void WarnIfRegionCut(vtkPointSet* input, const lsi::Neighborhoods& geometry,
    const lsi::SPHField* field, const std::vector<double>& points);
  lsi::SPHFieldRequest SPHRequest() const;
  // The input's bounds over every rank; `own` (if given) receives this rank's alone (empty:
  // +inf, -inf, ...).
  void Bounds(vtkPointSet* input, double bounds[6], double own[6] = nullptr);
  // Under MPI, messages about the whole run come from rank 0 only.
  bool ReportsForAll() const;
  vtkSmartPointer<vtkPointSet> WithPeriodicImages(vtkPointSet* input, std::vector<double>& values);
  void KeepPeriodicCell(lsi::IsopointSet& isopoints);
  void CheckPeriodicMargin(const lsi::Neighborhoods& geometry, const lsi::SPHField* field);
  // The neighbourhoods of `points` (cached), checked.
  const lsi::Neighborhoods* FindNeighborhoods(vtkPoints* points, bool duplicatesAllowed);
  lsi::EvolutionSettings ChooseEvolutionSettings(const lsi::SurfaceScale& scale);
  bool Initialize(vtkPointSet* input, const lsi::Neighborhoods& geometry,
    const std::vector<double>& dataOffsets, const lsi::SPHField* field,
    const lsi::EvolutionSettings& settings, std::vector<double>& phi);
  bool BuildSPHField(vtkPointSet* input, const lsi::Neighborhoods& geometry,
    const std::vector<double>& values, std::unique_ptr<lsi::SPHField>& field);
  /// (component: the flood's inside at the start, which the evolution keeps to; null with the
  /// seed spheres' start.)
  bool Evolve(const lsi::Neighborhoods& geometry, const std::vector<double>& dataOffsets,
    const std::vector<char>* component, const lsi::EvolutionSettings& settings,
    std::vector<double>& phi, vtkTable* iterations);
  /// (phi: the evolved level set, changed meanwhile and put back before it returns.)
  bool ExtractIsopoints(const lsi::Neighborhoods& geometry, const std::vector<double>& dataOffsets,
    std::vector<double>& phi, const lsi::SurfaceScale& scale, const lsi::SPHField* field,
    lsi::IsopointSet& isopoints, lsi::IsopointSettings& settings);
  // (`nearbyPoints`: the points whose distances set the splat radii, the isopoints or, under
  // MPI, every point the rank found; `surfaceIndex`: a search index over them, or null when
  // there are none.)
  bool MakeSurfaceOutput(vtkPointSet* input, const lsi::Neighborhoods& geometry,
    const lsi::IsopointSet& isopoints, const std::vector<double>& nearbyPoints,
    const lsi::SPHField* field, const lsi::PointCloudIndex* surfaceIndex, vtkPolyData* output,
    const std::vector<double>* scalarsInStorageOrder = nullptr,
    lsi::KeptCandidates* keptSplats = nullptr);
  // The particles with their LevelSet array (`original`: the input's points, `input`: with
  // images and ghosts) and the Enclosed table; `halfWidth`: the band's (phi is clamped beyond).
  // The particles' distances are measured to the points this rank keeps (`keptPoints`, in one
  // process every point, with `surfaceIndex`, a search index over them or null), under MPI to
  // every rank's kept points within reach (KeptSurfaceWithinReach; `surfaceIndex` unread).
  // The table's deep inside is kept for quick re-runs (`keep`), or taken from the last run's.
  // `changed`, if given: the only samples whose phi changed since the last run's particles
  // output (its LevelSet array is then copied and updated there).
  void MakeParticleOutputs(vtkPointSet* original, vtkPointSet* input,
    const lsi::Neighborhoods& geometry, const std::vector<double>& phi,
    const std::vector<vtkIdType>& mergedId, double halfWidth, const lsi::IsopointSet& keptPoints,
    const lsi::PointCloudIndex* surfaceIndex, vtkPolyData* particleOutput, vtkTable* enclosed,
    lsi::EnclosedDeepInside* keep, const lsi::EnclosedDeepInside* kept,
    const std::vector<std::size_t>* changed = nullptr);

  // The user's parameters, for the step files.
  lsi::RequestedParameters RequestedParameters() const;
  // Progress over the part [range[0], range[1]] of the run, and abort: returns true to stop.
  std::function<bool(double)> Stage(const double range[2]);
  // Reports progress (if not negative) and returns whether the user asked to abort.
  bool ProgressOrAbort(double progress);

  struct Internals;
  std::unique_ptr<Internals> Internal;
  // For a re-run's steps under MPI: the last run's ranks in place of this run's (ReRuns.cxx).
  class LastRanksScope;
  // Whether the last run's ranks (kept for re-runs) match this run's: kept under MPI, on as many
  // ranks; none in a serial run.
  bool LastRanksMatch() const;
};

#endif
