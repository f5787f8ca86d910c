#include "pqRadiosityAreaLightsWidget.h"
#include "pqRadiosityLampPlacement.h"


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
  if (column == 1 || !this->Table->item(row, column))
  {
    return;
  }
  const QStringList parts = this->typed(row, column, column == 0);
  // A lamp needs a name, a size (Mark Lights refuses one without) and a direction.
  const bool usable = column == 0 ? !parts[0].isEmpty()
    : column == 4                 ? this->numbers(parts, column, 0) && parts[0].toDouble() > 0 && parts[1].toDouble() > 0
                                  : this->numbers(parts, column, -HUGE_VAL) && (column != 3 || direction(parts));
  this->takeOrPutBack(row, column, parts, usable);
}

QStringList pqRadiosityAreaLightsWidget::newRow() const
{
  const pqRadiosityLampPlacement::NewLamp lamp = pqRadiosityLampPlacement::Place(this->proxy(), "Lamp", this->names());
  return QStringList{ lamp.Name, "0" } << lamp.Centre << lamp.Facing << lamp.Size << lamp.Size << "1" << "1" << "1";
}
