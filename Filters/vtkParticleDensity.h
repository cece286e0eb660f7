// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkParticleDensity
 * @brief   The SPH density the particles imply, for files that carry none.
 *
 * N-body and star particles carry no density, and initial conditions often carry placeholders.
 * This filter computes the SPH summation density
 *   rho_i = sum_j m_j W(|x_i - x_j|, H_i)
 * over the NumberOfNeighbors nearest particles j (the particle itself included), where the
 * support radius H_i is the distance to the farthest of them (the GADGET convention: the
 * kernel's support holds NumberOfNeighbors particles, 64 by default like GADGET's DesNumNgb).
 * Masses come from a point array named "Masses", "Mass" or "mass" (the readers' names), or are 1
 * when there is none (a warning says so). The output is the input with the point arrays
 * "Density" (the active scalars) and "SmoothingLength" (H_i) added, and field data naming them
 * ("DensityArray", "SmoothingLengthArray") as the snapshot readers do, so that the level-set
 * filter picks the density up without being told. Lengths scale with the data: no unit enters.
 *
 * @sa vtkLevelSetIsosurface vtkSPHInterpolator
 */
#ifndef vtkParticleDensity_h
#define vtkParticleDensity_h

#include "LevelSetIsosurfaceFiltersModule.h" // for export macro
#include "vtkLevelSetMacros.h"               // for vtkSetClampWarnMacro
#include "vtkPointSetAlgorithm.h"

class LEVELSETISOSURFACEFILTERS_EXPORT vtkParticleDensity : public vtkPointSetAlgorithm
{
public:
  static vtkParticleDensity* New();
  vtkTypeMacro(vtkParticleDensity, vtkPointSetAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /** Particles inside each kernel's support, the particle itself included. Default 64. */
  vtkSetClampWarnMacro(NumberOfNeighbors, int, 2, 1000);
  vtkGetMacro(NumberOfNeighbors, int);
  ///@}

  enum Kernels
  {
    CUBIC_SPLINE = 0,   // M4: GADGET, ChaNGa
    QUINTIC_SPLINE = 1, // M6: SWIFT's default
    WENDLAND_C2 = 2     // GIZMO and others
  };
  ///@{
  /** The SPH kernel. Default CUBIC_SPLINE. */
  vtkSetClampWarnMacro(Kernel, int, CUBIC_SPLINE, WENDLAND_C2);
  vtkGetMacro(Kernel, int);
  void SetKernelToCubicSpline() { this->SetKernel(CUBIC_SPLINE); }
  void SetKernelToQuinticSpline() { this->SetKernel(QUINTIC_SPLINE); }
  void SetKernelToWendlandC2() { this->SetKernel(WENDLAND_C2); }
  ///@}

protected:
  vtkParticleDensity() = default;
  ~vtkParticleDensity() override = default;

  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  int NumberOfNeighbors = 64;
  int Kernel = CUBIC_SPLINE;

private:
  vtkParticleDensity(const vtkParticleDensity&) = delete;
  void operator=(const vtkParticleDensity&) = delete;
};

#endif
