"""Runs inside the real ParaView GUI (started by RunParaViewGUI.py under Xvfb): builds the
pipeline in Python and shows each output in the view its hints ask for, as Apply does.
Checks what ParaView then shows with no change in the display panel: the Radiosity menu
in pipeline order, the relit colors as computed, the convergence as a log-scale line
chart with a line per light, and a Radiosity array in an HDR color map with its unit.
"""

import os
import sys

sys.path.insert(0, os.environ["RELIGHT_TEST_DIR"])
import guitest  # noqa: E402
from paraview import servermanager  # noqa: E402
from paraview.simple import (  # noqa: E402
    ColorBy, CreateView, GetActiveView, GetRepresentation, LightTaggedRadiosity, RadiosityMesher,
    RadiosityRelight, Show, XMLPolyDataReader)
from PyQt5.QtWidgets import QApplication, QMenu  # noqa: E402

result = guitest.Result()
app = QApplication.instance()
PIPELINE = ["Mark Lights", "Radiosity Mesher", "Light Tagged Radiosity", "Radiosity Relight", "Radiosity Work Plane"]
LIGHTS = ["Amber", "CoolWhite", "WarmWhite"]



def radiosity_menu():
    """Filters > Radiosity in the menu bar."""
    menus = [m for m in app.allWidgets() if isinstance(m, QMenu) and m.objectName() == "Radiosity"
             and m.parent() is not None and m.parent().objectName() == "menuFilters"]
    return menus[0] if menus else None


def show_in_preferred_view(source, port, render_view):
    """What Apply does with an output: the view the filter's hints ask for, else the
    render view."""
    controller = servermanager.vtkSMParaViewPipelineControllerWithRendering()
    view_type = controller.GetPreferredViewType(source.SMProxy, port)
    view = CreateView(view_type) if view_type and view_type != "RenderView" else render_view
    display = Show(servermanager.OutputPort(source, port), view)
    guitest.settle()
    return view_type, view, display


def check_menu():
    menu = radiosity_menu()
    labels = [a.text().replace("&", "") for a in menu.actions()] if menu else []
    result.check(labels == PIPELINE, "Radiosity menu is %s, expected pipeline order %s" % (labels, PIPELINE))


def check_relit(display):
    result.check(display.MapScalars == 0, "the relit output is shown through a color map (Map Scalars on)")
    result.check(display.ColorArrayName[1] == "DisplayColors",
                 "the relit output is colored by '%s', expected DisplayColors" % display.ColorArrayName[1])
    result.check(display.Ambient == 1 and display.Diffuse == 0,
                 "shading on top of the relit colors: Ambient %g, Diffuse %g" % (display.Ambient, display.Diffuse))


def check_chart(view_type, chart, line):
    if not result.check(view_type == "XYChartView", "the convergence opens in '%s', not a line chart" % view_type):
        return
    shown = sorted(line.SeriesVisibility)  # the names of the series shown
    result.check(chart.LeftAxisLogScale == 1, "the chart's unshot-energy axis is not logarithmic")
    result.check(line.UseIndexForXAxis == 0 and line.XArrayName == "Shot", "the chart's x axis is not Shot")
    result.check(shown == ["Remaining_" + name for name in LIGHTS], "the chart shows %s, not a line per light" % shown)
    result.note("convergence chart: %s against Shot, log axis %d" % (shown, chart.LeftAxisLogScale))


def check_legend(solver, view):
    display = Show(solver, view)
    ColorBy(display, ("POINTS", "Radiosity_WarmWhite"))
    display.SetScalarBarVisibility(view, True)  # as the GUI does when coloring by an array
    guitest.settle()
    bar = servermanager.vtkSMTransferFunctionProxy.FindScalarBarRepresentation(display.LookupTable.SMProxy,
                                                                               view.SMProxy)
    title = servermanager._getPyProxy(bar).Title if bar else "(no scalar bar)"
    result.check("W/m" in title, "the legend says '%s', with no unit" % title)
    result.note("legend: %s" % title)


check_menu()
render_view = GetActiveView()
scene = XMLPolyDataReader(FileName=[guitest.data_file("paper_3lights.vtp")])
mesher = RadiosityMesher(Input=scene, PatchSize=1.5, ElementSize=0.5)
solver = LightTaggedRadiosity(Input=mesher, ConvergenceThreshold=0.01)
relit = RadiosityRelight(Input=solver)
view_type, chart, line = show_in_preferred_view(solver, 1, render_view)
check_chart(view_type, chart, line)
_, _, relit_display = show_in_preferred_view(relit, 0, render_view)
check_relit(relit_display)
check_legend(solver, render_view)
result.finish()
