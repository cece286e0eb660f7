// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "LevelSetSPHField.h"

#include "IsopointRefinement.h"
#include "LevelSetParameters.h"
#include "LevelSetSplines.h"
#include "SmoothingLengthNames.h"

#include "vtkAbstractArray.h"
#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkPointData.h"
#include "vtkPointSet.h"
#include "vtkSMPTools.h"
#include "vtkStringArray.h"

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <type_traits>

namespace lsi
{
namespace
{
// Samples evaluated together (consecutive in storage order, so near each other, within the
// first one's support: GroupEnd): one walk of the tree gathers what reaches their box, which a
// few more candidates per sample repay.
constexpr std::size_t SPHSampleGroup = 32;

// The array named by the user, else by the marker, else by one of the usual names.
vtkDataArray* FindArray(vtkPointSet* input, const std::string& requested, const char* marker,
  std::initializer_list<const char*> usual, std::string& name)
{
  vtkPointData* data = input->GetPointData();
  name = !requested.empty() ? requested : MarkedArrayName(input, marker);
  if (!name.empty() || !requested.empty())
  {
    return data->GetArray(name.c_str());
  }
  for (const char* candidate : usual)
  {
    if (vtkDataArray* array = data->GetArray(candidate))
    {
      name = candidate;
      return array;
    }
  }
  return nullptr;
}

} // namespace

std::string MarkedArrayName(vtkDataObject* data, const char* marker)
{
  vtkFieldData* fields = data ? data->GetFieldData() : nullptr;
  auto* names = vtkStringArray::SafeDownCast(fields ? fields->GetAbstractArray(marker) : nullptr);
  return names && names->GetNumberOfValues() > 0 ? names->GetValue(0) : std::string();
}

vtkDataArray* MarkedMassArray(vtkPointSet* input, const std::string& requested)
{
  std::string name;
  vtkDataArray* array =
    FindArray(input, requested, "MassArray", { "Masses", "Mass", "mass" }, name);
  return array && array->GetNumberOfComponents() == 1 ? array : nullptr;
}

vtkDataArray* MarkedDensityArray(vtkPointSet* input, const std::string& requested)
{
  std::string name;
  vtkDataArray* array =
    FindArray(input, requested, "DensityArray", { "Density", "Densities", "rho" }, name);
  return array && array->GetNumberOfComponents() == 1 ? array : nullptr;
}

bool FindSPHArrays(vtkPointSet* input, vtkDataArray* scalars, const SPHFieldRequest& request,
  SPHFieldArrays& arrays, std::string& problem, std::string& choice)
{
  problem.clear();
  arrays = SPHFieldArrays();
  if (request.Model == 1)
  {
    choice = "Field: the MLS fit of the samples (Field is set to MLS).";
    return false;
  }
  std::string hName, mName, rhoName;
  arrays.SmoothingLength = FindArray(
    input, request.SmoothingLengthArray, "SmoothingLengthArray", UsualSmoothingLengthNames, hName);
  arrays.Mass =
    FindArray(input, request.MassArray, "MassArray", { "Masses", "Mass", "mass" }, mName);
  arrays.Density = FindArray(
    input, request.DensityArray, "DensityArray", { "Density", "Densities", "rho" }, rhoName);
  const vtkIdType n = input->GetNumberOfPoints();
  for (auto named : { std::make_pair(arrays.SmoothingLength, hName),
         std::make_pair(arrays.Mass, mName), std::make_pair(arrays.Density, rhoName) })
  {
    if (named.first &&
      (named.first->GetNumberOfComponents() != 1 || named.first->GetNumberOfTuples() != n))
    {
      problem = "The SPH array '" + named.second +
        "' must have one component and one value per point (" + std::to_string(n) + ").";
      return false;
    }
  }
  if (!arrays.SmoothingLength || !arrays.Mass)
  {
    const std::string missing = !arrays.SmoothingLength
      ? "no smoothing length array" + (hName.empty() ? std::string() : " '" + hName + "'")
      : "no mass array" + (mName.empty() ? std::string() : " '" + mName + "'");
    if (request.Model == 2)
    {
      problem = "Field is SPH, but the input has " + missing +
        ". Name the arrays (SmoothingLengthArray, MassArray), or compute them with Particle "
        "Density.";
      return false;
    }
    choice = "Field: the MLS fit of the samples (the input has " + missing + ").";
    return false;
  }
  arrays.ValuesAreDensity = arrays.Density &&
    (scalars == arrays.Density || (scalars && scalars->GetName() && rhoName == scalars->GetName()));
  if (request.Kernel > 0)
  {
    arrays.Kernel = static_cast<SPHKernel>(request.Kernel - 1);
  }
  else
  {
    // The marker a reader or Particle Density writes ("WendlandC4"; a snapshot's own name where
    // the reader knew no kernel by it, which warns here). None: the cubic spline of GADGET,
    // GIZMO and ChaNGa.
    const std::string marker = MarkedArrayName(input, "SPHKernel");
    if (!marker.empty() && !SPHKernelFromName(marker, arrays.Kernel))
    {
      arrays.UnknownKernel = marker;
    }
  }
  arrays.SupportPerSmoothingLength = request.SupportPerSmoothingLength;
  if (!(arrays.SupportPerSmoothingLength > 0.0))
  {
    vtkDataArray* marked = vtkDataArray::SafeDownCast(
      input->GetFieldData()->GetAbstractArray("SupportPerSmoothingLength"));
    // Without a marker: GADGET's convention (h is the support), or Gasoline's and ChaNGa's (2 h)
    // for the names they give h.
    arrays.SupportPerSmoothingLength = marked && marked->GetNumberOfTuples() > 0
      ? marked->GetTuple1(0)
      : SupportPerSmoothingLengthOfName(hName);
  }
  choice = std::string("Field: the SPH interpolant, ") + NamesOf(arrays.Kernel).Label +
    " kernel with support " + std::to_string(arrays.SupportPerSmoothingLength) + " x '" + hName +
    "', masses '" + mName + "', " +
    (arrays.ValuesAreDensity ? "the density summed from the masses."
        : arrays.Density     ? "volumes m / rho from '" + rhoName + "'."
                             : "volumes m / rho with rho summed from the masses.");
  return true;
}

SPHField::SPHField(const Neighborhoods& geometry, const SPHFieldArrays& arrays,
  const std::vector<double>& values, std::string& problem)
  : Geometry(geometry)
  , Kernel(arrays.Kernel)
{
  const std::size_t n = geometry.NumberOfSamples;
  this->H.resize(n);
  this->Coefficient.assign(n, 0.0);
  this->Volume.assign(n, 0.0);
  std::vector<double> mass(n);
  for (std::size_t j = 0; j < n; ++j)
  {
    const vtkIdType id = geometry.Order[j];
    this->H[j] = arrays.SupportPerSmoothingLength * arrays.SmoothingLength->GetTuple1(id);
    mass[j] = arrays.Mass->GetTuple1(id);
    if (!(this->H[j] > 0.0) || !std::isfinite(this->H[j]) || !(mass[j] >= 0.0) ||
      !std::isfinite(mass[j]))
    {
      problem = "Particle " + std::to_string(id) + " has smoothing length " +
        std::to_string(arrays.SmoothingLength->GetTuple1(id)) + " and mass " +
        std::to_string(mass[j]) +
        ": the SPH field needs positive finite smoothing lengths and non-negative masses.";
      return;
    }
  }
  if (n > 0)
  {
    this->Nodes.reserve(2 * (n / 8 + 1));
    this->Nodes.emplace_back();
    this->Build(0, 0, static_cast<std::uint32_t>(n));
  }
  // rho_j: stored, or summed here (the tree is ready) where none is stored or the stored one
  // is not positive and finite (real files hold zeros: boundary or placeholder particles).
  // In parallel, by groups of samples near each other (SampleGroupEnd), each group's
  // contributors gathered by one walk of the tree.
  std::vector<double> stored(n);
  for (std::size_t j = 0; j < n; ++j)
  {
    stored[j] = arrays.Density ? arrays.Density->GetTuple1(geometry.Order[j]) : 0.0;
  }
  auto summed = [&](std::size_t j) { return !(stored[j] > 0.0) || !std::isfinite(stored[j]); };
  vtkSMPTools::For(
    0, static_cast<vtkIdType>(n), BalancedGrain(n, 8192), [&](vtkIdType begin, vtkIdType end) {
      std::vector<std::uint32_t> scratch;
      double rho[SPHSampleGroup];
      for (std::size_t first = static_cast<std::size_t>(begin), last = first;
           first < static_cast<std::size_t>(end); first = last)
      {
        double lower[3], upper[3];
        last = this->SampleGroupEnd(first, static_cast<std::size_t>(end), lower, upper);
        bool any = false;
        for (std::size_t j = first; j < last && !any; ++j)
        {
          any = summed(j);
        }
        if (any)
        {
          this->SumDensities(mass, first, last, lower, upper, rho, scratch);
        }
        for (std::size_t j = first; j < last; ++j)
        {
          const double density = summed(j) ? rho[j - first] : stored[j];
          // A particle with no density at all (massless and alone) carries no volume.
          this->Volume[j] = density > 0.0 ? mass[j] / density : 0.0;
          this->Coefficient[j] =
            arrays.ValuesAreDensity ? mass[j] : this->Volume[j] * values[geometry.Order[j]];
        }
      }
    });
  if (arrays.Density)
  {
    for (std::size_t j = 0; j < n; ++j)
    {
      this->SummedDensities += summed(j) ? 1 : 0;
    }
  }
  this->IsValid = true;
}

void SPHField::SumDensities(const std::vector<double>& mass, std::size_t begin, std::size_t end,
  const double lower[3], const double upper[3], double* rho,
  std::vector<std::uint32_t>& scratch) const
{
  this->SamplesReaching(lower, upper, scratch);
  for (std::size_t j = begin; j < end; ++j)
  {
    // (The sum a walk from x_j alone makes: the same weights in the same order, and zeros.)
    const double* xj = this->Geometry.Position(j);
    double sum = 0.0;
    for (const std::uint32_t k : scratch)
    {
      const double* xk = this->Geometry.Position(k);
      const double r = std::sqrt((xj[0] - xk[0]) * (xj[0] - xk[0]) +
        (xj[1] - xk[1]) * (xj[1] - xk[1]) + (xj[2] - xk[2]) * (xj[2] - xk[2]));
      sum += mass[k] * SPHKernelValue(this->Kernel, r, this->H[k]);
    }
    rho[j - begin] = sum;
  }
}

void SPHField::Build(std::uint32_t index, std::uint32_t begin, std::uint32_t end)
{
  constexpr std::uint32_t leafSize = 8;
  this->Nodes[index].Begin = begin;
  this->Nodes[index].End = end;
  if (end - begin <= leafSize)
  {
    Node& leaf = this->Nodes[index];
    leaf.MaximumSupport = 0.0;
    for (int k = 0; k < 3; ++k)
    {
      leaf.Lower[k] = leaf.Upper[k] = this->Geometry.Position(begin)[k];
    }
    for (std::uint32_t j = begin; j < end; ++j)
    {
      for (int k = 0; k < 3; ++k)
      {
        leaf.Lower[k] = std::min(leaf.Lower[k], this->Geometry.Position(j)[k]);
        leaf.Upper[k] = std::max(leaf.Upper[k], this->Geometry.Position(j)[k]);
      }
      leaf.MaximumSupport = std::max(leaf.MaximumSupport, this->H[j]);
    }
    return;
  }
  // Children in two consecutive slots; Nodes may grow (and move) during the recursion.
  const std::uint32_t left = static_cast<std::uint32_t>(this->Nodes.size());
  this->Nodes.emplace_back();
  this->Nodes.emplace_back();
  const std::uint32_t middle = begin + (end - begin) / 2;
  this->Build(left, begin, middle);
  this->Build(left + 1, middle, end);
  Node& node = this->Nodes[index];
  const Node& a = this->Nodes[left];
  const Node& b = this->Nodes[left + 1];
  node.Left = left;
  for (int k = 0; k < 3; ++k)
  {
    node.Lower[k] = std::min(a.Lower[k], b.Lower[k]);
    node.Upper[k] = std::max(a.Upper[k], b.Upper[k]);
  }
  node.MaximumSupport = std::max(a.MaximumSupport, b.MaximumSupport);
}

void SPHField::Gather(const double* x, double extra, SPHCandidates& candidates) const
{
  candidates.Clear();
  this->ForEachSupportHolding(
    x,
    [&](std::uint32_t j) {
      const double* xj = this->Geometry.Position(j);
      const double reach = this->H[j] + extra;
      const double r2 = (x[0] - xj[0]) * (x[0] - xj[0]) + (x[1] - xj[1]) * (x[1] - xj[1]) +
        (x[2] - xj[2]) * (x[2] - xj[2]);
      if (r2 < reach * reach)
      {
        candidates.Add(xj, this->H[j], this->Coefficient[j]);
      }
    },
    extra);
}

namespace
{
// sum_j c_j W(|x - x_j|, H_j) and its gradient for kernel K over the particles that
// forEach(add) passes to add(xj, H, c): the one loop behind Evaluate, ValueAt and EvaluateAmong.
// Without the gradient (null) the value is the same sum, to the bit, for less work.
template <SPHKernel K, bool WithGradient, typename ForEach>
void SumKernels(ForEach&& forEach, const double* x, double& value, double* gradient)
{
  double v = 0.0, g0 = 0.0, g1 = 0.0, g2 = 0.0;
  forEach([&](const double* xj, double H, double c) {
    const double d0 = x[0] - xj[0], d1 = x[1] - xj[1], d2 = x[2] - xj[2];
    const double r2 = d0 * d0 + d1 * d1 + d2 * d2;
    if (!(r2 < H * H))
    {
      return;
    }
    const double r = std::sqrt(r2), inverse = 1.0 / H;
    double w, dw;
    KernelShape<K>(r * inverse, w, dw);
    const double scale = c * inverse * inverse * inverse;
    v += scale * w;
    if (WithGradient && r > 0.0)
    {
      const double slope = scale * inverse * dw / r;
      g0 += slope * d0;
      g1 += slope * d1;
      g2 += slope * d2;
    }
  });
  const double norm = Normalization<K>();
  value = norm * v;
  if (WithGradient)
  {
    gradient[0] = norm * g0;
    gradient[1] = norm * g1;
    gradient[2] = norm * g2;
  }
}

// SumKernels with the kernel chosen once, outside the loop; no gradient when it is null.
template <typename ForEach>
void SumKernels(
  SPHKernel kernel, ForEach&& forEach, const double* x, double& value, double* gradient)
{
  auto sum = [&](auto shape) {
    constexpr SPHKernel K = decltype(shape)::value;
    if (gradient)
    {
      SumKernels<K, true>(forEach, x, value, gradient);
    }
    else
    {
      SumKernels<K, false>(forEach, x, value, nullptr);
    }
  };
  switch (kernel)
  {
    case SPHKernel::QuinticSpline:
      sum(std::integral_constant<SPHKernel, SPHKernel::QuinticSpline>());
      break;
    case SPHKernel::WendlandC2:
      sum(std::integral_constant<SPHKernel, SPHKernel::WendlandC2>());
      break;
    case SPHKernel::QuarticSpline:
      sum(std::integral_constant<SPHKernel, SPHKernel::QuarticSpline>());
      break;
    case SPHKernel::WendlandC4:
      sum(std::integral_constant<SPHKernel, SPHKernel::WendlandC4>());
      break;
    case SPHKernel::WendlandC6:
      sum(std::integral_constant<SPHKernel, SPHKernel::WendlandC6>());
      break;
    default:
      sum(std::integral_constant<SPHKernel, SPHKernel::CubicSpline>());
  }
}
} // namespace

void SPHField::Evaluate(const double* x, double& value, double* gradient) const
{
  auto forEach = [&](auto&& add) {
    this->ForEachSupportHolding(x,
      [&](std::uint32_t j) { add(this->Geometry.Position(j), this->H[j], this->Coefficient[j]); });
  };
  SumKernels(this->Kernel, forEach, x, value, gradient);
}

double SPHField::ValueAt(const double* x) const
{
  auto forEach = [&](auto&& add) {
    this->ForEachSupportHolding(x,
      [&](std::uint32_t j) { add(this->Geometry.Position(j), this->H[j], this->Coefficient[j]); });
  };
  double value;
  SumKernels(this->Kernel, forEach, x, value, nullptr);
  return value;
}

void SPHField::EvaluateAmong(
  const SPHCandidates& candidates, const double* x, double& value, double* gradient) const
{
  auto forEach = [&](auto&& add) {
    for (std::size_t j = 0; j < candidates.X.size(); ++j)
    {
      const double xj[3] = { candidates.X[j], candidates.Y[j], candidates.Z[j] };
      add(xj, candidates.H[j], candidates.Coefficient[j]);
    }
  };
  SumKernels(this->Kernel, forEach, x, value, gradient);
}

void SPHField::GatherForBox(
  const double lower[3], const double upper[3], double extra, SPHCandidates& candidates) const
{
  candidates.Clear();
  this->ForEachSupportReaching(lower, upper, extra, [&](std::uint32_t j) {
    candidates.Add(this->Geometry.Position(j), this->H[j], this->Coefficient[j]);
  });
}

std::size_t SPHField::SampleGroupEnd(
  std::size_t first, std::size_t end, double lower[3], double upper[3]) const
{
  return GroupEnd(
    this->Geometry.Positions.data(), first, end, SPHSampleGroup, this->H[first], lower, upper);
}

void SPHField::SamplesReaching(
  const double lower[3], const double upper[3], std::vector<std::uint32_t>& samples) const
{
  samples.clear();
  this->ForEachSupportReaching(lower, upper, 0.0, [&](std::uint32_t j) { samples.push_back(j); });
}

void SPHField::GatherAmong(
  const SPHCandidates& from, const double* x, double extra, SPHCandidates& candidates)
{
  candidates.Clear();
  for (std::size_t j = 0; j < from.X.size(); ++j)
  {
    // (Gather's test, to the bit.)
    const double reach = from.H[j] + extra;
    const double r2 = (x[0] - from.X[j]) * (x[0] - from.X[j]) +
      (x[1] - from.Y[j]) * (x[1] - from.Y[j]) + (x[2] - from.Z[j]) * (x[2] - from.Z[j]);
    if (r2 < reach * reach)
    {
      const double xj[3] = { from.X[j], from.Y[j], from.Z[j] };
      candidates.Add(xj, from.H[j], from.Coefficient[j]);
    }
  }
}

double SPHField::ValueAmong(const SPHCandidates& candidates, const double* x) const
{
  auto forEach = [&](auto&& add) {
    for (std::size_t j = 0; j < candidates.X.size(); ++j)
    {
      const double xj[3] = { candidates.X[j], candidates.Y[j], candidates.Z[j] };
      add(xj, candidates.H[j], candidates.Coefficient[j]);
    }
  };
  double value;
  SumKernels(this->Kernel, forEach, x, value, nullptr);
  return value;
}

bool SolveOntoLevel(const SPHField& field, const SPHCandidates& candidates, double isoValue,
  Eigen::Vector3d& p, const Eigen::Vector3d& direction, double reach, double tolerance,
  Eigen::Vector3d& normal, bool newtonOnly)
{
  auto evaluate = [&](const Eigen::Vector3d& x, double& value, Eigen::Vector3d& g) {
    field.EvaluateAmong(candidates, x.data(), value, g.data());
    value -= isoValue;
    return std::isfinite(value);
  };
  Eigen::Vector3d gradient;
  Eigen::Vector3d q = p;
  if (!SolveOnLine(q, direction, evaluate, reach, tolerance, gradient, newtonOnly) ||
    !(gradient.squaredNorm() > 0.0))
  {
    return false;
  }
  p = q;
  normal = -gradient.normalized();
  return true;
}

std::size_t GroupEnd(const double* points, std::size_t first, std::size_t end, std::size_t most,
  double limit, double lower[3], double upper[3])
{
  for (int k = 0; k < 3; ++k)
  {
    lower[k] = upper[k] = points[3 * first + k];
  }
  std::size_t last = first + 1;
  for (; last < end && last - first < most; ++last)
  {
    const double* x = &points[3 * last];
    bool within = true;
    for (int k = 0; k < 3; ++k)
    {
      within = within && std::max(upper[k], x[k]) - std::min(lower[k], x[k]) <= limit;
    }
    if (!within)
    {
      break;
    }
    for (int k = 0; k < 3; ++k)
    {
      lower[k] = std::min(lower[k], x[k]);
      upper[k] = std::max(upper[k], x[k]);
    }
  }
  return last;
}

bool GatherAndSolveOntoLevel(const SPHField& field, double isoValue, Eigen::Vector3d& p,
  const Eigen::Vector3d& direction, double reach, SPHCandidates& candidates,
  Eigen::Vector3d& normal, const SPHCandidates* group)
{
  const double tolerance = 1e-9 * reach; // of the whole reach in both tries: the same steps
  const double nearReach = 0.25 * reach;
  if (group)
  {
    SPHField::GatherAmong(*group, p.data(), NearGatherExtra(reach), candidates);
  }
  else
  {
    field.Gather(p.data(), NearGatherExtra(reach), candidates);
  }
  if (SolveOntoLevel(field, candidates, isoValue, p, direction, nearReach, tolerance, normal, true))
  {
    return true;
  }
  field.Gather(p.data(), reach, candidates); // the point stays within the reach
  return SolveOntoLevel(field, candidates, isoValue, p, direction, reach, tolerance, normal);
}

bool SPHOffsetsAtSamples(const Neighborhoods& geometry, const SPHField& field, double isoValue,
  std::vector<double>& dataOffsets, const AbortCheck& aborted)
{
  const std::size_t n = geometry.NumberOfSamples;
  dataOffsets.resize(n);
  // By groups of samples near each other (consecutive in storage order), each group's
  // contributors gathered by one walk of the tree: ValueAt's numbers for a third of its time.
  return ParallelForInBlocks(
    n,
    [&](std::size_t begin, std::size_t end) {
      SPHCandidates candidates;
      for (std::size_t first = begin, last = begin; first < end; first = last)
      {
        double lower[3], upper[3];
        last = field.SampleGroupEnd(first, end, lower, upper);
        field.GatherForBox(lower, upper, 0.0, candidates);
        for (std::size_t j = first; j < last; ++j)
        {
          dataOffsets[j] = field.ValueAmong(candidates, geometry.Position(j)) - isoValue;
        }
      }
    },
    aborted, 8192);
}

} // namespace lsi
