#include "pqRadiosityRowsWidget.h"

#include "vtkCommand.h"
#include "vtkEventQtSlotConnect.h"
#include "vtkSMPropertyHelper.h"

pqRadiosityRowsWidget::pqRadiosityRowsWidget(vtkSMProxy* proxy, QWidget* parent)
  : Superclass(proxy, parent)
  , Watch(vtkEventQtSlotConnect::New())
{
}

pqRadiosityRowsWidget::~pqRadiosityRowsWidget()
{
  this->Watch->Disconnect();
  this->Watch->Delete();
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
  this->Linked = property;
  this->Watch->Connect(property, vtkCommand::ModifiedEvent, this, SLOT(followProperty()));
}

void pqRadiosityRowsWidget::followProperty()
{
  vtkSMPropertyHelper helper(this->Linked);
  QList<QVariant> values;
  for (unsigned int i = 0; i < helper.GetNumberOfElements(); ++i)
  {
    values.push_back(QString(helper.GetAsString(i)));
  }
  this->setRows(values); // nothing happens where they are the widget's already
}
