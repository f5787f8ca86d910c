#include "pqRadiosityAreaLightsWidget.h"
#include "pqActiveObjects.h"
#include "pqView.h"

#include "vtkDataObject.h"
#include "vtkPVArrayInformation.h"
#include "vtkPVDataInformation.h"
#include "vtkSMPropertyHelper.h"
#include "vtkSMSourceProxy.h"

#include <QComboBox>
#include <QRegularExpression>
#include <QSignalBlocker>
#include <QTableWidget>

#include <algorithm>
#include <cmath>

pqRadiosityAreaLightsWidget::pqRadiosityAreaLightsWidget(vtkSMProxy* proxy, vtkSMProperty* property, QWidget* parent)
  : Superclass(proxy,
      { "Area lights (lengths in the scene's units):", "AreaLightsTable",
        { "Name", "Shape", "Centre x, y, z", "Facing x, y, z", "Width, height", "Emission r, g, b (W/m²)" },
        { "The light's name (a light of this name gains the lamp)", "Rectangle, or Disk (its width is the diameter)",
          "Centre of the lamp", "The direction it emits towards", "Width and height (a disk: diameter, ignored)",
          "Emitted radiosity per color channel, W/m²" },
        "Add Lamp", "AddLamp", "RemoveLamps",
        // the elements of a lamp: name, shape, centre, facing, size, emission
        { 0, 1, 2, 5, 8, 10, 13 } },
      parent)
{
  this->linkRows(property);
  this->fill();
}

void pqRadiosityAreaLightsWidget::fillCell(int row, int column)
{
  const QStringList part = this->cell(row, column);
  if (column != 1)
  {
    this->Table->setItem(row, column, new QTableWidgetItem(part.join(", ")));
    return;
  }
  auto* shape = new QComboBox(this->Table);
  shape->addItems({ "Rectangle", "Disk" });
  shape->setCurrentIndex(part[0].toInt() == 1 ? 1 : 0);
  QObject::connect(shape, QOverload<int>::of(&QComboBox::currentIndexChanged), this, [this, shape](int index) {
    for (int r = 0; r < this->Table->rowCount(); ++r)
    {
      if (this->Table->cellWidget(r, 1) == shape)
      {
        this->Rows[this->at(r, 1)] = QString::number(index);
        Q_EMIT this->rowsChanged();
      }
    }
  });
  this->Table->setCellWidget(row, 1, shape);
}

void pqRadiosityAreaLightsWidget::cellEdited(int row, int column)
{
  if (column == 1)
  {
    return;
  }
  QTableWidgetItem* item = this->Table->item(row, column);
  if (!item)
  {
    return;
  }
  const QString text = item->text().trimmed();
  QStringList parts = column == 0 ? QStringList{ text }
                                  : text.split(QRegularExpression("[,;\\s]+"), Qt::SkipEmptyParts);
  bool usable = parts.size() == this->count(column) && !(column == 0 && text.isEmpty());
  for (int k = 0; usable && column > 0 && k < parts.size(); ++k)
  {
    bool number = false;
    const double value = parts[k].toDouble(&number);
    // A lamp needs a size (Mark Lights refuses one without) and a direction.
    usable = number && std::isfinite(value) && (column != 4 || value > 0);
  }
  if (usable && column == 3)
  {
    usable = parts[0].toDouble() != 0 || parts[1].toDouble() != 0 || parts[2].toDouble() != 0;
  }
  if (!usable)
  {
    const QSignalBlocker block(this->Table);
    item->setText(this->cell(row, column).join(", ")); // what it held
    return;
  }
  std::copy(parts.begin(), parts.end(), this->Rows.begin() + this->at(row, column));
  Q_EMIT this->rowsChanged();
}

vtkPVDataInformation* pqRadiosityAreaLightsWidget::InputInformation() const
{
  vtkSMPropertyHelper input(this->proxy(), "Input");
  auto* source = vtkSMSourceProxy::SafeDownCast(input.GetAsProxy());
  return source ? source->GetDataInformation(input.GetOutputPort()) : nullptr;
}

QStringList pqRadiosityAreaLightsWidget::newRow() const
{
  double bounds[6] = { -0.5, 0.5, -0.5, 0.5, -0.5, 0.5 };
  vtkPVDataInformation* info = this->InputInformation();
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
  double centre[3], facing[3] = { 0, 0, 0 };
  for (int a = 0; a < 3; ++a)
  {
    centre[a] = 0.5 * (bounds[2 * a] + bounds[2 * a + 1]);
  }
  const double height = bounds[2 * up + 1] - bounds[2 * up];
  const double diagonal =
    std::sqrt(std::pow(bounds[1] - bounds[0], 2) + std::pow(bounds[3] - bounds[2], 2) + std::pow(bounds[5] - bounds[4], 2));
  // Just under the top; above a flat scene, a tenth of its extent up.
  const double top = sign > 0 ? bounds[2 * up + 1] : bounds[2 * up];
  centre[up] = height > 0 ? top - sign * 0.01 * height : top + sign * 0.1 * diagonal;
  facing[up] = -sign;
  const QString size = QString::number(std::max(diagonal / 20.0, 1e-6), 'g', 3);
  QStringList lamp{ this->unusedName(), "0" };
  for (double v : centre)
  {
    lamp << QString::number(v, 'g', 10);
  }
  for (double v : facing)
  {
    lamp << QString::number(v);
  }
  lamp << size << size << "1" << "1" << "1";
  return lamp;
}

QString pqRadiosityAreaLightsWidget::unusedName() const
{
  // A lamp named as another light would join it: the first LampN the table and the input
  // do not use yet.
  QStringList taken;
  for (int k = 0; k < this->Rows.size(); k += this->PerRow)
  {
    taken << this->Rows[k];
  }
  vtkPVDataInformation* info = this->InputInformation();
  vtkPVArrayInformation* names = info ? info->GetArrayInformation("LightNames", vtkDataObject::FIELD) : nullptr;
  for (int k = 0; names && k < names->GetNumberOfStringValues(); ++k)
  {
    taken << QString::fromUtf8(names->GetStringValue(k));
  }
  int n = 1;
  while (taken.contains(QString("Lamp%1").arg(n)))
  {
    ++n;
  }
  return QString("Lamp%1").arg(n);
}
