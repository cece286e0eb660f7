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
 * MPI (pvbatch, pvserver): with the particles spread over the ranks of Controller (by default
 * the global controller), a rank's particles lack the neighbours that other ranks hold. The
 * particles are first redistributed by space if the pieces are poor (a reader's interleaved
 * pieces, or everything on one rank), then each rank receives copies of the other ranks'
 * particles within the reach of its own: each particle's NumberOfNeighbors nearest among the
 * rank's own lie no closer than its nearest overall, so the nearest overall lie within that
 * reach. Every particle gets the density of a serial run. The output is the rank's particles
 * after that redistribution (together, every input particle once).
 *
 * @sa vtkLevelSetIsosurface vtkSPHInterpolator
 */
#ifndef vtkParticleDensity_h
#define vtkParticleDensity_h

#include "LevelSetIsosurfaceFiltersModule.h" // for export macro
#include "vtkLevelSetMacros.h"               // for vtkSetClampWarnMacro
#include "vtkPointSetAlgorithm.h"

class vtkMultiProcessController;

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
    WENDLAND_C2 = 2,    // GIZMO and others
    QUARTIC_SPLINE = 3, // M5
    WENDLAND_C4 = 4,
    WENDLAND_C6 = 5
  };
  ///@{
  /** The SPH kernel (lsi::SPHKernel's numbering). Default CUBIC_SPLINE. */
  vtkSetClampWarnMacro(Kernel, int, CUBIC_SPLINE, WENDLAND_C6);
  vtkGetMacro(Kernel, int);
  void SetKernelToCubicSpline() { this->SetKernel(CUBIC_SPLINE); }
  void SetKernelToQuinticSpline() { this->SetKernel(QUINTIC_SPLINE); }
  void SetKernelToWendlandC2() { this->SetKernel(WENDLAND_C2); }
  ///@}

  ///@{
  /** The ranks over which the particles are spread. Default: the global controller. */
  virtual void SetController(vtkMultiProcessController*);
  vtkGetObjectMacro(Controller, vtkMultiProcessController);
  ///@}

protected:
  vtkParticleDensity();
  ~vtkParticleDensity() override;

  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  int NumberOfNeighbors = 64;
  int Kernel = CUBIC_SPLINE;
  vtkMultiProcessController* Controller = nullptr;

private:
  vtkParticleDensity(const vtkParticleDensity&) = delete;
  void operator=(const vtkParticleDensity&) = delete;
};

#endif
