// ParaView panel for Mark Lights' area lights: one row per lamp under column headers with
// units (name, shape, centre, facing, size, emission), Add and Remove buttons.
#ifndef pqRadiosityAreaLightsWidget_h
#define pqRadiosityAreaLightsWidget_h

#include "pqPropertyWidget.h"

#include <QList>
#include <QStringList>
#include <QVariant>

class QTableWidget;

class pqRadiosityAreaLightsWidget : public pqPropertyWidget
{
  Q_OBJECT
  typedef pqPropertyWidget Superclass;
  /// The property's elements, 13 per lamp (name, shape, centre x y z, facing x y z, width,
  /// height, emission r g b), linked through ParaView's property links: Apply, Reset and
  /// undo work as for any panel widget.
  Q_PROPERTY(QList<QVariant> rows READ rows WRITE setRows NOTIFY rowsChanged)

public:
  pqRadiosityAreaLightsWidget(vtkSMProxy* proxy, vtkSMProperty* property, QWidget* parent = nullptr);

  QList<QVariant> rows() const;
  void setRows(const QList<QVariant>& values);

Q_SIGNALS:
  void rowsChanged();

private Q_SLOTS:
  void addLamp();
  void removeLamps();
  /// A typed cell into the values; a cell that does not read as its numbers is put back.
  void cellEdited(int row, int column);

private:
  /// The table from Values (the rows as the property links last gave or took them).
  void fill();
  /// A new lamp's row: at the top of the input's box, facing down along its shortest side.
  QStringList newLamp() const;
  /// The first of Lamp1, Lamp2, ... that no lamp here and no light of the input is called.
  QString unusedName() const;
  void fitHeight();

  QTableWidget* Table;
  QStringList Values;
  bool Filling = false;
};

#endif
