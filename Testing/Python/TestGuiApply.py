# SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
# SPDX-License-Identifier: BSD-3-Clause
"""Run inside the ParaView GUI: paraview --script=TestGuiApply.py (under xvfb-run), with
LSI_PLUGIN, LSI_GLASS (the Evrard glass Tipsy file), LSI_SCREENSHOT and LSI_STATUS in the
environment.

Opens the real particles with the plugin's Tipsy reader, adds their analytic density, creates
Level-Set Isosurface with its default seed (or, with LSI_SNAPSHOT set, opens that snapshot as
File > Open does and creates the filter with no array named: it takes the snapshot's density), makes it the active source (its properties panel
then shows the seed's sphere widget) and applies it the way the Apply button does: each output
port goes to the view its XML hints prefer. Checks that the sphere widget is visible on the data,
that the convergence table opened in a line chart view (against Iteration, with the band size on
the right axis), that what the surface encloses opened in a spreadsheet view (the mass within
3% of the glass's 0.25 inside r = 0.5), that the particles output was not shown
and that the surface is in the 3D view; saves a screenshot of the whole layout; writes
"passed" to LSI_STATUS only if every check held.

The checks run from a one-shot timer of the view's interactor, that is from the GUI's event
loop once the script has returned: the properties panel creates the sphere widget only when it
processes the active-source change. The timer callback then quits the application."""
import math
import os

from paraview import servermanager
from paraview.simple import (AssignViewToLayout, Calculator, GetDisplayProperties, GetActiveViewOrCreate, GetLayout, GetViews, LoadPlugin, OpenDataFile,
                             Render, ResetCamera, SaveScreenshot, SetActiveSource, SetActiveView,
                             ShowInteractiveWidgets)

failures = []
LoadPlugin(os.environ["LSI_PLUGIN"], ns=globals())
snapshot = os.environ.get("LSI_SNAPSHOT")
if snapshot:
    # File > Open: ParaView picks the reader; Apply; then the filter with its defaults.
    reader = OpenDataFile(snapshot)
    reader.UpdatePipeline()
    surface = LevelSetIsosurface(Input=reader)
    rho = servermanager.Fetch(reader).GetPointData().GetScalars()
    print("the filter's scalars: %s (the reader's active scalars: %s)"
          % (list(surface.Scalars), rho.GetName()))
    if list(surface.Scalars)[-1] != rho.GetName():
        failures.append("the filter did not take the snapshot's density by itself")
    values = sorted(rho.GetValue(i) for i in range(rho.GetNumberOfTuples()))
    surface.IsoValue = values[len(values) // 2]  # the median density
else:
    glass = TipsyParticleReader(FileNames=[os.environ["LSI_GLASS"]])
    density = Calculator(Input=glass, ResultArrayName="density",
                         Function="1 / (2 * %.17g * mag(coords))" % math.pi)
    density.UpdatePipeline()  # as after Apply on the reader: the seed comes from the bounds
    surface = LevelSetIsosurface(Input=density, Scalars=["POINTS", "density"])
    surface.IsoValue = 1.0 / math.pi  # the sphere r = 0.5
render_view = GetActiveViewOrCreate("RenderView")
SetActiveSource(surface)

# What Apply does (pqApplyBehavior::showData): every port in its preferred view.
controller = servermanager.ParaViewPipelineController()
for port in range(4):
    controller.ShowInPreferredView(surface, port, render_view)
# Apply also puts a newly created view into the layout, beside the 3D view.
layout = GetLayout(render_view)
for view in GetViews():
    if GetLayout(view) is None:
        AssignViewToLayout(view=view, layout=layout, hint=0)
# The chart view, just created, is now the active view; the sphere widget lives in the active
# render view, so come back to the 3D view as a user does by clicking in it.
SetActiveView(render_view)
ShowInteractiveWidgets(proxy=surface)
ResetCamera(render_view)
# Half transparent in the screenshot, so that the seed sphere inside the surface shows.
GetDisplayProperties(surface, render_view).Opacity = 0.5
Render(render_view)



def check(caller, event):
    if checked:
        return  # the interactor's other timers fire TimerEvent too
    checked.append(True)
    print("seed: centre %s radius %.3f" % (list(surface.SeedCenter), surface.SeedRadius))
    if not snapshot and (max(abs(c) for c in surface.SeedCenter) > 0.05 or
                         not 0.1 < surface.SeedRadius < 0.3):
        failures.append("the default seed is not placed on the data's centre")

    # The sphere widget: a visible SphereWidgetRepresentation in the render view.
    hidden = render_view.GetProperty("HiddenRepresentations")
    widgets = [hidden[i] for i in range(len(hidden))
               if hidden[i].GetXMLName() == "SphereWidgetRepresentation"]
    visible = [w for w in widgets if w.GetPropertyValue("Visibility")]
    print("sphere widgets in the render view: %d, visible: %d" % (len(widgets), len(visible)))
    if not visible:
        failures.append("no visible sphere widget")

    chart_views = [v for v in GetViews() if v.GetXMLName() == "XYChartView"]
    shown_in_chart = [v for v in chart_views
                      if any(r.Input.SMProxy == surface.SMProxy and r.Visibility
                             for r in v.Representations if hasattr(r, "Input"))]
    print("views: %s" % [v.GetXMLName() for v in GetViews()])
    if not shown_in_chart:
        failures.append("the convergence table is not shown in a line chart view")
    else:
        # The plugin's GUI part plots it against Iteration, band size on the right axis.
        chart = [r for r in shown_in_chart[0].Representations
                 if hasattr(r, "Input") and r.Input.SMProxy == surface.SMProxy][0]
        corners = dict(zip(chart.SeriesPlotCorner[::2], chart.SeriesPlotCorner[1::2]))
        shown = list(chart.SeriesVisibility)  # the names of the visible series
        print("chart: x %s (index %d), corners %s, visible %s"
              % (chart.XArrayName, chart.UseIndexForXAxis, corners, shown))
        if chart.UseIndexForXAxis or chart.XArrayName != "Iteration":
            failures.append("the chart is not plotted against Iteration")
        if corners.get("BandSize") != "1" or corners.get("SignMismatch") != "0":
            failures.append("the band size is not on the right axis")
        if sorted(shown) != ["BandSize", "MaxGradientDeviation", "MeanGradientDeviation",
                             "SignMismatch"]:
            failures.append("wrong series shown")
    ports_in_render = sorted({r.Input.Port if hasattr(r.Input, "Port") else 0
                              for r in render_view.Representations
                              if hasattr(r, "Input") and r.Input.SMProxy == surface.SMProxy and r.Visibility})
    print("surface ports shown in the render view: %s" % ports_in_render)
    if ports_in_render != [0]:
        failures.append("expected only the surface (port 0) in the 3D view, got %s" % ports_in_render)

    # What the surface encloses: port 3 in a spreadsheet view, in the layout.
    sheets = [v for v in GetViews() if v.GetXMLName() == "SpreadSheetView"
              and any(r.Input.SMProxy == surface.SMProxy and r.Visibility
                      for r in v.Representations if hasattr(r, "Input"))]
    table = surface.GetClientSideObject().GetOutputDataObject(3)
    names = [table.GetValueByName(r, "Name").ToString() for r in range(table.GetNumberOfRows())]
    print("enclosed table in %d spreadsheet view(s): rows %s" % (len(sheets), names))
    if not sheets or GetLayout(sheets[0]) is None:
        failures.append("the enclosed table is not shown in a spreadsheet view in the layout")
    if not names or names[-1] != "Total" or not names[0].startswith("Component"):
        failures.append("the enclosed table lacks its component and total rows")
    elif not snapshot:
        # The glass's mass within r is r^2 (rho = 1 / (2 pi r), total mass 1).
        mass = table.GetValueByName(0, "Mass").ToDouble()
        print("enclosed mass %.4f, within r = 0.5: 0.25" % mass)
        if abs(mass / 0.25 - 1.0) > 0.03:
            failures.append("the enclosed mass is not within 3% of 0.25")

    splats = surface.GetClientSideObject().GetOutputDataObject(0)
    print("splat polygons: %d" % splats.GetNumberOfPolys())
    if splats.GetNumberOfPolys() < (100 if snapshot else 1000):
        failures.append("too few splats")

    if not chart_views or GetLayout(chart_views[0]) is None:
        failures.append("the chart view is not in the layout beside the 3D view")
    SaveScreenshot(os.environ["LSI_SCREENSHOT"], layout, ImageResolution=[1200, 600])
    for failure in failures:
        print("FAILED:", failure)
    with open(os.environ["LSI_STATUS"], "w") as status:
        status.write("failed\n" if failures else "passed\n")
    os._exit(0)


checked = []
interactor = render_view.GetRenderWindow().GetInteractor()
interactor.AddObserver("TimerEvent", check)
interactor.CreateOneShotTimer(2000)
