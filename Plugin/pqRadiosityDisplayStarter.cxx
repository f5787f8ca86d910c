#include "pqRadiosityDisplayStarter.h"

#include "pqApplicationCore.h"
#include "pqDataRepresentation.h"
#include "pqOutputPort.h"
#include "pqPipelineSource.h"
#include "pqRenderView.h"
#include "pqServerManagerModel.h"
#include "pqView.h"
#include "vtkDataObject.h"
#include "vtkPVArrayInformation.h"
#include "vtkPVDataInformation.h"
#include "vtkPVDataSetAttributesInformation.h"
#include "vtkSMPVRepresentationProxy.h"
#include "vtkSMRadiosityRelightProxy.h"
#include "vtkSMSession.h"
#include "vtkSMPropertyHelper.h"
#include "vtkSMTransferFunctionManager.h"
#include "vtkSMTransferFunctionProxy.h"
#include "vtkNew.h"

#include <QPointer>
#include <QStringList>
#include <QTimer>

namespace
{
const char* const RelitArray = "DisplayColors";
const char* const Unit = "W/m\xc2\xb2";

QString SourceName(pqDataRepresentation* representation, int* port)
{
  pqOutputPort* output = representation->getOutputPortFromInput();
  if (!output)
  {
    return QString();
  }
  *port = output->getPortNumber();
  return QString::fromUtf8(output->getSource()->getProxy()->GetXMLName());
}

bool IsRadiosityArray(const QString& name)
{
  return name.startsWith(QLatin1String("Radiosity")) || name.startsWith(QLatin1String("Direct"));
}
}

pqRadiosityDisplayStarter::pqRadiosityDisplayStarter(QObject* parent)
  : QObject(parent)
{
}

void pqRadiosityDisplayStarter::startup()
{
  // The lights panel shows the settings in effect and stores only the user's changes: no
  // copy of the data's lights into the property (that is for scripts).
  vtkSMRadiosityRelightProxy::SetShowDataLights(false);
  pqServerManagerModel* model = pqApplicationCore::instance()->getServerManagerModel();
  QObject::connect(model, &pqServerManagerModel::representationAdded, this,
    &pqRadiosityDisplayStarter::onRepresentationAdded);
}

void pqRadiosityDisplayStarter::onRepresentationAdded(pqRepresentation* representation)
{
  QPointer<pqDataRepresentation> data = qobject_cast<pqDataRepresentation*>(representation);
  if (!data)
  {
    return;
  }
  // ParaView sets its own defaults (coloring, scalar bar) after the representation is
  // registered; ours go on top of those, once control is back in the event loop.
  QTimer::singleShot(0, this, [this, data]() {
    if (data)
    {
      this->Configure(data);
    }
  });
}

void pqRadiosityDisplayStarter::Configure(pqDataRepresentation* representation)
{
  // Qt events run inside our filters (for the abort button): wait for the update to end,
  // as ParaView's own renders do, rather than touch a pipeline that is executing.
  if (representation->getProxy()->GetSession()->GetPendingProgress())
  {
    QPointer<pqDataRepresentation> later = representation;
    QTimer::singleShot(100, this, [this, later]() {
      if (later)
      {
        this->Configure(later);
      }
    });
    return;
  }
  int port = 0;
  const QString source = SourceName(representation, &port);
  const QString type = QString::fromUtf8(representation->getProxy()->GetXMLName());
  if (source == QLatin1String("RadiosityRelight") && type == QLatin1String("GeometryRepresentation"))
  {
    ShowRelitColors(representation);
    QObject::connect(representation, &pqDataRepresentation::colorArrayNameModified, representation,
      [representation]() { LeaveRelitToColor(representation); });
  }
  else if (source == QLatin1String("LightTaggedRadiosity") && port == 1 &&
    type == QLatin1String("XYChartRepresentation"))
  {
    ShowConvergence(representation);
  }
  else if (source == QLatin1String("LightTaggedRadiosity") && port == 0)
  {
    ShowRelitSurface(representation);
    StyleRadiosityColorMap(representation);
    // After ParaView's own steps for the new coloring (its lookup table and legend come
    // after the array name: styled at once, the toolbar's pick kept ParaView's defaults).
    QObject::connect(representation, &pqDataRepresentation::colorArrayNameModified, representation,
      [representation]() {
        QPointer<pqDataRepresentation> later = representation;
        QTimer::singleShot(0, representation, [later]() {
          if (later)
          {
            LeaveRelitToColor(later);
            StyleRadiosityColorMap(later);
          }
        });
      });
  }
}

void pqRadiosityDisplayStarter::ShowRelitColors(pqDataRepresentation* representation)
{
  vtkSMProxy* proxy = representation->getProxy();
  vtkSMPVRepresentationProxy::SetScalarColoring(proxy, RelitArray, vtkDataObject::POINT);
  vtkSMPropertyHelper(proxy, "MapScalars").Set(0);
  vtkSMPropertyHelper(proxy, "Ambient").Set(1.0);
  vtkSMPropertyHelper(proxy, "Diffuse").Set(0.0);
  if (pqView* view = representation->getView())
  {
    vtkSMPVRepresentationProxy::SetScalarBarVisibility(proxy, view->getProxy(), false);
  }
  proxy->UpdateVTKObjects();
  representation->renderViewEventually();
}

void pqRadiosityDisplayStarter::ShowRelitSurface(pqDataRepresentation* representation)
{
  // The solutions relit on the GPU: lights change in the display panel without Apply.
  vtkSMProxy* proxy = representation->getProxy();
  if (!proxy->GetProperty("RelitLightSettings"))
  {
    return; // a view without the Relit Surface type (a spreadsheet, say)
  }
  vtkSMPropertyHelper(proxy, "Representation").Set("Relit Surface");
  proxy->UpdateVTKObjects();
}

void pqRadiosityDisplayStarter::LeaveRelitToColor(pqDataRepresentation* representation)
{
  // Relit Surface draws the relit picture whatever the coloring says (the toolbar reads
  // Solid Color, ParaView's "no array"), Relit Colors the filter's DisplayColors: an array
  // picked while they are shown would change nothing, so it is shown on the plain Surface.
  // The relit picture is one choice away again.
  vtkSMProxy* proxy = representation->getProxy();
  vtkSMPropertyHelper type(proxy, "Representation", /*quiet=*/true);
  const QString shown = QString::fromUtf8(type.GetAsString() ? type.GetAsString() : "");
  const char* array = vtkSMPropertyHelper(proxy, "ColorArrayName", /*quiet=*/true).GetInputArrayNameToProcess();
  const QString picked = QString::fromUtf8(array ? array : "");
  // Solid Color ("no array") is what these representations show anyway: it stays.
  const bool relit = shown == QLatin1String("Relit Surface") || shown == QLatin1String("Relit Colors");
  if (!relit || picked.isEmpty() || picked == RelitArray)
  {
    return;
  }
  type.Set("Surface");
  proxy->UpdateVTKObjects();
  representation->renderViewEventually();
}

void pqRadiosityDisplayStarter::ShowConvergence(pqDataRepresentation* representation)
{
  vtkSMProxy* proxy = representation->getProxy();
  vtkPVDataSetAttributesInformation* columns =
    representation->getInputDataInformation()->GetRowDataInformation();
  QStringList visibility;
  bool perLight = false;
  for (int i = 0; columns && i < columns->GetNumberOfArrays(); ++i)
  {
    perLight = perLight || QString(columns->GetArrayInformation(i)->GetName()).startsWith("Remaining_");
  }
  for (int i = 0; columns && i < columns->GetNumberOfArrays(); ++i)
  {
    const QString name = columns->GetArrayInformation(i)->GetName();
    // One line per light where there are several; the total otherwise.
    const bool shown = perLight ? name.startsWith("Remaining_") : name == QLatin1String("Remaining");
    visibility << name << (shown ? "1" : "0");
  }
  vtkSMPropertyHelper(proxy, "UseIndexForXAxis").Set(0);
  vtkSMPropertyHelper(proxy, "XArrayName").Set("Shot");
  vtkSMPropertyHelper visible(proxy, "SeriesVisibility");
  visible.SetNumberOfElements(static_cast<unsigned int>(visibility.size()));
  for (int i = 0; i < visibility.size(); ++i)
  {
    visible.Set(static_cast<unsigned int>(i), visibility[i].toUtf8().data());
  }
  proxy->UpdateVTKObjects();
  if (pqView* view = representation->getView())
  {
    vtkSMProxy* chart = view->getProxy();
    vtkSMPropertyHelper(chart, "LeftAxisLogScale").Set(1);
    vtkSMPropertyHelper(chart, "LeftAxisTitle").Set("Unshot energy (fraction of the initial)");
    vtkSMPropertyHelper(chart, "BottomAxisTitle").Set("Shot");
    vtkSMPropertyHelper(chart, "ChartTitle").Set("Convergence");
    chart->UpdateVTKObjects();
  }
  representation->renderViewEventually();
  // The chart took half of the render view's place: frame the scene again in what is left
  // (it was framed for the whole width and would be cut off). Not while a state file is
  // loading: it brings its own cameras.
  if (pqApplicationCore::instance()->isLoadingState())
  {
    return;
  }
  pqPipelineSource* solver = representation->getOutputPortFromInput()->getSource();
  QTimer::singleShot(0, representation, [solver]() {
    for (pqRenderView* view : pqApplicationCore::instance()->getServerManagerModel()->findItems<pqRenderView*>())
    {
      if (pqDataRepresentation* shown = solver->getOutputPort(0)->getRepresentation(view))
      {
        if (shown->isVisible())
        {
          view->resetDisplay();
        }
      }
    }
  });
}

void pqRadiosityDisplayStarter::StyleRadiosityColorMap(pqDataRepresentation* representation)
{
  vtkSMProxy* proxy = representation->getProxy();
  vtkSMPropertyHelper colorArray(proxy, "ColorArrayName", /*quiet=*/true);
  const QString name = QString::fromUtf8(colorArray.GetInputArrayNameToProcess());
  vtkSMProxy* lut = representation->getLookupTableProxy();
  pqView* view = representation->getView();
  if (!IsRadiosityArray(name) || !lut || !view)
  {
    return;
  }
  // A color map of one array belongs to every view of it; style it once only, so that a
  // user's own choice is kept. The legend is made (not shown) if there is none yet.
  vtkNew<vtkSMTransferFunctionManager> manager;
  vtkSMProxy* bar = manager->GetScalarBarRepresentation(lut, view->getProxy());
  const QString title = QString("%1 (%2)").arg(name, QString::fromUtf8(Unit));
  if (bar && QString(vtkSMPropertyHelper(bar, "Title").GetAsString()) == title)
  {
    return;
  }
  vtkSMTransferFunctionProxy::ApplyPreset(lut, "Inferno (matplotlib)", /*rescale=*/false);
  vtkSMPVRepresentationProxy::RescaleTransferFunctionToDataRange(proxy, false, false);
  lut->UpdateVTKObjects();
  if (bar)
  {
    vtkSMPropertyHelper(bar, "Title").Set(title.toUtf8().data());
    vtkSMPropertyHelper(bar, "ComponentTitle").Set("");
    bar->UpdateVTKObjects();
  }
  representation->renderViewEventually();
}
