#include "pqRadiosityScheduleWidget.h"

#include "vtkRadiosityLights.h"

#include "vtkSMPropertyHelper.h"
#include "vtkSMProxy.h"

#include <QRegularExpression>
#include <QSignalBlocker>
#include <QTableWidget>

#include <algorithm>
#include <string>
#include <vector>

namespace
{
/// The keyframe in `row` as the property holds it (enabled as 1 or 0), or empty where it
/// does not read as the schedule file's rows do.
QStringList Checked(const QStringList& row)
{
  std::vector<std::string> cells;
  for (const QString& cell : row)
  {
    cells.push_back(cell.toStdString());
  }
  std::string light;
  bool enabled = false;
  if (!vtkRadiosityLights::ReadScheduleRow(cells, light, enabled))
  {
    return {};
  }
  QStringList checked = row;
  checked[1] = QString::fromStdString(light);
  checked[6] = enabled ? "1" : "0";
  return checked;
}
}

pqRadiosityScheduleWidget::pqRadiosityScheduleWidget(vtkSMProxy* proxy, vtkSMProperty* property, QWidget* parent)
  : Superclass(proxy,
      { "Keyframes (color and intensity run linearly between them):", "ScheduleTable",
        { "Time", "Light", "Color r, g, b", "Intensity", "On" },
        { "When the keyframe holds (the animation's time)", "The light's name, or its index from 0",
          "Its color at that time", "Its intensity at that time", "1: on, 0: off, from this keyframe until the next" },
        "Add Keyframe", "AddKeyframe", "RemoveKeyframes",
        // the elements of a keyframe: time, light, color, intensity, on
        { 0, 1, 2, 5, 6, 7 } },
      parent)
{
  this->linkRows(property);
  this->fill();
}

void pqRadiosityScheduleWidget::fillCell(int row, int column)
{
  const QStringList part = this->cell(row, column);
  this->Table->setItem(row, column, new QTableWidgetItem(part.join(", ")));
}

void pqRadiosityScheduleWidget::cellEdited(int row, int column)
{
  QTableWidgetItem* item = this->Table->item(row, column);
  if (!item)
  {
    return;
  }
  const QString text = item->text().trimmed();
  const QStringList parts =
    column == 1 ? QStringList{ text } : text.split(QRegularExpression("[,;\\s]+"), Qt::SkipEmptyParts);
  QStringList key = this->Rows.mid(this->at(row, 0), this->PerRow);
  QStringList checked;
  if (parts.size() == this->count(column))
  {
    std::copy(parts.begin(), parts.end(), key.begin() + this->Starts[column]);
    checked = Checked(key);
  }
  if (checked.isEmpty())
  {
    const QSignalBlocker block(this->Table);
    item->setText(this->cell(row, column).join(", ")); // what it held
    return;
  }
  std::copy(checked.begin(), checked.end(), this->Rows.begin() + this->at(row, 0));
  const QSignalBlocker block(this->Table);
  item->setText(this->cell(row, column).join(", ")); // as the property holds it
  Q_EMIT this->rowsChanged();
}

QString pqRadiosityScheduleWidget::firstLight() const
{
  // The relight filter names its lights in LightNamesInfo, Relit Surface in RelitLightNamesInfo.
  for (const char* name : { "LightNamesInfo", "RelitLightNamesInfo" })
  {
    if (vtkSMProperty* names = this->proxy()->GetProperty(name))
    {
      vtkSMPropertyHelper helper(names);
      if (helper.GetNumberOfElements() > 0)
      {
        return QString::fromUtf8(helper.GetAsString(0));
      }
    }
  }
  return "0";
}

QStringList pqRadiosityScheduleWidget::newRow() const
{
  if (this->Rows.size() >= this->PerRow)
  {
    QStringList key = this->Rows.mid(this->Rows.size() - this->PerRow, this->PerRow);
    key[0] = QString::number(key[0].toDouble() + 1.0, 'g', 10);
    return key;
  }
  return { "0", this->firstLight(), "1", "1", "1", "1", "1" };
}
