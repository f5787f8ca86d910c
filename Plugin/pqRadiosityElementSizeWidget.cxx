#include "pqRadiosityElementSizeWidget.h"

#include "vtkRadiosityMesher.h"

#include "pqDoubleLineEdit.h"
#include "vtkCommand.h"
#include "vtkEventQtSlotConnect.h"
#include "vtkSMPropertyHelper.h"
#include "vtkSMProxy.h"
#include "vtkSMUncheckedPropertyHelper.h"

#include <QLabel>
#include <QLocale>
#include <QVBoxLayout>

pqRadiosityElementSizeWidget::pqRadiosityElementSizeWidget(
  vtkSMProxy* proxy, vtkSMProperty* property, QWidget* parent)
  : Superclass(proxy, parent)
  , Edit(new pqDoubleLineEdit(this))
  , Estimate(new QLabel(this))
  , Connection(vtkEventQtSlotConnect::New())
{
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  this->Edit->setObjectName("ElementSizeEdit");
  this->Edit->setUseGlobalPrecisionAndNotation(true);
  this->Estimate->setObjectName("ElementEstimate");
  this->Estimate->setWordWrap(true);
  layout->addWidget(this->Edit);
  layout->addWidget(this->Estimate);
  this->addPropertyLink(this->Edit, "text2", SIGNAL(textChanged(const QString&)), property);
  QObject::connect(this->Edit, SIGNAL(textChangedAndEditingFinished()), this, SIGNAL(changeFinished()));
  QObject::connect(this->Edit, &QLineEdit::textChanged, this, &pqRadiosityElementSizeWidget::updateEstimate);
  // Patch Size changes the count too; the input is known after each information pass.
  this->Connection->Connect(proxy->GetProperty("PatchSize"), vtkCommand::UncheckedPropertyModifiedEvent,
    this, SLOT(updateEstimate()));
  this->Connection->Connect(proxy, vtkCommand::UpdateInformationEvent, this, SLOT(updateEstimate()));
  this->updateEstimate();
}

pqRadiosityElementSizeWidget::~pqRadiosityElementSizeWidget()
{
  this->Connection->Disconnect();
  this->Connection->Delete();
}

double pqRadiosityElementSizeWidget::estimate(double patchSize, double elementSize, bool& exact) const
{
  vtkSMProxy* proxy = this->proxy();
  exact = false;
  if (auto* mesher = vtkRadiosityMesher::SafeDownCast(proxy->GetClientSideObject()))
  {
    exact = true;
    return mesher->EstimateElements(patchSize, elementSize);
  }
  const double suggested = vtkSMPropertyHelper(proxy, "SuggestedElements").GetAsDouble();
  const double size = vtkSMPropertyHelper(proxy, "SuggestedElementSize").GetAsDouble();
  if (!(suggested > 0) || !(size > 0) || !(elementSize > 0))
  {
    return -1;
  }
  return suggested * (size / elementSize) * (size / elementSize);
}

void pqRadiosityElementSizeWidget::updateEstimate()
{
  bool ok = false;
  const double elementSize = this->Edit->text().toDouble(&ok);
  const double patchSize = vtkSMUncheckedPropertyHelper(this->proxy(), "PatchSize").GetAsDouble();
  bool exact = false;
  const double count = ok ? this->estimate(patchSize, elementSize, exact) : -1;
  if (!(count > 0))
  {
    this->Estimate->setText(tr("elements: known once the input is applied"));
    return;
  }
  const QString number = QLocale().toString(count, 'f', 0);
  this->Estimate->setText(exact ? tr("makes %1 elements").arg(number) : tr("makes about %1 elements").arg(number));
}
