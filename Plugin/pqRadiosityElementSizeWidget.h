// The mesher's Element Size box, with the element count these sizes make shown live as
// the sizes are typed, before Apply.
#ifndef pqRadiosityElementSizeWidget_h
#define pqRadiosityElementSizeWidget_h

#include "pqPropertyWidget.h"

class QLabel;
class pqDoubleLineEdit;
class vtkEventQtSlotConnect;

class pqRadiosityElementSizeWidget : public pqPropertyWidget
{
  Q_OBJECT
  typedef pqPropertyWidget Superclass;

public:
  pqRadiosityElementSizeWidget(vtkSMProxy* proxy, vtkSMProperty* property, QWidget* parent = nullptr);
  ~pqRadiosityElementSizeWidget() override;

private Q_SLOTS:
  /// Counts the elements for the sizes in the panel (applied or not).
  void updateEstimate();

private:
  /// The count, exact from the filter itself in a builtin session; elsewhere scaled from
  /// the suggestion's count by area (elements grow as 1 / size²). Negative if unknown.
  double estimate(double patchSize, double elementSize, bool& exact) const;

  pqDoubleLineEdit* Edit;
  QLabel* Estimate;
  vtkEventQtSlotConnect* Connection;
};

#endif
