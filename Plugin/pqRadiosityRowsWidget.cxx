#include "pqRadiosityRowsWidget.h"

pqRadiosityRowsWidget::pqRadiosityRowsWidget(vtkSMProxy* proxy, QWidget* parent)
  : Superclass(proxy, parent)
{
}

QList<QVariant> pqRadiosityRowsWidget::rows() const
{
  QList<QVariant> values;
  for (const QString& row : this->Rows)
  {
    values.push_back(row);
  }
  return values;
}

void pqRadiosityRowsWidget::setRows(const QList<QVariant>& values)
{
  QStringList rows;
  for (const QVariant& value : values)
  {
    rows.push_back(value.toString());
  }
  if (rows != this->Rows)
  {
    this->Rows = rows;
    this->rowsSet();
  }
}

void pqRadiosityRowsWidget::linkRows(vtkSMProperty* property)
{
  this->addPropertyLink(this, "rows", SIGNAL(rowsChanged()), property);
}
