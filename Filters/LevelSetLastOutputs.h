// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
// The last run's outputs, for a re-run that only moved the seeds. With the flood start, the
// seeds only choose which components of {f > f_iso} are flooded: a seed dragged inside the same
// component floods the same samples and gives the same initial level set, so the evolution, the
// isopoints and every output would come out the same. The filter then hands these on instead
// of recomputing them (checked by the initial level set's fingerprint, not assumed).
#ifndef LevelSetLastOutputs_h
#define LevelSetLastOutputs_h

#include "vtkPointSet.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkTable.h"
#include "vtkType.h"

#include <cstdint>
#include <cstring>
#include <vector>

namespace lsi
{

/// An order-dependent 64-bit hash of the values' bits (splitmix64 steps).
inline std::uint64_t Fingerprint(const std::vector<double>& values)
{
  std::uint64_t h = values.size();
  for (const double v : values)
  {
    std::uint64_t bits;
    std::memcpy(&bits, &v, sizeof bits);
    h ^= bits + 0x9e3779b97f4a7c15ULL + (h << 6) + (h >> 2);
    h ^= h >> 31;
    h *= 0xbf58476d1ce4e5b9ULL;
  }
  return h ^ (h >> 29);
}

struct LastOutputs
{
  bool Valid = false;
  const vtkPointSet* Input = nullptr; // identity only, never dereferenced
  vtkMTimeType InputTime = 0;
  std::uint64_t StartFingerprint = 0; // of the initial level set
  vtkSmartPointer<vtkPolyData> Surface, Particles;
  vtkSmartPointer<vtkTable> Convergence, Enclosed;
  int Iterations = 0;
  bool Converged = false;
  // For the quick check of a seed move (serial runs with the flood start, no periodic box and
  // no merged duplicates): the flooded samples, f - f_iso and the spacing, in storage order.
  bool QuickCheck = false;
  std::vector<char> Inside;
  std::vector<double> DataOffsets;
  double Spacing = 0.0;

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

  /// Whether they (if kept) are this run's outputs too: the same input, unmodified, and the
  /// same initial level set.
  bool Match(vtkPointSet* input, std::uint64_t startFingerprint) const
  {
    return this->Surface && input == this->Input && input->GetMTime() == this->InputTime &&
      startFingerprint == this->StartFingerprint;
  }

  void Restore(
    vtkPolyData* surface, vtkPolyData* particles, vtkTable* convergence, vtkTable* enclosed) const
  {
    surface->ShallowCopy(this->Surface);
    particles->ShallowCopy(this->Particles);
    convergence->ShallowCopy(this->Convergence);
    enclosed->ShallowCopy(this->Enclosed);
  }

  void Forget() { *this = LastOutputs(); }

  /// Whether `phi` (the flood's initial level set) marks exactly the samples flooded last time.
  static std::vector<char> InsideOf(const std::vector<double>& phi)
  {
    std::vector<char> inside(phi.size());
    for (std::size_t i = 0; i < phi.size(); ++i)
    {
      inside[i] = phi[i] > 0.0;
    }
    return inside;
  }
};

} // namespace lsi

#endif
