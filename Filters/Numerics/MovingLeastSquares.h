// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
// Moving-least-squares linear fits (paper §4.2): g(x) ~ a . (x - c) + b around a centre c,
// weighted by w(d) = 1 - |d|^2 / h^2 (squared in the least-squares sum). The fit matrix depends
// only on positions, so it is turned once into a "stencil": per-neighbour coefficients that give
// the gradient a (and value b) as weighted sums of the neighbours' values.
// Plain C++/Eigen: unit-tested in Testing/Cxx/TestNumerics.cxx.
#ifndef MovingLeastSquares_h
#define MovingLeastSquares_h

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace lsi
{

/// The paper's MLS weight (before squaring) for a squared distance d2 and support radius h.
inline double MLSWeight(double d2, double h2)
{
  const double w = 1.0 - d2 / h2;
  return w > 0.0 ? w : 0.0;
}

/// Result of a linear fit around a centre: for each neighbour j, gradient coefficients
/// (3 values) and a value coefficient, so that grad g(c) = sum_j grad[j] g_j and
/// g(c) = sum_j value[j] g_j.
struct LinearStencilView
{
  double* Gradient; // 3 * count values, neighbour-major
  double* Value;    // count values, may be null
};

/// Whether the normal matrix of a weighted linear fit is regular: the weighted samples span 3D
/// when its determinant is not negligible against its trace scale to the fourth power (a cheap,
/// scale-free test, the basis being O(1)). False for NaN entries too.
inline bool RegularLinearNormal(const Eigen::Matrix4d& normal)
{
  const double scale = normal.trace() / 4.0;
  return scale > 0.0 && std::abs(normal.determinant()) >= 1e-10 * (scale * scale) * (scale * scale);
}

/// MLSWeight (support 1) of two samples at once, from their offsets in units of h (NaN: 0).
inline Eigen::Array2d PairWeight(
  const Eigen::Array2d& qx, const Eigen::Array2d& qy, const Eigen::Array2d& qz)
{
  const Eigen::Array2d r = 1.0 - (qx * qx + qy * qy + qz * qz);
  return (r > 0.0).select(r, 0.0);
}

/// The linear fits' loop over samples, two at a time in packed arithmetic (each lane computes
/// what scalar code would: the same bits): body(j, qx, qy, qz, both) with the offsets from
/// `centre` of samples j and j + 1, times invH. An odd count's last sample comes with a second
/// lane two supports away (weight zero) and `both` false: the body must not store that lane.
template <typename PositionFn, typename Body>
void ForEachSamplePair(
  const double centre[3], std::size_t count, PositionFn position, double invH, Body&& body)
{
  using Pair = Eigen::Array2d;
  std::size_t j = 0;
  for (; j + 1 < count; j += 2)
  {
    const double* a = position(j);
    const double* b = position(j + 1);
    body(j, Pair((a[0] - centre[0]) * invH, (b[0] - centre[0]) * invH),
      Pair((a[1] - centre[1]) * invH, (b[1] - centre[1]) * invH),
      Pair((a[2] - centre[2]) * invH, (b[2] - centre[2]) * invH), true);
  }
  if (j < count)
  {
    const double* a = position(j);
    body(j, Pair((a[0] - centre[0]) * invH, 2.0), Pair((a[1] - centre[1]) * invH, 0.0),
      Pair((a[2] - centre[2]) * invH, 0.0), false);
  }
}

/// The normal matrix of the weighted linear fit at `centre` over `count` samples, in units of
/// h; false when singular (RegularLinearNormal).
template <typename PositionFn>
bool LinearNormalMatrix(const double centre[3], std::size_t count, PositionFn position, double invH,
  Eigen::Matrix4d& normal)
{
  // The 10 distinct entries of the symmetric sum of w^2 q q^T, summed over pairs of samples
  // (this loop runs for every sample of every fit), each pair's two lanes added at the end.
  using Pair = Eigen::Array2d;
  Pair xx = Pair::Zero(), xy = Pair::Zero(), xz = Pair::Zero(), x1 = Pair::Zero(),
       yy = Pair::Zero(), yz = Pair::Zero(), y1 = Pair::Zero(), zz = Pair::Zero(),
       z1 = Pair::Zero(), w1 = Pair::Zero();
  ForEachSamplePair(centre, count, position, invH,
    [&](std::size_t, const Pair& qx, const Pair& qy, const Pair& qz, bool) {
      const Pair w = PairWeight(qx, qy, qz);
      const Pair w2 = w * w, wx = w2 * qx, wy = w2 * qy, wz = w2 * qz;
      xx += wx * qx;
      xy += wx * qy;
      xz += wx * qz;
      x1 += wx;
      yy += wy * qy;
      yz += wy * qz;
      y1 += wy;
      zz += wz * qz;
      z1 += wz;
      w1 += w2;
    });
  auto sum = [](const Pair& p) { return p[0] + p[1]; };
  normal << sum(xx), sum(xy), sum(xz), sum(x1), sum(xy), sum(yy), sum(yz), sum(y1), sum(xz),
    sum(yz), sum(zz), sum(z1), sum(x1), sum(y1), sum(z1), sum(w1);
  return RegularLinearNormal(normal);
}

/// Builds the stencil of a weighted linear fit around `centre` from `count` neighbour positions
/// (each a pointer to 3 doubles, given by `position(j)`) with support radius h. Coordinates are
/// centred and scaled by 1/h before fitting, for conditioning. Returns false when the fit is
/// singular (fewer than four weighted points in general position: duplicate, collinear or
/// coplanar neighbourhoods); the stencil is then left zero.
template <typename PositionFn>
bool BuildLinearStencil(
  const double centre[3], std::size_t count, PositionFn position, double h, LinearStencilView out)
{
  using Matrix4 = Eigen::Matrix4d;
  for (std::size_t j = 0; j < 3 * count; ++j)
  {
    out.Gradient[j] = 0.0;
  }
  if (out.Value)
  {
    for (std::size_t j = 0; j < count; ++j)
    {
      out.Value[j] = 0.0;
    }
  }
  if (!(h > 0.0) || !std::isfinite(h))
  {
    return false;
  }
  const double invH = 1.0 / h;
  Matrix4 normal;
  if (!LinearNormalMatrix(centre, count, position, invH, normal))
  {
    return false;
  }
  const Matrix4 inverse = normal.inverse();
  // In the order of Eigen's product: the same bits as it.
  using Pair = Eigen::Array2d;
  ForEachSamplePair(centre, count, position, invH,
    [&](std::size_t j, const Pair& qx, const Pair& qy, const Pair& qz, bool both) {
      const Pair w = PairWeight(qx, qy, qz);
      const Pair w2 = w * w;
      const Pair v[4] = { w2 * qx, w2 * qy, w2 * qz, w2 };
      Pair c[4];
      for (int row = 0; row < 4; ++row)
      {
        c[row] = ((inverse(row, 0) * v[0] + inverse(row, 1) * v[1]) + inverse(row, 2) * v[2]) +
          inverse(row, 3) * v[3];
      }
      for (int lane = 0; lane < (both ? 2 : 1); ++lane)
      {
        // The fit is in scaled coordinates: d/dx = (1/h) d/dq.
        out.Gradient[3 * (j + lane) + 0] = c[0][lane] * invH;
        out.Gradient[3 * (j + lane) + 1] = c[1][lane] * invH;
        out.Gradient[3 * (j + lane) + 2] = c[2][lane] * invH;
        if (out.Value)
        {
          out.Value[j + lane] = c[3][lane];
        }
      }
    });
  return true;
}

/// The value weights alone of BuildLinearStencil's fit (`weights`: count values), for
/// interpolating fields at `centre`: the last row of the normal matrix's inverse applied to each
/// sample, a quarter of the stencil's work. False (weights zero) when the fit is singular.
template <typename PositionFn>
bool LinearValueWeights(
  const double centre[3], std::size_t count, PositionFn position, double h, double* weights)
{
  std::fill(weights, weights + count, 0.0);
  if (!(h > 0.0) || !std::isfinite(h))
  {
    return false;
  }
  const double invH = 1.0 / h;
  Eigen::Matrix4d normal;
  if (!LinearNormalMatrix(centre, count, position, invH, normal))
  {
    return false;
  }
  const Eigen::Vector4d last = normal.inverse().row(3).transpose();
  const double l0 = last[0], l1 = last[1], l2 = last[2], l3 = last[3];
  // Not through a Vector4d per sample, which went through the stack. (The dot product's order
  // is Eigen's.)
  using Pair = Eigen::Array2d;
  ForEachSamplePair(centre, count, position, invH,
    [&](std::size_t j, const Pair& qx, const Pair& qy, const Pair& qz, bool both) {
      const Pair w = PairWeight(qx, qy, qz);
      const Pair weight = (w * w) * ((l0 * qx + l2 * qz) + (l1 * qy + l3));
      weights[j] = weight[0];
      if (both)
      {
        weights[j + 1] = weight[1];
      }
    });
  return true;
}

/// The same weighted linear fit for one field only: its value and gradient at `centre`, from
/// the normal equations with the values on the right (one 4x4 solve, where a stencil applies
/// the inverse to every neighbour). Equal to the stencil's sums up to rounding. False (value
/// and gradient zero) when the fit is singular, as BuildLinearStencil.
template <typename PositionFn, typename ValueFn>
bool FitLinear(const double centre[3], std::size_t count, PositionFn position, ValueFn value,
  double h, double& fitted, Eigen::Vector3d& gradient)
{
  fitted = 0.0;
  gradient.setZero();
  if (!(h > 0.0) || !std::isfinite(h))
  {
    return false;
  }
  const double invH = 1.0 / h;
  // The sums of w^2 q q^T and of w^2 q f in plain arrays, entry by entry as Eigen's outer
  // product sums them (the same bits), without a Vector4d per sample: built through the stack,
  // reading it back whole stalled on every sample.
  alignas(16) double sums[4][4] = {}; // sums[c][r]: column-major, as Matrix4d
  alignas(16) double rightSums[4] = {};
  for (std::size_t j = 0; j < count; ++j)
  {
    const double* x = position(j);
    alignas(16) const double q[4] = { (x[0] - centre[0]) * invH, (x[1] - centre[1]) * invH,
      (x[2] - centre[2]) * invH, 1.0 };
    const double w = MLSWeight(q[0] * q[0] + q[1] * q[1] + q[2] * q[2], 1.0);
    const double w2 = w * w;
    alignas(16) const double weighted[4] = { w2 * q[0], w2 * q[1], w2 * q[2], w2 * q[3] };
    const double f = value(j);
    for (int c = 0; c < 4; ++c)
    {
      for (int r = 0; r < 4; ++r)
      {
        sums[c][r] += weighted[r] * q[c];
      }
      rightSums[c] += weighted[c] * f;
    }
  }
  const Eigen::Matrix4d normal = Eigen::Map<const Eigen::Matrix4d>(&sums[0][0]);
  const Eigen::Vector4d right = Eigen::Map<const Eigen::Vector4d>(rightSums);
  if (!RegularLinearNormal(normal))
  {
    return false;
  }
  const Eigen::Vector4d c = normal.inverse() * right;
  gradient = c.head<3>() * invH; // the fit is in scaled coordinates
  fitted = c[3];
  return true;
}

/// Solves A x = b for a symmetric positive definite A given by its lower triangle, by LDL^T
/// without pivoting. False (x unset) when a pivot is not positive or is below `relative` times
/// the largest: the matrix is singular or too ill-conditioned for the solve to mean anything.
template <int N>
bool SolveSymmetricDefinite(const Eigen::Matrix<double, N, N>& a,
  const Eigen::Matrix<double, N, 1>& b, double relative, Eigen::Matrix<double, N, 1>& x)
{
  // (Its loops unrolled, their bounds being known at compile time: the quadratic fit ran 5-10%
  // faster in LevelSetKernels.)
  double l[N][N]; // l[i][k], k < i: the unit lower factor; l[i][i]: pivot i
  double largest = 0.0, smallest = HUGE_VAL;
#pragma GCC unroll 10
  for (int j = 0; j < N; ++j)
  {
    double dj = a(j, j);
    double ld[N]; // l[j][k] * d_k
#pragma GCC unroll 10
    for (int k = 0; k < j; ++k)
    {
      ld[k] = l[j][k] * l[k][k];
      dj -= l[j][k] * ld[k];
    }
    if (!(dj > 0.0))
    {
      return false;
    }
    l[j][j] = dj;
    largest = std::max(largest, dj);
    smallest = std::min(smallest, dj);
#pragma GCC unroll 10
    for (int i = j + 1; i < N; ++i)
    {
      double sum = a(i, j);
#pragma GCC unroll 10
      for (int k = 0; k < j; ++k)
      {
        sum -= l[i][k] * ld[k];
      }
      l[i][j] = sum / dj;
    }
  }
  if (!(smallest >= relative * largest))
  {
    return false;
  }
  for (int i = 0; i < N; ++i) // L y = b
  {
    double sum = b[i];
    for (int k = 0; k < i; ++k)
    {
      sum -= l[i][k] * x[k];
    }
    x[i] = sum;
  }
  for (int i = N - 1; i >= 0; --i) // D L^T x = y
  {
    double sum = x[i] / l[i][i];
    for (int k = i + 1; k < N; ++k)
    {
      sum -= l[k][i] * x[k];
    }
    x[i] = sum;
  }
  return true;
}

/// Adds weight u^a v^b w^c to sums[a][b][c] for every a + b + c up to Degree, from the powers
/// of u, v and w (`pu[e]` = u^e, ...), for a pair of samples at once (FitLinearOrQuadratic's
/// moments). The products are shared along a, then b.
template <int Degree>
inline void AddMoments(Eigen::Array2d (&sums)[Degree + 1][Degree + 1][Degree + 1],
  const Eigen::Array2d& weight, const Eigen::Array2d* pu, const Eigen::Array2d* pv,
  const Eigen::Array2d* pw)
{
#pragma GCC unroll 5
  for (int a = 0; a <= Degree; ++a)
  {
    const Eigen::Array2d wa = weight * pu[a];
#pragma GCC unroll 5
    for (int b = 0; a + b <= Degree; ++b)
    {
      const Eigen::Array2d wab = wa * pv[b];
#pragma GCC unroll 5
      for (int c = 0; a + b + c <= Degree; ++c)
      {
        sums[a][b][c] += wab * pw[c];
      }
    }
  }
}

/// The weighted least-squares fit of per-sample values around `centre` that the data support:
/// quadratic (basis 1, x, y, z and the six second-order monomials, in coordinates centred and
/// scaled by 1/h; the linear fit's weights) where its six second-order terms explain
/// significantly more than noise would, by an F test against the quadratic fit's residual at
/// `criticalF`; linear where they do not (noisy data: a quadratic would follow the noise) or
/// where the quadratic is ill-posed (fewer than 16 effective samples, or a normal matrix whose
/// smallest LDL^T pivot is below 1e-7 of its largest). A quadratic fit is exact for quadratic
/// fields, so the zero it places carries no bias from the field's curvature. Gives the value and
/// gradient at the centre, and whether the quadratic was used; and the Hessian, if asked for
/// (zero for the linear fit). False if even the linear fit is singular.
template <typename PositionFn, typename ValueFn>
bool FitLinearOrQuadratic(const double centre[3], std::size_t count, PositionFn position,
  ValueFn value, double h, double criticalF, double& fitted, Eigen::Vector3d& gradient,
  bool& quadratic, Eigen::Matrix3d* hessian = nullptr)
{
  using Vector10 = Eigen::Matrix<double, 10, 1>;
  using Matrix10 = Eigen::Matrix<double, 10, 10>;
  quadratic = false;
  if (!(h > 0.0) || !std::isfinite(h) || count < 4)
  {
    return false;
  }
  const double invH = 1.0 / h;
  // Each sample's offsets (u, v, w), weight and value, in columns (per thread, reused), padded
  // to an even count: the sums below take the samples in pairs, in packed arithmetic.
  thread_local std::vector<double> table;
  const std::size_t padded = (count + 1) & ~std::size_t(1);
  table.resize(5 * padded);
  double* const U = table.data();
  double* const V = U + padded;
  double* const W = V + padded;
  double* const Weight = W + padded;
  double* const Value = Weight + padded;
  for (std::size_t j = 0; j < count; ++j)
  {
    const double* x = position(j);
    U[j] = (x[0] - centre[0]) * invH;
    V[j] = (x[1] - centre[1]) * invH;
    W[j] = (x[2] - centre[2]) * invH;
    const double m = MLSWeight(U[j] * U[j] + V[j] * V[j] + W[j] * W[j], 1.0);
    Weight[j] = m * m;
    Value[j] = value(j);
  }
  for (std::size_t j = count; j < padded; ++j) // (a copy of the last sample, without weight)
  {
    U[j] = U[j - 1];
    V[j] = V[j - 1];
    W[j] = W[j - 1];
    Value[j] = Value[j - 1];
    Weight[j] = 0.0;
  }
  // The normal matrix's entries are weighted moments: sum weight u^a v^b w^c with a + b + c up
  // to 4 (35 of them for its 55 distinct entries), and the right side's sum weight f u^a v^b w^c
  // up to 2. Summed per lane of a pair of samples (AddMoments), the lanes added at the end.
  using Pair = Eigen::Array2d;
  using Column = Eigen::Map<const Pair>; // a pair of samples' entries of one column
  Pair moments[5][5][5], rightMoments[3][3][3], squaredWeights = Pair::Zero();
  std::fill_n(&moments[0][0][0], 125, Pair::Zero());
  std::fill_n(&rightMoments[0][0][0], 27, Pair::Zero());
  for (std::size_t j = 0; j < padded; j += 2)
  {
    const Pair u = Column(U + j), v = Column(V + j), w = Column(W + j);
    const Pair weight = Column(Weight + j), weightedValue = weight * Column(Value + j);
    Pair pu[5], pv[5], pw[5];
    pu[0] = pv[0] = pw[0] = Pair::Ones();
#pragma GCC unroll 4
    for (int e = 1; e < 5; ++e)
    {
      pu[e] = pu[e - 1] * u;
      pv[e] = pv[e - 1] * v;
      pw[e] = pw[e - 1] * w;
    }
    AddMoments<4>(moments, weight, pu, pv, pw);
    AddMoments<2>(rightMoments, weightedValue, pu, pv, pw);
    squaredWeights += weight * weight;
  }
  // The basis 1, u, v, w, u^2, v^2, w^2, uv, uw, vw as exponents of u, v and w.
  static constexpr int Exponents[10][3] = { { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 },
    { 2, 0, 0 }, { 0, 2, 0 }, { 0, 0, 2 }, { 1, 1, 0 }, { 1, 0, 1 }, { 0, 1, 1 } };
  Matrix10 normal;
  Vector10 right;
  for (int r = 0; r < 10; ++r)
  {
    const int* er = Exponents[r];
    right[r] = rightMoments[er[0]][er[1]][er[2]].sum();
    for (int c = 0; c <= r; ++c)
    {
      const int* ec = Exponents[c];
      normal(r, c) = normal(c, r) = moments[er[0] + ec[0]][er[1] + ec[1]][er[2] + ec[2]].sum();
    }
  }
  const double sumWeights = normal(0, 0), sumSquaredWeights = squaredWeights.sum();
  // The linear fit: the leading 4 x 4 block.
  const Eigen::Matrix4d linearNormal = normal.topLeftCorner<4, 4>().selfadjointView<Eigen::Lower>();
  if (!RegularLinearNormal(linearNormal))
  {
    return false;
  }
  Vector10 coefficients = Vector10::Zero();
  coefficients.head<4>() = linearNormal.ldlt().solve(right.head<4>());
  const double samples = sumWeights * sumWeights / sumSquaredWeights; // effective count
  if (samples >= 16.0)
  {
    // LDL^T without pivoting (the normal matrix is positive semi-definite: pivoting adds no
    // stability; Eigen's pivoted LDLT was a sixth of the fit's time); its pivots' spread
    // measures the conditioning.
    Vector10 full;
    if (SolveSymmetricDefinite(normal, right, 1e-7, full))
    {
      Pair linearResidual = Pair::Zero(), quadraticResidual = Pair::Zero();
      const Vector10& q = full;
      for (std::size_t j = 0; j < padded; j += 2)
      {
        const Pair u = Column(U + j), v = Column(V + j), w = Column(W + j), f = Column(Value + j);
        const Pair weight = Column(Weight + j);
        const Pair linear =
          f - (coefficients[0] + coefficients[1] * u + coefficients[2] * v + coefficients[3] * w);
        const Pair quadraticPart = f -
          (q[0] + q[1] * u + q[2] * v + q[3] * w + q[4] * u * u + q[5] * v * v + q[6] * w * w +
            q[7] * u * v + q[8] * u * w + q[9] * v * w);
        linearResidual += weight * linear * linear;
        quadraticResidual += weight * quadraticPart * quadraticPart;
      }
      // F = (reduction per added term) / (residual per remaining degree of freedom).
      const double reduction = linearResidual.sum() - quadraticResidual.sum();
      quadratic = reduction > criticalF * 6.0 * quadraticResidual.sum() / (samples - 10.0);
      if (quadratic)
      {
        coefficients = full;
      }
    }
  }
  fitted = coefficients[0];
  gradient = coefficients.segment<3>(1) * invH;
  if (hessian) // of c4 u^2 + c5 v^2 + c6 w^2 + c7 uv + c8 uw + c9 vw, in x = centre + h u
  {
    const Eigen::Matrix<double, 10, 1>& c = coefficients;
    *hessian << 2.0 * c[4], c[7], c[8], c[7], 2.0 * c[5], c[9], c[8], c[9], 2.0 * c[6];
    *hessian *= invH * invH;
  }
  return true;
}

/// Applies a gradient stencil (3 coefficients per neighbour, stored as T) to neighbour values.
template <typename T, typename ValueFn>
Eigen::Vector3d ApplyGradientStencil(const T* stencil, std::size_t count, ValueFn value)
{
  Eigen::Vector3d g = Eigen::Vector3d::Zero();
  for (std::size_t j = 0; j < count; ++j)
  {
    const double v = value(j);
    g[0] += stencil[3 * j + 0] * v;
    g[1] += stencil[3 * j + 1] * v;
    g[2] += stencil[3 * j + 2] * v;
  }
  return g;
}

/// Divergence of a vector field from a gradient stencil: sum_j stencil_j . V_j (DEM variant).
template <typename T, typename VectorFn>
double ApplyDivergenceStencil(const T* stencil, std::size_t count, VectorFn vector)
{
  double div = 0.0;
  for (std::size_t j = 0; j < count; ++j)
  {
    const Eigen::Vector3d v = vector(j);
    div += stencil[3 * j + 0] * v[0] + stencil[3 * j + 1] * v[1] + stencil[3 * j + 2] * v[2];
  }
  return div;
}

} // namespace lsi

#endif
