// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
// The last run's outputs and state, for the re-runs that reuse them (vtkLevelSetIsosurface
// ReRuns.cxx). A seed move: with the flood start, the seeds only choose which components of
// {f > f_iso} are flooded; a seed dragged inside the same component floods the same samples
// and gives the same initial level set, so the evolution, the isopoints and every output would
// come out the same. The filter then hands these on instead of recomputing them (checked by
// flooding from the new seeds, not assumed). A small isovalue change (QuickIsoValueChanges):
// the last surface slides onto the new level (LevelSetIsoValueSlide.h).
#ifndef LevelSetLastOutputs_h
#define LevelSetLastOutputs_h

#include "LevelSetEnclosed.h"
#include "LevelSetIsoValueSlide.h"
#include "LevelSetIsopoints.h"
#include "LevelSetKeptCandidates.h"
#include "LevelSetNeighborCache.h"
#include "LevelSetSPHField.h"

#include "vtkAbstractArray.h"
#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkPointData.h"
#include "vtkPointSet.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSMPTools.h"
#include "vtkSmartPointer.h"
#include "vtkTable.h"
#include "vtkType.h"

#include <algorithm>
#include <memory>
#include <vector>

namespace lsi
{

/// What the method reads of an input, for telling whether it changed since the last run: the
/// points, every point and field array (their own modification times: ParaView touches the
/// input and its attribute containers on every update without changing any array), how many
/// there are, which array the scalars come from, and a fingerprint of the scalars' values (so
/// that values changed in place, with only the data set marked modified, are seen too).
struct InputStamp
{
  const vtkPoints* Points = nullptr;
  const vtkDataArray* Scalars = nullptr;
  vtkMTimeType Time = 0;
  int Arrays = -1;
  std::uint64_t ScalarValues = 0;

  static InputStamp Of(vtkPointSet* input, vtkDataArray* scalars)
  {
    InputStamp stamp;
    stamp.Points = input->GetPoints();
    stamp.Scalars = scalars;
    stamp.ScalarValues = scalars ? ValueFingerprint(scalars) : 0;
    stamp.Time = input->GetPoints() ? input->GetPoints()->GetMTime() : 0;
    stamp.Arrays = 0;
    for (vtkFieldData* arrays :
      { static_cast<vtkFieldData*>(input->GetPointData()), input->GetFieldData() })
    {
      for (int a = 0; arrays && a < arrays->GetNumberOfArrays(); ++a)
      {
        vtkAbstractArray* array = arrays->GetAbstractArray(a);
        stamp.Time = std::max(stamp.Time, array ? array->GetMTime() : stamp.Time);
        ++stamp.Arrays;
      }
    }
    return stamp;
  }
  bool operator==(const InputStamp& other) const
  {
    return this->Points == other.Points && this->Scalars == other.Scalars &&
      this->Time == other.Time && this->Arrays == other.Arrays &&
      this->ScalarValues == other.ScalarValues;
  }
};

/// The level set the flood started the last evolution from, with what it depends on: a run on
/// the same samples (told by their neighbourhoods' BuildNumber) with the same data offsets (f -
/// f_iso in storage order, told by a fingerprint), seed spheres, band and spacing starts from it
/// instead of flooding again: a change of CurvatureWeight, TimeStep or an output property (not
/// of Epsilon, which sets the band). Under MPI each rank keeps its own, and all start from
/// theirs or none does.
struct FloodStart
{
  std::uint64_t Samples = 0; // Neighborhoods::BuildNumber (0: nothing kept)
  std::uint64_t Offsets = 0; // ValueFingerprint of the data offsets
  std::vector<double> Spheres;
  double HalfWidth = 0.0, Spacing = 0.0;
  UninitializedVector<double> Phi; // the flood's signed distances (storage order)
  std::vector<char> InSeed;        // the samples in the spheres

  bool SameStart(const FloodStart& other) const
  {
    return this->Samples != 0 && this->Samples == other.Samples && this->Offsets == other.Offsets &&
      this->Spheres == other.Spheres && this->HalfWidth == other.HalfWidth &&
      this->Spacing == other.Spacing;
  }
};

struct LastOutputs
{
  bool Valid = false;
  const vtkPointSet* Input = nullptr; // identity only, never dereferenced
  InputStamp Stamp;
  vtkSmartPointer<vtkPolyData> Surface, Particles;
  vtkSmartPointer<vtkTable> Convergence, Enclosed;
  int Iterations = 0;
  bool Converged = false;
  double GhostFraction = 0.0; // under MPI
  // For the quick check of a seed move (runs with the flood start and no merged duplicates):
  // the flooded samples, f - f_iso and the spacing, in storage order. Work: in a periodic box
  // the particles with their images (the samples are theirs), under MPI with their ghosts
  // (kept with SurfaceReady).
  bool QuickCheck = false;
  vtkSmartPointer<vtkPointSet> Work;
  vtkSmartPointer<vtkPointSet> Owned; // under MPI: this rank's particles (before the ghosts)
  // Under MPI, what sized the halo besides the radii: Epsilon's band and a fingerprint of the
  // kernel supports (a full re-run with the same keeps the ghosts).
  double HaloBand = 0.0;
  std::uint64_t HaloSupport = 0;
  std::vector<double> WorkValues; // under MPI: f over Work, in its order (ghosts' included)
  std::vector<char> Inside;
  std::vector<double> DataOffsets;
  double Spacing = 0.0;
  // The last flood's seeds: their spheres, the input's bounds, and the samples in the spheres
  // (a re-run with the same spheres on the same points floods from these).
  std::vector<double> SeedSpheres;
  double Bounds[6] = { 0.0, 0.0, 0.0, 0.0, 0.0, 0.0 };
  std::vector<char> InSeed;
  // For the quick re-run after an isovalue change (with QuickCheck, QuickIsoValueChanges and
  // the refinement on the data): f at the samples, the level set phi after the evolution, in
  // storage order, the surface's points with their fits' samples and models, the isopoint
  // settings, the SPH field if the run used one, and the band (its half width, and how far each
  // point may have slid from the surface the method last made in full).
  bool SlideReady = false;
  std::vector<double> Values; // f in storage order: Values - IsoValue are the data offsets
  // Whether Values are exactly the Work's scalars array (one component; not on the SPH field,
  // nor averaged over merged duplicates): its interpolation onto the surface then reads them.
  bool ValuesAreScalars = false;
  const std::vector<double>* ScalarsInStorageOrder() const
  {
    return this->SlideReady && this->ValuesAreScalars ? &this->Values : nullptr;
  }
  double IsoValue = 0.0;
  std::vector<double> Phi;
  IsopointSet Isopoints;          // in a periodic box all of them, before the periodic cell is cut
  std::vector<double> FitCentres; // where FitSamples were gathered (empty: at the points)
  IsopointSettings Settings;
  std::unique_ptr<SPHField> Field; // the run's SPH field, if it used one
  BandDrift Drift;               // the band, and how far each of Isopoints may lie from its surface
  EnclosedDeepInside DeepInside; // the Enclosed sums' deep inside, which a slide leaves alone
  std::vector<double> NearGradients; // |grad f| per DeepInside.Near sample (GradientsInBand's)
  /// Where a slide looks for the band (ShiftLevelSet): the deep inside's near samples, where
  /// they were found over these samples; else null (every sample).
  const std::vector<std::uint32_t>* BandCandidates(const Neighborhoods& geometry) const
  {
    return this->DeepInside.Group.size() == geometry.NumberOfSamples ? &this->DeepInside.Near
                                                                     : nullptr;
  }
  FloodStart Start; // the last flood's level set, for runs that change no input to it
  // What the surface output was made from, for a change of its own properties alone
  // (SurfaceReady: any run without merged duplicates, whatever its start, ranks or box; with
  // Work and Stamp): the points shown, with their fits' samples (Isopoints themselves when those
  // are they: one process, no periodic cell to cut; not kept twice), and under MPI the points
  // near them, every point this rank found (the splat radii's neighbours: Isopoints when a
  // slide keeps them); whether the SPH field made it (then kept in Field, or built again for the
  // remake).
  bool SurfaceReady = false;
  bool ShownAreIsopoints = false;
  IsopointSet Shown;
  std::vector<double> Nearby;      // under MPI, unless NearbyAreIsopoints
  bool NearbyAreIsopoints = false; // under MPI with SlideReady, outside a periodic box
  bool OnField = false;
  // The splat radii's candidates, from the last full run's surface output (with
  // QuickIsoValueChanges and SlideReady): re-runs that show those points slid, or again, take
  // most radii from them.
  KeptCandidates Splats;
  KeptCandidates* SplatsIfKept() { return this->Splats.Empty() ? nullptr : &this->Splats; }
  const IsopointSet& ShownPoints() const
  {
    return this->ShownAreIsopoints ? this->Isopoints : this->Shown;
  }
  const std::vector<double>& NearbyPoints(bool distributed) const
  {
    return !distributed ? this->ShownPoints().Points
                        : (this->NearbyAreIsopoints ? this->Isopoints.Points : this->Nearby);
  }

  /// Keeps shallow copies of a successful run's outputs.
  void Remember(
    vtkPolyData* surface, vtkPolyData* particles, vtkTable* convergence, vtkTable* enclosed)
  {
    this->Surface = vtkSmartPointer<vtkPolyData>::New();
    this->Surface->ShallowCopy(surface);
    this->Particles = vtkSmartPointer<vtkPolyData>::New();
    this->Particles->ShallowCopy(particles);
    this->Convergence = vtkSmartPointer<vtkTable>::New();
    this->Convergence->ShallowCopy(convergence);
    this->Enclosed = vtkSmartPointer<vtkTable>::New();
    this->Enclosed->ShallowCopy(enclosed);
    this->Valid = true;
  }

  void Restore(
    vtkPolyData* surface, vtkPolyData* particles, vtkTable* convergence, vtkTable* enclosed) const
  {
    surface->ShallowCopy(this->Surface);
    particles->ShallowCopy(this->Particles);
    convergence->ShallowCopy(this->Convergence);
    enclosed->ShallowCopy(this->Enclosed);
  }

  /// The samples the flood's initial level set `phi` marks inside (positive).
  static std::vector<char> InsideOf(const std::vector<double>& phi)
  {
    std::vector<char> inside(phi.size());
    vtkSMPTools::For(0, static_cast<vtkIdType>(phi.size()), BalancedGrain(phi.size(), 16384),
      [&](vtkIdType begin, vtkIdType end) {
        for (vtkIdType i = begin; i < end; ++i)
        {
          inside[i] = phi[i] > 0.0;
        }
      });
    return inside;
  }
};

} // namespace lsi

#endif
