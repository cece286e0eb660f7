// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
// The particles output: the input points as vertices with their point data and "LevelSet", the
// final level-set function (positive inside the extracted components), in input order.
#ifndef LevelSetParticleOutput_h
#define LevelSetParticleOutput_h

#include "LevelSetNeighborhoods.h"

#include <vector>

class vtkPointSet;
class vtkPolyData;

namespace lsi
{

/// `phi` is in the samples' storage order (geometry.Order maps it back to input ids).
void MakeParticleOutput(vtkPointSet* input, const Neighborhoods& geometry,
  const std::vector<double>& phi, vtkPolyData* particles);

} // namespace lsi

#endif
