// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
// The convergence output: one row per iteration of the evolution (LevelSetEvolution.h's
// IterationRecord), for ParaView's line chart.
#ifndef LevelSetConvergenceTable_h
#define LevelSetConvergenceTable_h

#include "LevelSetEvolution.h"

#include "vtkNew.h"
#include "vtkTable.h"

namespace lsi
{

/// Columns Iteration, SignMismatch, MaxGradientDeviation, MeanGradientDeviation, BandSize,
/// Seconds (all double), no rows.
vtkNew<vtkTable> EmptyConvergenceTable();

void AppendIteration(vtkTable* table, const IterationRecord& record);

} // namespace lsi

#endif
