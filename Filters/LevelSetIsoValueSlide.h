// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
// The quick re-run after an isovalue change (QuickIsoValueChanges; ours, not the paper's).
// With the refinement on the data, the method's surface lies on the level {f = f_iso} of the
// data (their MLS fit, or the SPH field): the level set decided which components and where
// each point starts, the data placed it. After a change of f_iso, each point of the last
// surface slides onto the new level by the same refinement (along the data's gradient, in
// strides, when the level moved further than the refinement reaches), for a fraction of the
// method's cost. The flood from the seeds, run again at the new isovalue, vouches that the
// components are the same (FloodChangesNearPoints); each point vouches that it still lies
// between the new inside and outside, within the band the last full run resolved
// (SlideIsopoints). Any doubt: the long way.
#ifndef LevelSetIsoValueSlide_h
#define LevelSetIsoValueSlide_h

#include "LevelSetIsopoints.h"
#include "LevelSetNeighborhoods.h"
#include "LevelSetParallel.h"
#include "LevelSetSPHField.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

namespace lsi
{

// How far each point of the surface may lie from the surface about which the last full run
// resolved its band (|phi| < HalfWidth): at most its distance to where that run put it
// (Origins), the point having started there, and at most its bound when this slide began
// (Bounds) plus its way since. Per point, in the order of the kept surface (LastOutputs::
// Isopoints). A slider dragged back and forth so returns its points near their origins, and the
// band's reach with them.
struct BandDrift
{
  double HalfWidth = HUGE_VAL;
  std::vector<double> Origins; // 3 per point; NaN where not known (the free boundary's points)
  std::vector<double> Bounds;  // per point (none: 0)
  /// Points on the last full run's surface: each at its origin, bound 0.
  void Reset(const std::vector<double>& points, double halfWidth)
  {
    this->HalfWidth = halfWidth;
    this->Origins = points;
    this->Bounds.assign(points.size() / 3, 0.0);
  }
  /// Point i's bound at `p`, having travelled `way` since this slide began.
  double At(std::size_t i, const Eigen::Vector3d& p, double way) const
  {
    double bound = (i < this->Bounds.size() ? this->Bounds[i] : 0.0) + way;
    if (3 * i + 2 < this->Origins.size() && std::isfinite(this->Origins[3 * i]))
    {
      bound = std::min(bound, (p - Eigen::Vector3d(&this->Origins[3 * i])).norm());
    }
    return bound;
  }
};

struct SlideSettings
{
  double MaximumMove = 0.0; // per step: the refinement's reach from where it gathered
  double FarMove = 0.0;     // a stride's longest towards a level beyond that reach
  int Steps = 12;           // steps at most, each from the samples nearest to where it starts
  // How far the surface may move: within the band. A point's path must stay within it (its
  // BandDrift bound at most HalfWidth); where its bound plus twice the neighbourhood radius of
  // the sample nearest to it leaves it, samples beyond the band (whose phi stays clamped) may lie
  // nearer than two neighbourhoods to the new surface: the point is flagged (NearBandEdge) for
  // ClampedSamplesClear. Null: no band.
  const BandDrift* Drift = nullptr;
  int Iterations = 3; // the refinement's iterations and tolerance (IsopointSettings)
  double Tolerance = 0.0;
  // How near to where a fit was made its quadratic model stands in for a fit anew: the
  // refinement's last step, which checks that the point sits on the fit's zero, is then taken on
  // the model (a fit per point fewer; the points as near the level: RESULTS.md). 0: a fit at
  // every step, as the refinement does.
  double ModelReach = 0.0;
  bool Quadratic = true;    // the refinement's fit order (IsopointSettings::DataFitOrder == 2)
  double ValueChange = 0.0; // f_iso now less f_iso then: f - f_iso at the old points, negated
};

struct SlideResult
{
  bool Accepted = false;
  std::string Refusal; // why not, in words (for the debug output)
  // Each point's way (the length of its path: a sample it passed lies within it of where the
  // point ended), when accepted.
  std::vector<double> Moves;
  // Per point, when accepted: 1 where its band bound plus twice the neighbourhood radius of the
  // sample nearest to it leaves the band (ClampedSamplesClear then looks around it).
  std::vector<char> NearBandEdge;
  // Per point, when accepted: its BandDrift bound where it ended (the next slide's Bounds).
  std::vector<double> Bounds;
  double LargestMove() const // of any point (0 without points)
  {
    return this->Moves.empty() ? 0.0 : *std::max_element(this->Moves.begin(), this->Moves.end());
  }
};

/// Slides each of `isopoints` along its normal onto the zero of the MLS fit of `dataOffsets`
/// (f - f_iso, the new isovalue): RefineIsopointsOnData's step, from where the last run's points
/// ended, over the samples of their last fit (FitSamples, the nearest to `centres`, 3 per point;
/// empty: to the points themselves). A fit serves within MaximumMove of where its samples were
/// gathered. A point whose level lies beyond strides towards it by the fit's quadratic model
/// alone, at most FarMove, then goes on from the samples nearest to where it got (a tree
/// search), along the data's gradient there (the field's lines bend: a far level may not lie
/// on the first normal at all); at most Steps in all. FitSamples and `centres` then hold each
/// point's last fit (the surface's arrays are interpolated over those samples), and the normals
/// the fit's gradient. Refused (isopoints and centres then unchanged) if a point's level lies
/// beyond those steps or the band, or the data's gradient there does not cross the surface, or
/// its samples are not on both sides of the new flood (`inside`, per sample): it would lie on a
/// component the seeds no longer reach, or on none.
SlideResult SlideIsopoints(const Neighborhoods& geometry, const std::vector<double>& dataOffsets,
  const std::vector<char>& inside, const SlideSettings& settings, IsopointSet& isopoints,
  std::vector<double>& centres, const AbortCheck& aborted);

/// The same on the SPH field (the points the refinement solved onto its level): each point is
/// solved along its normal onto the field's new level `isoValue` within SPHMaximumMove kernel
/// supports of the sample nearest to it (RefineIsopointsOnSPHField's step), the normal becoming
/// the field's. Refused as above when a point finds no level within that reach or the band
/// (`drift`, SlideSettings::Drift), or when the samples nearest to it are not on both sides of
/// the new flood, unless they all lay inside the last flood (`lastInside`) too and still do:
/// the free boundary, where the level lies beyond the cloud's outermost particles.
SlideResult SlideIsopointsOnSPHField(const Neighborhoods& geometry, const SPHField& field,
  double isoValue, const std::vector<char>& inside, const std::vector<char>& lastInside,
  const IsopointSettings& settings, const BandDrift* drift, IsopointSet& isopoints,
  const AbortCheck& aborted);

/// Whether every sample flooded in `before` and not in `after`, or the other way round, lies
/// within its move (`moves`, per point) plus `margin` of one of the points that `points` indexes
/// (null: no points, so no sample may change): the flood then only moved with the surface, where
/// it moved. A component joined or lost, or a cavity opened, leaves changed samples away from
/// the slid surface, or further from it than it moved there. `changed` receives how many samples
/// changed. Only the samples of the first `particles` input points count: in a periodic box the
/// originals (each image is flooded as its original is, and the images' outer edge, whose
/// neighbourhoods are cut, has no surface). (On the SPH field the cloud's outermost particles,
/// their kernels cut by the edge, may cross the isovalue a support from the free boundary's
/// surface; such a change is refused too: the method's surface then leaves the edge in places,
/// which the slid surface does not follow.)
bool FloodChangesNearPoints(const Neighborhoods& geometry, const std::vector<char>& before,
  const std::vector<char>& after, const PointCloudIndex* points, const std::vector<double>& moves,
  double margin, std::size_t& changed, vtkIdType particles);

/// Whether no sample beyond the band the last full run resolved (|phi| at least `halfWidth`,
/// clamped: its distance to the surface unknown) lies within its own neighbourhood radius plus
/// `margin` of one of `points` flagged in `nearEdge` (and in `kept`, when given: under MPI the
/// points this rank keeps). The Enclosed table counts a sample a shell width (that radius) or
/// more from the surface whole or not at all, by phi's sign, which a clamped phi still gives;
/// nearer, it would need the distance a clamped phi lacks. `margin`: how far the surface may
/// lie from its nearest point (its points' spacing). Looked for within twice the radius of the
/// sample nearest to each flagged point, plus `margin`.
bool ClampedSamplesClear(const Neighborhoods& geometry, const std::vector<double>& phi,
  double halfWidth, const std::vector<double>& points, const std::vector<char>& nearEdge,
  const std::vector<char>* kept, double margin);

/// The samples of the band (|phi| < halfWidth) among `candidates` (storage order; they must
/// hold every sample of the band), else among every sample, with the norm of the data's
/// gradient there from `values` (f, or f minus any constant) by their MLS stencils.
/// `candidateGradients`, if given with `candidates`, keeps those norms per candidate across
/// calls on the same `values` (NaN until computed; sized here when its size is not the
/// candidates'): a full run fills it for its band, so that its slides compute only the samples
/// they bring into the band.
struct BandGradients
{
  std::vector<std::size_t> Samples;
  std::vector<double> Norms;
};
BandGradients GradientsInBand(const Neighborhoods& geometry, const std::vector<double>& values,
  double halfWidth, const std::vector<double>& phi,
  const std::vector<std::uint32_t>* candidates = nullptr,
  std::vector<double>* candidateGradients = nullptr);

/// phi after f_iso grew by `valueChange` (LevelSetAfterIsoValueChange per sample), over the
/// samples of the band (|phi| < halfWidth, whose MLS stencils the evolution computed) with the
/// data's gradient there from `values` (f, or f minus any constant); phi beyond the band stays
/// clamped. `largestMove`: see LevelSetAfterIsoValueChange. The band is looked for among
/// `candidates` if given (storage order; they must hold every sample with |phi| < halfWidth),
/// else among every sample; `candidateGradients`: see GradientsInBand. Returns the band's
/// samples: the only ones whose phi changed.
std::vector<std::size_t> ShiftLevelSet(const Neighborhoods& geometry,
  const std::vector<double>& values, double valueChange, double halfWidth, double largestMove,
  std::vector<double>& phi, const std::vector<std::uint32_t>* candidates = nullptr,
  std::vector<double>* candidateGradients = nullptr);

} // namespace lsi

#endif
