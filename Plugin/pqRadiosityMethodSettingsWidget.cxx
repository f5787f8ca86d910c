#include "pqRadiosityMethodSettingsWidget.h"

#include "vtkLightTaggedRadiosity.h"

#include <QTableWidget>

namespace
{
/// The known setting named `name`, or -1.
int Known(const QString& name)
{
  for (int i = 0; i < vtkLightTaggedRadiosity::GetNumberOfKnownMethodSettings(); ++i)
  {
    if (name == QString::fromUtf8(vtkLightTaggedRadiosity::GetKnownMethodSettingName(i)))
    {
      return i;
    }
  }
  return -1;
}

/// Each known setting with its method and range, for the Setting column's tip.
QString Listed()
{
  QStringList rows;
  for (int i = 0; i < vtkLightTaggedRadiosity::GetNumberOfKnownMethodSettings(); ++i)
  {
    rows << QString("%1 (%2, %3 to %4)")
              .arg(vtkLightTaggedRadiosity::GetKnownMethodSettingName(i))
              .arg(vtkLightTaggedRadiosity::GetKnownMethodSettingMethod(i))
              .arg(vtkLightTaggedRadiosity::GetKnownMethodSettingMinimum(i))
              .arg(vtkLightTaggedRadiosity::GetKnownMethodSettingMaximum(i));
  }
  return rows.join("; ");
}
} // namespace

pqRadiosityMethodSettingsWidget::pqRadiosityMethodSettingsWidget(
  vtkSMProxy* proxy, vtkSMProperty* property, QWidget* parent)
  : Superclass(proxy,
      { "Settings one method alone reads, by name:", "MethodSettingsTable", { "Setting", "Value" },
        { "One of: " + Listed(), "Its value, within its range" }, "Add Setting", "AddMethodSetting",
        "RemoveMethodSettings",
        // the elements of a setting: name, value
        { 0, 1, 2 } },
      parent)
{
  this->linkRows(property);
  this->fill();
}

void pqRadiosityMethodSettingsWidget::fillCell(int row, int column)
{
  this->Table->setItem(row, column, new QTableWidgetItem(this->cell(row, column).join("")));
}

void pqRadiosityMethodSettingsWidget::cellEdited(int row, int column)
{
  if (!this->Table->item(row, column))
  {
    return;
  }
  // The row as it would be: a name any method has and no other row holds, a value in its range.
  const QStringList parts = this->typed(row, column, true);
  const QString name = column == 0 ? parts[0] : this->cell(row, 0)[0];
  const int known = Known(name);
  bool number = false;
  const double value = (column == 1 ? parts[0] : this->cell(row, 1)[0]).toDouble(&number);
  QStringList others = this->names();
  others.removeAt(row);
  const bool usable = known >= 0 && !others.contains(name) && number &&
    value >= vtkLightTaggedRadiosity::GetKnownMethodSettingMinimum(known) &&
    value <= vtkLightTaggedRadiosity::GetKnownMethodSettingMaximum(known);
  this->takeOrPutBack(row, column, parts, usable);
}

QStringList pqRadiosityMethodSettingsWidget::newRow() const
{
  const QStringList taken = this->names();
  for (int i = 0; i < vtkLightTaggedRadiosity::GetNumberOfKnownMethodSettings(); ++i)
  {
    const QString name = QString::fromUtf8(vtkLightTaggedRadiosity::GetKnownMethodSettingName(i));
    if (!taken.contains(name))
    {
      return { name, QString::number(vtkLightTaggedRadiosity::GetKnownMethodSettingDefault(i), 'g', 10) };
    }
  }
  return {}; // every setting has its row
}
