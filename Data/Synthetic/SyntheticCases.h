// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
// The analytic test cases: the paper's one-component field (§8.2), a multi-component field of
// our own (§8.3 leaves its formula out), an adaptive noisy cloud, a snaking tube and a sphere. Each
// knows its value and gradient everywhere, so the exact isosurface is known. Used by the data
// generator, the tests and the benchmark (plain C++/Eigen).
#ifndef SyntheticCases_h
#define SyntheticCases_h

#include <Eigen/Dense>

#include <array>
#include <cmath>
#include <cstdint>
#include <memory>
#include <random>
#include <string>
#include <vector>

namespace lsi
{
namespace cases
{

struct Sphere3
{
  Eigen::Vector3d Center;
  double Radius;
};

struct Case
{
  std::string Name;
  double IsoValue = 0.0;
  Eigen::Vector3d BoxMin{ 0, 0, 0 }, BoxMax{ 128, 128, 128 };
  std::vector<Sphere3> Seeds;    // main seed first
  double CurvatureWeight = 0.05; // lambda used by the case (the paper's for its own runs)
  virtual ~Case() = default;
  virtual double Value(const Eigen::Vector3d& x) const = 0;
  virtual Eigen::Vector3d Gradient(const Eigen::Vector3d& x) const = 0;
  /// Which component of {f > iso} a point near the surface belongs to (0 if only one).
  virtual int Component(const Eigen::Vector3d&) const { return 0; }
  /// Whether that component meets the seeds (and so must be extracted).
  virtual bool Seeded(int component) const { return component == 0; }
  /// `count` sample positions (default: uniform in the box; deterministic for a given seed).
  virtual std::vector<Eigen::Vector3d> Samples(std::size_t count, std::uint64_t seed) const;
  /// The value a sample carries (default: exact; a noisy case perturbs it).
  virtual double MeasuredValue(const Eigen::Vector3d& x, std::mt19937_64&) const
  {
    return this->Value(x);
  }
  /// Mean sample spacing on the exact surface for `count` samples (default: uniform).
  virtual double SurfaceSpacing(std::size_t count) const
  {
    return std::cbrt((this->BoxMax - this->BoxMin).prod() / static_cast<double>(count));
  }
};

/// Paper §8.2: f = -((a x + 0.05 (a y)^3)^2 + 0.7 (a y)^2 + 0.3 (a z - 0.7 (a y)^2)^2 - 4) / a^2,
/// a = 0.1, in coordinates centred so that the surface (about 54 x 48 x 113) fits in
/// [0, 128]^3; isovalue 0; a sphere seed inside the object.
struct OneComponentCase : Case
{
  static constexpr double A = 0.1;
  Eigen::Vector3d Origin{ 64.0, 64.0, 44.0 };
  OneComponentCase()
  {
    this->Name = "one-component";
    this->IsoValue = 0.0;
    this->Seeds = { { Eigen::Vector3d(64.0, 64.0, 64.0), 12.0 } };
    this->CurvatureWeight = 0.15;
  }
  double Value(const Eigen::Vector3d& x) const override
  {
    const Eigen::Vector3d q = A * (x - this->Origin);
    const double u = q.x() + 0.05 * q.y() * q.y() * q.y();
    const double w = q.z() - 0.7 * q.y() * q.y();
    return -(u * u + 0.7 * q.y() * q.y() + 0.3 * w * w - 4.0) / (A * A);
  }
  Eigen::Vector3d Gradient(const Eigen::Vector3d& x) const override
  {
    const Eigen::Vector3d q = A * (x - this->Origin);
    const double v = q.y();
    const double u = q.x() + 0.05 * v * v * v;
    const double w = q.z() - 0.7 * v * v;
    const double dFdu = 2.0 * u;
    const double dFdv = 2.0 * u * 0.15 * v * v + 1.4 * v - 0.6 * w * 1.4 * v;
    const double dFdw = 0.6 * w;
    return -Eigen::Vector3d(dFdu, dFdv, dFdw) / A;
  }
};

/// Four Gaussian blobs, f = sum_k exp(-|S_k (x - c_k)|^2 / 2), isovalue 0.5: components A
/// (round), B (elongated), C and D (small). Two intersecting seed spheres meet A and B only;
/// the gap between A and B inside the seed has f < 0.5, so the front must also retreat there.
struct MultiComponentCase : Case
{
  struct Blob
  {
    Eigen::Vector3d Center, Sigma;
  };
  std::array<Blob, 4> Blobs{ { { { 36, 64, 64 }, { 14, 14, 14 } },
    { { 86, 64, 64 }, { 10, 16, 20 } }, { { 64, 64, 22 }, { 8, 8, 8 } },
    { { 64, 104, 100 }, { 10, 10, 10 } } } };
  MultiComponentCase()
  {
    this->Name = "multi-component";
    this->IsoValue = 0.5;
    this->Seeds = { { Eigen::Vector3d(44, 64, 64), 14.0 }, { Eigen::Vector3d(70, 64, 64), 14.0 } };
    this->CurvatureWeight = 0.01;
  }
  double Term(int k, const Eigen::Vector3d& x) const
  {
    const Eigen::Vector3d s = (x - this->Blobs[k].Center).cwiseQuotient(this->Blobs[k].Sigma);
    return std::exp(-0.5 * s.squaredNorm());
  }
  double Value(const Eigen::Vector3d& x) const override
  {
    double f = 0.0;
    for (int k = 0; k < 4; ++k)
    {
      f += this->Term(k, x);
    }
    return f;
  }
  Eigen::Vector3d Gradient(const Eigen::Vector3d& x) const override
  {
    Eigen::Vector3d g = Eigen::Vector3d::Zero();
    for (int k = 0; k < 4; ++k)
    {
      const Blob& b = this->Blobs[k];
      g -= this->Term(k, x) * (x - b.Center).cwiseQuotient(b.Sigma).cwiseQuotient(b.Sigma);
    }
    return g;
  }
  int Component(const Eigen::Vector3d& x) const override
  {
    int best = 0;
    for (int k = 1; k < 4; ++k)
    {
      if (this->Term(k, x) > this->Term(best, x))
      {
        best = k;
      }
    }
    return best;
  }
  bool Seeded(int component) const override { return component == 0 || component == 1; }
};

/// A ball: f = R - |x - c|, isovalue 0, so the exact surface is the sphere of radius R.
struct SphereCase : Case
{
  Eigen::Vector3d Center;
  double Radius;
  SphereCase(const Eigen::Vector3d& center, double radius, double boxHalfWidth)
    : Center(center)
    , Radius(radius)
  {
    this->Name = "sphere";
    this->BoxMin = center - Eigen::Vector3d::Constant(boxHalfWidth);
    this->BoxMax = center + Eigen::Vector3d::Constant(boxHalfWidth);
    this->Seeds = { { center, 0.5 * radius } };
  }
  double Value(const Eigen::Vector3d& x) const override
  {
    return this->Radius - (x - this->Center).norm();
  }
  Eigen::Vector3d Gradient(const Eigen::Vector3d& x) const override
  {
    return -(x - this->Center).normalized();
  }
};

/// Equal-mass particles of an ellipsoidal Plummer sphere, f = (1 + q^2)^(-5/2) with
/// q = |(x - c) / (a axes)|, truncated at q = 6: the density falls 8300x from the core to the
/// edge, so the sampling is adaptive. The isovalue is f at q = 4, in the sparse outskirts
/// (where the density is 1/1190 of the core's), so the exact surface is the ellipsoid q = 4.
/// Sample values carry 5% multiplicative Gaussian noise, f (1 + 0.05 N(0, 1)).
struct AdaptiveNoisyCase : Case
{
  Eigen::Vector3d Centre{ 64, 64, 64 };
  double Scale = 8.0; // a
  Eigen::Vector3d Axes{ 1.0, 0.7, 0.5 };
  static constexpr double SurfaceQ = 4.0, OuterQ = 6.0, Noise = 0.05;
  AdaptiveNoisyCase()
  {
    this->Name = "adaptive-noisy";
    this->IsoValue = Density(SurfaceQ);
    this->Seeds = { { this->Centre, this->Scale } };
    this->BoxMin = this->Centre - OuterQ * this->Scale * this->Axes;
    this->BoxMax = this->Centre + OuterQ * this->Scale * this->Axes;
  }
  static double Density(double q) { return std::pow(1.0 + q * q, -2.5); }
  // Fraction of the (untruncated) Plummer mass within q.
  static double MassWithin(double q) { return std::pow(q * q / (1.0 + q * q), 1.5); }
  Eigen::Vector3d Scaled(const Eigen::Vector3d& x) const
  {
    return (x - this->Centre).cwiseQuotient(this->Scale * this->Axes);
  }
  double Value(const Eigen::Vector3d& x) const override { return Density(this->Scaled(x).norm()); }
  Eigen::Vector3d Gradient(const Eigen::Vector3d& x) const override
  {
    const Eigen::Vector3d u = this->Scaled(x);
    const double q2 = u.squaredNorm();
    // d/dx (1 + q^2)^(-5/2) = -5 (1 + q^2)^(-7/2) u / (a axes)
    return (-5.0 * std::pow(1.0 + q2, -3.5)) * u.cwiseQuotient(this->Scale * this->Axes);
  }
  std::vector<Eigen::Vector3d> Samples(std::size_t count, std::uint64_t seed) const override
  {
    std::mt19937_64 random(seed);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::normal_distribution<double> gauss(0.0, 1.0);
    std::vector<Eigen::Vector3d> points(count);
    const double total = MassWithin(OuterQ);
    for (auto& p : points)
    {
      // Invert the mass profile: m = q^3 / (1 + q^2)^(3/2)  =>  q = 1 / sqrt(m^(-2/3) - 1).
      const double m = std::max(1e-300, total * unit(random));
      const double q = 1.0 / std::sqrt(std::pow(m, -2.0 / 3.0) - 1.0);
      Eigen::Vector3d direction(gauss(random), gauss(random), gauss(random));
      direction.normalize();
      p = this->Centre + (q * this->Scale) * direction.cwiseProduct(this->Axes);
    }
    return points;
  }
  double MeasuredValue(const Eigen::Vector3d& x, std::mt19937_64& random) const override
  {
    std::normal_distribution<double> gauss(0.0, 1.0);
    return this->Value(x) * (1.0 + Noise * gauss(random));
  }
  double SurfaceSpacing(std::size_t count) const override
  {
    // Number density on q = 4: count / mass(6) times the normalised Plummer density there.
    const double volume = std::pow(this->Scale, 3) * this->Axes.prod();
    const double density = static_cast<double>(count) / MassWithin(OuterQ) * 3.0 /
      (4.0 * 3.14159265358979323846 * volume) * Density(SurfaceQ);
    return std::cbrt(1.0 / density);
  }
};

/// A tube of radius 3 along a path that snakes back and forth in x through 6 rows in y and 4
/// layers in z (f = 3 - distance to the path, isovalue 0), in a box twice as long in x as wide.
/// One component, which crosses the plane x = 64 (where ranks split the box in x) 24 times: a
/// flood over MPI ranks goes round after round from one rank's half to the other's, a row at a
/// time. Rows 10 apart, so that 4 units of outside (about 3.7 spacings at 330,000 samples)
/// separate the tubes: no neighbourhood links one row's inside to the next row's.
struct SnakeCase : Case
{
  static constexpr int Rows = 6, Layers = 4;
  static constexpr double Radius = 3.0, Pitch = 10.0, First = 7.0, RunStart = 8.0, RunEnd = 120.0;
  std::vector<Eigen::Vector3d> Path; // the polyline's vertices
  SnakeCase()
  {
    this->Name = "snake";
    this->IsoValue = 0.0;
    this->BoxMax =
      Eigen::Vector3d(128, 2 * First + (Rows - 1) * Pitch, 2 * First + (Layers - 1) * Pitch);
    // Run k along x, in row r of layer l (the rows of a layer in turn, every other layer
    // backwards, so that consecutive runs are neighbours), joined at the runs' ends.
    for (int k = 0; k < Rows * Layers; ++k)
    {
      const int layer = k / Rows, j = k % Rows;
      const int row = layer % 2 == 0 ? j : Rows - 1 - j;
      const double y = First + row * Pitch, z = First + layer * Pitch;
      const bool forwards = k % 2 == 0;
      this->Path.emplace_back(forwards ? RunStart : RunEnd, y, z);
      this->Path.emplace_back(forwards ? RunEnd : RunStart, y, z);
    }
    this->Seeds = { { Eigen::Vector3d(RunStart + 4.0, First, First), 2.5 } };
    this->CurvatureWeight = 0.05;
  }
  // The path's point nearest to x.
  Eigen::Vector3d Nearest(const Eigen::Vector3d& x) const
  {
    Eigen::Vector3d best = this->Path[0];
    for (std::size_t k = 0; k + 1 < this->Path.size(); ++k)
    {
      const Eigen::Vector3d a = this->Path[k], ab = this->Path[k + 1] - a;
      const double t = std::max(0.0, std::min(1.0, (x - a).dot(ab) / ab.squaredNorm()));
      const Eigen::Vector3d c = a + t * ab;
      best = (x - c).squaredNorm() < (x - best).squaredNorm() ? c : best;
    }
    return best;
  }
  double Value(const Eigen::Vector3d& x) const override
  {
    return Radius - (x - this->Nearest(x)).norm();
  }
  Eigen::Vector3d Gradient(const Eigen::Vector3d& x) const override
  {
    return -(x - this->Nearest(x)).normalized();
  }
};

/// `count` uniform random samples in the case's box (deterministic for a given seed).
inline std::vector<Eigen::Vector3d> UniformSamples(
  const Case& c, std::size_t count, std::uint64_t seed)
{
  std::mt19937_64 random(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<Eigen::Vector3d> points(count);
  const Eigen::Vector3d size = c.BoxMax - c.BoxMin;
  for (auto& p : points)
  {
    const double x = unit(random), y = unit(random), z = unit(random);
    p = c.BoxMin + Eigen::Vector3d(x * size.x(), y * size.y(), z * size.z());
  }
  return points;
}

/// Newton projection of x onto the exact isosurface along the gradient.
inline bool ProjectOntoSurface(const Case& c, Eigen::Vector3d& x)
{
  for (int k = 0; k < 30; ++k)
  {
    const Eigen::Vector3d g = c.Gradient(x);
    const double r = c.Value(x) - c.IsoValue;
    if (!(g.squaredNorm() > 0.0))
    {
      return false;
    }
    const Eigen::Vector3d step = (r / g.squaredNorm()) * g;
    x -= step;
    if (step.norm() < 1e-10)
    {
      return true;
    }
  }
  return false;
}

inline std::vector<Eigen::Vector3d> Case::Samples(std::size_t count, std::uint64_t seed) const
{
  return UniformSamples(*this, count, seed);
}

/// The case called `name` (one-component, multi-component, adaptive-noisy, snake, sphere), or
/// null.
inline std::unique_ptr<Case> MakeCase(const std::string& name)
{
  if (name == "one-component")
    return std::unique_ptr<Case>(new OneComponentCase);
  if (name == "multi-component")
    return std::unique_ptr<Case>(new MultiComponentCase);
  if (name == "adaptive-noisy")
    return std::unique_ptr<Case>(new AdaptiveNoisyCase);
  if (name == "snake")
    return std::unique_ptr<Case>(new SnakeCase);
  if (name == "sphere")
    return std::unique_ptr<Case>(new SphereCase(Eigen::Vector3d(64, 64, 64), 40.0, 64.0));
  return nullptr;
}

} // namespace cases
} // namespace lsi

#endif
