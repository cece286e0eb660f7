// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "LevelSetEvolution.h"

#include "LevelSetTiming.h"
#include "MovingLeastSquares.h"

#include "vtkSMPThreadLocal.h"
#include "vtkSMPTools.h"

#include <algorithm>
#include <cmath>

namespace lsi
{

namespace
{
bool Positive(double phi)
{
  return phi > 0.0;
}
} // namespace

LevelSetEvolution::LevelSetEvolution(
  const Neighborhoods& geometry, const std::vector<double>& dataOffsets, std::vector<double>& phi)
  : Geometry(geometry)
  , DataOffsets(dataOffsets)
  , Phi(phi)
  , Gradient(3 * geometry.NumberOfSamples)
  , Collector(geometry)
  , Reinitializer(geometry, Collector)
{
}

void LevelSetEvolution::ComputeGradients(
  const std::vector<std::size_t>& where, const std::vector<double>& values)
{
  const std::size_t stride = static_cast<std::size_t>(this->Geometry.Stride);
  this->Geometry.EnsureStencils(where);
  ForEachIn(where, [&](std::size_t, std::size_t i) {
    const std::uint32_t* ids = this->Geometry.NeighborsOf(i);
    const Eigen::Vector3d g =
      this->Geometry.GradientAt(i, [&](std::size_t k) { return values[ids[k]]; });
    double* out = &this->Gradient[3 * i];
    out[0] = g[0];
    out[1] = g[1];
    out[2] = g[2];
  });
}

void LevelSetEvolution::Evolve(const EvolutionSettings& settings)
{
  const EvolutionCoefficients& c = settings.Coefficients;
  const std::size_t stride = static_cast<std::size_t>(this->Geometry.Stride);
  const bool regularize =
    settings.Method == Scheme::WithoutReinitialization && c.DistanceRegularization != 0.0;
  // The band: where delta_eps or delta_eps' is non-zero. With the distance regularisation
  // (which acts everywhere) a margin of one neighbourhood radius is added.
  double halfWidth = BandHalfWidth(std::max(c.Epsilon, c.CurvatureEpsilon));
  if (regularize)
  {
    halfWidth += 2.0 * settings.NeighborhoodRadius;
  }
  this->Collector.Where(this->Phi, halfWidth, this->Band);
  this->Ranks->KeepOwned(this->Band); // the ghosts take their owners' new values
  // Curvature needs unit normals on the band and on its neighbours (ghosts too).
  this->Collector.WithNeighbors(this->Band, this->Region);
  this->ComputeGradients(this->Region, this->Phi);

  auto unitNormal = [&](std::uint32_t j) {
    Eigen::Vector3d g(&this->Gradient[3 * j]);
    const double norm = g.norm();
    return norm > 0.0 ? Eigen::Vector3d(g / norm) : Eigen::Vector3d::Zero();
  };
  auto distanceFlux = [&](std::uint32_t j) {
    Eigen::Vector3d g(&this->Gradient[3 * j]);
    const double norm = g.norm();
    return norm > 0.0 ? Eigen::Vector3d(g * ((norm - 1.0) / norm)) : Eigen::Vector3d::Zero();
  };

  this->NewValues.resize(this->Band.size());
  if (settings.Method == Scheme::RosenthalLinsen)
  {
    const double limit = ReinitializationHalfWidth(settings);
    ForEachIn(this->Band, [&](std::size_t k, std::size_t i) {
      const std::uint32_t* ids = this->Geometry.NeighborsOf(i);
      const std::vector<double>& f = this->DataOffsets;
      const double slope =
        this->Geometry.GradientAt(i, [&](std::size_t m) { return f[ids[m]]; }).norm();
      // g = (f - f_iso) / |grad f|, bounded like phi where f is flat.
      const double offset = this->TargetOffset(i);
      const double target =
        slope > std::abs(offset) / limit ? offset / slope : Sign(offset) * limit;
      this->NewValues[k] =
        RosenthalLinsenValue(this->Phi[i], Eigen::Vector3d(&this->Gradient[3 * i]).norm(), target,
          settings.RelaxationRate, settings.MaximumStep);
    });
  }
  else
  {
    ForEachIn(this->Band, [&](std::size_t k, std::size_t i) {
      const std::uint32_t* ids = this->Geometry.NeighborsOf(i);
      const double curvature = c.CurvatureWeight != 0.0
        ? this->Geometry.DivergenceAt(i, [&](std::size_t m) { return unitNormal(ids[m]); })
        : 0.0;
      const double regularization = regularize
        ? this->Geometry.DivergenceAt(i, [&](std::size_t m) { return distanceFlux(ids[m]); })
        : 0.0;
      this->NewValues[k] =
        EvolvedValue(this->Phi[i], Sign(this->TargetOffset(i)), curvature, regularization, c);
    });
  }

  ForEachIn(this->Band, [&](std::size_t k, std::size_t i) { this->Phi[i] = this->NewValues[k]; });
  this->Ranks->RefreshGhosts(this->Phi);
}

void LevelSetEvolution::Measure(const EvolutionSettings& settings, IterationRecord& record)
{
  const std::size_t n = this->Geometry.NumberOfSamples;
  const Communicator& ranks = *this->Ranks;
  // P = (1/2N) sum |sgn(phi_i) - sgn(f_i - f_iso)|, with sgn(phi) taken as +1 / -1.
  vtkSMPThreadLocal<double> mismatch(0.0);
  vtkSMPTools::For(
    0, static_cast<vtkIdType>(n), BalancedGrain(n, 1024), [&](vtkIdType begin, vtkIdType end) {
      double& local = mismatch.Local();
      for (vtkIdType i = begin; i < end; ++i)
      {
        if (!ranks.Owns(static_cast<std::size_t>(i)))
        {
          continue;
        }
        const double s = Positive(this->Phi[i]) ? 1.0 : -1.0;
        local += std::abs(s - Sign(this->DataOffsets[i]));
      }
    });
  double total = 0.0;
  for (double v : mismatch)
  {
    total += v;
  }

  // MG and AG over the zero crossings between neighbours (the rough isopoints), with the
  // gradient interpolated linearly along each crossing segment.
  const double h = settings.NeighborhoodRadius;
  this->Collector.Where(this->Phi, 2.0 * h, this->Scratch);
  this->ComputeGradients(this->Scratch, this->Phi);
  this->Collector.Where(this->Phi, 1.0 * h, this->Front);
  struct Stats
  {
    double Max = 0.0, Sum = 0.0;
    std::size_t Count = 0;
  };
  vtkSMPThreadLocal<Stats> stats;
  const int stride = this->Geometry.Stride;
  ForEachIn(this->Front, [&](std::size_t, std::size_t i) {
    const double phii = this->Phi[i];
    if (!Positive(phii) || !ranks.Owns(i))
    {
      return;
    }
    Stats& local = stats.Local();
    const std::uint32_t* ids = this->Geometry.NeighborsOf(i);
    for (int m = 1; m < stride; ++m)
    {
      const std::uint32_t j = ids[m];
      const double phij = this->Phi[j];
      if (Positive(phij) || std::abs(phij) >= 2.0 * h)
      {
        continue;
      }
      const double t = phii / (phii - phij);
      const Eigen::Vector3d gi(&this->Gradient[3 * i]), gj(&this->Gradient[3 * j]);
      const double deviation = GradientDeviation(((1.0 - t) * gi + t * gj).norm());
      if (std::isfinite(deviation))
      {
        local.Max = std::max(local.Max, deviation);
        local.Sum += deviation;
        ++local.Count;
      }
    }
  });
  Stats all;
  for (const Stats& s : stats)
  {
    all.Max = std::max(all.Max, s.Max);
    all.Sum += s.Sum;
    all.Count += s.Count;
  }
  // Totals over the ranks: the statistics and the band.
  double owned = 0.0, band = 0.0;
  for (std::size_t i = 0; i < n && ranks.Distributed(); ++i)
  {
    owned += ranks.Owns(i) ? 1.0 : 0.0;
  }
  for (std::size_t i : this->Band)
  {
    band += ranks.Owns(i) ? 1.0 : 0.0;
  }
  double sums[5] = { total, ranks.Distributed() ? owned : static_cast<double>(n), all.Sum,
    static_cast<double>(all.Count), band };
  ranks.Sum(sums, 5);
  all.Max = ranks.Max(all.Max);
  record.SignMismatch = sums[1] > 0.0 ? sums[0] / (2.0 * sums[1]) : 0.0;
  record.MaxGradientDeviation = all.Max;
  record.MeanGradientDeviation = sums[3] > 0.0 ? sums[2] / sums[3] : 0.0;
  record.BandSize = static_cast<std::size_t>(sums[4]);
}

bool LevelSetEvolution::Run(const EvolutionSettings& settings,
  const IterationObserver& observeIteration, const AbortCheck& aborted)
{
  this->HasConverged = false;
  int stableIterations = 0;
  // Values beyond the reinitialised region are never read as distances: clamp them, so that a
  // front moving into stale values meets a bounded step that the reinitialisation repairs.
  const double clamp = ReinitializationHalfWidth(settings);
  const std::size_t n = this->Geometry.NumberOfSamples;
  this->InitiallyPositive.resize(n);
  this->HasChangedSign.resize(n);
  vtkSMPTools::For(
    0, static_cast<vtkIdType>(n), BalancedGrain(n, 16384), [&](vtkIdType begin, vtkIdType end) {
      for (vtkIdType i = begin; i < end; ++i)
      {
        this->Phi[i] = std::max(-clamp, std::min(clamp, this->Phi[i]));
        this->InitiallyPositive[i] = Positive(this->Phi[i]);
        this->HasChangedSign[i] = 0;
      }
    });
  const Communicator& ranks = *this->Ranks;
  for (int iteration = 1; iteration <= settings.MaximumIterations; ++iteration)
  {
    // Under MPI every rank stops together, when any rank was asked to.
    if (!ranks.All(!Aborted(aborted)))
    {
      return false;
    }
    const auto start = Clock::now();
    IterationRecord record;
    record.Iteration = iteration;
    this->Evolve(settings);
    const bool reinitialize =
      settings.Method != Scheme::WithoutReinitialization && settings.ReinitializationSteps > 0;
    if (reinitialize)
    {
      this->Reinitializer.Run(settings, this->Phi, ranks);
    }
    // First-time sign changes: scan the samples that may have changed (the band, and the
    // reinitialised region or else the band's neighbours).
    const std::vector<std::size_t>& region =
      reinitialize ? this->Reinitializer.Region() : this->Region;
    const std::vector<std::size_t>& band = this->Band;
    for (const std::vector<std::size_t>* touched : { &band, &region })
    {
      // Each list names a sample once, so the threads write distinct flags; counts add exactly.
      vtkSMPThreadLocal<std::size_t> changes(0);
      ForEachIn(*touched, [&](std::size_t, std::size_t i) {
        if (!this->HasChangedSign[i] && Positive(this->Phi[i]) != this->InitiallyPositive[i] &&
          ranks.Owns(i))
        {
          this->HasChangedSign[i] = 1;
          ++changes.Local();
        }
      });
      for (std::size_t count : changes)
      {
        record.FirstSignChanges += count;
      }
    }
    record.Seconds = SecondsSince(start);
    this->Measure(settings, record); // statistics are reported, not timed as part of the iteration
    record.FirstSignChanges =
      static_cast<std::size_t>(ranks.Sum(static_cast<double>(record.FirstSignChanges)));
    if (!ranks.All(!(observeIteration && observeIteration(record))))
    {
      return false;
    }
    const double allowed = settings.ConvergenceTolerance * static_cast<double>(record.BandSize);
    stableIterations =
      static_cast<double>(record.FirstSignChanges) <= allowed ? stableIterations + 1 : 0;
    if (stableIterations >= settings.StableIterationsToStop)
    {
      this->HasConverged = true;
      break;
    }
  }
  return true;
}

} // namespace lsi
