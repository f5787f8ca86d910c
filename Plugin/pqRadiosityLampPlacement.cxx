#include "pqRadiosityLampPlacement.h"

#include "pqActiveObjects.h"
#include "pqView.h"

#include "vtkDataObject.h"
#include "vtkPVArrayInformation.h"
#include "vtkPVDataInformation.h"
#include "vtkSMPropertyHelper.h"
#include "vtkSMSourceProxy.h"

#include <algorithm>
#include <cmath>

namespace pqRadiosityLampPlacement
{

vtkPVDataInformation* InputInformation(vtkSMProxy* proxy)
{
  vtkSMPropertyHelper input(proxy, "Input");
  auto* source = vtkSMSourceProxy::SafeDownCast(input.GetAsProxy());
  return source ? source->GetDataInformation(input.GetOutputPort()) : nullptr;
}

void CeilingSpot(vtkPVDataInformation* info, double centre[3], double facing[3], double& size)
{
  double bounds[6] = { -0.5, 0.5, -0.5, 0.5, -0.5, 0.5 };
  if (info && info->GetNumberOfCells() > 0)
  {
    info->GetBounds(bounds);
  }
  // A ceiling lamp just under the top, facing down; "up" is the view's, as the user sees the
  // scene (the shortest side, as most rooms stand, where there is no view: a scanned
  // figure is narrower than it is tall, and got its lamp on its flank).
  int up = 0;
  double sign = 1;
  double viewUp[3] = { 0, 0, 0 };
  pqView* view = pqActiveObjects::instance().activeView();
  if (view && view->getProxy()->GetProperty("CameraViewUp"))
  {
    vtkSMPropertyHelper(view->getProxy(), "CameraViewUp").Get(viewUp, 3);
  }
  for (int a = 1; a < 3; ++a)
  {
    up = std::fabs(viewUp[a]) > std::fabs(viewUp[up]) ? a : up;
  }
  if (std::fabs(viewUp[up]) > 0)
  {
    sign = viewUp[up] > 0 ? 1 : -1;
  }
  else
  {
    for (int a = 1; a < 3; ++a)
    {
      up = bounds[2 * a + 1] - bounds[2 * a] < bounds[2 * up + 1] - bounds[2 * up] ? a : up;
    }
  }
  for (int a = 0; a < 3; ++a)
  {
    centre[a] = 0.5 * (bounds[2 * a] + bounds[2 * a + 1]);
    facing[a] = 0;
  }
  const double height = bounds[2 * up + 1] - bounds[2 * up];
  const double diagonal =
    std::sqrt(std::pow(bounds[1] - bounds[0], 2) + std::pow(bounds[3] - bounds[2], 2) + std::pow(bounds[5] - bounds[4], 2));
  // Just under the top; above a flat scene, a tenth of its extent up.
  const double top = sign > 0 ? bounds[2 * up + 1] : bounds[2 * up];
  centre[up] = height > 0 ? top - sign * 0.01 * height : top + sign * 0.1 * diagonal;
  facing[up] = -sign;
  size = std::max(diagonal / 20.0, 1e-6);
}

QString UnusedName(const QString& stem, QStringList taken, vtkPVDataInformation* info)
{
  // A lamp named as another light would join it (or be refused): the first free name.
  vtkPVArrayInformation* names = info ? info->GetArrayInformation("LightNames", vtkDataObject::FIELD) : nullptr;
  for (int k = 0; names && k < names->GetNumberOfStringValues(); ++k)
  {
    taken << QString::fromUtf8(names->GetStringValue(k));
  }
  vtkPVArrayInformation* luminaires = info ? info->GetArrayInformation("LuminaireNames", vtkDataObject::FIELD) : nullptr;
  for (int k = 0; luminaires && k < luminaires->GetNumberOfStringValues(); ++k)
  {
    taken << QString::fromUtf8(luminaires->GetStringValue(k));
  }
  int n = 1;
  while (taken.contains(QString("%1%2").arg(stem).arg(n)))
  {
    ++n;
  }
  return QString("%1%2").arg(stem).arg(n);
}

NewLamp Place(vtkSMProxy* proxy, const QString& stem, const QStringList& taken)
{
  vtkPVDataInformation* info = InputInformation(proxy);
  double centre[3], facing[3], size;
  CeilingSpot(info, centre, facing, size);
  NewLamp lamp;
  lamp.Name = UnusedName(stem, taken, info);
  for (int a = 0; a < 3; ++a)
  {
    lamp.Centre << QString::number(centre[a], 'g', 10);
    lamp.Facing << QString::number(facing[a]);
  }
  lamp.Size = QString::number(size, 'g', 3);
  return lamp;
}
}
