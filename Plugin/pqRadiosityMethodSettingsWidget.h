// ParaView panel for the solver's settings by name: one row per setting (its name, its
// value), Add and Remove; names and ranges from the method table, through the filter.
#ifndef pqRadiosityMethodSettingsWidget_h
#define pqRadiosityMethodSettingsWidget_h

#include "pqRadiosityTableWidget.h"

class pqRadiosityMethodSettingsWidget : public pqRadiosityTableWidget
{
  Q_OBJECT
  typedef pqRadiosityTableWidget Superclass;

public:
  // Rows: 2 per setting (name, value).
  pqRadiosityMethodSettingsWidget(vtkSMProxy* proxy, vtkSMProperty* property, QWidget* parent = nullptr);

protected:
  void fillCell(int row, int column) override;
  /// The first setting not in the table yet, at its default (none when all are).
  QStringList newRow() const override;
  /// Taken where the row then holds a name any method has and no other row does, and a
  /// number in that setting's range; else put back.
  void cellEdited(int row, int column) override;
};

#endif
