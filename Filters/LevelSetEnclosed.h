// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
// Step 9: what the surface encloses, per connected component and in total: particles, mass,
// volume, surface area, centre of mass, and the mass-weighted mean of every point array.
// Each particle near the surface is weighted by a smooth step of its signed distance d to the
// surface (its height over the tangent plane of the nearest isopoint, positive inside) over
// plus or minus the local neighbourhood radius s (about two spacings):
// H(d) = 1/2 (1 + d/s + sin(pi d/s)/pi), so a particle
// straddling the surface counts in part, as much as it lies inside; further away, the sign of
// the level set phi decides. The surface area is the volume integral of the step's derivative,
// sum_j V_j H'(d_j).
// Two routes give the table: over every touching particle (LevelSetEnclosed.cxx: with periodic
// images and MPI ranks), or, on one process without images, around the deep inside
// (LevelSetEnclosedDeepInside.cxx: fewer passes, and a quick re-run sums the band alone).
#ifndef LevelSetEnclosed_h
#define LevelSetEnclosed_h

#include "LevelSetCommunicator.h"
#include "LevelSetKeptCandidates.h"
#include "LevelSetNeighborhoods.h"
#include "LevelSetPeriodicImages.h"
#include "UninitializedVector.h"

#include "vtkSmartPointer.h"

#include <cmath>
#include <cstdint>
#include <vector>

class vtkDataArray;
class vtkPointSet;
class vtkTable;

namespace lsi
{

/// What a run keeps of its Enclosed sums for the quick re-runs after an isovalue change (one
/// process, no periodic images, no merged particles): the samples deep inside the surface (phi
/// at least the band's half width, which the slides leave alone, and beyond two shell widths,
/// so that each counts in full wherever the surface slides within the band), joined into
/// groups through each other, with each group's sums. A re-run then sums only the other
/// touching samples (the band) and joins them to the groups: the table of the same phi and
/// surface, for the passes over the band alone.
struct EnclosedDeepInside
{
  enum : std::uint32_t
  {
    None = 0xffffffffu // (an enumerator: never odr-used, in any C++ standard)
  };
  // Per sample (storage order): a deep sample's group (below the number of groups), a Near
  // sample's place in Near plus the number of groups, or None (far outside).
  UninitializedVector<std::uint32_t> Group;
  std::vector<std::uint32_t> Rim; // deep samples listing a neighbour that is not deep
  // The samples neither deep nor far outside (phi above FarOutside), in storage order: a slide
  // changes phi only within the band's half width, so the band is among these, whatever slid.
  std::vector<std::uint32_t> Near;
  // Per Near sample, its particle's record (enclosed::ReadParticle: mass, density and the
  // averaged arrays' values).
  UninitializedVector<double> NearRecords;
  std::vector<double> Sums; // each group's sums, packed under its lowest particle id
  int Components = 0;       // the arrays' components averaged, when kept
  // The surface points nearest to the band's samples that measured their distance by a
  // tangent plane (SurfaceDistance): per Near sample its query in Surface (None: none), whose
  // candidates a re-run on the slid points takes the nearest from where it surely lies there.
  std::vector<std::uint32_t> SurfaceQuery;
  KeptCandidates Surface;
};

struct EnclosedInputs
{
  const Neighborhoods* Geometry = nullptr;
  const std::vector<double>* Phi = nullptr; // storage order, over particles and images
  // Samples with phi at or below this are far outside the surface (beyond the evolution's
  // band): left out without computing their neighbour lists.
  double FarOutside = -HUGE_VAL;
  vtkPointSet* Particles = nullptr;   // the particles the method ran on (and images)
  vtkIdType ParticleCount = 0;        // the real ones: ids below this
  std::vector<vtkIdType> OriginalIds; // per sample: the real particle it is (empty: Order)
  PeriodicBox Box;                    // for centres of mass across faces
  const double* CellCenter = nullptr; // the cell the centres are shown in (null: the box's own)
  vtkDataArray* Mass = nullptr;       // none: volumes from the spacing, no Mass column
  vtkDataArray* Density = nullptr;    // with Mass: volumes m / rho
  // The surface's points and unit normals (3 doubles each, normals out of the inside): the
  // signed distance of a particle near the surface is its height over the tangent plane of the
  // nearest surface point (phi's own distances are offset by a fraction of a spacing there).
  const std::vector<double>* SurfacePoints = nullptr;
  const std::vector<double>* SurfaceNormals = nullptr;
  const PointCloudIndex* SurfaceIndex = nullptr; // over SurfacePoints, if built already
  // Under MPI: components joined across ranks through the ghosts, sums over every rank's
  // particles (each table is then the whole run's).
  const Communicator* Ranks = &SingleProcess();
  // No periodic images, no merged particles (else both are ignored): find the deep inside and
  // keep it here, or sum around the one kept by the last run (LevelSetEnclosedDeepInside.h).
  EnclosedDeepInside* KeepDeepInside = nullptr;
  const EnclosedDeepInside* DeepInside = nullptr;
};

/// One row per connected component of the particles inside (phi > 0; connected through the
/// neighbour graph, their shells included), the largest volume first, then a row
/// "Total". Columns: Name, Particles (phi > 0), Mass (if masses), Volume, SurfaceArea,
/// CenterOfMass (3 components; volume-weighted without masses), and "Mean " + the name of every
/// numeric point array (mass-weighted, or volume-weighted without masses). Volumes are m / rho
/// with masses and densities, else (4/3) pi R^3 / n from each particle's neighbourhood radius R
/// (the distance to its n-th neighbour: for randomly placed points the ball's mean volume is n
/// times the volume per point).
vtkSmartPointer<vtkTable> EnclosedTable(const EnclosedInputs& inputs);

} // namespace lsi

#endif
