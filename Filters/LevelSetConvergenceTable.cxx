// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "LevelSetConvergenceTable.h"

#include "vtkDoubleArray.h"

namespace lsi
{

vtkNew<vtkTable> EmptyConvergenceTable()
{
  vtkNew<vtkTable> table;
  for (const char* name : { "Iteration", "SignMismatch", "MaxGradientDeviation",
         "MeanGradientDeviation", "BandSize", "Seconds" })
  {
    vtkNew<vtkDoubleArray> column;
    column->SetName(name);
    table->AddColumn(column);
  }
  return table;
}

void AppendIteration(vtkTable* table, const IterationRecord& record)
{
  const double values[6] = { static_cast<double>(record.Iteration), record.SignMismatch,
    record.MaxGradientDeviation, record.MeanGradientDeviation, static_cast<double>(record.BandSize),
    record.Seconds };
  for (int c = 0; c < 6; ++c)
  {
    vtkDoubleArray::SafeDownCast(table->GetColumn(c))->InsertNextValue(values[c]);
  }
}

} // namespace lsi
