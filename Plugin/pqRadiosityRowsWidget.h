// A panel widget for a repeatable string property edited as rows (the relight filter's
// lights, Mark Lights' area lights): the property's elements as one Qt property, `rows`,
// which ParaView's property links read and write, so Apply, Reset and undo work as for
// any panel widget.
#ifndef pqRadiosityRowsWidget_h
#define pqRadiosityRowsWidget_h

#include "pqPropertyWidget.h"

#include <QList>
#include <QStringList>
#include <QVariant>

class vtkEventQtSlotConnect;
class vtkSMProperty;

class pqRadiosityRowsWidget : public pqPropertyWidget
{
  Q_OBJECT
  typedef pqPropertyWidget Superclass;
  Q_PROPERTY(QList<QVariant> rows READ rows WRITE setRows NOTIFY rowsChanged)

public:
  pqRadiosityRowsWidget(vtkSMProxy* proxy, QWidget* parent = nullptr);
  ~pqRadiosityRowsWidget() override;

  QList<QVariant> rows() const;
  void setRows(const QList<QVariant>& values);

Q_SIGNALS:
  /// The rows changed in the widget: the links set the property, a change is available.
  void rowsChanged();

private Q_SLOTS:
  /// The property's rows were set (from Python, a state file, Apply): where they are not
  /// the widget's, show them. The links alone miss a property emptied from Python.
  void followProperty();

protected:
  /// Links `rows` to the property; called at the end of a subclass's constructor (the
  /// link gives the first rows at once, through rowsSet).
  void linkRows(vtkSMProperty* property);
  /// New rows came from the property (Reset, undo, Python): show them.
  virtual void rowsSet() = 0;

  QStringList Rows; ///< the property's elements as the links last gave or took them

private:
  vtkSMProperty* Linked = nullptr;
  vtkEventQtSlotConnect* Watch = nullptr;
};

#endif
