// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
// The field an SPH simulation defines (docs: sph-conventions.md), used instead of the MLS fit
// when the particles carry smoothing lengths and masses:
//   density:        rho(x) = sum_j m_j W(|x - x_j|, H_j)
//   any array A:      A(x) = sum_j (m_j / rho_j) A_j W(|x - x_j|, H_j)
// with each particle's own support radius H_j = SupportPerSmoothingLength * h_j (scatter form,
// as GADGET and SWIFT define it, not normalised). Its gradient is the kernel's analytic one.
// The refinement on the data, the output normals and the interpolated arrays use it.
#ifndef LevelSetSPHField_h
#define LevelSetSPHField_h

#include "LevelSetCommunicator.h"
#include "LevelSetNeighborhoods.h"
#include "SPHKernels.h"

#include <Eigen/Dense>

#include <cstdint>
#include <string>
#include <vector>

class vtkDataArray;
class vtkDataObject;
class vtkPointSet;

namespace lsi
{

/// What the user set (the filter's properties); empty or 0 means "as the reader marked it".
struct SPHFieldRequest
{
  int Model = 0;  // 0: automatic, 1: MLS always, 2: SPH field (an error if it cannot be built)
  int Kernel = 0; // 0: automatic, else SPHKernel + 1
  double SupportPerSmoothingLength = 0.0;
  std::string SmoothingLengthArray, MassArray, DensityArray;
};

/// The input arrays of the SPH field, found from the request, the field data markers the readers
/// and vtkParticleDensity write (DensityArray, SmoothingLengthArray, MassArray, SPHKernel,
/// SupportPerSmoothingLength), and the usual names.
struct SPHFieldArrays
{
  vtkDataArray* SmoothingLength = nullptr;
  vtkDataArray* Mass = nullptr;
  vtkDataArray* Density = nullptr; // null when unknown: computed by summation
  bool ValuesAreDensity = false;   // the isosurface's scalar is the density itself
  SPHKernel Kernel = SPHKernel::CubicSpline;
  double SupportPerSmoothingLength = 1.0;
  // The input's SPHKernel marker when it names no kernel the field knows (the cubic spline is
  // used then, and the filter warns); "" otherwise.
  std::string UnknownKernel;
};

/// The array name a reader's (or Particle Density's) field data marker names: a one-string
/// array such as DensityArray or SPHKernel; "" without one.
std::string MarkedArrayName(vtkDataObject* data, const char* marker);

/// The mass and density arrays as FindSPHArrays finds them (the request's name, else the marked
/// one, else the usual names), or null; for uses that need no smoothing length.
vtkDataArray* MarkedMassArray(vtkPointSet* input, const std::string& requested);
vtkDataArray* MarkedDensityArray(vtkPointSet* input, const std::string& requested);

/// Whether the SPH field applies: true with `arrays` filled when the input carries smoothing
/// lengths and masses (and the request does not say MLS). `problem` is set when the request
/// asks for the SPH field and the input cannot give it, or an array is malformed; `choice`
/// says in words which field is used and why, for the filter's log.
bool FindSPHArrays(vtkPointSet* input, vtkDataArray* scalars, const SPHFieldRequest& request,
  SPHFieldArrays& arrays, std::string& problem, std::string& choice);

/// The particles that can contribute near one place, copied together for fast loops.
struct SPHCandidates
{
  std::vector<double> X, Y, Z, H, Coefficient;
  void Clear()
  {
    X.clear();
    Y.clear();
    Z.clear();
    H.clear();
    Coefficient.clear();
  }
  /// Appends a particle at x with support h and coefficient c.
  void Add(const double* x, double h, double c)
  {
    X.push_back(x[0]);
    Y.push_back(x[1]);
    Z.push_back(x[2]);
    H.push_back(h);
    Coefficient.push_back(c);
  }
};

/// The SPH field over the samples, stored in their storage order (Neighborhoods::Order).
class SPHField
{
public:
  /// `values` are the scalar's values in input order. Returns a field with Valid() false (and
  /// `problem` set) when a smoothing length is not positive and finite or a mass is negative.
  SPHField(const Neighborhoods& geometry, const SPHFieldArrays& arrays,
    const std::vector<double>& values, std::string& problem);

  bool Valid() const { return this->IsValid; }

  /// The field f(x) and its gradient.
  void Evaluate(const double* x, double& value, double* gradient) const;

  /// The field f(x) alone: Evaluate's value, to the bit, without the gradient's work.
  double ValueAt(const double* x) const;

  /// The samples whose support reaches within `extra` of x: every sample that contributes
  /// anywhere in the ball of radius `extra` around x. Many evaluations near one place (a
  /// point's refinement, a splat's corners) then skip the tree walk (EvaluateAmong).
  void Gather(const double* x, double extra, SPHCandidates& candidates) const;

  /// The field and its gradient at x from `candidates` (Gather's, for a ball that holds x).
  void EvaluateAmong(
    const SPHCandidates& candidates, const double* x, double& value, double* gradient) const;

  /// The samples whose support reaches within `extra` of the box [lower, upper]: every sample
  /// that contributes anywhere within `extra` of it, in the order ValueAt meets them. One walk of
  /// the hierarchy then serves a group of points near each other: at each, ValueAmong and
  /// EvaluateAmong over these give ValueAt's and Gather's numbers, to the bit (a few candidates
  /// more to skip).
  void GatherForBox(
    const double lower[3], const double upper[3], double extra, SPHCandidates& candidates) const;

  /// Gather(x, extra)'s samples, in its order, taken from `from` (GatherForBox's, for a box
  /// that holds x, with at least that extra): a walk of the hierarchy for a group of points,
  /// then a pass over its candidates for each.
  static void GatherAmong(
    const SPHCandidates& from, const double* x, double extra, SPHCandidates& candidates);

  /// The field alone at x from `candidates` (GatherForBox's or Gather's, for a region that holds
  /// x): ValueAt's value, to the bit.
  double ValueAmong(const SPHCandidates& candidates, const double* x) const;

  /// Calls visit(sample, weight) for every sample j whose support holds x, with weight
  /// (m_j / rho_j) W(|x - x_j|, H_j): the interpolation weights of any array.
  template <typename Visit>
  void ForEachWeight(const double* x, Visit&& visit) const;

  /// The samples whose support reaches the box [lower, upper], in ForEachWeight's order (one
  /// walk of the hierarchy for a group of points near each other; GatherForBox's, as indices).
  void SamplesReaching(
    const double lower[3], const double upper[3], std::vector<std::uint32_t>& samples) const;
  /// The end of the group of consecutive samples (storage order) from `first` (before `end`)
  /// that one walk serves: GroupEnd within the first one's support. Their box into lower, upper.
  std::size_t SampleGroupEnd(
    std::size_t first, std::size_t end, double lower[3], double upper[3]) const;
  /// ForEachWeight(x, visit) over `samples` (SamplesReaching's, for a box that holds x): the
  /// same weights in the same order.
  template <typename Visit>
  void ForEachWeightAmong(
    const std::vector<std::uint32_t>& samples, const double* x, Visit&& visit) const;

  /// Particles whose stored density was not positive and finite, so summed from the masses.
  std::size_t SummedDensities = 0;

  /// The support radius H_j of sample j (storage order).
  double Support(std::size_t j) const { return this->H[j]; }

  /// The kernel sums of the masses at sample i: in i's own support (gather,
  /// sum_j m_j W(r_ij, H_i), the density most codes store) and in each neighbour's (scatter,
  /// sum_j m_j W(r_ij, H_j), this field's density at x_i). massOf(j): sample j's mass.
  template <typename MassOf>
  void KernelSumsAt(std::size_t i, MassOf&& massOf, double& gather, double& scatter) const;

private:
  struct Node
  {
    double Lower[3], Upper[3];
    double MaximumSupport;
    std::uint32_t Begin, End; // samples [Begin, End) in storage order
    std::uint32_t Left = 0;   // children Left and Left + 1; 0: a leaf
  };
  // Fills Nodes[index] for samples [begin, end), and its subtree.
  void Build(std::uint32_t index, std::uint32_t begin, std::uint32_t end);
  template <typename Visit>
  void ForEachSupportHolding(const double* x, Visit&& visit, double extra = 0.0) const;
  // Visits (at least) every sample closer than `radius` to x, whatever its support: the
  // samples of the leaves within that radius.
  template <typename Visit>
  void ForEachSampleNear(const double* x, double radius, Visit&& visit) const;
  // Visits the samples of every leaf within reachOf(node) of x, entering each node within its
  // reach (the walk of the two above).
  template <typename ReachOf, typename Visit>
  void ForEachSampleOfLeavesNear(const double* x, ReachOf&& reachOf, Visit&& visit) const;
  // Visits every sample whose support reaches within `extra` of the box [lower, upper], in the
  // order ForEachSupportHolding meets them: the same walk, entering a node when the box lies
  // within its largest support plus `extra`.
  template <typename Visit>
  void ForEachSupportReaching(
    const double lower[3], const double upper[3], double extra, Visit&& visit) const;
  // The density at samples [begin, end) (storage order, within the box [lower, upper]) by
  // summation over `mass`, into rho.
  void SumDensities(const std::vector<double>& mass, std::size_t begin, std::size_t end,
    const double lower[3], const double upper[3], double* rho,
    std::vector<std::uint32_t>& scratch) const;

  const Neighborhoods& Geometry;
  SPHKernel Kernel;
  std::vector<double> H;           // support radius per sample
  std::vector<double> Coefficient; // m_j (density) or (m_j / rho_j) f_j
  std::vector<double> Volume;      // m_j / rho_j
  std::vector<Node> Nodes;         // a bounding-volume hierarchy over storage order
  bool IsValid = false;
};

template <typename ReachOf, typename Visit>
void SPHField::ForEachSampleOfLeavesNear(const double* x, ReachOf&& reachOf, Visit&& visit) const
{
  // The storage order is the kd-tree's leaf order, so contiguous ranges are compact boxes.
  std::uint32_t stack[64];
  int top = 0;
  stack[top++] = 0;
  while (top > 0)
  {
    const Node& node = this->Nodes[stack[--top]];
    double d2 = 0.0;
    for (int k = 0; k < 3; ++k)
    {
      const double outside = std::max(node.Lower[k] - x[k], x[k] - node.Upper[k]);
      d2 += outside > 0.0 ? outside * outside : 0.0;
    }
    const double reach = reachOf(node);
    if (!(d2 < reach * reach))
    {
      continue;
    }
    if (node.Left == 0)
    {
      for (std::uint32_t j = node.Begin; j < node.End; ++j)
      {
        visit(j);
      }
      continue;
    }
    stack[top++] = node.Left;
    stack[top++] = node.Left + 1;
  }
}

template <typename Visit>
void SPHField::ForEachSupportHolding(const double* x, Visit&& visit, double extra) const
{
  // A node is entered when x is within the largest support of its samples.
  this->ForEachSampleOfLeavesNear(
    x, [extra](const Node& node) { return node.MaximumSupport + extra; }, visit);
}

template <typename Visit>
void SPHField::ForEachSampleNear(const double* x, double radius, Visit&& visit) const
{
  this->ForEachSampleOfLeavesNear(
    x, [radius](const Node&) { return radius; }, visit);
}

template <typename Visit>
void SPHField::ForEachSupportReaching(
  const double lower[3], const double upper[3], double extra, Visit&& visit) const
{
  // The squared distance between a box and the query box, per axis the gap between them.
  auto gap2 = [&](const double* low, const double* high) {
    double d2 = 0.0;
    for (int k = 0; k < 3; ++k)
    {
      const double gap = std::max(low[k] - upper[k], lower[k] - high[k]);
      d2 += gap > 0.0 ? gap * gap : 0.0;
    }
    return d2;
  };
  // (A billionth wider than the supports: whatever the rounding of a distance, every sample
  // that weighs anything at a point of the box is visited.)
  constexpr double Wider = 1.0 + 1e-9;
  std::uint32_t stack[64];
  int top = 0;
  stack[top++] = 0;
  while (top > 0)
  {
    const Node& node = this->Nodes[stack[--top]];
    const double reach = node.MaximumSupport + extra;
    if (!(gap2(node.Lower, node.Upper) < Wider * reach * reach))
    {
      continue;
    }
    if (node.Left == 0)
    {
      for (std::uint32_t j = node.Begin; j < node.End; ++j)
      {
        const double* xj = this->Geometry.Position(j);
        const double own = this->H[j] + extra;
        if (gap2(xj, xj) < Wider * own * own)
        {
          visit(j);
        }
      }
      continue;
    }
    stack[top++] = node.Left;
    stack[top++] = node.Left + 1;
  }
}

template <typename Visit>
void SPHField::ForEachWeight(const double* x, Visit&& visit) const
{
  this->ForEachSupportHolding(x, [&](std::uint32_t j) {
    const double* xj = this->Geometry.Position(j);
    const double d[3] = { x[0] - xj[0], x[1] - xj[1], x[2] - xj[2] };
    const double r = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    if (r < this->H[j])
    {
      visit(j, this->Volume[j] * SPHKernelValue(this->Kernel, r, this->H[j]));
    }
  });
}

template <typename Visit>
void SPHField::ForEachWeightAmong(
  const std::vector<std::uint32_t>& samples, const double* x, Visit&& visit) const
{
  for (const std::uint32_t j : samples)
  {
    // (ForEachWeight's test and weight, to the bit.)
    const double* xj = this->Geometry.Position(j);
    const double d[3] = { x[0] - xj[0], x[1] - xj[1], x[2] - xj[2] };
    const double r = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    if (r < this->H[j])
    {
      visit(j, this->Volume[j] * SPHKernelValue(this->Kernel, r, this->H[j]));
    }
  }
}

template <typename MassOf>
void SPHField::KernelSumsAt(std::size_t i, MassOf&& massOf, double& gather, double& scatter) const
{
  gather = scatter = 0.0;
  const double* xi = this->Geometry.Position(i);
  const double own = this->H[i];
  auto distance = [&](std::uint32_t j) {
    const double* xj = this->Geometry.Position(j);
    const double d[3] = { xi[0] - xj[0], xi[1] - xj[1], xi[2] - xj[2] };
    return std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
  };
  // Two walks, each over about one support's ball (one walk for both would search a ball of
  // H_i + H_j: eight times the volume).
  this->ForEachSupportHolding(xi, [&](std::uint32_t j) {
    const double r = distance(j);
    scatter += r < this->H[j] ? massOf(j) * SPHKernelValue(this->Kernel, r, this->H[j]) : 0.0;
  });
  this->ForEachSampleNear(xi, own, [&](std::uint32_t j) {
    const double r = distance(j);
    gather += r < own ? massOf(j) * SPHKernelValue(this->Kernel, r, own) : 0.0;
  });
}

/// Moves p along the line with `direction` (unit, out of f > f_iso) onto the field's level
/// `isoValue`, no further than `reach` (IsopointRefinement.h's SolveOnLine, to `tolerance`),
/// evaluating among `candidates` (gathered around the start for at least that reach). On success
/// `normal` is the field's unit normal there, out of f > f_iso; false leaves p unchanged.
bool SolveOntoLevel(const SPHField& field, const SPHCandidates& candidates, double isoValue,
  Eigen::Vector3d& p, const Eigen::Vector3d& direction, double reach, double tolerance,
  Eigen::Vector3d& normal, bool newtonOnly = false);

/// SolveOntoLevel within `reach`, to 1e-9 of it, gathering its own candidates: first those for a
/// quarter of the reach, with Newton's steps only; then, if those leave that quarter or do not
/// converge, those for the whole reach, as SolveOntoLevel does. Most points lie a small fraction
/// of the reach from the level, and the small gather holds every sample that contributes
/// within its quarter, in the same order: the same steps give the same point to the bit, from
/// a quarter of the candidates (at reach = one support: a ball of 1.25 supports, not 2).
/// `group`, if given, holds GatherForBox's candidates for a box that holds p, at least
/// NearGatherExtra(reach) wide: the small gather is then taken from them (GatherAmong).
bool GatherAndSolveOntoLevel(const SPHField& field, double isoValue, Eigen::Vector3d& p,
  const Eigen::Vector3d& direction, double reach, SPHCandidates& candidates,
  Eigen::Vector3d& normal, const SPHCandidates* group = nullptr);

/// How far around a point GatherAndSolveOntoLevel's small gather reaches, for `reach`.
inline double NearGatherExtra(double reach)
{
  // (A millionth wider: a direction a rounding off unit length moves a little further.)
  return 1.000001 * (0.25 * reach);
}

/// The end of the group of consecutive points of `points` (3 doubles each) that starts at
/// `first`: at most `most` of them, before `end`, while their box stays within `limit` on every
/// side (at least the first), so that one walk of the field's hierarchy serves them and its
/// gather stays local where consecutive points jump (at the seams of the spatial order).
/// Their box into lower, upper.
std::size_t GroupEnd(const double* points, std::size_t first, std::size_t end, std::size_t most,
  double limit, double lower[3], double upper[3]);

/// Consecutive surface points (near each other) whose small gathers one walk of the hierarchy
/// serves: at most SPHPointGroup::Most, within the first one's reach of each other.
struct SPHPointGroup
{
  static constexpr std::size_t Most = 16;
  std::size_t First = 0, Last = 0; // its points [First, Last)
  double Reaches[Most];
  SPHCandidates Candidates; // for GatherAndSolveOntoLevel at each (GatherForBox)
  /// Forms the group that starts at point i of `points` (up to `end`) unless i is in this
  /// one: reachOf(k) for each of its points k, in order (First already i), and the candidates
  /// for the widest.
  template <typename ReachOf>
  void Hold(
    const SPHField& field, const double* points, std::size_t i, std::size_t end, ReachOf&& reachOf)
  {
    if (i >= this->First && i < this->Last)
    {
      return;
    }
    this->First = i;
    this->Reaches[0] = reachOf(i);
    double lower[3], upper[3];
    this->Last = GroupEnd(points, i, end, Most, this->Reaches[0], lower, upper);
    double widest = this->Reaches[0];
    for (std::size_t k = i + 1; k < this->Last; ++k)
    {
      this->Reaches[k - i] = reachOf(k);
      widest = std::max(widest, this->Reaches[k - i]);
    }
    field.GatherForBox(lower, upper, NearGatherExtra(widest), this->Candidates);
  }
  double Reach(std::size_t i) const { return this->Reaches[i - this->First]; }
};

/// The SPH field at every sample (storage order) minus the isovalue, in parallel: the data's
/// sign at the samples as the field itself gives it. Returns false only when aborted.
bool SPHOffsetsAtSamples(const Neighborhoods& geometry, const SPHField& field, double isoValue,
  std::vector<double>& dataOffsets, const AbortCheck& aborted);

} // namespace lsi

#endif
