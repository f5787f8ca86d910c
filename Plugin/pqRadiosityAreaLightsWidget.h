// ParaView panel for Mark Lights' area lights: one row per lamp under column headers with
// units (name, shape, centre, facing, size, emission), Add and Remove buttons.
#ifndef pqRadiosityAreaLightsWidget_h
#define pqRadiosityAreaLightsWidget_h

#include "pqRadiosityTableWidget.h"

class pqRadiosityAreaLightsWidget : public pqRadiosityTableWidget
{
  Q_OBJECT
  typedef pqRadiosityTableWidget Superclass;

public:
  // Rows: 13 per lamp (name, shape, centre x y z, facing x y z, width, height, emission r g b).
  pqRadiosityAreaLightsWidget(vtkSMProxy* proxy, vtkSMProperty* property, QWidget* parent = nullptr);

protected:
  void fillCell(int row, int column) override;
  /// A new lamp: at the top of the input's box, facing down along its shortest side.
  QStringList newRow() const override;
  /// A typed cell into the rows; a cell that does not read as its numbers is put back.
  void cellEdited(int row, int column) override;
};

#endif
