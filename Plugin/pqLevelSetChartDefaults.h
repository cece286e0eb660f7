// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
#ifndef pqLevelSetChartDefaults_h
#define pqLevelSetChartDefaults_h

#include <QObject>

class pqRepresentation;

// GUI part of the plugin: when the convergence table (output port 2 of Level-Set Isosurface)
// is shown in a line chart, plots it against the "Iteration" column instead of the row index,
// shows P, MG and AG on the left axis and the band size on the right one (it counts samples, in
// the thousands, and would flatten the others), and hides the timing column.
//
// ParaView 5.11 offers no server-manager hint for a representation's series defaults, so this
// is done where the GUI creates representations. pvpython and pvbatch do not load it; scripts
// set the same properties themselves (see the README).
class pqLevelSetChartDefaults : public QObject
{
  Q_OBJECT
  typedef QObject Superclass;

public:
  pqLevelSetChartDefaults(QObject* parent = nullptr);
  ~pqLevelSetChartDefaults() override = default;

  void startup();
  void shutdown() {}

private Q_SLOTS:
  void onRepresentationAdded(pqRepresentation* representation);

private:
  Q_DISABLE_COPY(pqLevelSetChartDefaults)
};

#endif
