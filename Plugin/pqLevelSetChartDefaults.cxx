// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "pqLevelSetChartDefaults.h"

#include "pqApplicationCore.h"
#include "pqDataRepresentation.h"
#include "pqOutputPort.h"
#include "pqPipelineSource.h"
#include "pqServerManagerModel.h"
#include "pqView.h"
#include "vtkSMPropertyHelper.h"
#include "vtkSMProxy.h"

#include <QPointer>
#include <QTimer>

#include <cstring>

namespace
{
// The filter's convergence table: its columns and how the chart shows them.
struct SeriesStyle
{
  const char* Column;
  const char* Label;
  const char* Visible;
  const char* Corner; // vtkChartXY corner: 0 bottom-left axes, 1 bottom-right (right axis)
};
const SeriesStyle ConvergenceSeries[] = {
  { "SignMismatch", "P (sign mismatch)", "1", "0" },
  { "MaxGradientDeviation", "MG (max gradient deviation)", "1", "0" },
  { "MeanGradientDeviation", "AG (mean gradient deviation)", "1", "0" },
  { "BandSize", "band size (samples, right axis)", "1", "1" },
  { "Seconds", "seconds", "0", "0" },
  { "Iteration", "iteration", "0", "0" },
};

bool IsConvergenceChart(pqDataRepresentation* representation)
{
  if (std::strcmp(representation->getProxy()->GetXMLName(), "XYChartRepresentation") != 0)
  {
    return false;
  }
  pqOutputPort* port = representation->getOutputPortFromInput();
  return port && port->getPortNumber() == 2 && port->getSource() &&
    std::strcmp(port->getSource()->getProxy()->GetXMLName(), "LevelSetIsosurface") == 0;
}

// Sets a per-series property as (column, value) pairs, the value taken from `field`.
void SetPairs(vtkSMProxy* proxy, const char* property, const char* SeriesStyle::*field)
{
  vtkSMPropertyHelper helper(proxy, property);
  unsigned int index = 0;
  for (const SeriesStyle& series : ConvergenceSeries)
  {
    helper.Set(index++, series.Column);
    helper.Set(index++, series.*field);
  }
  helper.SetNumberOfElements(index);
}

void ApplyChartDefaults(pqDataRepresentation* representation)
{
  vtkSMProxy* proxy = representation->getProxy();
  vtkSMPropertyHelper(proxy, "UseIndexForXAxis").Set(0);
  vtkSMPropertyHelper(proxy, "XArrayName").Set("Iteration");
  SetPairs(proxy, "SeriesLabel", &SeriesStyle::Label);
  SetPairs(proxy, "SeriesVisibility", &SeriesStyle::Visible);
  SetPairs(proxy, "SeriesPlotCorner", &SeriesStyle::Corner);
  proxy->UpdateVTKObjects();

  if (pqView* view = representation->getView())
  {
    vtkSMProxy* chart = view->getProxy();
    vtkSMPropertyHelper(chart, "BottomAxisTitle").Set("iteration");
    vtkSMPropertyHelper(chart, "LeftAxisTitle").Set("P, MG, AG");
    vtkSMPropertyHelper(chart, "RightAxisTitle").Set("band size (samples)");
    chart->UpdateVTKObjects();
    view->render();
  }
}
}

pqLevelSetChartDefaults::pqLevelSetChartDefaults(QObject* parent)
  : Superclass(parent)
{
}

void pqLevelSetChartDefaults::startup()
{
  pqServerManagerModel* model = pqApplicationCore::instance()->getServerManagerModel();
  QObject::connect(model, &pqServerManagerModel::representationAdded, this,
    &pqLevelSetChartDefaults::onRepresentationAdded);
}

void pqLevelSetChartDefaults::onRepresentationAdded(pqRepresentation* added)
{
  // The new representation's input and view are set after this signal: look once control is
  // back in the event loop.
  QPointer<pqDataRepresentation> representation = qobject_cast<pqDataRepresentation*>(added);
  if (representation)
  {
    QTimer::singleShot(0, this, [representation]() {
      if (representation && IsConvergenceChart(representation))
      {
        ApplyChartDefaults(representation);
      }
    });
  }
}
